//! Doo–Sabin's points on a face with a reflex corner, clamped (docs/algorithms/biquadratic.md,
//! "Concave faces").
//!
//! Eq. (1) pulls every corner towards the vertex centroid, which on an L-shaped face lies in
//! the notch: on the tripod's rounded bottom the reflex corner's point lands outside the face
//! and the arm ends' points cross their arms, so the strips along those sides turn over (9
//! faces at once). With the clamp on, a plain Doo–Sabin step gives such a face — one with a
//! corner reflex by more than 10° whose eq. (1) points leave a side's inner half-plane or
//! turn a side back ([`doo_sabin_holds`]) — the **width offset** instead: each side moves
//! inwards, parallel to itself, by a quarter of the face's width across it (the least distance
//! from the side to a corner not on it, or from its ends to a side not beside it), and each
//! corner's point is where its two moved sides meet. On a parallelogram this is eq. (1)
//! exactly (`V + ¼e₁ + ¼e₂`); on an L it is a smaller L. Every point lies on the inner side of
//! both of its corner's sides, so no strip along a side turns over; the move is then scaled
//! down, as the vector sum's clamp is, until the new outline keeps a quarter of the face's
//! narrowest width and every side a quarter of its length along itself. The combination
//! rule's fold guard gives a face it moves into the vertex blend these points too, where they
//! stay near the face ([`stays_near`]); the blend's other faces keep eq. (1) — the offset on
//! all of them was measured to break more mixes of steps than it mended — except where a new
//! face beside one would still turn over and the offset leaves fewer folded
//! (the fold guard's re-placing, `mend/fold_guard.rs`).

use crate::geometry::segment_distance;
use crate::mesh::PolyMesh;
use glam::DVec3;

/// Whether the outline `v` moved by `s × moves` keeps every point within the largest distance
/// of a corner of `v` from its centroid. On a warped sliver (a dart 0.03 in area that a
/// Catmull–Clark step left on a chamfered tripod) the offset sides meet 2.1 away, outside the
/// face; the fold guard keeps eq. (1) there.
pub(super) fn stays_near(v: &[DVec3], moves: &[DVec3], s: f64) -> bool {
    let c = v.iter().sum::<DVec3>() / v.len().max(1) as f64;
    let radius = v.iter().map(|p| p.distance(c)).fold(0.0, f64::max);
    v.iter()
        .zip(moves)
        .all(|(p, d)| (*p + s * *d).distance(c) <= radius)
}

/// The corners of face `f` (its one loop), in the loop's order.
pub(super) fn corners(m: &PolyMesh, f: usize) -> Vec<DVec3> {
    let l = m.face_loops(f).start;
    m.loop_verts(l)
        .iter()
        .map(|&i| m.positions[i as usize])
        .collect()
}

/// Whether the outline `v` (a face of unit normal `n`) has a corner reflex by more than the
/// angle of sine `reflex_sin` ([`super::RoundingOptions::reflex_sin`]); nearly straight ones
/// keep eq. (1), which handles them.
pub(super) fn has_reflex_corner(v: &[DVec3], n: DVec3, reflex_sin: f64) -> bool {
    let k = v.len();
    (0..k).any(|i| {
        let (e1, e2) = (v[(i + 1) % k] - v[i], v[(i + k - 1) % k] - v[i]);
        n.dot(e1.cross(e2)) < -reflex_sin * e1.length() * e2.length()
    })
}

