//! The window as a user sees it: `prism --screenshot` opens it, waits for the levels, saves a
//! picture of the whole window and exits. It runs under Xvfb when that is installed (a private
//! 1280×800 screen, what `.ci/run` installs), else on the session's display; with neither the
//! tests stop at once with the one line to run.

use std::path::{Path, PathBuf};
use std::process::Command;

/// Whether `name` is a program on the PATH.
fn on_path(name: &str) -> bool {
    std::env::var_os("PATH")
        .is_some_and(|p| std::env::split_paths(&p).any(|d| d.join(name).is_file()))
}

/// The command that starts the window: under `xvfb-run`, or on the display there is.
fn window_command() -> Command {
    let prism = env!("CARGO_BIN_EXE_prism");
    if on_path("xvfb-run") {
        let mut c = Command::new("xvfb-run");
        c.args(["-a", "-s", "-screen 0 1280x800x24"]).arg(prism);
        c
    } else if std::env::var_os("DISPLAY").is_some() || std::env::var_os("WAYLAND_DISPLAY").is_some()
    {
        Command::new(prism)
    } else {
        panic!(
            "the window tests need Xvfb or a display; run: sudo apt-get install -y xvfb \
             libxkbcommon-x11-0 mesa-vulkan-drivers (or .ci/run, which installs them)"
        )
    }
}

fn screenshot(name: &str, args: &[&str]) -> image::RgbaImage {
    // The last run's screenshots stay in target/tmp to be looked at.
    let out: PathBuf = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("gui-{name}.png"));
    // A private runtime folder (tempfile makes it 0700), removed when the window has closed.
    let runtime = tempfile::tempdir().unwrap();
    let mut cmd = window_command();
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        cmd.env("XDG_RUNTIME_DIR", runtime.path());
    }
    let o = cmd
        .args(["--screenshot", out.to_str().unwrap()])
        .args(args)
        .current_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("../.."))
        .output()
        .expect("the window starts");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    let img = image::open(&out).expect("the screenshot").to_rgba8();
    // A desktop's scale factor gives a larger picture of the same 1280×800-point window.
    if img.dimensions() == (1280, 800) {
        img
    } else {
        let (w, h) = img.dimensions();
        assert!(
            (w as f32 / h as f32 - 1.6).abs() < 0.05,
            "a 1280×800 window, not {w}×{h}"
        );
        image::imageops::resize(&img, 1280, 800, image::imageops::FilterType::Triangle)
    }
}

/// Distinct colours in a rectangle (sampled every 5 pixels).
fn shades(img: &image::RgbaImage, x: std::ops::Range<u32>, y: std::ops::Range<u32>) -> usize {
    let mut s = std::collections::BTreeSet::new();
    for yy in y.step_by(5) {
        for xx in x.clone().step_by(5) {
            s.insert(img.get_pixel(xx, yy).0);
        }
    }
    s.len()
}

#[test]
fn the_window_opens_and_screenshots_itself() {
    let img = screenshot(
        "model",
        &[
            "--pipeline",
            "combination:r=0.2,combination:r=0.2",
            "--show",
            "smooth",
        ],
    );
    // The 3D view (right of the panel) shows the model: many distinct shades there.
    let n = shades(&img, 500..1100, 200..600);
    assert!(n > 20, "only {n} shades in the view");
    // The pipeline panel's text is there (light pixels in the left panel).
    let light = (0..250)
        .flat_map(|x| (0..120).map(move |y| (x, y)))
        .filter(|&(x, y)| img.get_pixel(x, y).0[0] > 180)
        .count();
    assert!(light > 100, "no text in the panel");
}

/// Nine Catmull–Clark steps on the cube: 1.6 M quads, 3.1 M triangles, 340 MiB of vertices
/// drawn smooth — more than wgpu's default largest buffer (256 MiB), which made the window
/// panic. The window asks for the adapter's limits and draws larger scenes in parts.
#[test]
fn a_level_of_three_million_triangles_is_drawn() {
    let steps = ["catmull-clark"; 9].join(",");
    let img = screenshot(
        "three-million",
        &["assets/cube.obj", "--pipeline", &steps, "--show", "smooth"],
    );
    let n = shades(&img, 600..1100, 250..550);
    assert!(n > 10, "only {n} shades in the view");
}

/// The bundled spout at resolution 256 (what the guide allows): 3.9 M quads, drawn.
#[test]
fn a_skin_at_resolution_256_is_drawn() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let text = std::fs::read_to_string(root.join("assets/spout.skin.json")).unwrap();
    let mut spec: serde_json::Value = serde_json::from_str(&text).unwrap();
    spec["resolution"] = 256.into();
    let file = Path::new(env!("CARGO_TARGET_TMPDIR")).join("spout-256.skin.json");
    std::fs::write(&file, spec.to_string()).unwrap();
    let img = screenshot("skin-256", &[file.to_str().unwrap(), "--tab", "skin"]);
    let n = shades(&img, 500..1100, 250..600);
    assert!(n > 10, "only {n} shades in the view");
}

