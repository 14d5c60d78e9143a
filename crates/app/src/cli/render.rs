//! `prism render IN -o OUT.png [--pipeline P | --scheme S --levels N ...] [--shading flat|smooth]
//! [--wireframe] [--cage] [--color-by uniform|kind|curvature|scheme|flipped|crossings] [--size 1280x800]
//! [--view iso|front|top|right | --eye X,Y,Z --target X,Y,Z] [--fov DEG] [--frame-vertex N]
//! [--frames N | --levels-strip] [--lines CURVES.obj]`: a headless picture with the viewport's renderer, on any adapter (Mesa's
//! software Vulkan on a machine without a GPU).
//!
//! The camera is a named view of the whole model, or a free one (`--eye`, `--target`, in
//! the model's coordinates), or a close-up of input vertex N's neighbourhood
//! (`--frame-vertex`: looking along the vertex's normal unless a view or an eye is given, a
//! sphere of half its shortest edge around the final level's vertex nearest it).
//! `--frames N` turns the camera once about the vertical through its target and writes
//! N pictures `OUT-000.png`, `OUT-001.png`, …
//! `--lines` draws an OBJ's polylines over the surface; an input OBJ of lines and no faces (a
//! curve network, `prism envelope --curves`) is drawn alone. `--levels-strip` draws every
//! level through one camera (`levels_strip.rs`).

