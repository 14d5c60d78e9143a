//! The three kinds of flat chart (docs/algorithms/envelope.md, "Charts"):
//! each maps a point c of a plane domain and a scalar h to the surface point
//! `X(c, h) = O(c) + h·N(c)`, with O and N fixed by the scene, so a region is the graph of h.
//!
//! - **Radial** (a primitive's face f): `X = G + s·(p − G)`, p = o + c₁e₁ + c₂e₂ on the face's
//!   plane, h = s. Every network curve of the primitive lies in a plane through G, so the
//!   central projection maps it onto a straight side of the clipped face.
//! - **Axial** (a fusion quad between A and B): `X = G_A + z·d + R·e(θ)`, c = (R̄θ, z), h = R;
//!   a fusion edge joins points of equal polar angle, so it lies on a line θ = const.
//! - **Height** (a lid over a facet of the hull of the centres): `X = p + H·n`, p on the
//!   facet's plane, h = H.
//!
//! The tangent plane with unit normal n becomes the gradient of h: from `n·∂ₐX = 0`,
//! `∂ₐh = −(n·∂ₐO + h·n·∂ₐN)/(n·N)`, defined wherever n·N > 0.

use glam::{DVec2, DVec3};

/// How a chart point and a scalar make a surface point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Frame {
    /// `X = g + h (o + c₁e₁ + c₂e₂ − g)`; e₁ × e₂ is the face's outward normal.
    Radial {
        g: DVec3,
        o: DVec3,
        e1: DVec3,
        e2: DVec3,
    },
    /// `X = a + c₂ d + h (cos θ ex + sin θ ey)`, θ = θ₀ + c₁/R̄.
    Axial(Axial),
    /// `X = o + c₁e₁ + c₂e₂ + h n`, n = e₁ × e₂.
    Height { o: DVec3, e1: DVec3, e2: DVec3 },
}

/// Two unit vectors completing unit `n` to a right-handed frame (e₁ × e₂ = n), chosen from n
/// alone: e₁ = unit(n × a), a the world axis least parallel to n, e₂ = n × e₁ (also the polar
/// angles' frame of the fusion, `fusion.rs`).
pub fn plane_axes(n: DVec3) -> (DVec3, DVec3) {
    let a = [DVec3::X, DVec3::Y, DVec3::Z]
        .into_iter()
        .min_by(|p, q| p.dot(n).abs().total_cmp(&q.dot(n).abs()))
        .expect("three axes");
    let e1 = n.cross(a).normalize();
    (e1, n.cross(e1))
}

/// The axial chart of a fusion quad: `X = a + c₂ d + h (cos θ ex + sin θ ey)`, θ = θ₀ + c₁/R̄;
/// (ex, ey, d) right-handed, d along the axis from one centre to the other.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axial {
    pub a: DVec3,
    pub d: DVec3,
    pub ex: DVec3,
    pub ey: DVec3,
    /// The mean radius that turns polar angle into chart length.
    pub rbar: f64,
    /// The polar angle at c₁ = 0.
    pub theta0: f64,
}

impl Axial {
    /// The unit direction from the axis at chart abscissa c₁.
    fn around(&self, c1: f64) -> DVec3 {
        let th = self.theta0 + c1 / self.rbar;
        th.cos() * self.ex + th.sin() * self.ey
    }

    /// The chart point and radius of x (`None` on the axis).
    fn chart(&self, x: DVec3) -> Option<(DVec2, f64)> {
        let v = x - self.a;
        let z = v.dot(self.d);
        let r = v - z * self.d;
        let len = r.length();
        if len <= 0.0 {
            return None;
        }
        let th = r.dot(self.ey).atan2(r.dot(self.ex));
        let rel = (th - self.theta0 + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU)
            - std::f64::consts::PI;
        Some((DVec2::new(self.rbar * rel, z), len))
    }
}

