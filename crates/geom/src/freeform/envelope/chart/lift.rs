//! Enclosure by construction: the fusion strips lifted, and primitive and lid regions raised,
//! over the primitives' points the paper's central cut leaves out (docs/algorithms/envelope.md,
//! "Enclosure", "Raises"). Both are positive bumps on a
//! graph, computed once; the surface stays a graph over the same charts ([`Raise`] below).
//!
//! The paper cuts each primitive by the plane through its centre normal to d, the direction
//! to its partner, and joins the two sections by a strip that leaves each section along d. A
//! primitive wider beyond that plane than at it (a cube seen along a body diagonal) then has
//! corners outside the strip at small t. The strip is a graph `R(θ, z)` about the axis
//! `G_A + z·d` (`frame.rs`, Axial), so raising it keeps it a graph: the lifted strip is
//!
//! `R′(θ, z) = R(θ, z)·exp(L(θ, z))`, L the [`smooth_max`] of the terms `λ_v·b_θ(θ − θ_v)·b_z(z; z_v)`,
//!
//! one term for every sample point v ([`sample_points`]) of either primitive's removed part, or
//! of any other primitive's part outside its own regions (a third primitive's corner, a swallowed
//! primitive's) not more than [`RAISE_REACH`] above the strip, that lies between the two
//! silhouette planes, 0 < z_v < D, over the strip's quads — or over a lid it ends at, less than
//! half a term's width past their common fusion edge and at least [`LID_CORNER`] of the strip's
//! length from its ends, R(θ_v, z_v) then the lid's along that ray ([`lid_value`]) — and not
//! more than [`TRIGGER`] under the surface, with `λ_v = ln(R_v(1 + μ)/R(θ_v, z_v))`,
//! μ = [`MARGIN`]. Every term is non-negative and L is at least each, which is λ_v at its own
//! point, so `R′ ≥ R_v(1 + μ)` at every such point: the removed corners and edges lie inside.
//! `b_z` rises from 0 at z = 0 to 1 at z_v and falls to 0 at z = D, `b_θ` falls from 1 to 0 at
//! |θ − θ_v| = [`WIDTH`], both smoothsteps (value and slope 0 at their ends, 1 and 0 at the top).
//!
//! The lift is a map of space, `(θ, z, R) ↦ (θ, z, R·exp(L(θ, z)·c(R)))`, c = 1 up to
//! [`INNER`] times the largest radius it lifts a point to and falling smoothly to 0 at
//! [`REACH`] times that: L and its gradient vanish on both silhouette planes (the borders with
//! the primitives' own charts, whose tangent planes it keeps), and every vertex of the mesh in
//! its reach — the strip's, a lid's beside it, another region's that comes near — is moved by
//! it (`Envelope::chart_mesh`), so the surface stays closed and tangent-continuous across every
//! border the map crosses. Where several lifts reach one vertex (about a lid's corner), their
//! displacements are weighted by the fourth power of their lengths.

use super::{Axial, Chart, Frame};
use crate::analysis::face_grid::FaceGrid;
use crate::freeform::envelope::network::{CurveKind, Network, RegionKind};
use crate::freeform::envelope::primitive::Primitive;
use crate::freeform::envelope::tolerances::TOLERANCES;
use glam::{DVec2, DVec3};
use rayon::prelude::*;
use std::f64::consts::PI;

/// [`TOLERANCES`]`.margin`.
pub const MARGIN: f64 = TOLERANCES.margin;

/// [`TOLERANCES`]`.trigger`.
pub const TRIGGER: f64 = TOLERANCES.trigger;

/// [`TOLERANCES`]`.width`.
pub const WIDTH: f64 = TOLERANCES.width;

/// [`TOLERANCES`]`.smooth_max`.
const SMOOTH_MAX: i32 = TOLERANCES.smooth_max;

/// [`TOLERANCES`]`.edge_points`.
const EDGE_POINTS: usize = TOLERANCES.edge_points;

/// One term of L.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Bump {
    theta: f64,
    z: f64,
    lambda: f64,
    width: f64,
}

/// The lift of the strip between primitives `from` and `to` (its axis as the strip's charts
/// have it).
#[derive(Debug, Clone, PartialEq)]
pub struct Lift {
    pub from: usize,
    pub to: usize,
    a: DVec3,
    d: DVec3,
    ex: DVec3,
    ey: DVec3,
    length: f64,
    bumps: Vec<Bump>,
    /// The lift is whole up to this distance from the axis and fades out by [`Lift::outer`]
    /// (`REACH` times it), so that it moves the strip and the regions beside it and leaves
    /// far parts of the surface where they are.
    inner: f64,
}

