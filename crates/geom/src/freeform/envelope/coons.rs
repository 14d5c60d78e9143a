//! Coons patches with Gregory's variable twist (seed 004 §6.2; ALGORITHMS §9;
//! docs/algorithms/envelope.md), fed with four rational boundary curves and four
//! cross-derivative functions `X(s) = k(s)·g(s) + a(s)·unit(C′(s))` (k linear or eased into a
//! short leg's corner, a the paper's `h·|C′|` fitted at the corners and monotone between
//! them, g the border's virtual basis, ALGORITHMS §8.2–8.3).
//!
//! With the cubic Hermite functions `H₀, H₁, G₀, G₁`,
//! `S = L_u + L_v − T`, `L_u = H₀(u)d₀(v) + H₁(u)d₁(v) + G₀(u)f₀(v) + G₁(u)f₁(v)`, `L_v` likewise
//! in v with c₀, c₁, e₀, e₁, and T the Hermite tensor of the corners whose twists are blended
//! per corner, e.g. `T₀₀(u, v) = (u·f₀′(0) + v·e₀′(0))/(u + v)` — so no twist compatibility is
//! needed and every border's position and cross derivative is reproduced exactly.
//!
//! Sides run counter-clockwise seen from outside: side 0 is v = 0 (s = u), side 1 u = 1
//! (s = v), side 2 v = 1 (s = 1 − u), side 3 u = 0 (s = 1 − v); each side's X points into
//! the patch.

use super::reparam::Reparam;
use crate::freeform::bezier::RationalBezier;
use crate::freeform::g1::fit;
use glam::DVec3;

/// The least share of the fitted part across a short side that its short-side cross
/// derivative keeps pointing into the patch ([`Side::short`]).
const INWARD_FLOOR: f64 = 0.25;

/// Legs at a side's two corners this many times apart start easing k into the shorter one;
/// the square of it apart, fully ([`Side::k_share`]).
const EASE_FROM: f64 = 8.0;

/// One border of a patch: its curve (parametrised along the side) and its inward cross
/// derivative `X(s) = (k₀ + (k₁ − k₀)φ(s))·g(s) + a(s)·unit(C′(s))`, `g(s) = (1−s)g₀ + s g₁`,
/// φ the share of [`Side::k_share`] (s itself unless the corner legs are far apart), where the
/// part along the side runs from `h₀|C′(0)|` to `h₁|C′(1)|` ([`Side::along`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Side {
    pub curve: RationalBezier,
    pub g: (DVec3, DVec3),
    pub k: (f64, f64),
    pub h: (f64, f64),
    /// |C′| at s = 0 and s = 1, the speeds the part along the side interpolates.
    pub speed: (f64, f64),
    /// The corner legs the cross derivative was fitted to.
    pub legs: (DVec3, DVec3),
    /// How far the cross derivative's part along the side goes from `a·unit(C′)` to the legs'
    /// parts along it interpolated as vectors ([`Side::short`]; 0: not at all).
    pub direct: f64,
    /// A side collapsed to a point ([`Side::collapsed`]).
    pub collapsed: bool,
    /// β of the cross derivative's scale `σ(s) = 1 − 4β·s(1 − s)` between the corners
    /// ([`Side::scaled`]; 0: the fitted one as is).
    pub squeeze: f64,
    /// The side run along its curve by φ, `τ = φ(s)` (set, then [`Side::refitted`]; none:
    /// τ = s).
    pub reparam: Option<Reparam>,
    /// μ′(0) and μ′(1) of the lean `μ(s)·g(s)` added to the cross derivative, `μ(s) =
    /// μ′(0)·s(1 − s)² − μ′(1)·s²(1 − s)` ([`Side::leaned`]; (0, 0): none).
    pub lean: (f64, f64),
}

impl Side {
    /// A side whose cross derivative is fitted to the legs `a0` (at s = 0) and `a1` (at
    /// s = 1), the neighbouring sides' derivatives leaving those corners into the patch.
    pub fn fitted(curve: RationalBezier, g: (DVec3, DVec3), a0: DVec3, a1: DVec3) -> Side {
        Side {
            curve,
            g,
            k: (0.0, 0.0),
            h: (0.0, 0.0),
            speed: (0.0, 0.0),
            legs: (a0, a1),
            direct: 0.0,
            collapsed: false,
            squeeze: 0.0,
            reparam: None,
            lean: (0.0, 0.0),
        }
        .refitted(a0, a1)
    }

