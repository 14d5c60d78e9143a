//! The app driven without a window: the "done when" walk (step the tripod with
//! combination r = 0.2 five times, smooth shading and wireframe, pick an edge and crease it,
//! compare two pipelines, undo, save and reopen), vertex editing, the budget question, and
//! the curve sketch as part of the document (undo across tabs, saved and reopened).

use super::command::{CurveEdit, EdgeMark, Edit};
use super::model::Coloring;
use super::model::pick::{self, Projector};
use super::*;
use egui_kittest::Harness;
use prism_geom::scheme::parse_pipeline;

pub(super) fn app() -> PrismApp {
    let mut a = PrismApp::headless(Launch::default(), None).unwrap();
    a.wait_idle();
    rebuild(&mut a);
    a.model.frame(a.doc.state());
    a
}

/// Line vertices of colour `color` in view 0's overlay (or, `overlay` false, its scene).
pub(super) fn lines_of(a: &PrismApp, overlay: bool, color: [f32; 3]) -> usize {
    let v = &a.model.views[0];
    let scene = if overlay { &v.overlay } else { &v.scene };
    scene.lines.iter().filter(|l| l.color == color).count()
}

/// Brings the scenes and overlays up to date, as a frame does.
pub(super) fn rebuild(a: &mut PrismApp) {
    let g = a.doc.generation();
    a.model.rebuild_scenes(a.doc.state(), g);
    a.flush();
}

/// The app started on a file, its levels computed.
pub(super) fn opened(path: &std::path::Path) -> PrismApp {
    let mut a = PrismApp::headless(
        Launch {
            file: Some(path.to_path_buf()),
            ..Launch::default()
        },
        None,
    )
    .unwrap();
    a.wait_idle();
    a
}

fn rect() -> egui::Rect {
    egui::Rect::from_min_size(egui::pos2(300.0, 30.0), egui::vec2(900.0, 700.0))
}

/// Clicks the middle of the first visible level-`k` edge that descends from `control`.
fn click_edge_of(a: &mut PrismApp, control: EdgeKey) -> bool {
    let proj: Projector = a.model.projector(0, rect());
    let origins = a.model.views[0].origins();
    let map = origins.as_ref().as_ref().unwrap().clone();
    let k = a.model.views[0].shown();
    let mesh = a.model.views[0].pipeline.levels()[k].mesh.clone();
    let scene = a.model.views[0].scene.clone();
    for (e, c) in &map {
        if *c != control {
            continue;
        }
        let mid = 0.5 * (mesh.positions[e.0 as usize] + mesh.positions[e.1 as usize]);
        if let Some((s, _)) = proj.project(mid)
            && proj.rect.contains(s)
            && proj.visible(&scene, mid)
        {
            let doc = a.doc.state().clone();
            a.model.click_pick(0, &proj, s, false, &doc);
            return true;
        }
    }
    false
}

#[test]
fn the_new_user_walk_through() {
    let mut a = app();
    assert!(a.doc.origin().name.contains("tripod"));
    a.model.next = parse_pipeline("combination:r=0.2").unwrap()[0];
    for _ in 0..5 {
        a.model.step();
    }
    a.wait_idle();
    let v = &a.model.views[0];
    assert_eq!(v.pipeline.levels().len(), 6);
    // The status bar's "last edit to picture": the levels and the scene of the last step.
    let edit = v.last_edit.expect("the edit was timed");
    assert!(edit.as_secs_f64() < 10.0, "{edit:?}");
    assert_eq!(v.shown(), 5);
    let last = v.pipeline.levels()[5].report.as_ref().unwrap();
    assert!(last.flipped.is_empty());

    // Smooth shading and wireframe.
    a.model.display.smooth = true;
    a.model.display.wireframe = true;
    rebuild(&mut a);
    assert!(!a.model.views[0].scene.lines.is_empty());

    // Pick an edge on level 5 and crease it: the mark lands on the control edge.
    a.model.tool = Tool::Edges;
    rebuild(&mut a);
    a.model.frame(a.doc.state());
    let control = *pick::mesh_edges(&a.doc.state().mesh.clone())
        .iter()
        .find(|&&e| {
            a.model.sel_edges.clear();
            click_edge_of(&mut a, e)
        })
        .expect("some control edge is visible on level 5");
    assert_eq!(
        a.model.sel_edges.iter().copied().collect::<Vec<_>>(),
        vec![control]
    );
    a.model.mark(EdgeMark::Crease(10.0));
    a.wait_idle();
    assert_eq!(a.doc.state().edge_attrs[&control].crease, 10.0);
    rebuild(&mut a);
    assert!(
        !a.model.views[0].overlay.lines.is_empty(),
        "the creased edge is drawn"
    );

    // Compare two pipelines side by side: Catmull–Clark keeps the creased edge sharp.
    a.run(Edit::SetViews(2));
    let other = parse_pipeline("catmull-clark,catmull-clark").unwrap();
    a.run(Edit::SetPipeline {
        view: 1,
        steps: other.clone(),
    });
    a.wait_idle();
    assert_eq!(a.model.views.len(), 2);
    assert_eq!(a.model.views[1].pipeline.levels().len(), 3);
    let mut plain = prism_geom::Pipeline::new(
        a.doc.state().mesh.clone(),
        Default::default(),
        other.clone(),
    );
    plain.compute().unwrap();
    let creased = &a.model.views[1].pipeline.levels()[2].mesh;
    let moved = creased
        .positions
        .iter()
        .zip(&plain.levels()[2].mesh.positions)
        .filter(|(p, q)| (**p - **q).length() > 1e-6)
        .count();
    assert!(moved > 0, "the crease changes the Catmull–Clark surface");
    let doc = a.doc.state().clone();
    let fillet = a.model.fillet_text(0, &doc);
    assert!(fillet.contains("(r 0.2"), "{fillet}");
    assert_eq!(a.model.fillet_text(1, &doc), "—");

    // Undo: the second pipeline, the split, the crease.
    a.run(Command::Undo);
    assert_eq!(a.doc.state().pipelines[1], a.doc.state().pipelines[0]);
    a.run(Command::Undo);
    assert_eq!(a.doc.state().pipelines.len(), 1);
    a.run(Command::Undo);
    assert!(a.doc.state().edge_attrs.is_empty());
    a.run(Command::Redo);
    assert_eq!(a.doc.state().edge_attrs[&control].crease, 10.0);
    a.wait_idle();
    assert_eq!(a.model.views.len(), 1);

    // Save and reopen.
    let scratch = tempfile::tempdir().unwrap();
    let path = scratch.path().join("walk.prism.json");
    a.save_to(&path).unwrap();
    let mut b = opened(&path);
    assert_eq!(b.doc.state().pipelines[0], a.doc.state().pipelines[0]);
    assert_eq!(b.doc.state().edge_attrs, a.doc.state().edge_attrs);
    assert!(
        b.model.views[0].pipeline.levels()[5].mesh == a.model.views[0].pipeline.levels()[5].mesh
    );
    // Exports of the shown level.
    for ext in ["obj", "stl", "glb"] {
        let p = path.with_extension(ext);
        b.export_to(&p, false).unwrap();
        assert!(std::fs::metadata(&p).unwrap().len() > 1000);
    }
    // Normals as shown: smooth shading gives fewer distinct OBJ normals than flat (one a
    // face), and a GLB written flat has more vertices (split at every edge).
    let obj = path.with_extension("vn.obj");
    let distinct = |b: &mut PrismApp, smooth: bool| {
        b.model.display.smooth = smooth;
        b.export_to(&obj, true).unwrap();
        let text = std::fs::read_to_string(&obj).unwrap();
        assert!(
            text.lines()
                .any(|l| l.starts_with("f ") && l.contains("//"))
        );
        let vn: std::collections::BTreeSet<&str> =
            text.lines().filter(|l| l.starts_with("vn ")).collect();
        vn.len()
    };
    let (smooth, flat) = (distinct(&mut b, true), distinct(&mut b, false));
    let faces = b.model.views[0].pipeline.levels()[5].mesh.num_faces();
    assert!(smooth > flat, "smooth {smooth}, flat {flat}");
    assert!(
        flat <= faces,
        "flat: at most a normal a face ({flat} for {faces})"
    );
    let glb = path.with_extension("glb");
    b.model.display.smooth = true;
    b.export_to(&glb, false).unwrap();
    let smooth_len = std::fs::metadata(&glb).unwrap().len();
    b.model.display.smooth = false;
    b.export_to(&glb, false).unwrap();
    assert!(std::fs::metadata(&glb).unwrap().len() > smooth_len);
}

