//! The envelope of one primitive (seed 004; docs/algorithms/envelope.md): curves on the
//! sphere, the surface between the primitive and its sphere, symmetric, independent of the
//! listing order, closed and outward for every t, enclosing the primitive, G1.

mod common;
use common::hausdorff;

use prism_geom::freeform::envelope::{
    Envelope, EnvelopeError, EnvelopeSpec, Placement, PrimitiveInput, Shape, envelope,
};
use prism_geom::{DVec3, PolyMesh, Topology};

fn scene(shape: Shape, t: f64) -> EnvelopeSpec {
    EnvelopeSpec {
        t,
        primitives: vec![shape.placed(&Placement::default())],
        resolution: 8,
        basis: Default::default(),
        patches: prism_geom::freeform::envelope::Surfacing::Paper,
        enclosure: Default::default(),
    }
}

fn build(shape: Shape, t: f64) -> Envelope {
    envelope(&scene(shape, t)).unwrap()
}

const SHAPES: [Shape; 6] = [
    Shape::Cube,
    Shape::Box {
        a: 1.0,
        b: 0.6,
        c: 0.3,
    },
    Shape::Tetrahedron,
    Shape::Octahedron,
    Shape::TriangularPrism { height: 1.0 },
    Shape::HexagonalPrism { height: 1.0 },
];

/// A simplex, a prism and the cube: the faces of three, four and six sides.
const THREE: [Shape; 3] = [
    Shape::Tetrahedron,
    Shape::HexagonalPrism { height: 1.0 },
    Shape::Cube,
];

use prism_geom::analysis::winding_number as winding;

fn face_normal(m: &PolyMesh, f: usize) -> (DVec3, DVec3) {
    let vs: Vec<DVec3> = m
        .face_corners(f)
        .map(|c| m.positions[m.corner_verts[c] as usize])
        .collect();
    let mut n = DVec3::ZERO;
    for k in 0..vs.len() {
        n += vs[k].cross(vs[(k + 1) % vs.len()]);
    }
    let c = vs.iter().sum::<DVec3>() / vs.len() as f64;
    (n.normalize_or_zero(), c)
}

