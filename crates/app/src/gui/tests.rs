//! The app driven without a window: the "done when" walk (step the tripod with
//! combination r = 0.2 five times, smooth shading and wireframe, pick an edge and crease it,
//! compare two pipelines, undo, save and reopen), vertex editing, and the budget question.

use super::pick::Projector;
use super::*;
use prism_geom::scheme::parse_pipeline;

fn app() -> PrismApp {
    let mut a = PrismApp::headless(Launch::default(), None).unwrap();
    a.wait_idle();
    a.rebuild_scenes();
    a.frame();
    a
}

/// The app started on a file, its levels computed.
fn opened(path: &std::path::Path) -> PrismApp {
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
    let proj: Projector = a.projector(0, rect());
    let origins = a.views[0].origins();
    let map = origins.as_ref().as_ref().unwrap().clone();
    let k = a.views[0].shown();
    let mesh = a.views[0].pipeline.levels()[k].mesh.clone();
    let scene = a.views[0].scene.clone();
    for (e, c) in &map {
        if *c != control {
            continue;
        }
        let mid = 0.5 * (mesh.positions[e.0 as usize] + mesh.positions[e.1 as usize]);
        if let Some((s, _)) = proj.project(mid)
            && proj.rect.contains(s)
            && proj.visible(&scene, mid)
        {
            a.click_pick(0, &proj, s, false);
            return true;
        }
    }
    false
}

#[test]
fn the_new_user_walk_through() {
    let mut a = app();
    assert!(a.origin.name.contains("tripod"));
    a.next = parse_pipeline("combination:r=0.2").unwrap()[0];
    for _ in 0..5 {
        a.step();
    }
    a.wait_idle();
    let v = &a.views[0];
    assert_eq!(v.pipeline.levels().len(), 6);
    assert_eq!(v.shown(), 5);
    let last = v.pipeline.levels()[5].report.as_ref().unwrap();
    assert!(last.flipped.is_empty());

    // Smooth shading and wireframe.
    a.display.smooth = true;
    a.display.wireframe = true;
    a.display_changed();
    a.rebuild_scenes();
    assert!(!a.views[0].scene.lines.is_empty());

    // Pick an edge on level 5 and crease it: the mark lands on the control edge.
    a.tool = Tool::Edges;
    a.rebuild_scenes();
    a.frame();
    let control = *pick::mesh_edges(&a.doc.mesh)
        .iter()
        .find(|&&e| {
            let mut b = std::mem::take(&mut a.sel_edges);
            b.clear();
            click_edge_of(&mut a, e)
        })
        .expect("some control edge is visible on level 5");
    assert_eq!(
        a.sel_edges.iter().copied().collect::<Vec<_>>(),
        vec![control]
    );
    a.mark_crease(10.0);
    a.wait_idle();
    assert_eq!(a.doc.edge_attrs[&control].crease, 10.0);
    a.rebuild_scenes();
    assert!(
        !a.views[0].overlay.lines.is_empty(),
        "the creased edge is drawn"
    );

    // Compare two pipelines side by side: Catmull–Clark keeps the creased edge sharp.
    a.set_compare(2);
    let other = parse_pipeline("catmull-clark,catmull-clark").unwrap();
    a.change(|d| d.pipelines[1] = other.clone());
    a.wait_idle();
    assert_eq!(a.views.len(), 2);
    assert_eq!(a.views[1].pipeline.levels().len(), 3);
    let mut plain =
        prism_geom::Pipeline::new(a.doc.mesh.clone(), Default::default(), other.clone());
    plain.compute().unwrap();
    let creased = &a.views[1].pipeline.levels()[2].mesh;
    let moved = creased
        .positions
        .iter()
        .zip(&plain.levels()[2].mesh.positions)
        .filter(|(p, q)| (**p - **q).length() > 1e-6)
        .count();
    assert!(moved > 0, "the crease changes the Catmull–Clark surface");
    let fillet = a.fillet_text(0);
    assert!(fillet.contains("r = 0.2"), "{fillet}");
    assert_eq!(a.fillet_text(1), "—");

    // Undo: the second pipeline, the split, the crease.
    a.undo();
    assert_eq!(a.doc.pipelines[1], a.doc.pipelines[0]);
    a.undo();
    assert_eq!(a.doc.pipelines.len(), 1);
    a.undo();
    assert!(a.doc.edge_attrs.is_empty());
    a.redo();
    assert_eq!(a.doc.edge_attrs[&control].crease, 10.0);
    a.wait_idle();
    assert_eq!(a.views.len(), 1);

    // Save and reopen.
    let path = std::env::temp_dir().join(format!("prism-walk-{}.prism.json", std::process::id()));
    a.save_to(&path).unwrap();
    let mut b = opened(&path);
    assert_eq!(b.doc.pipelines[0], a.doc.pipelines[0]);
    assert_eq!(b.doc.edge_attrs, a.doc.edge_attrs);
    assert!(b.views[0].pipeline.levels()[5].mesh == a.views[0].pipeline.levels()[5].mesh);
    // Exports of the shown level.
    for ext in ["obj", "stl", "glb"] {
        let p = path.with_extension(ext);
        b.export_to(&p).unwrap();
        assert!(std::fs::metadata(&p).unwrap().len() > 1000);
    }
}