/// Frames with nothing changed rebuild nothing: the scene and overlay (and so the GPU
/// upload, keyed on `version`) stay as they are.
#[test]
fn idle_frames_rebuild_neither_scene_nor_overlay() {
    let mut a = app();
    a.model.tool = Tool::Vertices;
    rebuild(&mut a);
    let v = a.model.views[0].version;
    for _ in 0..3 {
        rebuild(&mut a);
    }
    assert_eq!(a.model.views[0].version, v);
    // A selection change rebuilds the overlay once.
    a.model.sel_verts.insert(0);
    rebuild(&mut a);
    rebuild(&mut a);
    assert_eq!(a.model.views[0].version, v + 1);
}

#[test]
fn moving_a_control_vertex_recomputes_every_level_and_undoes_in_one_step() {
    let mut a = app();
    run_pipeline(&mut a, "combination:r=0.2,doo-sabin");
    let old = a.model.views[0].pipeline.levels()[2].mesh.clone();
    let p0 = a.doc.state().mesh.positions[0];
    a.model.sel_verts.insert(0);
    a.model.move_vertices(&[0], glam::DVec3::new(0.0, 0.0, 0.3));
    a.wait_idle();
    let new = &a.model.views[0].pipeline.levels()[2].mesh;
    assert!(*new != old, "level 2 follows the moved vertex");
    assert_eq!(new.num_faces(), old.num_faces());
    a.run(Command::Undo);
    a.wait_idle();
    assert_eq!(a.doc.state().mesh.positions[0], p0);
    assert!(a.model.views[0].pipeline.levels()[2].mesh == old);
    // Non-finite typed coordinates are refused.
    a.model
        .move_vertices(&[0], glam::DVec3::new(f64::NAN, 0.0, 0.0));
    a.flush();
    assert_eq!(a.doc.state().mesh.positions[0], p0);
    assert!(a.note.as_ref().unwrap().contains("numbers"));
    // A drag of the vertex is one undo step however many frames it took.
    for k in 1..=4 {
        let to = vec![(0, p0 + glam::DVec3::Z * (0.1 * k as f64))];
        a.run(Edit::DragVertices { drag: 9, to });
    }
    a.wait_idle();
    let dragged = a.model.views[0].pipeline.levels()[2].mesh.clone();
    assert!(dragged != old, "the levels follow the drag");
    a.run(Command::Undo);
    a.wait_idle();
    assert_eq!(a.doc.state().mesh.positions[0], p0);
    assert!(a.model.views[0].pipeline.levels()[2].mesh == old);
}

/// Dragging a cage vertex under primal steps evaluates the points again on the faces and
/// topology found before (`Pipeline::moved`): every level equals a fresh pipeline's.
#[test]
fn a_drag_under_primal_steps_gives_a_fresh_pipelines_levels() {
    let mut a = app();
    let steps = parse_pipeline("catmull-clark,catmull-clark,combination:r=0.05").unwrap();
    a.run(Edit::SetPipeline {
        view: 0,
        steps: steps.clone(),
    });
    a.wait_idle();
    let p0 = a.doc.state().mesh.positions[4];
    for k in 1..=3 {
        let to = vec![(4, p0 + glam::DVec3::new(0.02, -0.01, 0.05) * k as f64)];
        a.run(Edit::DragVertices { drag: 7, to });
        a.wait_idle();
    }
    let d = a.doc.state().clone();
    let mut fresh = prism_geom::Pipeline::with_tags(d.mesh, d.edge_attrs, d.tags, steps);
    fresh.options = a.model.views[0].pipeline.options;
    fresh.compute().unwrap();
    let shown = a.model.views[0].pipeline.levels();
    assert_eq!(shown.len(), 4);
    for (k, (x, y)) in shown.iter().zip(fresh.levels()).enumerate() {
        assert!(x.mesh == y.mesh, "level {k}");
    }
}

#[test]
fn a_drag_along_an_axis_moves_along_that_axis_only() {
    let mut a = app();
    a.model.axis = Some(2);
    let d = a.model.drag_vector(egui::vec2(0.0, -50.0), rect());
    assert!(d.z > 0.0 && d.x == 0.0 && d.y == 0.0, "{d}");
    a.model.axis = None;
    let d = a.model.drag_vector(egui::vec2(40.0, 0.0), rect());
    assert!(d.length() > 0.0);
    // In the view plane: perpendicular to the viewing direction.
    let c = a.model.camera;
    let fwd = (c.target - c.eye()).normalize().as_dvec3();
    assert!(d.dot(fwd).abs() < 1e-6 * d.length());
}

#[test]
fn sharper_than_selects_the_tripods_feature_edges() {
    let mut a = app();
    let doc = a.doc.state().clone();
    a.model.select_sharper_than(&doc, 60.0, false);
    let n = a.model.sel_edges.len();
    assert!(n > 0);
    a.model.select_sharper_than(&doc, 179.0, false);
    assert!(a.model.sel_edges.is_empty());
    a.model.select_sharper_than(&doc, 60.0, false);
    a.model.mark(EdgeMark::Radius(Some(0.05)));
    a.flush();
    assert_eq!(a.doc.state().edge_attrs.len(), n);
    a.model.mark(EdgeMark::Radius(Some(-1.0)));
    a.flush();
    assert!(a.note.as_ref().unwrap().contains("positive"));
}

/// The app after nine Doo–Sabin steps on view 0 that go over a budget of `mib`: it stops and
/// asks.
fn over_budget(mib: u64) -> PrismApp {
    let mut a = app();
    a.model.budget_mib = mib;
    run_pipeline(&mut a, &["doo-sabin"; 9].join(","));
    assert_eq!(a.model.question.as_ref().map(|q| q.0), Some(0), "asked");
    a
}

#[test]
fn a_step_over_the_memory_budget_asks_first() {
    let mut a = over_budget(64);
    let (_, o) = a.model.question.clone().unwrap();
    assert!(o.needed_mib > 64);
    let computed = a.model.views[0].pipeline.levels().len();
    assert!(computed < 10);
    // "Remove the step" keeps what was computed.
    a.run(Command::RemoveOverBudgetStep);
    a.wait_idle();
    assert!(a.model.question.is_none());
    assert_eq!(a.doc.state().pipelines[0].len(), computed - 1);
    assert!(a.model.views[0].pipeline.is_complete());
    assert!(a.model.views[0].error.is_none());
}

