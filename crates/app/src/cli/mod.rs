//! Command-line interface (clap derive): the subcommands and their shared error type.

mod bench;
mod curve;
mod curve_plot;
mod envelope;
mod envelope_study;
mod fillet_plot;
pub(crate) mod level_lines;
mod levels_strip;
mod limit;
mod negative;
mod new;
mod plot_style;
mod render;
mod skin;
pub(crate) mod subdivide;

use clap::{Parser, Subcommand};
pub use negative::joined as with_negative_values;

/// Prism — interactive polyhedral subdivision: chamfer and round the edges of solids.
#[derive(Debug, Parser)]
#[command(name = "prism", version, about, long_about = None, args_conflicts_with_subcommands = true)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Without a subcommand: the file to open in the window (the bundled tripod if none).
    pub file: Option<std::path::PathBuf>,
    /// Without a subcommand: the steps to start with, e.g. "combination:r=0.2,combination:r=0.2".
    #[arg(long)]
    pub pipeline: Option<String>,
    /// Without a subcommand: open the compare split with this pipeline in a further view
    /// (give it up to three times).
    #[arg(long, value_name = "PIPELINE")]
    pub compare: Vec<String>,
    /// Without a subcommand: display options to turn on.
    #[arg(long, value_delimiter = ',')]
    pub show: Vec<crate::gui::Show>,
    /// Without a subcommand: the tool to start with.
    #[arg(long)]
    pub tool: Option<crate::gui::Tool>,
    /// Without a subcommand: control edges to start with selected, e.g. "0-1,4-5".
    #[arg(long, value_name = "EDGES")]
    pub select_edges: Option<String>,
    /// Without a subcommand: the tab to open.
    #[arg(long)]
    pub tab: Option<crate::gui::Tab>,
    /// Without a subcommand: open the window, save a screenshot of it to this PNG, exit.
    #[arg(long)]
    pub screenshot: Option<std::path::PathBuf>,
    /// Without a subcommand: start with the clamp off, the papers' literal rules (a rounding
    /// whose radius does not fit its faces is refused, naming the edges, as the subcommands do
    /// without --clamp).
    #[arg(long)]
    pub no_clamp: bool,
}

/// Encodes `img` as PNG and writes it through a temporary file (`render`'s pictures and
/// `curve`'s plots).
pub(crate) fn write_png(img: image::DynamicImage, path: &std::path::Path) -> Result<(), CliError> {
    let mut png = Vec::new();
    img.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .map_err(|e| CliError::input(format!("encoding the PNG: {e}")))?;
    prism_geom::io::write_atomically(path, &png).map_err(CliError::input)
}

/// Numbers separated by commas, as `--size 3,2,1`, `--eye 1,2,3` and `--angles 15,30` give
/// them; `form` is what the message says was expected ("X,Y,Z").
pub(crate) fn comma_numbers(flag: &str, s: &str, form: &str) -> Result<Vec<f64>, CliError> {
    s.split(',')
        .map(|x| x.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| CliError::usage(format!("{flag} '{s}' is not {form}")))
}

