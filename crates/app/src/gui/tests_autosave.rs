//! No lost work: unsaved changes are copied (at once when the window closes, every two minutes
//! otherwise, an idle window woken for it), a save removes the copy, and the next start offers
//! it for restore — restored, the document is the work as it was; discarded, the copy is gone.
//! Every window has a copy of its own, and only a copy no running window owns is offered.

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
    assert!(b.autosave.offer().is_some());
    assert_ne!(b.doc.state(), &work);
    b.run(Command::RestoreAutosave);
    assert_eq!(b.doc.state().pipelines[0], work.pipelines[0]);
    assert_eq!(b.doc.state().curve, work.curve);
    assert_eq!(b.doc.state().mesh, work.mesh);
    assert!(b.autosave.offer().is_none());
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
    assert!(b.autosave.offer().is_some());
    let offered = b.autosave.offered_path().unwrap();
    b.run(Command::DiscardAutosave);
    assert!(b.autosave.offer().is_none());
    assert!(!offered.exists());
    let c = app_in(&dir);
    assert!(c.autosave.offer().is_none());
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

/// Two windows on one folder each copy their own work; neither offers or discards the other's
/// copy while it runs; closed, each copy is left for a later start, and two later windows
/// never offer the same copy.
#[test]
fn two_windows_never_share_or_discard_each_others_copy() {
    let dir = scratch("two");
    let mut a = app_in(&dir);
    let mut b = app_in(&dir);
    assert!(a.autosave.offer().is_none() && b.autosave.offer().is_none());
    a.run(CurveEdit::SetLevels(1));
    b.run(CurveEdit::SetLevels(3));
    assert!(a.autosave.tick(&a.doc, true).unwrap());
    assert!(b.autosave.tick(&b.doc, true).unwrap());
    let (ca, cb) = (a.autosave.path().unwrap(), b.autosave.path().unwrap());
    assert_ne!(ca, cb);
    // A third window while both run: nothing is left behind to offer.
    let c = app_in(&dir);
    assert!(c.autosave.offer().is_none());
    // b's Discard removes nothing of a's.
    b.run(Command::DiscardAutosave);
    assert!(ca.exists() && cb.exists());
    drop((a, b, c));
    // Two later windows: each offers one of the two copies, never the same.
    let d = app_in(&dir);
    let e = app_in(&dir);
    let (od, oe) = (d.autosave.offered_path(), e.autosave.offered_path());
    assert!(od.is_some() && oe.is_some() && od != oe, "{od:?} {oe:?}");
    std::fs::remove_dir_all(&dir).ok();
}

/// While the restore offer is unanswered the window's own work is still copied, to its own
/// copy, and the offered one stays as it was.
#[test]
fn work_is_copied_while_the_offer_is_open() {
    let (dir, _) = left_behind("offer-open", 1);
    let mut b = app_in(&dir);
    let offered = b.autosave.offered_path().unwrap();
    let before = std::fs::read(&offered).unwrap();
    b.run(CurveEdit::SetLevels(3));
    assert!(b.autosave.tick(&b.doc, true).unwrap());
    assert!(b.autosave.path().unwrap().exists());
    assert_eq!(std::fs::read(&offered).unwrap(), before);
    std::fs::remove_dir_all(&dir).ok();
}

/// An idle window is woken for the copy: with unsaved changes the next copy is due within
/// two minutes; with none, nothing is due.
#[test]
fn an_idle_window_is_woken_when_the_copy_is_due() {
    let dir = scratch("idle");
    let mut a = app_in(&dir);
    assert_eq!(a.autosave.due_in(&a.doc), None);
    a.run(CurveEdit::SetLevels(2));
    let due = a.autosave.due_in(&a.doc).unwrap();
    assert!(due <= super::autosave::EVERY);
    assert!(a.autosave.tick(&a.doc, true).unwrap());
    assert_eq!(a.autosave.due_in(&a.doc), None);
    std::fs::remove_dir_all(&dir).ok();
}

/// Restored work keeps its name and save target (issue 66, item 4): a document saved as a
/// `.prism.json`, edited and left unsaved comes back under that name, marked unsaved, and
/// Save writes it back there without asking.
#[test]
fn restored_work_keeps_its_name_and_save_target() {
    let dir = scratch("origin");
    std::fs::create_dir_all(&dir).unwrap();
    let target = dir.join("bracket.prism.json");
    let mut a = app_in(&dir);
    a.save_to(&target).unwrap();
    a.run(CurveEdit::SetLevels(3));
    assert!(a.autosave.tick(&a.doc, true).unwrap());
    let work = a.doc.state().clone();
    drop(a);
    let mut b = app_in(&dir);
    b.run(Command::RestoreAutosave);
    assert_eq!(b.doc.origin().path.as_deref(), Some(target.as_path()));
    assert_eq!(b.doc.origin().name, target.display().to_string());
    assert!(
        b.title().starts_with("*bracket.prism.json"),
        "{}",
        b.title()
    );
    b.run(Command::SaveDialog { as_new: false });
    assert!(!b.unsaved());
    let (saved, _) = document::open(&target).unwrap();
    assert_eq!(saved.curve, work.curve);
    std::fs::remove_dir_all(&dir).ok();
}
