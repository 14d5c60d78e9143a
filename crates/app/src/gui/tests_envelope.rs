//! The Envelope tab driven through its real panels (egui_kittest): a primitive placed from
//! the library, the envelope built closed and G1, t moved as one undo step, a vertex picked
//! by a click and given its own t, the primitive dragged in the view as one undo step, the
//! scene saved with the document and reopened, exported, and undone across tabs.

use super::command::Edit;
use super::envelope::EnvelopeTab;
use super::gestures::Tab3d;
use super::tests::{app, drag_right, in_tab, saved_and_exported, settle};
use super::*;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

fn scene(h: &Harness<'_, PrismApp>) -> Option<prism_geom::freeform::envelope::EnvelopeSpec> {
    h.state().doc.state().envelope.clone()
}

#[test]
fn the_envelope_tab_places_edits_undoes_saves_and_exports_an_envelope() {
    let mut h = in_tab("Envelope");
    assert_eq!(h.state().tab, Tab::Envelope);
    h.get_by_label("Tetrahedron").click();
    settle(&mut h);
    let start = scene(&h).expect("a scene");
    {
        let b = h.state().envelope.built().expect("built");
        let (e, mesh) = b.result.as_ref().expect("an envelope");
        assert_eq!((e.regions, e.patch_count()), (4, 4));
        let topo = prism_geom::Topology::build(mesh).unwrap();
        topo.require_closed(mesh).unwrap();
        assert!(b.jump < 1e-9, "{}", b.jump);
        assert_eq!(b.folds, None);
    }
    h.get_by_label_contains("Folds: none");

    // t through the model as one gesture: one undo step.
    for t in [0.9, 0.7, 0.5] {
        let mut s = scene(&h).unwrap();
        s.t = t;
        h.state_mut().run(Command::Edit(Edit::SetEnvelope {
            spec: Some(s),
            gesture: Some(700),
        }));
    }
    settle(&mut h);
    assert_eq!(scene(&h).unwrap().t, 0.5);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    assert_eq!(scene(&h).unwrap(), start);

    // A click on a vertex picks it; its own t goes into vertex_t.
    let rect = egui::Rect::from_min_max(egui::pos2(300.0, 24.0), egui::pos2(1280.0, 800.0));
    let proj = h.state().envelope.projector(rect);
    let v0 = glam::DVec3::from_array(start.primitives[0].vertices[0]);
    let (at, _) = proj.project(v0).expect("vertex 0 in front");
    h.event(egui::Event::PointerMoved(at));
    h.step();
    for pressed in [true, false] {
        h.event(egui::Event::PointerButton {
            pos: at,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: egui::Modifiers::NONE,
        });
        h.step();
    }
    settle(&mut h);
    assert_eq!(h.state().envelope.picked, Some((0, 0)));
    // The crossing check answers on its own thread; the field is found once it has.
    while matches!(
        h.state().envelope.built().map(|b| &b.crossings),
        Some(envelope::build::Crossings::Checking(_))
    ) {
        std::thread::sleep(std::time::Duration::from_millis(2));
        h.step();
    }
    settle(&mut h);
    let field = h.get_by_value("own t: 1.00").rect().center();
    drag_right(&mut h, field, &[-10.0, -20.0, -30.0]);
    let own = scene(&h).unwrap().primitives[0]
        .vertex_t
        .clone()
        .expect("own t");
    assert!(
        own[0] < 1.0 && own[1..].iter().all(|&t| t == 1.0),
        "{own:?}"
    );
    assert!(h.state().envelope.built().unwrap().result.is_ok());
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    assert_eq!(scene(&h).unwrap(), start);

    // A drag in the view with the move tool moves the primitive: one undo step.
    h.state_mut().envelope.mouse = envelope::Mouse::Move;
    drag_right(&mut h, egui::pos2(800.0, 400.0), &[30.0, 60.0, 90.0]);
    let moved = scene(&h).unwrap();
    let d = glam::DVec3::from_array(moved.primitives[0].vertices[0]) - v0;
    assert!(d.length() > 0.05, "{d}");
    for (a, b) in moved.primitives[0]
        .vertices
        .iter()
        .zip(&start.primitives[0].vertices)
    {
        let e = glam::DVec3::from_array(*a) - glam::DVec3::from_array(*b);
        assert!((e - d).length() < 1e-12, "a move moves every vertex alike");
    }
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    assert_eq!(scene(&h).unwrap(), start);
    h.state_mut().envelope.mouse = envelope::Mouse::Orbit;

    // Saved with the document and reopened; exported as STL from the tab.
    let (state, stl) = saved_and_exported(&mut h, "tet");
    let triangles = h
        .state()
        .envelope
        .built()
        .unwrap()
        .result
        .as_ref()
        .unwrap()
        .1
        .num_faces() as u64;
    assert_eq!(stl, 84 + 50 * triangles);
    assert_eq!(state.envelope.as_ref(), Some(&start));

    // Undo across tabs: back to no scene at all.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    assert!(scene(&h).is_none());
    assert!(h.state().envelope.built().is_none());
}