/// [`TOLERANCES`]`.lid_corner`.
const LID_CORNER: f64 = TOLERANCES.lid_corner;

/// [`TOLERANCES`]`.lift_inner`.
const INNER: f64 = TOLERANCES.lift_inner;

/// [`TOLERANCES`]`.lift_reach`.
const REACH: f64 = TOLERANCES.lift_reach;

/// The `SMOOTH_MAX`-norm of non-negative terms.
fn smooth_max(terms: impl Iterator<Item = f64>) -> f64 {
    terms
        .fold(0.0, |acc, x| acc + x.powi(SMOOTH_MAX))
        .powf(1.0 / f64::from(SMOOTH_MAX))
}

fn smoothstep(u: f64) -> f64 {
    let u = u.clamp(0.0, 1.0);
    u * u * (3.0 - 2.0 * u)
}

/// The signed angle from b to a, in (−π, π].
fn angle_between(a: f64, b: f64) -> f64 {
    let x = (a - b).rem_euclid(2.0 * PI);
    if x > PI { x - 2.0 * PI } else { x }
}

impl Lift {
    /// (θ, z, R) of x about the strip's axis.
    fn cylindrical(&self, x: DVec3) -> (f64, f64, f64) {
        let v = x - self.a;
        let z = v.dot(self.d);
        let r = v - z * self.d;
        (r.dot(self.ey).atan2(r.dot(self.ex)), z, r.length())
    }

    /// L at (θ, z).
    pub fn at(&self, theta: f64, z: f64) -> f64 {
        if !(z > 0.0 && z < self.length) {
            return 0.0;
        }
        smooth_max(self.bumps.iter().map(|b| {
            let bz = if z <= b.z {
                smoothstep(z / b.z)
            } else {
                smoothstep((self.length - z) / (self.length - b.z))
            };
            let bt = smoothstep(1.0 - angle_between(theta, b.theta).abs() / b.width);
            b.lambda * bz * bt
        }))
    }

    /// The distance from the axis by which the lift has faded out.
    fn outer(&self) -> f64 {
        REACH * self.inner
    }

    /// The lifted point of x: `R ↦ R·exp(L(θ, z)·c(R))`, c = 1 up to [`Lift::inner`] and
    /// falling smoothly to 0 at [`Lift::outer`].
    pub fn apply(&self, x: DVec3) -> DVec3 {
        let (theta, z, r) = self.cylindrical(x);
        if r <= 0.0 || r >= self.outer() {
            return x;
        }
        let fade = 1.0 - smoothstep((r - self.inner) / (self.outer() - self.inner));
        let l = self.at(theta, z) * fade;
        if l == 0.0 {
            return x;
        }
        let radial = x - self.a - z * self.d;
        x + radial * (l.exp() - 1.0)
    }

    /// A box that holds every point the lift moves.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        let (p, q) = (self.a, self.a + self.length * self.d);
        let pad = DVec3::splat(self.outer());
        (p.min(q) - pad, p.max(q) + pad)
    }

    /// Whether the lift moves nothing.
    pub fn is_empty(&self) -> bool {
        self.bumps.is_empty()
    }
}

/// Points of primitive `p`: its vertices, [`EDGE_POINTS`] points along each edge, each face's
/// centre and the points halfway from it to the face's corners.
fn sample_points(p: &Primitive) -> Vec<DVec3> {
    let mut out: Vec<DVec3> = p.vertices.clone();
    let edges: std::collections::BTreeSet<(usize, usize)> = p
        .faces
        .iter()
        .flat_map(|f| (0..f.len()).map(move |k| (f[k], f[(k + 1) % f.len()])))
        .map(|(i, j)| (i.min(j), i.max(j)))
        .collect();
    for (i, j) in edges {
        let (a, b) = (p.vertices[i], p.vertices[j]);
        out.extend((1..=EDGE_POINTS).map(|s| a.lerp(b, s as f64 / (EDGE_POINTS + 1) as f64)));
    }
    for f in &p.faces {
        let c = f.iter().map(|&i| p.vertices[i]).sum::<DVec3>() / f.len() as f64;
        out.push(c);
        out.extend(f.iter().map(|&i| c.lerp(p.vertices[i], 0.5)));
    }
    out
}

/// The strip's value R(θ, z) at x's angle and position along the axis, from the chart of its
/// fusion quad holding it; none where no quad does (beyond the strip's ends).
fn strip_value(charts: &[&Chart], x: DVec3) -> Option<f64> {
    charts.iter().find_map(|ch| {
        let (c, _) = ch.frame.chart(x)?;
        let inside = ch.sides.iter().all(|s| s.coords(c).1 >= -1e-12 * s.length);
        inside.then(|| ch.value(c))
    })
}