/// The memory question's third answer: the view frees its intermediate levels and computes
/// on within the budget; a freed level is never shown (the last is).
#[test]
fn a_step_over_the_budget_can_drop_the_kept_levels() {
    let mut a = over_budget(80);
    let (_, asked) = a.model.question.clone().unwrap();
    let before = a.model.views[0].pipeline.levels().len();
    a.run(Command::DropKeptLevels);
    a.wait_idle();
    let v = &a.model.views[0];
    let levels = v.pipeline.levels();
    // Freed levels count no more: either further levels fit, or the same step asks for
    // less (the guard counts the levels kept).
    match &a.model.question {
        Some((_, again)) if levels.len() == before => {
            assert!(again.needed_mib < asked.needed_mib, "{again:?} {asked:?}")
        }
        _ => assert!(
            levels.len() > before,
            "{} levels, {before} before",
            levels.len()
        ),
    }
    let last = levels.len() - 1;
    for (k, lv) in levels.iter().enumerate().take(last).skip(1) {
        assert!(
            v.pipeline.released(k) && lv.mesh.num_faces() == 0,
            "level {k}"
        );
    }
    assert!(levels[0].mesh.num_faces() > 0 && levels[last].mesh.num_faces() > 0);
    a.model.views[0].level = 1;
    assert_eq!(a.model.views[0].shown(), last);
}

#[test]
fn bundled_samples_open_and_bad_files_say_why() {
    let mut a = app();
    for k in 0..SAMPLES_FILES.len() {
        a.run(Command::OpenSample(k));
        a.wait_idle();
        assert!(a.doc.state().mesh.num_faces() > 0, "sample {k}");
    }
    let scratch = tempfile::tempdir().unwrap();
    let bad = scratch.path().join("bad.obj");
    std::fs::write(&bad, "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n").unwrap();
    let faces = a.doc.state().mesh.num_faces();
    a.run(Command::Open(bad.clone()));
    assert!(
        a.note.as_ref().unwrap().contains("could not open"),
        "{:?}",
        a.note
    );
    assert_eq!(
        a.doc.state().mesh.num_faces(),
        faces,
        "the document is kept"
    );
    assert!(
        a.note.as_ref().unwrap().contains("vertex 3 (line 3)"),
        "as the OBJ counts: {:?}",
        a.note
    );
    // Text that is not a mesh (it reads as an OBJ of no faces), opened or dropped: refused,
    // named, the document kept (issue 66, item 5).
    let text = scratch.path().join("notes.obj");
    std::fs::write(&text, "hello\nthese are notes, not a mesh\n").unwrap();
    let before = a.doc.generation();
    a.run(Command::Open(text));
    let note = a.note.clone().unwrap_or_default();
    assert!(note.contains("notes.obj: the mesh has no faces"), "{note}");
    assert_eq!(a.doc.generation(), before, "the document is kept");
    // An STL opens as a solid (its facets welded), as dropped or opened.
    let stl = scratch.path().join("tetra.stl");
    let tet = prism_geom::primitives::tetrahedron();
    std::fs::write(&stl, prism_geom::io::stl_bytes(&tet, &|_| false)).unwrap();
    a.run(Command::Open(stl));
    a.wait_idle();
    let m = &a.doc.state().mesh;
    assert_eq!((m.num_vertices(), m.num_faces()), (4, 4));
    a.run(Command::Undo);
    // Opening is undoable.
    a.run(Command::Undo);
    a.wait_idle();
    assert!(a.doc.state().mesh.num_faces() > 0);
    // A step's error about the opened OBJ names its faces as the file does.
    let twice = scratch.path().join("twice.obj");
    let tet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
    std::fs::write(&twice, format!("{tet}f 1 2 3\nf 1 2 4\nf 2 3 4\nf 3 1 4\n")).unwrap();
    a.run(Command::Open(twice.clone()));
    a.model.step();
    a.wait_idle();
    let error = a.model.views[0].error.clone().unwrap_or_default();
    assert!(
        error.contains("edge 1-2 is traversed 1→2 by both face 1 (line 5) and face 2 (line 6)"),
        "{error}"
    );
}

#[test]
fn remembered_settings_reopen_the_last_file_with_the_display_options() {
    let path = std::env::temp_dir().join(format!("prism-last-{}.prism.json", std::process::id()));
    let mut a = app();
    let steps = parse_pipeline("doo-sabin").unwrap();
    a.run(Edit::SetPipeline { view: 0, steps });
    a.save_to(&path).unwrap();
    a.model.display.color = Coloring::Scheme;
    a.model.display.smooth = true;
    // What eframe stores is the settings struct (RON through serde).
    let stored = serde_json::to_string(&a.settings()).unwrap();
    let back: Settings = serde_json::from_str(&stored).unwrap();
    let mut b = PrismApp::headless(Launch::default(), Some(back)).unwrap();
    b.wait_idle();
    assert_eq!(b.doc.origin().path.as_deref(), Some(path.as_path()));
    assert_eq!(b.doc.state().pipelines[0].len(), 1);
    assert!(b.model.display.smooth && b.model.display.color == Coloring::Scheme);
    // Colour by scheme paints the Doo–Sabin level in the scheme's colour.
    rebuild(&mut b);
    let want = prism_viewport::scene::scheme_color(b.doc.state().pipelines[0].first());
    assert!(
        b.model.views[0]
            .scene
            .vertices
            .iter()
            .all(|v| v.color == want)
    );
    // A file that is gone falls back to the bundled tripod.
    std::fs::remove_file(&path).unwrap();
    let c = PrismApp::headless(Launch::default(), Some(a.settings())).unwrap();
    assert!(c.doc.origin().name.contains("tripod"));
}

/// The real panels, driven through egui_kittest: buttons, checkboxes, radio buttons, keys
/// and the menu bar reach the document as a user's clicks would.
#[test]
fn the_panels_buttons_and_keys_drive_the_document() {
    use egui_kittest::Harness;
    use egui_kittest::kittest::Queryable;
    let mut h = harness(app());
    let settle = |h: &mut Harness<'_, PrismApp>| {
        for _ in 0..3 {
            h.step();
            h.state_mut().wait_idle();
        }
    };
    settle(&mut h);
    h.get_by_label("Step >> (S)").click();
    settle(&mut h);
    assert_eq!(h.state().doc.state().pipelines[0].len(), 1);
    h.key_press(egui::Key::S);
    settle(&mut h);
    assert_eq!(h.state().doc.state().pipelines[0].len(), 2);
    assert_eq!(h.state().model.views[0].pipeline.levels().len(), 3);
    h.get_by_label("<< Back (B)").click();
    settle(&mut h);
    assert_eq!(h.state().doc.state().pipelines[0].len(), 1);

    h.get_by_label("smooth shading (F)").click();
    settle(&mut h);
    assert!(h.state().model.display.smooth);
    h.key_press(egui::Key::F);
    settle(&mut h);
    assert!(!h.state().model.display.smooth);

    h.get_by_label("2 views").click();
    settle(&mut h);
    assert_eq!(h.state().model.views.len(), 2);
    // Ctrl+Z undoes the split, then the Back.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    assert_eq!(h.state().model.views.len(), 1);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    assert_eq!(h.state().doc.state().pipelines[0].len(), 2);

    h.get_by_label("Edges").click();
    settle(&mut h);
    assert_eq!(h.state().model.tool, Tool::Edges);
    h.get_by_label("Select edges sharper than").click();
    settle(&mut h);
    assert!(!h.state().model.sel_edges.is_empty());
    // Under biquadratic steps only, Crease is disabled (they ignore sharpness).
    h.get_by_label("Crease").click();
    settle(&mut h);
    assert!(h.state().doc.state().edge_attrs.is_empty());
    let steps = parse_pipeline("combination:r=0.2,catmull-clark").unwrap();
    h.state_mut().run(Edit::SetPipeline { view: 0, steps });
    settle(&mut h);
    h.get_by_label("Crease").click();
    settle(&mut h);
    let creased = &h.state().doc.state().edge_attrs;
    assert!(!creased.is_empty() && creased.values().all(|a| a.crease == 10.0));

    h.get_by_label("Curves").click();
    settle(&mut h);
    assert_eq!(h.state().tab, Tab::Curves);
    h.get_by_label("hexagon").click();
    settle(&mut h);
    assert_eq!(h.state().doc.state().curve.control.points.len(), 6);
    // Ctrl+Z in the Curves tab undoes the preset (history is global), not the crease.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    assert_eq!(h.state().doc.state().curve.control.points.len(), 4);
    assert!(!h.state().doc.state().edge_attrs.is_empty());
}

