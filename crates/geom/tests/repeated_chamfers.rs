//! Chamfers that can be repeated (seed 000 §3.1, docs/algorithms/chamfers.md): the vector
//! sum without a face normal, its repeatable bound α ≤ ¼ named, and the absolute chamfers'
//! per-face clamp with a shrinking schedule that survives sharp corners.

use prism_geom::rules::Overlap;
use prism_geom::scheme::parse_pipeline;
use prism_geom::{CornerRule, EdgeAttrs, Pipeline, PolyMesh, RoundingOptions, Scheme, primitives};

fn run(m: &PolyMesh, steps: Vec<Scheme>, overlap: Overlap) -> Pipeline {
    let mut p = Pipeline::new(m.clone(), EdgeAttrs::new(), steps);
    p.options = RoundingOptions {
        overlap,
        ..RoundingOptions::default()
    };
    p.compute().unwrap();
    p
}

fn flips(p: &Pipeline) -> Vec<usize> {
    p.levels()[1..]
        .iter()
        .map(|l| l.report.as_ref().unwrap().flipped.len())
        .collect()
}

/// A five-point star prism whose tips are 38° (the solid).
fn star_prism() -> PolyMesh {
    // Inner radius for 38° tips at outer radius 1.5.
    primitives::extrude(&primitives::star_polygon(5, 1.5, 0.596168), &[], 0.0, 1.0)
}

#[test]
fn the_shrinking_schedule_survives_sharp_tips_when_clamped() {
    let star = star_prism();
    let first: Scheme = "cut-width:d=0.1".parse().unwrap();
    let steps = first.schedule(3, 4.0);
    assert_eq!(
        steps,
        parse_pipeline("cut-width:d=0.1,cut-width:d=0.025,cut-width:d=0.00625").unwrap()
    );
    // As printed, the tips move d/sin(19°) ≈ 3.07 d and their faces fold at step 3.
    assert_eq!(
        flips(&run(&star, steps.clone(), Overlap::Refuse)),
        vec![0, 0, 40]
    );
    let p = run(&star, steps, Overlap::Clamp);
    assert_eq!(flips(&p), vec![0, 0, 0]);
    let lowered: Vec<usize> = p.levels()[1..]
        .iter()
        .map(|l| l.report.as_ref().unwrap().clamped_faces)
        .collect();
    assert!(lowered.iter().all(|&n| n > 0), "{lowered:?}");
    // The same with the angle bisector, and a constant l that the clamp alone keeps sound.
    for pipeline in [
        "angle-bisector:l=0.1,angle-bisector:l=0.025,angle-bisector:l=0.00625",
        "angle-bisector:l=0.1,angle-bisector:l=0.1,angle-bisector:l=0.1",
    ] {
        let p = run(&star, parse_pipeline(pipeline).unwrap(), Overlap::Clamp);
        assert_eq!(flips(&p), vec![0, 0, 0], "{pipeline}");
    }
    // The clamp leaves a solid whose faces have room untouched.
    let cube = primitives::cube3();
    let p = run(&cube, first.schedule(3, 4.0), Overlap::Clamp);
    assert_eq!(p.levels()[1].report.as_ref().unwrap().clamped_faces, 0);
    let q = run(&cube, first.schedule(3, 4.0), Overlap::Refuse);
    assert!(p.levels()[1].mesh == q.levels()[1].mesh);
    // Schedules shrink only l and d.
    let r: Scheme = "combination:r=0.2".parse().unwrap();
    assert_eq!(r.schedule(3, 4.0), vec![r; 3]);
}

#[test]
fn vector_sum_above_a_quarter_is_named_and_needs_no_face_normal() {
    let at = |alpha| {
        Scheme::Biquadratic(CornerRule::VectorSum {
            alpha,
            reflex: prism_geom::ReflexMode::AsPrinted,
        })
    };
    assert!(at(0.25).repeat_warning().is_none());
    let w = at(0.4).repeat_warning().unwrap();
    assert!(w.contains("0.4") && w.contains("¼"), "{w}");
    // α = 0.4 flattens faces at level 2 and went on to stop with "face 50 has no area":
    // the rule as printed needs no normal, so all four levels are made (folded, reported).
    let p = run(&primitives::cube3(), vec![at(0.4); 4], Overlap::Refuse);
    assert_eq!(p.levels().len(), 5);
    assert!(p.levels()[4].mesh.all_finite());
    assert!(!p.levels()[4].report.as_ref().unwrap().flipped.is_empty());
    // The reflex-inward option on a concave solid with flattened faces runs too.
    let inward = Scheme::Biquadratic(CornerRule::VectorSum {
        alpha: 0.4,
        reflex: prism_geom::ReflexMode::Inward,
    });
    let p = run(&primitives::l_block(), vec![inward; 4], Overlap::Refuse);
    assert!(p.levels()[4].mesh.all_finite());
}

