//! A new solid without a file: File ▸ New solid… (a box, a prism, a pyramid, a tripod) and
//! the Curves tab's polygon extruded, concave, with a hole; undoable, and a bad outline
//! named in the window.

use super::command::{Command, CurveEdit};
use super::new_solid::Kind;
use super::tests::app;
use glam::DVec2;
use prism_geom::curve::Polyline;
use prism_geom::geometry::signed_volume;
use prism_geom::scheme::parse_pipeline;

#[test]
fn new_solids_replace_the_model_and_keep_the_pipeline() {
    let mut a = app();
    let before = a.doc.state().mesh.clone();
    let pipeline = parse_pipeline("combination:r=0.2,combination:r=0.2").unwrap();
    a.run(super::command::Edit::SetPipeline {
        view: 0,
        steps: pipeline.clone(),
    });
    a.run(Command::ShowNewSolid { extrude: false });
    assert!(a.new_solid.open);
    for (kind, faces, volume) in [
        (Kind::Box, 6, 6.0),
        (Kind::Prism, 8, 1.5 * 3f64.sqrt() * 2.25 * 2.0),
        (Kind::Pyramid, 7, f64::NAN),
        (Kind::Tripod, 12, 7.0),
    ] {
        a.new_solid.kind = kind;
        let s = a.new_solid.solid(&a.doc.state().curve).unwrap();
        a.run(Command::NewSolid(s));
        a.wait_idle();
        let m = &a.doc.state().mesh;
        assert_eq!(m.num_faces(), faces, "{kind:?}");
        if volume.is_finite() {
            assert!((signed_volume(m) - volume).abs() < 1e-9, "{kind:?}");
        }
        assert_eq!(a.doc.state().pipelines[0], pipeline);
        let v = &a.model.views[0];
        assert!(v.pipeline.is_complete() && v.error.is_none(), "{kind:?}");
    }
    // Each was one undo step.
    for _ in 0..4 {
        a.run(Command::Undo);
    }
    assert!(a.doc.state().mesh == before);
}

#[test]
fn the_sketch_extrudes_concave_with_a_hole_and_a_crossing_one_is_named() {
    let mut a = app();
    // A concave closed L.
    let l: Vec<DVec2> = [(0., 0.), (2., 0.), (2., 1.), (1., 1.), (1., 2.), (0., 2.)]
        .map(DVec2::from)
        .to_vec();
    a.run(CurveEdit::SetControl(Polyline::new(l, true)));
    a.run(Command::ShowNewSolid { extrude: true });
    assert_eq!(a.new_solid.kind, Kind::Extrusion);
    a.new_solid.params.height = 0.5;
    a.new_solid.hole = true;
    a.new_solid.hole_scale = 0.3;
    let s = a.new_solid.solid(&a.doc.state().curve).unwrap();
    a.run(Command::NewSolid(s));
    a.wait_idle();
    let m = &a.doc.state().mesh;
    assert!((signed_volume(m) - 3.0 * (1.0 - 0.09) * 0.5).abs() < 1e-9);
    assert!(m.face_has_holes(0) || m.face_has_holes(1));
    assert!(a.model.views[0].error.is_none());
    // The refined curve: more points, still a solid.
    a.new_solid.refined = true;
    a.new_solid.hole = false;
    let s = a.new_solid.solid(&a.doc.state().curve).unwrap();
    a.run(Command::NewSolid(s));
    assert!(a.doc.state().mesh.num_faces() > 8);
    // A bow tie crosses itself: named, nothing replaced.
    let bow: Vec<DVec2> = [(0., 0.), (1., 1.), (1., 0.), (0., 1.)]
        .map(DVec2::from)
        .to_vec();
    a.run(CurveEdit::SetControl(Polyline::new(bow, true)));
    a.new_solid.refined = false;
    let g = a.doc.generation();
    let s = a.new_solid.solid(&a.doc.state().curve).unwrap();
    a.run(Command::NewSolid(s));
    assert_eq!(a.doc.generation(), g);
    assert!(
        a.note.as_deref().unwrap_or("").contains("crosses itself"),
        "{:?}",
        a.note
    );
    // An open sketch is not extruded.
    a.run(CurveEdit::SetClosed(false));
    let e = a.new_solid.solid(&a.doc.state().curve).unwrap_err();
    assert!(e.contains("open"), "{e}");
}
