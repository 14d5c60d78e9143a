//! Basic measures of a polygon mesh: Newell face normals, corner frames, bend angles of
//! edges, signed volume (docs/algorithms/conventions.md, biquadratic.md).
//!
//! Angles between vectors are always `atan2(|a × b|, a·b)`, never `acos` of a dot product,
//! which loses half the digits near 0 and π.

use crate::mesh::PolyMesh;
use crate::topology::{NONE, Topology};
use glam::{DVec2, DVec3};

/// Newell normal of face `f`: ½ Σ_loops Σ_i V_i × V_(i+1). Its length is the area of a
/// planar face (holes subtracted).
pub fn face_normal_raw(mesh: &PolyMesh, f: usize) -> DVec3 {
    let mut n = DVec3::ZERO;
    for l in mesh.face_loops(f) {
        n += loop_newell(mesh, mesh.loop_verts(l));
    }
    n
}

/// The summed length of face `f`'s loops (holes included).
pub fn face_perimeter(mesh: &PolyMesh, f: usize) -> f64 {
    mesh.face_loops(f)
        .map(|l| {
            let vs = mesh.loop_verts(l);
            (0..vs.len())
                .map(|i| {
                    let a = mesh.positions[vs[i] as usize];
                    a.distance(mesh.positions[vs[(i + 1) % vs.len()] as usize])
                })
                .sum::<f64>()
        })
        .sum()
}

/// ½ Σ V_i × V_(i+1) of one loop. Triangles and quads use the equal closed forms
/// ½(V₁ − V₀) × (V₂ − V₀) and ½(V₂ − V₀) × (V₃ − V₁) (the quad form holds for non-planar
/// quads too); longer loops sum relative to their first vertex (the same sum for a closed
/// loop, fewer cancelled digits far from the origin).
#[inline(always)]
pub fn loop_newell(mesh: &PolyMesh, vs: &[u32]) -> DVec3 {
    let p = |i: usize| mesh.positions[vs[i] as usize];
    match vs.len() {
        3 => 0.5 * (p(1) - p(0)).cross(p(2) - p(0)),
        4 => 0.5 * (p(2) - p(0)).cross(p(3) - p(1)),
        n => {
            let o = p(0);
            let mut acc = DVec3::ZERO;
            let mut prev = DVec3::ZERO;
            for i in 1..n {
                let cur = p(i) - o;
                acc += prev.cross(cur);
                prev = cur;
            }
            0.5 * acc
        }
    }
}

/// Whether the outline through `pts` (in order) crosses itself, seen along `n` (its Newell
/// normal as computed, not normalised: a quad's test uses its length): two edges that are not
/// neighbours cut each other, each one's ends on either side of the other by more than 1e-9 of
/// their lengths' product. Such a face — a bow-tie, a figure of eight — can keep a normal that
/// agrees with its parent while one lobe of it is turned over, so the flip test alone does not
/// see it; the combination rule's fold guard and its untangling look for it too
/// (docs/algorithms/cylindrical.md, "Fold guard"). Touching is not crossing. Orientations are
/// triple products with `n`, so nothing is projected or normalised; a quad takes two
/// ([`quad_crosses_itself`]).
pub fn points_cross_themselves(pts: &[DVec3], n: DVec3) -> bool {
    let k = pts.len();
    if k < 4 {
        return false;
    }
    if k == 4 {
        return quad_crosses_itself([pts[0], pts[1], pts[2], pts[3]], n);
    }
    let orient = |a: DVec3, b: DVec3, c: DVec3| n.dot((b - a).cross(c - a));
    for i in 0..k {
        for j in i + 2..k {
            if i == 0 && j == k - 1 {
                continue;
            }
            let (p, q) = (pts[i], pts[(i + 1) % k]);
            let (r, s) = (pts[j], pts[(j + 1) % k]);
            let (o1, o2) = (orient(p, q, r), orient(p, q, s));
            if o1 * o2 >= 0.0 {
                continue;
            }
            let (o3, o4) = (orient(r, s, p), orient(r, s, q));
            if o3 * o4 >= 0.0 {
                continue;
            }
            let tol = 1e-9 * n.length() * (q - p).length() * (s - r).length();
            if o1.abs().min(o2.abs()).min(o3.abs()).min(o4.abs()) > tol {
                return true;
            }
        }
    }
    false
}

