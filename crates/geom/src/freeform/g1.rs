//! What the G1 constructions of the skin and the envelope share (docs/algorithms/skin.md, "Patches and G1"):
//! writing a corner leg in the tangent plane spanned by a border's basis vector and tangent,
//! and the cubic Hermite basis the Coons blends (vector and scalar) interpolate across with.

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

/// The cubic Hermite basis `H₀, H₁, G₀, G₁` at t: values at 0 and 1, then derivatives at 0 and 1.
pub fn hermite(t: f64) -> [f64; 4] {
    let (t2, t3) = (t * t, t * t * t);
    [
        2.0 * t3 - 3.0 * t2 + 1.0,
        -2.0 * t3 + 3.0 * t2,
        t3 - 2.0 * t2 + t,
        t3 - t2,
    ]
}