impl Frame {
    /// The direction N along which h moves the point, at chart point c.
    pub fn direction(&self, c: DVec2) -> DVec3 {
        match *self {
            Frame::Radial { g, o, e1, e2 } => o + c.x * e1 + c.y * e2 - g,
            Frame::Axial(ax) => ax.around(c.x),
            Frame::Height { e1, e2, .. } => e1.cross(e2),
        }
    }

    /// The surface point of chart point c and scalar h.
    pub fn point(&self, c: DVec2, h: f64) -> DVec3 {
        match *self {
            Frame::Radial { g, .. } => g + h * self.direction(c),
            Frame::Axial(ax) => ax.a + c.y * ax.d + h * self.direction(c),
            Frame::Height { o, e1, e2 } => o + c.x * e1 + c.y * e2 + h * e1.cross(e2),
        }
    }

    /// The chart point and scalar of surface point x (`None` where x is not in the chart's
    /// half-space: behind the centre, on the axis).
    pub fn chart(&self, x: DVec3) -> Option<(DVec2, f64)> {
        match *self {
            Frame::Radial { g, o, e1, e2 } => {
                let n = e1.cross(e2);
                let h = (o - g).dot(n);
                let along = (x - g).dot(n);
                if along <= 0.0 || h <= 0.0 {
                    return None;
                }
                let s = along / h;
                let p = g + (x - g) / s;
                Some((DVec2::new((p - o).dot(e1), (p - o).dot(e2)), s))
            }
            Frame::Axial(ax) => ax.chart(x),
            Frame::Height { o, e1, e2 } => {
                let v = x - o;
                Some((DVec2::new(v.dot(e1), v.dot(e2)), v.dot(e1.cross(e2))))
            }
        }
    }

    /// The chart point and scalar of x, as [`Frame::chart`], and the derivative of the chart
    /// point along v: the map's differential in closed form.
    pub fn chart_along(&self, x: DVec3, v: DVec3) -> Option<(DVec2, f64, DVec2)> {
        let (c, h) = self.chart(x)?;
        let dc = match *self {
            Frame::Radial { g, o, e1, e2 } => {
                // p = g + k (x − g)/((x − g)·n), k = (o − g)·n.
                let n = e1.cross(e2);
                let (k, a) = ((o - g).dot(n), (x - g).dot(n));
                let dp = k * (v * a - (x - g) * v.dot(n)) / (a * a);
                DVec2::new(dp.dot(e1), dp.dot(e2))
            }
            Frame::Axial(ax) => {
                let w = x - ax.a;
                let r = w - w.dot(ax.d) * ax.d;
                let dr = v - v.dot(ax.d) * ax.d;
                let dtheta = ax.d.dot(r.cross(dr)) / r.length_squared();
                DVec2::new(ax.rbar * dtheta, v.dot(ax.d))
            }
            Frame::Height { e1, e2, .. } => DVec2::new(v.dot(e1), v.dot(e2)),
        };
        Some((c, h, dc))
    }

    /// The gradient of h at chart point c with scalar h that makes the surface tangent to the
    /// plane with unit normal n (`None` where n·N ≤ 0: the plane holds the chart's direction).
    pub fn gradient(&self, c: DVec2, h: f64, n: DVec3) -> Option<DVec2> {
        let dir = self.direction(c);
        let nn = n.dot(dir);
        if nn <= 1e-12 * dir.length() {
            return None;
        }
        Some(match *self {
            // ∂ₐO = 0, ∂ₐN = eₐ.
            Frame::Radial { e1, e2, .. } => -h * DVec2::new(n.dot(e1), n.dot(e2)) / nn,
            // ∂₁O = 0, ∂₁N = e′(θ)/R̄; ∂₂O = d, ∂₂N = 0.
            Frame::Axial(Axial { d, rbar, .. }) => {
                let e_prime = d.cross(dir);
                DVec2::new(-h * n.dot(e_prime) / (rbar * nn), -n.dot(d) / nn)
            }
            // ∂ₐO = eₐ, ∂ₐN = 0.
            Frame::Height { e1, e2, .. } => -DVec2::new(n.dot(e1), n.dot(e2)) / nn,
        })
    }