use super::CliError;
use crate::cli::subdivide::steps_from;
use clap::{Args, ValueEnum};
use glam::DVec3;
use prism_geom::geometry::{face_normal_raw, unit_or_zero};
use prism_geom::{Level, Pipeline, PolyMesh, Topology};
use prism_viewport::scene::FLIPPED_COLOR;
use prism_viewport::{
    Camera, ColorBy, Offscreen, Scene, SceneOptions, SectionPlane, Shading, View,
};
use std::path::{Path, PathBuf};

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum ShadingArg {
    Flat,
    Smooth,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum ColorArg {
    Uniform,
    Kind,
    Curvature,
    Scheme,
    /// The material colour, with the last step's flipped faces in red.
    Flipped,
    /// The material colour, with the faces of the last level that pass through another face
    /// in red (`analysis::crossings`).
    Crossings,
}

#[derive(Debug, Clone, Copy, Default, ValueEnum)]
pub enum ViewArg {
    #[default]
    Iso,
    Front,
    Top,
    Right,
}

#[derive(Debug, Args)]
pub struct RenderArgs {
    /// Input mesh (.obj or .prism.json).
    pub input: PathBuf,
    /// Output PNG.
    #[arg(short, long)]
    pub output: PathBuf,
    #[command(flatten)]
    pub steps: crate::cli::subdivide::StepArgs,
    #[arg(long, value_enum, default_value = "flat")]
    pub shading: ShadingArg,
    /// Draw the polygon edges.
    #[arg(long)]
    pub wireframe: bool,
    /// Draw the previous level as a ghost cage.
    #[arg(long)]
    pub cage: bool,
    #[arg(long, value_enum, default_value = "uniform")]
    pub color_by: ColorArg,
    /// Picture size WIDTHxHEIGHT.
    #[arg(long, default_value = "1280x800")]
    pub size: String,
    /// A named view of the whole model (iso unless a free camera is asked for).
    #[arg(long, value_enum)]
    pub view: Option<ViewArg>,
    /// Where the eye is, X,Y,Z in the model's coordinates (with --target, or the model's
    /// centre).
    #[arg(long, conflicts_with = "view")]
    pub eye: Option<String>,
    /// The point looked at, X,Y,Z in the model's coordinates.
    #[arg(long)]
    pub target: Option<String>,
    /// Vertical field of view in degrees (1 to 150); the camera is placed as for the default
    /// 35°, so a smaller angle zooms in.
    #[arg(long, default_value_t = 35.0)]
    pub fov: f64,
    /// Zoom on the neighbourhood of input vertex N (0-based, as in the file).
    #[arg(long)]
    pub frame_vertex: Option<u32>,
    /// A turntable: N pictures, the camera turned 360°/N about the vertical each time,
    /// written to OUT-000.png, OUT-001.png, ...
    #[arg(long)]
    pub frames: Option<u32>,
    /// Polylines to draw over the surface: an OBJ's `l` lines (`prism envelope --curves`);
    /// an input OBJ of lines and no faces is drawn alone, in the same colour.
    #[arg(long)]
    pub lines: Option<PathBuf>,
    /// Every level, level 0 (the input) included, through one camera (framed on the input):
    /// tiles of --size side by side in OUT.png (four a row, each labelled with its level and
    /// step) and each level alone in OUT-L0.png, OUT-L1.png, …
    #[arg(long, conflicts_with_all = ["frames", "cage"])]
    pub levels_strip: bool,
    /// Every line (--lines, the wireframe, the cage) drawn through the surface: curves inside
    /// the solid show.
    #[arg(long)]
    pub xray: bool,
    /// A section plane through the level drawn: `x=0.5` keeps the part of the model where x is
    /// at most halfway along its box (y, z likewise; 0 the low side, 1 the high side),
    /// `x=0.5,above` the part beyond; the outline where the plane cuts the surface in yellow.
    #[arg(long, value_parser = parse_section)]
    pub section: Option<SectionPlane>,
}

/// `--section`: `AXIS=SHARE[,above]`.
fn parse_section(text: &str) -> Result<SectionPlane, String> {
    let (plane, side) = match text.split_once(',') {
        Some((p, "above")) => (p, true),
        Some((_, other)) => {
            return Err(format!(
                "'{other}' is not a side (write 'above' or nothing)"
            ));
        }
        None => (text, false),
    };
    let (axis, at) = plane
        .split_once('=')
        .ok_or_else(|| format!("'{plane}' is not AXIS=SHARE (e.g. x=0.5)"))?;
    let axis = match axis {
        "x" => 0,
        "y" => 1,
        "z" => 2,
        _ => return Err(format!("'{axis}' is not an axis (x, y or z)")),
    };
    let at: f64 = at.parse().map_err(|_| format!("'{at}' is not a number"))?;
    if !(0.0..=1.0).contains(&at) {
        return Err(format!("{at} is not a share of the box (0 to 1)"));
    }
    Ok(SectionPlane {
        axis,
        at,
        flip: side,
    })
}

/// The colour of the polylines.
const LINES: [f32; 3] = [0.9, 0.3, 0.05];

/// The colour of `--lines` over a lines-only input (a network's control polygons over it).
const OVER_LINES: [f32; 3] = [0.35, 0.75, 1.0];

/// The polylines of OBJ `path`.
fn read_lines(path: &Path) -> Result<Vec<Vec<DVec3>>, CliError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::input(format!("cannot read {}: {e}", path.display())))?;
    prism_geom::io::obj_polylines_from_str(path, &text).map_err(CliError::input)
}

/// The segments of `lines`.
fn segments(lines: &[Vec<DVec3>]) -> Vec<(DVec3, DVec3)> {
    lines
        .iter()
        .flat_map(|l| l.windows(2).map(|w| (w[0], w[1])))
        .collect()
}

fn parse_point(flag: &str, s: &str) -> Result<DVec3, CliError> {
    let v = super::comma_numbers(flag, s, "X,Y,Z")?;
    match v[..] {
        [x, y, z] if v.iter().all(|c| c.is_finite()) => Ok(DVec3::new(x, y, z)),
        _ => Err(CliError::usage(format!(
            "{flag} '{s}' is not three finite numbers X,Y,Z"
        ))),
    }
}

