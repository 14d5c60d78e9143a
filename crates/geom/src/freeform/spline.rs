//! C2 piecewise cubic curves through a chain of points, as cubic Bézier segments
//! (docs/algorithms/skin.md, "The network"; seed 003 §2).
//!
//! Chord-length intervals `Δ_i = |Q_(i+1) − Q_i|`; the derivatives `T_i` at the points (with
//! respect to the global chord parameter) solve
//!
//! ```text
//! Δ_i T_(i−1) + 2(Δ_(i−1) + Δ_i) T_i + Δ_(i−1) T_(i+1)
//!     = 3 [Δ_i (Q_i − Q_(i−1))/Δ_(i−1) + Δ_(i−1) (Q_(i+1) − Q_i)/Δ_i]
//! ```
//!
//! at every inner point, with natural ends `2T₀ + T₁ = 3(Q₁ − Q₀)/Δ₀`,
//! `T_(m−1) + 2T_m = 3(Q_m − Q_(m−1))/Δ_(m−1)` for an open chain ([`open`]) and the same
//! equation at every point, indices taken cyclically, for a closed one ([`closed`]). Segment i
//! is `Q_i, Q_i + Δ_i T_i/3, Q_(i+1) − Δ_i T_(i+1)/3, Q_(i+1)`. Two points give a straight
//! segment. The points are assumed distinct (the callers check).

use glam::DVec3;

/// One cubic Bézier segment: four control points.
pub type Cubic = [DVec3; 4];

/// Solves the tridiagonal system `a_i x_(i−1) + b_i x_i + c_i x_(i+1) = d_i` (Thomas; `a₀` and
/// `c_(n−1)` unused). The matrices here are diagonally dominant, so no pivoting is needed.
fn tridiagonal(a: &[f64], b: &[f64], c: &[f64], d: &[DVec3]) -> Vec<DVec3> {
    let n = b.len();
    let mut cp = vec![0.0; n];
    let mut dp = vec![DVec3::ZERO; n];
    cp[0] = c[0] / b[0];
    dp[0] = d[0] / b[0];
    for i in 1..n {
        let m = b[i] - a[i] * cp[i - 1];
        cp[i] = c[i] / m;
        dp[i] = (d[i] - a[i] * dp[i - 1]) / m;
    }
    let mut x = dp;
    for i in (0..n - 1).rev() {
        x[i] = x[i] - cp[i] * x[i + 1];
    }
    x
}

fn segments(q: &[DVec3], t: &[DVec3], closed: bool) -> Vec<Cubic> {
    let n = q.len();
    let count = if closed { n } else { n - 1 };
    (0..count)
        .map(|i| {
            let j = (i + 1) % n;
            let d = (q[j] - q[i]).length();
            [q[i], q[i] + d * t[i] / 3.0, q[j] - d * t[j] / 3.0, q[j]]
        })
        .collect()
}

/// The open C2 cubic through `q` (at least 2 points) with natural ends: `q.len() − 1`
/// segments.
pub fn open(q: &[DVec3]) -> Vec<Cubic> {
    let m = q.len() - 1;
    if m == 1 {
        let d = q[1] - q[0];
        return vec![[q[0], q[0] + d / 3.0, q[1] - d / 3.0, q[1]]];
    }
    let delta: Vec<f64> = q.windows(2).map(|w| (w[1] - w[0]).length()).collect();
    let n = m + 1;
    let (mut a, mut b, mut c) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut d = vec![DVec3::ZERO; n];
    b[0] = 2.0;
    c[0] = 1.0;
    d[0] = 3.0 * (q[1] - q[0]) / delta[0];
    for i in 1..m {
        a[i] = delta[i];
        b[i] = 2.0 * (delta[i - 1] + delta[i]);
        c[i] = delta[i - 1];
        d[i] = 3.0
            * (delta[i] * (q[i] - q[i - 1]) / delta[i - 1]
                + delta[i - 1] * (q[i + 1] - q[i]) / delta[i]);
    }
    a[m] = 1.0;
    b[m] = 2.0;
    d[m] = 3.0 * (q[m] - q[m - 1]) / delta[m - 1];
    let t = tridiagonal(&a, &b, &c, &d);
    segments(q, &t, false)
}

