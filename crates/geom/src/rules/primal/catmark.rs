//! Catmull–Clark's smooth masks (Catmull & Clark 1978; seed 000's reference scheme;
//! docs/algorithms/primal.md):
//! - face point: the centroid of the face;
//! - smooth edge point: `¼(a + b) + ¼(F₀ + F₁)` with the two face points; with the
//!   "smooth triangles" option a triangle's face weight is 0.47 (OpenSubdiv's constant):
//!   `w_f = ½(w₀ + w₁)`, `w_v = ½(1 − 2w_f)`;
//! - smooth vertex point of valence n: `((n − 2)/n) v + (1/n²) Σ e_i + (1/n²) Σ F_i`.
//!
//! Everything is `f64`; the references of OpenSubdiv 3.5 agree to 1e-15 of the model size
//! (an `f32` 0.47, as later OpenSubdiv sources spell it, would not: it differs by 1e-9).

use crate::tags::TriangleSubdivision;
use glam::DVec3;

/// The face point: the centroid of the face's vertices.
#[inline]
pub fn face_point(sum: DVec3, n: usize) -> DVec3 {
    sum / n as f64
}

/// Vertex and face weights of a Catmull–Clark smooth edge between faces of `n0` and `n1`
/// corners (asked for only under the smooth triangle rule: the plain weights need no sizes).
#[inline]
pub fn edge_weights(
    tri: TriangleSubdivision,
    sizes: impl FnOnce() -> (usize, usize),
) -> (f64, f64) {
    if tri != TriangleSubdivision::Smooth {
        return (0.25, 0.25);
    }
    let (n0, n1) = sizes();
    if n0 == 3 || n1 == 3 {
        let t = 0.47;
        let w0 = if n0 == 3 { t } else { 0.25 };
        let w1 = if n1 == 3 { t } else { 0.25 };
        let fw = 0.5 * (w0 + w1);
        (0.5 * (1.0 - 2.0 * fw), fw)
    } else {
        (0.25, 0.25)
    }
}

/// Catmull–Clark smooth vertex point from the vertex, the sum of its neighbours along the
/// n edges and the sum of its n face points.
#[inline]
pub fn vertex_point(v: DVec3, edge_sum: DVec3, face_sum: DVec3, n: usize) -> DVec3 {
    let nf = n as f64;
    let vw = (nf - 2.0) / nf;
    let w = 1.0 / (nf * nf);
    vw * v + w * edge_sum + w * face_sum
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_sum_to_one() {
        for n in 3..12 {
            let p = vertex_point(DVec3::ONE, DVec3::ONE * n as f64, DVec3::ONE * n as f64, n);
            assert!((p - DVec3::ONE).length() < 1e-15);
        }
        let (vw, fw) = edge_weights(TriangleSubdivision::Smooth, || (3, 3));
        assert!((2.0 * vw + 2.0 * fw - 1.0).abs() < 1e-15);
        assert_eq!(
            edge_weights(TriangleSubdivision::Catmark, || (3, 3)),
            (0.25, 0.25)
        );
    }
}
