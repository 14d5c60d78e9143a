//! The papers' figures gallery (docs/figures.md): every `prism …` command on that page runs
//! from a clean build, in order, with `{out}` a fresh folder, and every picture a command names
//! is written as a PNG; the page covers all 50 figures and tables of the five papers.

use std::path::Path;
use std::process::Command;

/// The page, from the repository.
fn page() -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/figures.md"))
        .unwrap()
}

/// The commands of the page, as written (between backticks, starting `prism `, writing to
/// `{out}`).
fn commands(page: &str) -> Vec<String> {
    page.split('`')
        .skip(1)
        .step_by(2)
        .filter(|c| c.starts_with("prism ") && c.contains("{out}"))
        .map(str::to_string)
        .collect()
}

#[test]
fn every_figure_is_listed_and_every_picture_made() {
    let page = page();
    // 15 + 7 + 8 + 6 figures and 12 figures + 2 tables of seed 004.
    let entries = page.lines().filter(|l| l.starts_with("### ")).count();
    assert_eq!(entries, 50);
    for (paper, n) in [("000", 15), ("001", 7), ("002", 8), ("003", 6), ("004", 14)] {
        let listed = page
            .lines()
            .filter(|l| l.starts_with(&format!("### {paper} ")))
            .count();
        assert_eq!(listed, n, "seed {paper}");
    }
    let out = tempfile::tempdir().unwrap();
    let runtime = tempfile::tempdir().unwrap();
    let cmds = commands(&page);
    assert!(cmds.len() >= 40, "{}", cmds.len());
    for c in &cmds {
        let line = c.replace("{out}", &out.path().display().to_string());
        let args: Vec<&str> = line.split(' ').skip(1).collect();
        let mut run = Command::new(env!("CARGO_BIN_EXE_prism"));
        if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
            run.env("XDG_RUNTIME_DIR", runtime.path());
        }
        let o = run
            .args(&args)
            .current_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("../.."))
            .output()
            .unwrap();
        assert!(
            o.status.success(),
            "{c}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        for w in c
            .split(' ')
            .filter(|w| w.starts_with("{out}/") && w.ends_with(".png"))
        {
            let path = out.path().join(&w["{out}/".len()..]);
            let png = std::fs::read(&path).unwrap_or_else(|_| panic!("{c}: no {w}"));
            assert_eq!(&png[1..4], b"PNG", "{w}");
        }
    }
    // Every picture the page shows is one a command makes.
    for l in page.lines().filter(|l| l.starts_with("![")) {
        let file = l.split("](figures/").nth(1).unwrap().trim_end_matches(')');
        assert!(
            cmds.iter().any(|c| c.contains(&format!("{{out}}/{file}"))),
            "{file}"
        );
        assert!(
            Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../../docs/figures")
                .join(file)
                .is_file(),
            "{file}"
        );
    }
}