    /// The surface's partial derivatives ∂X/∂c₁, ∂X/∂c₂ where h has gradient `grad`.
    pub fn tangents(&self, c: DVec2, h: f64, grad: DVec2) -> (DVec3, DVec3) {
        let n = self.direction(c);
        match *self {
            Frame::Radial { e1, e2, .. } => (grad.x * n + h * e1, grad.y * n + h * e2),
            Frame::Axial(Axial { d, rbar, .. }) => {
                (grad.x * n + h * d.cross(n) / rbar, grad.y * n + d)
            }
            Frame::Height { e1, e2, .. } => (e1 + grad.x * n, e2 + grad.y * n),
        }
    }

    /// The scale from chart length to surface length at scalar h, up to the turn of the surface:
    /// s for the radial chart, R/R̄ for the axial one (at least 10⁻³), 1 for the height chart.
    pub fn scale(&self, h: f64) -> f64 {
        match *self {
            Frame::Radial { .. } => h,
            Frame::Axial(ax) => (h / ax.rbar).max(1e-3),
            Frame::Height { .. } => 1.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frames() -> Vec<Frame> {
        let (e1, e2) = plane_axes(DVec3::new(0.3, -0.5, 0.8).normalize());
        let (ex, ey) = plane_axes(DVec3::new(-0.2, 0.9, 0.1).normalize());
        vec![
            Frame::Radial {
                g: DVec3::new(0.1, 0.2, -0.3),
                o: DVec3::new(0.1, 0.2, -0.3) + 0.7 * e1.cross(e2),
                e1,
                e2,
            },
            Frame::Axial(Axial {
                a: DVec3::new(1.0, 0.0, 2.0),
                d: ex.cross(ey),
                ex,
                ey,
                rbar: 1.3,
                theta0: 0.4,
            }),
            Frame::Height {
                o: DVec3::new(-1.0, 0.5, 0.0),
                e1,
                e2,
            },
        ]
    }

    #[test]
    fn chart_inverts_point() {
        for f in frames() {
            for (c, h) in [(DVec2::new(0.2, -0.1), 1.3), (DVec2::new(-0.4, 0.5), 0.9)] {
                let x = f.point(c, h);
                let (c2, h2) = f.chart(x).unwrap();
                assert!((c2 - c).length() < 1e-12 && (h2 - h).abs() < 1e-12, "{f:?}");
            }
        }
    }

    /// The chart map's differential in closed form agrees with a central difference quotient.
    #[test]
    fn chart_along_is_the_differential() {
        for f in frames() {
            let x = f.point(DVec2::new(0.2, -0.1), 1.3);
            let v = DVec3::new(0.3, -0.7, 0.4);
            let (_, _, dc) = f.chart_along(x, v).unwrap();
            let e = 1e-6;
            let (c1, _) = f.chart(x + e * v).unwrap();
            let (c0, _) = f.chart(x - e * v).unwrap();
            assert!((dc - (c1 - c0) / (2.0 * e)).length() < 1e-8, "{f:?}");
        }
    }

    /// The gradient from a plane's normal makes the graph tangent to it: the surface's normal
    /// from difference quotients of X(c, h(c)) with h linear in c is the plane's.
    #[test]
    fn gradient_makes_tangent() {
        for f in frames() {
            let (c, h) = (DVec2::new(0.15, 0.05), 1.1);
            let x = f.point(c, h);
            let n = (f.direction(c).normalize() + DVec3::new(0.2, -0.1, 0.15)).normalize();
            let grad = f.gradient(c, h, n).unwrap();
            let e = 1e-6;
            let at = |dc: DVec2| f.point(c + dc, h + grad.dot(dc));
            let du = (at(DVec2::new(e, 0.0)) - x) / e;
            let dv = (at(DVec2::new(0.0, e)) - x) / e;
            assert!(du.dot(n).abs() < 1e-5 && dv.dot(n).abs() < 1e-5, "{f:?}");
            // And the graph faces along N.
            assert!(du.cross(dv).dot(f.direction(c)) > 0.0, "{f:?}");
        }
    }
}
