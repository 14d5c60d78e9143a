//! Aesthetic subdivision curves (seed 002, Ashida, Nakamura, Furuya, Saito; docs/algorithms/curves.md):
//! Catmull–Clark curve subdivision and the paper's two variants, one refinement loop for all.
//!
//! One level keeps every vertex, moved by the scheme's vertex rule, and inserts every edge
//! midpoint `P₁₂ = ½(P₁ + P₂)`: m points become 2m (closed) or 2m − 1 (open; the two end
//! points stay where they are, the end-interpolating B-spline rule). For consecutive
//! P₁, P₂, P₃ with edge points P₁₂, P₂₃ the new P₂ is:
//!
//! - **Catmull–Clark** (uniform cubic B-spline): `P' = ½ P₂ + ¼ (P₁₂ + P₂₃) = (P₁ + 6P₂ + P₃)/8`.
//! - **Method 1, circle-preserving** (eq. 3.1): `P' = ω (P₁₂ + P₂₃) + (1 − 2ω) P₂` with
//!   `ω = 1/(4 cos²(θ₀/4))`, θ₀ the turning angle at P₂. Evaluated trig-free:
//!   `cos²(θ₀/4) = (1 + cos(θ₀/2))/2`, `cos(θ₀/2) = √((1 + cos θ₀)/2)`, so
//!   `ω = 1/(2 + 2√((1 + cos θ₀)/2))`. A regular n-gon of circumradius R becomes the regular
//!   2n-gon of circumradius R cos(π/n): circles are kept; at θ₀ = 0 it is the B-spline rule.
//! - **Method 2, log-spiral-preserving** (eq. 3.2–3.4). The printed (3.3) is damaged
//!   ("sin^(1/2) θ₁"; θ₁ depends on the unknown P'). Derivation: a logarithmic spiral
//!   sampled at equal angle steps is `z_j = C + A m^j` in complex numbers, with the constant
//!   ratio `m = (z_(j+1) − z_j)/(z_j − z_(j−1))` (|m| = k the edge-length ratio, arg m = θ₀ the
//!   turning angle). Midpoints of such a sequence are such a sequence with the same C and
//!   m, so refinement must produce the half-step sequence, ratio √m: the new triangle
//!   P₁₂ P' P₂₃ has edge ratio `b₁/a₁ = √k` and turning angle `θ₁ = θ₀/2`. Then in (3.4)
//!   `a₁ = |P₁₂P'| = l₁/√(1 + k + 2√k cos θ₁)` and `α₁ = atan2(√k sin θ₁, 1 + √k cos θ₁)`
//!   (the sine law `sin α₁ = √k (a₁/l₁) sin θ₁` is the likely original of the printed
//!   (3.3)). Substituted into (3.4) all of it collapses to
//!   `P' = P₁₂ + (P₂₃ − P₁₂)/(1 + √m)` with `m = (P₃ − P₂)/(P₂ − P₁)` as a complex quotient
//!   and the principal square root: no trigonometry, no division by sin α₀, exact on
//!   spirals and (k = 1) on circles. At an exact reversal (m real and negative) the square
//!   root is ambiguous; there method 1 is used.
//!
//! Curvature: the signed curvature of the circle through three consecutive points,
//! `κ = 2 (d₁ × d₂)/(|d₁||d₂||P₃ − P₁|)`; its centre is a point of the evolute (fig. 4).

use glam::DVec2;
use serde::{Deserialize, Serialize};
use thiserror::Error;

/// The three schemes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum CurveScheme {
    CatmullClark,
    Circle,
    LogSpiral,
}

impl CurveScheme {
    pub const ALL: [CurveScheme; 3] = [
        CurveScheme::CatmullClark,
        CurveScheme::Circle,
        CurveScheme::LogSpiral,
    ];
    pub fn name(self) -> &'static str {
        match self {
            CurveScheme::CatmullClark => "catmull-clark",
            CurveScheme::Circle => "circle",
            CurveScheme::LogSpiral => "log-spiral",
        }
    }
    pub fn from_name(s: &str) -> Option<CurveScheme> {
        CurveScheme::ALL.into_iter().find(|c| c.name() == s)
    }
}

/// An open or closed polyline in the plane.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Polyline {
    pub closed: bool,
    pub points: Vec<DVec2>,
}

