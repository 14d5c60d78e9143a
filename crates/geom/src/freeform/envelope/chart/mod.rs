//! The envelope as scalar graphs over flat charts (docs/algorithms/envelope.md,
//! "Charts"): the construction that cannot fold.
//!
//! Every region of the network has a flat convex domain in which it is a graph ([`frame`]):
//! a primitive's region is the central projection of its clipped face, a fusion quad a
//! rectangle in (R̄θ, z) about the axis of its two centres, a lid the hull facet of its
//! centres. Each side of the domain is the image of network curves, so the network fixes the
//! scalar h along it, and the tangent plane of the curve — **one unit normal n(τ) per curve**,
//! shared by both regions beside it — fixes h's gradient there ([`Frame::gradient`]):
//!
//! - a curve of a primitive (a curved edge or a piece of one, a silhouette edge) lies in a
//!   plane through the centre G: `n = unit(Π(C − G))`, Π the projection normal to C′ — the
//!   normal in the curve's own plane, equal to unit(P − G) at its ends (§6.3);
//! - a fusion edge: `n = unit(Π((1 − τ)n₀ + τn₁))`, n₀, n₁ its end vertices' normals.
//!
//! Inside a fusion quad's rectangle, ln R is the Coons interpolant of the four sides' data
//! ([`Chart::coons`]); inside every other region, h is the **side blend** of the sides'
//! ribbons ([`side`]):
//! `h(c) = Σᵢ wᵢ Rᵢ(c) / Σᵢ wᵢ`, `wᵢ = 1/δᵢ²`, δᵢ the distance of c from side i's line.
//! On side i every other weight vanishes to second order, so h and ∇h are side i's data: the
//! two regions beside a curve share their tangent plane all along it (G1 by construction, not
//! by fitting), and the surface does not depend on how the scene is listed. Because X is a
//! graph of h over a convex domain with h > 0 (radial: no ribbon falls below its floor; axial:
//! R = exp(F)), no region can fold or face inwards.
//!
//! **Enclosure of the faces.** On a primitive's chart the face itself is s = 1. Every network
//! curve of the primitive bulges outward (s ≥ 1 on the sides), and the slope across a side is
//! never negative (its normal leans away from the face's centre), so every ribbon is ≥ 1 and
//! so is their blend: the region holds its face.
//!
//! **Shape.** A radial ribbon rises from its side by at most `ρ(1 − cos φ)/h_f` (Λ = that/g),
//! the rise of a circle of radius ρ = t·|P − G| turning from the side's tangent plane (at φ
//! from the face normal n_f) to the face's direction; h_f is the face's distance from G. So t
//! sets how wide the rounding is, small t tends to the flat face, and at t = 1 every ribbon
//! levels off at r/h_f — the circumsphere's value at the face's foot.

pub mod frame;
pub mod lift;
pub mod mesh;
pub mod quality;
pub mod side;
mod strip;

use crate::freeform::envelope::tolerances::TOLERANCES;
pub use frame::{Axial, Frame};
use side::{ChartSide, Normals, Piece, Ribbons};
use strip::Corner;

use super::EnvelopeError;
use super::network::{CurveKind, Network, PatchSide, RegionKind};
use super::primitive::Primitive;
use glam::{DVec2, DVec3};

/// [`TOLERANCES`]`.straight_sides`.
const STRAIGHT: f64 = TOLERANCES.straight_sides;

/// The region's chart: its frame, its convex domain's sides counter-clockwise (seen from
/// outside), and the region sides along each.
#[derive(Debug, Clone, PartialEq)]
pub struct Chart {
    pub region: usize,
    pub frame: Frame,
    pub sides: Vec<ChartSide>,
    pub pieces: Vec<Vec<PatchSide>>,
    /// A fusion quad's rectangle: the Coons blend's corner data ([`Chart::coons`]), computed
    /// once; `None` for the side blend.
    coons: Option<[Corner; 4]>,
}

impl Chart {
    /// The scalar at chart point c: the Coons blend on a fusion quad's rectangle, the side
    /// blend elsewhere.
    pub fn value(&self, c: DVec2) -> f64 {
        match &self.coons {
            Some(corners) => self.coons(c, corners),
            None => self.side_blend(c),
        }
    }

    /// The side blend of the sides' ribbons.
    fn side_blend(&self, c: DVec2) -> f64 {
        let mut num = 0.0;
        let mut den = 0.0;
        for s in &self.sides {
            let (_, delta) = s.coords(c);
            let r = s.ribbon(c);
            if delta <= 1e-14 * s.length {
                return r;
            }
            let w = 1.0 / (delta * delta);
            num += w * r;
            den += w;
        }
        num / den
    }

    /// The surface point over chart point c.
    pub fn point(&self, c: DVec2) -> DVec3 {
        self.frame.point(c, self.value(c))
    }

