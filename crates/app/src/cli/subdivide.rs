//! `prism subdivide IN -o OUT (--scheme S --levels N [params] | --pipeline P)`.
//!
//! Prints one summary line per level (vertices, edges, faces, flipped faces, milliseconds)
//! and every warning in words: flipped or degenerate faces, a solid turned inside out,
//! dissolved flat edges, the minimum type's stall.

use super::CliError;
use clap::Args;
use prism_geom::analysis::measure_fillet;
use prism_geom::io::{self, Document};
use prism_geom::pipeline::Keep;
use prism_geom::scheme::{Scheme, SchemeError, SchemeKind, parse_pipeline};
use prism_geom::{CornerRule, Pipeline, ReflexMode, Topology};
use std::path::{Path, PathBuf};

/// The parameter of a scheme given by name (shared by `subdivide`, `render` and `bench`).
#[derive(Debug, Args)]
pub struct ParamArgs {
    /// α of vector-sum (0 < α < 0.5).
    #[arg(long, allow_negative_numbers = true)]
    pub alpha: Option<f64>,
    /// Radius r of cylindrical, minimum and combination.
    #[arg(long, allow_negative_numbers = true)]
    pub radius: Option<f64>,
    /// Distance l of angle-bisector.
    #[arg(long, allow_negative_numbers = true)]
    pub distance: Option<f64>,
    /// Width d of cut-width.
    #[arg(long, allow_negative_numbers = true)]
    pub width: Option<f64>,
    /// vector-sum: reverse the displacement at reflex corners (the paper's remark).
    #[arg(long)]
    pub reflex_inward: bool,
}

/// The steps to run: one scheme repeated, or a pipeline (shared by `subdivide` and
/// `render`).
#[derive(Debug, Args)]
pub struct StepArgs {
    /// Scheme repeated --levels times (`prism schemes` lists them: the biquadratic ones
    /// need closed solids, the primal ones take open meshes too, with the file's creases,
    /// corners and holes).
    #[arg(long, conflicts_with = "pipeline")]
    pub scheme: Option<String>,
    /// Number of levels for --scheme.
    #[arg(long, default_value_t = 1)]
    pub levels: usize,
    #[command(flatten)]
    pub params: ParamArgs,
    /// Steps separated by commas, e.g. "vector-sum:alpha=0.2,doo-sabin,doo-sabin".
    #[arg(long)]
    pub pipeline: Option<String>,
    /// Lower the radius of edges whose rounds do not fit their faces to what fits, and say
    /// which (without it such a step is refused, naming them); lower a chamfer's l or d on
    /// faces too small for it (a quarter of the shorter edge at each corner) and the vector
    /// sum's α on faces whose reflex corners would cross them; where a chamfer's or the
    /// minimum type's new face would still turn over, smooth it or chamfer its vertices small.
    #[arg(long)]
    pub clamp: bool,
    /// After each rounding, search the whole level for faces that pass through each other
    /// and give the rounding up for a small chamfer at their vertices where they do (the
    /// default, as in the app).
    #[arg(long, overrides_with = "no_mend_crossings")]
    pub mend_crossings: bool,
    /// Do not search the whole level for crossings after a rounding (several times faster on
    /// big levels; only crossings beside the fold guard's moves are then looked for).
    #[arg(long, overrides_with = "mend_crossings")]
    pub no_mend_crossings: bool,
    /// With --scheme angle-bisector or cut-width: divide l or d by K at each step after the
    /// first (seed 000: about 4, so that the new faces are not cut from both sides).
    #[arg(long, value_name = "K")]
    pub shrink: Option<f64>,
    #[command(flatten)]
    pub memory: super::MemoryArgs,
}

impl StepArgs {
    /// The step options these arguments ask for, under the budget `--memory-budget` gave
    /// ([`super::MemoryArgs::check`]).
    pub fn options(&self, memory_budget: u64) -> prism_geom::RoundingOptions {
        prism_geom::RoundingOptions {
            overlap: prism_geom::rules::Overlap::clamping(self.clamp),
            memory_budget,
            mend: prism_geom::rules::MendOptions {
                crossings: !self.no_mend_crossings,
                ..Default::default()
            },
            ..Default::default()
        }
    }
}