pub(crate) fn parse_edges(s: &str) -> Result<Vec<prism_geom::EdgeKey>, String> {
    s.split(',')
        .filter(|t| !t.trim().is_empty())
        .map(|t| {
            let (a, b) = t
                .trim()
                .split_once('-')
                .ok_or_else(|| format!("edge '{t}' is not written as A-B"))?;
            let n = |x: &str| {
                x.trim()
                    .parse::<u32>()
                    .map_err(|_| format!("'{x}' in edge '{t}' is not a vertex number"))
            };
            Ok(prism_geom::EdgeKey::new(n(a)?, n(b)?))
        })
        .collect()
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Subdivide a solid with one scheme repeated, or with a pipeline of steps.
    Subdivide(subdivide::SubdivideArgs),
    /// Limit positions and unit normals of the vertices after N levels of Catmull-Clark or
    /// Loop, written as OBJ `v` and `vn` lines with the level's faces.
    Limit(limit::LimitArgs),
    /// Time a refinement: load once, run it --runs times, print time_ms=<median> and the
    /// peak memory.
    Bench(bench::BenchArgs),
    /// Render a picture offscreen (any adapter, software Vulkan included).
    Render(render::RenderArgs),
    /// Refine a 2D polyline with Catmull-Clark, the circle-preserving or the
    /// log-spiral-preserving rule; writes the points and their curvature.
    Curve(curve::CurveArgs),
    /// Make a new solid: a box, a prism or pyramid over a regular polygon, a tripod, or a
    /// closed outline extruded (concave, with an optional hole).
    New(new::NewArgs),
    /// Skin a smooth solid through planar cross-sections (seed 003): Gregory patches, G1
    /// across every inner border, tessellated K×K quads a patch, with planar caps.
    Skin(skin::SkinArgs),
    /// Envelope convex primitives with a smooth surface (seed 004): curved edges of end
    /// curvature 1/(t·r), Coons patches with variable twist, G1 across every border.
    Envelope(envelope::EnvelopeArgs),
    /// Seed 004's figs. 11 and 12: equal cubes at random centres, 2 to --max of them; the
    /// regions per face and the time of each stage, as a table and (--plot) a picture.
    EnvelopeStudy(envelope_study::EnvelopeStudyArgs),
    /// List the subdivision schemes: name, family, parameter with its range and default,
    /// paper, equation and the docs page with the formula.
    Schemes,
}

/// A command that runs once and exits pays for its memory once. On Linux a transparent huge
/// page (mimalloc advises its arenas huge) is first compacted for by the kernel where
/// `defrag` is `madvise`, the usual setting: on this machine that cost the 1M-quad
/// OBJ → OBJ job 0.3–0.9 s of system time, more than the refinement gains from the larger
/// pages (docs/performance.md). So the one-shot commands do without them; the window and
/// `bench`, which reuse their memory, keep them.
fn without_huge_pages() {
    #[cfg(target_os = "linux")]
    // SAFETY: PR_SET_THP_DISABLE takes an integer flag and no pointers; it only changes how
    // the kernel backs this process's later page faults.
    unsafe {
        libc::prctl(libc::PR_SET_THP_DISABLE, 1, 0, 0, 0);
    }
}

/// The text of an input file, or the error naming it.
pub fn read_text(path: &std::path::Path) -> Result<String, CliError> {
    std::fs::read_to_string(path)
        .map_err(|e| CliError::input(format!("{}: cannot read it: {e}", path.display())))
}

/// The most levels any command refines: every level has about four times the faces of the
/// one before, so level 40 of a single quad is 1.2e24 faces — past any machine. Larger
/// counts are bad usage (exit 2) before anything is read or allocated.
pub const MAX_LEVELS: usize = 40;

/// `--levels N` checked against [`MAX_LEVELS`].
pub fn check_levels(levels: usize) -> Result<(), CliError> {
    if levels > MAX_LEVELS {
        return Err(CliError::usage(format!(
            "--levels {levels} is out of range: at most {MAX_LEVELS} (each level has about 4× the faces of the one before)"
        )));
    }
    Ok(())
}

/// `--memory-budget SIZE`, shared by the commands that build big meshes.
#[derive(Debug, clap::Args)]
pub struct MemoryArgs {
    /// Memory the job may hold at once: 512M, 4G or 4GiB (powers of 1024), 4GB (powers of
    /// 1000), or bytes. A job whose estimated peak is larger is refused before it starts
    /// (exit 1). Default: half of the memory available now.
    #[arg(long, value_name = "SIZE", value_parser = prism_geom::memory::parse_size)]
    pub memory_budget: Option<u64>,
}

impl MemoryArgs {
    /// The budget in bytes.
    pub fn bytes(&self) -> u64 {
        self.memory_budget
            .unwrap_or_else(prism_geom::memory::default_budget)
    }

    /// Prints the estimate against the budget, and refuses a job over it (exit 1) naming
    /// both and what to change — `smaller`, the command's own knob ("give fewer levels",
    /// "give a smaller --resolution") — or the budget to give; returns the budget, read once
    /// (the default follows the memory available, which changes), for the work to run under.
    pub fn check(&self, estimate: u64, what: &str, smaller: &str) -> Result<u64, CliError> {
        use prism_geom::memory::mib;
        let budget = self.bytes();
        println!(
            "memory: about {} MiB at the peak, budget {} MiB",
            mib(estimate),
            mib(budget)
        );
        self.refuse_over(estimate, what, smaller)?;
        Ok(budget)
    }

