//! A side of a chart's convex domain and the data the network fixes along it: the scalar h
//! and its slope g across the side (docs/algorithms/envelope.md, "Charts").
//!
//! The side runs from corner a to corner b and is the image of one or more network curve
//! pieces. A chart point c has the side coordinates `σ = (c − a)·t̂/L` (0 at a, 1 at b) and
//! `δ = (c − a)·ν̂`, ν̂ the inward unit normal. At σ the side's data are computed from the
//! curve itself: the curve parameter τ whose point projects to σ (bracketed between stored
//! samples, then secant steps to 10⁻¹⁴), the point's h, and the gradient of h from the curve's
//! tangent plane ([`super::Frame::gradient`]) — so both regions beside a curve take the same
//! tangent plane at every point, not only at samples. Beyond σ ∈ [0, 1] the data continue to
//! first order from the nearer end, so that a **ribbon**
//!
//! `R(σ, δ) = h(σ) + g(σ)·Λ·ψ(δ/Λ)`,  ψ(x) = x − x²/4 for x ≤ 2, 1 beyond,
//!
//! has the side's value and slope on it and is first-order exact at both corners. ψ(0) = 0,
//! ψ′(0) = 1, so Λψ(δ/Λ) leaves the side with slope 1 and levels off at height Λ at δ = 2Λ: the
//! ribbon rises by at most g·Λ. κ = 1/Λ (0: the plain linear ribbon h + g·δ):
//! - radial charts, g > 0: Λ = ρ(1 − cos φ)/(h_f g), the rise of a circle of radius
//!   ρ = t·|P − G| turning from the curve's tangent plane (φ from the face normal) to the face's
//!   direction, in the chart's units;
//! - where g < 0: Λ = (h − floor)/|g|, so that the ribbon never falls below the floor (1 on a
//!   radial chart: the face itself; half its value on an axial chart: R > 0);
//! - otherwise linear.

use super::frame::Frame;
use crate::freeform::bezier::RationalBezier;
use glam::{DVec2, DVec3};

/// How a curve's tangent plane turns along it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Normals {
    /// In a plane through this centre: `n = unit(Π(C − G))`, Π the projection normal to C′.
    Radial(DVec3),
    /// Between its end vertices' normals: `n = unit(Π((1 − τ)n₀ + τn₁))`.
    Between(DVec3, DVec3),
}

impl Normals {
    /// The unit normal at τ where the curve's point and first derivative are `point` and `d1`.
    pub fn at_point(&self, point: DVec3, d1: DVec3, tau: f64) -> DVec3 {
        let t = d1.normalize_or_zero();
        let m = match *self {
            Normals::Radial(g) => point - g,
            Normals::Between(n0, n1) => n0.lerp(n1, tau.clamp(0.0, 1.0)),
        };
        (m - m.dot(t) * t).normalize_or_zero()
    }
}

/// What the ribbons of a chart's sides level off at and may not fall below.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Ribbons {
    /// A primitive's face: unit normal and distance from the centre.
    Radial {
        nf: DVec3,
        hf: f64,
    },
    Axial,
    Height,
}

/// A network curve piece along a side.
#[derive(Debug, Clone, PartialEq)]
pub struct Piece {
    pub curve: usize,
    pub bezier: RationalBezier,
    /// The piece runs from τ = t0 to t1 along the side (t0 > t1: backwards on the curve).
    pub t0: f64,
    pub t1: f64,
    pub normals: Normals,
    /// ρ = t·|P − G| at the curve's ends (τ = 0, 1).
    pub rho: (f64, f64),
}

/// A stored point of a side: where (σ) a piece's parameter τ lands.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Mark {
    sigma: f64,
    piece: usize,
    tau: f64,
}

/// The data at a point of a side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Data {
    pub h: f64,
    /// The gradient of h in the chart.
    pub grad: DVec2,
    pub kappa: f64,
}

/// A side of a chart's domain.
#[derive(Debug, Clone, PartialEq)]
pub struct ChartSide {
    pub a: DVec2,
    pub b: DVec2,
    pub length: f64,
    /// Unit direction from a to b.
    pub along: DVec2,
    /// Unit inward normal.
    pub inward: DVec2,
    pub frame: Frame,
    pub ribbons: Ribbons,
    pub pieces: Vec<Piece>,
    marks: Vec<Mark>,
    /// The data at the corners (σ = 0, 1), for the extrapolation.
    ends: [Data; 2],
}

