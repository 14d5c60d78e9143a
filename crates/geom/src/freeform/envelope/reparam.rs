//! A patch side run along its curve at nearly even speed (docs/algorithms/envelope.md,
//! "Sides run along their curves"): `τ = φ(s)`, φ the inverse of the curve's arc length as a share
//! of the whole, through [`NODES`] + 1 samples joined by monotone cubic Hermite pieces
//! (Fritsch–Carlson: each node's slope is the exact `L/|C′(τ)|`, capped at three times the
//! secants beside it so that every piece stays monotone). A rational edge for small t runs
//! through its ends a hundred times slower than through its middle; run by φ, the patch's
//! iso-lines across meet the side where the opposite side's do. G1 with the patch across holds
//! whatever φ is, since the cross derivative is taken in the plane of g and C′ at the same
//! curve point.

use super::coons::hermite;
use crate::freeform::bezier::RationalBezier;

/// Pieces of φ.
const NODES: usize = 32;

/// Steps of the arc-length table each piece is found from.
const STEPS: usize = 16;

/// φ: the curve parameter at side parameter s, with its slope.
#[derive(Debug, Clone, PartialEq)]
pub struct Reparam {
    /// τ at s = i / NODES.
    tau: Vec<f64>,
    /// dτ/ds there.
    slope: Vec<f64>,
}

impl Reparam {
    /// φ running `curve` at nearly even speed, or `None` for a curve of no length.
    pub fn arc_length(curve: &RationalBezier) -> Option<Reparam> {
        Reparam::following(curve, |s| (s, 1.0))
    }

    /// φ running `curve` so that at s it has covered the share `target(s).0` of its length
    /// (`target(s).1` the share's s-derivative; monotone, 0 at 0 and 1 at 1).
    pub fn following(
        curve: &RationalBezier,
        target: impl Fn(f64) -> (f64, f64),
    ) -> Option<Reparam> {
        let length = length_table(curve)?;
        let n = length.len() - 1;
        let total = length[n];
        let targets: Vec<(f64, f64)> = (0..=NODES)
            .map(|i| target(i as f64 / NODES as f64))
            .collect();
        // τ where the length is the share targets[i] of the whole, the table read linearly.
        let mut tau = Vec::with_capacity(NODES + 1);
        let mut j = 0;
        for &(share, _) in &targets {
            let want = total * share;
            while j + 1 < n && length[j + 1] < want {
                j += 1;
            }
            let span = length[j + 1] - length[j];
            let f = if span > 0.0 {
                ((want - length[j]) / span).clamp(0.0, 1.0)
            } else {
                0.0
            };
            tau.push((j as f64 + f) / n as f64);
        }
        tau[0] = 0.0;
        tau[NODES] = 1.0;
        let h = 1.0 / NODES as f64;
        let secant: Vec<f64> = tau.windows(2).map(|w| (w[1] - w[0]) / h).collect();
        let slope = (0..=NODES)
            .map(|i| {
                let speed = curve.derivatives(tau[i]).d1.length();
                let rate = targets[i].1;
                let exact = if speed > 0.0 {
                    rate * total / speed
                } else {
                    f64::INFINITY
                };
                let beside = match i {
                    0 => secant[0],
                    _ if i == NODES => secant[NODES - 1],
                    _ => secant[i - 1].min(secant[i]),
                };
                exact.min(3.0 * beside).max(0.0)
            })
            .collect();
        Some(Reparam { tau, slope })
    }