/// The angle between two vectors, accurate near 0 (atan2, not acos).
fn angle(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

/// Closed (every edge in two faces, consistently) and no face turned towards the centre.
fn assert_closed_outward(m: &PolyMesh, what: &str) {
    let t = Topology::build(m).unwrap_or_else(|e| panic!("{what}: not a manifold: {e}"));
    t.require_closed(m)
        .unwrap_or_else(|e| panic!("{what}: not closed: {e}"));
    for f in 0..m.num_faces() {
        let (n, c) = face_normal(m, f);
        assert!(n.dot(c) > 0.0, "{what}: face {f} faces inward");
    }
}

/// t = 1 on one cube: every network curve on the circumsphere (1e-12), the surface between
/// the cube and the sphere, the face centres inside the sphere by 9.88 %, 18.70 %, 34.16 % of
/// r at t = 1, 0.5, 0.1 (the spec's reference, with C′ itself in the cross derivative instead
/// of Prism's interpolated speed: 9.34 %, 16.49 %, 33.41 %; envelope.md).
#[test]
fn one_cube_lies_between_the_cube_and_its_sphere() {
    // The paper's patches as printed: the face centre as far inside the sphere as
    // envelope.md's model of one face predicts (9.3 %, 16.5 %, 33 %).
    for (t, centre_in) in [(1.0, 0.09340), (0.5, 0.16489), (0.1, 0.33406)] {
        let e = build(Shape::Cube, t);
        assert_eq!((e.regions, e.patches.len()), (6, 6));
        if t == 1.0 {
            for c in &e.network.curves {
                for k in 0..=50 {
                    let p = e.frame.to_world(c.bezier.eval(k as f64 / 50.0));
                    assert!((p.length() - 1.0).abs() < 1e-12);
                }
            }
        }
        let m = e.tessellate(8).unwrap();
        let inset = 1.0 / 3f64.sqrt();
        for p in &m.positions {
            assert!(p.length() <= 1.0 + 1e-12, "outside the sphere: {p}");
            assert!(
                p.abs().max_element() >= inset - 1e-12,
                "inside the cube: {p}"
            );
        }
        // The centre of face +x: the patch's (½, ½).
        let c = e
            .patches
            .iter()
            .map(|p| e.frame.to_world(p.coons.eval(0.5, 0.5)))
            .find(|p| p.x > 0.5)
            .unwrap();
        let inside = 1.0 - c.length();
        assert!(
            (inside - centre_in).abs() < 1e-4,
            "t = {t}: face centre {:.2} % of r inside the sphere",
            100.0 * inside
        );
    }
}

/// One cube's envelope has the cube's 48 symmetries (Hausdorff of the tessellation vertices
/// against their images ≤ 1e-9).
#[test]
fn one_cube_is_symmetric() {
    for t in [1.0, 0.3] {
        let m = build(Shape::Cube, t).tessellate(4).unwrap();
        let pts = &m.positions;
        for (k, s) in common::cube_symmetries().into_iter().enumerate() {
            let img: Vec<DVec3> = pts.iter().map(|p| s * *p).collect();
            let h = hausdorff(pts, &img);
            assert!(h < 1e-9, "t = {t}, symmetry {k}: {h}");
        }
    }
}

/// Renumbering vertices, listing faces in another order and starting each face elsewhere
/// gives the same surface.
#[test]
fn the_listing_order_does_not_matter() {
    for shape in THREE {
        for t in [1.0, 0.4] {
            let p = shape.placed(&Placement::default());
            let n = p.vertices.len();
            let new_of = |v: usize| (v * 5 + 3) % n; // a permutation for n ∈ {4, 8, 12}
            let mut vertices = vec![[0.0; 3]; n];
            for (v, x) in p.vertices.iter().enumerate() {
                vertices[new_of(v)] = *x;
            }
            let mut faces: Vec<Vec<usize>> = p
                .faces
                .iter()
                .enumerate()
                .map(|(i, f)| {
                    let mut f: Vec<usize> = f.iter().map(|&v| new_of(v)).collect();
                    let len = f.len();
                    f.rotate_left(i % len);
                    f
                })
                .collect();
            faces.reverse();
            let q = PrimitiveInput {
                vertices,
                faces,
                t: None,
                vertex_t: None,
            };
            let a = build(shape, t).tessellate(4).unwrap();
            let b = envelope(&EnvelopeSpec {
                t,
                primitives: vec![q],
                resolution: 8,
                basis: Default::default(),
                patches: prism_geom::freeform::envelope::Surfacing::Paper,
                enclosure: Default::default(),
            })
            .unwrap()
            .tessellate(4)
            .unwrap();
            let h = hausdorff(&a.positions, &b.positions);
            assert!(h < 1e-9, "{shape:?} t = {t}: {h}");
        }
    }
}

/// Every library shape (and flat prisms) for t from 0.001 to 3: closed, no face turned
/// inwards, no folded cell, no two faces through each other, G1 across every border (analytic
/// normal jump ≤ 1e-9°). Below t = 0.1 the half edges at a vertex are slow at the vertex end,
/// and the paper's `h·C′` along them sheared the corner cells past the vertex (tetrahedron
/// t ≤ 0.03, flat triangular prism t ≤ 0.05: envelope.md, "The part along the side").
#[test]
fn closed_outward_and_g1_for_every_t() {
    let flat = [
        Shape::TriangularPrism { height: 0.3 },
        Shape::HexagonalPrism { height: 0.3 },
    ];
    for shape in SHAPES.into_iter().chain(flat) {
        let turned = shape.placed(&Placement {
            rotation: [10.0, 20.0, 30.0],
            ..Placement::default()
        });
        for t in [
            3.0, 2.0, 1.0, 0.7, 0.5, 0.3, 0.1, 0.05, 0.02, 0.01, 0.003, 0.001,
        ] {
            let e = envelope(&EnvelopeSpec {
                primitives: vec![turned.clone()],
                ..scene(shape, t)
            })
            .unwrap();
            let what = format!("{shape:?} t = {t}");
            let m = e.tessellate(6).unwrap();
            if (0.1..=1.0).contains(&t) {
                // The paper's range: sound with no repair.
                assert_closed_outward(&m, &what);
                let jump = e.largest_border_jump();
                assert!(jump < 1e-9, "{what}: border jump {jump}°");
                assert_eq!(e.folds().len(), 0, "{what}: folded cells");
                let fine = e.tessellate(16).unwrap();
                let crossing = prism_geom::analysis::crossings(&fine);
                assert!(
                    crossing.is_empty(),
                    "{what}: faces cross {:?}",
                    &crossing[..1]
                );
            } else {
                assert_closed_faults_named(&e, &m, DVec3::ZERO, DVec3::ZERO, &what);
            }
        }
    }
}

/// The paper's patches are closed, and wherever they face inwards, are not G1 or pass through
/// themselves, what the build tells the user says so — folded cells, inward triangles in the
/// quality report, or the crossing warning: nothing is mended, nothing is hidden.
fn assert_closed_faults_named(e: &Envelope, m: &PolyMesh, ga: DVec3, gb: DVec3, what: &str) {
    let t = Topology::build(m).unwrap_or_else(|e| panic!("{what}: not a manifold: {e}"));
    t.require_closed(m)
        .unwrap_or_else(|e| panic!("{what}: not closed: {e}"));
    let d = (gb - ga).normalize_or_zero();
    let len = (gb - ga).length();
    let inward = (0..m.num_faces())
        .filter(|&f| {
            let (n, c) = face_normal(m, f);
            let axis = ga + (c - ga).dot(d).clamp(0.0, len) * d;
            n.dot(c - axis) <= 0.0
        })
        .count();
    let jump = e.largest_border_jump();
    let k = (m.num_faces() / e.patches.len()).isqrt();
    let (mesh, regions) = e.mesh(k).unwrap();
    let q = e.quality_of(&mesh, &regions);
    let told = !e.folds().is_empty()
        || q.inward > 0
        || e.crossing_warning(&prism_geom::freeform::envelope::folds::crossings(&mesh), k)
            .is_some();
    if inward > 0 || jump >= 1e-9 || !prism_geom::analysis::crossings(m).is_empty() {
        assert!(
            told,
            "{what}: {inward} faces inward, border jump {jump}°, nothing named"
        );
    }
}

#[test]
fn the_primitive_is_enclosed() {
    for shape in THREE {
        for t in [1.0, 0.5, 0.1] {
            let e = build(shape, t);
            let m = e.tessellate(8).unwrap();
            let p = &e.primitives[0];
            for face in &p.faces {
                let c = face.iter().map(|&v| p.vertices[v]).sum::<DVec3>() / face.len() as f64;
                for &v in face {
                    for s in [0.0, 0.5, 0.9] {
                        let q = e
                            .frame
                            .to_world(p.centre.lerp(c.lerp(p.vertices[v], s), 1.0 - 1e-3));
                        let w = winding(&m, q);
                        assert!(w > 0.5, "{shape:?} t = {t}: {q} has winding {w}");
                    }
                }
            }
        }
    }
}

/// The largest angle between neighbouring faces' normals falls with the resolution (a G1
/// surface: at K = 32 at most 0.4 × that at K = 8), for single primitives and pairs.
#[test]
fn normals_converge_with_the_resolution() {
    let scenes: Vec<(String, Envelope)> = vec![
        ("tetrahedron".into(), build(Shape::Tetrahedron, 1.0)),
        ("cube".into(), build(Shape::Cube, 1.0)),
        (
            "hexagonal prism".into(),
            build(Shape::HexagonalPrism { height: 1.0 }, 1.0),
        ),
        (
            "two cubes side by side, t = 0.5".into(),
            pair(
                cube_at([0.0; 3], [0.0; 3]),
                cube_at([3.0, 0.0, 0.0], [0.0; 3]),
                0.5,
            ),
        ),
        (
            "two diagonal cubes".into(),
            pair(
                cube_at([0.0; 3], [0.0; 3]),
                cube_at([3.0, 3.0, 3.0], [0.0; 3]),
                1.0,
            ),
        ),
    ];
    for (name, e) in &scenes {
        let worst = |k: usize| {
            let m = e.tessellate(k).unwrap();
            let t = Topology::build(&m).unwrap();
            t.require_closed(&m).unwrap();
            let mut w = 0.0f64;
            for &c in &t.edge_corner {
                let (fa, fb) = (
                    t.corner_face(c as usize) as usize,
                    t.corner_face(t.twin[c as usize] as usize) as usize,
                );
                w = w.max(angle(face_normal(&m, fa).0, face_normal(&m, fb).0));
            }
            w.to_degrees()
        };
        let (a, b) = (worst(8), worst(32));
        assert!(b <= 0.4 * a, "{name}: {a}° at K = 8, {b}° at K = 32");
    }
}

/// Bad scenes are refused naming the primitive.
#[test]
fn bad_primitives_are_named() {
    let cube = Shape::Cube.placed(&Placement::default());
    let err = |p: PrimitiveInput, t: f64| {
        envelope(&EnvelopeSpec {
            t,
            primitives: vec![p],
            resolution: 8,
            basis: Default::default(),
            patches: prism_geom::freeform::envelope::Surfacing::Paper,
            enclosure: Default::default(),
        })
        .unwrap_err()
        .to_string()
    };
    let mut off = cube.clone();
    off.vertices[3][0] *= 1.01;
    assert!(err(off, 1.0).contains("off the sphere"));
    assert!(err(cube.clone(), 0.0).contains("t must be finite and > 0"));
    assert!(err(cube.clone(), f64::NAN).contains("t must be"));
    let mut vt = cube.clone();
    vt.vertex_t = Some(vec![1.0, 1.0, -1.0, 1.0, 1.0, 1.0, 1.0, 1.0]);
    assert!(err(vt, 1.0).contains("vertex 2 of primitive 0"));
    let mut open = cube.clone();
    open.faces.pop();
    assert!(err(open, 1.0).contains("not closed"));
    let mut nan = cube.clone();
    nan.vertices[0][1] = f64::NAN;
    assert!(err(nan, 1.0).contains("vertex 0 is not a finite point"));
    // A cap face pushed out of the sphere's plane makes it non-convex/off-sphere: the centre
    // outside a half-sphere "primitive".
    let half = PrimitiveInput {
        vertices: vec![
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0],
        ],
        faces: vec![vec![0, 1, 3], vec![1, 2, 3], vec![2, 0, 3], vec![0, 2, 1]],
        t: None,
        vertex_t: None,
    };
    assert!(err(half, 1.0).contains("is not inside it"));
    // A vertex repeated (and a face using it, so that only the coincidence is wrong).
    let mut twice = cube.clone();
    twice.vertices.push(twice.vertices[0]);
    twice.faces[0][0] = 8;
    assert!(err(twice, 1.0).contains("vertices 0 and 8 coincide"));
    // The octahedron with one edge flipped through the inside: its vertices are on the
    // sphere, its surface closed and oriented, but two faces are reflex.
    let o = [
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [-1.0, 0.0, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, 0.0, -1.0],
    ];
    let flipped = PrimitiveInput {
        vertices: o.to_vec(),
        faces: [[4, 0, 5], [4, 5, 1], [4, 1, 2], [4, 2, 3]]
            .into_iter()
            .chain([[4, 3, 0], [5, 2, 1], [5, 3, 2], [5, 0, 3]])
            .map(|f| f.to_vec())
            .collect(),
        t: None,
        vertex_t: None,
    };
    let e = err(flipped, 1.0);
    assert!(e.contains("not convex: vertex"), "{e}");
    assert!(matches!(
        envelope(&EnvelopeSpec {
            t: 1.0,
            primitives: vec![],
            resolution: 8,
            basis: Default::default(),
            patches: prism_geom::freeform::envelope::Surfacing::Paper,
            enclosure: Default::default(),
        }),
        Err(EnvelopeError::Empty)
    ));
}

