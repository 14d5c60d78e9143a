//! Catmull–Clark and Loop: masks by hand, invariants per level, convergence to the limit
//! points, random meshes with random creases (no panic, no NaN).

mod common;

use prism_geom::analysis::counts;
use prism_geom::{
    DVec3, EdgeAttr, EdgeAttrs, EdgeKey, PolyMesh, PrimalError, PrimalScheme, SubdivTags, Topology,
    limit_points, primitives, refine_primal,
};
use proptest::prelude::*;

fn unit_cube() -> PolyMesh {
    primitives::cuboid(DVec3::splat(-0.5), DVec3::splat(0.5))
}

fn octahedron() -> PolyMesh {
    prism_geom::primitives::octahedron()
}

fn refine(m: &PolyMesh, attrs: &EdgeAttrs, s: PrimalScheme) -> prism_geom::PrimalOutput {
    refine_primal(m, attrs, &SubdivTags::default(), s, u64::MAX).unwrap()
}

#[test]
fn catmull_clark_masks_by_hand_on_a_cube() {
    let m = unit_cube();
    let out = refine(&m, &EdgeAttrs::new(), PrimalScheme::CatmullClark);
    // Corner (½,½,½), valence 3: (1/3)v + (1/9)Σe + (1/9)ΣF = (5/18)(1,1,1).
    let v = m
        .positions
        .iter()
        .position(|p| *p == DVec3::splat(0.5))
        .unwrap();
    assert!((out.mesh.positions[v] - DVec3::splat(5.0 / 18.0)).length() < 1e-15);
    // Every edge point: ¼(a + b) + ¼(F₀ + F₁): 0.375 along the two axes off the edge.
    for e in m.num_vertices()..m.num_vertices() + 12 {
        let p = out.mesh.positions[e].abs();
        let mut c = [p.x, p.y, p.z];
        c.sort_by(f64::total_cmp);
        assert!(
            (c[0]).abs() < 1e-15 && (c[1] - 0.375).abs() < 1e-15 && (c[2] - 0.375).abs() < 1e-15
        );
    }
    // Face points: the centroids (0.5 on one axis).
    for f in 0..6 {
        let p = out.mesh.positions[m.num_vertices() + 12 + f].abs();
        assert!((p.x + p.y + p.z - 0.5).abs() < 1e-15);
    }
    // A crease of sharpness 10 on one edge: its edge point is the midpoint.
    let mut attrs = EdgeAttrs::new();
    let (a, b) = (m.corner_verts[0], m.corner_verts[1]);
    attrs.insert(EdgeKey::new(a, b), EdgeAttr::creased(10.0));
    let out = refine(&m, &attrs, PrimalScheme::CatmullClark);
    let mid = 0.5 * (m.positions[a as usize] + m.positions[b as usize]);
    assert!(
        out.mesh
            .positions
            .iter()
            .any(|p| (*p - mid).length() < 1e-15)
    );
    // Sharpness 0.5: half way between the smooth and the crease edge point.
    attrs.get_mut(&EdgeKey::new(a, b)).unwrap().crease = 0.5;
    let half = refine(&m, &attrs, PrimalScheme::CatmullClark);
    let smooth = refine(&m, &EdgeAttrs::new(), PrimalScheme::CatmullClark);
    let i = (0..half.mesh.num_vertices())
        .find(|&i| (out.mesh.positions[i] - mid).length() < 1e-15)
        .unwrap();
    let expect = 0.5 * (mid + smooth.mesh.positions[i]);
    assert!((half.mesh.positions[i] - expect).length() < 1e-15);
}

