//! Command-line interface (clap derive): the subcommands and their shared error type.

mod subdivide;

use clap::{Parser, Subcommand};

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
        None => Err(CliError::usage(
            "the graphical app is not built yet; use a subcommand, e.g. \
             `prism subdivide assets/tripod.obj -o tripod-round.obj --scheme combination --radius 0.2 --levels 5` \
             (see `prism --help`)",
        )),
    }
}