#[test]
fn moving_a_control_vertex_recomputes_every_level_and_undoes_in_one_step() {
    let mut a = app();
    a.change(|d| d.pipelines[0] = parse_pipeline("combination:r=0.2,doo-sabin").unwrap());
    a.wait_idle();
    let old = a.views[0].pipeline.levels()[2].mesh.clone();
    let p0 = a.doc.mesh.positions[0];
    a.sel_verts.insert(0);
    a.move_vertices(&[0], glam::DVec3::new(0.0, 0.0, 0.3));
    a.wait_idle();
    let new = &a.views[0].pipeline.levels()[2].mesh;
    assert!(*new != old, "level 2 follows the moved vertex");
    assert_eq!(new.num_faces(), old.num_faces());
    a.undo();
    a.wait_idle();
    assert_eq!(a.doc.mesh.positions[0], p0);
    assert!(a.views[0].pipeline.levels()[2].mesh == old);
    // Non-finite typed coordinates are refused.
    a.move_vertices(&[0], glam::DVec3::new(f64::NAN, 0.0, 0.0));
    assert_eq!(a.doc.mesh.positions[0], p0);
    assert!(a.note.as_ref().unwrap().contains("numbers"));
}

#[test]
fn a_drag_along_an_axis_moves_along_that_axis_only() {
    let mut a = app();
    a.axis = Some(2);
    let d = a.drag_vector(egui::vec2(0.0, -50.0), rect());
    assert!(d.z > 0.0 && d.x == 0.0 && d.y == 0.0, "{d}");
    a.axis = None;
    let d = a.drag_vector(egui::vec2(40.0, 0.0), rect());
    assert!(d.length() > 0.0);
    // In the view plane: perpendicular to the viewing direction.
    let c = a.camera;
    let fwd = (c.target - c.eye()).normalize().as_dvec3();
    assert!(d.dot(fwd).abs() < 1e-6 * d.length());
}

#[test]
fn sharper_than_selects_the_tripods_feature_edges() {
    let mut a = app();
    a.select_sharper_than(60.0, false);
    let n = a.sel_edges.len();
    assert!(n > 0);
    a.select_sharper_than(179.0, false);
    assert!(a.sel_edges.is_empty());
    a.select_sharper_than(60.0, false);
    a.mark_radius(Some(0.05));
    assert_eq!(a.doc.edge_attrs.len(), n);
    a.mark_radius(Some(-1.0));
    assert!(a.note.as_ref().unwrap().contains("positive"));
}

#[test]
fn a_step_over_the_memory_budget_asks_first() {
    let mut a = app();
    a.budget_mib = 64;
    let steps = parse_pipeline(&["doo-sabin"; 9].join(",")).unwrap();
    a.change(|d| d.pipelines[0] = steps);
    a.wait_idle();
    let (view, o) = a.question.clone().expect("the budget question");
    assert_eq!(view, 0);
    assert!(o.needed_mib > 64);
    let computed = a.views[0].pipeline.levels().len();
    assert!(computed < 10);
    // "Remove the step" keeps what was computed.
    let keep = computed - 1;
    a.question = None;
    a.change(|d| d.pipelines[0].truncate(keep));
    a.wait_idle();
    assert!(a.views[0].pipeline.is_complete());
    assert!(a.views[0].error.is_none());
}

#[test]
fn bundled_samples_open_and_bad_files_say_why() {
    let mut a = app();
    for k in 0..SAMPLES_FILES.len() {
        a.open_sample(k);
        a.wait_idle();
        assert!(a.doc.mesh.num_faces() > 0, "sample {k}");
    }
    let bad = std::env::temp_dir().join(format!("prism-bad-{}.obj", std::process::id()));
    std::fs::write(&bad, "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n").unwrap();
    let faces = a.doc.mesh.num_faces();
    a.open_path(&bad);
    assert!(
        a.note.as_ref().unwrap().contains("could not open"),
        "{:?}",
        a.note
    );
    assert_eq!(a.doc.mesh.num_faces(), faces, "the document is kept");
    // Opening is undoable.
    a.undo();
    a.wait_idle();
    assert!(a.doc.mesh.num_faces() > 0);
}