#[derive(Debug, Args)]
pub struct SubdivideArgs {
    /// Input solid (.obj or .prism.json).
    pub input: PathBuf,
    /// Output file: .obj or .prism.json (with creases and tags), or .stl / .glb (triangles).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Replace a read-only output file (it keeps its permission bits).
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub steps: StepArgs,
    /// Report the fillet reached on these edges, A-B[,C-D...] (vertices of the input,
    /// 0-based, as in the file).
    #[arg(long)]
    pub measure_edge: Option<String>,
    /// With --measure-edge: draw the first edge's section at every level of the rounding run
    /// against the target circle (seed 000 fig. 8) into this PNG.
    #[arg(long, requires = "measure_edge")]
    pub plot: Option<PathBuf>,
    /// Also look at every level for faces that pass through each other (both still facing
    /// outward, which the flipped count cannot see): `crossings=N` in each level's line and
    /// a warning naming the first pair. Takes about as long as the step on big levels.
    #[arg(long)]
    pub check_crossings: bool,
    /// Normals of the output: `smooth` (split at edges sharper than 40°, as the app's smooth
    /// shading) or `flat` (one a face). glTF always carries them (smooth unless told); OBJ
    /// gets a `vn` a corner only when this is given; STL's are its facets'.
    #[arg(long, value_parser = ["smooth", "flat"])]
    pub normals: Option<String>,
}

/// The steps the arguments ask for; without any, the document's pipeline, or none when
/// `allow_none` (render the input as it is).
pub fn steps_from(
    a: &StepArgs,
    document: Option<&[Scheme]>,
    allow_none: bool,
) -> Result<Vec<Scheme>, CliError> {
    super::check_levels(a.levels)?;
    if a.scheme.is_some() && a.levels == 0 {
        return Err(CliError::usage(
            "--levels 0 refines nothing: give 1 or more (without --scheme the input is written as it is)",
        ));
    }
    let steps: Vec<Scheme> = match (&a.scheme, &a.pipeline) {
        (Some(name), None) => {
            let s = scheme_from_flags(name, &a.params)?;
            match a.shrink {
                None => vec![s; a.levels],
                Some(k) if !(k.is_finite() && k >= 1.0) => {
                    return Err(CliError::usage(format!(
                        "--shrink {k}: K must be a number of at least 1"
                    )));
                }
                Some(_) if !s.shrinks_when_repeated() => {
                    return Err(CliError::usage(format!(
                        "--shrink applies to angle-bisector and cut-width (absolute l, d), not {name}"
                    )));
                }
                Some(k) => s.schedule(a.levels, k),
            }
        }
        (None, Some(_)) if a.shrink.is_some() => {
            return Err(CliError::usage(
                "--shrink goes with --scheme; in a pipeline write each step's l or d",
            ));
        }
        (None, Some(p)) => parse_pipeline(p).map_err(CliError::usage)?,
        _ => Vec::new(),
    };
    if !steps.is_empty() {
        warn_unrepeatable(&steps);
        return Ok(steps);
    }
    match document {
        Some(p) => {
            warn_unrepeatable(p);
            Ok(p.to_vec())
        }
        None if allow_none => Ok(Vec::new()),
        None => Err(CliError::usage(
            "give --scheme and --levels, or --pipeline (the input holds no pipeline)",
        )),
    }
}

/// The scheme `--scheme NAME` names, with its parameter from the flag the catalogue gives
/// it; a parameter flag the scheme does not use is refused.
pub fn scheme_from_flags(name: &str, a: &ParamArgs) -> Result<Scheme, CliError> {
    let kind = SchemeKind::from_name(name)
        .ok_or_else(|| CliError::usage(SchemeError::Unknown(name.to_string())))?;
    let entry = kind.entry();
    let flags = [
        ("alpha", a.alpha),
        ("radius", a.radius),
        ("distance", a.distance),
        ("width", a.width),
    ];
    let wanted = entry.param.map(|p| p.flag);
    if let Some((flag, _)) = flags
        .iter()
        .find(|(f, v)| v.is_some() && Some(*f) != wanted)
    {
        return Err(CliError::usage(format!(
            "--{flag} is not a parameter of {name}{}",
            match entry.param {
                Some(p) => format!(" (it takes --{})", p.flag),
                None => " (it takes none)".into(),
            }
        )));
    }
    if a.reflex_inward && !entry.reflex_option {
        return Err(CliError::usage(format!(
            "--reflex-inward is not an option of {name}"
        )));
    }
    let param = flags
        .iter()
        .find(|(f, _)| Some(*f) == wanted)
        .and_then(|(_, v)| *v);
    let reflex = if a.reflex_inward {
        ReflexMode::Inward
    } else {
        ReflexMode::AsPrinted
    };
    kind.scheme(param, reflex).map_err(CliError::usage)
}

/// Says once per distinct step that its parameter is above what can be repeated (vector
/// sum with ¼ < α < ½): admitted, as the paper admits it, but named.
fn warn_unrepeatable(steps: &[Scheme]) {
    let mut said: Vec<String> = Vec::new();
    for w in steps.iter().filter_map(Scheme::repeat_warning) {
        if !said.contains(&w) {
            eprintln!("warning: {w}");
            said.push(w);
        }
    }
}