    /// Refuses, without a line, a job whose `estimate` is already over the budget before
    /// the whole can be estimated (an envelope's construction, before its mesh is known).
    pub fn refuse_over(&self, estimate: u64, what: &str, smaller: &str) -> Result<(), CliError> {
        use prism_geom::memory::mib;
        let budget = self.bytes();
        if estimate > budget {
            return Err(CliError::input(format!(
                "{what} would need about {} MiB at its peak, more than the memory budget of {} MiB: \
                 {smaller}, or --memory-budget {}M if the machine has it",
                mib(estimate),
                mib(budget),
                mib(estimate) + mib(estimate) / 4 + 1
            )));
        }
        Ok(())
    }
}

/// Loads the input solid; a file name of no known kind is bad usage (exit 2, like an
/// unknown output kind), anything wrong inside the file bad input (exit 1).
pub fn load_input(
    path: &std::path::Path,
) -> Result<(prism_geom::io::Document, prism_geom::io::Numbering), CliError> {
    prism_geom::io::FileKind::of(path).map_err(CliError::usage)?;
    prism_geom::io::load(path).map_err(CliError::input)
}

/// A solid's output must be one of the kinds Prism writes: bad usage (exit 2) otherwise.
pub fn check_solid_output_kind(path: &std::path::Path) -> Result<(), CliError> {
    use prism_geom::io::{ExportFormat, FileKind};
    if ExportFormat::of(path).is_none()
        && !matches!(FileKind::of(path), Ok(k) if k != FileKind::Ply)
    {
        return Err(CliError::usage(format!(
            "{}: unknown output type (use .obj, .prism.json, .stl or .glb; PLY is read only)",
            path.display()
        )));
    }
    Ok(())
}

/// Checks before any work that `-o` can be written (its directory exists and takes a file;
/// a read-only target needs `--force`): a long computation is never lost to a bad path.
/// `force` is `None` for commands without `--force`.
pub fn check_output(path: &std::path::Path, force: Option<bool>) -> Result<(), CliError> {
    prism_geom::io::check_writable(path, force.unwrap_or(false)).map_err(|e| {
        let m = e.to_string();
        match (m.contains("read-only"), force) {
            (true, Some(_)) => CliError::input(format!("{m} (give --force to replace it)")),
            (true, None) => CliError::input(format!("{m} (make it writable to replace it)")),
            _ => CliError::input(m),
        }
    })
}

/// Runs the save `f`; with `force` a read-only target is replaced (and keeps its bits).
pub fn saving<T>(
    path: &std::path::Path,
    force: bool,
    f: impl FnOnce() -> Result<T, prism_geom::io::IoError>,
) -> Result<T, CliError> {
    if force {
        prism_geom::io::forced(path, f)
    } else {
        f()
    }
    .map_err(CliError::input)
}

/// Refuses, before the work, to write a free-form result (`block`: "skin" or "envelope") over
/// its own input document when that document holds more than the result would: writing the
/// result's document there would drop the rest (its control mesh, pipeline, curve sketch, the
/// other block, creases, tags). A document that holds only that block and its mesh is rewritten
/// whole.
pub fn check_not_lossy(
    output: &std::path::Path,
    input: &std::path::Path,
    block: &str,
) -> Result<(), CliError> {
    use prism_geom::io;
    let same = matches!(
        (std::fs::canonicalize(output), std::fs::canonicalize(input)),
        (Ok(a), Ok(b)) if a == b
    );
    if !same || io::FileKind::of(input).ok() != Some(io::FileKind::Document) {
        return Ok(());
    }
    let (doc, _) = io::load(input).map_err(CliError::input)?;
    let has_block = match block {
        "skin" => doc.skin.is_some(),
        _ => doc.envelope.is_some(),
    };
    let mut lost = Vec::new();
    if !has_block && doc.mesh.num_faces() > 0 {
        lost.push("its control mesh");
    }
    if doc.pipeline.is_some() {
        lost.push("its pipeline");
    }
    if doc.curve.is_some() {
        lost.push("its curve sketch");
    }
    if block != "skin" && doc.skin.is_some() {
        lost.push("its skin");
    }
    if block != "envelope" && doc.envelope.is_some() {
        lost.push("its envelope scene");
    }
    if !doc.edge_attrs.is_empty() {
        lost.push("its creases and radii");
    }
    if !doc.tags.is_default() {
        lost.push("its corner, hole and subdivision tags");
    }
    if lost.is_empty() {
        return Ok(());
    }
    Err(CliError::input(format!(
        "{}: the output is also the input, and writing the {block} there would drop {}; write to another file",
        output.display(),
        lost.join(", ")
    )))
}