#[test]
fn loop_masks_by_hand_on_an_octahedron() {
    let m = octahedron();
    let out = refine(&m, &EdgeAttrs::new(), PrimalScheme::Loop);
    // Valence 4: β = (5/8 − (3/8 + ¼cos 90°)²)/4 = 31/256; the vertex X moves to
    // (1 − 4β)X + β(Y − Y + Z − Z) = (1 − 124/256) X.
    assert!((out.mesh.positions[0] - DVec3::X * (1.0 - 124.0 / 256.0)).length() < 1e-15);
    // Edge X–Y: ⅜(X + Y) + ⅛(Z − Z) = (⅜, ⅜, 0).
    let e = out
        .mesh
        .positions
        .iter()
        .any(|p| (*p - DVec3::new(0.375, 0.375, 0.0)).length() < 1e-15);
    assert!(e);
    // A quad is refused by name.
    match refine_primal(
        &unit_cube(),
        &EdgeAttrs::new(),
        &SubdivTags::default(),
        PrimalScheme::Loop,
        u64::MAX,
    ) {
        Err(PrimalError::NotTriangle {
            face: 0,
            corners: 4,
        }) => {}
        other => panic!("{other:?}"),
    }
    // A level over the memory budget is refused before it starts.
    match refine_primal(
        &m,
        &EdgeAttrs::new(),
        &SubdivTags::default(),
        PrimalScheme::Loop,
        100,
    ) {
        Err(PrimalError::TooLarge(e)) => assert_eq!(e.faces, 32),
        other => panic!("{other:?}"),
    }
}

#[test]
fn repeated_subdivision_converges_to_the_limit_points() {
    // Vertex points keep their index, so vertex i of level k descends from vertex i of
    // every earlier level: its position must approach the limit of level 1's vertex i.
    // (Not at a dart — a crease ending inside the surface —, where OpenSubdiv, and so
    // Prism, uses the smooth limit mask although the crease beside it changes the limit.)
    let mut open = primitives::torus(8, 6, 3.0, 1.0);
    open.truncate_faces(open.num_faces() - 8);
    let cases = [
        (primitives::tripod(), PrimalScheme::CatmullClark, false),
        (open, PrimalScheme::CatmullClark, false),
        (octahedron(), PrimalScheme::Loop, true),
    ];
    for (m, s, crease) in cases {
        let mut attrs = EdgeAttrs::new();
        if crease {
            // A closed loop of creases around the octahedron's equator: no darts.
            for (a, b) in [(0, 2), (2, 1), (1, 3), (3, 0)] {
                let attr = EdgeAttr::creased(10.0);
                attrs.insert(EdgeKey::new(a, b), attr);
            }
        }
        let l1 = refine(&m, &attrs, s);
        let lim = limit_points(&l1.mesh, &l1.edge_attrs, &l1.tags, s).unwrap();
        let mut cur = l1.clone();
        let mut errors = Vec::new();
        for _ in 0..6 {
            cur = refine(&cur.mesh, &cur.edge_attrs, s);
            let e = (0..l1.mesh.num_vertices())
                .map(|i| (cur.mesh.positions[i] - lim.positions[i]).length())
                .fold(0.0, f64::max);
            errors.push(e);
        }
        // Shrinks by a factor ≥ 1/0.6 per level and ends well below 1e-3 of the size.
        for w in errors.windows(2) {
            assert!(w[1] <= 0.6 * w[0], "{s:?}: {errors:?}");
        }
        assert!(errors[5] < 1e-3 * m.bbox_diagonal(), "{s:?}: {errors:?}");
    }
}