fn cube_at(centre: [f64; 3], rotation: [f64; 3]) -> PrimitiveInput {
    // Half-size 1: the unit-sphere cube scaled by √3.
    Shape::Cube.placed(&Placement {
        centre,
        scale: 3f64.sqrt(),
        rotation,
    })
}

fn pair(a: PrimitiveInput, b: PrimitiveInput, t: f64) -> Envelope {
    envelope(&EnvelopeSpec {
        t,
        primitives: vec![a, b],
        resolution: 8,
        basis: Default::default(),
        patches: prism_geom::freeform::envelope::Surfacing::Paper,
        enclosure: Default::default(),
    })
    .unwrap()
}

/// Closed, and every face turned away from the segment between the two centres.
fn assert_closed_outward_from(m: &PolyMesh, ga: DVec3, gb: DVec3, what: &str) {
    let t = Topology::build(m).unwrap_or_else(|e| panic!("{what}: not a manifold: {e}"));
    t.require_closed(m)
        .unwrap_or_else(|e| panic!("{what}: not closed: {e}"));
    let d = (gb - ga).normalize();
    let len = (gb - ga).length();
    for f in 0..m.num_faces() {
        let (n, c) = face_normal(m, f);
        let axis = ga + (c - ga).dot(d).clamp(0.0, len) * d;
        assert!(n.dot(c - axis) > 0.0, "{what}: face {f} faces inward");
    }
}