/// The t sweep builds the scene at t = 1, 0.5, 0.1 with the own values of vertices dropped,
/// and follows the scene when it changes.
#[test]
fn the_t_sweep_shows_the_three_t() {
    let mut a = app();
    let mut spec = EnvelopeTab::sample(2).unwrap();
    spec.primitives[0].vertex_t = Some(vec![0.3; 8]);
    a.run(Command::Edit(Edit::SetEnvelope {
        spec: Some(spec.clone()),
        gesture: None,
    }));
    a.envelope.sweep = true;
    a.wait_idle();
    assert_eq!(
        a.envelope.sweep_summary(),
        vec![(1.0, Some(14)), (0.5, Some(14)), (0.1, Some(14))]
    );
    let one = envelope::with_uniform_t(&spec, 1.0);
    assert!(one.primitives.iter().all(|p| p.vertex_t.is_none()));
    spec.primitives.pop();
    a.run(Command::Edit(Edit::SetEnvelope {
        spec: Some(spec),
        gesture: None,
    }));
    a.wait_idle();
    assert_eq!(
        a.envelope.sweep_summary(),
        vec![(1.0, Some(6)), (0.5, Some(6)), (0.1, Some(6))]
    );
}

/// Folds are shown in the summary: none on the seven-primitive sample (the charts) at its own
/// t, at 0.5 or at 0.1, where the slider stops; the paper's patches of a heap of three
/// primitives at t = 0.005 have cells on a primitive's face turned over, counted, with where
/// the first lies.
#[test]
fn the_summary_counts_folds() {
    let k = envelope::ENVELOPE_SAMPLES
        .iter()
        .position(|s| s.1 == "table2-seven.envelope.json")
        .unwrap();
    let mut heap: prism_geom::freeform::envelope::EnvelopeSpec = serde_json::from_str(
        include_str!("../../../geom/tests/data/envelope/still-folding-heap.envelope.json"),
    )
    .unwrap();
    heap.patches = prism_geom::freeform::envelope::Surfacing::Paper;
    let seven = EnvelopeTab::sample(k).unwrap();
    for (spec, folded) in [
        (seven.clone(), false),
        (envelope::with_uniform_t(&seven, 0.5), false),
        (envelope::with_uniform_t(&seven, 0.1), false),
        (heap, true),
    ] {
        let mut a = app();
        a.run(Command::Edit(Edit::SetEnvelope {
            spec: Some(spec),
            gesture: None,
        }));
        a.wait_idle();
        let b = a.envelope.built().expect("built");
        match &b.folds {
            Some((n, text)) => {
                assert!(folded && *n > 0);
                assert_eq!(b.fold_points.len(), *n);
                assert!(text.contains("the first on primitive "), "{text}");
            }
            None => assert!(!folded && b.fold_points.is_empty()),
        }
    }
}

/// Faces that pass through each other (a heap of five at t = 0.005) are found on a thread after
/// the build, counted in the summary with where the first lies, and marked; the
/// seven-primitive sample has none.
#[test]
fn the_summary_counts_crossings() {
    let mut heap: prism_geom::freeform::envelope::EnvelopeSpec = serde_json::from_str(
        include_str!("../../../geom/tests/data/envelope/crossing-heap.envelope.json"),
    )
    .unwrap();
    heap.patches = prism_geom::freeform::envelope::Surfacing::Paper;
    let k = envelope::ENVELOPE_SAMPLES
        .iter()
        .position(|s| s.1 == "table2-seven.envelope.json")
        .unwrap();
    for (spec, crossing) in [(heap, true), (EnvelopeTab::sample(k).unwrap(), false)] {
        let mut a = app();
        a.run(Command::Edit(Edit::SetEnvelope {
            spec: Some(spec),
            gesture: None,
        }));
        let (n, warning) = loop {
            a.envelope.sync(a.doc.state().envelope.as_ref());
            if let Some(b) = a.envelope.built()
                && !a.envelope.building()
                && let envelope::build::Crossings::Done(p, w) = &b.crossings
            {
                break (p.len(), w.clone());
            }
            std::thread::sleep(std::time::Duration::from_millis(2));
        };
        assert_eq!(n > 0, crossing);
        match warning {
            Some(w) => assert!(crossing && w.contains(&format!("{n} pair(s)")), "{w}"),
            None => assert!(!crossing),
        }
    }
}

/// `prism assets/two-cubes.envelope.json`: a bare scene file opens on the Envelope tab with
/// its scene (a skin's on the Skin tab), not as "missing field `version`".
#[test]
fn a_bare_scene_file_opens_on_its_tab() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets");
    let a = super::tests::opened(&dir.join("two-cubes.envelope.json"));
    assert_eq!(a.tab, Tab::Envelope);
    let spec = a.doc.state().envelope.clone().expect("the scene");
    assert_eq!(spec.primitives.len(), 2);
    let a = super::tests::opened(&dir.join("spout.skin.json"));
    assert_eq!(a.tab, Tab::Skin);
    assert!(a.doc.state().skin.is_some());
    // File ▸ Open from another tab too.
    let mut a = super::tests::opened(&dir.join("tripod.obj"));
    assert_eq!(a.tab, Tab::Model);
    a.run(Command::Open(dir.join("two-cubes.envelope.json")));
    a.wait_idle();
    assert_eq!(a.tab, Tab::Envelope);
    assert_eq!(a.doc.state().envelope.as_ref().unwrap().primitives.len(), 2);
}

