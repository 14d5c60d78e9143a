//! `prism bench IN --scheme S [--radius R …] --levels N [--runs 5]`: loads the file once, then times the
//! refinement from the face lists as read (the half-edge topology is built inside the timed
//! region, as OpenSubdiv's `TopologyRefinerFactory::Create` is inside its) and prints the
//! median as `time_ms=<median>`, every run, and the peak resident memory of the process.
//! Single thread.

use super::CliError;
use clap::Args;
use prism_geom::pipeline::Keep;
use prism_geom::{Pipeline, Scheme, parse_pipeline, refine_primal_levels};
use std::path::PathBuf;
use std::time::Instant;

#[derive(Debug, Args)]
pub struct BenchArgs {
    /// Input mesh (.obj or .prism.json).
    pub input: PathBuf,
    /// The step repeated --levels times: a scheme's name with its parameter flag, as
    /// `subdivide` takes it (`--scheme combination --radius 0.2`), or the pipeline's text form
    /// (`combination:r=0.2`, `cut-width:d=0.1`, `doo-sabin`, `catmull-clark`).
    #[arg(long)]
    pub scheme: String,
    #[command(flatten)]
    pub params: super::subdivide::ParamArgs,
    /// Number of levels.
    #[arg(long, default_value_t = 1)]
    pub levels: usize,
    /// Timed runs; the median is reported.
    #[arg(long, default_value_t = 5)]
    pub runs: usize,
    /// Time an edit as the app sees it instead: a cage vertex moved, every level recomputed
    /// with everything the app keeps (all levels, their provenance), and the scene of the
    /// last level built (triangles, normals, colours: the vertex buffers); prints each part.
    #[arg(long)]
    pub edit: bool,
    #[command(flatten)]
    pub memory: super::MemoryArgs,
}

/// Peak resident set size of this process in bytes (Linux `VmHWM`), if known.
fn peak_rss() -> Option<u64> {
    let s = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = s.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

pub fn run(a: BenchArgs) -> Result<(), CliError> {
    let p = &a.params;
    let flags = [p.alpha, p.radius, p.distance, p.width]
        .iter()
        .any(Option::is_some);
    let step = if a.scheme.contains([':', ',']) {
        if flags || p.reflex_inward {
            return Err(CliError::usage(format!(
                "--scheme {} already has its parameter: give it there or as a flag, not both",
                a.scheme
            )));
        }
        parse_pipeline(&a.scheme).map_err(CliError::usage)?
    } else {
        vec![super::subdivide::scheme_from_flags(&a.scheme, &a.params)?]
    };
    if step.len() != 1 {
        return Err(CliError::usage(
            "--scheme takes one scheme (use it with --levels)",
        ));
    }
    super::check_levels(a.levels)?;
    if a.runs == 0 || a.levels == 0 {
        return Err(CliError::usage("--runs and --levels must be at least 1"));
    }
    let steps = vec![step[0]; a.levels];
    let (loaded, _) = super::load_input(&a.input)?;
    println!(
        "input: {} vertices, {} faces; {} × {}",
        loaded.mesh.num_vertices(),
        loaded.mesh.num_faces(),
        a.levels,
        step[0]
    );
    let mut times = Vec::with_capacity(a.runs);
    let mut faces = 0;
    // A run holds a copy of the input, the level it steps from and the new one, beside the
    // input loaded once (the estimate's pipeline holds the input, then gives it back).
    let mut estimate =
        Pipeline::with_tags(loaded.mesh, loaded.edge_attrs, loaded.tags, steps.clone());
    estimate.keep = Keep::Needed;
    let peak = estimate.estimate_peak() + estimate.input().bytes();
    let budget = a
        .memory
        .check(peak, "this benchmark", "give fewer levels")?;
    let doc = estimate.into_last();
    if a.edit {
        return edit(doc, steps, budget, a.runs);
    }
    for run in 1..=a.runs {
        let t = Instant::now();
        if let Scheme::Primal(scheme) = step[0] {
            // The refinement alone (no report extras), the topology of levels after the
            // first written down from the split.
            let out = refine_primal_levels(
                &doc.mesh,
                &doc.edge_attrs,
                &doc.tags,
                scheme,
                a.levels,
                budget,
            )
            .map_err(CliError::input)?;
            faces = out.mesh.num_faces();
        } else {
            let mut p = Pipeline::with_tags(
                doc.mesh.clone(),
                doc.edge_attrs.clone(),
                doc.tags.clone(),
                steps.clone(),
            );
            p.options.memory_budget = budget;
            p.keep = Keep::Needed;
            faces = p.compute().map_err(CliError::input)?.mesh.num_faces();
        }
        let ms = t.elapsed().as_secs_f64() * 1e3;
        println!("run {run}: {ms:.2} ms");
        times.push(ms);
    }
    times.sort_by(f64::total_cmp);
    let median = times[times.len() / 2];
    println!("faces={faces}");
    println!("time_ms={median:.2}");
    match peak_rss() {
        Some(b) => println!("peak_memory_mb={:.1}", b as f64 / (1 << 20) as f64),
        None => println!("peak_memory_mb=unknown"),
    }
    Ok(())
}

/// `--edit`: vertex 0 moved by a thousandth of the solid's size (alternately up and back),
/// then the levels and the last level's scene, as the app's view computes them: the first
/// run from scratch, every later one from the run before ([`Pipeline::moved`]).
fn edit(
    doc: prism_geom::Level,
    steps: Vec<Scheme>,
    budget: u64,
    runs: usize,
) -> Result<(), CliError> {
    use crate::gui::model::view_pipe::level_scene;
    let nudge = 1e-3 * doc.mesh.bbox_diagonal();
    let mut mesh = doc.mesh.clone();
    let (mut compute, mut scene, mut total) = (Vec::new(), Vec::new(), Vec::new());
    let mut faces = 0;
    let opts = prism_viewport::SceneOptions::default();
    let mut last: Option<Pipeline> = None;
    for run in 1..=runs {
        if let Some(p) = mesh.positions.first_mut() {
            p.z += if run % 2 == 1 { nudge } else { -nudge };
        }
        let t = Instant::now();
        // As the app does: from the pipeline before, keeping what the move leaves as it was
        // (the primal steps' faces and topology), or afresh the first time.
        let mut p = match last.take() {
            Some(before) => Pipeline::moved(&before, mesh.positions.clone()),
            None => {
                let mut p = Pipeline::with_tags(
                    mesh.clone(),
                    doc.edge_attrs.clone(),
                    doc.tags.clone(),
                    steps.clone(),
                );
                p.options.memory_budget = budget;
                p.options.overlap = prism_geom::rules::Overlap::Clamp;
                p
            }
        };
        let result = p.compute().map(|_| ());
        let computed = t.elapsed().as_secs_f64() * 1e3;
        result.map_err(CliError::input)?;
        let k = p.levels().len() - 1;
        let s = level_scene(&p.levels()[k], steps.last().copied(), &opts);
        let all = t.elapsed().as_secs_f64() * 1e3;
        faces = p.levels()[k].mesh.num_faces();
        println!(
            "run {run}: levels {computed:.2} ms + scene {:.2} ms = {all:.2} ms ({} triangles)",
            all - computed,
            s.indices.len() / 3
        );
        compute.push(computed);
        scene.push(all - computed);
        total.push(all);
        last = Some(p);
    }
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    println!("faces={faces}");
    println!("levels_ms={:.2}", median(&mut compute));
    println!("scene_ms={:.2}", median(&mut scene));
    println!("edit_ms={:.2}", median(&mut total));
    Ok(())
}
