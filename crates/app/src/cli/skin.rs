//! `prism skin SECTIONS.json -o OUT.obj|.prism.json|.stl|.glb [--resolution K] [--no-caps]
//! [--basis virtual|one-sided] [--pairing shape|paper] [--allow-crossing] [--patches
//! PATCHES.json]`: a smooth solid through planar cross-sections (seed 003;
//! docs/algorithms/skin.md). A skin that passes through itself is refused (exit 1, naming the
//! sections) unless `--allow-crossing`. SECTIONS is `{"sections": [{"points": [[x, y, z], ...],
//! "corners": [i, ...], "polygon": false}, ...]}`, or a `.prism.json` with a `"skin"` block
//! of that form. Sections and points are numbered from 0 as listed.

use super::CliError;
use clap::Args;
use prism_geom::freeform::{Basis, Pairing, SectionInput, Skin, SkinSpec};
use prism_geom::io::{self, Document};
use std::path::{Path, PathBuf};

#[derive(Debug, Args)]
pub struct SkinArgs {
    /// Sections file: {"sections": [{"points": [[x, y, z], ...], "corners": [...], "polygon": false}, ...]}, or a .prism.json with a "skin" block.
    pub input: PathBuf,
    /// Output: .obj, .prism.json, .stl or .glb.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Quads along each side of a patch (1 to 256): section vertices are mesh vertices and
    /// each section curve is n·K mesh edges.
    #[arg(long, default_value_t = 8)]
    pub resolution: usize,
    /// Leave the end sections open (two boundary loops) instead of closing them with planar
    /// caps.
    #[arg(long)]
    pub no_caps: bool,
    /// G1 construction of inner borders: `virtual` (both sides from the crossing curves'
    /// tangents; independent of numbering) or `one-sided` (the paper's: the cell listed first
    /// is the basis).
    #[arg(long, default_value = "virtual", value_parser = ["virtual", "one-sided"])]
    pub basis: String,
    /// How the vertices of neighbouring sections are paired: `shape` (the best least-squares
    /// match after a turn about the normal; near-ties by the least twist) or `paper` (the
    /// paper's least total twist, which pairs corners with sides once a section turns past
    /// 180°/n from the last).
    #[arg(long, default_value = "shape", value_parser = ["shape", "paper"])]
    pub pairing: String,
    /// Write a skin that passes through itself (with a warning naming the sections) instead
    /// of refusing it.
    #[arg(long)]
    pub allow_crossing: bool,
    /// Replace a read-only output file (it keeps its permission bits).
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub memory: super::MemoryArgs,
    /// Also write the patches' control points as JSON.
    #[arg(long)]
    pub patches: Option<PathBuf>,
}

/// The sections of a file.
pub fn read_sections(path: &Path) -> Result<Vec<SectionInput>, CliError> {
    let text = super::read_text(path)?;
    io::sections_from_str(path, &text).map_err(|e| CliError::input(e.to_string()))
}

fn patches_json(s: &Skin) -> serde_json::Value {
    let p = |v: glam::DVec3| serde_json::json!([v.x, v.y, v.z]);
    let n = s.points_per_section();
    let patches: Vec<_> = s
        .patches
        .iter()
        .enumerate()
        .map(|(idx, g)| {
            serde_json::json!({
                "section": idx / n,
                "chain": idx % n,
                "points": g.points.iter().map(|row| row.iter().map(|&v| p(v)).collect::<Vec<_>>()).collect::<Vec<_>>(),
                "u_copies": g.u_copies.iter().map(|row| row.iter().map(|&v| p(v)).collect::<Vec<_>>()).collect::<Vec<_>>(),
            })
        })
        .collect();
    serde_json::json!({
        "kind": "bicubic Gregory patches, points[i][j] = P_ij (interior: the copies tied to the v-borders), u_copies[i-1][j-1] = the copies tied to the u-borders",
        "patches": patches,
    })
}