    /// The surface points of many chart points ([`Chart::point`] of each; a fusion quad computes
    /// its sides' data once for each abscissa and height the points share).
    pub fn points(&self, cs: &[DVec2]) -> Vec<DVec3> {
        match &self.coons {
            Some(corners) => self
                .coons_many(cs, corners)
                .into_iter()
                .zip(cs)
                .map(|(h, &c)| self.frame.point(c, h))
                .collect(),
            None => cs.iter().map(|&c| self.point(c)).collect(),
        }
    }

    /// The domain's corners, counter-clockwise.
    pub fn corners(&self) -> Vec<DVec2> {
        self.sides.iter().map(|s| s.a).collect()
    }
}

/// The unit normal of region `chart` at surface point x on its side `side`, from the side's
/// data (value and gradient of h), not from the curve's normal.
fn normal_on_side(chart: &Chart, side: usize, x: DVec3) -> Option<DVec3> {
    let (c, _) = chart.frame.chart(x)?;
    let s = &chart.sides[side];
    let (sigma, _) = s.coords(c);
    let d = s.data(sigma);
    let (du, dv) = chart.frame.tangents(c, d.h, d.grad);
    Some(du.cross(dv).normalize_or_zero())
}

/// The largest angle (degrees) between the two regions' normals along the network's curves,
/// `samples` + 1 points a region side, each side's normal from its own chart's data.
pub fn largest_border_jump(net: &Network, charts: &[Chart], samples: usize) -> f64 {
    // Per curve: (chart, chart side, τ range) of every region along it.
    let mut along: Vec<Vec<(usize, usize, f64, f64)>> = vec![Vec::new(); net.curves.len()];
    for (k, ch) in charts.iter().enumerate() {
        for (i, pieces) in ch.pieces.iter().enumerate() {
            for p in pieces {
                along[p.curve].push((k, i, p.t0.min(p.t1), p.t0.max(p.t1)));
            }
        }
    }
    let mut worst = 0.0f64;
    for (c, list) in along.iter().enumerate() {
        for &(k, i, lo, hi) in list {
            for j in 0..=samples {
                let tau = lo + (hi - lo) * j as f64 / samples as f64;
                let x = net.curves[c].bezier.eval(tau);
                let Some(n) = normal_on_side(&charts[k], i, x) else {
                    continue;
                };
                for &(k2, i2, lo2, hi2) in list {
                    if k2 == k || tau < lo2 - 1e-12 || tau > hi2 + 1e-12 {
                        continue;
                    }
                    if let Some(m) = normal_on_side(&charts[k2], i2, x) {
                        worst = worst.max(n.cross(m).length().atan2(n.dot(m)).to_degrees());
                    }
                }
            }
        }
    }
    worst
}

/// The normal rule of every curve: radial about the centre of a primitive whose region runs
/// along it, else between its ends' normals.
fn normal_rules(net: &Network, prims: &[Primitive]) -> Vec<Normals> {
    let mut rules: Vec<Normals> = net
        .curves
        .iter()
        .map(|c| {
            Normals::Between(
                net.vertices[c.ends[0]].normal,
                net.vertices[c.ends[1]].normal,
            )
        })
        .collect();
    for r in &net.regions {
        if let RegionKind::Primitive { primitive, .. } = r.kind {
            for s in &r.sides {
                if net.curves[s.curve].kind != CurveKind::Fusion {
                    rules[s.curve] = Normals::Radial(prims[primitive].centre);
                }
            }
        }
    }
    rules
}

/// A hull facet as the lids need it: a point on its plane (a centre) and its outward normal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LidPlane {
    pub point: DVec3,
    pub normal: DVec3,
}

/// The frame of region `r`.
fn frame_of(
    net: &Network,
    r: usize,
    prims: &[Primitive],
    lids: &[LidPlane],
) -> Result<Frame, EnvelopeError> {
    let region = &net.regions[r];
    let corners: Vec<DVec3> = region
        .sides
        .iter()
        .map(|s| net.curves[s.curve].bezier.eval(s.t0))
        .collect();
    Ok(match region.kind {
        RegionKind::Primitive { primitive, face } => {
            let p = &prims[primitive];
            let nf = p.normals[face];
            let hf = (p.vertices[p.faces[face][0]] - p.centre).dot(nf);
            let (e1, e2) = frame::plane_axes(nf);
            Frame::Radial {
                g: p.centre,
                o: p.centre + hf * nf,
                e1,
                e2,
            }
        }
        RegionKind::Fusion { from, to } => {
            let a = prims[from].centre;
            let d = (prims[to].centre - a).normalize();
            let (ex, ey) = frame::plane_axes(d);
            let radial = |x: DVec3| {
                let v = x - a;
                v - v.dot(d) * d
            };
            let rbar =
                corners.iter().map(|&x| radial(x).length()).sum::<f64>() / corners.len() as f64;
            let mid = corners
                .iter()
                .map(|&x| radial(x).normalize_or_zero())
                .sum::<DVec3>();
            if rbar.is_nan() || rbar <= 0.0 || mid.length() <= 1e-12 {
                return Err(chart_error(r, "it surrounds the axis of its centres"));
            }
            Frame::Axial(Axial {
                a,
                d,
                ex,
                ey,
                rbar,
                theta0: mid.dot(ey).atan2(mid.dot(ex)),
            })
        }
        RegionKind::Lid { facet } => {
            let l = lids
                .get(facet)
                .ok_or_else(|| chart_error(r, "its hull facet is missing"))?;
            let (e1, e2) = frame::plane_axes(l.normal);
            Frame::Height { o: l.point, e1, e2 }
        }
    })
}

