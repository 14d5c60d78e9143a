//! `prism render IN -o OUT.png [--pipeline P | --scheme S --levels N ...] [--shading flat|smooth]
//! [--wireframe] [--cage] [--color-by kind|uniform|curvature|scheme] [--size 1280x800] [--view iso|front|top]`:
//! a headless picture with the viewport's renderer, on any adapter (Mesa's software Vulkan
//! on a machine without a GPU).

use super::CliError;
use crate::cli::subdivide::steps_from;
use clap::{Args, ValueEnum};
use prism_geom::io;
use prism_geom::refine::FaceKind;
use prism_geom::{Pipeline, Topology};
use prism_viewport::{Camera, ColorBy, Offscreen, Scene, SceneOptions, Shading, View};
use std::path::PathBuf;

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
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum ViewArg {
    Iso,
    Front,
    Top,
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
    #[arg(long, value_enum, default_value = "iso")]
    pub view: ViewArg,
}

fn parse_size(s: &str) -> Option<(u32, u32)> {
    let (w, h) = s.split_once(['x', 'X'])?;
    Some((w.trim().parse().ok()?, h.trim().parse().ok()?))
}

pub fn run(a: RenderArgs) -> Result<(), CliError> {
    let (w, h) = parse_size(&a.size)
        .ok_or_else(|| CliError::usage(format!("--size '{}' is not WIDTHxHEIGHT", a.size)))?;
    let (doc, _) = io::load(&a.input).map_err(CliError::input)?;
    Topology::build(&doc.mesh)
        .map_err(|e| CliError::input(format!("{}: {e}", a.input.display())))?;
    let steps = steps_from(&a.steps, doc.pipeline.as_deref(), true)?;
    let mut pipeline = Pipeline::with_tags(doc.mesh, doc.edge_attrs, doc.tags, steps);
    pipeline.options = a.steps.options();
    let mut warnings = super::subdivide::LevelWarnings::new(&pipeline.levels()[0].mesh);
    let n = pipeline.steps().len();
    let last = pipeline
        .compute_with(n, |k, level| {
            let r = level.report.as_ref();
            warnings.level(k, r.expect("computed levels have a report"));
        })
        .map_err(CliError::input)?
        .clone();
    warnings.finish()?;
    let levels = pipeline.levels();
    let prev = (levels.len() > 1).then(|| &levels[levels.len() - 2].mesh);
    let opts = SceneOptions {
        shading: match a.shading {
            ShadingArg::Flat => Shading::Flat,
            ShadingArg::Smooth => Shading::Smooth,
        },
        color_by: match a.color_by {
            ColorArg::Uniform => ColorBy::Uniform,
            ColorArg::Kind => ColorBy::Kind,
            ColorArg::Curvature => ColorBy::Curvature,
            ColorArg::Scheme => {
                ColorBy::Solid(prism_viewport::scene::scheme_color(pipeline.steps().last()))
            }
        },
        wireframe: a.wireframe,
        ..SceneOptions::default()
    };
    let kinds: Option<&[FaceKind]> = last.provenance.as_ref().and_then(|p| p.face_kinds());
    if matches!(a.color_by, ColorArg::Kind) && kinds.is_none() {
        eprintln!("note: --color-by kind needs a biquadratic last step; drawing one colour");
    }
    let holes = &last.tags.holes;
    let mut scene = Scene::build(
        &last.mesh,
        &last.edge_attrs,
        kinds,
        &|f| holes.contains(&(f as u32)),
        &opts,
    );
    if let (true, Some(p)) = (a.cage, prev) {
        scene.add_cage(p, [0.95, 0.75, 0.25]);
    }
    let view = match a.view {
        ViewArg::Iso => View::Iso,
        ViewArg::Front => View::Front,
        ViewArg::Top => View::Top,
    };
    let camera = Camera::looking(view, glam::Vec3::ZERO, scene.radius());
    let gpu = Offscreen::new().map_err(CliError::input)?;
    let t = std::time::Instant::now();
    let img = gpu.render(&scene, &camera, w, h).map_err(CliError::input)?;
    let ms = t.elapsed().as_secs_f64() * 1e3;
    let mut png = Vec::new();
    img.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .map_err(|e| CliError::input(format!("encoding the PNG: {e}")))?;
    io::write_atomically(&a.output, &png).map_err(CliError::input)?;
    println!(
        "rendered {} triangles at {w}x{h} in {ms:.1} ms on {} ({:?}); wrote {}",
        scene.triangles(),
        gpu.adapter_info.name,
        gpu.adapter_info.device_type,
        a.output.display()
    );
    Ok(())
}