/// The Curves tab's sketch is part of the document: edits are undoable after a crease made
/// in the Model tab, in the order they were made, and the sketch is saved and reopened.
#[test]
fn the_curve_sketch_is_undone_with_the_document_and_saved() {
    let mut a = app();
    let doc = a.doc.state().clone();
    a.model.select_sharper_than(&doc, 60.0, false);
    a.model.mark(EdgeMark::Crease(10.0));
    a.flush();
    let p1 = a.doc.state().curve.control.points[1];
    for k in 1..=3 {
        let to = p1 + glam::DVec2::new(0.2 * k as f64, 0.0);
        a.run(CurveEdit::Move {
            index: 1,
            to,
            drag: 1,
        });
    }
    a.run(CurveEdit::SetScheme(
        prism_geom::curve::CurveScheme::LogSpiral,
    ));
    a.run(CurveEdit::Insert {
        index: 0,
        at: glam::DVec2::new(-2.0, 0.5),
    });
    let sketch = a.doc.state().curve.clone();
    assert_eq!(sketch.control.points.len(), 5);

    let path = std::env::temp_dir().join(format!("prism-curve-{}.prism.json", std::process::id()));
    a.save_to(&path).unwrap();
    let b = opened(&path);
    assert_eq!(
        b.doc.state().curve,
        sketch,
        "the sketch comes back from the file"
    );
    std::fs::remove_file(&path).ok();

    a.tab = Tab::Curves;
    a.run(Command::Undo);
    assert_eq!(a.doc.state().curve.control.points.len(), 4);
    let note = a.note.clone().unwrap_or_default();
    assert_eq!(note, "undid a change to the curve sketch (Curves tab)");
    a.run(Command::Undo);
    assert_eq!(
        a.doc.state().curve.scheme,
        prism_geom::curve::CurveScheme::Circle
    );
    a.run(Command::Undo);
    assert_eq!(
        a.doc.state().curve.control.points[1],
        p1,
        "the drag is one step"
    );
    assert!(!a.doc.state().edge_attrs.is_empty(), "the crease stays");
    // The crease was made in the Model tab: from the Curves tab, whose own changes are all
    // undone, Ctrl+Z first says what the next would take back there (issue 66, item 7).
    a.run(Command::Undo);
    assert!(!a.doc.state().edge_attrs.is_empty(), "not yet");
    let note = a.note.clone().unwrap_or_default();
    assert!(
        note.starts_with(
            "nothing left to undo in the Curves tab; Ctrl+Z again undoes a change to the solid"
        ),
        "{note}"
    );
    a.run(Command::Undo);
    assert!(a.doc.state().edge_attrs.is_empty());
    let note = a.note.clone().unwrap_or_default();
    assert!(note.ends_with("(Model tab)"), "{note}");
}

#[test]
fn a_big_level_gets_its_scene_on_a_thread_and_the_old_one_stays_meanwhile() {
    let path = std::env::temp_dir().join(format!("prism-big-{}.prism.json", std::process::id()));
    let doc = prism_geom::io::Document {
        mesh: prism_geom::primitives::torus(320, 320, 3.0, 1.0),
        edge_attrs: Default::default(),
        tags: Default::default(),
        ..Default::default()
    };
    prism_geom::io::save(&path, &doc).unwrap();
    let mut a = opened(&path);
    // The first scene comes from a thread; the window keeps drawing the empty one.
    rebuild(&mut a);
    assert!(a.model.views[0].preparing());
    assert_eq!(a.model.views[0].scene.triangles(), 0);
    while a.model.views[0].preparing() {
        std::thread::sleep(std::time::Duration::from_millis(5));
        rebuild(&mut a);
    }
    assert_eq!(a.model.views[0].scene.triangles(), 2 * 320 * 320);
    // A display change prepares again; the flat scene stays until the smooth one is there.
    let before = a.model.views[0].version;
    a.model.display.smooth = true;
    rebuild(&mut a);
    assert!(a.model.views[0].preparing());
    while a.model.views[0].preparing() {
        std::thread::sleep(std::time::Duration::from_millis(5));
        rebuild(&mut a);
    }
    assert!(a.model.views[0].version > before);
    assert_eq!(
        a.model.views[0].scene_opts.shading,
        prism_viewport::Shading::Smooth
    );
    std::fs::remove_file(&path).ok();
}

/// A few frames with the background work finished between them (the harness tests).
/// The app `a` in a 1280 × 800 window of egui_kittest, its panels driven as a user's clicks
/// and keys would.
pub(super) fn harness(a: PrismApp) -> Harness<'static, PrismApp> {
    Harness::builder()
        .with_size(egui::vec2(1280.0, 800.0))
        .build_ui_state(|ui, app: &mut PrismApp| app.frame_ui(ui), a)
}

/// `pipeline` (as `--pipeline` reads it) set on view 0 of `a`, and computed.
pub(super) fn run_pipeline(a: &mut PrismApp, pipeline: &str) {
    let steps = parse_pipeline(pipeline).unwrap();
    a.run(Edit::SetPipeline { view: 0, steps });
    a.wait_idle();
}

/// A fresh app in its window with the tab `label` clicked.
pub(super) fn in_tab(label: &str) -> Harness<'static, PrismApp> {
    use egui_kittest::kittest::Queryable;
    let mut h = harness(app());
    settle(&mut h);
    h.get_by_label(label).click();
    settle(&mut h);
    h
}

/// `bad`, set in the document, is refused by the build of its tab (`tab`), which names
/// `says`, and the document keeps it; with `zero_resolution` applied, the edit itself is
/// refused and named in the status bar.
pub(super) fn refused_and_kept<T: gestures::Tab3d>(
    tab: fn(&mut PrismApp) -> &mut T,
    (mut bad, says): (T::Spec, &str),
    zero_resolution: fn(&mut T::Spec),
) where
    T::Spec: PartialEq + std::fmt::Debug,
{
    let mut a = app();
    a.run(Command::Edit(T::edit(Some(bad.clone()), None)));
    assert_eq!(T::part(a.doc.state()), Some(&bad));
    a.wait_idle();
    let e = tab(&mut a).surface().expect_err("refused");
    assert!(e.contains(says), "{e}");
    zero_resolution(&mut bad);
    a.run(Command::Edit(T::edit(Some(bad), None)));
    assert!(
        a.note.as_ref().unwrap().contains("resolution 0"),
        "{:?}",
        a.note
    );
}

/// The document of the app in `h` saved as `NAME.prism.json` and opened again, and the size
/// of the STL its tab exports as `NAME.stl`.
pub(super) fn saved_and_exported(h: &mut Harness<'_, PrismApp>, name: &str) -> (DocState, u64) {
    let scratch = tempfile::tempdir().unwrap();
    let doc = scratch.path().join(format!("{name}.prism.json"));
    h.state_mut().save_to(&doc).unwrap();
    let stl = scratch.path().join(format!("{name}.stl"));
    h.state_mut().export_to(&stl, false).unwrap();
    let (state, _) = document::open(&doc).unwrap();
    (state, std::fs::metadata(&stl).unwrap().len())
}