    /// A side collapsed to the point `p`: the tip of a needle patched as one quad
    /// (envelope.md, "Needles"). No patch lies across it, so it has no basis to be G1 with; its
    /// cross derivative runs from the leg `a0` to the leg `a1` as vectors, and the patch fans
    /// out from `p` between the two sides that meet there.
    pub fn collapsed(p: DVec3, a0: DVec3, a1: DVec3) -> Side {
        Side {
            curve: RationalBezier::polynomial(vec![p; 4]).expect("a finite point"),
            g: (DVec3::ZERO, DVec3::ZERO),
            k: (0.0, 0.0),
            h: (0.0, 0.0),
            speed: (0.0, 0.0),
            legs: (a0, a1),
            direct: 0.0,
            collapsed: true,
            squeeze: 0.0,
            reparam: None,
            lean: (0.0, 0.0),
        }
    }

    /// This side with its cross derivative blended towards the short-side form by `direct`
    /// (0 to 1). On a side much shorter than its neighbours the corner legs are long against
    /// its own speed, `h` is large and `a·unit(C′)` swings with the side's direction; the
    /// short-side form keeps the fitted part across the side (`k g` less its part along the
    /// side, at least a quarter of it inwards) and takes the part along the side from the
    /// legs interpolated as vectors, which stays within them. It equals the fit at both ends and
    /// lies in the plane of g and C′, so G1 along the border is untouched.
    pub fn short(mut self, direct: f64) -> Side {
        self.direct = direct.clamp(0.0, 1.0);
        self
    }

    /// This side with its cross derivative scaled by `σ(s) = 1 − 4β·s(1 − s)` (β below 1):
    /// 1 at the corners, so the fits there hold, and positive, so that it stays in the plane
    /// of g and C′ on the same side of the curve — the normal along the border, and G1 with
    /// the patch across, are untouched.
    pub fn scaled(mut self, beta: f64) -> Side {
        self.squeeze = beta;
        self
    }

    /// This side with `μ(s)·g(s)` added to its cross derivative, μ zero at both corners with
    /// the slopes `lean` there ([`Side::lean`]): the fits at the corners hold, and the cross
    /// derivative stays in the plane of g and C′, so G1 with the patch across is untouched.
    pub fn leaned(mut self, lean: (f64, f64)) -> Side {
        self.lean = lean;
        self
    }

    /// Whether the lean keeps the cross derivative's part across the side pointing the way the
    /// unleaned one does, at least a quarter of it, at 65 points along the side: otherwise the
    /// plane of C′ and X would turn over with it (the border's normal reversed, no longer G1
    /// with the patch across).
    pub fn lean_keeps_its_side(&self) -> bool {
        if self.lean == (0.0, 0.0) {
            return true;
        }
        let plain = Side {
            lean: (0.0, 0.0),
            ..self.clone()
        };
        (0..=64).all(|i| {
            let s = f64::from(i) / 64.0;
            let t = self.d1(s).normalize_or_zero();
            let across = |x: DVec3| x - x.dot(t) * t;
            let (x, o) = (across(self.cross(s).0), across(plain.cross(s).0));
            x.dot(o) >= 0.25 * o.length_squared() && x.is_finite()
        })
    }

    /// This side's cross derivative fitted to the legs `a0` and `a1` (the neighbouring sides'
    /// derivatives leaving its corners), the paper's `k g + h C′` at both ends, with C′ the
    /// derivative of the side as it runs ([`Side::reparam`]; envelope.md, "Sides run along their
    /// curves"): the basis is taken at the same curve point, so G1 with the patch across holds
    /// whatever the run. A collapsed side only takes the legs.
    pub fn refitted(mut self, a0: DVec3, a1: DVec3) -> Side {
        if self.collapsed {
            self.legs = (a0, a1);
            return self;
        }
        let (d0, d1) = (self.d1(0.0), self.d1(1.0));
        let (k0, h0) = fit(a0, self.g.0, d0);
        let (k1, h1) = fit(a1, self.g.1, d1);
        self.k = (k0, k1);
        self.h = (h0, h1);
        self.speed = (d0.length(), d1.length());
        self.legs = (a0, a1);
        self
    }

    /// τ = φ(s) and φ′(s).
    pub fn phi(&self, s: f64) -> (f64, f64) {
        match &self.reparam {
            Some(r) => r.at(s),
            None => (s, 1.0),
        }
    }

    /// The side's point at s.
    pub fn point(&self, s: f64) -> DVec3 {
        self.curve.eval(self.phi(s).0)
    }

    /// The side's derivative at s.
    pub fn d1(&self, s: f64) -> DVec3 {
        let (t, dt) = self.phi(s);
        self.curve.derivatives(t).d1 * dt
    }