    /// φ(s) and φ′(s).
    pub fn at(&self, s: f64) -> (f64, f64) {
        let x = s.clamp(0.0, 1.0) * NODES as f64;
        let i = (x.floor() as usize).min(NODES - 1);
        let u = x - i as f64;
        let h = 1.0 / NODES as f64;
        let (p0, p1) = (self.tau[i], self.tau[i + 1]);
        let (m0, m1) = (self.slope[i] * h, self.slope[i + 1] * h);
        let [h0, h1, g0, g1] = hermite(u);
        let value = h0 * p0 + g0 * m0 + h1 * p1 + g1 * m1;
        let u2 = u * u;
        let d = (6.0 * u2 - 6.0 * u) * p0
            + (3.0 * u2 - 4.0 * u + 1.0) * m0
            + (-6.0 * u2 + 6.0 * u) * p1
            + (3.0 * u2 - 2.0 * u) * m1;
        (value, d * NODES as f64)
    }

    /// The s at which φ(s) = τ (φ is monotone: bisection).
    pub fn inverse(&self, tau: f64) -> f64 {
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if self.at(mid).0 < tau {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }
}

/// The share of `curve`'s length covered at parameter s, and its s-derivative, from a table
/// of [`NODES`] × [`STEPS`] chords read linearly.
pub fn arc_share(curve: &RationalBezier) -> Option<impl Fn(f64) -> (f64, f64) + '_> {
    let length = length_table(curve)?;
    let n = length.len() - 1;
    let total = length[n];
    Some(move |s: f64| {
        let x = s.clamp(0.0, 1.0) * n as f64;
        let i = (x.floor() as usize).min(n - 1);
        let f = x - i as f64;
        let share = (length[i] + f * (length[i + 1] - length[i])) / total;
        (share, curve.derivatives(s).d1.length() / total)
    })
}

/// The curve's length from τ = 0 to each of [`NODES`] × [`STEPS`] + 1 even steps of τ (chords
/// summed), or `None` for a curve of no length, or one not finite.
fn length_table(curve: &RationalBezier) -> Option<Vec<f64>> {
    let n = NODES * STEPS;
    let mut length = vec![0.0; n + 1];
    let mut prev = curve.eval(0.0);
    for i in 1..=n {
        let p = curve.eval(i as f64 / n as f64);
        length[i] = length[i - 1] + p.distance(prev);
        prev = p;
    }
    let total = length[n];
    (total > 0.0 && total.is_finite()).then_some(length)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// A rational cubic of weights 1, 0.037, 0.0048, 1 (the bundled five's edge at t = 0.01)
    /// covers 2 % of its length in the first fifth of its parameter; run by φ it covers each
    /// share of its length within a hundredth of that share of s, φ runs from 0 to 1
    /// monotonically, φ′ is its difference quotient, and the inverse finds s again.
    #[test]
    fn arc_length_spreads_a_crowded_curve() {
        let curve = RationalBezier::new(
            vec![
                DVec3::ZERO,
                DVec3::new(0.4, 0.1, 0.0),
                DVec3::new(0.8, 0.1, 0.0),
                DVec3::new(1.2, 0.0, 0.0),
            ],
            vec![1.0, 0.037, 0.0048, 1.0],
        )
        .unwrap();
        let share = arc_share(&curve).unwrap();
        assert!(share(0.2).0 < 0.05, "{}", share(0.2).0);
        let phi = Reparam::arc_length(&curve).unwrap();
        assert_eq!(phi.at(0.0).0, 0.0);
        assert_eq!(phi.at(1.0).0, 1.0);
        let mut last = -1.0;
        for i in 0..=1000 {
            let s = i as f64 / 1000.0;
            let (tau, d) = phi.at(s);
            assert!(tau >= last && d >= 0.0, "s = {s}");
            last = tau;
            assert!((share(tau).0 - s).abs() < 0.01, "s = {s}: {}", share(tau).0);
            assert!((phi.inverse(tau) - s).abs() < 1e-9, "s = {s}");
            let h = 1e-7;
            let (lo, hi) = ((s - h).max(0.0), (s + h).min(1.0));
            let fd = (phi.at(hi).0 - phi.at(lo).0) / (hi - lo);
            assert!(
                (fd - d).abs() < 1e-4 * (1.0 + d),
                "s = {s}: {fd} against {d}"
            );
        }
    }
}
