//! The window under Xvfb (installed by `.ci/run`): `prism --screenshot` opens it, lets it
//! settle, saves a picture of the whole window and exits.

use std::path::Path;
use std::process::Command;

#[test]
fn the_window_opens_and_screenshots_itself() {
    let out = std::env::temp_dir().join(format!("prism-gui-{}.png", std::process::id()));
    let runtime = std::env::temp_dir().join(format!("prism-xdg-{}", std::process::id()));
    std::fs::create_dir_all(&runtime).unwrap();
    let o = Command::new("xvfb-run")
        .args(["-a", "-s", "-screen 0 1280x800x24"])
        .arg(env!("CARGO_BIN_EXE_prism"))
        .args([
            "--screenshot",
            out.to_str().unwrap(),
            "--pipeline",
            "combination:r=0.2,combination:r=0.2",
        ])
        .env("XDG_RUNTIME_DIR", &runtime)
        .current_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("../.."))
        .output()
        .expect("xvfb-run (apt-get install xvfb; .ci/run installs it)");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    let img = image::open(&out).expect("the screenshot").to_rgba8();
    assert_eq!(img.dimensions(), (1280, 800));
    // The 3D view (right of the panel) shows the model: many distinct shades there.
    let mut shades = std::collections::BTreeSet::new();
    for y in (200..600).step_by(7) {
        for x in (500..1100).step_by(7) {
            shades.insert(img.get_pixel(x, y).0);
        }
    }
    assert!(
        shades.len() > 20,
        "only {} shades in the view",
        shades.len()
    );
    // The pipeline panel's text is there (light pixels in the left panel).
    let light = (0..250)
        .flat_map(|x| (0..120).map(move |y| (x, y)))
        .filter(|&(x, y)| img.get_pixel(x, y).0[0] > 180)
        .count();
    assert!(light > 100, "no text in the panel");
}