/// The closed (periodic) C2 cubic through `q` (at least 3 points): `q.len()` segments, the
/// last from `q[n−1]` back to `q[0]`.
pub fn closed(q: &[DVec3]) -> Vec<Cubic> {
    let n = q.len();
    let delta: Vec<f64> = (0..n).map(|i| (q[(i + 1) % n] - q[i]).length()).collect();
    let prev = |i: usize| (i + n - 1) % n;
    let (mut a, mut b, mut c) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut d = vec![DVec3::ZERO; n];
    for i in 0..n {
        let (dp, di) = (delta[prev(i)], delta[i]);
        a[i] = di;
        b[i] = 2.0 * (dp + di);
        c[i] = dp;
        d[i] = 3.0 * (di * (q[i] - q[prev(i)]) / dp + dp * (q[(i + 1) % n] - q[i]) / di);
    }
    // Cyclic tridiagonal by Sherman–Morrison: A = B + u vᵀ with u = (γ, 0…, c_(n−1)),
    // v = (1, 0…, a₀/γ), γ = −b₀.
    let gamma = -b[0];
    let mut bb = b.clone();
    bb[0] -= gamma;
    bb[n - 1] -= c[n - 1] * a[0] / gamma;
    let x = tridiagonal(&a, &bb, &c, &d);
    let mut u = vec![DVec3::ZERO; n];
    u[0] = DVec3::splat(gamma);
    u[n - 1] = DVec3::splat(c[n - 1]);
    let z = tridiagonal(&a, &bb, &c, &u);
    // Each component is its own scalar system; z is the same for all three.
    let vx = x[0] + a[0] / gamma * x[n - 1];
    let vz = z[0].x + a[0] / gamma * z[n - 1].x;
    let factor = vx / (1.0 + vz);
    let t: Vec<DVec3> = x
        .iter()
        .zip(&z)
        .map(|(&xi, zi)| xi - factor * zi.x)
        .collect();
    segments(q, &t, true)
}

/// Point of a cubic Bézier segment at `t`.
pub fn eval(c: &Cubic, t: f64) -> DVec3 {
    let s = 1.0 - t;
    s * s * s * c[0] + 3.0 * s * s * t * c[1] + 3.0 * s * t * t * c[2] + t * t * t * c[3]
}

/// First derivative of a cubic Bézier segment at `t`.
pub fn derivative(c: &Cubic, t: f64) -> DVec3 {
    let s = 1.0 - t;
    3.0 * (s * s * (c[1] - c[0]) + 2.0 * s * t * (c[2] - c[1]) + t * t * (c[3] - c[2]))
}

/// Second derivative of a cubic Bézier segment at `t`.
pub fn second_derivative(c: &Cubic, t: f64) -> DVec3 {
    6.0 * ((1.0 - t) * (c[2] - 2.0 * c[1] + c[0]) + t * (c[3] - 2.0 * c[2] + c[1]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Derivative with respect to the chord parameter: segment i spans Δ_i.
    fn joints(segs: &[Cubic], closed: bool) -> (f64, f64) {
        let (mut d1, mut d2) = (0.0f64, 0.0f64);
        let n = segs.len();
        let count = if closed { n } else { n - 1 };
        for i in 0..count {
            let (s, t) = (&segs[i], &segs[(i + 1) % n]);
            let (ls, lt) = ((s[3] - s[0]).length(), (t[3] - t[0]).length());
            let a1 = derivative(s, 1.0) / ls;
            let b1 = derivative(t, 0.0) / lt;
            let a2 = second_derivative(s, 1.0) / (ls * ls);
            let b2 = second_derivative(t, 0.0) / (lt * lt);
            d1 = d1.max((a1 - b1).length() / a1.length());
            d2 = d2.max((a2 - b2).length() / a2.length().max(b2.length()).max(1.0));
        }
        (d1, d2)
    }

    fn pts() -> Vec<DVec3> {
        vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.3, 0.1),
            DVec3::new(2.5, -0.2, 0.4),
            DVec3::new(3.0, 1.0, 1.0),
            DVec3::new(2.0, 2.2, 0.5),
        ]
    }

    #[test]
    fn open_chain_is_c2_through_its_points_with_natural_ends() {
        let q = pts();
        let s = open(&q);
        assert_eq!(s.len(), 4);
        for (i, c) in s.iter().enumerate() {
            assert_eq!(c[0], q[i]);
            assert_eq!(c[3], q[i + 1]);
        }
        let (d1, d2) = joints(&s, false);
        assert!(d1 < 1e-13 && d2 < 1e-12, "{d1} {d2}");
        assert!(second_derivative(&s[0], 0.0).length() < 1e-12);
        assert!(second_derivative(&s[3], 1.0).length() < 1e-12);
    }

    #[test]
    fn closed_curve_is_c2_everywhere_and_two_points_give_a_line() {
        let q = pts();
        let s = closed(&q);
        assert_eq!(s.len(), 5);
        let (d1, d2) = joints(&s, true);
        assert!(d1 < 1e-13 && d2 < 1e-12, "{d1} {d2}");
        let l = open(&[DVec3::ZERO, DVec3::new(3.0, 0.0, 0.0)]);
        assert_eq!(l[0][1], DVec3::X);
        // A regular polygon's closed spline keeps its symmetry: equal tangent lengths.
        let sq: Vec<DVec3> = (0..6)
            .map(|k| {
                let a = k as f64 * std::f64::consts::TAU / 6.0;
                DVec3::new(a.cos(), a.sin(), 0.0)
            })
            .collect();
        let c = closed(&sq);
        for seg in &c {
            let r = ((seg[1] - seg[0]).length() - (c[0][1] - c[0][0]).length()).abs();
            assert!(r < 1e-14);
        }
    }
}