    /// The basis g at s and its s-derivative (linear in the curve's parameter).
    pub(crate) fn basis(&self, s: f64) -> (DVec3, DVec3) {
        let (t, dt) = self.phi(s);
        (self.g.0.lerp(self.g.1, t), (self.g.1 - self.g.0) * dt)
    }

    /// The unit tangent at s and its s-derivative.
    fn tangent(&self, s: f64) -> (DVec3, DVec3) {
        let (t, dt) = self.phi(s);
        let (d, dd) = unit_tangent(&self.curve, t);
        (d, dd * dt)
    }

    /// The cross derivative and its s-derivative at s.
    pub fn cross(&self, s: f64) -> (DVec3, DVec3) {
        let (x, dx) = self.scaled_cross(s);
        if self.lean == (0.0, 0.0) {
            return (x, dx);
        }
        let (m0, m1) = self.lean;
        let mu = m0 * s * (1.0 - s) * (1.0 - s) - m1 * s * s * (1.0 - s);
        let d_mu = m0 * (1.0 - s) * (1.0 - 3.0 * s) - m1 * s * (2.0 - 3.0 * s);
        let (g, dg) = self.basis(s);
        (x + mu * g, dx + d_mu * g + mu * dg)
    }

    /// The cross derivative scaled ([`Side::scaled`]) and its s-derivative at s.
    fn scaled_cross(&self, s: f64) -> (DVec3, DVec3) {
        let (x, dx) = self.unscaled_cross(s);
        if self.squeeze == 0.0 {
            return (x, dx);
        }
        let sigma = 1.0 - 4.0 * self.squeeze * s * (1.0 - s);
        let d_sigma = -4.0 * self.squeeze * (1.0 - 2.0 * s);
        (sigma * x, d_sigma * x + sigma * dx)
    }

    fn unscaled_cross(&self, s: f64) -> (DVec3, DVec3) {
        if self.collapsed {
            return (self.legs.0.lerp(self.legs.1, s), self.legs.1 - self.legs.0);
        }
        let (x, dx) = self.fitted_cross(s);
        if self.direct == 0.0 {
            return (x, dx);
        }
        let (y, dy) = self.short_cross(s);
        let w = self.direct;
        (x.lerp(y, w), dx.lerp(dy, w))
    }

    /// The short-side form of the cross derivative ([`Side::short`]) and its s-derivative.
    fn short_cross(&self, s: f64) -> (DVec3, DVec3) {
        let (t, dt) = self.tangent(s);
        if t == DVec3::ZERO {
            return (DVec3::ZERO, DVec3::ZERO);
        }
        let (g, dg) = self.basis(s);
        let (k, dk) = (self.k.0 + (self.k.1 - self.k.0) * s, self.k.1 - self.k.0);
        // The fitted part across the side, its length and direction.
        let g_across = g - g.dot(t) * t;
        let across = k * g_across;
        let d_across = dk * g_across + k * (dg - (dg.dot(t) + g.dot(dt)) * t - g.dot(t) * dt);
        let kappa = across.length();
        if kappa == 0.0 {
            return (DVec3::ZERO, DVec3::ZERO);
        }
        let dir = across / kappa;
        let d_dir = (d_across - d_across.dot(dir) * dir) / kappa;
        let (v, dv) = (self.legs.0.lerp(self.legs.1, s), self.legs.1 - self.legs.0);
        let inward = v.dot(dir);
        let (beta, d_beta) = if inward >= INWARD_FLOOR * kappa {
            (inward, dv.dot(dir) + v.dot(d_dir))
        } else {
            (INWARD_FLOOR * kappa, INWARD_FLOOR * d_across.dot(dir))
        };
        let along = v.dot(t) * t;
        let d_along = (dv.dot(t) + v.dot(dt)) * t + v.dot(t) * dt;
        (beta * dir + along, d_beta * dir + beta * d_dir + d_along)
    }

    /// The cross derivative's part along the side, `a(s)` in `k g + a·unit(C′)`, and its
    /// s-derivative. At the corners `a = h·|C′|`, the fits' (the paper's `h C′`); in between
    /// the paper's `h(s)·|C′(s)|` is replaced by `h(s)·m(s)` with m the end speeds
    /// interpolated, `a₀(1−s) + a₁s − c·s(1−s)` with `c = (h₁−h₀)(m₁−m₀)`, whose bump `c` is
    /// flattened by λ = min(1, |a₁−a₀|/|c|) so that a runs monotonically from a₀ to a₁.
    /// Without λ a side that is slow at one end and whose h grows towards that end (a half
    /// edge at a primitive's vertex for small t: speeds 2.3 and 0.025, h 0 and 0.5) carries
    /// an along part 25 × its end values in the middle and shears the patch past the vertex.
    fn along(&self, s: f64) -> (f64, f64) {
        let (a0, a1) = (self.h.0 * self.speed.0, self.h.1 * self.speed.1);
        let c = (self.h.1 - self.h.0) * (self.speed.1 - self.speed.0);
        let lambda = if c.abs() <= (a1 - a0).abs() {
            1.0
        } else {
            (a1 - a0).abs() / c.abs()
        };
        let a = a0 + (a1 - a0) * s - lambda * c * s * (1.0 - s);
        let da = (a1 - a0) - lambda * c * (1.0 - 2.0 * s);
        (a, da)
    }