/// Input vertex `n`'s neighbourhood, from its ring in `topo`: its position, its normal (the
/// sum of its faces' area-weighted normals) and its shortest edge.
fn vertex_neighbourhood(
    mesh: &PolyMesh,
    topo: &Topology,
    n: u32,
) -> Result<(DVec3, DVec3, f64), CliError> {
    let p = *mesh.positions.get(n as usize).ok_or_else(|| {
        CliError::usage(format!(
            "--frame-vertex {n}: the input has {} vertices (0 to {})",
            mesh.num_vertices(),
            mesh.num_vertices().saturating_sub(1)
        ))
    })?;
    let (mut ring_e, mut ring_c) = (Vec::new(), Vec::new());
    topo.vertex_ring_from(mesh, topo.vert_corner[n as usize], &mut ring_e, &mut ring_c);
    let normal: DVec3 = ring_c
        .iter()
        .map(|&c| face_normal_raw(mesh, topo.corner_face(c as usize) as usize))
        .sum();
    let shortest = ring_e
        .iter()
        .map(|&(_, other)| p.distance(mesh.positions[other as usize]))
        .filter(|&len| len > 0.0)
        .fold(f64::INFINITY, f64::min);
    if !shortest.is_finite() {
        return Err(CliError::input(format!(
            "--frame-vertex {n}: vertex {n} is on no face of the input"
        )));
    }
    Ok((p, unit_or_zero(normal), shortest))
}

/// The camera the flags ask for, in the scene's coordinates.
fn camera(
    a: &RenderArgs,
    scene: &Scene,
    input: Option<(&PolyMesh, &Topology)>,
    last: &PolyMesh,
) -> Result<Camera, CliError> {
    if !(1.0..=150.0).contains(&a.fov) {
        return Err(CliError::usage(format!(
            "--fov {} is out of range (1 to 150 degrees)",
            a.fov
        )));
    }
    let fov = (a.fov as f32).to_radians();
    let named = |v: ViewArg| match v {
        ViewArg::Iso => View::Iso,
        ViewArg::Front => View::Front,
        ViewArg::Top => View::Top,
        ViewArg::Right => View::Right,
    };
    let target = a
        .target
        .as_deref()
        .map(|t| parse_point("--target", t))
        .transpose()?;
    let eye = a
        .eye
        .as_deref()
        .map(|e| parse_point("--eye", e))
        .transpose()?;
    let mut cam = Camera::looking(named(a.view.unwrap_or_default()), glam::Vec3::ZERO, 1.0);
    cam.fov_y = fov;
    let (centre, radius, normal) = match a.frame_vertex {
        Some(n) => {
            let (mesh, topo) = input.ok_or_else(|| {
                CliError::usage(format!("--frame-vertex {n}: the input has no faces"))
            })?;
            let (p, normal, shortest) = vertex_neighbourhood(mesh, topo, n)?;
            // The final level's vertex nearest the input vertex: the rounded corner.
            let near = last
                .positions
                .iter()
                .copied()
                .min_by(|x, y| x.distance_squared(p).total_cmp(&y.distance_squared(p)))
                .unwrap_or(p);
            (near, 0.5 * shortest, Some(normal))
        }
        None => (target.unwrap_or(scene.origin), scene.radius() as f64, None),
    };
    let centre = target.unwrap_or(centre);
    if let Some(eye) = eye {
        return Camera::from_eye(scene.to_local(eye), scene.to_local(centre), fov).ok_or_else(
            || CliError::usage("--eye is the point looked at: the camera has no direction"),
        );
    }
    if let (Some(n), None) = (normal, a.view)
        && n != DVec3::ZERO
    {
        let local = scene.to_local(centre);
        if let Some(c) = Camera::from_eye(local + n.as_vec3(), local, fov) {
            cam = c;
        }
    }
    // Framed with the default lens, then seen through the one asked for: a narrower field
    // of view zooms in from the same place.
    cam.fov_y = Camera::default().fov_y;
    cam.frame(scene.to_local(centre), radius as f32);
    cam.fov_y = fov;
    Ok(cam)
}

/// `OUT-007.png` for frame 7 of a turntable written to `OUT.png`.
fn frame_path(out: &Path, i: u32) -> PathBuf {
    super::levels_strip::suffixed(out, &format!("{i:03}"), "frame")
}

fn parse_size(s: &str) -> Option<(u32, u32)> {
    let (w, h) = s.split_once(['x', 'X'])?;
    Some((w.trim().parse().ok()?, h.trim().parse().ok()?))
}