/// Where the ray from `base` on a strip's axis through x meets the lid of chart `lid`, as a
/// distance from `base` (the ray starts under the lid, on the hull edge); none where
/// x's foot is not over the lid's domain or the ray does not leave the lid's underside.
fn lid_value(lid: &Chart, base: DVec3, x: DVec3) -> Option<f64> {
    let (c, _) = lid.frame.chart(x)?;
    if lid.sides.iter().any(|s| s.coords(c).1 < 0.0) {
        return None;
    }
    let dir = (x - base).normalize_or_zero();
    let above = |rho: f64| -> Option<f64> {
        let (c, h) = lid.frame.chart(base + rho * dir)?;
        Some(h - lid.value(c))
    };
    let (mut lo, mut hi) = (0.0, base.distance(x));
    let mut flo = above(lo)?;
    if flo >= 0.0 {
        return None;
    }
    let mut fhi = above(hi)?;
    while fhi < 0.0 {
        hi *= 2.0;
        if hi > 1e3 * base.distance(x) {
            return None;
        }
        fhi = above(hi)?;
    }
    // Regula falsi with the Illinois step (the stale end's value halved), to 10⁻¹² of the
    // bracket: a few steps where bisection took 48.
    let mut side = 0;
    for _ in 0..64 {
        let mid = (lo * fhi - hi * flo) / (fhi - flo);
        let fm = above(mid)?;
        if fm < 0.0 {
            (lo, flo) = (mid, fm);
            if side == -1 {
                fhi *= 0.5;
            }
            side = -1;
        } else {
            (hi, fhi) = (mid, fm);
            if side == 1 {
                flo *= 0.5;
            }
            side = 1;
        }
        if hi - lo <= 1e-12 * hi || fm == 0.0 {
            break;
        }
    }
    Some(if flo.abs() < fhi.abs() { lo } else { hi })
}

/// The strips' lifts and the regions' raises that hold the primitives ([`lifts`], [`raises`]),
/// from each primitive's [`sample_points`], computed once.
pub fn enclosure(net: &Network, charts: &[Chart], prims: &[Primitive]) -> (Vec<Lift>, Vec<Raise>) {
    let samples: Vec<Vec<DVec3>> = prims.iter().map(sample_points).collect();
    // A primitive's partners: the other ends of its strips. Its part on this side of every
    // cut towards them lies under its own regions (s ≥ 1): only the rest can stick out.
    let mut partners: Vec<Vec<usize>> = vec![Vec::new(); prims.len()];
    for r in &net.regions {
        if let RegionKind::Fusion { from, to } = r.kind {
            if !partners[from].contains(&to) {
                partners[from].push(to);
            }
            if !partners[to].contains(&from) {
                partners[to].push(from);
            }
        }
    }
    let loose: Vec<Vec<bool>> = prims
        .iter()
        .enumerate()
        .map(|(i, p)| {
            samples[i]
                .iter()
                .map(|&x| {
                    partners[i].is_empty()
                        || partners[i]
                            .iter()
                            .any(|&j| (x - p.centre).dot(prims[j].centre - p.centre) > 0.0)
                })
                .collect()
        })
        .collect();
    let (lifts, held) = lifts(net, charts, prims, &samples, &loose);
    let raises = raises(charts, net, &samples, &loose, &held);
    (lifts, raises)
}