/// Bad input in the 3D tabs: a scene with a non-convex primitive and a section off its plane
/// are refused by the build, named, and kept; a resolution outside 1..=256 is refused by the
/// edit.
#[test]
fn bad_input_in_the_3d_tabs_shows_its_message_and_is_kept() {
    use gestures::Tab3d;
    let mut scene = envelope::EnvelopeTab::sample(0).unwrap();
    scene.primitives[0].vertices[7][2] = 1.3;
    let says = "primitive 0: vertex";
    refused_and_kept(|a| &mut a.envelope, (scene, says), |s| s.resolution = 0);
    let mut sections = skin::SkinTab::sample(1).unwrap();
    sections.sections[2].points[3].z += 0.5;
    let says = "section 2 is not planar";
    refused_and_kept(|a| &mut a.skin, (sections, says), |s| s.resolution = 0);
}

/// The 3D tabs refuse a surface whose mesh would go over the memory budget before they
/// tessellate it, say so with both numbers, and build it when the budget is raised.
#[test]
fn the_3d_tabs_refuse_a_surface_over_the_memory_budget() {
    use gestures::Tab3d;
    let mut a = app();
    let scene = envelope::EnvelopeTab::sample(0).ok();
    a.run(Command::Edit(envelope::EnvelopeTab::edit(scene, None)));
    let sections = skin::SkinTab::sample(0).ok();
    a.run(Command::Edit(skin::SkinTab::edit(sections, None)));
    for mib in [16, 4096] {
        (a.envelope.budget, a.skin.budget) = (mib << 20, mib << 20);
        a.wait_idle();
        let surfaces = [
            a.envelope.surface().map(|m| m.num_faces()),
            a.skin.surface().map(|m| m.num_faces()),
        ];
        for s in surfaces {
            match mib {
                16 => {
                    let e = s.expect_err("refused");
                    assert!(e.contains("more than the memory budget of 16 MiB"), "{e}");
                    assert!(e.contains("a smaller resolution"), "{e}");
                }
                _ => assert!(s.expect("built") > 0),
            }
        }
    }
}

/// The clamp's checkbox acts at once (issue 66, item 3): a radius too big for the tripod is
/// refused with the clamp off; ticking the box computes the level with clamped radii, and
/// unticking refuses it again, with no other change in between; the mending box too.
#[test]
fn toggling_the_clamp_recomputes_at_once() {
    use egui_kittest::kittest::Queryable;
    let mut h = harness(app());
    settle(&mut h);
    let label = "Clamp overlapping radii and chamfers";
    h.get_by_label(label).click();
    settle(&mut h);
    assert!(!h.state().model.clamp);
    let steps = parse_pipeline("combination:r=1.5").unwrap();
    h.state_mut()
        .run(Command::Edit(Edit::SetPipeline { view: 0, steps }));
    settle(&mut h);
    let levels = |h: &Harness<'_, PrismApp>| h.state().model.views[0].pipeline.levels().len();
    assert_eq!(levels(&h), 1, "refused without the clamp");
    assert!(h.state().model.views[0].error.is_some());
    for (on, expected) in [(true, 2), (false, 1)] {
        h.get_by_label(label).click();
        settle(&mut h);
        assert_eq!(h.state().model.clamp, on);
        assert_eq!(
            levels(&h),
            expected,
            "clamp {on}: {:?}",
            h.state().model.views[0].error
        );
    }
    // Mending, likewise: the levels are computed again with the new option.
    let mending = h.state().model.mend_crossings;
    h.get_by_label("Mend faces that pass through each other")
        .click();
    settle(&mut h);
    let options = &h.state().model.views[0].pipeline.options;
    assert_eq!(options.mend.crossings, !mending);
}

/// The title says the document's name and marks unsaved changes with `*` (issue 66, item
/// 11); a save clears the mark. On closing with unsaved changes the window asks: *Cancel*
/// keeps it open, *Don't save* lets the close through.
#[test]
fn the_title_marks_unsaved_changes_and_closing_asks() {
    use egui_kittest::kittest::Queryable;
    let mut h = harness(app());
    settle(&mut h);
    assert_eq!(h.state().title(), "tripod (bundled sample) — Prism");
    let steps = parse_pipeline("doo-sabin").unwrap();
    h.state_mut()
        .run(Command::Edit(Edit::SetPipeline { view: 0, steps }));
    settle(&mut h);
    assert_eq!(h.state().title(), "*tripod (bundled sample) — Prism");
    for (answer, leave) in [("Cancel", false), ("Don't save", true)] {
        h.state_mut().closing.asking = true;
        settle(&mut h);
        h.get_by_label("Save the changes before closing?");
        h.get_by_label(answer).click();
        settle(&mut h);
        assert!(!h.state().closing.asking, "{answer}");
        assert_eq!(h.state().closing.leave, leave, "{answer}");
    }
    let scratch = tempfile::tempdir().unwrap();
    let doc = scratch.path().join("kept.prism.json");
    h.state_mut().save_to(&doc).unwrap();
    assert_eq!(h.state().title(), "kept.prism.json — Prism");
}

/// F11 hides the side panel so that the views fill the window, and shows it again; the
/// number keys turn the camera to the standard views (issue 66, items 9 and 11), in the
/// Model tab and in the 3D tabs.
#[test]
fn f11_hides_the_panel_and_number_keys_give_standard_views() {
    use egui_kittest::kittest::Queryable;
    let mut h = harness(app());
    settle(&mut h);
    h.get_by_label("Pipeline");
    h.key_press(egui::Key::F11);
    settle(&mut h);
    assert!(
        h.query_by_label("Pipeline").is_none(),
        "the panel is hidden"
    );
    h.key_press(egui::Key::F11);
    settle(&mut h);
    h.get_by_label("Pipeline");
    let turned = |c: prism_viewport::Camera, v: prism_viewport::View| {
        let (yaw, pitch) = v.angles();
        assert!(
            (c.yaw - yaw).abs() < 1e-6 && (c.pitch - pitch).abs() < 1e-6,
            "{v:?}: {c:?}"
        );
    };
    use prism_viewport::View;
    for (key, view) in [
        (egui::Key::Num1, View::Front),
        (egui::Key::Num3, View::Right),
        (egui::Key::Num7, View::Top),
        (egui::Key::Num0, View::Iso),
    ] {
        h.key_press(key);
        settle(&mut h);
        turned(h.state().model.camera, view);
    }
    h.get_by_label("Envelope").click();
    settle(&mut h);
    h.key_press(egui::Key::Num3);
    settle(&mut h);
    turned(h.state().envelope.base.view.camera, View::Right);
}

/// Compare: with "Same level in every view" ticked, the level slider moves every view
/// (issue 66, item 9); without it, only the active one.
#[test]
fn one_level_for_every_compare_view() {
    use egui_kittest::kittest::{NodeT, Queryable};
    let mut a = app();
    run_pipeline(&mut a, "doo-sabin,doo-sabin,doo-sabin");
    a.run(Edit::SetViews(2));
    let steps = parse_pipeline("catmull-clark,catmull-clark,catmull-clark").unwrap();
    a.run(Edit::SetPipeline { view: 1, steps });
    a.wait_idle();
    let mut h = harness(a);
    settle(&mut h);
    let levels = |h: &Harness<'_, PrismApp>| -> Vec<usize> {
        h.state().model.views.iter().map(|v| v.level).collect()
    };
    assert_eq!(levels(&h), [3, 3]);
    for (link, expected) in [(false, [2, 3]), (true, [1, 1])] {
        if link {
            h.get_by_label("Same level in every view").click();
            settle(&mut h);
        }
        // The level slider: the one whose value is the active view's level.
        let shown = h.state().model.views[0].level as f64;
        h.get_all_by_role(egui::accesskit::Role::Slider)
            .find(|s| s.accesskit_node().numeric_value() == Some(shown))
            .expect("the level slider")
            .focus();
        h.step();
        h.key_press(egui::Key::ArrowLeft);
        settle(&mut h);
        assert_eq!(levels(&h), expected, "linked {link}");
    }
}

