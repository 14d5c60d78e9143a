//! Fusion quads: the Coons blend in ln R with Gregory's twist over a quad's rectangle
//! (docs/algorithms/envelope.md, "Fusion quads: Coons in ln R"): R > 0 whatever the data, and
//! a strip that does not change along the axis is reproduced exactly.

use super::side::{self, ChartSide};
use super::{Chart, Frame};
use crate::freeform::g1::hermite;
use glam::DVec2;
use std::collections::HashMap;

/// A corner of a fusion quad's rectangle in ln R and (u, v) units: the value, ∂u, ∂v, and the
/// twist as the bottom or top side gives it (its ∂v differentiated along u) and as the left or
/// right side gives it (its ∂u differentiated along v).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Corner {
    h: f64,
    du: f64,
    dv: f64,
    twist_from_u_side: f64,
    twist_from_v_side: f64,
}

/// The rectangle of a fusion quad's chart: sides 0 (z = z₀), 1 (x = x₁), 2 (z = z₁), 3 (x = x₀).
struct Rect {
    x0: f64,
    z0: f64,
    w: f64,
    d: f64,
}

/// A side's data at a point of the rectangle in ln R: value and gradient ∇ln R = ∇R/R.
fn log_data(d: side::Data) -> side::Data {
    side::Data {
        h: d.h.ln(),
        grad: d.grad / d.h,
        kappa: d.kappa,
    }
}

/// Side `s` (along x) at x, in ln R.
fn along_x(s: &ChartSide, x: f64) -> side::Data {
    log_data(s.data((x - s.a.x) / (s.b.x - s.a.x)))
}

/// Side `s` (along z) at z, in ln R.
fn along_z(s: &ChartSide, z: f64) -> side::Data {
    log_data(s.data((z - s.a.y) / (s.b.y - s.a.y)))
}

impl Chart {
    /// A fusion quad's sides in its rectangle: bottom (z = z₀), right, top and left.
    fn rect_sides(&self) -> [&ChartSide; 4] {
        [
            &self.sides[0],
            &self.sides[1],
            &self.sides[2],
            &self.sides[3],
        ]
    }

    fn rect(&self) -> Rect {
        let [bottom, right, top, left] = self.rect_sides();
        Rect {
            x0: left.a.x,
            z0: bottom.a.y,
            w: right.a.x - left.a.x,
            d: top.a.y - bottom.a.y,
        }
    }

    /// The corner data of the rectangle, corners (0, 0), (1, 0), (0, 1), (1, 1) in (u, v); the
    /// twists are difference quotients taken from the corner inwards.
    pub(super) fn coons_corners(&self) -> [Corner; 4] {
        let Rect { x0, z0, w, d } = self.rect();
        let [bottom, right, top, left] = self.rect_sides();
        let corner = |su: &ChartSide, sv: &ChartSide, at_u: f64, at_v: f64| {
            // su runs along x (bottom or top) through this corner, sv along z (left or right).
            let eps = 1e-6;
            let e_u = if at_u == 0.0 { eps } else { -eps };
            let e_v = if at_v == 0.0 { eps } else { -eps };
            let x = x0 + at_u * w;
            let z = z0 + at_v * d;
            let here = along_x(su, x);
            let there = along_z(sv, z);
            Corner {
                h: here.h,
                du: here.grad.x * w,
                dv: here.grad.y * d,
                twist_from_u_side: (along_x(su, x + e_u * w).grad.y - here.grad.y) * d / e_u,
                twist_from_v_side: (along_z(sv, z + e_v * d).grad.x - there.grad.x) * w / e_v,
            }
        };
        [
            corner(bottom, left, 0.0, 0.0),
            corner(bottom, right, 1.0, 0.0),
            corner(top, left, 0.0, 1.0),
            corner(top, right, 1.0, 1.0),
        ]
    }

    /// R = exp(F), F the bicubically blended Coons interpolant of ln R — the four sides'
    /// values and cross slopes (∂ ln R = ∂R/R) — with Gregory's variable twist at the corners
    /// (Coons with Gregory's twist, on a scalar): a fusion quad is the rectangle [x₀, x₁] × [0, D] of its
    /// chart, sides 0 (z = 0), 1 (x = x₁), 2 (z = D) and 3 (x = x₀). R > 0 whatever the data (a
    /// graph about the axis), and a strip that does not change along the axis is reproduced
    /// exactly — the strip between two equal aligned primitives is their section swept along d.
    pub(super) fn coons(&self, c: DVec2, corners: &[Corner; 4]) -> f64 {
        self.coons_from(c, corners, self.bottom_top(c.x), self.left_right(c.y))
    }