    /// The share `φ(s) = s + μ·s(1 − s)` of the way from k₀ to k₁ at s, and φ′. Linear
    /// (μ = 0) unless one corner's leg is far shorter than the other's: then k eases into that
    /// corner (μ → ±1, φ′ → 0 there), so that the cross derivative does not change fast where
    /// it is tiny — the twist that folded the corner cells at a vertex of t = 0.0017 beside
    /// vertices of t ≈ 2 (envelope.md, "Left"). Any k(s) keeps X in the plane of g and C′.
    fn k_share(&self, s: f64) -> (f64, f64) {
        let (l0, l1) = (self.legs.0.length(), self.legs.1.length());
        let q = l0 / l1;
        let mu = if !(q.is_finite() && q > 0.0) || (1.0 / EASE_FROM..=EASE_FROM).contains(&q) {
            0.0
        } else {
            let r = q.ln() / EASE_FROM.ln();
            r.signum() * (r.abs() - 1.0).clamp(0.0, 1.0)
        };
        (s + mu * s * (1.0 - s), 1.0 + mu * (1.0 - 2.0 * s))
    }

    /// `k g + a·unit(C′)` ([`Side::along`]) and its s-derivative.
    fn fitted_cross(&self, s: f64) -> (DVec3, DVec3) {
        let (g, dg) = self.basis(s);
        let (phi, dphi) = self.k_share(s);
        let k = self.k.0 + (self.k.1 - self.k.0) * phi;
        let (dir, ddir) = self.tangent(s);
        let (a, da) = self.along(s);
        let x = k * g + a * dir;
        let dx = (self.k.1 - self.k.0) * dphi * g + k * dg + da * dir + a * ddir;
        (x, dx)
    }
}

/// The curve's unit tangent at s and its s-derivative (zero where the curve stands still).
fn unit_tangent(curve: &RationalBezier, s: f64) -> (DVec3, DVec3) {
    let d = curve.derivatives(s);
    let speed = d.d1.length();
    if speed == 0.0 {
        return (DVec3::ZERO, DVec3::ZERO);
    }
    let dir = d.d1 / speed;
    (dir, (d.d2 - d.d2.dot(dir) * dir) / speed)
}

/// A Coons patch with variable twist over four sides.
#[derive(Debug, Clone, PartialEq)]
pub struct Coons {
    pub sides: [Side; 4],
}

/// The cubic Hermite functions `H₀, H₁, G₀, G₁` at t.
pub(super) fn hermite(t: f64) -> [f64; 4] {
    let (t2, t3) = (t * t, t * t * t);
    [
        2.0 * t3 - 3.0 * t2 + 1.0,
        -2.0 * t3 + 3.0 * t2,
        t3 - 2.0 * t2 + t,
        t3 - t2,
    ]
}

/// Gregory's blend of two twists, the average where both weights vanish.
fn blend(wa: f64, a: DVec3, wb: f64, b: DVec3) -> DVec3 {
    let w = wa + wb;
    if w <= 0.0 {
        0.5 * (a + b)
    } else {
        (wa * a + wb * b) / w
    }
}

/// What the patch needs of its corners: positions, cross derivatives and their derivatives
/// along the sides (for the twists).
struct Corners {
    /// Positions and e (S_v) at the corners: rows H₀(u), H₁(u), G₀… of the Hermite tensor.
    m: [[DVec3; 2]; 4],
    /// f (S_u) at (0, 0), (0, 1), (1, 0), (1, 1).
    cross: [DVec3; 4],
    /// Twist pairs per corner (00, 01, 10, 11): (f′, e′).
    twists: [(DVec3, DVec3); 4],
}

/// The boundary data of the line u = const (c₀, c₁, e₀, e₁) or v = const (d₀, d₁, f₀, f₁).
type Line = [DVec3; 4];

