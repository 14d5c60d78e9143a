//! `prism limit IN -o OUT.obj --scheme catmull-clark|loop [--levels N]`.
//!
//! Refines N levels (default 1; 0 evaluates the input itself) and writes the limit
//! position (`v`) and unit limit normal (`vn`) of every vertex of that level, in the order
//! `prism subdivide` writes the level's vertices, followed by the level's faces (hole faces
//! left out) as `f a//a …`. Across a crease the normal is one-sided (docs/schemes.md); a
//! vertex with no normal (no faces, or vanishing tangents) gets `vn 0 0 0`.

use super::CliError;
use clap::Args;
use prism_geom::io::write_atomically_with;
use prism_geom::pipeline::Keep;
use prism_geom::{Pipeline, PrimalScheme, limit_points_ordered, refine_primal_ordered};
use std::path::PathBuf;

#[derive(Debug, Args)]
pub struct LimitArgs {
    /// Input mesh (.obj with OpenSubdiv tags, or .prism.json).
    pub input: PathBuf,
    /// Output OBJ.
    #[arg(short, long)]
    pub output: PathBuf,
    /// catmull-clark or loop.
    #[arg(long)]
    pub scheme: String,
    /// Levels to refine before evaluating the limit.
    #[arg(long, default_value_t = 1)]
    pub levels: usize,
    #[command(flatten)]
    pub memory: super::MemoryArgs,
}

pub fn run(a: LimitArgs) -> Result<(), CliError> {
    super::check_output(&a.output, None)?;
    super::check_levels(a.levels)?;
    // Limit masks exist for the B-spline schemes: Catmull–Clark and Loop.
    let with_limits = [PrimalScheme::CatmullClark, PrimalScheme::Loop];
    let scheme = with_limits
        .into_iter()
        .find(|s| s.name() == a.scheme)
        .ok_or_else(|| {
            let known: Vec<&str> = with_limits.iter().map(|s| s.name()).collect();
            CliError::usage(format!(
                "unknown scheme '{}' for limit (known: {})",
                a.scheme,
                known.join(", ")
            ))
        })?;
    let (doc, numbering) = super::load_input(&a.input)?;
    // Mesh errors of the input name its elements as the file counts them; those of a
    // refined level, Prism's numbers.
    let input_error = |e: prism_geom::PrimalError, input: bool| {
        let msg = match &e {
            prism_geom::PrimalError::Mesh(m) if input => numbering.describe(m),
            other => other.to_string(),
        };
        CliError::input(format!("{}: {msg}", a.input.display()))
    };
    // The memory guard: the levels (only the newest is kept) and the limit arrays (a
    // position and a normal a vertex), before any work; each level checks again.
    let steps = vec![prism_geom::Scheme::Primal(scheme); a.levels];
    let mut estimate = Pipeline::with_tags(doc.mesh, doc.edge_attrs, doc.tags, steps);
    estimate.keep = Keep::Needed;
    let last = estimate.predicted_counts();
    let budget = a.memory.check(
        estimate.estimate_peak_then(48 * last.vertices + last.topology_bytes()),
        "this refinement",
        "give fewer levels",
    )?;
    let input = estimate.into_last();
    let (mut mesh, mut attrs, mut tags) = (input.mesh, input.edge_attrs, input.tags);
    let mut order = None;
    for k in 1..=a.levels {
        let (out, o) = refine_primal_ordered(&mesh, &attrs, &tags, scheme, budget, order.as_ref())
            .map_err(|e| {
                CliError::input(format!("level {k}: {}", input_error(e, k == 1).message))
            })?;
        println!(
            "level {k}: {} vertices, {} faces, {:.2} ms",
            out.report.vertices, out.report.faces, out.report.millis
        );
        (mesh, attrs, tags, order) = (out.mesh, out.edge_attrs, out.tags, Some(o));
    }
    let lim = limit_points_ordered(&mesh, &attrs, &tags, scheme, order.as_ref())
        .map_err(|e| input_error(e, a.levels == 0))?;
    // Streamed into the save's temporary file.
    write_atomically_with(&a.output, |w| {
        writeln!(
            w,
            "# limit positions and normals after {} level(s) of {}, written by Prism",
            a.levels,
            scheme.name()
        )?;
        // Shortest round-trip decimals, as every OBJ Prism writes.
        prism_geom::io::write_point_lines(w, "v", &lim.positions)?;
        prism_geom::io::write_point_lines(w, "vn", &lim.normals)?;
        for f in 0..mesh.num_faces() {
            if tags.holes.contains(&(f as u32)) {
                continue;
            }
            w.write_all(b"f")?;
            for c in mesh.face_corners(f) {
                let v = mesh.corner_verts[c] + 1;
                write!(w, " {v}//{v}")?;
            }
            w.write_all(b"\n")?;
        }
        Ok(())
    })
    .map_err(CliError::input)?;
    let undefined = lim
        .normals
        .iter()
        .filter(|n| **n == prism_geom::DVec3::ZERO)
        .count();
    if undefined > 0 {
        eprintln!(
            "note: {undefined} vertex(es) have no normal (no faces, or vanishing tangents): written as vn 0 0 0"
        );
    }
    println!("wrote {}", a.output.display());
    Ok(())
}