/// The lift of every fusion strip of the network that has a removed point outside it, and which
/// of each primitive's `samples` the lifts hold: those between a strip's silhouette planes, in
/// its quads' angle and at least a quarter of [`WIDTH`] from its ends at a lid.
fn lifts(
    net: &Network,
    charts: &[Chart],
    prims: &[Primitive],
    samples: &[Vec<DVec3>],
    loose: &[Vec<bool>],
) -> (Vec<Lift>, Vec<Vec<bool>>) {
    let mut held: Vec<Vec<bool>> = samples.iter().map(|s| vec![false; s.len()]).collect();
    let mut strips: Vec<(usize, usize)> = net
        .regions
        .iter()
        .filter_map(|r| match r.kind {
            RegionKind::Fusion { from, to } => Some((from, to)),
            _ => None,
        })
        .collect();
    strips.sort_unstable();
    strips.dedup();
    let mut out = Vec::new();
    for (from, to) in strips {
        let quads: Vec<&Chart> = charts
            .iter()
            .filter(|ch| {
                matches!(net.regions[ch.region].kind,
                    RegionKind::Fusion { from: f, to: t } if (f, t) == (from, to))
            })
            .collect();
        let Some(Frame::Axial(Axial { a, d, ex, ey, .. })) = quads.first().map(|c| c.frame) else {
            continue;
        };
        let length = (prims[to].centre - a).dot(d);
        let mut lift = Lift {
            from,
            to,
            a,
            d,
            ex,
            ey,
            length,
            bumps: Vec::new(),
            inner: 0.0,
        };
        // The lids the strip ends at, with the angle of the fusion edge it meets each along: a
        // point over a lid less than half a term's width past that edge is held by the lift too
        // (one smooth map across the edge), not by a steep raise of the lid beside its side.
        let lids: Vec<(f64, &Chart)> = net
            .regions
            .iter()
            .enumerate()
            .filter(|(_, r)| matches!(r.kind, RegionKind::Lid { .. }))
            .filter_map(|(k, r)| {
                let s = r.sides.iter().find(|s| {
                    net.curves[s.curve].kind == CurveKind::Fusion
                        && quads
                            .iter()
                            .any(|ch| ch.pieces.iter().flatten().any(|p| p.curve == s.curve))
                })?;
                let end = lift.cylindrical(net.curves[s.curve].bezier.eval(0.5)).0;
                Some((end, charts.iter().find(|ch| ch.region == k)?))
            })
            .collect();
        // Another primitive is met only if its sphere comes within reach of the strip: between
        // its silhouette planes and less than [`RAISE_REACH`] above twice its corners' radii.
        let widest = quads
            .iter()
            .flat_map(|ch| ch.sides.iter().map(|s| ch.value(s.a)))
            .fold(0.0, f64::max);
        let near: Vec<bool> = prims
            .iter()
            .map(|p| {
                let (_, z, r) = lift.cylindrical(p.centre);
                z + p.radius > 0.0
                    && z - p.radius < length
                    && r - p.radius < 2.0 * widest * (1.0 + RAISE_REACH)
            })
            .collect();
        for (i, p) in prims.iter().enumerate() {
            let own = i == from || i == to;
            if !own && !near[i] {
                continue;
            }
            for (k, &x) in samples[i].iter().enumerate() {
                let beyond = if i == from {
                    (x - p.centre).dot(d) > 0.0
                } else if i == to {
                    (x - p.centre).dot(d) < 0.0
                } else {
                    loose[i][k]
                };
                if !beyond {
                    continue;
                }
                let (theta, z, r) = lift.cylindrical(x);
                if !(z > 0.0 && z < length) || r <= 0.0 {
                    continue;
                }
                let Some(r0) = strip_value(&quads, x).or_else(|| {
                    lids.iter()
                        .filter(|(end, _)| {
                            angle_between(theta, *end).abs() < 0.5 * WIDTH
                                && z.min(length - z) > LID_CORNER * length
                        })
                        .find_map(|(_, lid)| lid_value(lid, lift.a + z * lift.d, x))
                }) else {
                    continue;
                };
                // Another primitive's point far above the strip lies beyond another part of the
                // surface, not under this one.
                if !own && r > r0 * (1.0 + RAISE_REACH) {
                    continue;
                }
                held[i][k] = true;
                // A point under the strip by more than [`TRIGGER`] is left as it lies.
                if r * (1.0 + TRIGGER) <= r0 {
                    continue;
                }
                lift.inner = lift.inner.max(INNER * r * (1.0 + MARGIN));
                lift.bumps.push(Bump {
                    theta,
                    z,
                    lambda: (r * (1.0 + MARGIN) / r0).ln(),
                    width: WIDTH,
                });
            }
        }
        if !lift.is_empty() {
            out.push(lift);
        }
    }
    (out, held)
}

/// A raise of one primitive's or lid's region over the points that no strip's lift holds: a
/// corner past the partner's centre plane (primitives overlapping deeply), one near a lid's corner, a
/// swallowed primitive's. On the region's chart, `h′(c) = h(c) +` the [`smooth_max`] of the `λ_v·B_v(c)`,
/// `B_v(c) = Π_i smoothstep(min(1, δ_i(c)/δ_i(c_v)))`, δ_i the distance from the domain's side i:
/// 1 at the point's own chart point c_v and, with its gradient, 0 on every side of the domain —
/// the region's borders, their tangent planes and every other region stay as they are.
/// `λ_v = h_v(1 + μ) − h(c_v)` for a point v at (c_v, h_v) in the chart less than [`TRIGGER`]
/// under the graph or above it by at most [`RAISE_REACH`] (a point further out lies beyond another part
/// of the surface, not under this one); a primitive's own regions hold it already (s ≥ 1).
#[derive(Debug, Clone, PartialEq)]
pub struct Raise {
    pub region: usize,
    bumps: Vec<(DVec2, f64)>,
}