pub fn run(a: RenderArgs) -> Result<(), CliError> {
    super::check_output(&a.output, None)?;
    let (w, h) = parse_size(&a.size)
        .ok_or_else(|| CliError::usage(format!("--size '{}' is not WIDTHxHEIGHT", a.size)))?;
    if a.frames == Some(0) {
        return Err(CliError::usage(
            "--frames 0: a turntable needs at least one frame",
        ));
    }
    let over = a.lines.as_deref().map(read_lines).transpose()?;
    let (doc, numbering) = super::load_input(&a.input)?;
    if doc.mesh.num_faces() == 0 {
        // An OBJ of lines and no faces (a curve network): drawn alone.
        let lines = read_lines(&a.input)?;
        if !lines.is_empty() {
            return render_lines(&a, (w, h), &lines, over.as_deref());
        }
    }
    let topo = Topology::build(&doc.mesh).map_err(|e| {
        CliError::input(format!("{}: {}", a.input.display(), numbering.describe(&e)))
    })?;
    let steps = steps_from(&a.steps, doc.pipeline.as_deref(), true)?;
    let mut pipeline = Pipeline::with_tags(doc.mesh, doc.edge_attrs, doc.tags, steps);
    // Every level is kept (the cage is the one before). The scene: three vertices of about
    // 48 bytes a triangle with its indices, copied into the GPU's buffers through staging
    // ones (on software Vulkan all of it in main memory: about 500 bytes a triangle
    // measured), its lines, and the picture at 4× multisampling with its depth.
    let last = pipeline.predicted_counts();
    let scene = 500 * last.triangles() + 64 * last.edges + 40 * u64::from(w) * u64::from(h);
    let budget = a.steps.memory.check(
        pipeline.estimate_peak_then(scene),
        "this picture",
        "give fewer levels or a smaller --size",
    )?;
    pipeline.options = a.steps.options(budget);
    let mut warnings = super::level_lines::LevelWarnings::new(&pipeline.levels()[0].mesh);
    let n = pipeline.steps().len();
    let last = pipeline
        .compute_with(n, |k, level| {
            let r = level.report.as_ref();
            warnings.level(k, r.expect("computed levels have a report"));
        })
        .map_err(|e| CliError::input(e.describe(&numbering)))?
        .clone();
    let levels = pipeline.levels();
    let prev = (levels.len() > 1).then(|| &levels[levels.len() - 2].mesh);
    let opts = SceneOptions {
        shading: match a.shading {
            ShadingArg::Flat => Shading::Flat,
            ShadingArg::Smooth => Shading::Smooth,
        },
        color_by: match a.color_by {
            ColorArg::Uniform | ColorArg::Flipped | ColorArg::Crossings => ColorBy::Uniform,
            ColorArg::Kind => ColorBy::Kind,
            ColorArg::Curvature => ColorBy::Curvature,
            ColorArg::Scheme => {
                ColorBy::Solid(prism_viewport::scene::scheme_color(pipeline.steps().last()))
            }
        },
        wireframe: a.wireframe,
        section: a.section,
        ..SceneOptions::default()
    };
    if a.section.is_some() && matches!(a.color_by, ColorArg::Crossings) {
        return Err(CliError::usage(
            "--section draws the faces it cuts anew: --color-by crossings needs the whole level",
        ));
    }
    let has_kinds = last
        .provenance
        .as_ref()
        .and_then(|p| p.face_kinds())
        .is_some();
    if matches!(a.color_by, ColorArg::Kind) && !has_kinds {
        eprintln!("note: --color-by kind needs a biquadratic last step; drawing one colour");
    }
    // A level's scene: its faces painted as --color-by asks, the --lines over it.
    let scene_of = |lv: &Level, say: bool| {
        let mut scene = Scene::of_level(lv, &opts);
        if matches!(a.color_by, ColorArg::Flipped) {
            let flipped = lv.report.as_ref().map_or(&[][..], |r| &r.flipped[..]);
            // A section paints the flipped faces it keeps itself.
            if a.section.is_none() {
                scene.paint_faces(&lv.mesh, flipped, FLIPPED_COLOR);
            }
            if say {
                println!("{} flipped face(s) drawn in red", flipped.len());
            }
        }
        if matches!(a.color_by, ColorArg::Crossings) {
            let pairs = prism_geom::analysis::crossings(&lv.mesh);
            let faces = prism_geom::analysis::crossing_faces(&pairs);
            scene.paint_faces(&lv.mesh, &faces, FLIPPED_COLOR);
            if say {
                println!(
                    "{} face(s) that pass through another drawn in red ({} pair(s))",
                    faces.len(),
                    pairs.len()
                );
            }
        }
        if let Some(l) = &over {
            scene.add_segments(&segments(l), LINES);
        }
        scene.xray = a.xray;
        scene
    };
    let input = (&pipeline.levels()[0].mesh, &topo);
    if a.levels_strip {
        let first = scene_of(&levels[0], false);
        let camera = camera(&a, &first, Some(input), &last.mesh)?;
        super::levels_strip::render(
            &a.output,
            (w, h),
            levels,
            pipeline.steps(),
            &first,
            &camera,
            |lv| scene_of(lv, false),
        )?;
        println!(
            "rendered {} levels at {w}x{h} through one camera; wrote {} and {} … {}",
            levels.len(),
            a.output.display(),
            super::levels_strip::level_path(&a.output, 0).display(),
            super::levels_strip::level_path(&a.output, levels.len() - 1).display(),
        );
        return Ok(());
    }
    let mut scene = scene_of(&last, true);
    if let (true, Some(p)) = (a.cage, prev) {
        scene.add_cage(p, [0.95, 0.75, 0.25]);
    }
    let camera = camera(&a, &scene, Some(input), &last.mesh)?;
    draw(&a, (w, h), &scene, camera)
}