/// The least distance between two corners of one face of `m` lying in the plane z = 0.
fn closest_corners_at_the_bottom(m: &PolyMesh) -> f64 {
    let mut least = f64::INFINITY;
    let at = |c: usize| m.positions[m.corner_verts[c] as usize];
    for f in 0..m.num_faces() {
        if m.face_corners(f).any(|c| at(c).z != 0.0) {
            continue;
        }
        let cs: Vec<_> = m.face_corners(f).collect();
        for (i, &a) in cs.iter().enumerate() {
            for &b in &cs[i + 1..] {
                least = least.min(at(a).distance(at(b)));
            }
        }
    }
    least
}

/// At α = 0.2 with the reflex corners moved inwards, the tripod's L-shaped bottom (and its
/// two twins) has its reflex corner (1, 1, 0) and its armpit corner (0, 0, 0) both land on
/// (0.6, 0.6, 0): the face touches itself, and a rounding after it folds. The clamp lowers
/// α on exactly those three faces until a quarter of their narrowest width is kept, and the
/// rounding that follows is sound; a convex solid is not touched.
#[test]
fn the_vector_sum_clamp_keeps_reflex_corners_off_the_far_side() {
    let tripod = primitives::tripod();
    let inward = "vector-sum:alpha=0.2:reflex=inward";
    let p = run(&tripod, parse_pipeline(inward).unwrap(), Overlap::Refuse);
    assert!(closest_corners_at_the_bottom(&p.levels()[1].mesh) < 1e-12);
    let rounded = format!("{inward},combination:r=0.2,combination:r=0.2,combination:r=0.2");
    let p = run(&tripod, parse_pipeline(&rounded).unwrap(), Overlap::Clamp);
    let first = p.levels()[1].report.as_ref().unwrap();
    assert_eq!(first.clamped_faces, 3);
    // The neck keeps a quarter of the face's narrowest width (1, from the reflex corner to
    // the far sides).
    let gap = closest_corners_at_the_bottom(&p.levels()[1].mesh);
    assert!(gap > 0.25, "{gap}");
    assert_eq!(flips(&p), vec![0, 0, 0, 0]);
    for lv in &p.levels()[1..] {
        assert!(prism_geom::analysis::crossings(&lv.mesh).is_empty());
    }
    // Without the clamp the first rounding already folds, or gives up the round for small
    // chamfers where it would (docs/algorithms/cylindrical.md, "Small
    // chamfers"); with it, no vertex needs them.
    let q = run(&tripod, parse_pipeline(&rounded).unwrap(), Overlap::Refuse);
    let chamfers = |p: &Pipeline| -> Vec<usize> {
        p.levels()[2..]
            .iter()
            .map(|lv| lv.report.as_ref().unwrap().mend.small_chamfers)
            .collect()
    };
    assert!(
        flips(&q).iter().any(|&n| n > 0) || chamfers(&q).iter().any(|&n| n > 0),
        "{:?} {:?}",
        flips(&q),
        chamfers(&q)
    );
    assert_eq!(chamfers(&p), vec![0, 0, 0]);
    // Convex faces keep α exactly.
    let cube = primitives::cube3();
    let steps = parse_pipeline(inward).unwrap();
    let (a, b) = (
        run(&cube, steps.clone(), Overlap::Clamp),
        run(&cube, steps, Overlap::Refuse),
    );
    assert_eq!(a.levels()[1].report.as_ref().unwrap().clamped_faces, 0);
    assert!(a.levels()[1].mesh == b.levels()[1].mesh);
}

#[test]
fn primitives_are_closed_solids_of_positive_volume() {
    for m in [
        primitives::ngon_prism(6, 1.5, 2.0),
        primitives::pyramid(5, 1.0, 1.5),
        star_prism(),
    ] {
        let t = prism_geom::Topology::build(&m).unwrap();
        t.require_closed(&m).unwrap();
        assert!(prism_geom::geometry::signed_volume(&m) > 0.0);
    }
    // Hexagonal prism R = 1.5, h = 2: volume (3√3/2)·R²·h.
    let v = prism_geom::geometry::signed_volume(&primitives::ngon_prism(6, 1.5, 2.0));
    assert!((v - 1.5 * 3f64.sqrt() * 2.25 * 2.0).abs() < 1e-12, "{v}");
}