/// A curve as the user edits and saves it: the control polyline, the scheme that refines it
/// and how many levels are shown (the Curves tab's part of a document, the `"curve"` block of
/// a `.prism.json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CurveSketch {
    #[serde(flatten)]
    pub control: Polyline,
    pub scheme: CurveScheme,
    pub levels: usize,
}

/// The most levels a sketch may ask for (a 6-point polygon becomes 1536 points at 8).
pub const MAX_SKETCH_LEVELS: usize = 8;

impl Default for CurveSketch {
    /// Seed 002's fig. 6 polyline (θ₁ = 60°, θ₂ = 30°, l₁ = l₂ = 1) under method 1.
    fn default() -> Self {
        CurveSketch {
            control: presets::fig6(60f64.to_radians(), 30f64.to_radians(), 1.0, 1.0),
            scheme: CurveScheme::Circle,
            levels: 4,
        }
    }
}

impl CurveSketch {
    /// Checks what a file may hold: finite points and at most [`MAX_SKETCH_LEVELS`] levels
    /// (fewer than 3 points is a sketch in progress, not an error).
    pub fn validate(&self) -> Result<(), CurveError> {
        self.control.check_finite()?;
        if self.levels > MAX_SKETCH_LEVELS {
            return Err(CurveError::TooManyLevels {
                levels: self.levels,
                limit: MAX_SKETCH_LEVELS,
            });
        }
        Ok(())
    }
}

#[derive(Debug, Clone, PartialEq, Error)]
pub enum CurveError {
    #[error("a curve needs at least 3 points, this one has {0}")]
    TooFewPoints(usize),
    #[error("point {index} is not finite ({x}, {y})")]
    NonFinite { index: usize, x: f64, y: f64 },
    #[error("points {a} and {b} are the same point: the turning angle there is undefined")]
    RepeatedPoint { a: usize, b: usize },
    #[error(
        "{levels} levels of {points} points would make {would} points, more than the limit of {limit}"
    )]
    TooLarge {
        levels: usize,
        points: usize,
        would: u128,
        limit: usize,
    },
    #[error("{levels} levels asked for: a sketch shows at most {limit}")]
    TooManyLevels { levels: usize, limit: usize },
}

/// At most this many points after refinement.
pub const MAX_POINTS: usize = 50_000_000;