impl Coons {
    fn corners(&self) -> Corners {
        let [s0, s1, s2, s3] = &self.sides;
        let p00 = s0.point(0.0);
        let p10 = s1.point(0.0);
        let p11 = s2.point(0.0);
        let p01 = s3.point(0.0);
        let (x0a, dx0a) = s0.cross(0.0);
        let (x0b, dx0b) = s0.cross(1.0);
        let (x1a, dx1a) = s1.cross(0.0);
        let (x1b, dx1b) = s1.cross(1.0);
        let (x2a, dx2a) = s2.cross(0.0);
        let (x2b, dx2b) = s2.cross(1.0);
        let (x3a, dx3a) = s3.cross(0.0);
        let (x3b, dx3b) = s3.cross(1.0);
        // e₀(u) = X₀(u), e₁(u) = −X₂(1−u), f₀(v) = X₃(1−v), f₁(v) = −X₁(v); derivatives
        // e₀′ = X₀′(u), e₁′ = X₂′(1−u), f₀′ = −X₃′(1−v), f₁′ = −X₁′(v).
        let (e0_0, e0_1, e1_0, e1_1) = (x0a, x0b, -x2b, -x2a);
        let (f0_0, f0_1, f1_0, f1_1) = (x3b, x3a, -x1a, -x1b);
        Corners {
            m: [[p00, p01], [p10, p11], [e0_0, e1_0], [e0_1, e1_1]],
            cross: [f0_0, f0_1, f1_0, f1_1],
            twists: [(-dx3b, dx0a), (-dx3a, dx2b), (-dx1a, dx0b), (-dx1b, dx2a)],
        }
    }

    /// The data along the line u = const.
    fn u_line(&self, u: f64) -> Line {
        let [s0, _, s2, _] = &self.sides;
        [
            s0.point(u),
            s2.point(1.0 - u),
            s0.cross(u).0,
            -s2.cross(1.0 - u).0,
        ]
    }

    /// The data along the line v = const.
    fn v_line(&self, v: f64) -> Line {
        let [_, s1, _, s3] = &self.sides;
        [
            s3.point(1.0 - v),
            s1.point(v),
            s3.cross(1.0 - v).0,
            -s1.cross(v).0,
        ]
    }

    fn combine(c: &Corners, u: f64, v: f64, ul: &Line, vl: &Line) -> DVec3 {
        Coons::combine_at(c, (u, hermite(u)), (v, hermite(v)), ul, vl)
    }

    /// [`Coons::combine`] with the Hermite functions at u and v given.
    fn combine_at(
        c: &Corners,
        (u, hu): (f64, [f64; 4]),
        (v, hv): (f64, [f64; 4]),
        ul: &Line,
        vl: &Line,
    ) -> DVec3 {
        let lu = hu[0] * vl[0] + hu[1] * vl[1] + hu[2] * vl[2] + hu[3] * vl[3];
        let lv = hv[0] * ul[0] + hv[1] * ul[1] + hv[2] * ul[2] + hv[3] * ul[3];
        let [(f00, e00), (f01, e01), (f10, e10), (f11, e11)] = c.twists;
        let t00 = blend(u, f00, v, e00);
        let t01 = blend(u, f01, 1.0 - v, e01);
        let t10 = blend(1.0 - u, f10, v, e10);
        let t11 = blend(1.0 - u, f11, 1.0 - v, e11);
        // Rows: H₀(u), H₁(u), G₀(u), G₁(u); columns H₀(v), H₁(v), G₀(v), G₁(v).
        let rows = [
            [c.m[0][0], c.m[0][1], c.m[2][0], c.m[2][1]],
            [c.m[1][0], c.m[1][1], c.m[3][0], c.m[3][1]],
            [c.cross[0], c.cross[1], t00, t01],
            [c.cross[2], c.cross[3], t10, t11],
        ];
        let mut t = DVec3::ZERO;
        for a in 0..4 {
            for b in 0..4 {
                t += hu[a] * hv[b] * rows[a][b];
            }
        }
        lu + lv - t
    }

    /// The point at (u, v).
    pub fn eval(&self, u: f64, v: f64) -> DVec3 {
        Coons::combine(&self.corners(), u, v, &self.u_line(u), &self.v_line(v))
    }

