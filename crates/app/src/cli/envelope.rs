//! `prism envelope SCENE.json -o OUT.obj|.prism.json|.stl|.glb [--t T] [--resolution K]
//! [--patches charts|paper] [--enclosure lifted|paper] [--basis virtual|one-sided] [--curves CURVES.obj] [--control-polygons CONTROL.obj]`: a smooth surface enveloping convex primitives (seed 004;
//! docs/algorithms/envelope.md). SCENE is `{"t": 1.0, "primitives": [{"vertices": [[x, y, z],
//! ...], "faces": [[i, ...], ...], "t": optional, "vertex_t": [optional, per vertex]}]}`, or a
//! `.prism.json` with an `"envelope"` block of that form. Primitives, vertices and faces are
//! numbered from 0 as listed.

use super::CliError;
use clap::Args;
use prism_geom::freeform::envelope::{CurveKind, Envelope, EnvelopeSpec, Surfacing, envelope};
use prism_geom::io::{self, Document};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The written mesh is checked for faces that pass through each other up to this many faces.
const CROSSING_CHECK_FACES: usize = 1_000_000;

#[derive(Debug, Args)]
pub struct EnvelopeArgs {
    /// Scene: {"t": 1.0, "primitives": [{"vertices": [[x, y, z], ...], "faces": [[i, ...], ...]}]}, or a .prism.json with an "envelope" block.
    pub input: PathBuf,
    /// Output: .obj, .prism.json, .stl or .glb.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Curvature parameter t of every vertex (ρ = t·r), replacing the scene's: 1 gives arcs on
    /// each primitive's sphere, smaller values tend to the flat faces.
    #[arg(long, allow_negative_numbers = true)]
    pub t: Option<f64>,
    /// Resolution (1 to 256; default: the scene's, else 8): about this many mesh edges along a
    /// primitive's edge (charts), or quads along each side of a patch (paper).
    #[arg(long)]
    pub resolution: Option<usize>,
    /// How the regions are filled: `charts` (scalar graphs over flat charts: cannot fold) or
    /// `paper` (seed 004 §6's vector Coons patches, for comparison; default: the scene's, else
    /// charts).
    #[arg(long, value_parser = ["charts", "paper"])]
    pub patches: Option<String>,
    /// What holds the corners the silhouette plane through each centre cuts off: `lifted`
    /// (the fusion strips, and the lids beside them, raised over them; the quality line names any
    /// primitive still out) or `paper` (the paper's
    /// central cut as it lies, for the teaching gallery; default: the scene's, else lifted).
    /// The charts only.
    #[arg(long, value_parser = ["lifted", "paper"])]
    pub enclosure: Option<String>,
    /// G1 construction of the borders: `virtual` (both sides from the crossing curves;
    /// independent of the listing) or `one-sided` (the paper's: the region listed first leads
    /// each border; default: the scene's, else virtual).
    #[arg(long, value_parser = ["virtual", "one-sided"])]
    pub basis: Option<String>,
    /// Also write the curve network as OBJ polylines (32 segments uniform in each curve's
    /// parameter).
    #[arg(long)]
    pub curves: Option<PathBuf>,
    /// Also write every curve's rational Bézier control polygon as an OBJ polyline (its
    /// weights in a comment), to draw with `prism render --lines`.
    #[arg(long)]
    pub control_polygons: Option<PathBuf>,
    /// Replace a read-only output file (it keeps its permission bits).
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub memory: super::MemoryArgs,
}

/// The scene of a file: the file itself, or its `"envelope"` block (a `.prism.json`).
pub fn read_scene(path: &Path) -> Result<EnvelopeSpec, CliError> {
    let text = super::read_text(path)?;
    io::scene_from_str(path, &text).map_err(|e| CliError::input(e.to_string()))
}

/// The network as OBJ polylines, one a curve: `segments` chords uniform in its parameter, or
/// (`control`) its rational Bézier control polygon, the weights in the curve's comment
/// (seed 004 figs. 2–3).
fn curves_obj(e: &Envelope, segments: usize, control: bool) -> String {
    let mut out = String::from(if control {
        "# Prism envelope curve network: each curve's rational Bezier control polygon\n"
    } else {
        "# Prism envelope curve network: one polyline a curve, uniform in its parameter\n"
    });
    let mut base = 1;
    // A triangle's collapsed tip is a curve of one point: no polyline.
    for (i, c) in e
        .network
        .curves
        .iter()
        .enumerate()
        .filter(|(_, c)| !c.is_point())
    {
        let kind = match c.kind {
            CurveKind::Edge => "primitive edge",
            CurveKind::Silhouette => "silhouette edge",
            CurveKind::Fusion => "fusion edge",
            CurveKind::Insertion => "insertion curve",
        };
        let points: Vec<glam::DVec3> = if control {
            let w: Vec<String> = c.bezier.weights.iter().map(|w| format!("{w:.6}")).collect();
            let _ = writeln!(out, "# curve {i}: {kind}, weights {}", w.join(" "));
            c.bezier.points.clone()
        } else {
            let _ = writeln!(out, "# curve {i}: {kind}");
            (0..=segments)
                .map(|j| c.bezier.eval(j as f64 / segments as f64))
                .collect()
        };
        for p in &points {
            let p = e.frame.to_world(*p);
            let _ = writeln!(out, "v {} {} {}", p.x, p.y, p.z);
        }
        let ids: Vec<String> = (base..base + points.len()).map(|k| k.to_string()).collect();
        let _ = writeln!(out, "l {}", ids.join(" "));
        base += points.len();
    }
    out
}

