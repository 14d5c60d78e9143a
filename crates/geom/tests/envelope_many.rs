//! Envelopes of three or more primitives (seed 004 §5.1.3, §5.2 b; docs/algorithms/envelope.md,
//! "Three or more primitives"): sections cut again, fusion strips along the hull edges of the
//! centres, lids on its facets, swallowed primitives; closed, outward, G1, independent of the
//! listing.

mod common;
use common::past_corners;
use prism_geom::freeform::envelope::network::RegionKind;
use prism_geom::freeform::envelope::{
    Envelope, EnvelopeSpec, Placement, Primitive, PrimitiveInput, Shape, envelope,
};
use prism_geom::{DVec3, PolyMesh, Topology};

fn cube_at(centre: [f64; 3], rotation: [f64; 3]) -> PrimitiveInput {
    Shape::Cube.placed(&Placement {
        centre,
        scale: 3f64.sqrt(),
        rotation,
    })
}

fn spec(primitives: Vec<PrimitiveInput>, t: f64) -> EnvelopeSpec {
    EnvelopeSpec {
        t,
        primitives,
        resolution: 8,
        basis: Default::default(),
        patches: prism_geom::freeform::envelope::Surfacing::Paper,
    }
}

fn build(primitives: Vec<PrimitiveInput>, t: f64) -> Envelope {
    envelope(&spec(primitives, t)).unwrap()
}

/// The envelope of `primitives` at `t` as listed and listed backwards, each checked to fold
/// nowhere and, tessellated 8 × 8 a patch, to cross itself nowhere.
fn unfolded_both_ways(primitives: &[PrimitiveInput], t: f64) -> [Envelope; 2] {
    use prism_geom::freeform::envelope::folds::crossings;
    let backwards: Vec<PrimitiveInput> = primitives.iter().rev().cloned().collect();
    [primitives.to_vec(), backwards].map(|listed| {
        let e = build(listed, t);
        assert_eq!(past_corners(&e), vec![], "t = {t}");
        assert!(crossings(&e.tessellate(8).unwrap()).is_empty(), "t = {t}");
        e
    })
}

use prism_geom::analysis::winding_number as winding;

fn face_normal(m: &PolyMesh, f: usize) -> (DVec3, DVec3, f64) {
    let vs: Vec<DVec3> = m
        .face_corners(f)
        .map(|c| m.positions[m.corner_verts[c] as usize])
        .collect();
    let mut n = DVec3::ZERO;
    for k in 0..vs.len() {
        n += vs[k].cross(vs[(k + 1) % vs.len()]);
    }
    let c = vs.iter().sum::<DVec3>() / vs.len() as f64;
    let size = vs.iter().map(|v| v.distance(c)).fold(0.0, f64::max);
    (n.normalize_or_zero(), c, size)
}

/// Faces whose outside (a step of a tenth of the face's size along its normal) is inside the
/// solid: folds.
fn inward_faces(m: &PolyMesh) -> usize {
    (0..m.num_faces())
        .filter(|&f| {
            let (n, c, size) = face_normal(m, f);
            winding(m, c + 0.1 * size * n) > 0.5
        })
        .count()
}

fn closed(m: &PolyMesh) -> Result<(), String> {
    let t = Topology::build(m).map_err(|e| e.to_string())?;
    t.require_closed(m).map_err(|e| e.to_string())
}

/// Samples of every face of every kept primitive, pulled 1e-3 towards its centre.
fn samples(e: &Envelope) -> Vec<DVec3> {
    let mut out = Vec::new();
    for (i, p) in e.primitives.iter().enumerate() {
        if e.removed.contains(&i) {
            continue;
        }
        for face in &p.faces {
            let c = face.iter().map(|&v| p.vertices[v]).sum::<DVec3>() / face.len() as f64;
            for &v in face {
                for s in [0.0, 0.5, 0.9] {
                    out.push(p.centre + (c.lerp(p.vertices[v], s) - p.centre) * (1.0 - 1e-3));
                }
            }
        }
    }
    out
}