/// Two equal cubes of one orientation on an axis (envelope.md, "Enclosure"): 14 regions; the fusion
/// surface is the silhouette loop translated along d for every t, and at t = 1 the circular
/// cylinder of radius √3 (half-size 1) about the centre line; closed, and its faults named
/// (at t = 0.1 the paper's cube faces fold beside the silhouette).
#[test]
fn two_aligned_cubes_fuse_by_translation() {
    let gb = DVec3::new(3.0, 0.0, 0.0);
    for t in [1.0, 0.7, 0.5, 0.3, 0.1, 2.0] {
        let e = pair(
            cube_at([0.0; 3], [0.0; 3]),
            cube_at(gb.to_array(), [0.0; 3]),
            t,
        );
        assert_eq!((e.regions, e.patches.len()), (14, 14));
        assert!(e.largest_border_jump() < 1e-9);
        let m = e.tessellate(8).unwrap();
        assert_closed_faults_named(&e, &m, DVec3::ZERO, gb, &format!("t = {t}"));
        if t == 1.0 {
            assert_closed_outward_from(&m, DVec3::ZERO, gb, "t = 1");
        }
        for p in &e.patches {
            if !e.network.regions[p.region].kind.between() {
                continue;
            }
            for i in 0..=8 {
                let u = i as f64 / 8.0;
                // The fusion quad runs along d from A's loop (v = 0) to B's (v = 1).
                let base = e.frame.to_world(p.coons.eval(u, 0.0));
                for j in 0..=8 {
                    let q = e.frame.to_world(p.coons.eval(u, j as f64 / 8.0));
                    assert!((q - base).cross(DVec3::X).length() < 1e-12, "t = {t}: {q}");
                    if t == 1.0 {
                        let r = (q.y * q.y + q.z * q.z).sqrt();
                        assert!((r - 3f64.sqrt()).abs() < 1e-12, "{r}");
                    }
                }
            }
        }
    }
}