/// `x` with at most six decimals, trailing zeros dropped (a clamped 0.15000000000000038
/// reads 0.15).
fn short(x: f64) -> String {
    let s = format!("{x:.6}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// The fillet line of the summary (every rounded edge of the level the rounding run
/// started from) and the `--measure-edge` lines.
fn report_fillets(
    p: &Pipeline,
    measure: Option<&str>,
    plot: Option<&Path>,
) -> Result<(), CliError> {
    let n = p.steps().len();
    let edges = measure
        .map(|m| super::parse_edges(m).map_err(|e| CliError::usage(format!("--measure-edge: {e}"))))
        .transpose()?;
    let Some(measured) = p.measure_fillets(n) else {
        return match edges {
            Some(_) => Err(CliError::usage(
                "--measure-edge needs a rounding step (cylindrical, minimum or combination)",
            )),
            None => Ok(()),
        };
    };
    let (run, summary) = measured.map_err(CliError::input)?;
    let of = if run.start > 0 {
        format!(" of level {}", run.start)
    } else {
        String::new()
    };
    match &summary {
        Some(s) => {
            let target = if s.target.0 == s.target.1 {
                short(s.target.0)
            } else {
                format!("{}–{}", short(s.target.0), short(s.target.1))
            };
            println!(
                "fillet at level {n}: {} rounded edge(s){of}, fitted r {:.5}–{:.5} (target {target}), fitted/target {:.5}–{:.5}, largest radial error {:+.3} % at edge {}-{}{}",
                s.edges,
                s.fitted.0,
                s.fitted.1,
                s.ratio.0,
                s.ratio.1,
                100.0 * s.worst.1,
                s.worst.0.0,
                s.worst.0.1,
                if s.unmeasured > 0 {
                    format!(" ({} edge(s) with too few section points)", s.unmeasured)
                } else {
                    String::new()
                }
            );
        }
        None => println!("fillet at level {n}: no rounded edge{of} could be measured"),
    }
    for (e, r, m) in p.missed_radii(n) {
        let m = m.map_or("too few section points to measure".to_string(), |m| {
            format!("{m:.4} at level {n}")
        });
        eprintln!(
            "warning: edge {}-{}{of} was clamped to r = {} but the combination rule reaches {m}",
            e.0,
            e.1,
            short(r)
        );
    }
    let base = &p.levels()[run.start];
    let edges = edges.unwrap_or_default();
    if let (Some(path), Some(&e)) = (plot, edges.first()) {
        let r = run.radius(&base.edge_attrs, e).ok_or_else(|| {
            CliError::usage(format!(
                "--measure-edge {}-{}: the edge is not rounded",
                e.0, e.1
            ))
        })?;
        let sections = (run.start + 1..=n)
            .filter_map(|k| {
                measure_fillet(&base.mesh, e.0, e.1, &p.levels()[k].mesh, r)
                    .ok()
                    .map(|m| (k, m.section))
            })
            .collect::<Vec<_>>();
        super::fillet_plot::fillet_plot(&sections, r, (e.0, e.1), path)?;
        println!("plotted {}", path.display());
    }
    for e in edges {
        let r = run.radius(&base.edge_attrs, e).ok_or_else(|| {
            CliError::usage(format!(
                "--measure-edge {}-{}: the edge is not rounded",
                e.0, e.1
            ))
        })?;
        let m = measure_fillet(&base.mesh, e.0, e.1, &p.levels()[n].mesh, r)
            .map_err(|x| CliError::input(format!("--measure-edge {}-{}: {x}", e.0, e.1)))?;
        println!(
            "edge {}-{}{of}: target r {}, fitted {:.6} (centre {:.2e} off the ideal axis), radial error {:+.4} % to {:+.4} %, {} section point(s), {}",
            e.0,
            e.1,
            short(r),
            m.fitted_radius,
            m.centre_offset,
            100.0 * m.min_radial_error,
            100.0 * m.max_radial_error,
            m.points,
            if m.concave { "concave" } else { "convex" }
        );
    }
    Ok(())
}

pub fn run(a: SubdivideArgs) -> Result<(), CliError> {
    let parsed = steps_from(&a.steps, None, true)?;
    super::check_solid_output_kind(&a.output)?;
    super::check_output(&a.output, Some(a.force))?;
    let (doc, numbering) = super::load_input(&a.input)?;
    let steps = if parsed.is_empty() {
        steps_from(&a.steps, doc.pipeline.as_deref(), false)?
    } else {
        parsed
    };
    let topo = Topology::build(&doc.mesh).map_err(|e| {
        CliError::input(format!("{}: {}", a.input.display(), numbering.describe(&e)))
    })?;
    for w in &topo.warnings {
        let w = numbering.describe_warning(w);
        eprintln!("warning: {}: {w}", a.input.display());
    }
    let needs_closed = matches!(steps.first(), Some(Scheme::Biquadratic(_)));
    let check = if needs_closed {
        topo.require_closed(&doc.mesh)
    } else {
        topo.require_single_fans(&doc.mesh)
    };
    check.map_err(|e| {
        CliError::input(format!("{}: {}", a.input.display(), numbering.describe(&e)))
    })?;

    let c0 = prism_geom::analysis::counts(&doc.mesh);
    println!(
        "level 0: {} vertices, {} edges, {} faces (input)",
        c0.vertices, c0.edges, c0.faces
    );
    let mut warnings = super::level_lines::LevelWarnings::new(&doc.mesh);
    let mut pipeline = Pipeline::with_tags(doc.mesh, doc.edge_attrs, doc.tags, steps.clone());
    // Only the levels the output and the fillet report need are kept (every level for a
    // section plot of them all).
    pipeline.keep = if a.plot.is_some() {
        Keep::All
    } else {
        Keep::Needed
    };
    let n = steps.len();
    // The options first: mending crossings adds a search of each rounded level to its step.
    pipeline.options = a.steps.options(pipeline.options.memory_budget);
    // After the last step: the fillet report, then an export assembled in memory; a search
    // for crossings after each level, the last the largest, before both.
    let last_counts = pipeline.predicted_counts();
    let output = prism_geom::memory::export_bytes(&last_counts, io::ExportFormat::of(&a.output));
    let report = if pipeline.rounds() {
        prism_geom::memory::fillet_report_bytes(&last_counts)
    } else {
        0
    };
    let crossing = if a.check_crossings {
        prism_geom::memory::crossing_bytes(&last_counts)
    } else {
        0
    };
    let budget = a.steps.memory.check(
        pipeline.estimate_peak_then(output.max(report).max(crossing)),
        "this pipeline",
        "give fewer levels",
    )?;
    pipeline.options.memory_budget = budget;
    let result = pipeline.compute_with(n, |k, level| {
        let r = level
            .report
            .as_ref()
            .expect("computed levels have a report");
        // Every step checks its new faces against their parents; primal steps (smooth
        // schemes) report their holes too.
        let check = if matches!(steps[k - 1], Scheme::Biquadratic(_)) {
            format!("flipped={}", r.flipped.len())
        } else {
            format!(
                "flipped={}, {} hole faces",
                r.flipped.len(),
                level.tags.holes.len()
            )
        };
        let crossings = a
            .check_crossings
            .then(|| prism_geom::analysis::crossings(&level.mesh));
        let shown = crossings
            .as_ref()
            .map_or(String::new(), |c| format!(", crossings={}", c.len()));
        println!(
            "level {k}: {} vertices, {} edges, {} faces, {check}{shown}, {:.2} ms  [{}]",
            r.vertices,
            r.edges,
            r.faces,
            r.millis,
            steps[k - 1]
        );
        warnings.level(k, r);
        if let Some(c) = crossings.as_ref().filter(|c| !c.is_empty()) {
            let (f, g) = c[0];
            eprintln!(
                "warning: level {k}: the surface passes through itself at {} pair(s) of faces, e.g. faces {f} and {g}",
                c.len()
            );
        }
    });
    if steps
        .iter()
        .any(|s| matches!(s, Scheme::Biquadratic(CornerRule::Minimum { .. })))
    {
        eprintln!(
            "note: the minimum type never flips faces but does not converge to r: its fillets stall near 0.2 % of r (use combination for true radii)"
        );
    }
    result.map_err(|e| CliError::input(e.describe(&numbering)))?;
    report_fillets(&pipeline, a.measure_edge.as_deref(), a.plot.as_deref())?;
    let normals = a.normals.as_deref().map(|n| {
        if n == "flat" {
            io::Normals::Flat
        } else {
            io::Normals::Smooth
        }
    });
    let last = pipeline.into_last();
    if io::ExportFormat::of(&a.output).is_some() {
        let holes = &last.tags.holes;
        super::saving(&a.output, a.force, || {
            io::export(
                &a.output,
                &last.mesh,
                &|f| holes.contains(&(f as u32)),
                normals.unwrap_or_default(),
            )
        })?;
        println!("wrote {}", a.output.display());
        return Ok(());
    }
    let out = Document {
        mesh: last.mesh,
        edge_attrs: last.edge_attrs,
        tags: last.tags,
        ..Document::default()
    };
    let obj = io::FileKind::of(&a.output).ok() == Some(io::FileKind::Obj);
    let warnings = super::saving(&a.output, a.force, || match normals {
        Some(n) if obj => {
            io::write_obj_with_normals(&a.output, &out.mesh, &out.edge_attrs, &out.tags, Some(n))
        }
        _ => io::save(&a.output, &out),
    })?;
    for w in warnings {
        eprintln!("warning: {}: {w}", a.output.display());
    }
    println!("wrote {}", a.output.display());
    Ok(())
}