/// [`points_cross_themselves`] for a quad ABCD. Of its four
/// triangles (orientations against `n`), AB cuts CD when ABC, ABD and CDA, CDB differ in
/// sign, BC cuts DA when BCD, BCA and DAB, DAC do. With `n` the quad's Newell normal
/// `½ AC × BD`, `ABC + ACD = ABD + BCD = 2|n|²`, so two triple products give all four: the
/// quad is a bow-tie exactly when each pair has one negative.
#[inline]
pub fn quad_crosses_itself([a, b, c, d]: [DVec3; 4], n: DVec3) -> bool {
    let two = 2.0 * n.length_squared();
    let abc = n.dot((b - a).cross(c - a));
    let abd = n.dot((b - a).cross(d - a));
    let (acd, bcd) = (two - abc, two - abd);
    if abc.min(acd) >= 0.0 || abd.min(bcd) >= 0.0 {
        return false;
    }
    let least = abc.abs().min(abd.abs()).min(acd.abs()).min(bcd.abs());
    let l = if abc * abd < 0.0 {
        (b - a).length() * (d - c).length()
    } else {
        (c - b).length() * (a - d).length()
    };
    least > 1e-9 * n.length() * l
}

/// Whether the segments a0–a1 and b0–b1 in the plane meet: cross, touch, or overlap along
/// one line. An orientation (twice a triangle's signed area) within `tolerance` of zero counts
/// as zero, so only a clear miss is a miss: with `tolerance` = 0 the test is exact (an extruded
/// outline's check, `solid.rs`); a check that may only err towards "they meet" passes its
/// rounding.
/// Segments on one line (all four orientations zero) meet where their spans along it overlap.
pub fn segments_meet(a0: DVec2, a1: DVec2, b0: DVec2, b1: DVec2, tolerance: f64) -> bool {
    let sign = |x: f64| {
        if x > tolerance {
            1
        } else if x < -tolerance {
            -1
        } else {
            0
        }
    };
    let turn = |p: DVec2, q: DVec2, r: DVec2| sign((q - p).perp_dot(r - p));
    let (t1, t2) = (turn(a0, a1, b0), turn(a0, a1, b1));
    let (t3, t4) = (turn(b0, b1, a0), turn(b0, b1, a1));
    if t1 * t2 > 0 || t3 * t4 > 0 {
        return false;
    }
    if t1 == 0 && t2 == 0 && t3 == 0 && t4 == 0 {
        // Spans along the longer segment's direction (a point, if both are points).
        let (p0, p1, q0, q1) = if (a1 - a0).length_squared() >= (b1 - b0).length_squared() {
            (a0, a1, b0, b1)
        } else {
            (b0, b1, a0, a1)
        };
        let dir = p1 - p0;
        if dir == DVec2::ZERO {
            return p0 == q0;
        }
        let at = |p: DVec2| (p - p0).dot(dir);
        let (c0, c1) = (at(q0), at(q1));
        return c0.max(c1) >= 0.0 && c0.min(c1) <= at(p1);
    }
    // Not all on one line, and each segment's ends on both sides of (or on) the other's
    // line: the two lines cross at one point, which lies on both segments.
    true
}

/// The first pair (i, j), i < j, of segments of the closed polygon `p` (segment i runs from
/// p[i] to p[i + 1]) that meet though they are not neighbours ([`segments_meet`] with
/// `tolerance`); `None` when the polygon is simple.
pub fn outline_meets_itself(p: &[DVec2], tolerance: f64) -> Option<(usize, usize)> {
    let n = p.len();
    for i in 0..n {
        for j in i + 2..n {
            if i == 0 && j == n - 1 {
                continue;
            }
            if segments_meet(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n], tolerance) {
                return Some((i, j));
            }
        }
    }
    None
}

/// Newell normal of every face (raw, not normalised), on every core (each face on its own,
/// so the result is the serial one).
pub fn face_normals_raw(mesh: &PolyMesh) -> Vec<DVec3> {
    use rayon::prelude::*;
    (0..mesh.num_faces())
        .into_par_iter()
        .with_min_len(4096)
        .map(|f| face_normal_raw(mesh, f))
        .collect()
}

/// Unit normal, or zero for a face of no area.
pub fn unit_or_zero(v: DVec3) -> DVec3 {
    let l = v.length();
    if l > 0.0 { v / l } else { DVec3::ZERO }
}