/// Writes a free-form result (a skin, an envelope): its triangles as STL or glTF, or the whole
/// document — its mesh with the block that made it — as OBJ or `.prism.json`.
pub fn write_surface(
    path: &std::path::Path,
    force: bool,
    doc: &prism_geom::io::Document,
) -> Result<(), CliError> {
    use prism_geom::io;
    if io::ExportFormat::of(path).is_some() {
        saving(path, force, || {
            io::export(path, &doc.mesh, &|_| false, io::Normals::Smooth)
        })
    } else {
        saving(path, force, || io::save(path, doc)).map(|_| ())
    }
}

/// An error for the user: one line, and the exit code (1 bad input, 2 bad usage).
#[derive(Debug)]
pub struct CliError {
    pub message: String,
    pub code: u8,
}

impl CliError {
    pub fn input(message: impl std::fmt::Display) -> Self {
        CliError {
            message: message.to_string(),
            code: 1,
        }
    }
    pub fn usage(message: impl std::fmt::Display) -> Self {
        CliError {
            message: message.to_string(),
            code: 2,
        }
    }
}

pub fn run(cli: Cli) -> Result<(), CliError> {
    if !matches!(cli.command, None | Some(Command::Bench(_))) {
        without_huge_pages();
    }
    match cli.command {
        Some(Command::Subdivide(a)) => subdivide::run(a),
        Some(Command::Limit(a)) => limit::run(a),
        Some(Command::Bench(a)) => bench::run(a),
        Some(Command::Render(a)) => render::run(a),
        Some(Command::Curve(a)) => curve::run(a),
        Some(Command::New(a)) => new::run(a),
        Some(Command::Skin(a)) => skin::run(a),
        Some(Command::Envelope(a)) => envelope::run(a),
        Some(Command::EnvelopeStudy(a)) => envelope_study::run(a),
        Some(Command::Schemes) => {
            print!("{}", prism_geom::scheme::table());
            Ok(())
        }
        None => {
            let pipeline = match &cli.pipeline {
                Some(p) => prism_geom::parse_pipeline(p).map_err(CliError::usage)?,
                None => Vec::new(),
            };
            let compare = cli
                .compare
                .iter()
                .map(|p| prism_geom::parse_pipeline(p).map_err(CliError::usage))
                .collect::<Result<Vec<_>, _>>()?;
            if compare.len() > 3 {
                return Err(CliError::usage(
                    "at most three --compare pipelines (four views)",
                ));
            }
            let select_edges = match &cli.select_edges {
                Some(s) => parse_edges(s).map_err(CliError::usage)?,
                None => Vec::new(),
            };
            // A file that cannot be opened: the window opens on the bundled tripod with the
            // error in its status bar, and the terminal says it too (never as a graphics
            // failure). A screenshot is a script's job: it stops with the error instead.
            if let Some(f) = &cli.file
                && let Err(e) = crate::gui::document::open(f)
            {
                if cli.screenshot.is_some() {
                    return Err(CliError::input(e));
                }
                eprintln!("warning: could not open {}: {e}", f.display());
            }
            crate::gui::run(crate::gui::Launch {
                file: cli.file,
                pipeline,
                compare,
                show: cli.show,
                tool: cli.tool,
                select_edges,
                tab: cli.tab,
                autosave: if cli.screenshot.is_some() {
                    None
                } else {
                    crate::gui::autosave_dir()
                },
                screenshot: cli.screenshot,
                no_clamp: cli.no_clamp,
            })
            .map_err(CliError::input)
        }
    }
}
