//! Curved edges of a primitive (seed 004 §4.1–4.2, eq. 1 and 2;
//! docs/algorithms/envelope.md, "Curved edges"): the straight edge A–B of a primitive with centre G becomes a
//! rational cubic tangent at both ends to the sphere through them, with end curvature 1/ρ,
//! ρ = t·|V| (t = the end's curvature parameter, V = the end minus G).
//!
//! 1. `V₀ = A − G`, `V₂ = B − G`, central angle γ; the quadratic middle point P₁ is where the
//!    lines through A and B perpendicular to V₀ and V₂ meet in the plane (G, A, B).
//! 2. The arc (A, P₁, B; 1, cos(γ/2), 1) is raised to degree 3 (eq. 2):
//!    `s = 2w/(1 + 2w)`, `P₁⁺ = (1 − s)A + sP₁`, `P₂⁺ = sP₁ + (1 − s)B`.
//! 3. The inner weights come from eq. 1 for the end curvatures κ = 1/ρ:
//!    `w₁ = (4/3)∛(c_s² c_e/(κ_s² κ_e))`, `w₂ = (4/3)∛(c_s c_e²/(κ_s κ_e²))`,
//!    `c_s = area(P₀P₁P₂)/|P₁ − P₀|³`, `c_e = area(P₁P₂P₃)/|P₃ − P₂|³`.
//!
//! t = 1 gives the great-circle arc, t = 3/(1 + 2cos(γ/2)) the polynomial cubic, t → 0 the
//! chord.

use crate::freeform::bezier::RationalBezier;
use glam::DVec3;

/// The share of a third of its chord that a polynomial network curve's leg takes at an end
/// whose curvature parameter is `t`: all of it from t = ½ up, in proportion to t below, so that
/// as t → 0 the curve tends to its chord as every curved edge does. Used by the cubic that
/// replaces a hooked edge piece (`clip.rs`) and by fusion edges (`fusion.rs`); legs of a third
/// at every t left them bulging between edges that hug their chords, with ten times their
/// speed at a shared corner at t = 0.1, and the patches there folded (envelope.md, "Hooked
/// pieces at small t", "Fusion edges at small t").
pub(super) fn legs_for(t: f64) -> f64 {
    (2.0 * t).min(1.0)
}

/// The curved edge from `a` to `b` about centre `g`, with curvature parameters `ta`, `tb`
/// (> 0). `None` when the edge is degenerate (zero length, or through or opposite the centre).
pub fn curved_edge(g: DVec3, a: DVec3, b: DVec3, ta: f64, tb: f64) -> Option<RationalBezier> {
    let (v0, v2) = (a - g, b - g);
    let nrm = v0.cross(v2);
    if nrm.length() <= 1e-12 * v0.length() * v2.length() {
        return None;
    }
    // P₁ = A + α (n × V₀) = B + β (V₂ × n)... solved in the plane: P₁ − G satisfies
    // (P₁ − G)·V₀ = |V₀|², (P₁ − G)·V₂ = |V₂|², (P₁ − G)·n = 0.
    let m = glam::DMat3::from_cols(v0, v2, nrm).transpose();
    let q = m.inverse() * DVec3::new(v0.length_squared(), v2.length_squared(), 0.0);
    let p1 = g + q;
    let cos_g = (v0.dot(v2) / (v0.length() * v2.length())).clamp(-1.0, 1.0);
    let w = ((1.0 + cos_g) / 2.0).sqrt();
    let s = 2.0 * w / (1.0 + 2.0 * w);
    let c1 = a.lerp(p1, s);
    let c2 = b.lerp(p1, s);
    let area = |p: DVec3, q: DVec3, r: DVec3| 0.5 * (q - p).cross(r - q).length();
    let cs = area(a, c1, c2) / (c1 - a).length().powi(3);
    let ce = area(c1, c2, b) / (b - c2).length().powi(3);
    let ks = 1.0 / (ta * v0.length());
    let ke = 1.0 / (tb * v2.length());
    let w1 = 4.0 / 3.0 * (cs * cs * ce / (ks * ks * ke)).cbrt();
    let w2 = 4.0 / 3.0 * (cs * ce * ce / (ks * ke * ke)).cbrt();
    RationalBezier::new(vec![a, c1, c2, b], vec![1.0, w1, w2, 1.0]).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube_edge(t: f64) -> RationalBezier {
        curved_edge(
            DVec3::ZERO,
            DVec3::new(-1.0, -1.0, 1.0),
            DVec3::new(1.0, -1.0, 1.0),
            t,
            t,
        )
        .unwrap()
    }

    /// t = 1: the great-circle arc (on the sphere to 1e-12) with curvature 1/r at its ends.
    #[test]
    fn t_one_is_the_great_circle_arc() {
        let r = 3f64.sqrt();
        let c = cube_edge(1.0);
        for k in 0..=100 {
            let p = c.eval(k as f64 / 100.0);
            assert!((p.length() - r).abs() < 1e-12, "{k}: {}", p.length());
        }
        for t in [0.0, 1.0] {
            assert!((c.curvature(t) * r - 1.0).abs() < 1e-12);
        }
    }

    /// The end curvature is 1/(t r) at each end, for unequal t too (eq. 1).
    #[test]
    fn end_curvatures_follow_t() {
        let r = 3f64.sqrt();
        let c = curved_edge(
            DVec3::ZERO,
            DVec3::new(-1.0, -1.0, 1.0),
            DVec3::new(1.0, -1.0, 1.0),
            0.4,
            1.3,
        )
        .unwrap();
        assert!((c.curvature(0.0) * 0.4 * r - 1.0).abs() < 1e-11);
        assert!((c.curvature(1.0) * 1.3 * r - 1.0).abs() < 1e-11);
    }

    /// The mid-curve point moves monotonically towards the chord as t falls; t = 3/(1+2cos θ)
    /// is the polynomial cubic.
    #[test]
    fn mid_point_moves_monotonically_with_t() {
        let mut last = f64::INFINITY;
        for t in [2.0, 1.5, 1.0, 0.7, 0.5, 0.3, 0.1, 0.01, 1e-4] {
            let d = cube_edge(t).eval(0.5).y + 1.0; // distance below the chord's y = −1 … outwards
            let out = -d;
            assert!(out < last, "t = {t}: {out} ≥ {last}");
            last = out;
        }
        assert!(last.abs() < 1e-3, "t → 0 tends to the chord: {last}");
        let theta = (1.0f64 / 3.0).acos() / 2.0; // half the central angle of a cube edge
        let tp = 3.0 / (1.0 + 2.0 * theta.cos());
        assert!((tp - 1.139388).abs() < 1e-6, "{tp}");
        let c = cube_edge(tp);
        for w in &c.weights {
            assert!((w - 1.0).abs() < 1e-12, "{:?}", c.weights);
        }
    }
}
