//! `prism`: the desktop modeller (the window by default, `prism FILE` opens a file) and its
//! headless subcommands. Exit codes: 0 success, 1 bad input (unreadable file, bad mesh, a step that
//! fails), 2 bad usage (unknown flag, bad scheme or parameter).

mod cli;
mod gui;

use clap::Parser;
use std::process::ExitCode;

/// mimalloc keeps freed pages for the next level instead of returning them to the kernel;
/// with the system allocator page faults cost more than a subdivision step
/// (docs/performance.md).
#[global_allocator]
static ALLOC: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> ExitCode {
    let args = match cli::Cli::try_parse() {
        Ok(a) => a,
        Err(e) => {
            let code = if e.use_stderr() { 2 } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    match cli::run(args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", e.message);
            ExitCode::from(e.code)
        }
    }
}
