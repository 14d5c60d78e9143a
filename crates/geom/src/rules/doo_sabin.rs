//! Doo–Sabin corner points (seed 000 eq. (1); Doo & Sabin 1978).
//!
//! `V_i' = Σ_j W_ij V_j` with `W_ii = (n+5)/(4n)`, `W_ij = (3 + 2cos(2π(i−j)/n))/(4n)`,
//! evaluated in O(n) through the closed form (docs/algorithms/biquadratic.md)
//! `V_i' = ¼V_i + ¾c + (1/2n)(cos(2πi/n)A + sin(2πi/n)B)`, with `c` the vertex centroid,
//! `A = Σ_j cos(2πj/n)V_j`, `B = Σ_j sin(2πj/n)V_j`. Quads use the exact weights
//! 9/16, 3/16, 1/16, 3/16 (no rounding of cos(π/2)). The weights are applied as printed to
//! every n, concave faces included; faces with holes are refused by the caller.

use crate::mesh::PolyMesh;
use glam::DVec3;

/// Writes the Doo–Sabin point of every corner of loop `l` into `out` (indexed by corner).
pub(crate) fn loop_points(m: &PolyMesh, l: usize, out: &mut [DVec3], base: usize) {
    let r = m.loop_corners(l);
    let p = |k: usize| m.positions[m.corner_verts[r.start + k] as usize];
    let n = r.len();
    if n == 4 {
        let v = [p(0), p(1), p(2), p(3)];
        for i in 0..4 {
            out[r.start - base + i] =
                (9.0 * v[i] + 3.0 * v[(i + 1) % 4] + v[(i + 2) % 4] + 3.0 * v[(i + 3) % 4]) / 16.0;
        }
        return;
    }
    let mut centroid = DVec3::ZERO;
    let mut a = DVec3::ZERO;
    let mut b = DVec3::ZERO;
    let step = std::f64::consts::TAU / n as f64;
    for j in 0..n {
        let (s, c) = (step * j as f64).sin_cos();
        let v = p(j);
        centroid += v;
        a += c * v;
        b += s * v;
    }
    centroid /= n as f64;
    for i in 0..n {
        let (s, c) = (step * i as f64).sin_cos();
        out[r.start - base + i] =
            0.25 * p(i) + 0.75 * centroid + (c * a + s * b) / (2.0 * n as f64);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Eq. (1) as a double loop, to check the closed form against.
    fn eq1(v: &[DVec3], i: usize) -> DVec3 {
        let n = v.len();
        (0..n)
            .map(|j| {
                let w = if i == j {
                    (n as f64 + 5.0) / (4.0 * n as f64)
                } else {
                    let d = (i as f64 - j as f64) * std::f64::consts::TAU / n as f64;
                    (3.0 + 2.0 * d.cos()) / (4.0 * n as f64)
                };
                w * v[j]
            })
            .sum()
    }

    #[test]
    fn closed_form_equals_eq1_and_keeps_the_centroid() {
        for n in 3..=10usize {
            let v: Vec<DVec3> = (0..n)
                .map(|k| {
                    DVec3::new(
                        (k * k) as f64 * 0.3 + 1.0,
                        (k as f64).sin() * 2.0,
                        0.1 * k as f64,
                    )
                })
                .collect();
            let m = PolyMesh::from_polygons(v.clone(), &[(0..n as u32).collect()]);
            let mut out = vec![DVec3::ZERO; n];
            loop_points(&m, 0, &mut out, 0);
            for (i, o) in out.iter().enumerate() {
                assert!((*o - eq1(&v, i)).length() < 1e-13, "n={n} i={i}");
            }
            let c0: DVec3 = v.iter().sum::<DVec3>() / n as f64;
            let c1: DVec3 = out.iter().sum::<DVec3>() / n as f64;
            assert!((c0 - c1).length() < 1e-14);
        }
    }

    #[test]
    fn triangle_weights_by_hand() {
        // n = 3: W_ii = 8/12 = 2/3, W_ij = (3 + 2cos(120°))/12 = 1/6.
        let v = vec![
            DVec3::ZERO,
            DVec3::new(6.0, 0.0, 0.0),
            DVec3::new(0.0, 6.0, 0.0),
        ];
        let m = PolyMesh::from_polygons(v, &[vec![0, 1, 2]]);
        let mut out = vec![DVec3::ZERO; 3];
        loop_points(&m, 0, &mut out, 0);
        assert!((out[0] - DVec3::new(1.0, 1.0, 0.0)).length() < 1e-14);
        assert!((out[1] - DVec3::new(4.0, 1.0, 0.0)).length() < 1e-14);
    }
}
