//! Coons patches with Gregory's variable twist (seed 004 §6.2;
//! docs/algorithms/envelope.md, "The paper's patches"), fed with four rational boundary
//! curves and four cross-derivative functions `X(s) = k(s)·g(s) + h(s)·C′(s)`, k and h
//! linear between their fits at the corners and g the border's virtual basis (the paper's
//! form, docs/algorithms/skin.md, "Patches and G1").
//!
//! With the cubic Hermite functions `H₀, H₁, G₀, G₁`,
//! `S = L_u + L_v − T`, `L_u = H₀(u)d₀(v) + H₁(u)d₁(v) + G₀(u)f₀(v) + G₁(u)f₁(v)`, `L_v` likewise
//! in v with c₀, c₁, e₀, e₁, and T the Hermite tensor of the corners whose twists are blended
//! per corner, e.g. `T₀₀(u, v) = (u·f₀′(0) + v·e₀′(0))/(u + v)` — so no twist compatibility is
//! needed and every border's position and cross derivative is reproduced exactly.
//!
//! Sides run counter-clockwise seen from outside: side 0 is v = 0 (s = u), side 1 u = 1
//! (s = v), side 2 v = 1 (s = 1 − u), side 3 u = 0 (s = 1 − v); each side's X points into
//! the patch. Nothing in this form keeps `S_u × S_v` on one side of the tangent plane: the
//! paper's patches can fold, and the build names where ([`super::folds`]).

use crate::freeform::bezier::RationalBezier;
use crate::freeform::g1::{fit, hermite};
use glam::DVec3;

/// One border of a patch: its curve and its inward cross derivative
/// `X(s) = (k₀ + (k₁ − k₀)s)·g(s) + (h₀ + (h₁ − h₀)s)·C′(s)`, `g(s) = (1−s)g₀ + s g₁`.
#[derive(Debug, Clone, PartialEq)]
pub struct Side {
    pub curve: RationalBezier,
    pub g: (DVec3, DVec3),
    pub k: (f64, f64),
    pub h: (f64, f64),
}

impl Side {
    /// A side whose cross derivative is fitted to the legs `a0` (at s = 0) and `a1` (at
    /// s = 1), the neighbouring sides' derivatives leaving those corners into the patch: the
    /// paper's `k g + h C′` at both ends.
    pub fn fitted(curve: RationalBezier, g: (DVec3, DVec3), a0: DVec3, a1: DVec3) -> Side {
        let (d0, d1) = (curve.derivatives(0.0).d1, curve.derivatives(1.0).d1);
        let (k0, h0) = fit(a0, g.0, d0);
        let (k1, h1) = fit(a1, g.1, d1);
        Side {
            curve,
            g,
            k: (k0, k1),
            h: (h0, h1),
        }
    }

    /// The side's point at s.
    pub fn point(&self, s: f64) -> DVec3 {
        self.curve.eval(s)
    }

    /// The side's derivative at s.
    pub fn d1(&self, s: f64) -> DVec3 {
        self.curve.derivatives(s).d1
    }

    /// The cross derivative and its s-derivative at s.
    pub fn cross(&self, s: f64) -> (DVec3, DVec3) {
        let d = self.curve.derivatives(s);
        let g = self.g.0.lerp(self.g.1, s);
        let dg = self.g.1 - self.g.0;
        let (k, dk) = (self.k.0 + (self.k.1 - self.k.0) * s, self.k.1 - self.k.0);
        let (h, dh) = (self.h.0 + (self.h.1 - self.h.0) * s, self.h.1 - self.h.0);
        (k * g + h * d.d1, dk * g + k * dg + dh * d.d1 + h * d.d2)
    }
}

/// A Coons patch with variable twist over four sides.
#[derive(Debug, Clone, PartialEq)]
pub struct Coons {
    pub sides: [Side; 4],
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

    fn line(a: DVec3, b: DVec3) -> RationalBezier {
        RationalBezier::polynomial(vec![a, a.lerp(b, 1.0 / 3.0), a.lerp(b, 2.0 / 3.0), b]).unwrap()
    }

    /// A side's cross derivative is fitted to its legs at both corners, and its s-derivative
    /// is its difference quotient.
    #[test]
    fn a_side_fits_its_legs_and_differentiates() {
        let curve = RationalBezier::new(
            vec![
                DVec3::ZERO,
                DVec3::new(0.3, 0.2, 0.0),
                DVec3::new(0.7, 0.1, 0.05),
                DVec3::new(1.0, 0.0, 0.0),
            ],
            vec![1.0, 0.7, 1.2, 1.0],
        )
        .unwrap();
        let g = (DVec3::Y, DVec3::new(0.1, 1.0, 0.05));
        let a0 = 0.4 * g.0 + 0.3 * curve.derivatives(0.0).d1;
        let a1 = 0.2 * g.1 - 0.1 * curve.derivatives(1.0).d1;
        let side = Side::fitted(curve, g, a0, a1);
        assert!((side.cross(0.0).0 - a0).length() < 1e-12);
        assert!((side.cross(1.0).0 - a1).length() < 1e-12);
        for s in [0.1, 0.5, 0.9] {
            let h = 1e-6;
            let q = (side.cross(s + h).0 - side.cross(s - h).0) / (2.0 * h);
            assert!((q - side.cross(s).1).length() < 1e-6, "{q}");
        }
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
