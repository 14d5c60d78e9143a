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

/// A command whose output is cut short (`prism subdivide … | head -1`) ends quietly, as Unix
/// tools do, instead of panicking on the next print: SIGPIPE goes back to its default action,
/// which Rust's runtime sets to "ignore" so that writes fail with EPIPE.
#[cfg(unix)]
fn end_quietly_on_broken_pipes() {
    // SAFETY: called first thing in main, before any thread exists; `signal` with SIG_DFL
    // installs no handler code.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}

fn main() -> ExitCode {
    #[cfg(unix)]
    end_quietly_on_broken_pipes();
    let args = match cli::Cli::try_parse_from(cli::with_negative_values(std::env::args_os())) {
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
