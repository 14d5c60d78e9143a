//! Rational Bézier curves of any degree in space (Farin, *Curves and Surfaces for CAGD*,
//! ch. 13; seeds 003 and 004 build their trajectories and primitive edges from them;
//! docs/algorithms/bezier.md).
//!
//! `C(t) = Σ B_i^n(t) w_i P_i / Σ B_i^n(t) w_i` with the Bernstein polynomials `B_i^n`. Every
//! operation works on the homogeneous points `(w_i P_i, w_i)` in 4D, where the curve is a
//! polynomial Bézier curve:
//!
//! - evaluation: de Casteljau in 4D, then the projection (stable for t ∈ [0, 1]);
//! - derivatives: with `A(t) = Σ B_i w_i P_i` and `w(t) = Σ B_i w_i`, `C = A/w`,
//!   `C' = (A' − w'C)/w`, `C'' = (A'' − 2w'C' − w''C)/w`, where `A'`, `w'` are the hodograph
//!   (`n Δ` of the homogeneous points) evaluated by de Casteljau (in buffers on the stack up to
//!   8 points: curves are evaluated without allocating);
//! - curvature `κ = |C' × C''| / |C'|³`;
//! - degree elevation `Q_i = (i/(n+1)) P_(i−1) + (1 − i/(n+1)) P_i` in 4D (the same curve);
//! - splitting at t: the two outer edges of the de Casteljau triangle in 4D.
//!
//! Weights must be positive (the curve then lies in the convex hull of its points); a
//! quarter circle is the quadratic with weights `1, cos(φ/2), 1` for an arc of angle φ.

use glam::{DVec3, DVec4};
use thiserror::Error;

#[derive(Debug, Clone, PartialEq, Error)]
pub enum BezierError {
    #[error("a Bézier curve needs at least 2 control points, this one has {0}")]
    TooFewPoints(usize),
    #[error("{points} control points but {weights} weights")]
    WeightCount { points: usize, weights: usize },
    #[error("weight {index} is {weight}: weights must be finite and > 0")]
    BadWeight { index: usize, weight: f64 },
    #[error("control point {index} is not finite")]
    NonFinite { index: usize },
}

/// A rational Bézier curve: control points and their weights.
#[derive(Debug, Clone, PartialEq)]
pub struct RationalBezier {
    pub points: Vec<DVec3>,
    pub weights: Vec<f64>,
}

/// Position and first two derivatives at a parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Derivatives {
    pub point: DVec3,
    pub d1: DVec3,
    pub d2: DVec3,
}

/// Control points up to which [`RationalBezier::eval`] and [`RationalBezier::derivatives`] work
/// in a buffer on the stack.
const ON_STACK: usize = 8;

/// de Casteljau on 4D points, in place: the value at t.
fn casteljau(q: &mut [DVec4], t: f64) -> DVec4 {
    for k in (1..q.len()).rev() {
        for i in 0..k {
            q[i] = q[i].lerp(q[i + 1], t);
        }
    }
    q.first().copied().unwrap_or(DVec4::ZERO)
}

/// A homogeneous cubic at t, by its Bernstein polynomials.
fn cubic_point(h: &[DVec4; 4], t: f64) -> DVec4 {
    let s = 1.0 - t;
    h[0] * (s * s * s) + h[1] * (3.0 * s * s * t) + h[2] * (3.0 * s * t * t) + h[3] * (t * t * t)
}

/// A homogeneous cubic's first derivative at t.
fn cubic_first(h: &[DVec4; 4], t: f64) -> DVec4 {
    let s = 1.0 - t;
    3.0 * ((h[1] - h[0]) * (s * s) + (h[2] - h[1]) * (2.0 * s * t) + (h[3] - h[2]) * (t * t))
}

/// The hodograph (control points of the derivative, `n Δ`) of the polynomial 4D Bézier curve
/// `p`, into `out` (one point fewer).
fn hodograph(p: &[DVec4], out: &mut [DVec4]) {
    let n = (p.len() - 1) as f64;
    for (o, w) in out.iter_mut().zip(p.windows(2)) {
        *o = n * (w[1] - w[0]);
    }
}

impl RationalBezier {
    /// A curve, checked: at least 2 points, one positive finite weight per point.
    pub fn new(points: Vec<DVec3>, weights: Vec<f64>) -> Result<RationalBezier, BezierError> {
        if points.len() < 2 {
            return Err(BezierError::TooFewPoints(points.len()));
        }
        if weights.len() != points.len() {
            return Err(BezierError::WeightCount {
                points: points.len(),
                weights: weights.len(),
            });
        }
        if let Some((index, &weight)) = weights
            .iter()
            .enumerate()
            .find(|(_, w)| !(w.is_finite() && **w > 0.0))
        {
            return Err(BezierError::BadWeight { index, weight });
        }
        if let Some(index) = points.iter().position(|p| !p.is_finite()) {
            return Err(BezierError::NonFinite { index });
        }
        Ok(RationalBezier { points, weights })
    }