/// `Λψ(δ/Λ)` with κ = 1/Λ.
pub fn profile(kappa: f64, delta: f64) -> f64 {
    if kappa <= 0.0 {
        delta
    } else if delta * kappa <= 2.0 {
        delta - 0.25 * kappa * delta * delta
    } else {
        1.0 / kappa
    }
}

/// Samples a piece carries between its ends (its τ at σ is bracketed between them).
const MARKS: usize = 16;

impl ChartSide {
    /// The side along `pieces` (consecutive, the first starting at corner a, the last ending
    /// at b) in `frame`. `None` when a point leaves the chart, a tangent plane holds the chart's
    /// direction, or the pieces do not advance along the side.
    pub fn new(frame: Frame, ribbons: Ribbons, pieces: Vec<Piece>) -> Option<ChartSide> {
        let first = pieces.first()?;
        let last = pieces.last()?;
        let a = frame.chart(first.bezier.eval(first.t0))?.0;
        let b = frame.chart(last.bezier.eval(last.t1))?.0;
        let v = b - a;
        let length = v.length();
        if length.is_nan() || length <= 0.0 {
            return None;
        }
        let along = v / length;
        let inward = DVec2::new(-along.y, along.x);
        let mut side = ChartSide {
            a,
            b,
            length,
            along,
            inward,
            frame,
            ribbons,
            pieces,
            marks: Vec::new(),
            ends: [Data {
                h: 0.0,
                grad: DVec2::ZERO,
                kappa: 0.0,
            }; 2],
        };
        let mut marks = Vec::new();
        for (i, p) in side.pieces.iter().enumerate() {
            for j in usize::from(i > 0)..=MARKS {
                let tau = p.t0 + (p.t1 - p.t0) * j as f64 / MARKS as f64;
                let (c, _) = frame.chart(p.bezier.eval(tau))?;
                marks.push(Mark {
                    sigma: (c - a).dot(along) / length,
                    piece: i,
                    tau,
                });
            }
        }
        marks.first_mut()?.sigma = 0.0;
        marks.last_mut()?.sigma = 1.0;
        if marks
            .windows(2)
            .any(|w| w[1].sigma.is_nan() || w[1].sigma <= w[0].sigma)
        {
            return None;
        }
        side.marks = marks;
        let n = side.pieces.len();
        side.ends = [
            side.exact(0, side.pieces[0].t0)?,
            side.exact(n - 1, side.pieces[n - 1].t1)?,
        ];
        Some(side)
    }

    /// The data of piece `i` at τ, from the curve.
    fn exact(&self, i: usize, tau: f64) -> Option<Data> {
        let p = &self.pieces[i];
        let (x, d1) = p.bezier.point_and_tangent(tau);
        let n = p.normals.at_point(x, d1, tau);
        let (c, h) = self.frame.chart(x)?;
        let grad = self.frame.gradient(c, h, n)?;
        let g = grad.dot(self.inward);
        let floor = match self.ribbons {
            Ribbons::Radial { .. } => 1.0,
            Ribbons::Axial => 0.5 * h,
            Ribbons::Height => f64::NEG_INFINITY,
        };
        let kappa = if g > 0.0 {
            match self.ribbons {
                Ribbons::Radial { nf, hf } => {
                    let rho = p.rho.0 + (p.rho.1 - p.rho.0) * tau;
                    let rise = rho * (1.0 - n.dot(nf)).max(0.0) / hf;
                    (g / rise.max(1e-300)).min(1e12)
                }
                _ => 0.0,
            }
        } else if g < 0.0 && floor.is_finite() {
            (-g / (h - floor).max(1e-300)).min(1e12)
        } else {
            0.0
        };
        Some(Data { h, grad, kappa })
    }

