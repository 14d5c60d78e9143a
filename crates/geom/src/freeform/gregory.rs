//! The bicubic Gregory patch (Chiyokura & Kimura 1983; seeds 003 and 004;
//! docs/algorithms/skin.md, "Patches and G1").
//!
//! Twenty control points: the 12 boundary points `P_ij` (i or j ∈ {0, 3}) and each of the four
//! interior points in two copies, `P_ij^(v)` tied to the nearer v-boundary (j = 1: v = 0,
//! j = 2: v = 1) and `P_ij^(u)` tied to the nearer u-boundary. With `w_u = u` (i = 1) or `1 − u`
//! (i = 2) and `w_v` likewise,
//!
//! ```text
//! S(u, v) = Σ_i Σ_j B_i(u) B_j(v) P_ij(u, v),     P_ij = (w_u P_ij^(v) + w_v P_ij^(u)) / (w_u + w_v)
//! ```
//!
//! so the cross derivative along each boundary depends only on that boundary's copies
//! (`S_u(0, v) = 3 Σ_j B_j(v)(P_1j^(u) − P_0j)`, …): each border can be made G1 with its
//! neighbour on its own. At a corner, where `w_u + w_v = 0`, the average of the copies is used
//! (its Bernstein weight vanishes there). Equal copies give the bicubic Bézier patch.

use glam::DVec3;

/// A bicubic Gregory patch. `points[i][j]` is `P_ij` (u index i, v index j), its interior
/// entries the copies tied to the v-boundaries; `u_copies[i − 1][j − 1]` the copies tied to
/// the u-boundaries.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gregory {
    pub points: [[DVec3; 4]; 4],
    pub u_copies: [[DVec3; 2]; 2],
}

/// Position, first partial derivatives and unit normal at a parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchPoint {
    pub point: DVec3,
    pub du: DVec3,
    pub dv: DVec3,
    pub normal: DVec3,
}

fn bernstein(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t]
}

fn bernstein_d(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    // B_i' = 3(B_(i−1)^2 − B_i^2).
    let q = [s * s, 2.0 * s * t, t * t];
    [
        -3.0 * q[0],
        3.0 * (q[0] - q[1]),
        3.0 * (q[1] - q[2]),
        3.0 * q[2],
    ]
}

impl Gregory {
    /// The bicubic Bézier patch with control net `p` as a Gregory patch (both copies equal).
    pub fn from_bezier(p: [[DVec3; 4]; 4]) -> Gregory {
        Gregory {
            points: p,
            u_copies: [[p[1][1], p[1][2]], [p[2][1], p[2][2]]],
        }
    }

    /// The blended interior point `P_ij(u, v)` and its partial derivatives.
    fn interior(&self, i: usize, j: usize, u: f64, v: f64) -> (DVec3, DVec3, DVec3) {
        let pv = self.points[i][j];
        let pu = self.u_copies[i - 1][j - 1];
        let (wu, su) = if i == 1 { (u, 1.0) } else { (1.0 - u, -1.0) };
        let (wv, sv) = if j == 1 { (v, 1.0) } else { (1.0 - v, -1.0) };
        let den = wu + wv;
        if den <= 0.0 {
            return (0.5 * (pv + pu), DVec3::ZERO, DVec3::ZERO);
        }
        let p = (wu * pv + wv * pu) / den;
        let d2 = den * den;
        let du = su * wv * (pv - pu) / d2;
        let dv = sv * wu * (pu - pv) / d2;
        (p, du, dv)
    }

    /// `S`, `S_u` and `S_v` at (u, v): the Bernstein sums of §7.3, the interior points blended
    /// and their own derivatives included.
    fn sums(&self, u: f64, v: f64) -> (DVec3, DVec3, DVec3) {
        let (bu, bv) = (bernstein(u), bernstein(v));
        let (du_b, dv_b) = (bernstein_d(u), bernstein_d(v));
        let (mut p, mut du, mut dv) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
        for i in 0..4 {
            for j in 0..4 {
                let inner = (1..=2).contains(&i) && (1..=2).contains(&j);
                let (q, qu, qv) = if inner {
                    self.interior(i, j, u, v)
                } else {
                    (self.points[i][j], DVec3::ZERO, DVec3::ZERO)
                };
                p += bu[i] * bv[j] * q;
                du += du_b[i] * bv[j] * q + bu[i] * bv[j] * qu;
                dv += bu[i] * dv_b[j] * q + bu[i] * bv[j] * qv;
            }
        }
        (p, du, dv)
    }