fn hausdorff(a: &[DVec3], b: &[DVec3]) -> f64 {
    let one = |a: &[DVec3], b: &[DVec3]| {
        a.iter()
            .map(|p| {
                b.iter()
                    .map(|q| p.distance(*q))
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(0.0, f64::max)
    };
    one(a, b).max(one(b, a))
}

fn l_of_three() -> Vec<PrimitiveInput> {
    vec![
        cube_at([0.0; 3], [0.0; 3]),
        cube_at([3.0, 0.0, 0.0], [0.0; 3]),
        cube_at([0.0, 3.0, 0.0], [0.0; 3]),
    ]
}

fn tetrahedron_of_four() -> Vec<PrimitiveInput> {
    vec![
        cube_at([0.0; 3], [0.0; 3]),
        cube_at([4.0, 0.0, 0.0], [0.0; 3]),
        cube_at([0.0, 4.0, 0.0], [0.0; 3]),
        cube_at([0.0, 0.0, 4.0], [0.0; 3]),
    ]
}

/// Closed, G1 (analytic border jump ≤ 1e-9°), no face turned inwards, and (where asked) every
/// kept primitive enclosed. No face is turned inwards exactly when the tessellation (K = 4) is
/// closed and consistently oriented, passes through itself nowhere and has a positive volume:
/// it then bounds one solid and every face has it on its back. (The winding test of
/// [`inward_faces`], a point a tenth of a face off its centroid, samples this and also flags
/// a coarse cell that a neighbour's chord hangs over: one cell of a sliver 0.002 wide among the
/// two dozen cubes below, which crosses nothing at K = 4, 8 or 16, has no folded cell and no
/// face flagged at K = 8 or 16.)
fn assert_sound(e: &Envelope, enclosed: bool, what: &str) {
    let jump = e.largest_border_jump();
    assert!(jump < 1e-9, "{what}: border jump {jump}°");
    let m = e.tessellate(4).unwrap();
    closed(&m).unwrap_or_else(|why| panic!("{what}: {why}"));
    let pairs = prism_geom::freeform::envelope::folds::crossings(&m);
    assert!(
        pairs.is_empty(),
        "{what}: passes through itself near {:?}",
        pairs.first()
    );
    let volume = prism_geom::geometry::signed_volume(&m);
    assert!(volume > 0.0, "{what}: volume {volume}");
    if enclosed {
        for q in samples(e) {
            let w = winding(&m, q);
            assert!(w > 0.5, "{what}: {q} has winding {w}");
        }
    }
}

/// Three equal cubes in an L (centres coplanar): each keeps the part outside the corner of
/// the centres' triangle, three fusion strips and two triangular lids. Sound for t from 0.1
/// to 1; at t = 1 every point of the strips and lids is √3 (the circumradius) from the
/// triangle of centres: the convex hull of the three spheres, exactly (1e-12).
#[test]
fn three_cubes_in_an_l() {
    for t in [1.0, 0.7, 0.5, 0.3, 0.1] {
        let e = build(l_of_three(), t);
        assert!(e.removed.is_empty());
        assert_eq!(e.straight.len(), 6, "two rays per cube");
        assert_sound(&e, t == 1.0, &format!("t = {t}"));
        if t != 1.0 {
            continue;
        }
        // Distance from the triangle (0,0,0), (3,0,0), (0,3,0) in the plane z = 0.
        let from_triangle = |p: DVec3| {
            let (x, y) = (p.x, p.y);
            let inside = x >= 0.0 && y >= 0.0 && x + y <= 3.0;
            let seg = |a: (f64, f64), b: (f64, f64)| {
                let (dx, dy) = (b.0 - a.0, b.1 - a.1);
                let s = (((x - a.0) * dx + (y - a.1) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
                ((x - a.0 - s * dx).powi(2) + (y - a.1 - s * dy).powi(2)).sqrt()
            };
            let flat = if inside {
                0.0
            } else {
                seg((0.0, 0.0), (3.0, 0.0))
                    .min(seg((3.0, 0.0), (0.0, 3.0)))
                    .min(seg((0.0, 3.0), (0.0, 0.0)))
            };
            (flat * flat + p.z * p.z).sqrt()
        };
        let mut fusion_points = 0;
        for p in &e.patches {
            if !e.network.regions[p.region].kind.between() {
                continue;
            }
            for i in 0..=6 {
                for j in 0..=6 {
                    let q = p.coons.eval(i as f64 / 6.0, j as f64 / 6.0);
                    let d = from_triangle(q);
                    assert!((d - 3f64.sqrt()).abs() < 1e-12, "{q}: {d}");
                    fusion_points += 1;
                }
            }
        }
        assert!(fusion_points > 0);
    }
}

/// Four cubes on the corners of a tetrahedron of centres (non-coplanar): six strips, four
/// triangular lids; sound for t from 0.1 to 1, enclosed at t = 1.
#[test]
fn four_cubes_on_a_tetrahedron() {
    for t in [1.0, 0.5, 0.1] {
        let e = build(tetrahedron_of_four(), t);
        assert_eq!(e.straight.len(), 12, "three rays per cube");
        assert_sound(&e, t == 1.0, &format!("t = {t}"));
    }
}

/// A primitive whose centre is not a corner of the centres' hull is swallowed (§5.1.3), and so is
/// one within a tenth of its radius of the others' hull: it is reported and the surface is the
/// one without it.
#[test]
fn swallowed_primitives_are_removed() {
    let mut row = vec![
        cube_at([0.0; 3], [0.0; 3]),
        cube_at([4.0, 0.0, 0.0], [0.0; 3]),
    ];
    let mut inner = l_of_three();
    let mut deep = tetrahedron_of_four();
    let mut long = vec![
        cube_at([0.0; 3], [0.0; 3]),
        cube_at([6.0, 0.0, 0.0], [0.0; 3]),
    ];
    let cases = [
        (&mut row, cube_at([1.5, 0.0, 0.0], [0.0, 0.0, 30.0])),
        (&mut inner, cube_at([1.0, 1.0, 0.0], [10.0, 20.0, 30.0])),
        (&mut deep, cube_at([0.8, 0.9, 1.0], [0.0; 3])),
        // 0.05 off the line: within a tenth of r of the others' hull (a 1.9° sliver of it
        // would be kept, and it folded: 50 of 768 faces inwards).
        (&mut long, cube_at([3.0, 0.05, 0.0], [0.0; 3])),
    ];
    for (without, extra) in cases {
        let bare = build(without.clone(), 0.7);
        let mut with = without.clone();
        with.insert(1, extra);
        let e = build(with, 0.7);
        assert_eq!(e.removed, vec![1]);
        let (a, b) = (bare.tessellate(4).unwrap(), e.tessellate(4).unwrap());
        assert_eq!(a.num_faces(), b.num_faces());
        assert!(hausdorff(&a.positions, &b.positions) < 1e-12);
    }
}

/// Listing the primitives in another order, or a primitive's vertices and faces in another
/// order, gives the same surface — also where regions are cut by diagonals (the bundled scenes
/// at t = 0.1, envelope.md "Diagonals").
#[test]
fn the_listing_order_of_many_does_not_matter() {
    let skew = vec![
        cube_at([0.0; 3], [0.0; 3]),
        cube_at([3.0, 0.5, 0.2], [20.0, 35.0, 10.0]),
        cube_at([0.7, 3.2, 1.1], [5.0, 0.0, 40.0]),
    ];
    let bundled = |text: &str| paper_scene(text).unwrap().primitives;
    for (scene, t) in [
        (l_of_three(), 0.5),
        (tetrahedron_of_four(), 1.0),
        (skew, 1.0),
        (
            bundled(include_str!("../../../assets/table2-seven.envelope.json")),
            0.1,
        ),
        (
            bundled(include_str!("../../../assets/table2-five.envelope.json")),
            0.1,
        ),
        // Patches rescaled where they folded or crossed themselves (envelope.md, "Folded
        // patches: cross derivatives rescaled").
        (
            bundled(include_str!("data/envelope/tiny-side-quad.envelope.json")),
            0.1,
        ),
        (
            bundled(include_str!(
                "data/envelope/short-sides-pentagon.envelope.json"
            )),
            0.1,
        ),
        (
            bundled(include_str!(
                "data/envelope/self-crossing-patches.envelope.json"
            )),
            0.1,
        ),
        // Short legs given back around a fold (envelope.md, "Short legs given back where a
        // patch folds"): the curves chosen do not depend on the listing either.
        (
            bundled(include_str!("data/envelope/folding-heap.envelope.json")),
            0.1,
        ),
        (
            bundled(include_str!(
                "data/envelope/hooked-needle-heap.envelope.json"
            )),
            0.1,
        ),
    ] {
        let one = build(scene.clone(), t).tessellate(4).unwrap();
        let mut turned = scene.clone();
        turned.reverse();
        // Vertices renumbered backwards, faces listed backwards, each from its next corner: the
        // last primitive's, or every one's in the bundled scenes (whose surfaces then agree to
        // 10⁻⁷, rounding; another partition of a region would move it by hundredths).
        let relisted = if t == 0.1 { 0 } else { turned.len() - 1 };
        for p in &mut turned[relisted..] {
            let n = p.vertices.len();
            p.vertices.reverse();
            p.faces.reverse();
            for f in &mut p.faces {
                for v in f.iter_mut() {
                    *v = n - 1 - *v;
                }
                f.rotate_left(1);
            }
            if let Some(vt) = &mut p.vertex_t {
                vt.reverse();
            }
        }
        let two = build(turned, t).tessellate(4).unwrap();
        let h = hausdorff(&one.positions, &two.positions);
        let tol = if t == 0.1 { 1e-6 } else { 1e-9 };
        assert!(h < tol, "{} primitives at t = {t}: {h}", scene.len());
    }
}

/// The bundled scenes like the paper's Table 2 (seven and five primitives of several kinds and
/// sizes) are closed, G1, without a face whose outside is inside and without a folded cell
/// (the stricter patch-by-patch check) at t = 1, 0.7, 0.5, 0.3, 0.2 and 0.1, where the
/// Envelope tab's slider stops — the seven folded in 5 cells at t = 0.1 while hooked edge pieces
/// kept legs of a third of their chord at every t (envelope.md, "Hooked pieces at small t") —
/// and enclose their primitives at t = 1.
#[test]
fn the_bundled_scenes_of_several_are_sound() {
    for (name, text) in [
        (
            "seven",
            include_str!("../../../assets/table2-seven.envelope.json"),
        ),
        (
            "five",
            include_str!("../../../assets/table2-five.envelope.json"),
        ),
    ] {
        let spec: EnvelopeSpec = paper_scene(text).unwrap();
        for t in [1.0, 0.7, 0.5, 0.3, 0.2, 0.1] {
            let e = envelope(&EnvelopeSpec { t, ..spec.clone() }).unwrap();
            assert!(e.removed.is_empty());
            assert_sound(&e, t == 1.0, &format!("{name} at t = {t}"));
            assert_eq!(past_corners(&e), vec![], "{name} at t = {t}");
        }
    }
}

/// Three primitives turned at random (from the scratch stress run) whose fusion quads are
/// thin strips: with fusion edges' legs a third of the chord at every t the strips folded at
/// t = 0.1 (17 cells); with legs shrinking as 2t below ½, like the primitives' edges, no cell
/// folds from t = 1 to 0.1, and the envelope is closed and G1 (envelope.md, "Fusion edges at
/// small t"; at t = 0.1 the winding test still finds two faces whose outside lies inside the
/// solid — its primitives overlap deeply — not looked into yet).
#[test]
fn thin_fusion_strips_do_not_fold_at_small_t() {
    let spec: EnvelopeSpec = paper_scene(include_str!(
        "data/envelope/thin-fusion-strips.envelope.json"
    ))
    .unwrap();
    for t in [1.0, 0.5, 0.3, 0.2, 0.1] {
        fold_free_at(&spec, t);
    }
}

/// `spec` at `t`, asserted to fold nowhere, to be G1 (10⁻⁹°) and to tessellate closed (K = 4).
fn fold_free_at(spec: &EnvelopeSpec, t: f64) -> Envelope {
    let e = envelope(&EnvelopeSpec { t, ..spec.clone() }).unwrap();
    assert_eq!(past_corners(&e), vec![], "t = {t}");
    assert!(e.largest_border_jump() < 1e-9, "t = {t}");
    closed(&e.tessellate(4).unwrap()).unwrap();
    e
}

/// Asserts that no cell of `e`'s patches is turned past its corners' normals sampled at any of
/// `ks` cells a side ([`prism_geom::freeform::envelope::folds::folds_past_corners`], the build's
/// test, stricter than the report's: a step along a border counts); `what` names the case in
/// the message.
fn folds_nowhere(e: &Envelope, ks: &[usize], what: &str) {
    for &k in ks {
        assert_eq!(
            prism_geom::freeform::envelope::folds::folds_past_corners(&e.network, &e.patches, k),
            vec![],
            "{what}, {k} a side"
        );
    }
}

/// Asserts that `e`'s tessellation passes through itself at none of the resolutions `ks` (K
/// quads a patch side); `what` names the case in the message.
fn crosses_nowhere(e: &Envelope, ks: &[usize], what: &str) {
    for &k in ks {
        let m = e.tessellate(k).unwrap();
        assert!(
            prism_geom::freeform::envelope::folds::crossings(&m).is_empty(),
            "{what}, K = {k}"
        );
    }
}

/// Folds are found patch by patch (envelope.md, "Folds, reported"): none on single
/// primitives and pairs for any t from 0.1 to 1, nor on the bundled scenes (the test above),
/// nor at t = 0.5 on a heap of four equal cubes whose cuts leave a thin four-sided region
/// (chords about 0.60, 0.04, 0.61, 0.01), which folded before corners inside a face were drawn
/// to their neighbours' distance (envelope.md, "Corners inside a face"); a heap of three
/// primitives at t = 0.005, below the tab's slider (heap 300059 of the mixed survey), has 3
/// cells turned over on a tetrahedron's face beside its tip (4, 12, 46 cells past their
/// corners' normals at 8, 16, 32 a side), and the warning names where they lie.
/// (The heaps this test showed folding before no longer do: a fusion strip a thousandth wide
/// at t = 0.5, since corners inside a face are drawn together by their distance across it; a
/// heap of six at t = 0.2, since folded patches have their cross derivatives rescaled, and at
/// t = 0.1, since short legs are given back where a patch folds; a heap of three at t = 0.05,
/// since a patch that still folds has its sides run along their curves afresh; a heap of six
/// at t = 0.05 (600332), since the rescaling search also counts the folds at the report's own
/// samples; another at t = 0.05 (600349), since every way to patch a region still folding is
/// tried rescaled; heap 400039 at t = 0.02, whose cells beside a fusion edge only follow the
/// edge's steep tangent plane, since a step along a border is not called a fold:
/// `a_step_along_a_border_is_not_a_fold`; heap 400332 at t = 0.01, since a side's cross
/// derivative may be pushed out further still, `a_side_pushed_further_out_clears_a_fold`, and
/// at t = 0.003, since corners near each other are drawn together,
/// `corners_near_each_other_are_drawn_together`.)
#[test]
fn folds_are_found_patch_by_patch() {
    for text in [
        include_str!("../../../assets/cube.envelope.json"),
        include_str!("../../../assets/hexagonal-prism.envelope.json"),
        include_str!("../../../assets/two-cubes.envelope.json"),
        include_str!("../../../assets/diagonal-cubes.envelope.json"),
    ] {
        let spec: EnvelopeSpec = paper_scene(text).unwrap();
        for t in [1.0, 0.7, 0.5, 0.3, 0.1] {
            let mut s = EnvelopeSpec { t, ..spec.clone() };
            for p in &mut s.primitives {
                p.t = None;
                p.vertex_t = None;
            }
            let e = envelope(&s).unwrap();
            assert_eq!(past_corners(&e), vec![], "t = {t}");
            assert_eq!(e.fold_warning(&[]), None);
        }
    }
    let spec: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/thin-quad-heap.envelope.json")).unwrap();
    assert_eq!(
        envelope(&EnvelopeSpec { t: 0.5, ..spec }).unwrap().folds(),
        vec![]
    );
    let spec: EnvelopeSpec = paper_scene(include_str!(
        "data/envelope/still-folding-heap.envelope.json"
    ))
    .unwrap();
    let e = envelope(&spec).unwrap();
    assert_eq!(spec.t, 0.005);
    let folds = e.folds();
    assert!(!folds.is_empty());
    // Found while building, as the report samples them.
    assert_eq!(
        folds,
        prism_geom::freeform::envelope::folds::folds(&e.network, &e.patches, 8)
    );
    let w = e.fold_warning(&folds).unwrap();
    assert!(w.contains("the first on primitive 2 face 0"), "{w}");
    assert!(
        w.contains(&format!(
            "{} of {} sampled cells fold",
            folds.len(),
            64 * e.patches.len()
        )),
        "{w}"
    );
}

/// A step along a border is not a fold (folds.rs, `follows_its_border`; envelope.md, "Folds,
/// reported", *Steps along a border*). Heap 400039 of the mixed survey at t = 0.02: a fusion
/// strip whose short side, a fusion edge, climbs 0.53 over a chord of 0.57 between corners
/// whose normals are 7° apart, so that along its middle the tangent plane the network
/// prescribes (shared with the patch across) is 91° from the corners' normals. Cells beside
/// it follow that plane and are turned past the corners' normals, which the build's test
/// counts (and the build tries to repair); the report does not: each of them lies within 10° of
/// the plane along the side at its foot and within 10° of its neighbours, where a cell turned
/// over differs from a neighbour by 130–160° (heap 400332 at t = 0.003 before session 48,
/// `folds_are_found_patch_by_patch`). Nothing folds at 8, 16 or 32 a side as the report
/// samples, and the tessellation crosses itself nowhere at K = 8 or 16.
#[test]
fn a_step_along_a_border_is_not_a_fold() {
    use prism_geom::freeform::envelope::folds::folds_past_corners;
    let spec: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/step-heap.envelope.json")).unwrap();
    assert_eq!(spec.t, 0.02);
    let e = envelope(&spec).unwrap();
    assert_eq!(e.folds(), vec![]);
    for k in [8, 16, 32] {
        assert_eq!(
            prism_geom::freeform::envelope::folds::folds(&e.network, &e.patches, k),
            vec![],
            "{k} a side"
        );
    }
    crosses_nowhere(&e, &[8, 16], "the step heap");
    for k in [8, 16] {
        let past = folds_past_corners(&e.network, &e.patches, k);
        assert!(!past.is_empty(), "k = {k}");
        for f in past {
            let p = &e.patches[f.patch];
            let g = p.coons.grid(k);
            let (i, j) = ((f.u * k as f64) as usize, (f.v * k as f64) as usize);
            let normal = |i: usize, j: usize| {
                let at = |i: usize, j: usize| g[i + (k + 1) * j];
                let du = at(i + 1, j) - at(i, j) + at(i + 1, j + 1) - at(i, j + 1);
                let dv = at(i, j + 1) - at(i, j) + at(i + 1, j + 1) - at(i + 1, j);
                du.cross(dv)
            };
            // The nearest side and the foot's parameter along it.
            let (_, side, s) = [
                (f.v, 0, f.u),
                (1.0 - f.u, 1, f.v),
                (1.0 - f.v, 2, 1.0 - f.u),
                (f.u, 3, 1.0 - f.v),
            ]
            .into_iter()
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .unwrap();
            let side = &p.coons.sides[side];
            let plane = side.d1(s).cross(side.cross(s).0);
            let n = normal(i, j);
            assert!(n.angle_between(plane).to_degrees() < 10.0, "k = {k}: {f:?}");
            for (di, dj) in [(-1i64, 0i64), (1, 0), (0, -1), (0, 1)] {
                let (a, b) = (i as i64 + di, j as i64 + dj);
                if (0..k as i64).contains(&a) && (0..k as i64).contains(&b) {
                    let m = normal(a as usize, b as usize);
                    assert!(n.angle_between(m).to_degrees() < 10.0, "k = {k}: {f:?}");
                }
            }
        }
    }
}

/// Heap 500086 of the mixed survey at t = 0.01, below the slider: a patch still folded between
/// the report's samples (5 cells at 32 a side as the report counts them) after every scale of
/// its sides' cross derivatives and every run along their curves. The search then also leans a
/// side's cross derivative across it (`μ(s)·g(s)`, zero at both corners: the fits and G1 hold;
/// envelope.md, "Folded patches: cross derivatives rescaled", *Leaned across*), which clears
/// it at 8, 16 and 32 a side; every lean kept leaves the part across its side pointing the way
/// it did. (Until session 47 the test held heap 500291, whose fold at the report's samples a
/// lean cleared; a side pushed out further still clears it better now.)
#[test]
fn a_side_leaned_across_clears_a_fold() {
    use prism_geom::freeform::envelope::folds::folds;
    let spec: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/leaned-side-heap.envelope.json")).unwrap();
    assert_eq!(spec.t, 0.01);
    let e = envelope(&spec).unwrap();
    for k in [8, 16, 32] {
        assert_eq!(folds(&e.network, &e.patches, k), vec![], "k = {k}");
    }
    assert!(e.largest_border_jump() < 1e-9);
    let leaned: Vec<_> = e
        .patches
        .iter()
        .flat_map(|p| &p.coons.sides)
        .filter(|s| s.lean != (0.0, 0.0))
        .collect();
    assert!(!leaned.is_empty());
    assert!(leaned.iter().all(|s| s.lean_keeps_its_side()));
}

/// The narrowest angle (degrees) between the insertion curves leaving any one inserted point
/// of `e`, seen along its normal (the points where three or more insertion curves start).
fn narrowest_at_inserted_points(e: &Envelope) -> f64 {
    use prism_geom::freeform::envelope::CurveKind;
    let net = &e.network;
    let mut leaving: std::collections::BTreeMap<usize, Vec<DVec3>> = Default::default();
    for c in &net.curves {
        if c.kind == CurveKind::Insertion && c.ends[0] != c.ends[1] {
            leaving
                .entry(c.ends[0])
                .or_default()
                .push(c.bezier.derivatives(0.0).d1);
        }
    }
    let mut least = 360.0f64;
    for (v, dirs) in leaving.into_iter().filter(|(_, d)| d.len() >= 3) {
        let n = net.vertices[v].normal;
        let e0 = (dirs[0] - dirs[0].dot(n) * n).normalize();
        let e1 = n.cross(e0);
        let mut a: Vec<f64> = dirs
            .iter()
            .map(|d| d.dot(e1).atan2(d.dot(e0)).to_degrees().rem_euclid(360.0))
            .collect();
        a.sort_by(f64::total_cmp);
        for k in 0..a.len() {
            let next = if k + 1 < a.len() {
                a[k + 1]
            } else {
                a[0] + 360.0
            };
            least = least.min(next - a[k]);
        }
    }
    least
}

/// Legs at P_i apart (envelope.md, "Legs at P_i apart"): heap 400035 of the mixed survey at
/// t = 0.7, on the slider, a six-sided region of primitive 1's face 6 split round an inserted
/// point whose insertion curves to two neighbouring silhouette sides left it 0.3° apart (their
/// P_d 42° apart; one's cross derivative there lay nearly in P_i's tangent plane and drew the
/// leg sideways). The sub-quad between them had a corner of 0.4° and folded between the
/// report's samples (3 cells at 32 a side, 23 at 64). Now every leg points at its P_d there:
/// no insertion curves leave an inserted point under 5° apart, and nothing folds at 8, 16, 32
/// or 64 a side. The bundled seven at t = 1 had two 0.19° apart (no fold at up to 128 a side);
/// they are apart now too.
#[test]
fn legs_at_an_inserted_point_leave_apart() {
    use prism_geom::freeform::envelope::folds::folds_past_corners;
    let heap: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/cusp-heap.envelope.json")).unwrap();
    assert_eq!(heap.t, 0.7);
    let seven: EnvelopeSpec =
        paper_scene(include_str!("../../../assets/table2-seven.envelope.json")).unwrap();
    for (spec, t, ks) in [
        (heap, 0.7, &[8, 16, 32, 64][..]),
        (seven, 1.0, &[8, 16, 32][..]),
    ] {
        let e = envelope(&EnvelopeSpec { t, ..spec }).unwrap();
        let least = narrowest_at_inserted_points(&e);
        assert!(least >= 5.0 - 1e-9, "t = {t}: {least}°");
        for &k in ks {
            assert_eq!(
                folds_past_corners(&e.network, &e.patches, k),
                vec![],
                "t = {t}, k = {k}"
            );
        }
        assert!(e.largest_border_jump() < 1e-9);
    }
}

/// Heap 600094 of the mixed survey at t = 0.01, below the slider: a patch of primitive 1's
/// face 4 between two rational edges of weights under 0.01 (sides 1.71, 0.38, 0.61, 0.78)
/// still folds at the report's samples after every scale down to β = −4, every run along its
/// curves and every lean. The last pass also pushes a side's cross derivative out to β = −8
/// and −16 (envelope.md, "Folded patches: cross derivatives rescaled", *Pushed out further
/// still*), which clears it there (its side of 0.78 pushed to −16); σ stays 1 at the corners
/// and positive, so the fits and G1 hold. (The heap this test held first, 500287, has nothing
/// left to push since session 48: its sliver of 0.0166 is drawn into one corner, envelope.md,
/// "Corners drawn together".)
#[test]
fn a_side_pushed_further_out_clears_a_fold() {
    let spec: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/pushed-side-heap.envelope.json")).unwrap();
    assert_eq!(spec.t, 0.01);
    let e = fold_free_at(&spec, spec.t);
    assert!(
        e.patches
            .iter()
            .flat_map(|p| &p.coons.sides)
            .any(|s| s.squeeze < -4.0)
    );
}

/// Corners drawn together (envelope.md, "Corners drawn together"): the last four of 1,800
/// mixed heaps that folded or passed through themselves below the slider each had a sliver
/// side in the network — heaps 600001 and 600002 at t = 0.02 a silhouette piece 0.0009 and
/// 0.0045 long between an edge's cut point and a ray (600001's fusion strip over it 2.85 long,
/// its two long sides lying on each other: 47, 92, 166 pairs crossing at K = 8, 16, 32; 600002
/// 16, 30, 66), 500174 at t = 0.01 an edge piece 0.007 long where a cut passed that close to a
/// vertex and a face piece 0.003 across (1, 8, 41 cells turned past their corners at 8, 16, 32
/// a side), 600175 at t = 0.01 the 0.018 base of a needle (15, 55, 199 cells; 33, 57, 137
/// pairs). With the corners drawn onto their neighbours no network curve is shorter than 0.02,
/// and whichever way the primitives are listed, nothing folds at 8, 16 or 32 cells a side or
/// passes through itself at K = 8, 16 or 32, and the borders stay G1.
#[test]
fn corners_near_each_other_are_drawn_together() {
    use prism_geom::freeform::envelope::CurveKind;
    for (text, t) in [
        (
            include_str!("data/envelope/drawn-ray-strip-heap.envelope.json"),
            0.02,
        ),
        (
            include_str!("data/envelope/drawn-ray-strip-heap-2.envelope.json"),
            0.02,
        ),
        (
            include_str!("data/envelope/drawn-vertex-heap.envelope.json"),
            0.01,
        ),
        (
            include_str!("data/envelope/drawn-needle-heap.envelope.json"),
            0.01,
        ),
    ] {
        let spec: EnvelopeSpec = paper_scene(text).unwrap();
        assert_eq!(spec.t, t);
        for e in unfolded_both_ways(&spec.primitives, t) {
            let shortest = e
                .network
                .curves
                .iter()
                .filter(|c| c.kind != CurveKind::Insertion && !c.is_point())
                .map(|c| c.bezier.eval(0.0).distance(c.bezier.eval(1.0)))
                .fold(f64::INFINITY, f64::min);
            assert!(shortest > 0.02, "t = {t}: {shortest}");
            assert_eq!(e.folds(), vec![], "t = {t}");
            folds_nowhere(&e, &[8, 16, 32], &format!("t = {t}"));
            crosses_nowhere(&e, &[8, 16, 32], &format!("t = {t}"));
            assert!(e.largest_border_jump() < 1e-9, "t = {t}");
        }
    }
}

/// The build's check of corners drawn together (envelope.md, "Corners drawn together"): heap
/// 500308 of the mixed survey at t = 0.01 draws two edge points onto a vertex, and a patch of
/// the five-sided region at that vertex then turned back along a fifth of a border (normal jump
/// 180°, 75 patches). The regions at a drawn corner are checked for G1, and the scene is built
/// as it lies: 91 patches, G1 across every border, and nothing folds or crosses itself.
#[test]
fn a_drawn_network_that_is_not_g1_is_built_as_it_lies() {
    let spec: EnvelopeSpec = paper_scene(include_str!(
        "data/envelope/drawn-not-g1-heap.envelope.json"
    ))
    .unwrap();
    assert_eq!(spec.t, 0.01);
    let e = envelope(&spec).unwrap();
    assert_eq!(e.patches.len(), 91);
    assert!(
        e.largest_border_jump() < 1e-6,
        "{}",
        e.largest_border_jump()
    );
    assert_eq!(e.folds(), vec![]);
    crosses_nowhere(&e, &[8, 16], "heap 500308");
}

/// Short legs given back where a patch folds (`legs.rs`, envelope.md, "Short legs given back
/// where a patch folds"): the two heaps of the mixed survey that still folded on the tab's
/// slider. A heap of six (600182, turned by 180° about the vertical) whose narrow lid between
/// three primitives folded in 7 cells from t = 0.1 to 0.18, its base a fusion edge with legs
/// of 2t thirds of its chord that climbs 0.62 over 0.67; and a heap of four (400167) whose
/// needle on a primitive's face, beside a hooked edge piece, folded in 2 cells at t = 0.1. Now
/// neither folds (at 8, 16 or 32 cells a side) nor crosses itself at K = 8, 16 or 32 (the lid
/// crossed itself at 24 and 32),
/// the borders stay G1, and the lid's fusion edges have legs of at least half a third of their
/// chord where the others keep 2t thirds. (The needle is cleared before that since session 42:
/// its patch, still folding after the rescaling search, has its sides run along their curves,
/// envelope.md, "Sides run along their curves". The lid at t = 0.1 clears at the report's samples
/// with the rescaling alone since session 45, whose search pushes a side out to β = −4, but
/// still folds between them (13 cells at 16 a side in the survey's heap, not turned): legs are
/// given back for that too.)
#[test]
fn short_legs_are_given_back_where_a_patch_folds() {
    use prism_geom::freeform::envelope::CurveKind;
    for (text, ts) in [
        (
            include_str!("data/envelope/folding-heap.envelope.json"),
            &[0.1, 0.12, 0.14, 0.16, 0.18][..],
        ),
        (
            include_str!("data/envelope/hooked-needle-heap.envelope.json"),
            &[0.1][..],
        ),
    ] {
        let spec: EnvelopeSpec = paper_scene(text).unwrap();
        for &t in ts {
            let e = envelope(&EnvelopeSpec { t, ..spec.clone() }).unwrap();
            assert_eq!(past_corners(&e), vec![], "t = {t}");
            assert!(e.largest_border_jump() < 1e-6, "t = {t}");
            crosses_nowhere(&e, &[8, 16, 32], &format!("t = {t}"));
            folds_nowhere(&e, &[8, 16, 32], &format!("t = {t}"));
            // Some fusion edges or rebuilt edge pieces (polynomial cubics with legs of 2t thirds
            // of their chord) now have longer legs.
            let long = e
                .network
                .curves
                .iter()
                .filter(|c| matches!(c.kind, CurveKind::Fusion | CurveKind::Edge))
                .filter(|c| c.bezier.weights.iter().all(|&w| w == 1.0))
                .filter(|c| {
                    let p = &c.bezier.points;
                    let third = p[0].distance(p[3]) / 3.0;
                    p[0].distance(p[1]) >= 0.5 * third - 1e-12
                        && p[0].distance(p[1]) > 2.0 * t * third + 1e-9
                })
                .count();
            let run = e
                .patches
                .iter()
                .filter(|p| p.coons.sides.iter().any(|s| s.reparam.is_some()))
                .count();
            assert!(long > 0 || run > 0, "t = {t}");
        }
    }
}

/// Equal axis-aligned cubes at random centres (seed 004 fig. 12): every scene of 2 to 5
/// builds closed; the regions (faces of the curve network) stay within 1.75 × the cubes'
/// faces (the paper reports about 1.6 ×; docs/algorithms/envelope.md gives the spread).
#[test]
fn random_cubes_build_closed_with_few_regions() {
    let mut rng = Lcg(4);
    for count in 2..=5 {
        let mut worst = 0.0f64;
        for _ in 0..60 {
            let e = build(random_cubes(&mut rng, count, 4.0), 1.0);
            worst = worst.max(e.regions as f64 / (6 * count) as f64);
            let m = e.tessellate(2).unwrap();
            closed(&m).unwrap();
        }
        assert!(worst <= 1.75, "{count} cubes: {worst}");
    }
}

/// An ignored survey: regions, patches, G1, closedness, folds and enclosure of the scenes.
#[test]
#[ignore]
fn survey() {
    let scenes: Vec<(&str, Vec<PrimitiveInput>)> = vec![
        (
            "L of three",
            vec![
                cube_at([0.0; 3], [0.0; 3]),
                cube_at([3.0, 0.0, 0.0], [0.0; 3]),
                cube_at([0.0, 3.0, 0.0], [0.0; 3]),
            ],
        ),
        (
            "tetrahedron of four",
            vec![
                cube_at([0.0; 3], [0.0; 3]),
                cube_at([4.0, 0.0, 0.0], [0.0; 3]),
                cube_at([0.0, 4.0, 0.0], [0.0; 3]),
                cube_at([0.0, 0.0, 4.0], [0.0; 3]),
            ],
        ),
        (
            "skew three",
            vec![
                cube_at([0.0; 3], [0.0; 3]),
                cube_at([3.0, 0.5, 0.2], [20.0, 35.0, 10.0]),
                cube_at([0.7, 3.2, 1.1], [5.0, 0.0, 40.0]),
            ],
        ),
    ];
    let mut scenes = scenes;
    for off in [0.05, 0.2, 0.5, 1.0] {
        scenes.push((
            "near row",
            vec![
                cube_at([0.0; 3], [0.0; 3]),
                cube_at([3.0, off, 0.0], [0.0; 3]),
                cube_at([6.0, 0.0, 0.0], [0.0; 3]),
            ],
        ));
    }
    for (name, text) in [
        (
            "table2-seven",
            include_str!("../../../assets/table2-seven.envelope.json"),
        ),
        (
            "table2-five",
            include_str!("../../../assets/table2-five.envelope.json"),
        ),
    ] {
        let s: EnvelopeSpec = paper_scene(text).unwrap();
        scenes.push((name, s.primitives));
    }
    for (name, prims) in scenes {
        for t in [1.0, 0.5, 0.1] {
            match envelope(&spec(prims.clone(), t)) {
                Err(e) => println!("{name} t={t}: error {e}"),
                Ok(e) => {
                    let m = e.tessellate(4).unwrap();
                    let inside = samples(&e)
                        .iter()
                        .filter(|q| winding(&m, **q) < 0.5)
                        .count();
                    println!(
                        "{name} t={t}: regions {} patches {} removed {:?} jump {:.2e} closed {:?} inward {} of {} outside samples {}",
                        e.regions,
                        e.patches.len(),
                        e.removed,
                        e.largest_border_jump(),
                        closed(&m),
                        inward_faces(&m),
                        m.num_faces(),
                        inside
                    );
                }
            }
        }
    }
}

/// A fixed pseudo-random sequence in [0, 1).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `count` equal axis-aligned cubes (half-size 1) with centres uniform in [0, 4]³.
fn random_cubes(rng: &mut Lcg, count: usize, spread: f64) -> Vec<PrimitiveInput> {
    (0..count)
        .map(|_| {
            cube_at(
                [
                    spread * rng.next(),
                    spread * rng.next(),
                    spread * rng.next(),
                ],
                [0.0; 3],
            )
        })
        .collect()
}

/// `count` equal axis-aligned cubes (half-size 1) that do not overlap one another, centres
/// uniform in [0, 6]³ (heaps with two cubes closer than 2 on every axis drawn again).
fn apart_cubes(rng: &mut Lcg, count: usize) -> Vec<PrimitiveInput> {
    loop {
        let c: Vec<[f64; 3]> = (0..count)
            .map(|_| [6.0 * rng.next(), 6.0 * rng.next(), 6.0 * rng.next()])
            .collect();
        let apart = |a: &[f64; 3], b: &[f64; 3]| (0..3).any(|k| (a[k] - b[k]).abs() >= 2.0);
        if (0..count).all(|i| (0..i).all(|j| apart(&c[i], &c[j]))) {
            return c.iter().map(|&p| cube_at(p, [0.0; 3])).collect();
        }
    }
}

/// Regions, closedness, folds and G1 of equal cubes at random centres (docs/algorithms/
/// envelope.md, "Regions against the cubes' faces"); `APART=1`: cubes that do not overlap;
/// `TS` the t values (default "1,0.5"). Each scene with a face inward by the winding test, a
/// folded cell or a tessellation that is not closed is printed (the winding test's with its
/// crossings at K = 8) and, when `DUMP` names a folder, written there as `inward-…`, `folded-…`
/// or `open-COUNT-SCENE-T.envelope.json`.
#[test]
#[ignore]
fn survey_random() {
    let mut rng = Lcg(4);
    let apart = std::env::var("APART").is_ok();
    let ts: Vec<f64> = std::env::var("TS").map_or(vec![1.0, 0.5], |v| {
        v.split(',').map(|x| x.parse().unwrap()).collect()
    });
    for count in 2..=5 {
        let (mut worst, mut bad, mut errors, mut folds, mut jumps) = (0.0f64, 0, 0, 0, 0);
        let mut folds_at_1 = 0;
        // Scenes above the paper's 1.6 × the cubes' faces at t = 1.
        let mut over = 0;
        // Scenes with a folded cell ([`Envelope::folds`]: stricter than the winding test).
        let (mut cells, mut cells_at_1) = (0, 0);
        for scene in 0..100 {
            let spread: f64 = std::env::var("SPREAD").map_or(4.0, |v| v.parse().unwrap());
            let prims = if apart {
                apart_cubes(&mut rng, count)
            } else {
                random_cubes(&mut rng, count, spread)
            };
            // The scene, written into the folder DUMP when set.
            let dump = |what: &str, t: f64| {
                if let Ok(dir) = std::env::var("DUMP") {
                    let path = format!("{dir}/{what}-{count}-{scene}-{t}.envelope.json");
                    let text = serde_json::to_string_pretty(&spec(prims.clone(), t)).unwrap();
                    std::fs::write(&path, text).unwrap();
                }
            };
            for &t in &ts {
                match envelope(&spec(prims.clone(), t)) {
                    Err(e) => {
                        errors += 1;
                        println!("error {e}");
                    }
                    Ok(e) => {
                        let ratio = e.regions as f64 / (6 * count) as f64;
                        worst = worst.max(ratio);
                        over += usize::from(t == 1.0 && ratio > 1.6);
                        let m = e.tessellate(3).unwrap();
                        if let Err(why) = closed(&m) {
                            bad += 1;
                            println!("{count} cubes, t = {t}, scene {scene}: open at K = 3: {why}");
                            dump("open", t);
                        }
                        let inward = inward_faces(&m);
                        if inward > 0 {
                            let crossing = prism_geom::freeform::envelope::folds::crossings(
                                &e.tessellate(8).unwrap(),
                            );
                            println!(
                                "{count} cubes, t = {t}, scene {scene}: {inward} of {} faces inward at K = 3, {} crossing pairs at K = 8",
                                m.num_faces(),
                                crossing.len()
                            );
                            dump("inward", t);
                            folds += 1;
                            if t == 1.0 {
                                folds_at_1 += 1;
                            }
                        }
                        let fl = e.folds();
                        if !fl.is_empty() {
                            println!(
                                "{count} cubes, t = {t}, scene {scene}: {}",
                                e.fold_warning(&fl).unwrap_or_default()
                            );
                            dump("folded", t);
                            cells += 1;
                            if t == 1.0 {
                                cells_at_1 += 1;
                            }
                        }
                        if e.largest_border_jump() > 1e-3 {
                            jumps += 1;
                        }
                    }
                }
            }
        }
        println!(
            "{count} cubes: worst regions/faces {worst:.3} ({over} of 100 above 1.6 at t = 1), errors {errors}, open {bad}, folded {folds} ({folds_at_1} at t = 1), a folded cell {cells} ({cells_at_1} at t = 1), G1 broken {jumps} of {}",
            100 * ts.len()
        );
    }
}

/// Cells of the primitives' parts that face their primitive's centre, sampled 16 × 16.
fn cells_facing_the_centre(e: &Envelope) -> usize {
    let k = 16;
    let mut n = 0;
    for p in &e.patches {
        let RegionKind::Primitive { primitive, .. } = e.network.regions[p.region].kind else {
            continue;
        };
        let centre = e.primitives[primitive].centre;
        let g = p.coons.grid(k);
        let at = |i: usize, j: usize| g[i + (k + 1) * j];
        for j in 0..k {
            for i in 0..k {
                let normal = (at(i + 1, j + 1) - at(i, j)).cross(at(i, j + 1) - at(i + 1, j));
                let c = 0.25 * (at(i, j) + at(i + 1, j) + at(i, j + 1) + at(i + 1, j + 1));
                if normal.dot(c - centre) <= 0.0 {
                    n += 1;
                }
            }
        }
    }
    n
}

/// A grazing cut leaves a thin triangle on a cube face (sides 0.64, 0.65 and 0.066 on the
/// middle cube here): split at its sides' middles, its quads turned cells towards the cube's
/// centre at t = 1; split at the feet of its incentre with square insertion curves
/// (envelope.md, "Three-sided regions"), none does, and the patch check finds no fold.
#[test]
fn a_thin_triangle_is_split_at_the_feet_of_its_incentre() {
    let e = build(
        vec![
            cube_at([0.565348333199, 2.073710053444, 1.201416233653], [0.0; 3]),
            cube_at([3.721235812321, 2.747735118965, 1.868713682061], [0.0; 3]),
            cube_at([2.314143065356, 1.279304673443, 1.695121210114], [0.0; 3]),
        ],
        1.0,
    );
    assert!(
        e.network
            .regions
            .iter()
            .any(|r| r.sides.len() == 3 && matches!(r.kind, RegionKind::Primitive { .. }))
    );
    assert_eq!(cells_facing_the_centre(&e), 0);
    assert_eq!(past_corners(&e), vec![]);
}

/// Two cubes whose cut leaves each a triangle of 2.08 × 2.15 × 0.15 with a 4.6° corner:
/// split at the feet of the inserted point alone, the quad at the 4.6° corner folded (14
/// cells at t = 1, 32 at 0.7); with the incentre's feet and square insertion curves no cell
/// of those needles folds from t = 1 to 0.3, nor any cell of the scene at t = 1, 0.7 and 0.3,
/// and none faces its cube's centre at t = 1 and 0.7 (at 0.5 triangles 0.05 across
/// and a pentagon's sliver still fold: envelope.md, "Left").
#[test]
fn a_needle_triangle_does_not_fold() {
    let prims = vec![
        cube_at([1.353, 3.941, 3.292], [0.0; 3]),
        cube_at([1.669, 0.472, 0.121], [0.0; 3]),
    ];
    for t in [1.0, 0.7, 0.5, 0.3] {
        let e = build(prims.clone(), t);
        let needles: Vec<usize> = (0..e.network.regions.len())
            .filter(|&r| {
                let len = chords(&e, r);
                len.len() == 3
                    && len.iter().cloned().fold(f64::INFINITY, f64::min) < 0.2
                    && len.iter().cloned().fold(0.0, f64::max) > 2.0
            })
            .collect();
        assert_eq!(needles.len(), 2, "t = {t}");
        let folds = e.folds();
        assert!(
            folds.iter().all(|f| !needles.contains(&f.region)),
            "t = {t}: {folds:?}"
        );
        if [1.0, 0.7, 0.3].contains(&t) {
            assert_eq!(folds, vec![], "t = {t}");
        }
        if t >= 0.7 {
            assert_eq!(cells_facing_the_centre(&e), 0, "t = {t}");
        }
    }
}

/// Random pairs of equal axis-aligned cubes (the survey's first hundred): no sampled cell folds
/// at t = 1, 0.5 or 0.1 (1 and 17 of the hundred folded at t = 1 and 0.5 before the inserted
/// point followed the virtual edges, nearly hooked pieces were replaced and short sides took
/// their own cross derivative; 8 at t = 0.1 while hooked edge pieces kept legs of a third of
/// their chord: envelope.md, "Hooked pieces at small t"), and every envelope is G1.
#[test]
fn random_pairs_do_not_fold() {
    for scene in 0..100 {
        heap_does_not_fold(2, scene, &[1.0, 0.5, 0.1]);
    }
}

/// Random triples of equal axis-aligned cubes (the survey's second hundred, after its hundred
/// pairs): no sampled cell folds at t = 1 or 0.5, and every envelope is G1. Two of them folded
/// at both t before thin pentagons were split as strips (envelope.md, "Runs of short sides"),
/// two more at t = 0.5 before nearly hooked edge pieces took the section-tangent cubic.
#[test]
fn random_triples_do_not_fold() {
    for scene in 0..100 {
        heap_does_not_fold(3, scene, &[1.0, 0.5]);
    }
}

/// The survey's heap `scene` (0–99) of `count` (2–5) cubes: [`survey_random`] draws 100 heaps
/// of each count in turn from `Lcg(4)`.
fn survey_heap(count: usize, scene: usize) -> Vec<PrimitiveInput> {
    let mut rng = Lcg(4);
    for c in 2..count {
        for _ in 0..100 {
            random_cubes(&mut rng, c, 4.0);
        }
    }
    for _ in 0..scene {
        random_cubes(&mut rng, count, 4.0);
    }
    random_cubes(&mut rng, count, 4.0)
}

/// No sampled cell of the survey's heap folds at any of `ts`, and its envelope is G1.
fn heap_does_not_fold(count: usize, scene: usize, ts: &[f64]) {
    let prims = survey_heap(count, scene);
    for &t in ts {
        let e = build(prims.clone(), t);
        assert_eq!(
            past_corners(&e),
            vec![],
            "{count} cubes, scene {scene}, t = {t}"
        );
        assert!(
            e.largest_border_jump() < 1e-9,
            "{count} cubes, scene {scene}, t = {t}: {}",
            e.largest_border_jump()
        );
    }
}

/// The chords of region `r`'s sides.
fn chords(e: &Envelope, r: usize) -> Vec<f64> {
    e.network.regions[r]
        .sides
        .iter()
        .map(|s| {
            let c = &e.network.curves[s.curve].bezier;
            c.eval(s.t0).distance(c.eval(s.t1))
        })
        .collect()
}

/// A cube face cut down to a thin strip along one of its edges: a pentagon with chords about
/// 2.00, 0.15, 2.01, 0.32 and 0.03 long. Split round one inserted point, its sub-quads at the
/// short sides have corners of a few degrees there, and 33 cells folded at t = 1. Split as a
/// strip (a four-sided patch between the long sides, the two short sides at one end closed by
/// a curve across into a triangle) nothing folds; at t = 0.5 and 0.4, where the split round a
/// point does not fold (at 0.5 it did, 4 cells, before corners inside a face were drawn to
/// their neighbours' distance) and the strip's triangle would, the region keeps the paper's
/// split.
/// The surface stays G1 throughout.
#[test]
fn a_thin_pentagon_is_split_as_a_strip() {
    let prims = vec![
        cube_at([3.93, 1.54, 2.34], [0.0; 3]),
        cube_at([1.76, 2.27, 0.84], [0.0; 3]),
        cube_at([1.58, 3.31, 2.31], [0.0; 3]),
    ];
    for t in [1.0, 0.5, 0.4] {
        let e = build(prims.clone(), t);
        let slivers: Vec<usize> = (0..e.network.regions.len())
            .filter(|&r| {
                let len = chords(&e, r);
                len.len() == 5
                    && len.iter().filter(|&&l| l > 1.9).count() == 2
                    && len.iter().filter(|&&l| l < 0.4).count() == 3
            })
            .collect();
        assert_eq!(slivers.len(), 1, "t = {t}");
        // The strip and the triangle's three quads, or five quads round a point.
        let patches = e.patches.iter().filter(|p| p.region == slivers[0]).count();
        assert_eq!(patches, if t < 1.0 { 5 } else { 4 }, "t = {t}");
        assert_eq!(past_corners(&e), vec![], "t = {t}");
        assert!(e.largest_border_jump() < 1e-9, "t = {t}");
    }
}

/// Corners inside a face (envelope.md, "Corners inside a face"): every short silhouette side
/// on a primitive (under 3 % of r) has its ends at nearly one distance from the primitive's
/// centre (they differ by under a fifth of its chord; at most 0.09 here): the normals there
/// run along the radii, so two such corners a few thousandths apart at distances as far
/// apart as that fold the patches between them.
/// A cut crossing a face nearly along one of its edges (four primitives: a triangle of chords
/// 0.55, 0.016, 0.55 on a box) put its corner 0.014 further out than the silhouette point
/// 0.016 away on the edge (24 cells folded at t = 0.5, 64 pairs crossing); three cuts crossing
/// a face nearly at one point (five primitives) put two corners 0.004 apart at distances 0.004
/// apart (42 cells at t = 0.5, 38 pairs). Both now lie as far out as their neighbours, and
/// nothing folds or crosses from t = 1 to 0.1, whatever the listing (the second folded one
/// cell at 0.1 on a four-sided region that is nearly a triangle, sides 0.51, 1.20, 0.0004,
/// 1.37, until such regions were tried split: the test below). Corners are drawn together
/// by how far apart they lie across the face, not by their located distance: where the
/// rays of two cuts nearly coincide (heap 600151 of the mixed survey, six primitives, two
/// hull facets 0.06° from one plane) two corners 0.0013 apart across a prism's face were
/// located 0.027 apart along their radii, so they counted as far apart and stayed 0.0047
/// apart, and the fusion strip between them, 3.9 long, folded at t = 0.5, 0.2 and 0.1.
/// A corner is drawn only by corners near it: among five equal cubes placed apart, one cut
/// crosses a cube's face 6 × 10⁻⁵ from where another crosses its edge, and a corner 1.2 away
/// on that face pulled the first 0.0006 in from the edge's silhouette point — the whole
/// length of the short side between them, so the fusion strip over it (4.18 long,
/// 0.0001–0.0006 wide) stood on edge and folded 6 and 10 cells at t = 0.2 and 0.1. Since
/// session 48 that corner and the silhouette point are one network vertex (corners drawn
/// together, envelope.md, "Corners drawn together"), so that scene has no short side left.
#[test]
fn corners_inside_a_face_lie_as_far_out_as_their_neighbours() {
    use prism_geom::freeform::envelope::CurveKind;
    for (text, ts, with_short_sides) in [
        (
            include_str!("data/envelope/inside-corner-near-edge.envelope.json"),
            &[1.0, 0.5, 0.2, 0.1][..],
            true,
        ),
        (
            include_str!("data/envelope/three-cuts-near-a-point.envelope.json"),
            &[1.0, 0.5, 0.2, 0.1][..],
            true,
        ),
        (
            include_str!("data/envelope/cuts-at-nearly-one-ray.envelope.json"),
            &[1.0, 0.5, 0.2, 0.1][..],
            true,
        ),
        (
            include_str!("data/envelope/corner-drawn-by-a-far-one.envelope.json"),
            &[1.0, 0.5, 0.2, 0.1][..],
            false,
        ),
    ] {
        let spec: EnvelopeSpec = paper_scene(text).unwrap();
        for &t in ts {
            for e in unfolded_both_ways(&spec.primitives, t) {
                let mut short = 0;
                for r in &e.network.regions {
                    let RegionKind::Primitive { primitive, .. } = r.kind else {
                        continue;
                    };
                    let p = &e.primitives[primitive];
                    for s in &r.sides {
                        let c = &e.network.curves[s.curve];
                        let (a, b) = (c.bezier.eval(0.0), c.bezier.eval(1.0));
                        let chord = a.distance(b);
                        if c.kind == CurveKind::Silhouette && chord < 0.03 * p.radius {
                            short += 1;
                            let step = (a.distance(p.centre) - b.distance(p.centre)).abs();
                            assert!(step < 0.2 * chord, "t = {t}: {step} over {chord}");
                        }
                    }
                }
                assert_eq!(short > 0, with_short_sides, "t = {t}");
            }
        }
    }
}

/// Four-sided regions with a short side (envelope.md, "Four-sided regions with a short
/// side"): where such a region folds as one Coons patch it is split round an inserted point as
/// one of any other n is. Five primitives whose cuts cross a prism's face nearly at one point
/// leave a region of chords 0.51, 1.20, 0.0004, 1.37 there (two rays 0.0004 apart, which stay
/// apart), split into four patches at t = 0.1; from t = 1 to 0.1 nothing folds or crosses and
/// the surface stays G1, whatever the listing. Two scenes that held such regions before
/// session 48 hold none with a side under 0.5 % of its longest now that the corners at their
/// short side are drawn together (envelope.md, "Corners drawn together"): a cut passing 0.002
/// from a cube's vertex (a quad of chords 0.0034, 1.04, 0.73, 1.30, which folded 2 cells at t =
/// 0.1 as one patch) and five primitives' cuts leaving a sliver of chords 0.51, 0.60, 0.017,
/// 0.23 on a prism's face (3 cells at t = 0.5), now a triangle.
#[test]
fn four_sided_regions_with_a_short_side_split_where_they_fold() {
    // (scene, the t where its region folded as one patch, or the face whose short side is
    // drawn away: primitive, face).
    for (text, folded_at, drawn) in [
        (
            include_str!("data/envelope/cut-near-a-vertex.envelope.json"),
            None,
            Some((0, 3)),
        ),
        (
            include_str!("data/envelope/prism-face-sliver.envelope.json"),
            None,
            Some((4, 3)),
        ),
        (
            include_str!("data/envelope/three-cuts-near-a-point.envelope.json"),
            Some(0.1),
            None,
        ),
    ] {
        let spec: EnvelopeSpec = paper_scene(text).unwrap();
        for t in [1.0, 0.5, 0.2, 0.1] {
            for (way, e) in unfolded_both_ways(&spec.primitives, t).iter().enumerate() {
                assert!(e.largest_border_jump() < 1e-9, "t = {t}");
                let with_short_side: Vec<usize> = (0..e.network.regions.len())
                    .filter(|&r| {
                        let len = chords(e, r);
                        let longest = len.iter().cloned().fold(0.0, f64::max);
                        len.len() == 4 && len.iter().any(|&c| c < 0.05 * longest)
                    })
                    .collect();
                // The face as listed (listed backwards its primitive has another number).
                if let (Some((primitive, face)), 0) = (drawn, way) {
                    let on_face: Vec<usize> = (0..e.network.regions.len())
                        .filter(|&r| {
                            e.network.regions[r].kind == (RegionKind::Primitive { primitive, face })
                        })
                        .collect();
                    assert!(!on_face.is_empty(), "t = {t}");
                    for r in on_face {
                        let len = chords(e, r);
                        let longest = len.iter().cloned().fold(0.0, f64::max);
                        assert!(len.iter().all(|&c| c >= 0.05 * longest), "t = {t}: {len:?}");
                    }
                }
                if folded_at == Some(t) {
                    assert!(
                        with_short_side.iter().any(|&r| e
                            .patches
                            .iter()
                            .filter(|p| p.region == r)
                            .count()
                            == 4),
                        "t = {t}"
                    );
                }
            }
        }
    }
}

/// Needles with a tiny side: four cubes leave a triangle of chords 0.02, 1.95, 1.96 on one
/// cube's face and one of 0.005, 0.14, 0.14 on another's, each with a corner of half a degree.
/// Split round an inserted point, the quad at the tip folded (42 and 57 cells at t = 0.5, 12 in
/// all at t = 1); patched as one quad running from the tiny side to the tip, collapsed there,
/// nothing folds, the tessellation is closed (the cells at the tip are triangles) and outward,
/// and the surface stays G1.
#[test]
fn needles_with_a_tiny_side_are_patched_as_one_quad() {
    // Centres about (3.99, 1.77, 2.40), (2.46, 3.28, 2.38), (1.96, 0.58, 2.11), (1.90, 1.14, 0.09).
    let prims = survey_heap(4, 98);
    for t in [1.0, 0.5] {
        let e = build(prims.clone(), t);
        let needles: Vec<usize> = (0..e.network.regions.len())
            .filter(|&r| {
                let mut len = chords(&e, r);
                len.sort_by(f64::total_cmp);
                len.len() == 3 && len[0] < 0.05 * len[1]
            })
            .collect();
        assert_eq!(needles.len(), 2, "t = {t}");
        for &r in &needles {
            let patches: Vec<_> = e.patches.iter().filter(|p| p.region == r).collect();
            assert_eq!(patches.len(), 1, "t = {t}");
            assert!(patches[0].coons.sides.iter().any(|s| s.collapsed));
        }
        assert_eq!(past_corners(&e), vec![], "t = {t}");
        assert!(e.largest_border_jump() < 1e-9, "t = {t}");
        let m = e.tessellate(8).unwrap();
        closed(&m).unwrap();
        assert_eq!(cells_facing_the_centre(&e), 0, "t = {t}");
    }
}

/// Six primitives turned at random (heap 600135 of the mixed survey: two hexagonal prisms, a
/// tetrahedron, two boxes, an octahedron) leave a three-sided fusion region between three of
/// them with a corner of about 9° (chords about 3.82, 2.67, 1.26: no needle), patched as one
/// quad with the narrow corner collapsed, like a needle; nothing folds from t = 1 to 0.1 and
/// the surface stays closed and G1 (envelope.md, "Narrow corners as tips"). (The scene this
/// test first used, whose 14° corner folded 8, 5, 4 and 1 cells at t = 1, 0.5, 0.3, 0.2 when
/// split round a point, lost that region when nested primitives came to be left out.)
#[test]
fn a_narrow_fusion_triangle_is_patched_as_one_quad() {
    let spec: EnvelopeSpec = paper_scene(include_str!(
        "data/envelope/narrow-fusion-triangle.envelope.json"
    ))
    .unwrap();
    for t in [1.0, 0.5, 0.3, 0.2, 0.1] {
        let e = fold_free_at(&spec, t);
        if t == 1.0 {
            let tips = (0..e.network.regions.len())
                .filter(|&r| {
                    let region = &e.network.regions[r];
                    let len = chords(&e, r);
                    let shortest = len.iter().cloned().fold(f64::MAX, f64::min);
                    let mut one = e.patches.iter().filter(|p| p.region == r);
                    region.kind.between()
                        && len.len() == 3
                        && shortest > 0.2 * len.iter().cloned().fold(0.0, f64::max)
                        && one
                            .next()
                            .is_some_and(|p| p.coons.sides.iter().any(|s| s.collapsed))
                        && one.next().is_none()
                })
                .count();
            assert_eq!(tips, 1);
            assert_eq!(inward_faces(&e.tessellate(8).unwrap()), 0);
        }
    }
}

/// Random heaps of four and five equal axis-aligned cubes (the survey's third and fourth
/// hundreds): no sampled cell folds at t = 1, and every envelope is G1 — 3 and 7 of them folded
/// before slivers, needles and runs of short sides got their own patches (envelope.md,
/// "Runs of short sides", "Needles").
#[test]
fn random_heaps_of_four_and_five_do_not_fold_at_t_1() {
    for count in [4, 5] {
        for scene in 0..100 {
            heap_does_not_fold(count, scene, &[1.0]);
        }
    }
}

/// A cube face cut into a triangle with clipped corners: chords about 1.70, 2.13, 0.53, 0.41,
/// 0.13, 2.55 (the survey's 55th heap of four). Split round one point it folded at t = 1 (4
/// cells); with its run of three short sides closed by a curve across, it is one quad for the
/// run and one for the rest, nothing folds and the surface stays G1.
#[test]
fn a_run_of_short_sides_is_closed_off() {
    let e = build(survey_heap(4, 54), 1.0);
    let clipped: Vec<usize> = (0..e.network.regions.len())
        .filter(|&r| {
            let len = chords(&e, r);
            len.len() == 6 && len.iter().filter(|&&l| l > 1.5).count() == 3
        })
        .collect();
    assert_eq!(clipped.len(), 1);
    let patches = e.patches.iter().filter(|p| p.region == clipped[0]).count();
    assert_eq!(patches, 2);
    assert_eq!(past_corners(&e), vec![]);
    assert!(e.largest_border_jump() < 1e-9);
}

/// A scene of many primitives (the hull of the centres found by gift wrapping, envelope.md
/// "Finding the hull"): 24 cubes on a sphere are all kept, the envelope is closed, G1 and
/// sound, and listing them backwards gives the same surface.
#[test]
fn two_dozen_cubes_on_a_sphere_are_all_kept_and_sound() {
    let scene = common::cubes_on_a_sphere(24, 10.0);
    let e = build(scene.clone(), 0.7);
    assert!(e.removed.is_empty(), "{:?}", e.removed);
    assert_sound(&e, false, "24 cubes");
    assert_eq!(past_corners(&e), vec![]);
    let mut backwards = scene;
    backwards.reverse();
    let one = e.tessellate(4).unwrap();
    let two = build(backwards, 0.7).tessellate(4).unwrap();
    let h = hausdorff(&one.positions, &two.positions);
    assert!(h < 1e-9, "{h}");
}

/// A cube's edge crossing its silhouette plane at a grazing angle (1.7°), at a silhouette point
/// where the edge's kept piece hooks for small t: six mixed primitives, turned and scaled. When
/// the hooked piece was the edge's own, S's tangent plane went through its tangent and the
/// section's — nearly the silhouette plane, within 10° of normal to d from t = 0.45 down — and
/// the fusion quads there folded back over the cube's faces (normal jump 180° across their
/// borders). The cubic normal to both radii keeps S's tangent plane normal to S − G: G1 and
/// closed at every t, and no face turned inwards at t = 0.45 (envelope.md, "Where the rebuilt
/// piece would hook").
#[test]
fn a_grazing_cut_keeps_the_surface_g1() {
    let spec: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/grazing-cut.envelope.json")).unwrap();
    for t in [1.0, 0.5, 0.45, 0.3, 0.2] {
        let e = envelope(&EnvelopeSpec { t, ..spec.clone() }).unwrap();
        let jump = e.largest_border_jump();
        assert!(jump < 1e-6, "t = {t}: normal jump {jump}°");
        closed(&e.tessellate(4).unwrap()).unwrap();
        if t == 0.45 {
            assert_eq!(inward_faces(&e.tessellate(8).unwrap()), 0, "t = {t}");
        }
    }
}

/// Six primitives turned at random (from the scratch stress run) cut a hexagon on a box face
/// with a side 0.005 long. Split round P_i, the insertion curve to that side's middle left it
/// with a leg far under a ninth of its chord (the side's cross derivative there is tiny), the
/// sub-quads'
/// cross derivatives along the side's halves were fitted to it and pinched them against the
/// border: 3 and 9 folded cells at t = 0.2 and 0.1. With the leg lengthened to a ninth of the
/// chord (envelope.md, "Short legs at P_d") nothing folds from t = 1 to 0.1.
#[test]
fn a_short_leg_at_a_split_point_is_lengthened() {
    let spec: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/short-leg-heap.envelope.json")).unwrap();
    for t in [1.0, 0.5, 0.3, 0.2, 0.1] {
        fold_free_at(&spec, t);
    }
}

/// Two regions at t = 0.1 that fold whatever partition patches them (heaps 200144 and 400252 of
/// the mixed survey): a quad on a box face with a side 0.0084 long among sides of 1.2–2.2 (a
/// corner clipped by a cut passing near a vertex; 1 folded cell at 8 × 8, 24 at 32 × 32), and a
/// pentagon with sides 0.066 and 0.032 among sides of 0.6–1.3 (4 cells; 92 at 32 × 32). With
/// their sides' cross derivatives rescaled between the corners (envelope.md, "Folded patches:
/// cross derivatives rescaled") neither folds from t = 1 to 0.1, nor between the samples (32 ×
/// 32), nor does the tessellation pass through itself; G1 holds.
#[test]
fn folded_patches_are_unfolded_by_rescaling_their_cross_derivatives() {
    for text in [
        include_str!("data/envelope/tiny-side-quad.envelope.json"),
        include_str!("data/envelope/short-sides-pentagon.envelope.json"),
    ] {
        let spec: EnvelopeSpec = paper_scene(text).unwrap();
        for t in [1.0, 0.5, 0.3, 0.2, 0.1] {
            let e = fold_free_at(&spec, t);
            folds_nowhere(&e, &[32], &format!("t = {t}"));
            crosses_nowhere(&e, &[8, 16], &format!("t = {t}"));
        }
    }
}

/// A heap of three primitives (heap 300069 of the mixed survey) whose split faces had
/// sub-quads passing through themselves at t = 0.1 with no folded cell — a side 0.09 long
/// against 0.89 — so the tessellation crossed itself in 8, 24, 64 pairs at K = 8, 16, 32 (the
/// crossing test's heap until then). Patches are checked for passing through themselves too
/// and rescaled as folded ones are (envelope.md,
/// "Folded patches: cross derivatives rescaled"): no crossing at any K from t = 1 to 0.1, no
/// fold, G1.
#[test]
fn patches_through_themselves_are_rescaled_too() {
    let spec: EnvelopeSpec = paper_scene(include_str!(
        "data/envelope/self-crossing-patches.envelope.json"
    ))
    .unwrap();
    for t in [1.0, 0.5, 0.2, 0.1] {
        let e = fold_free_at(&spec, t);
        crosses_nowhere(&e, &[8, 16, 32], &format!("t = {t}"));
    }
}

/// A heap of six primitives (heap 600266 of the mixed survey) at t = 3, the top of the tab's
/// slider: one sub-quad of a split face, sides 0.16 to 0.89 (none under 15 % of the longest, so
/// it was not checked), bulged through itself, and the tessellation crossed itself in 3, 4, 12,
/// 26 pairs at K = 6, 8, 16, 32 with no folded cell. Every patch is checked for passing through
/// itself now (envelope.md, "Patches through themselves"): no crossing at any K, no fold, G1.
#[test]
fn a_patch_through_itself_is_found_whatever_its_sides() {
    let spec: EnvelopeSpec = paper_scene(include_str!(
        "data/envelope/bulging-patch-through-itself.envelope.json"
    ))
    .unwrap();
    for t in [3.0, 2.0, 1.0] {
        let e = fold_free_at(&spec, t);
        crosses_nowhere(&e, &[6, 8, 16, 32], &format!("t = {t}"));
    }
}

/// Three heaps of the mixed survey whose tessellation crossed itself, though their surfaces do
/// not: the border cells, which hold the other side's samples too, were left to the renderer's
/// ear clipping, which took ears of three neighbouring border points (envelope.md,
/// "Tessellation"). In heaps 600210 and 300013 at t = 0.16 a fusion strip's side is a piece of a
/// silhouette curve ending at a T-point at 0.5000005 and 0.857143 of it, so the strip samples
/// the curve a ten-millionth from where the face beside it does, and the sliver of two such
/// samples had a normal of noise (1–3 and 1–5 pairs at K = 16 to 32); in heap 300332 at t = 3
/// the sliver of three samples of a bent curve stood in its osculating plane, across the face
/// beside it (3–7 pairs at K = 8 and 16). Each border cell is a fan from its inner corners
/// now: no crossing, and every face a quad or a triangle with a point inside its patch.
#[test]
fn border_cells_are_fans_from_their_inner_corners() {
    use prism_geom::freeform::envelope::folds::crossings;
    for (scene, ks) in [
        (
            include_str!("data/envelope/t-point-samples-heap.envelope.json"),
            &[8, 16, 32][..],
        ),
        (
            include_str!("data/envelope/t-point-samples-heap-of-three.envelope.json"),
            &[8, 16, 32],
        ),
        (
            include_str!("data/envelope/border-sliver-heap.envelope.json"),
            &[8, 16],
        ),
    ] {
        let spec: EnvelopeSpec = paper_scene(scene).unwrap();
        let e = fold_free_at(&spec, spec.t);
        for &k in ks {
            let m = e.tessellate(k).unwrap();
            closed(&m).unwrap();
            assert!(
                (0..m.num_faces()).all(|f| m.face_corners(f).len() <= 4),
                "t = {}, K = {k}",
                spec.t
            );
            assert!(crossings(&m).is_empty(), "t = {}, K = {k}", spec.t);
        }
    }
}

/// Two heaps of the mixed survey at t = 3 (300040, and the pair 200274) whose tessellation
/// crossed itself at K = 16 to 32 and not at 8: a primitive face's sub-quad beside a silhouette
/// piece 0.007 long (6, 23 pairs at K = 16, 32), and one beside an edge piece of weights 1,
/// 6.54, 1.94, 1 (3, 10), each bulging through itself between the 8 × 8 samples its check
/// takes. A patch whose 8 × 8 grid lines turn by more than 20° between samples is checked at
/// 16 × 16 too (envelope.md, "Patches through themselves"): no crossing at any K, no fold.
#[test]
fn a_patch_bending_between_its_samples_is_checked_finer() {
    for scene in [
        include_str!("data/envelope/bulging-between-samples-heap.envelope.json"),
        include_str!("data/envelope/bulging-between-samples-pair.envelope.json"),
    ] {
        let spec: EnvelopeSpec = paper_scene(scene).unwrap();
        let e = fold_free_at(&spec, spec.t);
        let what = format!("{} primitives", spec.primitives.len());
        crosses_nowhere(&e, &[8, 16, 24, 32], &what);
    }
}

/// Heap 600313 of the mixed survey at t = 0.12: primitive 2's face 3 is split round an
/// inserted point, and one of its sub-quads, beside an edge piece 0.001 long, turns its 8 × 8
/// grid lines by 77°. Each sub-quad is one to one, but between the samples that one bulged into
/// its neighbour across the insertion curve they share (11, 17 and 19 pairs of faces through
/// each other at K = 16, 24 and 32, none at 8). A patch turning that sharply is checked at
/// 16 × 16 against its neighbours in the region and rescaled with those crossings counted
/// (`patches.rs`, `kept_apart`; envelope.md, "Patches through themselves", *Finer still, and
/// into a neighbour*).
#[test]
fn sub_quads_of_a_region_are_kept_apart() {
    let spec: EnvelopeSpec = paper_scene(include_str!(
        "data/envelope/sub-quads-through-each-other.envelope.json"
    ))
    .unwrap();
    let e = fold_free_at(&spec, 0.12);
    crosses_nowhere(&e, &[8, 16, 24, 32], "t = 0.12");
}

/// Heap 600350 of the mixed survey at t = 0.7: a patch of primitive 2's face 5 with a side
/// 0.0056 long against 0.94 turns by only 8° between its 8 × 8 samples, and folded in the strip
/// beside that side finer than them (1, 4 and 11 cells at 16, 32 and 48 a side; the tessellation
/// through itself at K = 16 and 32). A patch whose shortest side is under 2 % of its longest is
/// checked at 16 and 32 a side too (envelope.md, "Patches through themselves", *Finer still,
/// and into a neighbour*). Heap 600327 at t = 3: a needle quad of primitive 3's face 1 with a
/// side 1.2 % of its longest folded in 3 cells at 32 a side, none at 16, while the share was 1 %.
#[test]
fn a_patch_beside_a_very_short_side_is_checked_finer() {
    let spec: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/short-side-bulge.envelope.json")).unwrap();
    let e = fold_free_at(&spec, 0.7);
    crosses_nowhere(&e, &[8, 16, 24, 32], "t = 0.7");
    folds_nowhere(&e, &[16], "t = 0.7");
    let spec: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/short-side-at-3.envelope.json")).unwrap();
    let e = fold_free_at(&spec, 3.0);
    crosses_nowhere(&e, &[8, 16, 32], "t = 3");
    folds_nowhere(&e, &[16, 24, 32], "t = 3");
}

/// Patches sound at their 8 × 8 samples with a cell there nearly flattened (the sine of its
/// corner angle, tilted from the normal expected there, under 0.3) folded in a strip between
/// them. Heap 600105 of the mixed survey at t = 0.1, a patch of primitive 2's face 0 with no
/// corner under 68° and no side under 24 % of its longest: 3, 8 and 10 folded cells at 16, 24
/// and 32 a side; heap 500275 at t = 3: 2, 6 and 11. Such a patch is checked finer, at 16 and
/// 32 a side, and its search scores both (envelope.md, "Patches through themselves", *Nearly
/// flat cells, and 32 a side*). Heap 400183 at t = 0.1 folded in one cell at 16 a side and 24, none at 32: the search of a
/// patch checked finer counts its folds at 16 too. Heap 600161 at t = 0.1 folded in 15 cells at
/// 32 a side and none at 16, in a strip along a side of a patch of primitive 4's face 0: a patch
/// checked finer is checked at 32 a side as well as at 16.
#[test]
fn a_patch_with_a_nearly_flat_cell_is_checked_finer() {
    for scene in [
        include_str!("data/envelope/nearly-flat-cell-heap.envelope.json"),
        include_str!("data/envelope/nearly-flat-cell-heap-at-3.envelope.json"),
        include_str!("data/envelope/fold-between-32-samples.envelope.json"),
        include_str!("data/envelope/fold-between-16-samples.envelope.json"),
    ] {
        let spec: EnvelopeSpec = paper_scene(scene).unwrap();
        let e = fold_free_at(&spec, spec.t);
        let what = format!("{} primitives, t = {}", spec.primitives.len(), spec.t);
        folds_nowhere(&e, &[16, 24, 32], &what);
        crosses_nowhere(&e, &[16], &what);
    }
}

/// Heap 500132 of the mixed survey at t = 0.1: a strip 3.4 long and 0.07–0.16 wide on
/// primitive 1's face 1, whose corner normals turn 120° along it, folded in a crease a thousandth
/// wide along its long side 2 (2, 14 and 20 cells at 16, 24 and 32 a side; none at 8) with that
/// side's cross derivative pushed out as far as the search went, β = −2. The search goes to
/// β = −4 (the middle five times the fitted one), and the patch folds nowhere (envelope.md,
/// "Folded patches: cross derivatives rescaled", *Pushed out further*).
#[test]
fn a_crease_along_a_long_side_is_pushed_out_further() {
    let spec: EnvelopeSpec = paper_scene(include_str!(
        "data/envelope/crease-along-a-long-side.envelope.json"
    ))
    .unwrap();
    let e = fold_free_at(&spec, 0.1);
    folds_nowhere(&e, &[16, 24, 32], "t = 0.1");
    crosses_nowhere(&e, &[16, 32], "t = 0.1");
}

/// Below the slider, which stops at t = 0.1 (the CLI and scene files take any t > 0), the
/// bundled scenes of several primitives fold nowhere and do not pass through themselves down to
/// t = 0.001. The five folded at t <= 0.01 (1 to 10 cells) in a thin region on primitive 3's
/// face 4 between a rational edge crowded at both ends (2 % of its length in its first fifth
/// of parameter) and a silhouette cubic run evenly: a patch that still folds after every other
/// repair has its sides run along their curves afresh, by arc length or with opposite sides
/// matched (envelope.md, "Sides run along their curves").
#[test]
fn the_bundled_scenes_hold_below_the_slider() {
    use prism_geom::freeform::envelope::folds::crossings;
    for scene in [
        include_str!("../../../assets/table2-five.envelope.json"),
        include_str!("../../../assets/table2-seven.envelope.json"),
    ] {
        let spec: EnvelopeSpec = paper_scene(scene).unwrap();
        for t in [0.05, 0.01, 0.005, 0.002, 0.001] {
            let e = fold_free_at(&spec, t);
            assert!(
                crossings(&e.tessellate(8).unwrap()).is_empty(),
                "{} primitives, t = {t}",
                spec.primitives.len()
            );
        }
    }
}

/// A heap of four primitives at t = 0.05 (heap 400187 of the mixed survey) whose patch on
/// primitive 0's face 0 still folded (1 cell) with its sides run by arc length or matched to the
/// slower of each two opposite sides: matched the other way, to the faster one, it folds
/// nowhere and does not pass through itself (envelope.md, "Sides run along their curves").
/// Since session 48 its corners drawn together leave that patch nothing to mend at t = 0.05;
/// at t = 0.01 a patch of it still has its sides run along their curves.
#[test]
fn opposite_sides_are_also_matched_the_other_way() {
    use prism_geom::freeform::envelope::folds::crossings;
    let spec: EnvelopeSpec = paper_scene(include_str!(
        "data/envelope/matched-other-way-heap.envelope.json"
    ))
    .unwrap();
    for t in [0.05, 0.01] {
        let e = fold_free_at(&spec, t);
        assert!(crossings(&e.tessellate(8).unwrap()).is_empty(), "t = {t}");
        if t == 0.01 {
            assert!(
                e.patches
                    .iter()
                    .any(|p| p.coons.sides.iter().any(|s| s.reparam.is_some()))
            );
        }
    }
}

/// A needle beside its tip (heap 600332 of the mixed survey at t = 0.05, below the slider: a
/// triangle of sides 0.45, 0.46 and 0.60 on primitive 4's face 0, patched as one quad with its
/// 34° corner collapsed, one leg there 15 times the other). Its grid lines near the tip bunch
/// towards the shorter leg: two cells beside the tip turned over at 8 cells a side (the
/// report's samples, and the tessellation at K = 8) and one at 16. The rescaling search scored
/// the folds at 16 a side only, and ended with that one still there. It now scores the
/// folds at the report's samples too (envelope.md, "Folded patches: cross derivatives
/// rescaled"), takes changes that clear those, and ends with none at 8 or 16 cells a side.
#[test]
fn the_rescaling_search_counts_the_reports_samples() {
    let spec: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/needle-tip-heap.envelope.json")).unwrap();
    let e = fold_free_at(&spec, 0.05);
    folds_nowhere(&e, &[16], "t = 0.05");
    crosses_nowhere(&e, &[8], "t = 0.05");
}

/// Every way to patch a region that still folds once rescaled (heap 600349 of the mixed survey
/// at t = 0.05, below the slider, turned by 180° about x): a needle triangle on primitive 5's
/// face 6 (sides about 1.2, 1.15 and 0.09) that the partition choice split round an inserted
/// point, since its tip folded more cells as built. Rescaled, two of the split's sub-quads
/// still folded in 2 cells, beside insertion curves whose tangent planes turn by 68° and 85°
/// along 0.07; the tip, rescaled, folds in none. Each way is now tried rescaled where the
/// chosen one still folds (`patches.rs`, `build`; envelope.md, "Every way, rescaled").
#[test]
fn every_way_is_tried_rescaled_where_a_region_still_folds() {
    use prism_geom::freeform::envelope::folds::crossings;
    let spec: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/every-way-heap.envelope.json")).unwrap();
    let e = fold_free_at(&spec, 0.05);
    assert!(crossings(&e.tessellate(8).unwrap()).is_empty());
    // The face is one quad with its tip collapsed.
    let face: Vec<_> = (0..e.regions)
        .filter(|&r| e.describe_region(r) == "primitive 5 face 6")
        .collect();
    assert_eq!(face.len(), 1);
    let patches: Vec<_> = e.patches.iter().filter(|p| p.region == face[0]).collect();
    assert_eq!(patches.len(), 1);
    assert!(patches[0].coons.sides.iter().any(|s| s.collapsed));
}

/// Four cubes placed apart (the equal-cube survey's `APART=1` scene 32) at t = 0.1: a triangle
/// patched as one quad with its tip collapsed was then tried split round an inserted point as a
/// quad with a short side, the insertion curve to the collapsed side's middle ended at the tip
/// with no direction for its basis, and two patches were NaN throughout — the fold check counted
/// none and `prism envelope` wrote 8 NaN vertices. A collapsed tip is never split now, a cell
/// with a point that is not finite counts as folded, and a tessellation with one is refused.
#[test]
fn a_collapsed_tip_is_not_split_again() {
    let spec: EnvelopeSpec = paper_scene(include_str!(
        "data/envelope/collapsed-tip-not-split.envelope.json"
    ))
    .unwrap();
    let e = fold_free_at(&spec, 0.1);
    for k in [3, 8] {
        let m = e.tessellate(k).unwrap();
        assert!(m.positions.iter().all(|p| p.is_finite()), "K = {k}");
        closed(&m).unwrap();
    }
}

/// Per-vertex t a thousand times apart on one octahedron (0.0017 beside 2.2 and 2.5): the
/// sides meeting at the sharp vertex leave it with legs 3 % of their other ends', and with k
/// running linearly along them the twist there (0.39) was 30–120 times the corner's
/// derivatives: the four patches folded over themselves in their corner cells (16 pairs of
/// faces through each other at 12 quads a patch side, none of it seen by the fold check). With
/// k eased into the short leg's corner (`coons.rs`, `Side::k_share`) the twist is 0.04 and
/// nothing crosses at 8, 12 or 16 quads a side, still G1 (envelope.md, "Per-vertex t far
/// apart").
#[test]
fn per_vertex_t_far_apart_does_not_fold_the_sharp_corner() {
    use prism_geom::freeform::envelope::folds::crossings;
    let spec: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/vertex-t-apart.envelope.json")).unwrap();
    let e = envelope(&spec).unwrap();
    assert!(past_corners(&e).is_empty());
    assert!(e.largest_border_jump() < 1e-6);
    for k in [8, 12, 16] {
        let m = e.tessellate(k).unwrap();
        assert!(crossings(&m).is_empty(), "K = {k}");
        assert_eq!(inward_faces(&m), 0, "K = {k}");
    }
}

/// A heap of five primitives at t = 0.005 (below the tab's slider, which stops at 0.1; the CLI
/// takes any t) whose surface passes through itself where no patch folds (heap 500289 of the
/// mixed survey). The crossing check of the tessellation finds the pairs, more as it refines
/// (6, 12, 52 at K = 8, 16, 32). (The heaps this test held before no longer cross at K = 8:
/// heap 600002 at t = 0.02 since corners near each other are drawn together,
/// `corners_near_each_other_are_drawn_together`; the heap of six at t = 0.1
/// since folded patches have their cross derivatives rescaled, the heap of three at t = 0.1
/// since patches that pass through themselves are too, a heap of four and one of six at t =
/// 0.05 since a patch that still folds has its sides run along their curves afresh.)
#[test]
fn the_crossing_check_finds_a_heap_through_itself() {
    use prism_geom::freeform::envelope::folds::crossings;
    let spec: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/crossing-heap.envelope.json")).unwrap();
    let e = envelope(&spec).unwrap();
    let counts: Vec<usize> = [8, 16, 32]
        .iter()
        .map(|&k| crossings(&e.tessellate(k).unwrap()).len())
        .collect();
    assert!(
        counts[0] > 0 && counts[0] < counts[1] && counts[1] < counts[2],
        "{counts:?}"
    );
}

/// A heap of `count` primitives of every library shape (flat and tall prisms, boxes of
/// random proportions), each turned at random, scaled 1–2, centres uniform in [0, 4]³.
fn mixed_heap(rng: &mut Lcg, count: usize) -> Vec<PrimitiveInput> {
    (0..count)
        .map(|_| {
            let shape = match (rng.next() * 7.0) as usize {
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
            };
            let centre = [4.0 * rng.next(), 4.0 * rng.next(), 4.0 * rng.next()];
            let rotation = [360.0 * rng.next(), 360.0 * rng.next(), 360.0 * rng.next()];
            shape.placed(&Placement {
                centre,
                scale: 1.0 + rng.next(),
                rotation,
            })
        })
        .collect()
}

/// Whether a primitive's centre lies inside the sphere of a larger one (envelope.md, "Nested
/// primitives").
fn has_nested_pair(prims: &[PrimitiveInput]) -> bool {
    let sphere: Vec<(DVec3, f64)> = prims
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let p = Primitive::new(i, p, 1.0).unwrap();
            (p.centre, p.radius)
        })
        .collect();
    sphere.iter().any(|&(ca, ra)| {
        sphere
            .iter()
            .any(|&(cb, rb)| ra < rb && ca.distance(cb) < rb)
    })
}

/// An ignored survey of heaps of 2–6 primitives of every library shape (envelope.md, "Left"):
/// per t, the heaps with a folded cell ([`Envelope::folds`]), with faces passing through each
/// other at K quads a patch side (`K`, default 8), and errors (a border normal jump over 10⁻⁶° counts as one). `HEAPS` heaps per count (default
/// 60), `TS` the t values (default "1"); each failing heap is printed with its seed so that it can be rebuilt, and
/// written as `heap-SEED.envelope.json` into the folder `DUMP` when it is set. `SLOW=ms` prints
/// every heap whose `envelope()` takes longer than that.
#[test]
#[ignore]
fn survey_mixed_heaps() {
    let heaps: usize = std::env::var("HEAPS").map_or(60, |v| v.parse().unwrap());
    // The tessellation checked for crossing itself, K quads a patch side.
    let k: usize = std::env::var("K").map_or(8, |v| v.parse().unwrap());
    let ts: Vec<f64> = std::env::var("TS").map_or(vec![1.0], |v| {
        v.split(',').map(|x| x.parse().unwrap()).collect()
    });
    for &t in &ts {
        let (mut folded, mut crossed, mut errors, mut total) = (0, 0, 0, 0);
        // Heaps with a centre inside a larger primitive's sphere, and of those failing, how
        // many have such a pair.
        let (mut close, mut close_failing) = (0, 0);
        for count in 2..=6 {
            for scene in 0..heaps {
                let seed = (count * 100_000 + scene) as u64;
                let prims = mixed_heap(&mut Lcg(seed), count);
                total += 1;
                let near = has_nested_pair(&prims);
                close += usize::from(near);
                let (f0, c0) = (folded, crossed);
                let scene = spec(prims, t);
                let dump = |scene: &EnvelopeSpec| {
                    if let Ok(dir) = std::env::var("DUMP") {
                        let path = format!("{dir}/heap-{seed}.envelope.json");
                        std::fs::write(&path, serde_json::to_string_pretty(scene).unwrap())
                            .unwrap();
                    }
                };
                if std::env::var("SEEDS").is_ok_and(|v| v.split(',').any(|x| x == seed.to_string()))
                {
                    dump(&scene);
                }
                let started = std::time::Instant::now();
                let built = envelope(&scene);
                let ms = started.elapsed().as_secs_f64() * 1e3;
                if std::env::var("SLOW").is_ok_and(|v| ms > v.parse::<f64>().unwrap()) {
                    println!("SLOW t = {t}: heap {seed}: {ms:.1} ms");
                }
                match built {
                    Err(e) => {
                        errors += 1;
                        println!("t = {t}: heap {seed}: error {e}");
                    }
                    Ok(e) => {
                        let folds = e.folds();
                        if !folds.is_empty() {
                            folded += 1;
                            dump(&scene);
                            println!(
                                "t = {t}: heap {seed}: {}",
                                e.fold_warning(&folds).unwrap_or_default()
                            );
                        }
                        let jump = e.largest_border_jump();
                        if jump.is_nan() || jump >= 1e-6 {
                            errors += 1;
                            println!("t = {t}: heap {seed}: border jump {jump}°");
                        }
                        if std::env::var("FINE").is_ok() {
                            finer_than_the_report(&e, t, seed);
                        }
                        let m = e.tessellate(k).unwrap();
                        let pts = prism_geom::freeform::envelope::folds::crossings(&m);
                        if !pts.is_empty() {
                            crossed += 1;
                            dump(&scene);
                            println!("t = {t}: heap {seed}: crosses itself near {:?}", pts[0]);
                        }
                    }
                }
                if near && (folded > f0 || crossed > c0) {
                    close_failing += 1;
                }
            }
        }
        println!(
            "t = {t}: of {total} heaps {folded} with a folded cell, {crossed} crossing themselves, {errors} errors; {close} heaps have a centre inside a larger primitive's sphere, {close_failing} of them fail"
        );
    }
}

/// The survey's `FINE=1`: every patch with folded cells at 16 or 32 cells a side, or passing
/// through itself at 16, finer than the report's 8 × 8 (envelope.md, "Left", *Finer than the
/// report*), with its shortest side over its longest and the angle at its narrowest corner.
fn finer_than_the_report(e: &Envelope, t: f64, seed: u64) {
    use prism_geom::freeform::envelope::folds::{folds, self_crossings};
    for (i, p) in e.patches.iter().enumerate() {
        let count = |k| folds(&e.network, std::slice::from_ref(p), k).len();
        let (f16, f32, s16) = (count(16), count(32), self_crossings(p, 16));
        if f16 + f32 + s16 == 0 {
            continue;
        }
        let chords: Vec<f64> = p
            .coons
            .sides
            .iter()
            .filter(|s| !s.collapsed)
            .map(|s| s.point(0.0).distance(s.point(1.0)))
            .collect();
        let share = chords.iter().copied().fold(f64::INFINITY, f64::min)
            / chords.iter().copied().fold(0.0, f64::max);
        // The corners' angles between the sides leaving them (a collapsed side's legs).
        let corner = (0..4)
            .map(|c| {
                let (a, b) = (&p.coons.sides[c], &p.coons.sides[(c + 3) % 4]);
                a.d1(0.0).angle_between(-b.d1(1.0)).to_degrees()
            })
            .filter(|x| x.is_finite())
            .fold(180.0f64, f64::min);
        println!(
            "FINE t = {t}: heap {seed} patch {i} ({}): folded at 16, 32: {f16}, {f32}; through itself at 16: {s16}; shortest side {share:.4} of the longest; narrowest corner {corner:.1}°",
            e.describe_region(p.region)
        );
    }
}

/// A primitive whose centre lies inside a larger one's sphere and whose curved shape lies inside
/// that primitive's is left out (envelope.md, "Nested primitives"): a box of radius 1.01 whose
/// centre is 0.28 from a tetrahedron's of radius 1.94 (heap 300359 of the mixed survey). The
/// paper's strip between their sections, less than r apart and r wide apart, folded 80 cells of
/// five patches at t = 1. From t = 1 down to 0.5 the box lies inside the envelope of the other
/// two: it is removed, and the surface is theirs and encloses it; at t = 0.3 and 0.1 it pokes
/// out (at 0.3 from their envelope, though not from the curved tetrahedron) and is kept. No
/// fold and no crossing at any t, whatever the listing.
#[test]
fn a_primitive_nested_in_another_is_left_out() {
    let spec: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/nested-heap.envelope.json")).unwrap();
    for t in [1.0, 0.7, 0.5, 0.3, 0.1] {
        let e = build(spec.primitives.clone(), t);
        assert!(past_corners(&e).is_empty(), "t = {t}");
        let m = e.tessellate(8).unwrap();
        assert!(
            prism_geom::freeform::envelope::folds::crossings(&m).is_empty(),
            "t = {t}"
        );
        let mut backwards = spec.primitives.clone();
        backwards.reverse();
        let b = build(backwards, t);
        assert_eq!(
            b.removed.iter().map(|&i| 2 - i).collect::<Vec<_>>(),
            e.removed,
            "t = {t}"
        );
        if t < 0.5 {
            assert!(e.removed.is_empty(), "t = {t}");
            continue;
        }
        assert_eq!(e.removed, vec![0], "t = {t}");
        let bare = build(spec.primitives[1..].to_vec(), t)
            .tessellate(4)
            .unwrap();
        let with = e.tessellate(4).unwrap();
        assert_eq!(bare.num_faces(), with.num_faces());
        assert!(
            hausdorff(&bare.positions, &with.positions) < 1e-9,
            "t = {t}"
        );
        let box_ = &e.primitives[0];
        for &v in &box_.vertices {
            assert!(
                winding(&with, v) > 0.5,
                "t = {t}: the box's corner {v} is outside"
            );
        }
    }
}

/// Two sections with points at nearly equal polar angles (under 0.02 rad apart) pair them as
/// they are instead of inserting a T-point for each (envelope.md, "Nearly equal angles"): in
/// heap 500073 of the mixed survey (five primitives) that left a fusion quad 0.003 and 0.005
/// wide at its ends and 2.55 long, which folded 38 cells at t = 0.5 and crossed itself. No
/// fold and no crossing from t = 1 to 0.5, whatever the listing, and one fusion quad fewer
/// whose loop sides are both under 0.01.
#[test]
fn nearly_equal_angles_pair_without_a_sliver() {
    let spec: EnvelopeSpec =
        paper_scene(include_str!("data/envelope/near-angle-heap.envelope.json")).unwrap();
    for t in [1.0, 0.7, 0.5] {
        for reversed in [false, true] {
            let mut prims = spec.primitives.clone();
            if reversed {
                prims.reverse();
            }
            let e = build(prims, t);
            assert!(past_corners(&e).is_empty(), "t = {t}, reversed {reversed}");
            let m = e.tessellate(8).unwrap();
            assert!(
                prism_geom::freeform::envelope::folds::crossings(&m).is_empty(),
                "t = {t}, reversed {reversed}"
            );
            let net = &e.network;
            let thin = net
                .regions
                .iter()
                .filter(|r| r.kind.between())
                .map(|r| {
                    [0, 2]
                        .map(|k| {
                            let s = &r.sides[k];
                            let c = &net.curves[s.curve].bezier;
                            c.eval(s.t0).distance(c.eval(s.t1))
                        })
                        .into_iter()
                        .fold(0.0, f64::max)
                })
                .filter(|&w| w < 0.01)
                .collect::<Vec<_>>();
            // The two left are short silhouette edges of both sections at one angle (no
            // T-point on either side); the third, a T-point 0.005 from a vertex, is gone.
            assert!(thin.len() <= 2, "t = {t}: fusion quads {thin:?} wide");
        }
    }
}

/// A scene file read for the paper's patches (what these tests measure; the charts have
/// their own, envelope_charts.rs).
fn paper_scene(text: &str) -> Result<EnvelopeSpec, serde_json::Error> {
    let mut s: EnvelopeSpec = serde_json::from_str(text)?;
    s.patches = prism_geom::freeform::envelope::Surfacing::Paper;
    Ok(s)
}