/// Two cubes on the body diagonal: 18 regions (each cube's 3 triangles and 3 pentagons, 6 fusion
/// quads), 54 patches; closed at every t, outward, G1 and both cubes enclosed at t = 1; where
/// the star condition at the inserted points fails (envelope.md, "The paper's patches": t = 0.7 and below) the
/// folds are named.
#[test]
fn two_diagonal_cubes_are_closed_outward_and_g1() {
    let gb = DVec3::new(3.0, 3.0, 3.0);
    for t in [1.0, 0.7, 0.5, 0.3, 0.1, 2.0, 3.0] {
        let e = pair(
            cube_at([0.0; 3], [0.0; 3]),
            cube_at(gb.to_array(), [0.0; 3]),
            t,
        );
        assert_eq!((e.regions, e.patches.len()), (18, 54));
        let m = e.tessellate(8).unwrap();
        assert_closed_faults_named(&e, &m, DVec3::ZERO, gb, &format!("t = {t}"));
        if t == 1.0 {
            let jump = e.largest_border_jump();
            assert!(jump < 1e-9, "t = {t}: {jump}°");
            assert_closed_outward_from(&m, DVec3::ZERO, gb, "t = 1");
            for p in &e.primitives {
                for face in &p.faces {
                    let c = face.iter().map(|&v| p.vertices[v]).sum::<DVec3>() / face.len() as f64;
                    for &v in face {
                        for s in [0.0, 0.5, 0.9] {
                            let q = e.frame.to_world(
                                p.centre + (c.lerp(p.vertices[v], s) - p.centre) * (1.0 - 1e-3),
                            );
                            let w = winding(&m, q);
                            assert!(w > 0.5, "{q} has winding {w}");
                        }
                    }
                }
            }
        }
    }
}