    /// The piece and its τ whose point lies at σ ∈ [0, 1].
    fn locate(&self, sigma: f64) -> (usize, f64) {
        let m = &self.marks;
        let k = m
            .partition_point(|x| x.sigma <= sigma)
            .clamp(1, m.len() - 1);
        let (lo, hi) = (m[k - 1], m[k]);
        // The bracket's two marks lie on one piece (a piece's last mark is the next one's
        // first, stored once, as the next one's τ at its start): take hi's piece.
        let piece = hi.piece;
        let p = &self.pieces[piece];
        let tau_lo = if lo.piece == piece { lo.tau } else { p.t0 };
        // σ and dσ/dτ at τ: the chart's map differentiated along C′.
        let sigma_and_slope = |tau: f64| -> Option<(f64, f64)> {
            let (point, d1) = p.bezier.point_and_tangent(tau);
            let (c, _, dc) = self.frame.chart_along(point, d1)?;
            let s = (c - self.a).dot(self.along) / self.length;
            Some((s, dc.dot(self.along) / self.length))
        };
        // Newton from the secant between the bracketing marks, kept inside the bracket
        // (bisection where a step would leave it).
        let (mut t0, mut t1) = (tau_lo, hi.tau);
        let (lo_s, hi_s) = (lo.sigma, hi.sigma);
        let mut tau = t0 + (t1 - t0) * (sigma - lo_s) / (hi_s - lo_s);
        for _ in 0..32 {
            let Some((s, ds)) = sigma_and_slope(tau) else {
                break;
            };
            let f = s - sigma;
            if f.abs() <= 1e-14 {
                break;
            }
            // t0 is the bracket's end below σ, t1 the end above (τ may run either way).
            if f < 0.0 {
                t0 = tau;
            } else {
                t1 = tau;
            }
            let step = tau - f / ds;
            let inside = (step - t0) * (step - t1) < 0.0;
            let next = if ds.is_finite() && ds != 0.0 && inside {
                step
            } else {
                0.5 * (t0 + t1)
            };
            if (next - tau).abs() <= 1e-14 {
                tau = next;
                break;
            }
            tau = next;
        }
        (piece, tau)
    }

    /// h, its gradient and κ at σ (first order beyond the corners).
    pub fn data(&self, sigma: f64) -> Data {
        let beyond = |d: Data, by: f64| Data {
            h: d.h + by * self.length * d.grad.dot(self.along),
            ..d
        };
        if sigma <= 0.0 {
            return beyond(self.ends[0], sigma);
        }
        if sigma >= 1.0 {
            return beyond(self.ends[1], sigma - 1.0);
        }
        let (i, tau) = self.locate(sigma);
        self.exact(i, tau).unwrap_or(self.ends[0])
    }

    /// Side coordinates (σ, δ) of chart point c.
    pub fn coords(&self, c: DVec2) -> (f64, f64) {
        let v = c - self.a;
        (v.dot(self.along) / self.length, v.dot(self.inward))
    }

    /// The ribbon's value at chart point c (δ taken as at least 0).
    pub fn ribbon(&self, c: DVec2) -> f64 {
        let (sigma, delta) = self.coords(c);
        let d = self.data(sigma);
        d.h + d.grad.dot(self.inward) * profile(d.kappa, delta.max(0.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn profile_levels_off() {
        let k = 2.0;
        assert_eq!(profile(k, 0.0), 0.0);
        let e = 1e-7;
        assert!(((profile(k, e) - profile(k, 0.0)) / e - 1.0).abs() < 1e-6);
        assert!((profile(k, 1.0) - 0.5).abs() < 1e-15);
        assert!((profile(k, 5.0) - 0.5).abs() < 1e-15);
        assert_eq!(profile(0.0, 3.0), 3.0);
    }

    /// A height chart over a straight curve whose tangent plane is tilted: the ribbon is the
    /// plane, along the side and beyond its ends, and σ finds the curve's point.
    #[test]
    fn plane_reproduced() {
        let frame = Frame::Height {
            o: DVec3::ZERO,
            e1: DVec3::X,
            e2: DVec3::Y,
        };
        // The plane z = 1 + 0.2y, through the line y = 0.
        let n = DVec3::new(0.0, -0.2, 1.0).normalize();
        let bez = RationalBezier::new(
            vec![
                DVec3::new(0.0, 0.0, 1.0),
                DVec3::new(0.5, 0.0, 1.0),
                DVec3::new(0.6, 0.0, 1.0),
                DVec3::new(2.0, 0.0, 1.0),
            ],
            vec![1.0, 2.0, 0.5, 1.0],
        )
        .unwrap();
        let piece = Piece {
            curve: 0,
            bezier: bez.clone(),
            t0: 0.0,
            t1: 1.0,
            normals: Normals::Between(n, n),
            rho: (1.0, 1.0),
        };
        let s = ChartSide::new(frame, Ribbons::Height, vec![piece]).unwrap();
        for c in [
            DVec2::new(1.0, 1.5),
            DVec2::new(-0.5, 0.3),
            DVec2::new(2.5, 2.0),
        ] {
            assert!((s.ribbon(c) - (1.0 + 0.2 * c.y)).abs() < 1e-12, "{c}");
        }
        for tau in [0.1, 0.37, 0.8] {
            let x = bez.eval(tau);
            let (i, t) = s.locate(x.x / 2.0);
            assert_eq!(i, 0);
            assert!((t - tau).abs() < 1e-12, "{t} {tau}");
        }
    }
}
