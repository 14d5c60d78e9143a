//! The Skin tab driven through its real panels (egui_kittest): a sample placed from the
//! tab, the skin built closed through every section vertex, a section added, deleted and
//! reordered, a number dragged as one undo step, the whole skin undone across tabs, saved
//! with the document and reopened, and exported.

use super::command::Edit;
use super::tests::{drag_right, in_tab, saved_and_exported, settle};
use super::*;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

fn sections(h: &Harness<'_, PrismApp>) -> usize {
    h.state()
        .doc
        .state()
        .skin
        .as_ref()
        .map_or(0, |s| s.sections.len())
}

/// The app at 1280 × 800 on the Skin tab, with the spout placed from the tab's button.
fn spout_in_the_skin_tab() -> Harness<'static, PrismApp> {
    let mut h = in_tab("Skin");
    assert_eq!(h.state().tab, Tab::Skin);
    h.get_by_label("Spout (6 sections)").click();
    settle(&mut h);
    assert_eq!(sections(&h), 6);
    h
}

#[test]
fn the_skin_tab_places_edits_undoes_saves_and_exports_a_skin() {
    let mut h = spout_in_the_skin_tab();
    {
        let b = h.state().skin.built().expect("built");
        let (s, mesh) = b.result.as_ref().expect("a skin");
        assert_eq!(s.patches.len(), 60);
        let topo = prism_geom::Topology::build(mesh).unwrap();
        topo.require_closed(mesh).unwrap();
        let d = mesh.bbox_diagonal();
        for sec in &b.spec.sections {
            for p in &sec.points {
                let near = mesh
                    .positions
                    .iter()
                    .map(|q| (*q - *p).length())
                    .fold(f64::INFINITY, f64::min);
                assert!(near <= 1e-12 * d);
            }
        }
        assert!(b.jump < 1e-9);
    }
    // Add after the selected (first) section, then delete it again, then reorder.
    h.get_by_label("Add after").click();
    settle(&mut h);
    assert_eq!(sections(&h), 7);
    assert_eq!(h.state().skin.selected, 1);
    h.get_by_label("Delete").click();
    settle(&mut h);
    assert_eq!(sections(&h), 6);
    let before = h.state().doc.state().skin.clone().unwrap();
    h.get_by_label("Down").click();
    settle(&mut h);
    let after = h.state().doc.state().skin.clone().unwrap();
    assert_eq!(after.sections[1], before.sections[2]);
    // A moved-out-of-order skin still builds (least twist), and Ctrl+Z puts it back.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    assert_eq!(h.state().doc.state().skin.as_ref().unwrap(), &before);
    // One gesture of typed numbers is one undo step.
    let mut moved = before.clone();
    for p in &mut moved.sections[1].points {
        p.z += 0.1;
    }
    h.state_mut().run(Command::Edit(Edit::SetSkin {
        spec: Some(moved.clone()),
        gesture: Some(900),
    }));
    for p in &mut moved.sections[1].points {
        p.z += 0.1;
    }
    h.state_mut().run(Command::Edit(Edit::SetSkin {
        spec: Some(moved),
        gesture: Some(900),
    }));
    settle(&mut h);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    assert_eq!(h.state().doc.state().skin.as_ref().unwrap(), &before);

    // A drag in the view with the turn tool turns the selected section: one undo step.
    h.state_mut().skin.mouse = skin::Mouse::Turn;
    h.state_mut().skin.selected = 2;
    drag_right(&mut h, egui::pos2(800.0, 400.0), &[30.0, 60.0, 90.0, 120.0]);
    let turned = h.state().doc.state().skin.clone().unwrap();
    assert_ne!(turned.sections[2], before.sections[2]);
    assert_eq!(turned.sections[1], before.sections[1]);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    assert_eq!(h.state().doc.state().skin.as_ref().unwrap(), &before);
    h.state_mut().skin.mouse = skin::Mouse::Orbit;

    // Saved with the document and reopened; exported as STL from the tab.
    let (state, stl) = saved_and_exported(&mut h, "spout");
    assert!(stl > 84 + 50 * 7000, "{stl} bytes");
    assert_eq!(state.skin.as_ref(), Some(&before));

    // Undo across tabs: back to no skin at all.
    for _ in 0..3 {
        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
        settle(&mut h);
    }
    assert_eq!(sections(&h), 0);
    assert!(h.state().skin.built().is_none());
}

/// Dragging a number of the selected section (the tilt about x) over several frames is one
/// undo step: the fields drawn after it in the same frame used to end its gesture, so every
/// frame of the drag was an undo step of its own.
#[test]
fn dragging_a_section_number_is_one_undo_step() {
    let mut h = spout_in_the_skin_tab();
    let before = h.state().doc.state().skin.clone().unwrap();
    let at = h.get_by_value("about x: 0.0").rect().center();
    drag_right(&mut h, at, &[10.0, 20.0, 30.0, 40.0]);
    let tilted = h.state().doc.state().skin.clone().unwrap();
    assert_ne!(
        tilted.sections[0], before.sections[0],
        "the drag tilted nothing"
    );
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    assert_eq!(h.state().doc.state().skin.as_ref().unwrap(), &before);
}

/// The pairing in the tab: the spout is paired by shape, its summary names each pair's shift
/// and twist; the paper's least twist is one click away (undoable); a skin through itself is
/// marked (its crossing midpoints in the overlay) and named in the summary by section.
#[test]
fn the_tab_pairs_by_shape_or_least_twist_and_names_a_skin_through_itself() {
    let mut h = spout_in_the_skin_tab();
    assert!(
        h.query_by_label_contains("Paired by shape: 0–1: shift")
            .is_some()
    );
    assert!(h.query_by_label("Crossings: none").is_some());
    h.get_by_label("least twist (paper)").click();
    settle(&mut h);
    let spec = h.state().doc.state().skin.clone().unwrap();
    assert_eq!(spec.pairing, prism_geom::freeform::Pairing::Paper);
    assert!(
        h.query_by_label_contains("Paired by least twist (paper)")
            .is_some()
    );
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    settle(&mut h);
    let spec = h.state().doc.state().skin.clone().unwrap();
    assert_eq!(spec.pairing, prism_geom::freeform::Pairing::Shape);

    // A tube of 12 circles around a ring through 440°: its last part runs through its first.
    let ring: Vec<prism_geom::freeform::SectionInput> = (0..12)
        .map(|k| {
            let a = (40.0 * k as f64).to_radians();
            let c = glam::DVec3::new(2.0 * a.cos(), 2.0 * a.sin(), 0.1 * k as f64);
            let radial = glam::DVec3::new(a.cos(), a.sin(), 0.0);
            prism_geom::freeform::SectionInput {
                points: (0..12)
                    .map(|i| {
                        let u = i as f64 / 12.0 * std::f64::consts::TAU;
                        c + 0.6 * (u.cos() * radial + u.sin() * glam::DVec3::Z)
                    })
                    .collect(),
                ..Default::default()
            }
        })
        .collect();
    let crossing = prism_geom::freeform::SkinSpec::new(ring);
    h.state_mut()
        .run(super::command::Command::Edit(Edit::SetSkin {
            spec: Some(crossing),
            gesture: None,
        }));
    settle(&mut h);
    let b = h.state().skin.built().unwrap();
    let c = b.crossings().expect("checked");
    assert!(c.faces > 0 && c.points.len() == c.faces);
    assert!(
        h.query_by_label_contains("Crossings (red crosses): the skin passes through itself")
            .is_some()
    );
}
