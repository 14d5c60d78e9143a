//! Loop's smooth masks (Loop 1987; seed 001 eq. 1–2; docs/algorithms/primal.md):
//! - smooth edge point: `⅜(a + b) + ⅛(c + d)` with c, d the vertices opposite the edge;
//! - smooth vertex point of valence n: `(1 − nβ) v + β Σ e_i` with
//!   `β = (⅝ − (⅜ + ¼ cos(2π/n))²)/n`, which is 1/16 at n = 6.
//!
//! β is written here once; the limit masks ([`crate::primal::limit`]) take it from
//! [`beta`]. The cosine is `f64`, as in OpenSubdiv 3.5 (an `f32` cosine differs by 1e-9).

/// Loop's β for valence `n`: the weight of each neighbour in the smooth vertex mask.
#[inline]
pub fn beta(n: usize) -> f64 {
    if n == 6 {
        return 0.0625;
    }
    let inv = 1.0 / n as f64;
    let c = (std::f64::consts::PI * 2.0 * inv).cos();
    let b = 0.25 * c + 0.375;
    (0.625 - b * b) * inv
}

/// Loop's vertex and per-neighbour weights for valence `n`: `(1 − nβ, β)`.
#[inline]
pub fn vertex_weights(n: usize) -> (f64, f64) {
    if n == 6 {
        return (0.625, 0.0625);
    }
    let ew = beta(n);
    (1.0 - ew * n as f64, ew)
}

/// Loop's smooth edge weights: each end vertex, each opposite vertex.
pub const EDGE_WEIGHTS: (f64, f64) = (0.375, 0.125);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_sum_to_one() {
        for n in 3..12 {
            let (v, e) = vertex_weights(n);
            assert!((v + n as f64 * e - 1.0).abs() < 1e-15);
        }
        assert_eq!(vertex_weights(6), (0.625, 0.0625));
        // Valence 3: β = 3/16 (Warren's value coincides with Loop's here).
        let (_, e) = vertex_weights(3);
        assert!((e - 3.0 / 16.0).abs() < 1e-7);
        assert_eq!(2.0 * EDGE_WEIGHTS.0 + 2.0 * EDGE_WEIGHTS.1, 1.0);
    }
}