fn chart_error(r: usize, why: &str) -> EnvelopeError {
    EnvelopeError::Chart {
        region: r,
        why: why.to_string(),
    }
}

/// The charts of every region of `net`.
pub fn charts(
    net: &Network,
    prims: &[Primitive],
    lids: &[LidPlane],
) -> Result<Vec<Chart>, EnvelopeError> {
    let rules = normal_rules(net, prims);
    (0..net.regions.len())
        .map(|r| chart(net, r, prims, lids, &rules))
        .collect()
}

fn chart(
    net: &Network,
    r: usize,
    prims: &[Primitive],
    lids: &[LidPlane],
    rules: &[Normals],
) -> Result<Chart, EnvelopeError> {
    let frame = frame_of(net, r, prims, lids)?;
    let region = &net.regions[r];
    let ribbons = match frame {
        Frame::Radial { g, o, .. } => Ribbons::Radial {
            nf: (o - g).normalize(),
            hf: (o - g).length(),
        },
        Frame::Axial { .. } => Ribbons::Axial,
        Frame::Height { .. } => Ribbons::Height,
    };
    let pieces: Vec<Piece> = region
        .sides
        .iter()
        .map(|s| {
            let curve = &net.curves[s.curve];
            let [v0, v1] = curve.ends;
            Piece {
                curve: s.curve,
                bezier: curve.bezier.clone(),
                t0: s.t0,
                t1: s.t1,
                normals: rules[s.curve],
                rho: (net.vertices[v0].rho, net.vertices[v1].rho),
            }
        })
        .collect();
    // Straight runs of pieces are one side; start at a real corner.
    let ends: Vec<(DVec2, DVec2)> = pieces
        .iter()
        .map(|p| {
            let c0 = frame.chart(p.bezier.eval(p.t0)).map(|x| x.0);
            let c1 = frame.chart(p.bezier.eval(p.t1)).map(|x| x.0);
            c0.zip(c1)
                .ok_or_else(|| chart_error(r, &format!("curve {} leaves its chart", p.curve)))
        })
        .collect::<Result<_, _>>()?;
    let m = pieces.len();
    let turns = |i: usize| {
        let (a, b) = (ends[(i + m - 1) % m], ends[i]);
        let (u, v) = (a.1 - a.0, b.1 - b.0);
        let (lu, lv) = (u.length(), v.length());
        !(lu > 0.0 && lv > 0.0) || u.perp_dot(v).abs() > STRAIGHT * lu * lv || u.dot(v) < 0.0
    };
    let start = (0..m)
        .find(|&i| turns(i))
        .ok_or_else(|| chart_error(r, "its domain has no corner"))?;
    let mut sides = Vec::new();
    let mut along = Vec::new();
    let mut run: Vec<Piece> = Vec::new();
    let close = |run: Vec<Piece>| -> Result<(ChartSide, Vec<PatchSide>), EnvelopeError> {
        let patch_sides = run
            .iter()
            .map(|p| PatchSide {
                curve: p.curve,
                t0: p.t0,
                t1: p.t1,
            })
            .collect();
        let curves: Vec<usize> = run.iter().map(|p| p.curve).collect();
        let side = ChartSide::new(frame, ribbons, run).ok_or_else(|| {
            chart_error(
                r,
                &format!("its side along curve(s) {curves:?} is not a graph in its chart"),
            )
        })?;
        Ok((side, patch_sides))
    };
    for k in 0..m {
        let i = (start + k) % m;
        if k > 0 && turns(i) {
            let (side, ps) = close(std::mem::take(&mut run))?;
            sides.push(side);
            along.push(ps);
        }
        run.push(pieces[i].clone());
    }
    let (side, ps) = close(run)?;
    sides.push(side);
    along.push(ps);
    let n = sides.len();
    if n < 3 {
        return Err(chart_error(r, "its domain has fewer than three sides"));
    }
    for i in 0..n {
        let (u, v) = (sides[i].along, sides[(i + 1) % n].along);
        if u.perp_dot(v) <= 0.0 {
            return Err(chart_error(r, "its domain is not convex"));
        }
    }
    let mut chart = Chart {
        region: r,
        frame,
        sides,
        pieces: along,
        coons: None,
    };
    if chart.is_rectangle() {
        chart.coons = Some(chart.coons_corners());
    }
    Ok(chart)
}