/// A cube turned against the other (T-points on the silhouette edges): closed, outward, G1 at
/// t = 1, and the same surface when the two are listed the other way round.
#[test]
fn skew_cubes_and_the_order_of_the_pair() {
    let (ca, cb) = ([0.0; 3], [2.5, 1.0, 0.5]);
    let rot = [20.0, 35.0, 10.0];
    let e = pair(cube_at(ca, [0.0; 3]), cube_at(cb, rot), 1.0);
    assert!(e.patches.len() > e.regions, "some regions are split");
    assert!(e.largest_border_jump() < 1e-9);
    let m = e.tessellate(6).unwrap();
    assert_closed_outward_from(&m, DVec3::ZERO, DVec3::from_array(cb), "skew");
    let swapped = pair(cube_at(cb, rot), cube_at(ca, [0.0; 3]), 1.0)
        .tessellate(6)
        .unwrap();
    let h = hausdorff(&m.positions, &swapped.positions);
    assert!(h < 1e-9, "{h}");
    for (a, b) in [
        (cube_at(ca, [0.0; 3]), cube_at([3.0, 3.0, 3.0], [0.0; 3])),
        (cube_at(ca, [0.0; 3]), cube_at([3.0, 0.0, 0.0], [0.0; 3])),
    ] {
        let one = pair(a.clone(), b.clone(), 0.5).tessellate(4).unwrap();
        let two = pair(b, a, 0.5).tessellate(4).unwrap();
        assert!(hausdorff(&one.positions, &two.positions) < 1e-9);
    }
}

/// The same turned pair at small t: closed, and wherever the paper's patches fold, named.
#[test]
fn a_turned_pair_at_small_t_is_closed_and_its_folds_named() {
    let gb = [2.5, 1.0, 0.5];
    for t in [0.3, 0.2, 0.1] {
        let e = pair(
            cube_at([0.0; 3], [0.0; 3]),
            cube_at(gb, [20.0, 35.0, 10.0]),
            t,
        );
        let m = e.tessellate(6).unwrap();
        let what = format!("t = {t}");
        assert_closed_faults_named(&e, &m, DVec3::ZERO, DVec3::from_array(gb), &what);
    }
}