    /// Position, partials and normal at (u, v) ∈ [0, 1]². Where
    /// `S_u × S_v` vanishes (a corner with collinear legs) the normal is taken a small step
    /// towards the patch centre.
    pub fn eval(&self, u: f64, v: f64) -> PatchPoint {
        let (p, du, dv) = self.sums(u, v);
        let mut n = du.cross(dv);
        if n.length_squared() <= 1e-30 * (du.length_squared() + dv.length_squared()).powi(2) {
            let (cu, cv) = (u + 1e-6 * (0.5 - u).signum(), v + 1e-6 * (0.5 - v).signum());
            let (_, su, sv) = self.sums(cu, cv);
            n = su.cross(sv);
        }
        PatchPoint {
            point: p,
            du,
            dv,
            normal: n.normalize_or_zero(),
        }
    }

    /// The patch's point at (u, v).
    pub fn point(&self, u: f64, v: f64) -> DVec3 {
        self.sums(u, v).0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn net() -> [[DVec3; 4]; 4] {
        let mut p = [[DVec3::ZERO; 4]; 4];
        for (i, row) in p.iter_mut().enumerate() {
            for (j, q) in row.iter_mut().enumerate() {
                let (x, y) = (i as f64, j as f64);
                *q = DVec3::new(x, y, 0.3 * (x * y).sin() + 0.1 * x * x - 0.2 * y);
            }
        }
        p
    }

    fn bezier(p: &[[DVec3; 4]; 4], u: f64, v: f64) -> DVec3 {
        let (bu, bv) = (bernstein(u), bernstein(v));
        let mut s = DVec3::ZERO;
        for i in 0..4 {
            for j in 0..4 {
                s += bu[i] * bv[j] * p[i][j];
            }
        }
        s
    }

    /// Equal copies: the bicubic Bézier patch.
    #[test]
    fn equal_copies_give_the_bezier_patch() {
        let p = net();
        let g = Gregory::from_bezier(p);
        for k in 0..=10 {
            for l in 0..=10 {
                let (u, v) = (k as f64 / 10.0, l as f64 / 10.0);
                assert!((g.point(u, v) - bezier(&p, u, v)).length() < 1e-14);
            }
        }
    }

    /// Partials against central differences with unequal copies, and the cross derivative
    /// along u = 0 depends only on the u-copies (§7.2).
    #[test]
    fn partials_and_boundary_cross_derivatives() {
        let mut g = Gregory::from_bezier(net());
        g.u_copies[0][0] += DVec3::new(0.2, -0.1, 0.4);
        g.u_copies[1][1] += DVec3::new(-0.3, 0.2, 0.1);
        g.points[2][1] += DVec3::new(0.1, 0.1, -0.3);
        let h = 1e-6;
        for &(u, v) in &[(0.3, 0.6), (0.71, 0.2), (0.5, 0.5)] {
            let e = g.eval(u, v);
            let fu = (g.point(u + h, v) - g.point(u - h, v)) / (2.0 * h);
            let fv = (g.point(u, v + h) - g.point(u, v - h)) / (2.0 * h);
            assert!((e.du - fu).length() < 1e-8, "{} {}", e.du, fu);
            assert!((e.dv - fv).length() < 1e-8);
        }
        for k in 1..10 {
            let v = k as f64 / 10.0;
            let bv = bernstein(v);
            let p = &g.points;
            let c = &g.u_copies;
            let want = 3.0
                * (bv[0] * (p[1][0] - p[0][0])
                    + bv[1] * (c[0][0] - p[0][1])
                    + bv[2] * (c[0][1] - p[0][2])
                    + bv[3] * (p[1][3] - p[0][3]));
            assert!((g.eval(0.0, v).du - want).length() < 1e-13);
        }
    }
}