/// Complex quotient on `DVec2` (x + iy).
fn cdiv(a: DVec2, b: DVec2) -> DVec2 {
    let d = b.length_squared();
    DVec2::new(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / d
}
/// Principal square root (argument in (−π/2, π/2]).
fn csqrt(z: DVec2) -> DVec2 {
    let r = z.length();
    let re = ((r + z.x) * 0.5).max(0.0).sqrt();
    let im = ((r - z.x) * 0.5).max(0.0).sqrt();
    DVec2::new(re, if z.y < 0.0 { -im } else { im })
}

/// Method 1's weight ω at a vertex with incoming edge `d1` and outgoing edge `d2`.
pub fn circle_weight(d1: DVec2, d2: DVec2) -> f64 {
    circle_weight_of_cos(d1.dot(d2) / (d1.length() * d2.length()))
}

/// Method 1's weight `ω = 1/(4 cos²(θ₀/4))` from `cos θ₀` of the turning angle θ₀, in the
/// stable form `1/(2 + 2·√((1 + cos θ₀)/2))` (`cos(θ₀/4)² = (1 + cos(θ₀/2))/2`). Written once
/// for the curves and for the crease curves of [`crate::PrimalScheme::CatmullClarkCircle`].
pub fn circle_weight_of_cos(cos_theta: f64) -> f64 {
    let c = cos_theta.clamp(-1.0, 1.0);
    1.0 / (2.0 + 2.0 * ((1.0 + c) * 0.5).sqrt())
}

/// The new position of P₂ from P₁, P₂, P₃.
pub fn vertex_rule(scheme: CurveScheme, p1: DVec2, p2: DVec2, p3: DVec2) -> DVec2 {
    let (e12, e23) = (0.5 * (p1 + p2), 0.5 * (p2 + p3));
    match scheme {
        CurveScheme::CatmullClark => 0.5 * p2 + 0.25 * (e12 + e23),
        CurveScheme::Circle => {
            let w = circle_weight(p2 - p1, p3 - p2);
            w * (e12 + e23) + (1.0 - 2.0 * w) * p2
        }
        CurveScheme::LogSpiral => {
            let m = cdiv(p3 - p2, p2 - p1);
            if m.y == 0.0 && m.x < 0.0 {
                return vertex_rule(CurveScheme::Circle, p1, p2, p3);
            }
            let r = csqrt(m);
            e12 + cdiv(e23 - e12, DVec2::new(1.0 + r.x, r.y))
        }
    }
}

impl Polyline {
    pub fn new(points: Vec<DVec2>, closed: bool) -> Self {
        Polyline { closed, points }
    }

    /// The first point that is not finite, as an error.
    pub fn check_finite(&self) -> Result<(), CurveError> {
        match self.points.iter().enumerate().find(|(_, p)| !p.is_finite()) {
            Some((index, p)) => Err(CurveError::NonFinite {
                index,
                x: p.x,
                y: p.y,
            }),
            None => Ok(()),
        }
    }

    /// Checks the input: at least 3 points, finite, no two consecutive ones equal.
    pub fn validate(&self) -> Result<(), CurveError> {
        let n = self.points.len();
        if n < 3 {
            return Err(CurveError::TooFewPoints(n));
        }
        self.check_finite()?;
        let pairs = if self.closed { n } else { n - 1 };
        for i in 0..pairs {
            let j = (i + 1) % n;
            if self.points[i] == self.points[j] {
                return Err(CurveError::RepeatedPoint { a: i, b: j });
            }
        }
        Ok(())
    }

    /// One level of `scheme`.
    pub fn refine(&self, scheme: CurveScheme) -> Result<Polyline, CurveError> {
        self.validate()?;
        let p = &self.points;
        let n = p.len();
        let mut out = Vec::with_capacity(2 * n);
        for i in 0..n {
            let at_end = !self.closed && (i == 0 || i + 1 == n);
            let v = if at_end {
                p[i]
            } else {
                vertex_rule(scheme, p[(i + n - 1) % n], p[i], p[(i + 1) % n])
            };
            out.push(v);
            if self.closed || i + 1 < n {
                out.push(0.5 * (p[i] + p[(i + 1) % n]));
            }
        }
        Ok(Polyline::new(out, self.closed))
    }

    /// `levels` levels of `scheme`.
    pub fn refine_levels(
        &self,
        scheme: CurveScheme,
        levels: usize,
    ) -> Result<Polyline, CurveError> {
        self.validate()?;
        let n = self.points.len() as u128;
        let would = if levels >= 100 {
            u128::MAX
        } else if self.closed {
            n << levels
        } else {
            ((n - 1) << levels) + 1
        };
        if would > MAX_POINTS as u128 {
            return Err(CurveError::TooLarge {
                levels,
                points: self.points.len(),
                would,
                limit: MAX_POINTS,
            });
        }
        let mut cur = self.clone();
        for _ in 0..levels {
            cur = cur.refine(scheme)?;
        }
        Ok(cur)
    }

    /// Signed curvature at every point (positive turning left); 0 at the ends of an open
    /// polyline, where no circle through three points exists.
    pub fn curvature(&self) -> Vec<f64> {
        let p = &self.points;
        let n = p.len();
        (0..n)
            .map(|i| {
                if !self.closed && (i == 0 || i + 1 == n) || n < 3 {
                    return 0.0;
                }
                let (a, b, c) = (p[(i + n - 1) % n], p[i], p[(i + 1) % n]);
                let (d1, d2) = (b - a, c - b);
                let den = d1.length() * d2.length() * (c - a).length();
                if den == 0.0 {
                    0.0
                } else {
                    2.0 * d1.perp_dot(d2) / den
                }
            })
            .collect()
    }

    /// Cumulative arc length at every point (0 at the first).
    pub fn arc_length(&self) -> Vec<f64> {
        let mut s = 0.0;
        let mut out = Vec::with_capacity(self.points.len());
        for (i, p) in self.points.iter().enumerate() {
            if i > 0 {
                s += (*p - self.points[i - 1]).length();
            }
            out.push(s);
        }
        out
    }

    /// Centres of curvature (the evolute's points); `None` at the ends of an open polyline
    /// and where three points are collinear.
    pub fn evolute(&self) -> Vec<Option<DVec2>> {
        let p = &self.points;
        let n = p.len();
        (0..n)
            .map(|i| {
                if !self.closed && (i == 0 || i + 1 == n) || n < 3 {
                    return None;
                }
                let c = p[i];
                let a = p[(i + n - 1) % n] - c;
                let b = p[(i + 1) % n] - c;
                let d = 2.0 * a.perp_dot(b);
                let scale = a.length() * b.length();
                if d.abs() <= 1e-12 * scale {
                    return None;
                }
                let (la, lb) = (a.length_squared(), b.length_squared());
                Some(c + DVec2::new(b.y * la - a.y * lb, a.x * lb - b.x * la) / d)
            })
            .collect()
    }
}

/// Presets of the Curves tab and the tests.
pub mod presets {
    use super::Polyline;
    use glam::DVec2;
    use std::f64::consts::TAU;

    /// A regular n-gon of circumradius r (closed).
    pub fn regular_polygon(n: usize, r: f64) -> Polyline {
        Polyline::new(
            (0..n)
                .map(|i| {
                    let a = TAU * i as f64 / n as f64;
                    r * DVec2::new(a.cos(), a.sin())
                })
                .collect(),
            true,
        )
    }

    /// Points of the logarithmic spiral `r = e^(b φ)` at `φ = φ₀ + j·step`, j = 0..n (open).
    pub fn log_spiral(n: usize, b: f64, step: f64) -> Polyline {
        Polyline::new(
            (0..n)
                .map(|j| {
                    let phi = j as f64 * step;
                    (b * phi).exp() * DVec2::new(phi.cos(), phi.sin())
                })
                .collect(),
            false,
        )
    }

    /// The paper's fig. 6 configuration: a polyline P₀…P₃ with edge lengths l₁, l₂ and
    /// l₃ = 1 and turning angles θ₁ at P₁ and θ₂ at P₂ (radians).
    pub fn fig6(theta1: f64, theta2: f64, l1: f64, l2: f64) -> Polyline {
        let mut pts = vec![DVec2::ZERO];
        let mut dir = 0.0f64;
        for (len, turn) in [(l1, theta1), (l2, theta2), (1.0, 0.0)] {
            let last = *pts.last().unwrap();
            pts.push(last + len * DVec2::new(dir.cos(), dir.sin()));
            dir += turn;
        }
        Polyline::new(pts, false)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cmul(a: DVec2, b: DVec2) -> DVec2 {
        DVec2::new(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x)
    }

    #[test]
    fn complex_helpers() {
        let z = DVec2::new(-3.0, 4.0);
        let r = csqrt(z);
        assert!((cmul(r, r) - z).length() < 1e-14);
        assert!(r.x > 0.0);
        let q = cdiv(DVec2::new(1.0, 2.0), DVec2::new(3.0, -1.0));
        assert!((cmul(q, DVec2::new(3.0, -1.0)) - DVec2::new(1.0, 2.0)).length() < 1e-14);
    }

    #[test]
    fn omega_is_the_printed_formula() {
        for k in 1..180 {
            let t = (k as f64).to_radians();
            let d2 = DVec2::new(t.cos(), t.sin());
            let printed = 1.0 / (4.0 * (t / 4.0).cos().powi(2));
            assert!((circle_weight(DVec2::X, 2.5 * d2) - printed).abs() < 1e-15);
        }
    }

    #[test]
    fn bad_input_is_refused() {
        let p = |v: &[(f64, f64)]| {
            Polyline::new(v.iter().map(|&(x, y)| DVec2::new(x, y)).collect(), false)
        };
        assert_eq!(
            p(&[(0.0, 0.0), (1.0, 0.0)]).validate(),
            Err(CurveError::TooFewPoints(2))
        );
        assert!(matches!(
            p(&[(0.0, 0.0), (1.0, 0.0), (1.0, 0.0)]).validate(),
            Err(CurveError::RepeatedPoint { a: 1, b: 2 })
        ));
        assert!(matches!(
            p(&[(0.0, 0.0), (f64::NAN, 0.0), (1.0, 0.0)]).validate(),
            Err(CurveError::NonFinite { index: 1, .. })
        ));
        assert!(matches!(
            presets::regular_polygon(4, 1.0).refine_levels(CurveScheme::Circle, 40),
            Err(CurveError::TooLarge { .. })
        ));
    }
}