/// The camera stays put in the world while the model changes under it (issue 66, item 6):
/// a vertex moved far out grows the level's box, whose centre the scene's positions are
/// measured from, and the view does not re-frame; in the Skin tab likewise when a section
/// moves.
#[test]
fn the_camera_stays_put_while_the_model_changes() {
    let mut h = harness(app());
    settle(&mut h);
    let world = |h: &Harness<'_, PrismApp>| {
        let m = &h.state().model;
        m.views[0].scene.origin + m.view_camera(0).target.as_dvec3()
    };
    let before = world(&h);
    let origin = h.state().model.views[0].scene.origin;
    h.state_mut().run(Command::Edit(Edit::MoveVertices {
        verts: vec![0],
        by: glam::DVec3::new(10.0, 10.0, 10.0),
    }));
    settle(&mut h);
    assert_ne!(
        h.state().model.views[0].scene.origin,
        origin,
        "the test needs a moved box"
    );
    assert!(
        (world(&h) - before).length() < 1e-5,
        "{} against {before}",
        world(&h)
    );
    // The Skin tab: a section moved along x.
    use egui_kittest::kittest::Queryable;
    h.get_by_label("Skin").click();
    settle(&mut h);
    h.get_by_label("Spout (6 sections)").click();
    settle(&mut h);
    let world = |h: &Harness<'_, PrismApp>| {
        let v = &h.state().skin.base.view;
        v.scene.origin + v.camera.target.as_dvec3()
    };
    let before = world(&h);
    let mut spec = h.state().doc.state().skin.clone().unwrap();
    for p in &mut spec.sections[5].points {
        p.x += 4.0;
    }
    h.state_mut()
        .run(Command::Edit(skin::SkinTab::edit(Some(spec), None)));
    settle(&mut h);
    assert!(
        (world(&h) - before).length() < 1e-5,
        "{} against {before}",
        world(&h)
    );
}

/// Layout at 1024 × 700 (issue 66, item 8): a step's warning in the panel (vector sum above
/// α = ¼) wraps instead of widening the side panel, which stays within its width range.
#[test]
fn long_messages_never_widen_the_side_panel() {
    let mut a = app();
    run_pipeline(&mut a, "vector-sum:alpha=0.45,vector-sum:alpha=0.45");
    let mut h = Harness::builder()
        .with_size(egui::vec2(1024.0, 700.0))
        .build_ui_state(|ui, app: &mut PrismApp| app.frame_ui(ui), a);
    settle(&mut h);
    use egui_kittest::kittest::Queryable;
    let right = h
        .query_all_by_label_contains("above 0.25")
        .map(|n| n.rect().right())
        .fold(0.0f32, f32::max);
    assert!(right > 0.0, "the warning is shown");
    assert!(right <= 440.0, "the warning reaches x = {right}");
    // The status bar starts where the side panel ends.
    let edge = h
        .query_all_by_label_contains("level 2 of 2")
        .map(|n| n.rect().left())
        .fold(f32::INFINITY, f32::min);
    assert!(edge <= 460.0, "the side panel ends at x = {edge}");
}

/// File ▸ Recent (issue 66, item 11): files opened or saved, the latest first, each once,
/// remembered with the settings; choosing one opens it.
#[test]
fn recent_files_are_listed_remembered_and_opened() {
    use egui_kittest::kittest::Queryable;
    let scratch = tempfile::tempdir().unwrap();
    let (a_obj, b_obj) = (scratch.path().join("a.obj"), scratch.path().join("b.obj"));
    let tet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
    std::fs::write(&a_obj, tet).unwrap();
    std::fs::write(&b_obj, tet).unwrap();
    let mut a = app();
    for p in [&a_obj, &b_obj, &a_obj] {
        a.run(Command::Open(p.clone()));
    }
    let saved = scratch.path().join("c.prism.json");
    a.save_to(&saved).unwrap();
    let abs = |p: &std::path::Path| std::path::absolute(p).unwrap();
    assert_eq!(a.recent, [abs(&saved), abs(&a_obj), abs(&b_obj)]);
    // The next run remembers them; File ▸ Recent ▸ b.obj opens it.
    let b = PrismApp::headless(Launch::default(), Some(a.settings())).unwrap();
    assert_eq!(b.recent.len(), 3);
    let mut h = harness(b);
    settle(&mut h);
    h.get_by_label("File").click();
    h.run();
    h.get_by_label("Recent").hover();
    h.run();
    h.get_by_label("b.obj").click();
    settle(&mut h);
    assert!(h.state().doc.origin().name.ends_with("b.obj"));
}

pub(super) fn settle(h: &mut Harness<'_, PrismApp>) {
    for _ in 0..3 {
        h.step();
        h.state_mut().wait_idle();
    }
}

/// A primary-button drag from `at` to the right by `steps` (one frame each), then settled.
pub(super) fn drag_right(h: &mut Harness<'_, PrismApp>, at: egui::Pos2, steps: &[f32]) {
    let button = |pos, pressed| egui::Event::PointerButton {
        pos,
        button: egui::PointerButton::Primary,
        pressed,
        modifiers: egui::Modifiers::NONE,
    };
    h.event(egui::Event::PointerMoved(at));
    h.step();
    h.event(button(at, true));
    h.step();
    let mut end = at;
    for &x in steps {
        end = at + egui::vec2(x, 0.0);
        h.event(egui::Event::PointerMoved(end));
        h.step();
    }
    h.event(button(end, false));
    settle(h);
}

/// The Curves tab names each scheme as `prism curve --scheme` does, and choosing another does
/// not move the controls after the menu (its width is fixed).
#[test]
fn the_curve_scheme_menu_uses_the_cli_names_and_keeps_its_place() {
    use egui_kittest::kittest::Queryable;
    let mut h = in_tab("Curves");
    let mut places = Vec::new();
    for s in prism_geom::curve::CurveScheme::ALL {
        h.state_mut().run(CurveEdit::SetScheme(s));
        settle(&mut h);
        let name = s.name();
        let label = format!("{name}: ");
        assert!(h.get_by_label_contains(&label).rect().width() > 100.0);
        places.push(h.get_by_label("closed").rect().left());
    }
    assert!(
        places.windows(2).all(|w| (w[0] - w[1]).abs() < 0.5),
        "{places:?}"
    );
}

/// Every control the app can disable says why when hovered: each `add_enabled` in the GUI's
/// sources is followed, within its statement, by `on_disabled_hover_text` (Loop's and the step
/// arrows' greyed-out buttons said nothing).
#[test]
fn every_disabled_control_says_why() {
    // Every source file of the window but its tests, read from the source tree.
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/gui");
    let mut sources = Vec::new();
    let mut dirs = vec![root.clone()];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            let name = path.strip_prefix(&root).unwrap().display().to_string();
            if path.is_dir() {
                dirs.push(path);
            } else if name.ends_with(".rs") && !name.contains("tests") {
                sources.push((name, std::fs::read_to_string(&path).unwrap()));
            }
        }
    }
    assert!(sources.len() > 20, "{} files", sources.len());
    let mut found = 0;
    for (name, text) in &sources {
        // The text without its `#[cfg(test)]` part.
        let text = text.split("#[cfg(test)]").next().unwrap();
        for (at, _) in text.match_indices("add_enabled") {
            found += 1;
            // The statement: up to the next `;` or `{` that opens the branch it guards, but
            // far enough to hold a multi-line button.
            let rest = &text[at..(at + 700).min(text.len())];
            let line = text[..at].lines().count();
            assert!(
                rest.contains("on_disabled_hover_text"),
                "{name}:{line}: a control that can be disabled without saying why"
            );
        }
    }
    assert!(found >= 9, "{found}");
}