/// A scene whose t, a vertex's own t and resolution lie outside the tab's ranges (t = 0.05 and
/// 0.02, 40 quads a patch side: the CLI takes any t > 0 and up to 256) keeps them while the
/// tab shows it, the vertex picked; the sliders clamp only what is dragged or typed (egui's
/// clamp existing values unless told not to, which turned such a scene into t = 0.1 and 32
/// quads as it opened). The Skin tab's resolution likewise.
#[test]
fn values_outside_the_sliders_are_kept() {
    let mut h = in_tab("Envelope");
    let mut spec: prism_geom::freeform::envelope::EnvelopeSpec = serde_json::from_str(
        include_str!("../../../geom/tests/data/envelope/still-folding-heap.envelope.json"),
    )
    .unwrap();
    spec.t = 0.05;
    spec.resolution = 40;
    let mut vt = vec![0.05; spec.primitives[0].vertices.len()];
    vt[0] = 0.02;
    spec.primitives[0].vertex_t = Some(vt);
    h.state_mut().run(Command::Edit(Edit::SetEnvelope {
        spec: Some(spec.clone()),
        gesture: None,
    }));
    h.state_mut().envelope.picked = Some((0, 0));
    settle(&mut h);
    h.get_by_label_contains("vertex 0");
    assert_eq!(scene(&h).as_ref(), Some(&spec));
    {
        let b = h.state().envelope.built().expect("built");
        let (e, mesh) = b.result.as_ref().expect("an envelope");
        // Built at 40 quads a patch side, not the slider's 32 (border cells holding the other
        // side's samples are fans of triangles, so the count is more than 40 × 40 a patch).
        assert_eq!(mesh.num_faces(), e.tessellate(40).unwrap().num_faces());
        assert_ne!(mesh.num_faces(), e.tessellate(32).unwrap().num_faces());
    }

    h.get_by_label("Skin").click();
    settle(&mut h);
    h.get_by_label("Spout (6 sections)").click();
    settle(&mut h);
    let mut skin = h.state().doc.state().skin.clone().expect("the spout");
    skin.resolution = 48;
    h.state_mut().run(Command::Edit(Edit::SetSkin {
        spec: Some(skin.clone()),
        gesture: None,
    }));
    settle(&mut h);
    assert_eq!(h.state().doc.state().skin.as_ref(), Some(&skin));
}

/// A long build shows its progress and stops at Cancel: the view keeps the last surface, the
/// tab says so and does not build the cancelled scene again until asked (Build).
#[test]
fn a_long_build_shows_its_progress_and_stops_at_cancel() {
    let mut h = in_tab("Envelope");
    h.get_by_label("Tetrahedron").click();
    settle(&mut h);
    let small = scene(&h).expect("a scene");
    // The seven primitives at resolution 160 (about 3.4 M triangles): seconds of meshing,
    // within a budget that lets it start.
    h.state_mut().envelope.budget = 16 << 30;
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../assets/table2-seven.envelope.json"),
    )
    .unwrap();
    let mut big: prism_geom::freeform::envelope::EnvelopeSpec =
        serde_json::from_str(&text).unwrap();
    big.resolution = 160;
    h.state_mut().run(Command::Edit(Edit::SetEnvelope {
        spec: Some(big.clone()),
        gesture: None,
    }));
    h.step();
    assert!(h.state().envelope.building());
    // The bar shows once the build has run a while (a drag's short builds never show it).
    let bar = |h: &mut Harness<'_, PrismApp>| {
        let start = std::time::Instant::now();
        while h.query_by_label_contains("Building…").is_none() {
            assert!(start.elapsed().as_secs() < 20, "no progress shown");
            std::thread::sleep(std::time::Duration::from_millis(20));
            h.step();
        }
    };
    bar(&mut h);
    h.get_by_label("Cancel").click();
    for _ in 0..5 {
        h.step();
    }
    assert!(!h.state().envelope.building(), "stopped");
    h.get_by_label_contains("Cancelled: the view shows the last one built");
    let b = h.state().envelope.built().expect("the last build");
    assert_eq!(b.spec, small, "the last surface kept");
    assert_eq!(scene(&h), Some(big), "the document keeps the scene");
    // Build asks again.
    h.get_by_label("Build").click();
    h.step();
    h.step();
    assert!(h.state().envelope.building());
    bar(&mut h);
    h.get_by_label("Cancel").click();
    h.step();
    assert!(!h.state().envelope.building());
}
