//! The envelope over flat charts (docs/algorithms/envelope.md, "Charts"): invariants on scenes
//! generated from seeds — closed, outward, no crossing, no inward triangle, every kept part of
//! every primitive enclosed, G1 exactly along the network and by the mesh's own normals,
//! independent of the listing, and the shapes the construction promises.

mod common;
use common::off_surface;
use common::spec;
use prism_geom::analysis::winding_number;
use prism_geom::freeform::envelope::chart::quality::Quality;
use prism_geom::freeform::envelope::folds::crossings;
use prism_geom::freeform::envelope::{
    Envelope, EnvelopeError, EnvelopeSpec, Placement, Primitive, PrimitiveInput, Shape, envelope,
};
use prism_geom::{DVec3, PolyMesh, Topology};

/// A small generator (SplitMix64), so that every heap is reproducible from its seed.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn shape(rng: &mut Rng) -> Shape {
    match (rng.next() * 6.0) as usize {
        0 => Shape::Cube,
        1 => Shape::Box {
            a: 0.3 + rng.next(),
            b: 0.3 + rng.next(),
            c: 0.3 + rng.next(),
        },
        2 => Shape::Tetrahedron,
        3 => Shape::Octahedron,
        4 => Shape::TriangularPrism {
            height: 0.3 + 2.0 * rng.next(),
        },
        _ => Shape::HexagonalPrism {
            height: 0.3 + 2.0 * rng.next(),
        },
    }
}

/// Heap `seed`: 2 to 6 primitives of every library shape, turned every way, scaled 0.5 to 2,
/// their centres in a box that grows with the count.
fn heap(seed: u64) -> Vec<PrimitiveInput> {
    let mut rng = Rng(seed.wrapping_mul(0x2545_F491_4F6C_DD1D) ^ 0x5EED);
    let count = 2 + (rng.next() * 5.0) as usize;
    let side = 1.5 + 1.2 * count as f64;
    (0..count)
        .map(|_| {
            let s = shape(&mut rng);
            let centre = [side * rng.next(), side * rng.next(), side * rng.next()];
            let rotation = [360.0 * rng.next(), 360.0 * rng.next(), 360.0 * rng.next()];
            s.placed(&Placement {
                centre,
                scale: 0.5 + 1.5 * rng.next(),
                rotation,
            })
        })
        .collect()
}

/// Triangles whose normal is against their chart's direction.
fn inward(e: &Envelope, m: &PolyMesh, regions: &[u32]) -> usize {
    (0..m.num_faces())
        .filter(|&f| {
            let c: Vec<DVec3> = m
                .face_corners(f)
                .map(|i| m.positions[m.corner_verts[i] as usize])
                .collect();
            let n = (c[1] - c[0]).cross(c[2] - c[0]);
            let ch = &e.charts[regions[f] as usize];
            ch.frame
                .chart(e.frame.to_local((c[0] + c[1] + c[2]) / 3.0))
                .is_none_or(|(x, _)| n.dot(ch.frame.direction(x)) <= 0.0)
        })
        .count()
}

/// Everything the construction promises of one build, with `what` in the messages.
fn assert_sound(e: &Envelope, k: usize, what: &str) {
    let jump = e.largest_border_jump();
    assert!(jump < 1e-7, "{what}: border jump {jump}°");
    let (m, regions) = e
        .chart_mesh(k)
        .unwrap_or_else(|err| panic!("{what}: {err}"));
    assert!(m.positions.iter().all(|p| p.is_finite()), "{what}");
    let topo = Topology::build(&m).unwrap();
    topo.require_closed(&m)
        .unwrap_or_else(|err| panic!("{what}: {err}"));
    assert_eq!(inward(e, &m, &regions), 0, "{what}: inward triangles");
    assert_eq!(crossings(&m).len(), 0, "{what}: crossings");
    for x in common::kept_points(e, &[0.0, 0.5, 0.9, 1.0], 1e-6) {
        let w = winding_number(&m, x);
        assert!(w > 0.5, "{what}: kept point {x} outside (winding {w})");
    }
}