#[test]
fn counts_closedness_and_euler_per_level() {
    for (m, s) in [
        (primitives::tripod(), PrimalScheme::CatmullClark),
        (
            primitives::torus(7, 5, 3.0, 1.0),
            PrimalScheme::CatmullClark,
        ),
        (octahedron(), PrimalScheme::Loop),
    ] {
        let mut cur = m.clone();
        for _ in 0..3 {
            let t = Topology::build(&cur).unwrap();
            let (v, e, f, c) = (
                cur.num_vertices(),
                t.num_edges(),
                cur.num_faces(),
                cur.num_corners(),
            );
            let out = refine(&cur, &EdgeAttrs::new(), s);
            let n = &out.mesh;
            match s {
                PrimalScheme::CatmullClark | PrimalScheme::CatmullClarkCircle => {
                    assert_eq!((n.num_vertices(), n.num_faces()), (v + e + f, c));
                }
                PrimalScheme::Loop => assert_eq!((n.num_vertices(), n.num_faces()), (v + e, 4 * f)),
            }
            Topology::build(n).unwrap().require_closed(n).unwrap();
            assert_eq!(counts(n).euler(), counts(&cur).euler());
            cur = out.mesh;
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    #[test]
    fn random_closed_meshes_with_random_creases(
        shape in 0u8..4,
        jitter in proptest::collection::vec(-0.2f64..0.2, 17 * 3),
        creases in proptest::collection::vec((0usize..200, 0.0f64..12.0), 0..8),
        corner in proptest::option::of((0u32..40, 0.0f64..12.0)),
        chaikin in any::<bool>(),
    ) {
        let tri = |m: PolyMesh| primitives::fan_triangulated(&m);
        let (mut m, s) = match shape {
            0 => (primitives::tripod(), PrimalScheme::CatmullClark),
            1 => (primitives::torus(6, 5, 3.0, 1.0), PrimalScheme::CatmullClark),
            2 => (tri(primitives::cube3()), PrimalScheme::Loop),
            _ => (octahedron(), PrimalScheme::Loop),
        };
        common::jitter(&mut m, &jitter);
        let mut attrs = EdgeAttrs::new();
        for (c, sharp) in creases {
            let c = c % m.num_corners();
            let f = (0..m.num_faces()).find(|&f| m.face_corners(f).contains(&c)).unwrap();
            let r = m.face_corners(f);
            let n = if c + 1 == r.end { r.start } else { c + 1 };
            attrs.insert(EdgeKey::new(m.corner_verts[c], m.corner_verts[n]), EdgeAttr::creased(sharp));
        }
        let mut tags = SubdivTags::default();
        if let Some((v, sharp)) = corner {
            tags.corners.insert(v % m.num_vertices() as u32, sharp);
        }
        if chaikin {
            tags.crease_method = prism_geom::CreaseMethod::Chaikin;
        }
        let mut cur = (m, attrs, tags);
        for _ in 0..3 {
            let out = refine_primal(&cur.0, &cur.1, &cur.2, s, u64::MAX).unwrap();
            prop_assert!(out.mesh.all_finite());
            prop_assert_eq!(counts(&out.mesh).euler(), counts(&cur.0).euler());
            let lim = limit_points(&out.mesh, &out.edge_attrs, &out.tags, s).unwrap();
            prop_assert!(lim.positions.iter().all(|p| p.is_finite()));
            prop_assert!(lim.normals.iter().all(|n| n.is_finite()));
            cur = (out.mesh, out.edge_attrs, out.tags);
        }
    }
}

/// A pipeline of primal steps (the app's and the command line's path) passes each split's
/// written-down topology on to the next primal step instead of searching the child again:
/// every level is the one single steps give, bit for bit, on an open mesh with creases and
/// from Loop on to Catmull–Clark.
/// A 9 × 7 torus with four faces cut away (a boundary) and three semi-sharp creases.
fn open_torus_with_creases() -> (PolyMesh, EdgeAttrs) {
    let mut open = primitives::torus(9, 7, 3.0, 1.0);
    open.truncate_faces(open.num_faces() - 4);
    let mut attrs = EdgeAttrs::new();
    for (a, b, s) in [(0, 1, 2.5), (1, 2, 1.0), (9, 10, 4.0)] {
        attrs.insert(
            EdgeKey::new(a, b),
            EdgeAttr {
                crease: s,
                ..EdgeAttr::default()
            },
        );
    }
    (open, attrs)
}

#[test]
fn a_pipeline_of_primal_steps_gives_the_single_steps_levels() {
    use prism_geom::{Pipeline, Scheme};
    let (open, attrs) = open_torus_with_creases();
    let cc = Scheme::Primal(PrimalScheme::CatmullClark);
    let lp = Scheme::Primal(PrimalScheme::Loop);
    for (mesh, steps) in [
        (open.clone(), vec![cc, cc, cc]),
        (primitives::fan_triangulated(&open), vec![lp, lp, cc]),
    ] {
        let tags = SubdivTags::default();
        let mut p = Pipeline::with_tags(mesh.clone(), attrs.clone(), tags.clone(), steps.clone());
        p.compute().unwrap();
        let (mut m, mut a, mut t) = (mesh, attrs.clone(), tags);
        for (k, s) in steps.iter().enumerate() {
            let Scheme::Primal(s) = *s else {
                unreachable!()
            };
            let out = refine_primal(&m, &a, &t, s, u64::MAX).unwrap();
            let level = &p.levels()[k + 1];
            assert_eq!(
                level.mesh.corner_verts,
                out.mesh.corner_verts,
                "level {}",
                k + 1
            );
            assert_eq!(level.mesh.positions, out.mesh.positions, "level {}", k + 1);
            assert_eq!(level.edge_attrs, out.edge_attrs, "level {}", k + 1);
            (m, a, t) = (out.mesh, out.edge_attrs, out.tags);
        }
    }
}

/// A dragged cage vertex: the moved pipeline keeps each primal step's faces, marks and
/// topology and evaluates only the points, and gives the levels of a fresh pipeline bit for
/// bit — creases, corners, a hole and a boundary included, with Loop, and with a rounding
/// step after the primal ones (computed afresh: its faces depend on the points); moved
/// again, from the moved one, too. A moved point that is not finite is named.
#[test]
fn moved_points_give_a_fresh_pipelines_levels() {
    use prism_geom::rules::CornerRule;
    use prism_geom::{Pipeline, Scheme};
    let (open, attrs) = open_torus_with_creases();
    let mut tags = SubdivTags::default();
    tags.corners.insert(20, 1.5);
    tags.holes.insert(30);
    let cc = Scheme::Primal(PrimalScheme::CatmullClark);
    let lp = Scheme::Primal(PrimalScheme::Loop);
    let round = Scheme::Biquadratic(CornerRule::Combination { r: 0.02 });
    let closed = primitives::tripod();
    for (mesh, attrs, tags, steps) in [
        (open.clone(), attrs.clone(), tags.clone(), vec![cc, cc, cc]),
        (
            primitives::fan_triangulated(&open),
            attrs.clone(),
            SubdivTags::default(),
            vec![lp, lp],
        ),
        (
            closed,
            EdgeAttrs::new(),
            SubdivTags::default(),
            vec![cc, round, cc],
        ),
    ] {
        let clamp = prism_geom::rules::Overlap::Clamp;
        let mut p = Pipeline::with_tags(mesh.clone(), attrs.clone(), tags.clone(), steps.clone());
        p.options.overlap = clamp;
        p.compute().unwrap();
        let mut from = p;
        for round in 1..=2 {
            let mut moved = mesh.positions.clone();
            moved[3] += DVec3::new(0.01, -0.02, 0.03) * round as f64;
            moved[7].z -= 0.015 * round as f64;
            let mut m = from.moved(moved.clone());
            let primal_first = steps
                .iter()
                .take_while(|s| matches!(s, Scheme::Primal(_)))
                .count();
            assert_eq!(m.reused_steps(), primal_first);
            m.compute().unwrap();
            assert_eq!(m.reused_steps(), 0);
            let mut fresh_mesh = mesh.clone();
            fresh_mesh.positions = moved;
            let mut fresh =
                Pipeline::with_tags(fresh_mesh, attrs.clone(), tags.clone(), steps.clone());
            fresh.options.overlap = clamp;
            fresh.compute().unwrap();
            for (k, (a, b)) in m.levels().iter().zip(fresh.levels()).enumerate() {
                assert_eq!(a.mesh, b.mesh, "level {k}, move {round}, {steps:?}");
                assert_eq!(a.edge_attrs, b.edge_attrs, "level {k}");
                assert_eq!(a.tags, b.tags, "level {k}");
                let volume = |l: &prism_geom::Level| l.report.as_ref().map(|r| r.volume);
                assert_eq!(volume(a), volume(b), "level {k}");
            }
            from = m;
        }
    }
    let mut p = Pipeline::new(primitives::tripod(), EdgeAttrs::new(), vec![cc, cc]);
    p.compute().unwrap();
    let mut moved = p.input().mesh.positions.clone();
    moved[5].y = f64::NAN;
    let err = p.moved(moved).compute().map(|_| ()).unwrap_err();
    assert!(err.to_string().contains("vertex 5"), "{err}");
}
