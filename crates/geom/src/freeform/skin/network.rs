//! The curve network of a skin (seed 003 §2 steps 1–4;
//! docs/algorithms/skin.md, "The network"): the virtual trajectory between neighbouring section centres (a
//! rational quadratic, for display), the sweep of each section into the next plane by the
//! minimal rotation `R(N_k → N_(k+1))`, the correspondence of minimal total twist over all n
//! shifts, and the C2 chains through corresponding vertices.

use super::sections::Section;
use crate::freeform::RationalBezier;
use crate::freeform::spline::{self, Cubic};
use glam::{DQuat, DVec3};

/// The minimal rotation taking unit `a` to unit `b` (a U-turn turns about a perpendicular).
pub fn rotation(a: DVec3, b: DVec3, d: DVec3) -> DQuat {
    let axis = a.cross(b);
    let s = axis.length();
    let c = a.dot(b);
    if s > 1e-15 {
        return DQuat::from_axis_angle(axis / s, s.atan2(c));
    }
    if c > 0.0 {
        return DQuat::IDENTITY;
    }
    let mut p = a.cross(d);
    if p.length_squared() < 1e-30 {
        p = a.any_orthonormal_vector();
    }
    DQuat::from_axis_angle(p.normalize(), std::f64::consts::PI)
}

/// Section `a` swept into section `b`'s plane: `C_b + R (V − C_a)`.
pub fn sweep(a: &Section, b: &Section) -> Vec<DVec3> {
    let r = rotation(a.normal, b.normal, b.centre - a.centre);
    a.points
        .iter()
        .map(|&v| b.centre + r * (v - a.centre))
        .collect()
}

/// The shift σ pairing swept vertex i with vertex (i + σ) mod n of the next section: the
/// least total twist `Σ ∠(V'_i − C, V_(i+σ) − C)` over all n shifts; ties by the smaller sum of
/// squared distances, then the smaller σ.
pub fn least_twist(swept: &[DVec3], next: &Section) -> (usize, f64) {
    let n = swept.len();
    let c = next.centre;
    let mut best = (0usize, f64::INFINITY, f64::INFINITY);
    for s in 0..n {
        let (mut twist, mut dist) = (0.0, 0.0);
        for (i, &v) in swept.iter().enumerate() {
            let (a, b) = (v - c, next.points[(i + s) % n] - c);
            twist += a.cross(b).length().atan2(a.dot(b));
            dist += (v - next.points[(i + s) % n]).length_squared();
        }
        let tol = 1e-12 * (1.0 + twist);
        if twist < best.1 - tol || ((twist - best.1).abs() <= tol && dist < best.2) {
            best = (s, twist, dist);
        }
    }
    (best.0, best.1)
}

/// The virtual trajectory from section `a`'s centre to `b`'s (§10.3): a rational quadratic
/// through the tangent lines' meeting point with weight cos(½∠(N_a, N_b)), a cubic Hermite
/// when they meet behind a section, a line when they are parallel.
pub fn trajectory(a: &Section, b: &Section) -> RationalBezier {
    let (c1, c2, n1, n2) = (a.centre, b.centre, a.normal, b.normal);
    let d = c2 - c1;
    let bb = n1.dot(n2);
    let (e, f) = (n1.dot(d), n2.dot(d));
    let den = 1.0 - bb * bb;
    let l = d.length();
    let hermite = || {
        RationalBezier::polynomial(vec![c1, c1 + l / 3.0 * n1, c2 - l / 3.0 * n2, c2])
            .expect("finite points")
    };
    if den <= 1e-12 {
        return if (n1 - d / l).length() < 1e-9 {
            RationalBezier::polynomial(vec![c1, c2]).expect("finite points")
        } else {
            hermite()
        };
    }
    let s = (e - bb * f) / den;
    let t = (bb * e - f) / den;
    if s <= 0.0 || t >= 0.0 {
        return hermite();
    }
    let q = 0.5 * ((c1 + s * n1) + (c2 + t * n2));
    let w = ((1.0 + bb) / 2.0).sqrt();
    RationalBezier::new(vec![c1, q, c2], vec![1.0, w, 1.0]).expect("positive weights")
}

/// The chains: `shifts[k]` is σ between sections k and k + 1; chain i runs through vertex
/// `(i + σ₀ + … + σ_(k−1)) mod n` of section k. Returns, per chain, its K − 1 cubic pieces,
/// and per section the offset of chain 0.
pub fn chains(sections: &[Section], shifts: &[usize]) -> (Vec<Vec<Cubic>>, Vec<usize>) {
    let n = sections[0].points.len();
    let mut offset = vec![0usize; sections.len()];
    for k in 1..sections.len() {
        offset[k] = (offset[k - 1] + shifts[k - 1]) % n;
    }
    let chains = (0..n)
        .map(|i| {
            let q: Vec<DVec3> = sections
                .iter()
                .zip(&offset)
                .map(|(s, &o)| s.points[(i + o) % n])
                .collect();
            spline::open(&q)
        })
        .collect();
    (chains, offset)
}