/// 1,000 heaps of 2 to 6 primitives, each at t = 3, 1, 0.5, 0.2 and 0.1: every build succeeds
/// and is closed, outward, G1, free of crossings, and holds every kept part.
#[test]
fn a_thousand_heaps_are_sound_at_every_t() {
    let from: u64 = std::env::var("HEAPS_FROM")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0);
    for seed in from..1000 {
        let prims = heap(seed);
        for t in [3.0, 1.0, 0.5, 0.2, 0.1] {
            let what = format!("heap {seed} at t = {t}");
            let e = envelope(&spec(prims.clone(), t)).unwrap_or_else(|err| panic!("{what}: {err}"));
            assert_sound(&e, 3, &what);
        }
    }
}

/// One cube's envelope has the cube's 48 symmetries at every t: every mesh vertex, mapped by
/// each, lies on the surface (to 10⁻⁹), though the mesh itself is not symmetric.
#[test]
fn one_cube_has_its_48_symmetries() {
    for t in [2.0, 1.0, 0.3] {
        let e = envelope(&spec(vec![Shape::Cube.placed(&Placement::default())], t)).unwrap();
        let (m, _) = e.chart_mesh(6).unwrap();
        for s in common::cube_symmetries() {
            for x in &m.positions {
                let y = s * *x;
                let d = off_surface(&e, y);
                assert!(d < 1e-9, "t = {t}: {y} is {d} off");
            }
        }
    }
}

/// The surface does not depend on the listing: primitives listed backwards and every face's
/// corners started elsewhere give a surface through every vertex of the first's mesh (to
/// 10⁻⁸ of the edge length: the fusion quads' corner twists are difference quotients taken
/// from each corner inwards, which a listing backwards takes from the other end).
#[test]
fn the_surface_does_not_depend_on_the_listing() {
    for seed in 0..40 {
        let prims = heap(seed);
        let mut again: Vec<PrimitiveInput> = prims.iter().rev().cloned().collect();
        for p in &mut again {
            for f in &mut p.faces {
                f.rotate_left(1);
            }
            p.faces.reverse();
        }
        // The charts themselves (the strips' lifts, a sum over the primitives' points, are
        // applied to the mesh afterwards and left out here).
        let cut = |p: &[PrimitiveInput], t: f64| EnvelopeSpec {
            enclosure: prism_geom::freeform::envelope::Enclosure::Paper,
            ..spec(p.to_vec(), t)
        };
        for t in [1.0, 0.3] {
            let a = envelope(&cut(&prims, t)).unwrap();
            let b = envelope(&cut(&again, t)).unwrap();
            let (m, _) = a.chart_mesh(4).unwrap();
            let size = a.edge_length * a.frame.scale;
            for x in &m.positions {
                let d = off_surface(&b, *x);
                assert!(d < 1e-8 * size, "heap {seed} at t = {t}: {x} is {d} off");
            }
        }
    }
}

/// Two equal cubes of one orientation on a line parallel to a cube axis, t = 1: the fusion
/// strip is the circular cylinder of radius r about the centre line (seed 004's fig. 11), to
/// rounding; each cube's kept part lies within 5 % of r of its sphere (the charts reproduce
/// the sphere along every curve and level off at its height over each face's foot, not in
/// between: envelope.md, "Shape").
#[test]
fn two_aligned_cubes_at_t_1_give_a_cylinder_between_spheres() {
    let cube = |x: f64| {
        Shape::Cube.placed(&Placement {
            centre: [x, 0.0, 0.0],
            ..Placement::default()
        })
    };
    let e = envelope(&spec(vec![cube(0.0), cube(3.0)], 1.0)).unwrap();
    let r = e.primitives[0].radius;
    let (m, regions) = e.chart_mesh(8).unwrap();
    for (f, &region) in regions.iter().enumerate() {
        let kind = e.network.regions[region as usize].kind;
        for c in m.face_corners(f) {
            let x = e.frame.to_local(m.positions[m.corner_verts[c] as usize]);
            let off = match kind {
                prism_geom::freeform::envelope::network::RegionKind::Primitive {
                    primitive,
                    ..
                } => (x.distance(e.primitives[primitive].centre) - r) * 1e-9 / 0.05,
                _ => DVec3::new(0.0, x.y, x.z).length() - r,
            };
            assert!(off.abs() < 1e-9 * r, "{kind:?}: {x} is {off} off");
        }
    }
}

