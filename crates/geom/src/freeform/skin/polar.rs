//! Sections with unequal point counts (beyond seed 003, which requires equal counts;
//! docs/algorithms/skin.md, "Unequal point counts").
//!
//! Vertices are inserted **by polar angle after the sweep**, as OpenCascade's polar method
//! does for closed wires: every vertex of section k, swept into section k + 1's plane by the
//! minimal rotation, gives a ray from that section's centre; where no vertex of section k + 1
//! lies on the ray (within 1e-9 rad) one is inserted on its curve where the ray meets it (the
//! piece split by de Casteljau, so the curve does not change). A forward pass and a backward
//! pass leave one vertex on every transported ray in every section: equal counts, and the
//! least-twist pairing of the matched rays has total twist 0. Each section must be star-shaped
//! about its centre (every ray meets its curve once; `sections::check_star`).

use super::SkinError;
use super::network::rotation;
use super::sections::Section;
use crate::freeform::spline::{self, Cubic};
use glam::DVec3;
use std::f64::consts::TAU;

const SAME_RAY: f64 = 1e-9;

/// The polar angle of `p` about the section's centre in its plane, in [0, 2π).
fn angle(s: &Section, x: DVec3, p: DVec3) -> f64 {
    let y = s.normal.cross(x);
    let d = p - s.centre;
    d.dot(y).atan2(d.dot(x)).rem_euclid(TAU)
}

/// Splits a cubic at t (de Casteljau).
fn split(c: &Cubic, t: f64) -> (Cubic, Cubic) {
    let l = |a: DVec3, b: DVec3| a.lerp(b, t);
    let (p01, p12, p23) = (l(c[0], c[1]), l(c[1], c[2]), l(c[2], c[3]));
    let (p012, p123) = (l(p01, p12), l(p12, p23));
    let m = l(p012, p123);
    ([c[0], p01, p012, m], [m, p123, p23, c[3]])
}

/// The frame axis of each section's polar angles.
fn axis(s: &Section) -> DVec3 {
    s.normal.any_orthonormal_vector()
}

/// Inserts into `s` a vertex on the ray at polar angle `alpha`, unless one lies on it.
/// Returns whether it inserted.
fn insert_on_ray(s: &mut Section, x: DVec3, alpha: f64) -> bool {
    let n = s.points.len();
    let diff = |a: f64, b: f64| ((a - b + TAU / 2.0).rem_euclid(TAU) - TAU / 2.0).abs();
    if s.points
        .iter()
        .any(|&p| diff(angle(s, x, p), alpha) < SAME_RAY)
    {
        return false;
    }
    // The piece whose angular span (counter-clockwise) contains alpha.
    for j in 0..n {
        let a0 = angle(s, x, s.points[j]);
        let a1 = angle(s, x, s.points[(j + 1) % n]);
        let span = (a1 - a0).rem_euclid(TAU);
        let off = (alpha - a0).rem_euclid(TAU);
        if off <= 0.0 || off >= span {
            continue;
        }
        // Bisection on the angle along the piece (monotone: the section is star-shaped).
        let piece = s.curve[j];
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            let o = (angle(s, x, spline::eval(&piece, mid)) - a0).rem_euclid(TAU);
            if o < off {
                lo = mid;
            } else {
                hi = mid;
            }
            if hi - lo < 1e-15 {
                break;
            }
        }
        let (a, b) = split(&piece, 0.5 * (lo + hi));
        s.curve[j] = a;
        s.curve.insert(j + 1, b);
        s.points.insert(j + 1, a[3]);
        s.corner.insert(j + 1, false);
        s.original.insert(j + 1, usize::MAX);
        return true;
    }
    false
}

/// Makes every section's count equal by polar insertion; returns the number of inserted
/// vertices per section.
pub(super) fn equalise(sections: &mut [Section]) -> Result<Vec<usize>, SkinError> {
    let m = sections.len();
    let mut inserted = vec![0usize; m];
    let mut carry = |from: usize, to: usize, sections: &mut [Section]| {
        let (a, b) = (&sections[from], &sections[to]);
        let r = rotation(a.normal, b.normal, b.centre - a.centre);
        let x = axis(b);
        let rays: Vec<f64> = a
            .points
            .iter()
            .map(|&v| angle(b, x, b.centre + r * (v - a.centre)))
            .collect();
        for alpha in rays {
            if insert_on_ray(&mut sections[to], x, alpha) {
                inserted[to] += 1;
            }
        }
    };
    for k in 0..m - 1 {
        carry(k, k + 1, sections);
    }
    for k in (1..m).rev() {
        carry(k, k - 1, sections);
    }
    // Rays closer than SAME_RAY share a vertex: two vertices of one section on one ray of the
    // next (a section hundreds of millions of times longer than wide) leave counts unequal.
    if let Some(k) = (1..m).find(|&k| sections[k].points.len() != sections[0].points.len()) {
        return Err(SkinError::NotMatched { a: 0, b: k });
    }
    Ok(inserted)
}