/// [`TOLERANCES`]`.raise_reach`.
pub const RAISE_REACH: f64 = TOLERANCES.raise_reach;

impl Raise {
    /// The [`smooth_max`] of the λ_v B_v at chart point c of `chart` (the chart of [`Raise::region`]).
    pub fn at(&self, chart: &Chart, c: DVec2) -> f64 {
        smooth_max(self.bumps.iter().map(|&(cv, lambda)| {
            lambda
                * chart
                    .sides
                    .iter()
                    .map(|s| smoothstep(s.coords(c).1 / s.coords(cv).1))
                    .product::<f64>()
        }))
    }

    /// The raised point of surface point x of the region.
    pub fn apply(&self, chart: &Chart, x: DVec3) -> DVec3 {
        let Some((c, h)) = chart.frame.chart(x) else {
            return x;
        };
        let l = self.at(chart, c);
        if l == 0.0 {
            return x;
        }
        chart.frame.point(c, h + l)
    }
}

/// The raises of the primitives' and lids' regions over every point of every primitive
/// (its `samples`) that lies above one of them and that no strip's lift holds (`held`).
fn raises(
    charts: &[Chart],
    net: &Network,
    samples: &[Vec<DVec3>],
    loose: &[Vec<bool>],
    held: &[Vec<bool>],
) -> Vec<Raise> {
    let mut points: Vec<(usize, DVec3)> = Vec::new();
    for (i, s) in samples.iter().enumerate() {
        for (k, &x) in s.iter().enumerate() {
            if loose[i][k] && !held[i][k] {
                points.push((i, x));
            }
        }
    }
    // A ball about each region's corners that holds every point a raise can reach.
    let balls: Vec<(DVec3, f64)> = charts
        .par_iter()
        .map(|ch| {
            let corners: Vec<DVec3> = ch
                .sides
                .iter()
                .map(|s| ch.frame.point(s.a, ch.value(s.a)))
                .collect();
            let mid = corners.iter().sum::<DVec3>() / corners.len().max(1) as f64;
            let reach = corners.iter().map(|c| c.distance(mid)).fold(0.0, f64::max);
            (mid, reach * (2.0 + RAISE_REACH))
        })
        .collect();
    // The points on a grid, each as a box of the median reach, so that a region meets the
    // points near it rather than all of them.
    let mut reaches: Vec<f64> = balls
        .iter()
        .map(|b| b.1)
        .filter(|r| r.is_finite())
        .collect();
    reaches.sort_by(f64::total_cmp);
    let pad = DVec3::splat(reaches.get(reaches.len() / 2).copied().unwrap_or(0.0));
    let grid = (!points.is_empty())
        .then(|| FaceGrid::of_boxes(points.iter().map(|p| (p.1 - pad, p.1 + pad)).collect(), 1e6));
    // Every region's raise on its own (in parallel, like the meshing).
    let raise = |(ch, &(mid, reach)): (&Chart, &(DVec3, f64))| -> Option<Raise> {
        // A primitive's own regions hold its faces by construction (s ≥ 1).
        let own = match net.regions[ch.region].kind {
            RegionKind::Fusion { .. } => return None,
            RegionKind::Primitive { primitive, .. } => Some(primitive),
            RegionKind::Lid { .. } => None,
        };
        let mut near = Vec::new();
        if let Some(g) = &grid {
            let r = DVec3::splat(reach);
            g.for_each_overlapping((mid - r, mid + r), |k| near.push(k));
        }
        // In the order of the points, as a scan would meet them.
        near.sort_unstable();
        let mut bumps = Vec::new();
        for &(i, x) in near.iter().map(|&k| &points[k]) {
            if own == Some(i) || x.distance(mid) > reach {
                continue;
            }
            let Some((c, hx)) = ch.frame.chart(x) else {
                continue;
            };
            let least = ch
                .sides
                .iter()
                .map(|s| s.coords(c).1 / s.length)
                .fold(f64::INFINITY, f64::min);
            if least <= 1e-6 {
                continue;
            }
            let h = ch.value(c);
            if hx * (1.0 + TRIGGER) <= h || hx > h * (1.0 + RAISE_REACH) {
                continue;
            }
            let lambda = hx * (1.0 + MARGIN) - h;
            bumps.push((c, lambda));
        }
        (!bumps.is_empty()).then_some(Raise {
            region: ch.region,
            bumps,
        })
    };
    charts.par_iter().zip(&balls).filter_map(raise).collect()
}