/// The mesh's own G1 measure (the angle between the two regions' vertex normals at a border
/// vertex) falls with the resolution like 1/K: to under 0.4 of its value from K = 8 to 64.
#[test]
fn the_mesh_normal_gap_falls_like_one_over_k() {
    let shapes = [
        Shape::Cube,
        Shape::Tetrahedron,
        Shape::Octahedron,
        Shape::HexagonalPrism { height: 1.0 },
    ];
    for shape in shapes {
        for t in [1.0, 0.5] {
            let e = envelope(&spec(vec![shape.placed(&Placement::default())], t)).unwrap();
            let gap = |k: usize| {
                let (m, regions) = e.chart_mesh(k).unwrap();
                e.quality_of(&m, &regions).border_gap
            };
            let (coarse, fine) = (gap(8), gap(64));
            assert!(
                fine < 0.4 * coarse,
                "{shape:?} at t = {t}: {coarse}° -> {fine}°"
            );
        }
    }
}

/// A single primitive of every library shape, turned, is enclosed at every t of the slider
/// and beyond (its vertices lie on the surface, so the margin is ~0, never negative), the
/// report finds nothing inward or open, and no angle of the mesh is a needle (the refinement
/// asks for 20°; beside a corner whose sides it keeps, 8.9° is the least measured).
#[test]
fn one_primitive_is_enclosed_at_every_t() {
    let mut rng = Rng(7);
    for _ in 0..12 {
        let p = shape(&mut rng).placed(&Placement {
            centre: [rng.next(), rng.next(), rng.next()],
            scale: 0.5 + rng.next(),
            rotation: [360.0 * rng.next(), 360.0 * rng.next(), 360.0 * rng.next()],
        });
        for t in [3.0, 1.0, 0.5, 0.2, 0.1, 0.02] {
            let e = envelope(&spec(vec![p.clone()], t)).unwrap();
            let (_, q): (PolyMesh, Quality) = e.quality(6).unwrap();
            assert!(q.enclosure[0] > -1e-9, "t = {t}: {q:?}");
            assert_eq!((q.inward, q.open_edges), (0, 0), "t = {t}");
            assert!(q.smallest_angle > 5.0, "t = {t}: {q:?}");
        }
    }
}

/// Pair `seed`: two primitives of every library shape, turned every way, the second scaled 0.5
/// to 2 and placed in any direction with their spheres 5 % to twice their radii apart (each
/// one's cut-off part then lies between the two silhouette planes).
fn pair(seed: u64) -> Vec<PrimitiveInput> {
    let mut rng = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ 0xA11);
    let first = shape(&mut rng).placed(&Placement {
        centre: [0.0; 3],
        scale: 1.0,
        rotation: [360.0 * rng.next(), 360.0 * rng.next(), 360.0 * rng.next()],
    });
    let s = shape(&mut rng);
    let (u, v) = (rng.next(), rng.next());
    let (z, phi) = (2.0 * u - 1.0, std::f64::consts::TAU * v);
    let dir = DVec3::new(
        (1.0 - z * z).sqrt() * phi.cos(),
        (1.0 - z * z).sqrt() * phi.sin(),
        z,
    );
    let scale = 0.5 + 1.5 * rng.next();
    let at = dir * (1.0 + scale) * (1.05 + rng.next());
    let second = s.placed(&Placement {
        centre: at.to_array(),
        scale,
        rotation: [360.0 * rng.next(), 360.0 * rng.next(), 360.0 * rng.next()],
    });
    vec![first, second]
}