    /// A polynomial curve (all weights 1).
    pub fn polynomial(points: Vec<DVec3>) -> Result<RationalBezier, BezierError> {
        let w = vec![1.0; points.len()];
        RationalBezier::new(points, w)
    }

    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }

    fn homogeneous(&self) -> Vec<DVec4> {
        self.points
            .iter()
            .zip(&self.weights)
            .map(|(p, &w)| (*p * w).extend(w))
            .collect()
    }

    fn from_homogeneous(h: &[DVec4]) -> RationalBezier {
        RationalBezier {
            points: h.iter().map(|q| q.truncate() / q.w).collect(),
            weights: h.iter().map(|q| q.w).collect(),
        }
    }

    /// `f` of the homogeneous control points, in a buffer on the stack up to [`ON_STACK`]
    /// points (every curve of the network and the skins' sections: evaluation without
    /// allocating).
    fn with_homogeneous<R>(&self, f: impl FnOnce(&mut [DVec4]) -> R) -> R {
        let n = self.points.len();
        if n <= ON_STACK {
            let mut buf = [DVec4::ZERO; ON_STACK];
            for (b, (p, &w)) in buf.iter_mut().zip(self.points.iter().zip(&self.weights)) {
                *b = (*p * w).extend(w);
            }
            f(&mut buf[..n])
        } else {
            f(&mut self.homogeneous())
        }
    }

    /// The point at parameter t.
    pub fn eval(&self, t: f64) -> DVec3 {
        if let Some(h) = self.cubic() {
            let q = cubic_point(&h, t);
            return q.truncate() / q.w;
        }
        let q = self.with_homogeneous(|h| casteljau(h, t));
        q.truncate() / q.w
    }

    /// The point and its first derivative at t (a cubic in closed form, any other degree from
    /// [`RationalBezier::derivatives`]).
    pub fn point_and_tangent(&self, t: f64) -> (DVec3, DVec3) {
        let Some(h) = self.cubic() else {
            let d = self.derivatives(t);
            return (d.point, d.d1);
        };
        let (q, q1) = (cubic_point(&h, t), cubic_first(&h, t));
        let c = q.truncate() / q.w;
        (c, (q1.truncate() - q1.w * c) / q.w)
    }

    /// The homogeneous control points of a cubic (the network's curves are all cubics: the
    /// closed forms below are their fast path).
    fn cubic(&self) -> Option<[DVec4; 4]> {
        (self.points.len() == 4).then(|| {
            std::array::from_fn(|i| (self.points[i] * self.weights[i]).extend(self.weights[i]))
        })
    }

    /// The point and its first and second derivatives at t: de Casteljau in homogeneous space
    /// on the points and on their first and second hodographs, then the quotient rule.
    pub fn derivatives(&self, t: f64) -> Derivatives {
        let (q, q1, q2) = if let Some(h) = self.cubic() {
            let s = 1.0 - t;
            let second = 6.0 * (s * (h[2] - 2.0 * h[1] + h[0]) + t * (h[3] - 2.0 * h[2] + h[1]));
            (cubic_point(&h, t), cubic_first(&h, t), second)
        } else {
            self.general_derivatives(t)
        };
        let (w, w1, w2) = (q.w, q1.w, q2.w);
        let c = q.truncate() / w;
        let d1 = (q1.truncate() - w1 * c) / w;
        let d2 = (q2.truncate() - 2.0 * w1 * d1 - w2 * c) / w;
        Derivatives { point: c, d1, d2 }
    }

    /// The homogeneous point and its first and second derivatives at t for any degree.
    fn general_derivatives(&self, t: f64) -> (DVec4, DVec4, DVec4) {
        self.with_homogeneous(|h| {
            let m = h.len();
            let (mut stack1, mut stack2) = ([DVec4::ZERO; ON_STACK], [DVec4::ZERO; ON_STACK]);
            let (mut heap1, mut heap2);
            let (d1, d2): (&mut [DVec4], &mut [DVec4]) = if m <= ON_STACK {
                (&mut stack1[..m - 1], &mut stack2[..m - 2])
            } else {
                (heap1, heap2) = (vec![DVec4::ZERO; m - 1], vec![DVec4::ZERO; m - 2]);
                (&mut heap1, &mut heap2)
            };
            hodograph(h, d1);
            hodograph(d1, d2);
            let q2 = if d1.len() >= 2 {
                casteljau(d2, t)
            } else {
                DVec4::ZERO
            };
            (casteljau(h, t), casteljau(d1, t), q2)
        })
    }

    /// Curvature `|C' × C''| / |C'|³` at t (0 where the tangent vanishes).
    pub fn curvature(&self, t: f64) -> f64 {
        let d = self.derivatives(t);
        let s = d.d1.length();
        if s == 0.0 {
            return 0.0;
        }
        d.d1.cross(d.d2).length() / (s * s * s)
    }

    /// The same curve one degree higher.
    pub fn elevated(&self) -> RationalBezier {
        let h = self.homogeneous();
        let n1 = h.len() as f64;
        let mut q = Vec::with_capacity(h.len() + 1);
        q.push(h[0]);
        for i in 1..h.len() {
            let a = i as f64 / n1;
            q.push(a * h[i - 1] + (1.0 - a) * h[i]);
        }
        q.push(h[h.len() - 1]);
        RationalBezier::from_homogeneous(&q)
    }

    /// The pieces `[0, t]` and `[t, 1]`, each reparametrised to `[0, 1]`.
    pub fn split(&self, t: f64) -> (RationalBezier, RationalBezier) {
        let mut q = self.homogeneous();
        let n = q.len();
        let mut left = Vec::with_capacity(n);
        let mut right = Vec::with_capacity(n);
        left.push(q[0]);
        right.push(q[n - 1]);
        for k in (1..n).rev() {
            for i in 0..k {
                q[i] = q[i].lerp(q[i + 1], t);
            }
            left.push(q[0]);
            right.push(q[k - 1]);
        }
        right.reverse();
        (
            RationalBezier::from_homogeneous(&left),
            RationalBezier::from_homogeneous(&right),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    /// The arc of the unit circle from angle 0 to φ as a rational quadratic.
    fn arc(phi: f64) -> RationalBezier {
        let mid = DVec3::new(1.0, (phi / 2.0).tan(), 0.0);
        RationalBezier::new(
            vec![DVec3::X, mid, DVec3::new(phi.cos(), phi.sin(), 0.0)],
            vec![1.0, (phi / 2.0).cos(), 1.0],
        )
        .unwrap()
    }

    #[test]
    fn a_conic_arc_lies_on_its_circle_with_curvature_one() {
        for phi in [0.3, FRAC_PI_2, 2.0] {
            let c = arc(phi);
            for k in 0..=20 {
                let t = k as f64 / 20.0;
                assert!((c.eval(t).length() - 1.0).abs() < 1e-14, "φ {phi} t {t}");
                assert!((c.curvature(t) - 1.0).abs() < 1e-12, "φ {phi} t {t}");
            }
        }
    }

    #[test]
    fn derivatives_match_finite_differences() {
        let c = RationalBezier::new(
            vec![
                DVec3::ZERO,
                DVec3::new(1.0, 2.0, 0.5),
                DVec3::new(3.0, -1.0, 1.0),
                DVec3::new(4.0, 1.0, -0.5),
            ],
            vec![1.0, 0.4, 2.5, 0.8],
        )
        .unwrap();
        let h = 1e-5;
        for t in [0.1, 0.37, 0.8] {
            let d = c.derivatives(t);
            let fd1 = (c.eval(t + h) - c.eval(t - h)) / (2.0 * h);
            let fd2 = (c.eval(t + h) - 2.0 * c.eval(t) + c.eval(t - h)) / (h * h);
            assert!((d.d1 - fd1).length() < 1e-6 * d.d1.length(), "{t}");
            assert!((d.d2 - fd2).length() < 1e-3 * d.d2.length().max(1.0), "{t}");
        }
    }

    #[test]
    fn elevation_and_splitting_keep_the_curve() {
        let c = arc(2.0);
        let e = c.elevated().elevated();
        assert_eq!(e.degree(), 4);
        let (l, r) = c.split(0.3);
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            assert!((e.eval(t) - c.eval(t)).length() < 1e-14);
            assert!((l.eval(t) - c.eval(0.3 * t)).length() < 1e-14);
            assert!((r.eval(t) - c.eval(0.3 + 0.7 * t)).length() < 1e-14);
        }
        // The pieces of a circle are circles: curvature stays 1.
        assert!((l.curvature(0.5) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn bad_input_is_refused_by_name() {
        let p = vec![DVec3::ZERO, DVec3::X];
        assert!(matches!(
            RationalBezier::new(p.clone(), vec![1.0, 0.0]),
            Err(BezierError::BadWeight { index: 1, .. })
        ));
        assert!(matches!(
            RationalBezier::new(p.clone(), vec![1.0]),
            Err(BezierError::WeightCount { .. })
        ));
        assert!(matches!(
            RationalBezier::polynomial(vec![DVec3::ZERO]),
            Err(BezierError::TooFewPoints(1))
        ));
        assert!(matches!(
            RationalBezier::polynomial(vec![DVec3::ZERO, DVec3::NAN]),
            Err(BezierError::NonFinite { index: 1 })
        ));
    }
}