/// Two primitives with one centre have no view vector between them: refused, naming both
/// (also when others are in the scene).
#[test]
fn primitives_with_one_centre_are_refused() {
    let e = envelope(&EnvelopeSpec {
        t: 1.0,
        primitives: vec![
            cube_at([0.0; 3], [0.0; 3]),
            cube_at([0.0; 3], [10.0, 0.0, 0.0]),
        ],
        resolution: 8,
        basis: Default::default(),
        patches: prism_geom::freeform::envelope::Surfacing::Paper,
        enclosure: Default::default(),
    })
    .unwrap_err();
    assert_eq!(e, EnvelopeError::SameCentre { a: 0, b: 1 });
    let e = envelope(&EnvelopeSpec {
        t: 1.0,
        primitives: vec![
            cube_at([0.0; 3], [0.0; 3]),
            cube_at([3.0, 0.0, 0.0], [0.0; 3]),
            cube_at([0.0, 3.0, 0.0], [0.0; 3]),
            cube_at([3.0, 0.0, 0.0], [0.0, 0.0, 45.0]),
        ],
        resolution: 8,
        basis: Default::default(),
        patches: prism_geom::freeform::envelope::Surfacing::Paper,
        enclosure: Default::default(),
    })
    .unwrap_err();
    assert_eq!(e, EnvelopeError::SameCentre { a: 1, b: 3 });
}

/// Two cubes off every symmetry axis: at t = 0.3 the rebuilt kept pieces of two edges would
/// hook (no convex arc leaves the corner and reaches the silhouette point normal to both
/// radii); the edge's own piece is kept there, so no network curve hooks at any t; the paper's
/// patches over it are closed and their faults named.
#[test]
fn an_off_axis_pair_keeps_the_edge_where_the_rebuilt_piece_would_hook() {
    let gb = DVec3::new(3.0, 1.2, 0.6);
    for t in [1.0, 0.7, 0.5, 0.3, 0.1] {
        let e = pair(
            cube_at([0.0; 3], [0.0; 3]),
            cube_at(gb.to_array(), [0.0; 3]),
            t,
        );
        for c in &e.network.curves {
            let chord = c.bezier.eval(1.0) - c.bezier.eval(0.0);
            assert!(
                c.bezier.derivatives(0.0).d1.dot(chord) > 0.0,
                "t = {t}: a hook"
            );
        }
        let m = e.tessellate(8).unwrap();
        assert_closed_faults_named(&e, &m, DVec3::ZERO, gb, &format!("t = {t}"));
    }
}

/// The paper's one-sided basis as an option (skin.md, "Patches and G1"): G1 too, but on one cube at
/// t = 1 the basis side's cross direction at the middle of every edge arc points 18.4° into
/// the sphere (the mean of the corner legs), where the virtual basis keeps the sphere's tangent
/// plane (0°); and the surface depends on the order the faces are listed in.
#[test]
fn the_one_sided_basis_tilts_the_cube_and_depends_on_the_listing() {
    use prism_geom::freeform::Basis;
    let tilt = |basis: Basis| {
        let mut s = scene(Shape::Cube, 1.0);
        s.basis = basis;
        let e = envelope(&s).unwrap();
        assert!(e.largest_border_jump() < 1e-9, "{basis:?}");
        let mut worst = 0.0f64;
        for p in &e.patches {
            for side in &p.coons.sides {
                let c = side.curve.eval(0.5);
                let x = side.cross(0.5).0.normalize();
                worst = worst.max(x.dot(c.normalize()).abs().asin().to_degrees());
            }
        }
        (worst, e.tessellate(4).unwrap())
    };
    let (virtual_tilt, _) = tilt(Basis::Virtual);
    let (one_sided_tilt, m) = tilt(Basis::OneSided);
    assert!(virtual_tilt < 1e-9, "{virtual_tilt}");
    assert!((one_sided_tilt - 18.43).abs() < 0.01, "{one_sided_tilt}");
    // Listed the other way round, the one-sided surface changes; the virtual one does not.
    let reversed = |basis: Basis| {
        let mut s = scene(Shape::Cube, 1.0);
        s.primitives[0].faces.reverse();
        s.basis = basis;
        envelope(&s).unwrap().tessellate(4).unwrap()
    };
    assert!(hausdorff(&m.positions, &reversed(Basis::OneSided).positions) > 1e-4);
    let (_, v) = tilt(Basis::Virtual);
    assert!(hausdorff(&v.positions, &reversed(Basis::Virtual).positions) < 1e-9);
}