/// Enclosure by construction (docs/algorithms/envelope.md, "Enclosure"): on 150 generated pairs
/// at t = 3, 1, 0.5, 0.2 and 0.1, every point of both primitives — the corners the silhouette
/// planes cut off included — lies inside the mesh at K = 8 (the quality report's margins; the
/// surface holds them 5 % clear, the mesh's chords across a lift's bump to within 1 % of r, or
/// to within 0.1 % at K = 32 where a bump is narrow), and
/// the lifted surface stays closed, outward and free of crossings. With the paper's central cut
/// (`Enclosure::Paper`) nothing is lifted, and some pair's cut-off corner pokes out.
#[test]
fn every_primitive_of_a_pair_is_enclosed_at_every_t() {
    let mut poked = 0;
    for seed in 0..150 {
        let prims = pair(seed);
        for t in [3.0, 1.0, 0.5, 0.2, 0.1] {
            let what = format!("pair {seed} at t = {t}");
            let e = envelope(&spec(prims.clone(), t)).unwrap_or_else(|err| panic!("{what}: {err}"));
            assert_sound(&e, 3, &what);
            let (m, regions) = e.mesh(8).unwrap();
            let q = e.quality_of(&m, &regions);
            assert_eq!(q.inward, 0, "{what}");
            for (i, &margin) in q.enclosure.iter().enumerate() {
                if !e.removed.contains(&i) {
                    let finer = || {
                        let (m, regions) = e.mesh(32).unwrap();
                        e.quality_of(&m, &regions).enclosure[i]
                    };
                    assert!(
                        margin > -0.01 || finer() > -1e-3,
                        "{what}: primitive {i} reaches {margin} r outside"
                    );
                }
            }
            if t == 0.1 {
                let cut = envelope(&EnvelopeSpec {
                    enclosure: prism_geom::freeform::envelope::Enclosure::Paper,
                    ..spec(prims.clone(), t)
                })
                .unwrap();
                assert!(cut.lifts.is_empty());
                let (m, regions) = cut.mesh(8).unwrap();
                if cut
                    .quality_of(&m, &regions)
                    .enclosure
                    .iter()
                    .any(|&x| x < -1e-3)
                {
                    poked += 1;
                }
            }
        }
    }
    assert!(poked > 10, "{poked}");
}

/// Where a primitive sits and how large it is decide neither whether it is valid nor the
/// surface: every primitive of the seven-primitive scene, moved by 1e6 or 1e8 or scaled by
/// 1e-100 or 1e100, is accepted with its centre and radius moved and scaled (its checks run
/// about its centre in units of its radius); and the scene so moved or scaled builds the
/// surface of the scene as given, moved and scaled (the envelope is built about the scene's
/// centre in units of its size: every mesh vertex, mapped back, within 1e-6 of the scene's size
/// of a vertex of the scene's own mesh, and the other way).
#[test]
fn where_a_primitive_sits_and_its_size_do_not_decide_its_validity() {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../assets/table2-seven.envelope.json"),
    )
    .unwrap();
    let base: prism_geom::freeform::envelope::EnvelopeSpec = serde_json::from_str(&text).unwrap();
    let moved = |shift: f64, scale: f64| {
        let mut m = base.clone();
        for p in &mut m.primitives {
            for v in &mut p.vertices {
                *v = (DVec3::from_array(*v) * scale + DVec3::splat(shift)).to_array();
            }
        }
        m
    };
    for (shift, scale) in [(1e6, 1.0), (1e8, 1.0), (0.0, 1e-100), (0.0, 1e100)] {
        let m = moved(shift, scale);
        for (i, (p, q)) in base.primitives.iter().zip(&m.primitives).enumerate() {
            let a = Primitive::new(i, p, 1.0).unwrap();
            let b = Primitive::new(i, q, 1.0)
                .unwrap_or_else(|e| panic!("moved by {shift:e}, scaled by {scale:e}: {e}"));
            let centre = (b.centre - DVec3::splat(shift)) / scale;
            assert!(
                centre.distance(a.centre) < 1e-6 * a.radius,
                "{shift:e} {scale:e}"
            );
            assert!((b.radius / scale - a.radius).abs() < 1e-6 * a.radius);
        }
    }
    let charts_only = |s: EnvelopeSpec| EnvelopeSpec {
        enclosure: prism_geom::freeform::envelope::Enclosure::Paper,
        ..s
    };
    let reference = envelope(&base).unwrap();
    let cut = envelope(&charts_only(base.clone())).unwrap();
    let size = {
        let (m, _) = reference.chart_mesh(4).unwrap();
        let (lo, hi) = m.bbox();
        (hi - lo).length()
    };
    for (shift, scale) in [(1e6, 1.0), (1e8, 1.0), (0.0, 1e-100), (0.0, 1e100)] {
        let what = format!("moved by {shift:e}, scaled by {scale:e}");
        let e = envelope(&moved(shift, scale)).unwrap_or_else(|e| panic!("{what}: {e}"));
        let back = |p: DVec3| (p - DVec3::splat(shift)) / scale;
        // The network, vertex by vertex; the same lifts and raises.
        assert_eq!(
            e.network.vertices.len(),
            reference.network.vertices.len(),
            "{what}"
        );
        for (a, b) in e.network.vertices.iter().zip(&reference.network.vertices) {
            let (a, b) = (
                back(e.frame.to_world(a.position)),
                reference.frame.to_world(b.position),
            );
            assert!(
                a.distance(b) < 1e-7 * size,
                "{what}: network vertex {a} for {b}"
            );
        }
        assert_eq!(
            (e.lifts.len(), e.raises.len()),
            (reference.lifts.len(), reference.raises.len()),
            "{what}"
        );
        // The charts' surface: every vertex of the mesh (lifts left out), mapped back, on the
        // reference's charts.
        let (m, _) = envelope(&charts_only(moved(shift, scale)))
            .unwrap()
            .chart_mesh(4)
            .unwrap();
        let off = m
            .positions
            .iter()
            .map(|&p| off_surface(&cut, back(p)))
            .fold(0.0, f64::max);
        assert!(off < 1e-7 * size, "{what}: {off:e} off");
    }
}