    /// The bottom and top sides' data at abscissa x, in ln R.
    fn bottom_top(&self, x: f64) -> [side::Data; 2] {
        [along_x(&self.sides[0], x), along_x(&self.sides[2], x)]
    }

    /// The left and right sides' data at height z, in ln R.
    fn left_right(&self, z: f64) -> [side::Data; 2] {
        [along_z(&self.sides[3], z), along_z(&self.sides[1], z)]
    }

    /// [`Chart::coons`] at many points, each side's data computed once for every abscissa and
    /// height the points share (a lattice's rows and columns).
    pub(super) fn coons_many(&self, cs: &[DVec2], corners: &[Corner; 4]) -> Vec<f64> {
        let mut xs: HashMap<u64, [side::Data; 2]> = HashMap::new();
        let mut zs: HashMap<u64, [side::Data; 2]> = HashMap::new();
        cs.iter()
            .map(|&c| {
                let bt = *xs
                    .entry(c.x.to_bits())
                    .or_insert_with(|| self.bottom_top(c.x));
                let lr = *zs
                    .entry(c.y.to_bits())
                    .or_insert_with(|| self.left_right(c.y));
                self.coons_from(c, corners, bt, lr)
            })
            .collect()
    }

    /// The Coons blend at c from the bottom and top sides' data at c.x and the left and right
    /// sides' at c.y.
    fn coons_from(
        &self,
        c: DVec2,
        [c00, c10, c01, c11]: &[Corner; 4],
        [b, t]: [side::Data; 2],
        [l, r]: [side::Data; 2],
    ) -> f64 {
        let Rect { x0, z0, w, d } = self.rect();
        let u = (c.x - x0) / w;
        let v = (c.y - z0) / d;
        // Side data at the point's projections, in (u, v) units: value and the slope across.
        let pu = hermite(u);
        let pv = hermite(v);
        let p_u = pu[0] * l.h + pu[1] * r.h + pu[2] * l.grad.x * w + pu[3] * r.grad.x * w;
        let p_v = pv[0] * b.h + pv[1] * t.h + pv[2] * b.grad.y * d + pv[3] * t.grad.y * d;
        // Gregory's twist: the bottom or top side's at u = 0 or 1, the left or right side's at
        // v = 0 or 1, blended between.
        let twist = |k: &Corner, a: f64, b: f64| {
            if a + b <= 0.0 {
                0.5 * (k.twist_from_u_side + k.twist_from_v_side)
            } else {
                (a * k.twist_from_u_side + b * k.twist_from_v_side) / (a + b)
            }
        };
        let t00 = twist(c00, v, u);
        let t10 = twist(c10, v, 1.0 - u);
        let t01 = twist(c01, 1.0 - v, u);
        let t11 = twist(c11, 1.0 - v, 1.0 - u);
        let m = [
            [c00.h, c01.h, c00.dv, c01.dv],
            [c10.h, c11.h, c10.dv, c11.dv],
            [c00.du, c01.du, t00, t01],
            [c10.du, c11.du, t10, t11],
        ];
        let mut p_uv = 0.0;
        for i in 0..4 {
            for j in 0..4 {
                p_uv += pu[i] * m[i][j] * pv[j];
            }
        }
        (p_u + p_v - p_uv).exp()
    }

    /// Whether the chart is a fusion quad's rectangle: four sides along +x, +z, −x, −z.
    pub(super) fn is_rectangle(&self) -> bool {
        let Frame::Axial(_) = self.frame else {
            return false;
        };
        let dirs = [
            DVec2::new(1.0, 0.0),
            DVec2::new(0.0, 1.0),
            DVec2::new(-1.0, 0.0),
            DVec2::new(0.0, -1.0),
        ];
        self.sides.len() == 4
            && self
                .sides
                .iter()
                .zip(dirs)
                .all(|(s, d)| s.along.distance(d) <= 1e-9)
    }
}
