//! Coons patches with Gregory's variable twist (seed 004 §6.2; ALGORITHMS §9;
//! docs/algorithms/envelope.md), fed with four rational boundary curves and four
//! cross-derivative functions `X(s) = k(s)·g(s) + h(s)·C′(s)` (k, h linear, g the border's
//! virtual basis, ALGORITHMS §8.2–8.3).
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

use crate::freeform::bezier::RationalBezier;
use crate::freeform::g1::fit;
use glam::DVec3;

/// One border of a patch: its curve (parametrised along the side) and its inward cross
/// derivative `X(s) = (k₀(1−s) + k₁s)·g(s) + (h₀(1−s) + h₁s)·T(s)`, `g(s) = (1−s)g₀ + s g₁`,
/// where `T(s) = unit(C′(s))·((1−s)|C′(0)| + s|C′(1)|)` is the curve's tangent with its speed
/// interpolated between the ends ([`Side::tangent`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Side {
    pub curve: RationalBezier,
    pub g: (DVec3, DVec3),
    pub k: (f64, f64),
    pub h: (f64, f64),
}

impl Side {
    /// A side whose cross derivative is fitted to the legs `a0` (at s = 0) and `a1` (at
    /// s = 1), the neighbouring sides' derivatives leaving those corners into the patch.
    pub fn fitted(curve: RationalBezier, g: (DVec3, DVec3), a0: DVec3, a1: DVec3) -> Side {
        // T = C′ at both ends.
        let d0 = curve.derivatives(0.0).d1;
        let d1 = curve.derivatives(1.0).d1;
        let (k0, h0) = fit(a0, g.0, d0);
        let (k1, h1) = fit(a1, g.1, d1);
        Side {
            curve,
            g,
            k: (k0, k1),
            h: (h0, h1),
        }
    }

    /// The tangent `T(s)` the cross derivative uses along the side, and its s-derivative:
    /// C′'s direction with the speed interpolated linearly between the ends. It equals C′ at
    /// the ends (so the corner fits are the paper's) but, unlike C′, does not outgrow the end
    /// legs in the middle of a curve whose weights are small (t → 0: the end speeds vanish
    /// while the middle crosses the chord at speed ≈ 3|chord|, and `h·C′` would shear the
    /// patch until it folds).
    pub fn tangent(&self, s: f64) -> (DVec3, DVec3) {
        let d = self.curve.derivatives(s);
        let m0 = self.curve.derivatives(0.0).d1.length();
        let m1 = self.curve.derivatives(1.0).d1.length();
        let speed = d.d1.length();
        if speed == 0.0 {
            return (DVec3::ZERO, DVec3::ZERO);
        }
        let dir = d.d1 / speed;
        let m = m0 + (m1 - m0) * s;
        let ddir = (d.d2 - d.d2.dot(dir) * dir) / speed;
        (m * dir, (m1 - m0) * dir + m * ddir)
    }

    /// The cross derivative and its s-derivative at s.
    pub fn cross(&self, s: f64) -> (DVec3, DVec3) {
        let (t, dt) = self.tangent(s);
        let g = self.g.0.lerp(self.g.1, s);
        let dg = self.g.1 - self.g.0;
        let k = self.k.0 + (self.k.1 - self.k.0) * s;
        let h = self.h.0 + (self.h.1 - self.h.0) * s;
        let x = k * g + h * t;
        let dx = (self.k.1 - self.k.0) * g + k * dg + (self.h.1 - self.h.0) * t + h * dt;
        (x, dx)
    }
}

/// A Coons patch with variable twist over four sides.
#[derive(Debug, Clone, PartialEq)]
pub struct Coons {
    pub sides: [Side; 4],
}

fn hermite(t: f64) -> [f64; 4] {
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

impl Coons {
    /// The point at (u, v).
    pub fn eval(&self, u: f64, v: f64) -> DVec3 {
        let [s0, s1, s2, s3] = &self.sides;
        let c0 = s0.curve.eval(u);
        let c1 = s2.curve.eval(1.0 - u);
        let d0 = s3.curve.eval(1.0 - v);
        let d1 = s1.curve.eval(v);
        let (x0u, _) = s0.cross(u);
        let (x2u, _) = s2.cross(1.0 - u);
        let (x3v, _) = s3.cross(1.0 - v);
        let (x1v, _) = s1.cross(v);
        let (e0, e1, f0, f1) = (x0u, -x2u, x3v, -x1v);
        let hu = hermite(u);
        let hv = hermite(v);
        let lu = hu[0] * d0 + hu[1] * d1 + hu[2] * f0 + hu[3] * f1;
        let lv = hv[0] * c0 + hv[1] * c1 + hv[2] * e0 + hv[3] * e1;
        // Corner data.
        let p00 = s0.curve.eval(0.0);
        let p10 = s1.curve.eval(0.0);
        let p11 = s2.curve.eval(0.0);
        let p01 = s3.curve.eval(0.0);
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
        let (de0_0, de0_1, de1_0, de1_1) = (dx0a, dx0b, dx2b, dx2a);
        let (df0_0, df0_1, df1_0, df1_1) = (-dx3b, -dx3a, -dx1a, -dx1b);
        let t00 = blend(u, df0_0, v, de0_0);
        let t01 = blend(u, df0_1, 1.0 - v, de1_0);
        let t10 = blend(1.0 - u, df1_0, v, de0_1);
        let t11 = blend(1.0 - u, df1_1, 1.0 - v, de1_1);
        let m = [
            [p00, p01, e0_0, e1_0],
            [p10, p11, e0_1, e1_1],
            [f0_0, f0_1, t00, t01],
            [f1_0, f1_1, t10, t11],
        ];
        let mut t = DVec3::ZERO;
        for a in 0..4 {
            for b in 0..4 {
                t += hu[a] * hv[b] * m[a][b];
            }
        }
        lu + lv - t
    }

    /// The unit normal at (u, v) by central differences (one-sided at the borders).
    pub fn normal(&self, u: f64, v: f64) -> DVec3 {
        let h = 1e-6;
        let (ua, ub) = ((u - h).max(0.0), (u + h).min(1.0));
        let (va, vb) = ((v - h).max(0.0), (v + h).min(1.0));
        let su = (self.eval(ub, v) - self.eval(ua, v)) / (ub - ua);
        let sv = (self.eval(u, vb) - self.eval(u, va)) / (vb - va);
        su.cross(sv).normalize_or_zero()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