/// The memory guard of a skin: `patches` patches at `k`×`k` quads, their crossing check, and
/// the export of `output` when it is assembled in memory.
pub fn check_tessellation(
    memory: &super::MemoryArgs,
    output: &std::path::Path,
    patches: usize,
    k: usize,
    what: &str,
) -> Result<(), CliError> {
    use prism_geom::memory;
    let counts = memory::tessellation_counts(patches as u64, k as u64);
    let export = memory::export_bytes(&counts, io::ExportFormat::of(output));
    // The crossing check runs on every skin before it is written.
    let check = memory::crossing_bytes(&counts);
    memory
        .check(
            memory::tessellation_bytes(&counts) + check + export,
            what,
            "give a smaller --resolution",
        )
        .map(|_| ())
}

pub fn run(a: SkinArgs) -> Result<(), CliError> {
    super::check_solid_output_kind(&a.output)?;
    if a.resolution == 0 || a.resolution > 256 {
        return Err(CliError::usage(format!(
            "--resolution {} is out of range: 1 to 256",
            a.resolution
        )));
    }
    super::check_output(&a.output, Some(a.force))?;
    super::check_not_lossy(&a.output, &a.input, "skin")?;
    let sections = read_sections(&a.input)?;
    let basis = if a.basis == "one-sided" {
        Basis::OneSided
    } else {
        Basis::Virtual
    };
    let pairing = if a.pairing == "paper" {
        Pairing::Paper
    } else {
        Pairing::Shape
    };
    let spec = SkinSpec {
        sections: sections.clone(),
        resolution: a.resolution,
        caps: !a.no_caps,
        basis,
        pairing,
    };
    let s = spec
        .build()
        .map_err(|e| CliError::input(format!("{}: {e}", a.input.display())))?;
    check_tessellation(
        &a.memory,
        &a.output,
        s.patches.len(),
        a.resolution,
        "this skin",
    )?;
    let mesh = s
        .tessellate(a.resolution, !a.no_caps)
        .map_err(CliError::input)?;
    let n = s.points_per_section();
    let shifts: Vec<String> = s
        .pairs()
        .map(|(k, sh, t)| format!("{k}→{}: {sh} (twist {t:.1}°)", k + 1))
        .collect();
    let paired = s.paired_by();
    println!(
        "{} sections of {n} points, {} patches, paired {paired}: shifts {}, {} point(s) inserted by polar angle, {} crease chain(s), largest normal jump across patch borders {:.2e}°",
        s.sections.len(),
        s.patches.len(),
        shifts.join(", "),
        s.inserted.iter().sum::<usize>(),
        s.creases(),
        s.border_normal_jump(8)
    );
    for note in s.notes() {
        eprintln!("note: {note}");
    }
    if let Some(w) = s.crossings(&mesh, a.resolution).warning() {
        if !a.allow_crossing {
            return Err(CliError::input(format!(
                "{}: {w} (move those sections apart, or write it anyway with --allow-crossing)",
                a.input.display()
            )));
        }
        eprintln!("warning: {w}");
    }
    let counts = prism_geom::analysis::counts(&mesh);
    if let Some(pp) = &a.patches {
        let text = serde_json::to_string_pretty(&patches_json(&s)).expect("JSON of numbers");
        io::write_atomically(pp, text.as_bytes()).map_err(CliError::input)?;
        println!("wrote {}", pp.display());
    }
    let doc = Document {
        mesh,
        skin: Some(spec),
        ..Document::default()
    };
    super::write_surface(&a.output, a.force, &doc)?;
    println!(
        "{} vertices, {} faces ({}×{} quads a patch{}); wrote {}",
        counts.vertices,
        counts.faces,
        a.resolution,
        a.resolution,
        if a.no_caps {
            ", open ends"
        } else {
            ", two caps"
        },
        a.output.display()
    );
    Ok(())
}
