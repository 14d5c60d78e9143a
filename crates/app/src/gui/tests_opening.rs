//! A big file opens on a thread behind a progress bar with Cancel: the window keeps drawing
//! while it reads, the document comes when it is done, and Cancel leaves the document as it
//! was (the reader stops at its next block).

use super::tests::{app, harness, settle};
use super::*;
use egui_kittest::kittest::Queryable;

fn scratch(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("prism-opening-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn a_big_file_opens_behind_a_progress_bar() {
    let dir = scratch("open");
    let path = dir.join("torus.obj");
    let torus = prism_geom::primitives::torus(120, 60, 3.0, 1.0);
    prism_geom::io::write_obj(&path, &torus, &Default::default(), &Default::default()).unwrap();
    let mut a = app();
    a.open_in_background_from = 0;
    let mut h = harness(a);
    settle(&mut h);
    h.state_mut().run(Command::Open(path.clone()));
    assert!(h.state().opening.is_some());
    for _ in 0..500 {
        if h.state().opening.is_none() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
        h.step();
    }
    assert!(
        h.state().opening.is_none(),
        "the file never finished opening"
    );
    settle(&mut h);
    let a = h.state();
    assert!(
        a.doc.origin().name.ends_with("torus.obj"),
        "{}",
        a.doc.origin().name
    );
    assert_eq!(a.doc.state().mesh.num_faces(), 120 * 60);
    assert!(h.query_by_label("Cancel").is_none());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The reader is held on a named pipe that nothing writes, so the opening is still under way
/// when Cancel is pressed; the document stays the tripod, the thread is then let go.
#[test]
fn cancel_stops_opening_and_keeps_the_document() {
    let dir = scratch("cancel");
    let fifo = dir.join("slow.obj");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    if !made.is_ok_and(|s| s.success()) {
        eprintln!("no mkfifo here: skipped");
        return;
    }
    let mut a = app();
    a.open_in_background_from = 0;
    let before = a.doc.origin().name.clone();
    let faces = a.doc.state().mesh.num_faces();
    let mut h = harness(a);
    settle(&mut h);
    h.state_mut().run(Command::Open(fifo.clone()));
    // A window shows from its second frame (egui sizes it in the first).
    h.step();
    h.step();
    assert!(h.state().opening.is_some());
    h.get_by_label("Opening");
    h.get_by_label("Cancel").click();
    h.step();
    let a = h.state();
    assert!(a.opening.is_none());
    assert_eq!(a.doc.origin().name, before);
    assert_eq!(a.doc.state().mesh.num_faces(), faces);
    assert!(
        a.note
            .as_deref()
            .is_some_and(|n| n.contains("stopped opening")),
        "{:?}",
        a.note
    );
    // Let the reader go: it sees the cancel at its next block and ends (it may close the
    // pipe before this is written).
    let _ = std::fs::write(&fifo, b"v 0 0 0\n");
    std::fs::remove_dir_all(&dir).unwrap();
}