/// The width offset's move of every corner of the outline `v` (a face of unit normal `n`), in
/// its order.
pub(super) fn width_offset(v: &[DVec3], n: DVec3) -> Vec<DVec3> {
    let k = v.len();
    let next = |i: usize| (i + 1) % k;
    let prev = |i: usize| (i + k - 1) % k;
    // Side i runs from v[i] to v[i + 1]; its inward unit normal.
    let inward: Vec<DVec3> = (0..k)
        .map(|i| n.cross(v[next(i)] - v[i]).normalize_or_zero())
        .collect();
    let width: Vec<f64> = (0..k)
        .map(|i| {
            let (a, b) = (v[i], v[next(i)]);
            let mut w = f64::INFINITY;
            for j in 0..k {
                if j != i && j != next(i) {
                    w = w.min(segment_distance(v[j], a, b));
                }
                if j != i && j != prev(i) && j != next(i) {
                    let (c, d) = (v[j], v[next(j)]);
                    w = w
                        .min(segment_distance(a, c, d))
                        .min(segment_distance(b, c, d));
                }
            }
            w
        })
        .collect();
    (0..k)
        .map(|i| {
            let (s1, s2) = (prev(i), i);
            let (m1, m2) = (inward[s1], inward[s2]);
            let (d1, d2) = (0.25 * width[s1], 0.25 * width[s2]);
            let c = m1.dot(m2);
            let det = 1.0 - c * c;
            if det < 1e-12 {
                if c > 0.0 {
                    0.5 * (d1 + d2) * m1
                } else {
                    DVec3::ZERO
                }
            } else {
                (d1 * (m1 - c * m2) + d2 * (m2 - c * m1)) / det
            }
        })
        .collect()
}

/// Whether eq. (1) keeps face `f` (one loop, unit normal `n`) sound: every point on the inner
/// side of both of its corner's sides, and every side of the new outline running the way its
/// old side runs.
pub(super) fn doo_sabin_holds(m: &PolyMesh, n: DVec3, f: usize) -> bool {
    let l = m.face_loops(f).start;
    let v = corners(m, f);
    let k = v.len();
    let mut p = vec![DVec3::ZERO; k];
    super::doo_sabin::loop_points(m, l, &mut p, m.loop_corners(l).start);
    (0..k).all(|i| {
        let j = (i + 1) % k;
        let side = v[j] - v[i];
        let inward = n.cross(side);
        (p[i] - v[i]).dot(inward) > 0.0
            && (p[j] - v[i]).dot(inward) > 0.0
            && (p[j] - p[i]).dot(side) > 0.0
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn face(points: &[[f64; 2]]) -> PolyMesh {
        let v = points.iter().map(|p| DVec3::new(p[0], p[1], 0.0)).collect();
        PolyMesh::from_polygons(v, &[(0..points.len() as u32).collect()])
    }

    #[test]
    fn on_a_parallelogram_the_width_offset_is_doo_sabin() {
        let m = face(&[[0.0, 0.0], [3.0, 0.0], [4.0, 1.5], [1.0, 1.5]]);
        let v = corners(&m, 0);
        assert!(!has_reflex_corner(&v, DVec3::Z, 0.17));
        let moves = width_offset(&v, DVec3::Z);
        let mut ds = vec![DVec3::ZERO; 4];
        crate::rules::doo_sabin::loop_points(&m, 0, &mut ds, 0);
        for i in 0..4 {
            assert!((v[i] + moves[i]).distance(ds[i]) < 1e-12, "{i}");
        }
        assert!(doo_sabin_holds(&m, DVec3::Z, 0));
    }

    /// The tripod's rounded bottom: arms 0.766 wide and 2.766 long. Eq. (1) puts the reflex
    /// corner's point at (1.287, 1.287), in the notch; the width offset moves the long sides in
    /// by a quarter of 0.766 and the arms' ends by a quarter of 2.0 (their distance to the
    /// reflex corner), and leaves an L with arms half as wide and 0.5 shorter.
    #[test]
    fn on_an_l_the_width_offset_is_a_smaller_l() {
        let (a, b, c) = (0.117, 0.883, 2.883);
        let m = face(&[[a, a], [c, a], [c, b], [b, b], [b, c], [a, c]]);
        assert!(!doo_sabin_holds(&m, DVec3::Z, 0));
        let v = corners(&m, 0);
        assert!(has_reflex_corner(&v, DVec3::Z, 0.17));
        let moves = width_offset(&v, DVec3::Z);
        let (q, e) = (0.25 * (b - a), 0.25 * (c - b));
        let want = [
            [a + q, a + q],
            [c - e, a + q],
            [c - e, b - q],
            [b - q, b - q],
            [b - q, c - e],
            [a + q, c - e],
        ];
        for i in 0..6 {
            let p = v[i] + moves[i];
            assert!(
                p.distance(DVec3::new(want[i][0], want[i][1], 0.0)) < 1e-12,
                "{i}: {p}"
            );
        }
    }
}