/// Heaps of 2 to 6 primitives keep their primitives inside where the paper's central cut leaves
/// corners out — the strips' lifts hold their own primitives' cut-off corners, other
/// primitives' corners over them and corners over a lid beside them (one map across the
/// strip's edge with the lid) — but for corners where the strips about a lid's corner meet
/// (docs/algorithms/envelope.md, "Known limits"). 60 heaps at K = 8: heaps with a primitive out
/// (quality report's margin under −10⁻⁶), measured 2 at t = 1 and 4 at t = 0.5 (the central
/// cut: 29 and 59).
#[test]
fn heaps_keep_their_primitives_inside_but_near_a_lids_corner() {
    let out = |t: f64, enclosure| {
        (0..60)
            .filter(|&seed| {
                let e = envelope(&EnvelopeSpec {
                    enclosure,
                    ..spec(heap(seed), t)
                })
                .unwrap();
                let (m, regions) = e.mesh(8).unwrap();
                let q = e.quality_of(&m, &regions);
                q.enclosure
                    .iter()
                    .enumerate()
                    .any(|(i, &x)| !e.removed.contains(&i) && x < -1e-6)
            })
            .count()
    };
    use prism_geom::freeform::envelope::Enclosure;
    for (t, most, cut_least) in [(1.0, 3, 25), (0.5, 5, 50)] {
        let (lifted, cut) = (out(t, Enclosure::Lifted), out(t, Enclosure::Paper));
        assert!(
            lifted <= most,
            "t = {t}: {lifted} heaps with a primitive out"
        );
        assert!(cut >= cut_least, "t = {t}: the central cut leaves {cut}");
    }
}

/// A mesh whose progress is cancelled stops with `Cancelled`; a whole one counts every chart
/// and is the mesh as built without progress (the Envelope tab's progress bar and Cancel).
#[test]
fn a_cancelled_mesh_stops_and_a_whole_one_counts_every_chart() {
    let e = envelope(&spec(vec![Shape::Cube.placed(&Placement::default())], 0.5)).unwrap();
    let progress = prism_geom::progress::Progress::default();
    let whole = e.mesh_with(8, &progress).unwrap();
    assert_eq!(progress.fraction(), 1.0);
    assert_eq!(whole, e.mesh(8).unwrap());
    progress.cancel();
    assert_eq!(e.mesh_with(8, &progress), Err(EnvelopeError::Cancelled));
}