pub fn run(a: EnvelopeArgs) -> Result<(), CliError> {
    super::check_solid_output_kind(&a.output)?;
    super::check_output(&a.output, Some(a.force))?;
    super::check_not_lossy(&a.output, &a.input, "envelope")?;
    let mut spec = read_scene(&a.input)?;
    if let Some(t) = a.t {
        spec.t = t;
        for p in &mut spec.primitives {
            p.t = None;
            p.vertex_t = None;
        }
    }
    if let Some(k) = a.resolution {
        spec.resolution = k;
    }
    match a.patches.as_deref() {
        Some("paper") => spec.patches = Surfacing::Paper,
        Some(_) => spec.patches = Surfacing::Charts,
        None => {}
    }
    match a.enclosure.as_deref() {
        Some("paper") => spec.enclosure = prism_geom::freeform::envelope::Enclosure::Paper,
        Some(_) => spec.enclosure = prism_geom::freeform::envelope::Enclosure::Lifted,
        None => {}
    }
    match a.basis.as_deref() {
        Some("one-sided") => spec.basis = prism_geom::freeform::Basis::OneSided,
        Some(_) => spec.basis = prism_geom::freeform::Basis::Virtual,
        None => {}
    }
    if spec.resolution == 0 || spec.resolution > 256 {
        return Err(CliError::usage(format!(
            "--resolution {} is out of range: 1 to 256",
            spec.resolution
        )));
    }
    // The construction's memory, from the primitives alone, before it is built.
    let construction = spec.construction_bytes();
    let knob = "give a smaller --resolution or fewer primitives";
    let alone = construction + prism_geom::memory::BASELINE;
    a.memory.refuse_over(alone, "this envelope", knob)?;
    let start = Instant::now();
    let e = envelope(&spec).map_err(|e| CliError::input(format!("{}: {e}", a.input.display())))?;
    let millis = start.elapsed().as_secs_f64() * 1e3;
    // The mesh's counts estimated from the charts at a low resolution; on top of the mesh,
    // the quality report's maps and the crossing check.
    let counts = e.mesh_counts(spec.resolution);
    let export = prism_geom::memory::export_bytes(&counts, io::ExportFormat::of(&a.output));
    a.memory
        .check(
            construction + prism_geom::memory::surface_bytes(&counts) + export,
            "this envelope",
            knob,
        )
        .map(|_| ())?;
    let (mesh, quality) = e.quality(spec.resolution).map_err(CliError::input)?;
    let counts = prism_geom::analysis::counts(&mesh);
    let folds = e.folds();
    // The written mesh, when the check is affordable (3 s and 70 MB a million faces).
    let crossings = (mesh.num_faces() <= CROSSING_CHECK_FACES)
        .then(|| prism_geom::freeform::envelope::folds::crossings(&mesh));
    println!(
        "primitives={} regions={} patches={} removed={} time_ms={millis:.3} surface={} folded={} crossings={} largest normal jump across patch borders {:.2e}°",
        e.primitives.len(),
        e.regions,
        e.patch_count(),
        e.removed.len(),
        e.surfacing.name(),
        folds.len(),
        crossings
            .as_ref()
            .map_or("unchecked".to_string(), |c| c.len().to_string()),
        e.largest_border_jump()
    );
    let crossed = crossings
        .as_ref()
        .and_then(|c| e.crossing_warning(c, spec.resolution));
    println!("quality: {}", quality.summary());
    for w in [
        e.fold_warning(&folds),
        crossed,
        quality.enclosure_warning(&e.removed),
    ]
    .into_iter()
    .flatten()
    {
        eprintln!("warning: {w}");
    }
    if crossings.is_none() {
        eprintln!(
            "note: {} faces: not checked for faces that pass through each other (at most {CROSSING_CHECK_FACES}; a lower --resolution is checked)",
            mesh.num_faces()
        );
    }
    if let Some(note) = e.removed_note() {
        println!("{note}");
    }
    if let Some(path) = &a.control_polygons {
        io::write_atomically(path, curves_obj(&e, 32, true).as_bytes()).map_err(CliError::input)?;
        println!("wrote {} (control polygons)", path.display());
    }
    if let Some(path) = &a.curves {
        io::write_atomically(path, curves_obj(&e, 32, false).as_bytes())
            .map_err(CliError::input)?;
        println!(
            "wrote {} ({} curves)",
            path.display(),
            e.network.curves.iter().filter(|c| !c.is_point()).count()
        );
    }
    let doc = Document {
        mesh,
        envelope: Some(spec.clone()),
        ..Document::default()
    };
    super::write_surface(&a.output, a.force, &doc)?;
    let density = match e.surfacing {
        Surfacing::Charts => format!("about {} edges along a primitive's edge", spec.resolution),
        Surfacing::Paper => format!("{0}×{0} quads a patch", spec.resolution),
    };
    println!(
        "{} vertices, {} faces ({density}); wrote {}",
        counts.vertices,
        counts.faces,
        a.output.display()
    );
    Ok(())
}
