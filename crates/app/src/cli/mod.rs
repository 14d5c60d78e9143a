//! Command-line interface (clap derive): the subcommands and their shared error type.

mod bench;
mod curve;
mod limit;
mod render;
mod subdivide;

use clap::{Parser, Subcommand};
use prism_geom::MeshError;

/// Prism — interactive polyhedral subdivision: chamfer and round the edges of solids.
#[derive(Debug, Parser)]
#[command(name = "prism", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
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
    match cli.command {
        Some(Command::Subdivide(a)) => subdivide::run(a),
        Some(Command::Limit(a)) => limit::run(a),
        Some(Command::Bench(a)) => bench::run(a),
        Some(Command::Render(a)) => render::run(a),
        Some(Command::Curve(a)) => curve::run(a),
        None => Err(CliError::usage(
            "the graphical app is not built yet; use a subcommand, e.g. \
             `prism subdivide assets/tripod.obj -o tripod-round.obj --scheme combination --radius 0.2 --levels 5` \
             (see `prism --help`)",
        )),
    }
}

/// Adds the OBJ line of the face a mesh error names, when known.
pub(crate) fn with_line(e: &MeshError, face_lines: Option<&[usize]>) -> String {
    let face = match e {
        MeshError::IndexOutOfRange { face, .. }
        | MeshError::EmptyFace { face }
        | MeshError::DegenerateLoop { face, .. }
        | MeshError::RepeatedVertex { face, .. }
        | MeshError::BoundaryEdge { face, .. } => Some(*face),
        MeshError::InconsistentOrientation { f2, .. } => Some(*f2),
        _ => None,
    };
    match (face, face_lines) {
        (Some(f), Some(lines)) if (f as usize) < lines.len() => {
            format!("{e} (face {f} is on line {})", lines[f as usize])
        }
        _ => e.to_string(),
    }
}
