//! No lost work: unsaved changes are copied (at once when the window closes, every two minutes
//! otherwise), a save removes the copy, and the next start offers it for restore — restored,
//! the document is the work as it was; discarded, the copy is gone.

use super::command::{CurveEdit, Edit};
use super::*;

fn app_in(dir: &std::path::Path) -> PrismApp {
    let launch = Launch {
        autosave: Some(dir.to_path_buf()),
        ..Launch::default()
    };
    let mut a = PrismApp::headless(launch, None).unwrap();
    a.wait_idle();
    a
}

fn scratch(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("prism-autosave-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// A fresh autosave folder named `name`, left by a run whose curve had `levels` levels and was
/// copied when its window closed; the curve it left.
fn left_behind(name: &str, levels: usize) -> (std::path::PathBuf, prism_geom::curve::CurveSketch) {
    let dir = scratch(name);
    let mut a = app_in(&dir);
    a.run(CurveEdit::SetLevels(levels));
    assert!(a.autosave.tick(&a.doc, true).unwrap());
    (dir, a.doc.state().curve.clone())
}

#[test]
fn unsaved_work_is_copied_and_restored_at_the_next_start() {
    let dir = scratch("restore");
    let mut a = app_in(&dir);
    let copy = a.autosave.path().unwrap();
    // Nothing unsaved: nothing written, even when closing.
    assert!(!a.autosave.tick(&a.doc, true).unwrap());
    assert!(!copy.exists());
    // An edit in two tabs, then the window closes (or two minutes pass).
    a.run(Edit::SetPipeline {
        view: 0,
        steps: prism_geom::parse_pipeline("combination:r=0.2,doo-sabin").unwrap(),
    });
    a.run(CurveEdit::SetLevels(2));
    assert!(!a.autosave.tick(&a.doc, false).unwrap(), "not due yet");
    assert!(a.autosave.tick(&a.doc, true).unwrap());
    assert!(copy.exists());
    let work = a.doc.state().clone();
    drop(a);

    // The next start offers it; restored, the document is that work, unsaved and undoable.
    let mut b = app_in(&dir);
    assert!(b.autosave.offer.is_some());
    assert_ne!(b.doc.state(), &work);
    b.run(Command::RestoreAutosave);
    assert_eq!(b.doc.state().pipelines[0], work.pipelines[0]);
    assert_eq!(b.doc.state().curve, work.curve);
    assert_eq!(b.doc.state().mesh, work.mesh);
    assert!(b.autosave.offer.is_none());
    assert_eq!(b.doc.origin().name, "recovered work");
    // Saved: the copy goes.
    let saved = dir.join("work.prism.json");
    b.save_to(&saved).unwrap();
    assert!(!copy.exists());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_discarded_copy_is_gone() {
    let (dir, _) = left_behind("discard", 1);
    let mut b = app_in(&dir);
    assert!(b.autosave.offer.is_some());
    b.run(Command::DiscardAutosave);
    assert!(b.autosave.offer.is_none());
    assert!(!b.autosave.path().unwrap().exists());
    let c = app_in(&dir);
    assert!(c.autosave.offer.is_none());
    std::fs::remove_dir_all(&dir).ok();
}

/// The offer is a window with two buttons; clicking "Restore it" restores.
#[test]
fn the_offer_window_restores_on_click() {
    use egui_kittest::kittest::Queryable;
    let (dir, work) = left_behind("window", 2);
    let mut h = super::tests::harness(app_in(&dir));
    super::tests::settle(&mut h);
    h.get_by_label("Restore it").click();
    super::tests::settle(&mut h);
    assert_eq!(h.state().doc.state().curve, work);
    assert!(h.query_by_label("Restore it").is_none());
    std::fs::remove_dir_all(&dir).ok();
}