/// Undoing an Open brings back the other document framed as it was: the camera stayed on the
/// opened one (the Computer room's framing around the small tripod).
#[test]
fn undoing_an_open_frames_the_document_it_brings_back() {
    let mut h = harness(app());
    settle(&mut h);
    let tripod = h.state().model.camera.distance;
    let room = SAMPLES_FILES
        .iter()
        .position(|s| s.0 == "Computer room")
        .unwrap();
    h.state_mut().run(Command::OpenSample(room));
    // The old picture goes at once (issue 66, item 6): the view frames the new model when
    // its first level comes, not the old one still on screen.
    assert!(h.state().model.views[0].scene.vertices.is_empty());
    settle(&mut h);
    let far = h.state().model.camera.distance;
    assert!(far > 2.0 * tripod, "{far} vs {tripod}");
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    let back = h.state().model.camera.distance;
    assert!((back / tripod - 1.0).abs() < 0.01, "{back} vs {tripod}");
    // And redo frames the room again.
    h.key_press_modifiers(
        egui::Modifiers::COMMAND | egui::Modifiers::SHIFT,
        egui::Key::Z,
    );
    settle(&mut h);
    assert!((h.state().model.camera.distance / far - 1.0).abs() < 0.01);
}

#[test]
fn each_compare_view_frames_its_own_model() {
    let mut a = app();
    a.model.step();
    a.model.step();
    a.wait_idle();
    a.run(Edit::SetViews(2));
    a.wait_idle();
    rebuild(&mut a);
    // View 2 shows a level with a vertex thrown far out: its bounding box, and with it its
    // scene's origin, lies thousands of units from view 1's.
    let shown = |a: &PrismApp, i: usize| {
        let v = &a.model.views[i];
        v.pipeline.levels()[v.shown()].mesh.clone()
    };
    let mut m = shown(&a, 1);
    m.positions[0] = glam::DVec3::new(1e4, 0.0, 0.0);
    a.model.views[1].show_scene(prism_viewport::Scene::plain(&m));
    a.model.active = 1;
    a.model.frame(a.doc.state());
    // Two views of the width / height the frame was fitted to (1.5 before a frame is drawn).
    let cells = model::views::grid(
        egui::Rect::from_min_size(egui::pos2(0.0, 0.0), egui::vec2(902.0, 300.0)),
        2,
    );
    for (i, cell) in cells.iter().enumerate() {
        let proj = a.model.projector(i, *cell);
        let v = &a.model.views[i];
        let (c, _, far) = v.frame_sphere();
        assert_eq!(far > 0, i == 1);
        let (s, _) = proj.project(v.scene.origin + c.as_dvec3()).unwrap();
        assert!(
            (s - cell.center()).length() < 1.0,
            "view {}: framing centre at {s:?}, the view's middle is {:?}",
            i + 1,
            cell.center()
        );
        let mesh = shown(&a, i);
        let positions: Vec<_> = if i == 1 {
            m.positions[1..].to_vec()
        } else {
            mesh.positions.clone()
        };
        for p in positions {
            let (s, _) = proj.project(p).unwrap();
            assert!(
                cell.contains(s),
                "view {}: vertex at {p} drawn at {s:?}, outside {cell:?}",
                i + 1
            );
        }
    }
}

/// Keys typed into a file dialog reach the window when the dialog returns; they must not
/// step, go back or toggle the display. Keys typed after that work again.
#[test]
fn keys_typed_while_a_file_dialog_was_open_are_dropped() {
    let mut h = harness(app());
    settle(&mut h);
    let wire = h.state().model.display.wireframe;
    // What the dialog functions mark when rfd returns (a real dialog needs a desktop).
    h.state_mut().dialog_returned();
    h.key_press(egui::Key::S);
    h.key_press(egui::Key::W);
    h.event(egui::Event::Text("sw".into()));
    settle(&mut h);
    assert_eq!(h.state().doc.state().pipelines[0].len(), 0);
    assert_eq!(h.state().model.display.wireframe, wire);
    std::thread::sleep(std::time::Duration::from_millis(350));
    settle(&mut h);
    h.key_press(egui::Key::S);
    settle(&mut h);
    assert_eq!(h.state().doc.state().pipelines[0].len(), 1);
}

/// A step that throws vertices far out, framed on: Ctrl+Z brings back the model and the
/// camera it had before the step.
#[test]
fn undoing_a_blow_up_restores_the_camera_it_had() {
    let mut a = app();
    a.model.camera.orbit(0.3, 0.1);
    let before = a.model.camera;
    a.model.step();
    a.wait_idle();
    rebuild(&mut a);
    let mut m = a.model.views[0].pipeline.levels()[1].mesh.clone();
    m.positions[0] = glam::DVec3::new(1e4, 0.0, 0.0);
    a.model.views[0].show_scene(prism_viewport::Scene::plain(&m));
    a.model.camera.zoom(40.0);
    assert_ne!(a.model.camera, before);
    a.run(Command::Undo);
    assert_eq!(a.doc.state().pipelines[0].len(), 0);
    assert_eq!(a.model.camera, before);
}

/// At the default window size, 1280×800, with four views of five-step pipelines and the
/// Edges tool (the tallest side panel): the side panel's last control is inside the window
/// and the compare table shows every column and every row.
#[test]
fn the_model_tab_fits_1280_by_800() {
    use egui_kittest::kittest::Queryable;
    let mut a = app();
    let five = parse_pipeline(&["combination:r=0.2"; 5].join(",")).unwrap();
    a.run(Edit::SetPipeline {
        view: 0,
        steps: five,
    });
    a.run(Edit::SetViews(4));
    let mixed = parse_pipeline(
        "cylindrical:r=0.2,cylindrical:r=0.2,vector-sum:alpha=0.2,doo-sabin,doo-sabin",
    )
    .unwrap();
    for view in 1..4 {
        a.run(Edit::SetPipeline {
            view,
            steps: mixed.clone(),
        });
    }
    a.model.tool = Tool::Edges;
    let mut h = harness(a);
    settle(&mut h);
    let window = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(1280.0, 800.0));
    let inside = |h: &Harness<'_, PrismApp>, label: &str| {
        let r = h.get_by_label(label).rect();
        assert!(window.contains_rect(r), "{label} at {r:?}");
        r
    };
    inside(&h, "Frame the model");
    inside(&h, "Clear crease");
    inside(&h, "4 views");
    let header = inside(&h, "ms per level");
    inside(&h, "fillet radius reached");
    inside(&h, "crossing");
    // The fourth row is on screen, below the header.
    let row = inside(&h, "4");
    assert!(row.top() > header.bottom(), "{row:?}");
}

/// A file that cannot be opened at start opens the window anyway, on the bundled tripod,
/// with the reason in the status bar.
#[test]
fn a_missing_file_at_start_opens_the_tripod_and_says_why() {
    let a = PrismApp::headless(
        Launch {
            file: Some("no-such-file.obj".into()),
            ..Launch::default()
        },
        None,
    )
    .unwrap();
    assert!(a.doc.origin().name.contains("tripod"));
    let note = a.note.clone().unwrap_or_default();
    assert!(
        note.contains("could not open no-such-file.obj") && note.contains("cannot read"),
        "{note}"
    );
}

/// `--no-clamp` starts the app on the papers' literal rules: a radius that does not fit the
/// tripod's arms is refused (the default clamps it and computes), and the panel says the clamp
/// is off.
#[test]
fn no_clamp_at_start_gives_the_papers_literal_rules() {
    let launch = |no_clamp: bool| {
        let mut a = PrismApp::headless(
            Launch {
                pipeline: parse_pipeline("combination:r=1.5").unwrap(),
                no_clamp,
                ..Launch::default()
            },
            None,
        )
        .unwrap();
        a.wait_idle();
        a
    };
    let clamped = launch(false);
    assert!(clamped.model.clamp);
    assert!(clamped.model.views[0].error.is_none());
    let literal = launch(true);
    assert!(!literal.model.clamp);
    let error = literal.model.views[0].error.clone().unwrap_or_default();
    assert!(error.contains("fits up to"), "{error}");
    let mut h = harness(literal);
    h.step();
    egui_kittest::kittest::Queryable::get_by_label_contains(
        &h,
        "Clamp off: the papers' literal rules",
    );
}

