//! What the G1 constructions of the skin and the envelope share (ALGORITHMS §8.2 step 3):
//! writing a corner leg in the tangent plane spanned by a border's basis vector and tangent.

use glam::DVec3;

/// Least-squares `a ≈ k g + h l` (g, l span the tangent plane); `h = 0` when g ∥ l.
pub fn fit(a: DVec3, g: DVec3, l: DVec3) -> (f64, f64) {
    let (gg, gl, ll) = (g.dot(g), g.dot(l), l.dot(l));
    let (ag, al) = (a.dot(g), a.dot(l));
    let det = gg * ll - gl * gl;
    if det.abs() <= 1e-24 * gg * ll {
        return (ag / gg, 0.0);
    }
    ((ag * ll - al * gl) / det, (al * gg - ag * gl) / det)
}
