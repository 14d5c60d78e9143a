//! The in-app file dialog (files.rs): where the desktop shows none (Linux without zenity or a
//! portal), Save as, Open and Export go through `egui_file`'s dialog in the window.

use super::files::Purpose;
use super::tests::{app, harness, settle};
use egui_kittest::kittest::Queryable;

/// A fresh folder for one test.
fn folder(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("prism-files-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The in-app dialog for `purpose` opened on `dir` with the file name `name`, its button
/// `button` clicked.
fn answer(
    h: &mut egui_kittest::Harness<'static, super::PrismApp>,
    purpose: Purpose,
    dir: &std::path::Path,
    name: &str,
    button: &str,
) {
    h.state_mut().in_app_dialog(purpose, Some(name.to_string()));
    h.state_mut()
        .file_dialog
        .as_mut()
        .unwrap()
        .dialog
        .set_path(dir);
    settle(h);
    h.get_by_label(button).click();
    settle(h);
}

/// Save as with no desktop dialog: the document is written where the in-app dialog says, a
/// name without a kind Prism writes as a `.prism.json`, the window's title takes its name;
/// Export writes the level shown as STL; Open, choosing the saved file in the list, reads it
/// back; Cancel does nothing.
#[test]
fn the_in_app_dialog_saves_exports_and_opens() {
    let dir = folder("cycle");
    let mut h = harness(app());
    settle(&mut h);
    answer(
        &mut h,
        Purpose::Save { then_close: false },
        &dir,
        "mine",
        "Save",
    );
    let saved = dir.join("mine.prism.json");
    assert!(saved.is_file(), "{:?}", h.state().note);
    assert!(h.state().file_dialog.is_none());
    assert!(h.state().doc.origin().name.contains("mine"));
    answer(&mut h, Purpose::Export("stl"), &dir, "level.stl", "Save");
    assert!(dir.join("level.stl").is_file(), "{:?}", h.state().note);
    answer(&mut h, Purpose::Open, &dir, "", "Cancel");
    assert!(h.state().file_dialog.is_none());
    // Open: the saved file picked in the list, then Open.
    h.state_mut().in_app_dialog(Purpose::Open, None);
    h.state_mut()
        .file_dialog
        .as_mut()
        .unwrap()
        .dialog
        .set_path(&dir);
    settle(&mut h);
    h.get_by_label("🗋 mine.prism.json").click();
    settle(&mut h);
    h.get_by_label("Open").click();
    settle(&mut h);
    assert!(h.state().file_dialog.is_none());
    assert_eq!(
        h.state().doc.origin().path.as_deref(),
        Some(saved.as_path())
    );
}