#[test]
fn remembered_settings_reopen_the_last_file_with_the_display_options() {
    let path = std::env::temp_dir().join(format!("prism-last-{}.prism.json", std::process::id()));
    let mut a = app();
    a.change(|d| d.pipelines[0] = parse_pipeline("doo-sabin").unwrap());
    a.save_to(&path).unwrap();
    a.display.color = Coloring::Scheme;
    a.display.smooth = true;
    // What eframe stores is the settings struct (RON through serde).
    let stored = serde_json::to_string(&a.settings()).unwrap();
    let back: Settings = serde_json::from_str(&stored).unwrap();
    let mut b = PrismApp::headless(Launch::default(), Some(back)).unwrap();
    b.wait_idle();
    assert_eq!(b.origin.path.as_deref(), Some(path.as_path()));
    assert_eq!(b.doc.pipelines[0].len(), 1);
    assert!(b.display.smooth && b.display.color == Coloring::Scheme);
    // Colour by scheme paints the Doo–Sabin level in the scheme's colour.
    b.rebuild_scenes();
    let want = prism_viewport::scene::scheme_color(b.doc.pipelines[0].first());
    assert!(b.views[0].scene.vertices.iter().all(|v| v.color == want));
    // A file that is gone falls back to the bundled tripod.
    std::fs::remove_file(&path).unwrap();
    let c = PrismApp::headless(Launch::default(), Some(a.settings())).unwrap();
    assert!(c.origin.name.contains("tripod"));
}

/// The real panels, driven through egui_kittest: buttons, checkboxes, radio buttons, keys
/// and the menu bar reach the document as a user's clicks would.
#[test]
fn the_panels_buttons_and_keys_drive_the_document() {
    use egui_kittest::Harness;
    use egui_kittest::kittest::Queryable;
    let mut h = Harness::builder()
        .with_size(egui::vec2(1280.0, 800.0))
        .build_ui_state(|ui, app: &mut PrismApp| app.frame_ui(ui), app());
    let settle = |h: &mut Harness<'_, PrismApp>| {
        for _ in 0..3 {
            h.step();
            h.state_mut().wait_idle();
        }
    };
    settle(&mut h);
    h.get_by_label("Step >> (S)").click();
    settle(&mut h);
    assert_eq!(h.state().doc.pipelines[0].len(), 1);
    h.key_press(egui::Key::S);
    settle(&mut h);
    assert_eq!(h.state().doc.pipelines[0].len(), 2);
    assert_eq!(h.state().views[0].pipeline.levels().len(), 3);
    h.get_by_label("<< Back (B)").click();
    settle(&mut h);
    assert_eq!(h.state().doc.pipelines[0].len(), 1);

    h.get_by_label("smooth shading (F)").click();
    settle(&mut h);
    assert!(h.state().display.smooth);
    h.key_press(egui::Key::F);
    settle(&mut h);
    assert!(!h.state().display.smooth);

    h.get_by_label("2 views").click();
    settle(&mut h);
    assert_eq!(h.state().views.len(), 2);
    // Ctrl+Z undoes the split, then the Back.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    assert_eq!(h.state().views.len(), 1);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    assert_eq!(h.state().doc.pipelines[0].len(), 2);

    h.get_by_label("Edges").click();
    settle(&mut h);
    assert_eq!(h.state().tool, Tool::Edges);
    h.get_by_label("Select edges sharper than").click();
    settle(&mut h);
    assert!(!h.state().sel_edges.is_empty());
    h.get_by_label("Crease").click();
    settle(&mut h);
    assert!(h.state().doc.edge_attrs.values().all(|a| a.crease == 10.0));

    h.get_by_label("Curves").click();
    settle(&mut h);
    assert_eq!(h.state().tab, Tab::Curves);
    h.get_by_label("hexagon").click();
    settle(&mut h);
    assert_eq!(h.state().curves.control.points.len(), 6);
}

#[test]
fn a_big_level_gets_its_scene_on_a_thread_and_the_old_one_stays_meanwhile() {
    let path = std::env::temp_dir().join(format!("prism-big-{}.prism.json", std::process::id()));
    let doc = prism_geom::io::Document {
        mesh: prism_geom::primitives::torus(320, 320, 3.0, 1.0),
        edge_attrs: Default::default(),
        tags: Default::default(),
        pipeline: None,
    };
    prism_geom::io::save(&path, &doc).unwrap();
    let mut a = opened(&path);
    // The first scene comes from a thread; the window keeps drawing the empty one.
    a.rebuild_scenes();
    assert!(a.views[0].preparing());
    assert_eq!(a.views[0].scene.triangles(), 0);
    while a.views[0].preparing() {
        std::thread::sleep(std::time::Duration::from_millis(5));
        a.rebuild_scenes();
    }
    assert_eq!(a.views[0].scene.triangles(), 2 * 320 * 320);
    // A display change prepares again; the flat scene stays until the smooth one is there.
    let before = a.views[0].version;
    a.display.smooth = true;
    a.display_changed();
    a.rebuild_scenes();
    assert!(a.views[0].preparing());
    while a.views[0].preparing() {
        std::thread::sleep(std::time::Duration::from_millis(5));
        a.rebuild_scenes();
    }
    assert!(a.views[0].version > before);
    assert_eq!(
        a.views[0].scene_opts.shading,
        prism_viewport::Shading::Smooth
    );
    std::fs::remove_file(&path).ok();
}