/// Polylines alone (and those of `--lines`), framed as the whole model is.
fn render_lines(
    a: &RenderArgs,
    size: (u32, u32),
    lines: &[Vec<DVec3>],
    over: Option<&[Vec<DVec3>]>,
) -> Result<(), CliError> {
    if a.cage || a.steps.scheme.is_some() || a.steps.pipeline.is_some() {
        return Err(CliError::usage(format!(
            "{}: lines and no faces: nothing to subdivide or cage",
            a.input.display()
        )));
    }
    // A mesh of the lines' points and no faces: the scene's origin and box, nothing drawn.
    let mut points = PolyMesh::new();
    points.positions = lines
        .iter()
        .chain(over.unwrap_or_default())
        .flatten()
        .copied()
        .collect();
    let mut scene = Scene::plain(&points);
    scene.add_segments(&segments(lines), LINES);
    if let Some(l) = over {
        scene.add_segments(&segments(l), OVER_LINES);
    }
    let camera = camera(a, &scene, None, &PolyMesh::new())?;
    draw(a, size, &scene, camera)
}

/// Renders `scene` through `camera` (turned for each frame of a turntable) and writes it.
fn draw(
    a: &RenderArgs,
    (w, h): (u32, u32),
    scene: &Scene,
    mut camera: Camera,
) -> Result<(), CliError> {
    let gpu = Offscreen::new().map_err(CliError::input)?;
    let uploaded = gpu.upload(scene).map_err(CliError::input)?;
    let frames = a.frames.unwrap_or(1);
    let t = std::time::Instant::now();
    for i in 0..frames {
        let img = gpu
            .render_uploaded(&uploaded, &camera, w, h)
            .map_err(CliError::input)?;
        let path = match a.frames {
            Some(_) => frame_path(&a.output, i),
            None => a.output.clone(),
        };
        super::write_png(img.into(), &path)?;
        camera.orbit(std::f32::consts::TAU / frames as f32, 0.0);
    }
    let ms = t.elapsed().as_secs_f64() * 1e3 / frames as f64;
    let wrote = match a.frames {
        Some(n) => format!(
            "{n} frames {} … {}",
            frame_path(&a.output, 0).display(),
            frame_path(&a.output, n - 1).display()
        ),
        None => a.output.display().to_string(),
    };
    println!(
        "rendered {} triangles and {} line segments at {w}x{h} in {ms:.1} ms per frame on {} ({:?}); wrote {wrote}",
        scene.triangles(),
        scene.lines.len() / 2,
        gpu.adapter_info.name,
        gpu.adapter_info.device_type,
    );
    Ok(())
}