#[test]
fn the_compare_split_draws_a_model_in_each_of_four_views() {
    let img = screenshot(
        "compare",
        &[
            "--pipeline",
            "combination:r=0.2,combination:r=0.2",
            "--compare",
            "cut-width:d=0.1,doo-sabin",
            "--compare",
            "catmull-clark,catmull-clark",
            "--compare",
            "doo-sabin,doo-sabin",
            "--show",
            "kinds",
        ],
    );
    // The views fill x 405..1280 and y 25..~650 in a 2×2 grid.
    for (x, y) in [
        (480..800, 80..320),
        (920..1240, 80..320),
        (480..800, 400..620),
        (920..1240, 400..620),
    ] {
        let n = shades(&img, x.clone(), y.clone());
        assert!(n > 8, "only {n} shades in the view at {x:?} {y:?}");
    }
}

#[test]
fn the_curves_tab_draws_curves_and_the_curvature_plot() {
    let img = screenshot("curves", &["--tab", "curves"]);
    // Curve colours: the main scheme's orange in the canvas, the plot's lines below it.
    let orange = |x: std::ops::Range<u32>, y: std::ops::Range<u32>| {
        y.flat_map(|yy| x.clone().map(move |xx| (xx, yy)))
            .filter(|&(xx, yy)| {
                let p = img.get_pixel(xx, yy).0;
                p[0] > 180 && p[1] > 110 && p[2] < 120
            })
            .count()
    };
    assert!(orange(0..1280, 100..560) > 200, "no curve in the canvas");
    assert!(orange(0..1280, 570..790) > 50, "no curvature plot");
}

/// A `.prism.json` written by `prism COMMAND INPUT -o …` (a skin or envelope block with its
/// mesh), in target/tmp.
fn document_by(command: &str, input: &str, name: &str) -> std::path::PathBuf {
    let doc = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("gui-{name}.prism.json"));
    let o = Command::new(env!("CARGO_BIN_EXE_prism"))
        .args([command, input, "-o", doc.to_str().unwrap()])
        .current_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("../.."))
        .output()
        .unwrap();
    assert!(o.status.success(), "{o:?}");
    doc
}

/// The window opened on the document `prism COMMAND INPUT` writes, on `tab`: its picture,
/// checked to show a shaded surface (more than 20 shades) in the view's middle `(x, y)`.
fn tab_picture(
    (command, input, name): (&str, &str, &str),
    tab: &str,
    (x, y): (std::ops::Range<u32>, std::ops::Range<u32>),
) -> image::RgbaImage {
    let doc = document_by(command, input, name);
    let img = screenshot(command, &[doc.to_str().unwrap(), "--tab", tab]);
    let n = shades(&img, x, y);
    assert!(n > 20, "only {n} shades in the view");
    img
}

/// The pixels of `img` in `x` × `y` whose colour `is`.
fn count(
    img: &image::RgbaImage,
    (x, y): (std::ops::Range<u32>, std::ops::Range<u32>),
    is: impl Fn([u8; 4]) -> bool,
) -> usize {
    x.flat_map(|x| y.clone().map(move |y| (x, y)))
        .filter(|&(x, y)| is(img.get_pixel(x, y).0))
        .count()
}

fn yellow(p: [u8; 4]) -> bool {
    p[0] > 200 && p[1] > 170 && p[2] < 100
}

/// The Skin tab on a document with a skin block (the spout, written by `prism skin`): the
/// shaded skin fills the view and the yellow section curves are drawn over it.
#[test]
fn the_skin_tab_draws_the_skin_and_its_sections() {
    let input = ("skin", "assets/spout.skin.json", "spout");
    let img = tab_picture(input, "skin", (450..1200, 150..700));
    let yellow = count(&img, (450..1200, 100..750), yellow);
    assert!(
        yellow > 300,
        "only {yellow} yellow pixels: no section curves"
    );
}

/// The Envelope tab on a document with an envelope block (the hexagonal prism, written by
/// `prism envelope`): the shaded envelope fills the view, the yellow curved edges are drawn
/// over it, and no blue insertion curve (the charts split no region).
#[test]
fn the_envelope_tab_draws_the_envelope_and_its_curves() {
    let input = ("envelope", "assets/hexagonal-prism.envelope.json", "hex");
    let img = tab_picture(input, "envelope", (500..1100, 250..600));
    let view = (310..1270, 40..780);
    let yellow = count(&img, view.clone(), yellow);
    let blue = count(&img, view, |p| p[0] < 120 && p[1] > 150 && p[2] > 200);
    assert!(yellow > 300, "only {yellow} yellow pixels: no curved edges");
    assert!(blue < 20, "{blue} blue pixels: insertion curves drawn");
}