    /// The points at (i/k, j/k), i + (k + 1)j: the boundary data computed once per line.
    pub fn grid(&self, k: usize) -> Vec<DVec3> {
        let kf = k as f64;
        let c = self.corners();
        let ul: Vec<Line> = (0..=k).map(|i| self.u_line(i as f64 / kf)).collect();
        let vl: Vec<Line> = (0..=k).map(|j| self.v_line(j as f64 / kf)).collect();
        // The Hermite functions at each line's parameter, once (the same values `combine` takes).
        let h: Vec<(f64, [f64; 4])> = (0..=k)
            .map(|i| {
                let s = i as f64 / kf;
                (s, hermite(s))
            })
            .collect();
        let mut out = Vec::with_capacity((k + 1) * (k + 1));
        for (vline, &hv) in vl.iter().zip(&h) {
            for (uline, &hu) in ul.iter().zip(&h) {
                out.push(Coons::combine_at(&c, hu, hv, uline, vline));
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A test side's curve (a cubic with these weights), basis and corner legs.
    fn side_data(weights: Vec<f64>) -> (RationalBezier, (DVec3, DVec3), DVec3, DVec3) {
        let curve = RationalBezier::new(
            vec![
                DVec3::ZERO,
                DVec3::new(0.3, 0.2, 0.0),
                DVec3::new(0.7, 0.1, 0.05),
                DVec3::new(1.0, 0.0, 0.0),
            ],
            weights,
        )
        .unwrap();
        let g = (DVec3::Y, DVec3::new(0.1, 1.0, 0.05));
        let a0 = 0.4 * g.0 + 0.3 * curve.derivatives(0.0).d1;
        let a1 = 0.2 * g.1 - 0.1 * curve.derivatives(1.0).d1;
        (curve, g, a0, a1)
    }

    /// The difference quotient of `side`'s cross derivative at s, a step `h` either side
    /// (one-sided at the ends), against which its s-derivative is checked.
    fn cross_quotient(side: &Side, s: f64, h: f64) -> DVec3 {
        let (lo, hi) = ((s - h).max(0.0), (s + h).min(1.0));
        (side.cross(hi).0 - side.cross(lo).0) / (hi - lo)
    }

    /// A rescaled cross derivative keeps the corner fits, is a positive multiple of the
    /// fitted one between them (so the border's normal `C′ × X`, and G1, are the same), and
    /// its s-derivative is its difference quotient.
    #[test]
    fn a_rescaled_cross_derivative_keeps_the_fits_and_the_border_normal() {
        let (curve, g, a0, a1) = side_data(vec![1.0, 0.7, 1.2, 1.0]);
        let side = Side::fitted(curve, g, a0, a1);
        for beta in [0.9, 0.5, -0.5, -2.0] {
            let scaled = side.clone().scaled(beta);
            assert!((scaled.cross(0.0).0 - a0).length() < 1e-12);
            assert!((scaled.cross(1.0).0 - a1).length() < 1e-12);
            for i in 0..=20 {
                let s = i as f64 / 20.0;
                let (x, dx) = scaled.cross(s);
                let y = side.cross(s).0;
                assert!(
                    x.cross(y).length() < 1e-12 * (1.0 + y.length_squared()),
                    "{s}"
                );
                assert!(x.dot(y) > 0.0, "β = {beta}, s = {s}");
                let fd = cross_quotient(&scaled, s, 1e-6);
                assert!((fd - dx).length() < 1e-5 * (1.0 + dx.length()), "{s}");
            }
        }
    }

    /// A leaned cross derivative keeps the corner fits, lies in the plane of g and C′ (so the
    /// border's normal, and G1, are the same where its part across the side keeps its way), and
    /// its s-derivative is its difference quotient; a lean that turns that part over is refused.
    #[test]
    fn a_leaned_cross_derivative_keeps_the_fits_and_the_border_plane() {
        let (curve, g, a0, a1) = side_data(vec![1.0, 0.7, 1.2, 1.0]);
        let side = Side::fitted(curve, g, a0, a1);
        for lean in [(0.5, -0.5), (2.0, -2.0), (-0.3, 0.3), (1.0, 0.4)] {
            let leaned = side.clone().leaned(lean);
            assert!((leaned.cross(0.0).0 - a0).length() < 1e-12);
            assert!((leaned.cross(1.0).0 - a1).length() < 1e-12);
            for i in 0..=20 {
                let s = i as f64 / 20.0;
                let (x, dx) = leaned.cross(s);
                let plane = side.d1(s).cross(side.cross(s).0).normalize();
                assert!(x.dot(plane).abs() < 1e-12 * (1.0 + x.length()), "{s}");
                let fd = cross_quotient(&leaned, s, 1e-6);
                assert!((fd - dx).length() < 1e-5 * (1.0 + dx.length()), "{s}");
            }
        }
        assert!(side.clone().leaned((0.5, -0.5)).lean_keeps_its_side());
        // Far enough against the part across the side to turn it over in the middle.
        let k = side.cross(0.5).0.length() / side.basis(0.5).0.length();
        assert!(
            !side
                .clone()
                .leaned((-40.0 * k, 40.0 * k))
                .lean_keeps_its_side()
        );
    }

    /// A side run along its curve by φ (envelope.md, "Sides run along their curves") passes
    /// through the same points, fits the new legs at its corners, and its cross derivative at
    /// s lies in the plane of g and C′ at the curve point φ(s) on the same side of the curve as
    /// the side's own there, so the border's normal (and G1 with the patch across) is
    /// unchanged; the s-derivatives are difference quotients.
    #[test]
    fn a_side_run_along_its_curve_keeps_the_border_normal() {
        // Crowded at both ends, as a rational edge is for small t.
        let (curve, g, a0, a1) = side_data(vec![1.0, 0.04, 0.005, 1.0]);
        let side = Side::fitted(curve.clone(), g, a0, a1);
        let phi = Reparam::arc_length(&curve).unwrap();
        // New legs in the corners' tangent planes, far longer along the side.
        let (t0, t1) = (
            curve.derivatives(0.0).d1.normalize(),
            curve.derivatives(1.0).d1.normalize(),
        );
        let (b0, b1) = (0.5 * g.0 + 2.0 * t0, 0.3 * g.1 - 1.5 * t1);
        let run = Side {
            reparam: Some(phi),
            ..side.clone()
        }
        .refitted(b0, b1);
        assert!((run.cross(0.0).0 - b0).length() < 1e-12);
        assert!((run.cross(1.0).0 - b1).length() < 1e-12);
        for i in 0..=40 {
            let s = i as f64 / 40.0;
            let tau = run.phi(s).0;
            assert!((run.point(s) - curve.eval(tau)).length() < 1e-14);
            let n_run = run.d1(s).cross(run.cross(s).0).normalize();
            let n_own = side.d1(tau).cross(side.cross(tau).0).normalize();
            assert!(
                n_run.dot(n_own) > 1.0 - 1e-12,
                "s = {s}: {n_run} against {n_own}"
            );
            // One-sided at the ends, where φ bends fast: a shorter step there.
            let h = if i == 0 || i == 40 { 1e-9 } else { 1e-6 };
            let (lo, hi) = ((s - h).max(0.0), (s + h).min(1.0));
            let fd = cross_quotient(&run, s, h);
            let dx = run.cross(s).1;
            assert!(
                (fd - dx).length() < 1e-4 * (1.0 + dx.length()),
                "{s}: {fd} against {dx}"
            );
            let fd = (run.point(hi) - run.point(lo)) / (hi - lo);
            assert!(
                (fd - run.d1(s)).length() < 1e-4 * (1.0 + fd.length()),
                "{s}"
            );
        }
    }

    /// The short-side cross derivative meets the corner legs at both ends, lies in the plane
    /// of g and C′ everywhere (G1), and its s-derivative is its difference quotient.
    #[test]
    fn the_short_side_form_fits_the_legs_in_the_tangent_plane() {
        // A short, bent side with long legs leaning along it from both corners.
        let curve = RationalBezier::new(
            vec![
                DVec3::ZERO,
                DVec3::new(0.02, 0.01, 0.0),
                DVec3::new(0.05, 0.01, 0.005),
                DVec3::new(0.06, 0.0, 0.0),
            ],
            vec![1.0, 0.8, 1.3, 1.0],
        )
        .unwrap();
        let g = (DVec3::Y, DVec3::new(0.1, 1.0, 0.05));
        // Legs in the corners' tangent planes, mostly along the side (h ≈ ±8).
        let a0 = 0.5 * g.0 + 8.0 * curve.derivatives(0.0).d1;
        let a1 = 0.6 * g.1 - 7.0 * curve.derivatives(1.0).d1;
        let side = Side::fitted(curve.clone(), g, a0, a1).short(1.0);
        assert!((side.cross(0.0).0 - a0).length() < 1e-12);
        assert!((side.cross(1.0).0 - a1).length() < 1e-12);
        for i in 0..=20 {
            let s = i as f64 / 20.0;
            let (x, dx) = side.cross(s);
            let gs = g.0.lerp(g.1, s);
            let n = gs.cross(curve.derivatives(s).d1).normalize();
            assert!(x.dot(n).abs() < 1e-12 * x.length(), "{s}");
            let fd = cross_quotient(&side, s, 1e-6);
            assert!(
                (fd - dx).length() < 1e-5 * (1.0 + dx.length()),
                "{s}: {fd} {dx}"
            );
        }
    }

    /// The part along a side fits the paper's `h C′` at both corners and runs monotonically
    /// between them, also where `h(s)·|C′|` interpolated would bulge (a half edge at a vertex
    /// for small t: fast at its middle end, slow at the vertex, h growing towards it); where
    /// that product is monotone it is kept. Its s-derivative is its difference quotient.
    #[test]
    fn the_part_along_a_side_is_monotone_between_the_corner_fits() {
        // Weights small in the middle: speed ≈ 2.3 at s = 0, ≈ 0.02 at s = 1.
        let curve = RationalBezier::new(
            vec![
                DVec3::ZERO,
                DVec3::new(0.75, 0.0, 0.0),
                DVec3::new(0.99, 0.001, 0.0),
                DVec3::new(1.0, 0.0, 0.0),
            ],
            vec![1.0, 1.0, 0.1, 1.0],
        )
        .unwrap();
        let g = (DVec3::Y, DVec3::Y);
        let m1 = curve.derivatives(1.0).d1;
        let a0 = 0.07 * DVec3::Y;
        let a1 = 0.02 * DVec3::Y + 0.5 * m1;
        let side = Side::fitted(curve.clone(), g, a0, a1);
        assert!(side.speed.0 > 50.0 * side.speed.1, "{:?}", side.speed);
        assert!((side.cross(0.0).0 - a0).length() < 1e-12);
        assert!((side.cross(1.0).0 - a1).length() < 1e-12);
        let ends = (side.along(0.0).0, side.along(1.0).0);
        let mut last = ends.0;
        for i in 1..=40 {
            let s = i as f64 / 40.0;
            let (a, da) = side.along(s);
            assert!(
                a >= last - 1e-15 && a <= ends.1 + 1e-15,
                "{s}: {a} after {last}"
            );
            last = a;
            let h = 1e-6;
            let fd = (side.along(s).0 - side.along(s - h).0) / h;
            assert!((fd - da).abs() < 1e-5, "{s}: {fd} {da}");
        }
        // The product would have reached about 0.3 in the middle, 25 × the vertex end.
        let (h, m) = (side.h, side.speed);
        let product = 0.5 * (h.0 + h.1) * 0.5 * (m.0 + m.1);
        assert!(product > 10.0 * ends.1, "{product} {}", ends.1);
        // Where h grows towards the fast end the product is monotone, and kept.
        let m0 = curve.derivatives(0.0).d1;
        let even = Side::fitted(curve, g, 0.07 * DVec3::Y + 0.5 * m0, 0.02 * DVec3::Y);
        let (h, m) = (even.h, even.speed);
        let s = 0.3;
        let product = (h.0 + (h.1 - h.0) * s) * (m.0 + (m.1 - m.0) * s);
        assert!((even.along(s).0 - product).abs() < 1e-12);
    }

    fn line(a: DVec3, b: DVec3) -> RationalBezier {
        RationalBezier::polynomial(vec![a, a.lerp(b, 1.0 / 3.0), a.lerp(b, 2.0 / 3.0), b]).unwrap()
    }

    /// Borders and cross derivatives are reproduced with deliberately incompatible twists;
    /// a unit square with straight sides and constant cross derivatives is the bilinear square.
    #[test]
    fn reproduces_borders_and_cross_derivatives() {
        let p = [DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
        let legs = |k: usize| (p[(k + 3) % 4] - p[k], p[(k + 2) % 4] - p[(k + 1) % 4]);
        let sides: Vec<Side> = (0..4)
            .map(|k| {
                let (a0, a1) = legs(k);
                // Bases leaning along the side by different amounts: incompatible twists.
                let along = p[(k + 1) % 4] - p[k];
                let g = (a0 + (0.3 * k as f64 - 0.4) * along, a1 + 0.25 * along);
                Side::fitted(line(p[k], p[(k + 1) % 4]), g, a0, a1)
            })
            .collect();
        let c = Coons {
            sides: sides.try_into().unwrap(),
        };
        for k in 0..=10 {
            let s = k as f64 / 10.0;
            assert!((c.eval(s, 0.0) - c.sides[0].curve.eval(s)).length() < 1e-14);
            assert!((c.eval(1.0, s) - c.sides[1].curve.eval(s)).length() < 1e-14);
            assert!((c.eval(1.0 - s, 1.0) - c.sides[2].curve.eval(s)).length() < 1e-14);
            assert!((c.eval(0.0, 1.0 - s) - c.sides[3].curve.eval(s)).length() < 1e-14);
            let h = 1e-7;
            let sv = (c.eval(s, h) - c.eval(s, 0.0)) / h;
            assert!((sv - c.sides[0].cross(s).0).length() < 1e-5, "{sv}");
            let su = (c.eval(h, 1.0 - s) - c.eval(0.0, 1.0 - s)) / h;
            assert!((su - c.sides[3].cross(s).0).length() < 1e-5, "{su}");
        }
    }
}