/// Play levels shows the levels one after another, a second each, round again after the
/// last; Pause levels stops at the level shown.
#[test]
fn play_levels_steps_through_them_and_pause_stops() {
    use egui_kittest::kittest::Queryable;
    let mut a = PrismApp::headless(
        Launch {
            pipeline: parse_pipeline("catmull-clark,catmull-clark").unwrap(),
            ..Launch::default()
        },
        None,
    )
    .unwrap();
    a.wait_idle();
    let mut h = harness(a);
    h.step();
    assert_eq!(h.state().model.views[0].level, 2);
    h.get_by_label("Play levels").click();
    h.step();
    assert!(h.state().model.playing.is_some());
    let mut shown = Vec::new();
    for _ in 0..4 {
        // As if a second had passed.
        h.state_mut().model.playing =
            Some(std::time::Instant::now() - std::time::Duration::from_millis(1100));
        h.step();
        shown.push(h.state().model.views[0].level);
    }
    assert_eq!(shown, [0, 1, 2, 0], "round again after the last");
    h.get_by_label("Pause levels").click();
    h.step();
    assert!(h.state().model.playing.is_none());
    h.step();
    assert_eq!(h.state().model.views[0].level, 0, "stays");
}

/// Every teaching overlay of the Skin, Envelope and Curves tabs can be asked for at start
/// (`--show`), for a screenshot of a paper's figure.
#[test]
fn the_teaching_overlays_can_be_asked_for_at_start() {
    let a = PrismApp::headless(
        Launch {
            show: vec![
                Show::NetworkOnly,
                Show::Trajectories,
                Show::Swept,
                Show::Contours,
                Show::Twists,
                Show::Evolute,
                Show::NoComb,
                Show::Xray,
            ],
            ..Launch::default()
        },
        None,
    )
    .unwrap();
    assert!(!a.envelope.overlays.surface);
    let o = &a.skin.overlays;
    assert!(o.trajectories && o.swept && o.contours && o.twists);
    assert!(a.curves.evolute && !a.curves.comb);
    assert!(a.skin.overlays.look.xray && a.envelope.overlays.look.xray);
    let plain = PrismApp::headless(Launch::default(), None).unwrap();
    assert!(plain.envelope.overlays.surface && !plain.skin.overlays.trajectories);
    assert!(!plain.curves.evolute && plain.curves.comb);
}

/// The Measure tool: clicks on the surface of the level shown put points on it — where the
/// ray meets the nearest face — and the panel's lines give the distances between them and
/// the radius of the circle through three; the overlay draws them; a fourth click starts
/// again.
#[test]
fn the_measure_tool_reads_distances_and_a_radius() {
    let mut a = app();
    a.model.tool = Tool::Measure;
    let proj: Projector = a.model.projector(0, rect());
    let mesh = a.model.views[0].pipeline.levels()[0].mesh.clone();
    let scene = a.model.views[0].scene.clone();
    // The centroids of the first three square faces seen (an L's centroid lies in its notch).
    let mut picked = Vec::new();
    for f in (0..mesh.num_faces()).filter(|&f| mesh.face_corners(f).len() == 4) {
        let c = mesh
            .face_corners(f)
            .map(|c| mesh.positions[mesh.corner_verts[c] as usize]);
        let n = mesh.face_corners(f).len() as f64;
        let centroid = c.sum::<glam::DVec3>() / n;
        if let Some((s, _)) = proj.project(centroid)
            && proj.rect.contains(s)
            && proj.visible(&scene, centroid)
        {
            let doc = a.doc.state().clone();
            a.model.click_pick(0, &proj, s, false, &doc);
            picked.push(centroid);
            if picked.len() == 3 {
                break;
            }
        }
    }
    assert_eq!(picked.len(), 3);
    let m = a.model.measure.clone();
    assert_eq!(m.len(), 3);
    for (p, q) in m.iter().zip(&picked) {
        assert!(p.distance(*q) < 1e-3, "{p} {q}");
    }
    let lines = super::model::panels::measure_lines(&m);
    let d = picked[0].distance(picked[1]);
    assert!(
        lines[0].starts_with(&format!("distance 1–2: {:.2}", d)),
        "{lines:?}"
    );
    let r = prism_geom::geometry::circumradius(picked[0], picked[1], picked[2]).unwrap();
    assert!(lines[3].contains(&format!("{:.2}", r)), "{lines:?}");
    rebuild(&mut a);
    let cyan = lines_of(&a, true, [0.30, 0.95, 1.0]);
    assert!(cyan >= 6, "{cyan}");
    let doc = a.doc.state().clone();
    let s = proj.project(picked[0]).unwrap().0;
    a.model.click_pick(0, &proj, s, false, &doc);
    assert_eq!(a.model.measure.len(), 1);
}

/// Help ▸ Paper figures opens a figure's state: seed 000 fig. 2 (clicked in the menu) is the
/// tripod through three Doo–Sabin steps with the last level shown, on the Model tab, with
/// the clamp off (the paper's literal rule); fig. 13 colours by face kind; seed 003 fig. 4 is
/// the spout on the Skin tab with its contours; seed 004 fig. 4 the two cubes' network alone
/// on the Envelope tab. Each is undoable as an open.
#[test]
fn help_opens_the_papers_figures() {
    use egui_kittest::kittest::Queryable;
    let mut h = harness(app());
    settle(&mut h);
    h.get_by_label("Help").click();
    settle(&mut h);
    h.get_by_label("Paper figures").click();
    settle(&mut h);
    h.get_by_label("000 fig. 2: Doo–Sabin subdivision of the tripod")
        .click();
    settle(&mut h);
    let a = h.state_mut();
    a.wait_idle();
    assert_eq!(a.tab, Tab::Model);
    assert!(
        a.doc.origin().name.contains("tripod"),
        "{}",
        a.doc.origin().name
    );
    assert_eq!(
        a.doc.state().pipelines[0],
        parse_pipeline("doo-sabin,doo-sabin,doo-sabin").unwrap()
    );
    assert_eq!(a.model.views[0].shown(), 3);
    assert!(!a.model.clamp);
    let mut a = app();
    let index = |id: &str| {
        super::paper_figures::FIGURES
            .iter()
            .position(|f| f.id == id)
            .unwrap()
    };
    a.run(Command::OpenFigure(index("000 fig. 13")));
    a.wait_idle();
    assert_eq!(a.model.display.color, super::model::Coloring::Kind);
    a.run(Command::OpenFigure(index("003 fig. 4")));
    a.wait_idle();
    assert_eq!(a.tab, Tab::Skin);
    assert!(a.skin.overlays.contours);
    a.run(Command::OpenFigure(index("004 fig. 4")));
    a.wait_idle();
    assert_eq!(a.tab, Tab::Envelope);
    assert!(!a.envelope.overlays.surface);
    // Every figure opens without a note of failure.
    for k in 0..super::paper_figures::FIGURES.len() {
        a.run(Command::OpenFigure(k));
        a.wait_idle();
        let note = a.note.clone().unwrap_or_default();
        assert!(note.starts_with("opened seed"), "{k}: {note}");
        assert!(
            a.model.views[0].error.is_none(),
            "{k}: {:?}",
            a.model.views[0].error
        );
    }
}