/// Distance from `p` to the segment `ab` (to `a` when the segment has no length).
pub fn segment_distance(p: DVec3, a: DVec3, b: DVec3) -> f64 {
    let ab = b - a;
    let s = ((p - a).dot(ab) / ab.length_squared().max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
    p.distance(a + s * ab)
}

/// Angle between two vectors in [0, π], computed as atan2(|a × b|, a·b).
pub fn angle_between(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

/// The sum of the unit normals of the faces around every vertex: the normal a VERTEX-face of
/// the dual split is checked against (`step::check_children`, the combination rule's guards).
pub fn vertex_normal_sums(mesh: &PolyMesh, topo: &Topology, unit_normals: &[DVec3]) -> Vec<DVec3> {
    let mut vsum = vec![DVec3::ZERO; mesh.num_vertices()];
    for c in 0..mesh.num_corners() {
        vsum[mesh.corner_verts[c] as usize] += unit_normals[topo.corner_face(c) as usize];
    }
    vsum
}

/// The bend angle ψ ∈ [0, π] of every edge (angle between the two face normals), signed
/// negative for a concave (reflex) edge. Boundary edges get 0.
pub fn signed_bend_angles(mesh: &PolyMesh, topo: &Topology, unit_normals: &[DVec3]) -> Vec<f64> {
    use rayon::prelude::*;
    let cv = &mesh.corner_verts;
    topo.edge_corner
        .par_iter()
        .with_min_len(4096)
        .map(|&c| {
            let t = topo.twin[c as usize];
            if t == NONE {
                return 0.0;
            }
            let nl = unit_normals[topo.corner_face(c as usize) as usize];
            let nr = unit_normals[topo.corner_face(t as usize) as usize];
            let psi = angle_between(nl, nr);
            let d = mesh.positions[cv[topo.next(c as usize) as usize] as usize]
                - mesh.positions[cv[c as usize] as usize];
            if nl.cross(nr).dot(d) < 0.0 { -psi } else { psi }
        })
        .collect()
}

/// Newell normal of face `f` (as [`face_normal_raw`]) and six times the face's share of the
/// signed volume. For a closed loop the fan from its first vertex gives
/// `Σ_i V₀·(V_i × V_(i+1)) = V₀·Σ_cyclic V_i × V_(i+1) = 2 V₀·N_loop`, so one pass yields both.
#[inline(always)]
pub fn face_normal_and_volume6(mesh: &PolyMesh, f: usize) -> (DVec3, f64) {
    let mut n = DVec3::ZERO;
    let mut v6 = 0.0;
    for l in mesh.face_loops(f) {
        let vs = mesh.loop_verts(l);
        let nl = loop_newell(mesh, vs);
        v6 += 2.0 * mesh.positions[vs[0] as usize].dot(nl);
        n += nl;
    }
    (n, v6)
}

/// Signed volume: Σ over faces and loops of a fan from the loop's first vertex. Negative
/// when a closed solid has turned inside out.
pub fn signed_volume(mesh: &PolyMesh) -> f64 {
    (0..mesh.num_faces())
        .map(|f| face_normal_and_volume6(mesh, f).1)
        .sum::<f64>()
        / 6.0
}

/// The distance from q to the triangle (a, b, c), its inside and its edges.
pub fn point_triangle_distance(q: DVec3, a: DVec3, b: DVec3, c: DVec3) -> f64 {
    // Ericson, Real-Time Collision Detection §5.1.5.
    let (ab, ac, ap) = (b - a, c - a, q - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return q.distance(a);
    }
    let bp = q - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return q.distance(b);
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return q.distance(a + ab * (d1 / (d1 - d3)));
    }
    let cp = q - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return q.distance(c);
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return q.distance(a + ac * (d2 / (d2 - d6)));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return q.distance(b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
    }
    let den = 1.0 / (va + vb + vc);
    q.distance(a + ab * (vb * den) + ac * (vc * den))
}

/// The radius of the circle through three points, `|a−b|·|b−c|·|c−a| / (2·|(b−a)×(c−a)|)`, or
/// `None` where they lie on a line (the measuring tool's three-point radius).
pub fn circumradius(a: DVec3, b: DVec3, c: DVec3) -> Option<f64> {
    let twice_area = (b - a).cross(c - a).length();
    let sides = a.distance(b) * b.distance(c) * c.distance(a);
    (twice_area > 1e-12 * sides.cbrt().powi(2)).then(|| sides / (2.0 * twice_area))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;

    /// Three points of a circle of radius 2 give 2; three on a line give none.
    #[test]
    fn the_circle_through_three_points() {
        let on = |t: f64| DVec3::new(1.0 + 2.0 * t.cos(), -3.0, 2.0 * t.sin());
        let r = circumradius(on(0.1), on(1.3), on(2.9)).unwrap();
        assert!((r - 2.0).abs() < 1e-12, "{r}");
        assert_eq!(circumradius(DVec3::ZERO, DVec3::X, 2.0 * DVec3::X), None);
    }

    #[test]
    fn segments_meet_when_they_cross_touch_or_overlap() {
        let v = DVec2::new;
        let o = v(0.0, 0.0);
        // Crossing, a T, a shared end, collinear overlap: they meet, at any tolerance.
        for tol in [0.0, 1e-9] {
            assert!(segments_meet(o, v(2.0, 2.0), v(0.0, 2.0), v(2.0, 0.0), tol));
            assert!(segments_meet(o, v(2.0, 0.0), v(1.0, 0.0), v(1.0, 3.0), tol));
            assert!(segments_meet(o, v(2.0, 0.0), v(2.0, 0.0), v(3.0, 5.0), tol));
            assert!(segments_meet(o, v(2.0, 0.0), v(1.0, 0.0), v(5.0, 0.0), tol));
            assert!(segments_meet(v(1.0, 1.0), v(1.0, 1.0), o, v(2.0, 2.0), tol));
            // Clear misses: parallel, on one line apart, a T short of the other, a point
            // off the other's line.
            let misses = [
                [o, v(2.0, 0.0), v(0.0, 1.0), v(2.0, 1.0)],
                [o, v(1.0, 0.0), v(2.0, 0.0), v(3.0, 0.0)],
                [o, v(2.0, 0.0), v(1.0, 0.5), v(1.0, 3.0)],
                [v(1.0, 1.0), v(1.0, 1.0), v(3.0, 3.0), v(4.0, 4.0)],
            ];
            for [a, b, c, d] in misses {
                assert!(!segments_meet(a, b, c, d, tol), "{a} {b} {c} {d}");
            }
        }
        // A T short of the other by 1e-12: a miss exactly, a touch within the tolerance.
        let (a, b) = (v(1.0, 1e-12), v(1.0, 3.0));
        assert!(!segments_meet(o, v(2.0, 0.0), a, b, 0.0));
        assert!(segments_meet(o, v(2.0, 0.0), a, b, 1e-9));
        // A square is simple; a bow-tie meets itself at its two crossing sides.
        let square = [o, v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)];
        assert_eq!(outline_meets_itself(&square, 0.0), None);
        let bow = [o, v(1.0, 1.0), v(1.0, 0.0), v(0.0, 1.0)];
        assert_eq!(outline_meets_itself(&bow, 0.0), Some((0, 2)));
    }

    #[test]
    fn volumes_and_normals_of_the_test_solids() {
        assert!((signed_volume(&primitives::cube3()) - 27.0).abs() < 1e-12);
        assert!((signed_volume(&primitives::l_block()) - 12.0).abs() < 1e-12);
        assert!((signed_volume(&primitives::holed_block()) - 8.0).abs() < 1e-12);
        assert!((signed_volume(&primitives::tripod()) - 7.0).abs() < 1e-12);
        let hb = primitives::holed_block();
        // Top face: area 9 - 1 = 8, normal +z.
        let n = face_normal_raw(&hb, 1);
        assert!((n - DVec3::new(0.0, 0.0, 8.0)).length() < 1e-12, "{n}");
    }

    #[test]
    fn bend_angles_sign_concave_edges() {
        let m = primitives::l_block();
        let t = Topology::build(&m).unwrap();
        let n: Vec<DVec3> = face_normals_raw(&m).into_iter().map(unit_or_zero).collect();
        let b = signed_bend_angles(&m, &t, &n);
        let concave = b.iter().filter(|&&x| x < 0.0).count();
        assert_eq!(concave, 1);
        for x in b {
            assert!((x.abs() - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
        }
    }
}
