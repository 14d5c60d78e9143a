//! Patches over the envelope's network (seed 004 §6; ALGORITHMS §8.2–8.3, §9, §11.6–11.7;
//! docs/algorithms/envelope.md).
//!
//! **G1.** Every border takes the virtual basis of its curve, `g(τ) = (1 − τ)g₀ + τg₁`, on
//! both sides; each side's cross derivative is `X(s) = k(s)g(s) + a(s)·unit(C′(s))`, k linear
//! (eased into a corner whose leg is far the shorter, `Side::k_share`) and `a = h|C′|` at the
//! corners, fitted there to the neighbouring sides' legs (`k g + h C′`,
//! the paper's), a monotone between them (`coons.rs`, `Side::along`). Both sides' X lie in
//! span(g, C′): one tangent plane along the whole border, whatever the numbering. A side that
//! is part of a curve takes the restriction of the curve's g (linear in τ is linear in s).
//!
//! **Four-sided regions** are one Coons patch with variable twist (§9). **Other regions** are
//! split into n quads around an inserted point P_i (§11.7):
//! 1. `P_d(k)` = boundary k at τ = ½, `b_k = X_k(½)/3`;
//! 2. `P_i` = mean of `P_d(k) + (3/2)b_k`;
//! 3. moved along G → P_i to the distance `max(d_v, d_face)` from the primitive's centre G,
//!    d_v = the mean of where virtual edges from the region's corners (§6.3, each corner's t)
//!    across the ray cross it, d_face = distance to the face's plane along the ray, so P_i
//!    never lies inside the primitive. At t = 1 d_v is the sphere, the paper's ρ̄ = t·r; for
//!    t ≠ 1 it lies as far out as the region's own curves bulge, where ρ̄ dented wide faces
//!    (envelope.md, "The inserted point");
//! 4. tangent plane at P_i normal to `P_i − G`, or the face normal when the clamp acted;
//! 5. insertion curve k, with `λ_k = ((P_i − P_d)·n)/(b_k·n)`, `λ̂ = max(λ_k, ¼)` and Π the
//!    projection onto that plane: `P_i, P_i + ⅔Π(P_d + λ̂b_k − P_i), P_d + ⅔λ̂b_k, P_d` — the
//!    paper's elevated quadratic whenever λ_k ≥ ¼, and always leaving P_d into the region;
//!    A leg at P_d under a ninth of the insertion chord (and under half the region's mean leg
//!    at P_d) is lengthened to that along itself (envelope.md, "Short legs at P_d");
//! 6. sub-quad k = insertion k, the second half of boundary k, the first half of boundary
//!    k + 1, insertion k + 1 backwards. The insertion curve's basis is rule (a) at P_d (the
//!    boundary runs on through P_d) and rule (b) at P_i.
//!
//! A three-sided region is split at the feet of its incentre on its sides (where a side is
//! square to the line from the incentre, not the nearest point: for t > 1 the sides bulge
//! and the nearest points are the corners) instead of the middles, with
//! `b_k` square to the side, and as its smallest corner narrows from 50° to 20° its insertion
//! curves turn from the paper's into cubics a third long at both ends, straight at the foot
//! and square to the side (envelope.md, "Three-sided regions"); a regular triangle is the
//! paper's.
//!
//! A region of five or more sides with runs of short sides (a sliver between two long sides,
//! a triangle with clipped corners) is also tried with each run closed by a curve across into
//! a region of its own — a sliver's rest is then a strip, one quad between its long sides —
//! and split so where that folds fewer cells than the split round P_i and stays G1
//! (envelope.md, "Runs of short sides"); a three-sided region likewise as one quad whose
//! fourth side is a corner under 60° collapsed to a point, each such corner tried
//! (envelope.md, "Needles", "Narrow corners as tips"); and a region of
//! five or more sides whose split folds also with each diagonal that cuts off a fat triangle of
//! two consecutive sides (envelope.md, "Diagonals"): the one that folds fewest is taken.
//!
//! A patch that still folds, or passes through itself, has its sides'
//! cross derivatives scaled by `σ(s) = 1 − 4β·s(1 − s)` (1 at the corners, positive), β per
//! side from a short list, the one that folds and crosses least: a positive multiple of X keeps
//! the border's normal `C′ × X`, so G1 holds whatever β is (envelope.md, "Folded patches: cross
//! derivatives rescaled"); one whose grid bends sharply between its samples, or that has a
//! side under a hundredth of its longest or a corner under 20°, is checked at 16 × 16 too, and
//! one bending more sharply still against its neighbours in the region, whose grids it may
//! pass into between the samples ([`kept_apart`]; envelope.md, "Patches through themselves",
//! *Finer still, and into a neighbour*). Where a build still folds after that and after its
//! short legs are given back (`legs.rs`), each region of other than four sides that folds is
//! patched every way it can be, each rescaled, and the way folding fewest kept ([`build`];
//! envelope.md, "Every way, rescaled").

use super::coons::{Coons, Side};
use super::edges::curved_edge;
use super::folds::{
    FOLD_CELLS, Fold, grid_crossings, grid_folds, grids_crossing, largest_turn, least_sine,
};
use super::network::{CurveKind, Network, PatchSide, Region, RegionKind};
use super::primitive::Primitive;
use super::reparam::Reparam;
use crate::freeform::bezier::RationalBezier;
use glam::DVec3;

/// λ₀ of §11.7 step 5: the least leg an insertion curve leaves P_d with, in units of b_k.
const LAMBDA_MIN: f64 = 0.25;

/// The least share of the way from P_i to P_d (projected) that an insertion curve's middle
/// control point P_m keeps: larger λ would put P_m past P_i, and the curve would leave P_i
/// away from its P_d (a sub-quad with a negative angle at P_i: a fold).
const LEAVE: f64 = 0.3;

/// The least leg (control point's offset) an insertion curve leaves P_d with, as a share of
/// its chord |P_i − P_d| ([`split`]; envelope.md, "Short legs at P_d") — but no more than
/// [`LEG_SHARE`] of the region's mean leg at its P_d, so that a region whose legs are all
/// short (every face of a primitive at small t, where the edges' cross derivatives shrink
/// with t) keeps them.
const LEG_FLOOR: f64 = 1.0 / 9.0;

/// See [`LEG_FLOOR`].
const LEG_SHARE: f64 = 0.5;

/// The split point of a three-sided region's side (the foot of its incentre) stays this far
/// from the side's ends (a share of its parameter).
const SPLIT_MIN: f64 = 0.02;

/// A three-sided region whose smallest corner is below this angle (radians, 20°) takes the
/// square insertion curves; above [`PAPER_ABOVE`] (50°) the paper's; in between a blend, so
/// the surface moves continuously as a corner narrows.
const SQUARE_BELOW: f64 = 20.0 * std::f64::consts::PI / 180.0;

/// See [`SQUARE_BELOW`].
const PAPER_ABOVE: f64 = 50.0 * std::f64::consts::PI / 180.0;

/// A patch side whose chord is below this share of the patch's longest side starts to take
/// the short-side cross derivative ([`Side::short`]), wholly below [`SHORT_FULL`]: no side of a
/// single primitive's patches is that short, so they keep the paper's.
const SHORT_FROM: f64 = 0.45;

/// See [`SHORT_FROM`].
const SHORT_FULL: f64 = 0.2;

/// Cells along each side of a patch that [`region_patches`] samples to judge whether a split
/// folds where a corner of the region has t below [`FINE_BELOW`]: finer than the report's
/// [`super::folds::FOLD_CELLS`], so that a fold in the corner cell at a primitive's vertex, a
/// twelfth of the patch wide at t = 0.1, is not missed between samples (the seven-primitive
/// scene's hexagonal cap: 8 × 8 saw none, 16 × 16 four cells, and the tessellation had a face
/// turned inwards there; envelope.md, "Hooked pieces at small t"). The edges' end zones, where
/// such folds sit, are about t·r long, so at larger t the report's cells do.
const FINE_CELLS: usize = 12;

/// See [`FINE_CELLS`].
const FINE_BELOW: f64 = 0.3;

/// The cells a side that [`region_patches`] samples for `region`: [`FINE_CELLS`] where one of
/// its corners on a primitive has t below [`FINE_BELOW`], else the report's.
fn choice_cells(net: &Network, region: &Region, prims: &[Primitive]) -> usize {
    let RegionKind::Primitive { primitive, .. } = region.kind else {
        return super::folds::FOLD_CELLS;
    };
    let g = prims[primitive].centre;
    let small = region.sides.iter().any(|s| {
        net.vertex_at(s.curve, s.t0)
            .is_some_and(|v| net.vertices[v].t_about(g) < FINE_BELOW)
    });
    if small {
        FINE_CELLS
    } else {
        super::folds::FOLD_CELLS
    }
}

/// A side under this share of its region's longest is short ([`short_runs`]).
const SHORT_RUN: f64 = 0.45;

/// The largest normal jump (degrees) across the curves that closing runs or collapsing a
/// triangle's tip adds, for the result to be taken: G1 to rounding (elsewhere the jumps are
/// about 10⁻¹⁰°).
const G1_KEPT: f64 = 1e-6;

/// A side under this share of another is as good as none beside it: a triangle with such a
/// side is a needle, and a diagonal along such a side is not tried ([`fat`]).
const NEEDLE: f64 = 0.2;

/// The widest sector (radians) the P_d and the insertion curves' tangents may leave between
/// neighbours around P_i: a sub-quad's corner there must stay well below 180°.
const STAR: f64 = 150.0 * std::f64::consts::PI / 180.0;

/// The narrowest sector (radians) the insertion curves' tangents may leave between neighbours
/// around P_i: two leaving nearly along one direction give the sub-quad between them a cusp
/// there, whose Coons twist turns it over (envelope.md, "Legs at P_i apart").
const CUSP: f64 = 5.0 * std::f64::consts::PI / 180.0;

/// The widest corner (radians, 60°) of a three-sided region that [`region_patches`] tries as
/// the collapsed tip of one quad: every triangle but an equilateral one has one narrower, and
/// a fan over a wider corner gave faces turned inwards where the split round P_i had none
/// (envelope.md, "Narrow corners as tips").
const NARROW_TIP: f64 = 60.0 * std::f64::consts::PI / 180.0;

/// The widest corner (radians, 135°) between the two sides of a triangle that a diagonal cuts
/// off ([`fat`]).
const FLAT_APEX: f64 = 135.0 * std::f64::consts::PI / 180.0;

/// One four-sided patch: its sides in the network and its Coons patch.
#[derive(Debug, Clone, PartialEq)]
pub struct EnvelopePatch {
    pub sides: [PatchSide; 4],
    pub coons: Coons,
    /// The region it lies in.
    pub region: usize,
}

impl EnvelopePatch {
    /// The network curve's parameter at side `k`'s parameter s (the side's own run along it,
    /// [`Side::phi`], then its piece of the curve).
    pub fn tau(&self, k: usize, s: f64) -> f64 {
        self.sides[k].tau(self.coons.sides[k].phi(s).0)
    }

    /// The side parameter at which side `k` reaches the network curve's parameter `tau`, if
    /// its piece holds it.
    pub fn side_parameter(&self, k: usize, tau: f64) -> Option<f64> {
        let s = self.sides[k];
        let (lo, hi) = (s.t0.min(s.t1), s.t0.max(s.t1));
        if tau < lo - 1e-12 || tau > hi + 1e-12 {
            return None;
        }
        let share = (tau - s.t0) / (s.t1 - s.t0);
        Some(match &self.coons.sides[k].reparam {
            Some(r) => r.inverse(share),
            None => share,
        })
    }
}

/// The part of `c` from t0 to t1 (backwards when t0 > t1), parametrised on [0, 1].
pub fn piece(c: &RationalBezier, t0: f64, t1: f64) -> RationalBezier {
    let (lo, hi) = (t0.min(t1), t0.max(t1));
    let right = if lo > 0.0 { c.split(lo).1 } else { c.clone() };
    let mut p = if hi < 1.0 {
        right.split((hi - lo) / (1.0 - lo)).0
    } else {
        right
    };
    if t0 > t1 {
        p.points.reverse();
        p.weights.reverse();
    }
    p
}

/// The curves of `sides` as pieces, and each side's fitted cross derivative.
fn fitted_sides(net: &Network, sides: &[PatchSide]) -> Vec<Side> {
    let curves: Vec<RationalBezier> = sides
        .iter()
        .map(|s| piece(&net.curves[s.curve].bezier, s.t0, s.t1))
        .collect();
    let n = sides.len();
    let chords: Vec<f64> = curves
        .iter()
        .map(|c| c.eval(0.0).distance(c.eval(1.0)))
        .collect();
    let longest = chords.iter().cloned().fold(0.0, f64::max);
    (0..n)
        .map(|k| {
            let prev = &curves[(k + n - 1) % n];
            let next = &curves[(k + 1) % n];
            let a0 = -prev.derivatives(1.0).d1;
            let a1 = next.derivatives(0.0).d1;
            let c = &net.curves[sides[k].curve];
            if c.is_point() {
                return Side::collapsed(curves[k].eval(0.0), a0, a1);
            }
            let g = (c.basis_at(sides[k].t0), c.basis_at(sides[k].t1));
            // A side much shorter than the patch's longest takes the short-side cross
            // derivative (envelope.md, "Short sides").
            let ratio = chords[k] / longest.max(f64::MIN_POSITIVE);
            Side::fitted(curves[k].clone(), g, a0, a1)
                .short((SHORT_FROM - ratio) / (SHORT_FROM - SHORT_FULL))
        })
        .collect()
}

fn patch(net: &Network, sides: [PatchSide; 4], region: usize) -> EnvelopePatch {
    let fitted = fitted_sides(net, &sides);
    EnvelopePatch {
        sides,
        coons: Coons {
            sides: fitted.try_into().expect("four sides"),
        },
        region,
    }
}

/// Where a virtual edge (§6.3, curvature parameter `t` at both ends) from corner `c` to its
/// image under the half-turn about the ray G + λu crosses the ray: its distance from G. On
/// the sphere for t = 1, the corner's projection on the ray as t → 0.
fn virtual_crossing(g: DVec3, c: DVec3, u: DVec3, t: f64) -> f64 {
    let v = c - g;
    let axial = v.dot(u) * u;
    let image = g + 2.0 * axial - v;
    match curved_edge(g, c, image, t, t) {
        Some(e) => e.eval(0.5).distance(g),
        None => v.length(),
    }
}

/// The parameter in [SPLIT_MIN, 1 − SPLIT_MIN] of the foot of `p` on `c`: where the curve is
/// square to the line from p, `(c(u) − p)·c′(u) = 0`, the root nearest the point over the
/// foot of p on the chord. On a curve that bends towards p that is the nearest point; on one
/// that bulges away from p more than its ends lie from it (a triangle's edges for t above 1:
/// the nearest points are then the corners) it is the curve's farthest point from p near the
/// chord's foot, so the split stays in the side's middle. No root: the nearest point.
fn foot_parameter(c: &RationalBezier, p: DVec3) -> f64 {
    let (a, z) = (c.eval(0.0), c.eval(1.0));
    let chord = z - a;
    let len2 = chord.length_squared();
    let over = |u: f64| (c.eval(u) - a).dot(chord) / len2;
    let target = ((p - a).dot(chord) / len2).clamp(SPLIT_MIN, 1.0 - SPLIT_MIN);
    let bisect = |f: &dyn Fn(f64) -> f64, mut lo: f64, mut hi: f64| {
        let flo = f(lo) < 0.0;
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if (f(mid) < 0.0) == flo {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    let u_over = if (over(SPLIT_MIN) - target) * (over(1.0 - SPLIT_MIN) - target) < 0.0 {
        bisect(&|u| over(u) - target, SPLIT_MIN, 1.0 - SPLIT_MIN)
    } else {
        target
    };
    let square = |u: f64| {
        let d = c.derivatives(u);
        (d.point - p).dot(d.d1)
    };
    let steps = 24;
    let grid = |i: usize| SPLIT_MIN + (1.0 - 2.0 * SPLIT_MIN) * i as f64 / steps as f64;
    let at: Vec<f64> = (0..=steps).map(|i| square(grid(i))).collect();
    let root = (0..steps)
        .filter(|&i| at[i] * at[i + 1] <= 0.0)
        .map(|i| bisect(&square, grid(i), grid(i + 1)))
        .min_by(|x, y| (x - u_over).abs().total_cmp(&(y - u_over).abs()));
    let u = root.unwrap_or_else(|| nearest_parameter(c, p));
    if (u - 0.5).abs() < 1e-6 { 0.5 } else { u }
}

/// The parameter in [SPLIT_MIN, 1 − SPLIT_MIN] of the point of `c` nearest `p`: the best
/// of 13 samples, then golden-section steps around it. The search finds a minimum to about
/// 1e-8 (the distance is flat there), so a result within 1e-6 of the middle is the middle:
/// a regular triangle and its neighbour across a side split it at one point.
fn nearest_parameter(c: &RationalBezier, p: DVec3) -> f64 {
    let d = |u: f64| c.eval(u).distance_squared(p);
    let span = 1.0 - 2.0 * SPLIT_MIN;
    let step = span / 12.0;
    let u0 = (0..=12)
        .map(|i| SPLIT_MIN + step * i as f64)
        .min_by(|&a, &b| d(a).total_cmp(&d(b)))
        .expect("samples");
    let (mut lo, mut hi) = ((u0 - step).max(SPLIT_MIN), (u0 + step).min(1.0 - SPLIT_MIN));
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..30 {
        let (a, z) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if d(a) <= d(z) {
            hi = z;
        } else {
            lo = a;
        }
    }
    let u = 0.5 * (lo + hi);
    if (u - 0.5).abs() < 1e-6 { 0.5 } else { u }
}

/// Where the inserted point of region `r` goes for the estimate `mean` (§11.7 steps 3–4), and
/// its tangent plane's normal.
fn place(
    net: &Network,
    region: &super::network::Region,
    prims: &[Primitive],
    pd: &[DVec3],
    b: &[DVec3],
    tangent_d: &[DVec3],
    mean: DVec3,
) -> (DVec3, DVec3) {
    let sides = &region.sides;
    let n = sides.len();
    match region.kind {
        RegionKind::Primitive { primitive, face } => {
            let p = &prims[primitive];
            let g = p.centre;
            let u = (mean - g).normalize();
            let corners: Vec<usize> = sides
                .iter()
                .map(|s| {
                    net.vertex_at(s.curve, s.t0)
                        .expect("a region corner is a vertex")
                })
                .collect();
            let nf = p.normals[face];
            let d_face = nf.dot(p.vertices[p.faces[face][0]] - g) / nf.dot(u);
            // Where virtual edges from the corners across the ray cross it (envelope.md, "The
            // inserted point"): the sphere at t = 1, as the paper's ρ̄; for t ≠ 1 as far out as
            // the region's own curves bulge.
            let d = corners
                .iter()
                .map(|&v| {
                    let c = net.vertices[v].position;
                    virtual_crossing(g, c, u, net.vertices[v].t_about(g))
                })
                .sum::<f64>()
                / corners.len() as f64;
            if d < d_face {
                // Clamped: on the face plane, at the centroid of the P_d projected onto it
                // (the face centre for a regular face; inside a cut face's part, envelope.md).
                let f0 = p.vertices[p.faces[face][0]];
                let c = pd
                    .iter()
                    .map(|q| *q - (*q - f0).dot(nf) * nf)
                    .sum::<DVec3>()
                    / n as f64;
                (c, nf)
            } else {
                (g + d * u, u)
            }
        }
        RegionKind::Fusion { .. } | RegionKind::Lid { .. } => {
            let m = (0..n).map(|k| tangent_d[k].cross(b[k])).sum::<DVec3>();
            (mean, m.normalize())
        }
    }
}

/// The angles (radians) between consecutive directions (projected into the plane normal to
/// `n`), counter-clockwise about n in their order; none when they do not go round once in that
/// order.
fn sectors(n: DVec3, dirs: impl Iterator<Item = DVec3>) -> Option<Vec<f64>> {
    let d: Vec<DVec3> = dirs.map(|v| v - v.dot(n) * n).collect();
    let m = d.len();
    let s: Vec<f64> = (0..m)
        .map(|k| {
            let (a, c) = (d[k], d[(k + 1) % m]);
            n.dot(a.cross(c))
                .atan2(a.dot(c))
                .rem_euclid(std::f64::consts::TAU)
        })
        .collect();
    ((s.iter().sum::<f64>() - std::f64::consts::TAU).abs() <= 1e-6).then_some(s)
}

/// The widest of the [`sectors`]; 2π when they do not go round once.
fn widest_sector(n: DVec3, dirs: impl Iterator<Item = DVec3>) -> f64 {
    sectors(n, dirs).map_or(std::f64::consts::TAU, |s| s.into_iter().fold(0.0, f64::max))
}

/// The narrowest of the [`sectors`]; 0 when they do not go round once.
fn narrowest_sector(n: DVec3, dirs: impl Iterator<Item = DVec3>) -> f64 {
    sectors(n, dirs).map_or(0.0, |s| s.into_iter().fold(f64::INFINITY, f64::min))
}

/// Splits region `r` (not four-sided) into quads around an inserted point (§11.7), adding the
/// new vertices and insertion curves to `net`.
fn split(net: &mut Network, region: Region, r: usize, prims: &[Primitive]) -> Vec<EnvelopePatch> {
    let sides = region.sides.clone();
    let fitted = fitted_sides(net, &sides);
    let n = sides.len();
    // Where each side is split, its point P_d, the cross derivative there and the tangent.
    let at = |split: &[f64]| {
        let mut pd = Vec::with_capacity(n);
        let mut b = Vec::with_capacity(n);
        let mut tangent_d = Vec::with_capacity(n);
        for (s, &u) in fitted.iter().zip(split) {
            let d = s.curve.derivatives(u);
            pd.push(d.point);
            b.push(s.cross(u).0 / 3.0);
            tangent_d.push(d.d1);
        }
        (pd, b, tangent_d)
    };
    // The inserted point for split points `pd` (cross derivatives `b`, tangents `tangent_d`).
    // The star condition at P_i (envelope.md): the P_d must go round P_i in the region's order
    // with every sector below STAR; where the paper's estimate fails it, the estimate moves
    // towards the centroid of the P_d, the first of a few steps that passes (or the best).
    let inserted = |pd: &[DVec3], b: &[DVec3], tangent_d: &[DVec3]| {
        let mean = (0..n).map(|k| pd[k] + 1.5 * b[k]).sum::<DVec3>() / n as f64;
        let centroid = pd.iter().sum::<DVec3>() / n as f64;
        let mut best: Option<(f64, DVec3, DVec3)> = None;
        for mu in [0.0, 0.25, 0.5, 0.75, 1.0] {
            let (p, nrm) = place(
                net,
                &region,
                prims,
                pd,
                b,
                tangent_d,
                mean.lerp(centroid, mu),
            );
            let sector = widest_sector(nrm, pd.iter().map(|q| *q - p));
            if best.is_none_or(|b| sector < b.0) {
                best = Some((sector, p, nrm));
            }
            if sector <= STAR {
                break;
            }
        }
        best.expect("tried")
    };
    // A three-sided region is split at the feet of its incentre, with cross derivatives
    // square to its sides there (envelope.md, "Three-sided regions"): a thin triangle's
    // quads then have corners near 90° at the feet. A regular one is split at its middles,
    // where the cross derivatives are square already, as the paper does; other regions at
    // their sides' middles.
    // `thin`: how far the insertion curves go from the paper's legs to the square ones.
    let mut split_at = vec![0.5; n];
    let mut thin = 0.0;
    if n == 3 {
        let least = (0..3)
            .map(|k| {
                let out = fitted[k].curve.derivatives(0.0).d1;
                let back = -fitted[(k + 2) % 3].curve.derivatives(1.0).d1;
                out.angle_between(back)
            })
            .fold(f64::INFINITY, f64::min);
        thin = ((PAPER_ABOVE - least) / (PAPER_ABOVE - SQUARE_BELOW)).clamp(0.0, 1.0);
        let corner: Vec<DVec3> = fitted.iter().map(|s| s.curve.eval(0.0)).collect();
        // Side k joins corners k and k + 1; the side opposite corner k is side k + 1.
        let chord = |k: usize| corner[k].distance(corner[(k + 1) % 3]);
        let perimeter = chord(0) + chord(1) + chord(2);
        let incentre = (0..3)
            .map(|k| corner[k] * chord((k + 1) % 3))
            .sum::<DVec3>()
            / perimeter;
        for (k, s) in fitted.iter().enumerate() {
            split_at[k] = foot_parameter(&s.curve, incentre);
        }
    }
    let (pd, mut b, tangent_d) = at(&split_at);
    if n == 3 {
        for k in 0..n {
            let t = tangent_d[k].normalize();
            let across = b[k] - b[k].dot(t) * t;
            if across.length() > 1e-9 * b[k].length() {
                b[k] = across;
            }
        }
    }
    let best = inserted(&pd, &b, &tangent_d);
    let (_, pi_, normal) = best;
    let rho_i = match region.kind {
        RegionKind::Primitive { primitive, .. } => pi_.distance(prims[primitive].centre),
        RegionKind::Fusion { .. } | RegionKind::Lid { .. } => 0.0,
    };
    let vi = net.add_vertex(pi_, normal, rho_i);
    let proj = |x: DVec3| x - x.dot(normal) * normal;
    // Per insertion curve: the legs it leaves P_i and P_d with.
    let mut legs: Vec<(DVec3, DVec3)> = Vec::with_capacity(n);
    for k in 0..n {
        let bn = b[k].dot(normal);
        let lambda = if bn.abs() < 1e-12 * b[k].length() {
            LAMBDA_MIN
        } else {
            ((pi_ - pd[k]).dot(normal) / bn).max(LAMBDA_MIN)
        };
        // The curve must leave P_i towards its P_d: P_m's projection at least LEAVE of the
        // way from P_i to P_d's (envelope.md, "The star condition at P_i").
        let w = proj(pd[k] - pi_);
        let beta = proj(b[k]).dot(w);
        let lambda = if beta < 0.0 {
            lambda.min(((1.0 - LEAVE) * w.length_squared() / -beta).max(LAMBDA_MIN))
        } else {
            lambda
        };
        let paper = (
            2.0 / 3.0 * proj(pd[k] + lambda * b[k] - pi_),
            2.0 / 3.0 * lambda * b[k],
        );
        // Square: a third of the way, straight at the foot (projected) and square to the
        // side; the paper's legs overshoot across a thin triangle.
        let third = pd[k].distance(pi_) / 3.0;
        let square = (w / 3.0, third * b[k].normalize_or_zero());
        legs.push((paper.0.lerp(square.0, thin), paper.1.lerp(square.1, thin)));
    }
    // A leg at P_d far shorter than the region's others is lengthened along itself
    // (envelope.md, "Short legs at P_d"): the sub-quads' cross derivatives along the boundary
    // halves at P_d are fitted to it, and a tiny one pinches them against the border.
    let mean_d = legs.iter().map(|l| l.1.length()).sum::<f64>() / n as f64;
    for (k, leg) in legs.iter_mut().enumerate() {
        let least = (LEG_FLOOR * pd[k].distance(pi_)).min(LEG_SHARE * mean_d);
        let len = leg.1.length();
        if len > 0.0 && len < least {
            leg.1 *= least / len;
        }
    }
    // Legs that do not go round P_i with every sector below STAR, or leave two of them nearly
    // along one direction (a cusp in the sub-quad between them: envelope.md, "Legs at P_i
    // apart"), point straight at their P_d (projected) instead, keeping their length.
    let leaving = || legs.iter().map(|l| l.0);
    if widest_sector(normal, leaving()) > STAR || narrowest_sector(normal, leaving()) < CUSP {
        for (k, leg) in legs.iter_mut().enumerate() {
            leg.0 = proj(pd[k] - pi_).normalize_or_zero() * leg.0.length();
        }
    }
    let mut ins = Vec::with_capacity(n);
    for k in 0..n {
        let nd = tangent_d[k].cross(b[k]).normalize();
        // The region across may have split this curve already: share its P_d.
        let tau = sides[k].tau(split_at[k]);
        let vd = match net.vertex_at(sides[k].curve, tau) {
            Some(v) => v,
            None => {
                let v = net.add_vertex(pd[k], nd, 0.0);
                net.pin(sides[k].curve, tau, v);
                v
            }
        };
        let (leg_i, leg_d) = legs[k];
        let bez = RationalBezier::polynomial(vec![pi_, pi_ + leg_i, pd[k] + leg_d, pd[k]])
            .expect("finite points");
        let end = bez.derivatives(1.0).d1;
        let c = net.add_curve(bez, vi, vd, CurveKind::Insertion);
        // Rule (a) at P_d: the boundary runs on through it.
        let along = tangent_d[k].normalize();
        let g1 = if along.dot(nd.cross(end)) >= 0.0 {
            along
        } else {
            -along
        };
        net.curves[c].basis.1 = g1;
        ins.push(c);
    }
    (0..n)
        .map(|k| {
            let j = (k + 1) % n;
            let quad = [
                PatchSide {
                    curve: ins[k],
                    t0: 0.0,
                    t1: 1.0,
                },
                PatchSide {
                    t0: sides[k].tau(split_at[k]),
                    ..sides[k]
                },
                PatchSide {
                    t1: sides[j].tau(split_at[j]),
                    ..sides[j]
                },
                PatchSide {
                    curve: ins[j],
                    t0: 1.0,
                    t1: 0.0,
                },
            ];
            patch(net, quad, r)
        })
        .collect()
}

/// A side's chord.
fn chord(net: &Network, s: &PatchSide) -> f64 {
    let b = &net.curves[s.curve].bezier;
    b.eval(s.t0).distance(b.eval(s.t1))
}

/// The shortest and the longest chord of `sides`.
fn chord_range(net: &Network, sides: &[PatchSide]) -> (f64, f64) {
    sides
        .iter()
        .map(|s| chord(net, s))
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), c| {
            (lo.min(c), hi.max(c))
        })
}

/// Keys compared entry by entry ([`f64::total_cmp`]), the first that differs deciding: the
/// orders that keep a choice independent of the listing ([`region_patches`], [`unfolded`]).
fn by_keys(a: &[f64], b: &[f64]) -> std::cmp::Ordering {
    a.iter()
        .zip(b)
        .map(|(x, y)| x.total_cmp(y))
        .find(|o| o.is_ne())
        .unwrap_or(std::cmp::Ordering::Equal)
}

/// The runs of short sides of a region of five or more sides: (first side, count) of each
/// maximal run of consecutive sides whose chords are under [`SHORT_RUN`] of the longest, for
/// the runs of two or more; `None` when there is none, every side is short, or closing the
/// runs would leave fewer than three sides.
fn short_runs(net: &Network, region: &Region) -> Option<Vec<(usize, usize)>> {
    let n = region.sides.len();
    if n < 5 {
        return None;
    }
    let chords: Vec<f64> = region.sides.iter().map(|s| chord(net, s)).collect();
    let longest = chords.iter().cloned().fold(0.0, f64::max);
    let short: Vec<bool> = chords.iter().map(|&c| c < SHORT_RUN * longest).collect();
    // Start after a long side, so that no run wraps round the start.
    let first_long = (0..n).find(|&k| !short[k])?;
    let mut runs = Vec::new();
    let mut k = 1;
    while k <= n {
        let at = (first_long + k) % n;
        if short[at] {
            let len = (k..=n).take_while(|&m| short[(first_long + m) % n]).count();
            if len >= 2 {
                runs.push((at, len));
            }
            k += len;
        } else {
            k += 1;
        }
    }
    // The rest must stay a region of three sides or more (then every part has fewer sides
    // than the region, and closing runs in the parts ends).
    let core = n - runs.iter().map(|&(_, len)| len - 1).sum::<usize>();
    (!runs.is_empty() && core >= 3).then_some(runs)
}

/// A region with its runs of short sides ([`short_runs`]) each closed by a curve across into a
/// region of its own, and the rest (the core) last (envelope.md, "Runs of short sides"): a
/// sliver's core is the strip between its long sides, a clipped triangle's one of fewer sides.
/// The curve across is a cubic with legs a third of its chord projected into its ends' tangent
/// planes, with the rule (b) basis [`Network::add_curve`] gives it.
fn close_runs(net: &mut Network, region: &Region, runs: &[(usize, usize)]) -> Vec<Region> {
    let sides = &region.sides;
    let n = sides.len();
    let mut parts = Vec::new();
    let mut core = Vec::new();
    let mut k = 0;
    // Walk from the first run's start so that each run is contiguous.
    let start = runs[0].0;
    while k < n {
        let at = (start + k) % n;
        let Some(&(_, len)) = runs.iter().find(|r| r.0 == at) else {
            core.push(sides[at]);
            k += 1;
            continue;
        };
        let chain: Vec<PatchSide> = (0..len).map(|m| sides[(at + m) % n]).collect();
        let last = chain[len - 1];
        let corner = |s: &PatchSide, tau: f64| {
            net.vertex_at(s.curve, tau)
                .expect("a region corner is a vertex")
        };
        let (va, vb) = (corner(&chain[0], chain[0].t0), corner(&last, last.t1));
        let (a, b) = (net.vertices[va], net.vertices[vb]);
        let d = b.position - a.position;
        let proj = |n: DVec3| d - d.dot(n) * n;
        let bez = RationalBezier::polynomial(vec![
            a.position,
            a.position + proj(a.normal) / 3.0,
            b.position - proj(b.normal) / 3.0,
            b.position,
        ])
        .expect("finite points");
        let c = net.add_curve(bez, va, vb, CurveKind::Insertion);
        core.push(PatchSide::whole(c, true));
        let mut closed = chain;
        closed.push(PatchSide::whole(c, false));
        parts.push(Region {
            sides: closed,
            kind: region.kind,
        });
        k += len;
    }
    parts.push(Region {
        sides: core,
        kind: region.kind,
    });
    parts
}

/// A three-sided region as one four-sided region: the corner opposite side `k`, the tip,
/// becomes a fourth side collapsed to a point (a network curve from the tip vertex to itself),
/// and the patch runs from side k to the tip between the two other sides (envelope.md,
/// "Needles", "Narrow corners as tips").
fn collapsed(net: &mut Network, region: &Region, k: usize) -> Region {
    let [a, b, c] = [0, 1, 2].map(|i| region.sides[(k + i) % 3]);
    let tip = net
        .vertex_at(b.curve, b.t1)
        .expect("a region corner is a vertex");
    let p = net.vertices[tip].position;
    let point = RationalBezier::polynomial(vec![p; 4]).expect("a finite point");
    let curve = net.add_curve(point, tip, tip, CurveKind::Insertion);
    Region {
        sides: vec![a, b, PatchSide::whole(curve, true), c],
        kind: region.kind,
    }
}

/// The triangle that the diagonal from the start of side `k` of `region` to the end of side
/// k + 1 cuts off: that start, the corner between the two sides, that end.
fn cut_off(net: &Network, region: &Region, k: usize) -> [DVec3; 3] {
    let n = region.sides.len();
    let (a, b) = (region.sides[k], region.sides[(k + 1) % n]);
    [(a.curve, a.t0), (b.curve, b.t0), (b.curve, b.t1)].map(|(c, tau)| {
        let v = net.vertex_at(c, tau).expect("a region corner is a vertex");
        net.vertices[v].position
    })
}

/// Whether a triangle that a diagonal cuts off ([`cut_off`]) is worth trying
/// ([`region_patches`]): neither of its two sides under [`NEEDLE`] of the other (a needle, or a
/// side of no length, leaves the curve across lying along the other side) and the corner
/// between them at most [`FLAT_APEX`] (a flatter one leaves it along both).
fn fat([p, apex, q]: [DVec3; 3]) -> bool {
    let (u, v) = (p - apex, q - apex);
    let (lu, lv) = (u.length(), v.length());
    lu.min(lv) >= NEEDLE * lu.max(lv) && u.angle_between(v) <= FLAT_APEX
}

/// Another way to patch a region than the split round one inserted point, tried where that
/// split folds.
enum Partition {
    /// Runs of sides, (first side, count) each, closed off by a curve across ([`close_runs`]).
    Runs(Vec<(usize, usize)>),
    /// A triangle as one quad with the corner opposite this side collapsed ([`collapsed`]).
    Tip(usize),
}

/// The order among partitions that fold alike ([`region_patches`]): the runs first, then the
/// longest diagonal, then by the diagonal's ends' positions (coordinate by coordinate, the
/// lower end first); a triangle's tips by the side opposite, shortest first (a needle's tip),
/// then by the tip's position.
fn rank(net: &Network, region: &Region, partition: &Partition) -> [f64; 8] {
    let runs = match partition {
        Partition::Runs(runs) => runs,
        &Partition::Tip(k) => {
            let tip = cut_off(net, region, (k + 1) % 3)[1];
            let opposite = chord(net, &region.sides[k]);
            return [0.0, opposite, tip.x, tip.y, tip.z, 0.0, 0.0, 0.0];
        }
    };
    let &[(k, 2)] = runs.as_slice() else {
        return [0.0; 8];
    };
    let [p, _, q] = cut_off(net, region, k);
    let (p, q) = if p.to_array() <= q.to_array() {
        (p, q)
    } else {
        (q, p)
    };
    [1.0, -p.distance(q), p.x, p.y, p.z, q.x, q.y, q.z]
}

/// The patches of `region` (number `r`) cut into the parts of `partition`, each patched by
/// [`region_patches`].
fn partitioned(
    net: &mut Network,
    region: &Region,
    partition: &Partition,
    r: usize,
    prims: &[Primitive],
) -> Vec<EnvelopePatch> {
    let parts = match partition {
        Partition::Runs(runs) => close_runs(net, region, runs),
        Partition::Tip(k) => vec![collapsed(net, region, *k)],
    };
    parts
        .into_iter()
        .flat_map(|part| region_patches(net, part, r, prims))
        .collect()
}

/// The patches of a four-sided `region` (number `r`): one Coons patch — or, where one side's
/// chord is under [`QUAD_SHORT`] of the longest and that patch folds, the split round an
/// inserted point as for any other n, where that folds fewer cells and stays G1 across the
/// curves it adds (envelope.md, "Four-sided regions with a short side").
fn quad_patches(
    net: &mut Network,
    region: Region,
    r: usize,
    prims: &[Primitive],
) -> Vec<EnvelopePatch> {
    let quad: [PatchSide; 4] = region.sides.clone().try_into().expect("four");
    let one = vec![patch(net, quad, r)];
    // A triangle's collapsed tip ([`collapsed`]) is a side of no length by design: split there,
    // the insertion curve to its middle would end at the tip with no direction to take its
    // basis from (NaN; two scenes of four cubes placed apart at t = 0.1 wrote such points).
    if region.sides.iter().any(|s| {
        let ends = net.curves[s.curve].ends;
        ends[0] == ends[1]
    }) {
        return one;
    }
    let (shortest, longest) = chord_range(net, &region.sides);
    if shortest >= QUAD_SHORT * longest {
        return one;
    }
    let cells = choice_cells(net, &region, prims);
    let before = super::folds::folds_past_corners(net, &one, cells).len();
    if before == 0 {
        return one;
    }
    let (nv, nc) = (net.vertices.len(), net.curves.len());
    let other = split(net, region, r, prims);
    if super::folds::folds_past_corners(net, &other, cells).len() < before
        && largest_border_jump(net, &other, 8) < G1_KEPT
    {
        return other;
    }
    net.truncate(nv, nc);
    one
}

/// A four-sided region with a side under this share of its longest is tried split
/// ([`quad_patches`]).
const QUAD_SHORT: f64 = 0.05;

/// The partitions of a region of other than four sides tried where its split folds
/// ([`region_patches`]): its runs of short sides closed off, a triangle's narrow corners as
/// tips, and for five or more sides the diagonals that cut off a fat triangle.
fn partitions(net: &Network, region: &Region) -> Vec<Partition> {
    let n = region.sides.len();
    let mut tries = Vec::new();
    if let Some(runs) = short_runs(net, region) {
        tries.push(Partition::Runs(runs));
    }
    if n == 3 {
        // Each narrow corner as the tip of one quad (envelope.md, "Narrow corners as tips").
        tries.extend(
            (0..3)
                .filter(|&k| {
                    let [p, tip, q] = cut_off(net, region, (k + 1) % 3);
                    (p - tip).angle_between(q - tip) < NARROW_TIP
                })
                .map(Partition::Tip),
        );
    }
    if n >= 5 {
        tries.extend(
            (0..n)
                .filter(|&k| fat(cut_off(net, region, k)))
                .map(|k| Partition::Runs(vec![(k, 2)])),
        );
    }
    tries
}

/// One way to patch a region of other than four sides ([`Way::patches`]), tried again where
/// the way [`region_patches`] chose still folds once its patches are rescaled ([`build`]).
enum Way {
    /// As [`region_patches`] chooses.
    Chosen,
    /// Split round one inserted point.
    Split,
    /// Cut into parts ([`partitioned`]).
    Parts(Partition),
}

impl Way {
    /// Every way to patch `region`: as chosen first, then its split round an inserted point and
    /// the partitions of [`partitions`]. A four-sided region has only the way chosen: its one
    /// other, the split, is tried already where a side is short ([`quad_patches`]), and tried
    /// on every quad left folding it cost a heap of four at t = 0.02 1.2 s and cleared no fold
    /// at t = 0.05 or 0.02 (envelope.md, "Every way, rescaled").
    fn all(net: &Network, region: &Region) -> Vec<Way> {
        let mut ways = vec![Way::Chosen];
        if region.sides.len() != 4 {
            ways.push(Way::Split);
            // In [`rank`]'s order, never the listing's.
            let mut parts: Vec<([f64; 8], Partition)> = partitions(net, region)
                .into_iter()
                .map(|p| (rank(net, region, &p), p))
                .collect();
            parts.sort_by(|a, b| by_keys(&a.0, &b.0));
            ways.extend(parts.into_iter().map(|(_, p)| Way::Parts(p)));
        }
        ways
    }

    /// The patches of `region` (number `r`) made this way.
    fn patches(
        &self,
        net: &mut Network,
        region: &Region,
        r: usize,
        prims: &[Primitive],
    ) -> Vec<EnvelopePatch> {
        match self {
            Way::Chosen => region_patches(net, region.clone(), r, prims),
            Way::Split => split(net, region.clone(), r, prims),
            Way::Parts(p) => partitioned(net, region, p, r, prims),
        }
    }
}

/// The patches of `region` (number `r`): [`quad_patches`] if it is four-sided, else its split
/// round one inserted point — or, where that split folds, the partition that folds fewest of
/// its cells and stays G1 across the curves it adds (envelope.md, "Runs of short sides",
/// "Needles" and "Diagonals"), tried in [`rank`]'s order: runs of short sides closed off
/// ([`short_runs`], [`close_runs`]), a triangle as one quad with a corner collapsed
/// ([`collapsed`], each corner under [`NARROW_TIP`]), and for five or more sides each
/// diagonal that cuts off the triangle of two consecutive sides. Trial patches are undone by
/// truncating what they added to the network.
fn region_patches(
    net: &mut Network,
    region: Region,
    r: usize,
    prims: &[Primitive],
) -> Vec<EnvelopePatch> {
    if region.sides.len() == 4 {
        return quad_patches(net, region, r, prims);
    }
    let tries = partitions(net, &region);
    if tries.is_empty() {
        return split(net, region, r, prims);
    }
    let cells = choice_cells(net, &region, prims);
    let folded = |net: &Network, patches: &[EnvelopePatch]| {
        super::folds::folds_past_corners(net, patches, cells).len()
    };
    let (nv, nc) = (net.vertices.len(), net.curves.len());
    let plain = split(net, region.clone(), r, prims);
    let mut least = folded(net, &plain);
    if least == 0 {
        return plain;
    }
    net.truncate(nv, nc);
    // The one that folds fewest; on a tie the runs, a triangle's tip across its shortest side,
    // the longest diagonal, then by position ([`rank`]) — never the listing's order, so that
    // the surface does not depend on it. Tried in that order, so the first that folds nothing
    // ends the search.
    let mut order: Vec<(usize, [f64; 8])> = tries
        .iter()
        .enumerate()
        .map(|(i, p)| (i, rank(net, &region, p)))
        .collect();
    order.sort_by(|a, b| by_keys(&a.1, &b.1));
    let mut best = None;
    for (i, _) in order {
        let other = partitioned(net, &region, &tries[i], r, prims);
        let folds = folded(net, &other);
        // Taken where it folds less than the split and stays G1 across the curves it adds;
        // one that folds nothing is the pick, kept as built.
        if folds < least && largest_border_jump(net, &other, 8) < G1_KEPT {
            if folds == 0 {
                return other;
            }
            (least, best) = (folds, Some(i));
        }
        net.truncate(nv, nc);
    }
    match best {
        Some(i) => partitioned(net, &region, &tries[i], r, prims),
        None => split(net, region, r, prims),
    }
}

/// The patches of every region of `net` ([`region_patches`]), each that still folds or passes
/// through itself with its cross derivatives rescaled ([`unfolded`]), their folded cells as
/// the report samples them ([`FOLD_CELLS`] a side: what [`super::Envelope::folds`] returns),
/// and the regions whose patches still fold between those samples, with how many cells
/// (region, cells; envelope.md, "Short legs given back where a patch folds", *Between the
/// samples too*).
pub fn build(
    net: &mut Network,
    prims: &[Primitive],
    every_way: bool,
) -> (Vec<EnvelopePatch>, Vec<Fold>, Vec<(usize, usize)>) {
    let mut out = Vec::new();
    let mut folded = Vec::new();
    let mut between = Vec::new();
    for r in 0..net.regions.len() {
        let region = net.regions[r].clone();
        let cells = choice_cells(net, &region, prims);
        let unfold = |net: &mut Network, way: &Way| -> Vec<Unfolded> {
            let made = way.patches(net, &region, r, prims);
            made.into_iter()
                .map(|p| unfolded(net, p, cells, &[]))
                .collect()
        };
        let count = |made: &[Unfolded]| made.iter().map(|m| m.folds.len()).sum();
        let (nv, nc) = (net.vertices.len(), net.curves.len());
        let mut made = unfold(net, &Way::Chosen);
        let mut least: usize = count(&made);
        if least > 0 && every_way {
            // Still folding once rescaled: every other way to patch the region, each rescaled,
            // and the one that folds fewest (envelope.md, "Every way, rescaled"); on a tie the
            // way chosen, then the order of [`Way::all`] (the region's geometry).
            let ways = Way::all(net, &region);
            let mut best = 0;
            for (i, way) in ways.iter().enumerate().skip(1) {
                net.truncate(nv, nc);
                let other = unfold(net, way);
                let patches: Vec<EnvelopePatch> = other.iter().map(|m| m.patch.clone()).collect();
                let n = count(&other);
                if n < least && largest_border_jump(net, &patches, 8) < G1_KEPT {
                    (least, best) = (n, i);
                    if n == 0 {
                        // Built last: the network holds its curves.
                        made = other;
                        break;
                    }
                }
            }
            if least > 0 {
                net.truncate(nv, nc);
                made = unfold(net, &ways[best]);
            }
        }
        kept_apart(net, &mut made, cells);
        let left: usize = made.iter().map(|m| m.between).sum();
        if left > 0 {
            between.push((r, left));
        }
        for Unfolded {
            patch: p, folds, ..
        } in made
        {
            let patch = out.len();
            folded.extend(folds.into_iter().map(|f| Fold { patch, ..f }));
            out.push(p);
        }
    }
    (out, folded, between)
}

/// A patch whose 8 × 8 grid lines turn by more than this (radians, 20°) from one segment to the
/// next is checked finer ([`unfolded`]: for folded cells at 16 and 32 a side, and for passing
/// through itself at 16; envelope.md, "Patches through themselves").
const TURN_CHECKED_FINER: f64 = 20.0 * std::f64::consts::PI / 180.0;

/// A patch whose shortest side (not collapsed) is under this share of its longest is checked
/// for folded cells at 16 and 32 a side too ([`unfolded`]; envelope.md, "Patches through
/// themselves", *Finer still, and into a neighbour*): beside a side that short the patch can
/// turn over within a cell of the 8 × 8 grid (heap 600327 at t = 3, a side 1.2 % of the
/// longest: 3 cells at 32 a side, none at 16).
const SHORT_CHECKED_FINER: f64 = 0.02;

/// A patch whose 8 × 8 grid lines turn by more than this (radians, 45°) is checked against its
/// neighbours at 16 × 16 ([`kept_apart`]).
const TURN_CHECKED_AGAINST: f64 = 45.0 * std::f64::consts::PI / 180.0;

/// Of one region's patches, each whose 8 × 8 grid lines turn by more than
/// [`TURN_CHECKED_AGAINST`] and whose 16 × 16 grid passes through a neighbour's (one across a
/// curve they share; [`grids_crossing`]) is rescaled again ([`unfolded`]) with those crossings
/// counted, in the order the region's patches are made (its geometry): sub-quads of a split
/// face beside a short or heavily weighted side bulged into each other between the samples
/// (envelope.md, "Patches through themselves", *Finer still, and into a neighbour*).
fn kept_apart(net: &Network, made: &mut [Unfolded], cells: usize) {
    if made.len() < 2 || made.iter().all(|m| m.turn <= TURN_CHECKED_AGAINST) {
        return;
    }
    let k = 2 * FOLD_CELLS;
    // Each patch's 16 × 16 grid, evaluated once (again where the patch changes).
    let mut fine: Vec<Option<Vec<DVec3>>> = vec![None; made.len()];
    for i in 0..made.len() {
        if made[i].turn <= TURN_CHECKED_AGAINST {
            continue;
        }
        // Its neighbours: the patches across a curve it shares.
        let beside: Vec<usize> = (0..made.len())
            .filter(|&j| {
                j != i
                    && made[i]
                        .patch
                        .sides
                        .iter()
                        .any(|a| made[j].patch.sides.iter().any(|b| a.curve == b.curve))
            })
            .collect();
        for &j in beside.iter().chain([&i]) {
            fine[j].get_or_insert_with(|| made[j].patch.coons.grid(k));
        }
        let grid = |j: usize| fine[j].as_ref().expect("evaluated above");
        if beside
            .iter()
            .all(|&j| grids_crossing(grid(i), grid(j), k) == 0)
        {
            continue;
        }
        let others: Vec<Vec<DVec3>> = beside.iter().map(|&j| grid(j).clone()).collect();
        made[i] = unfolded(net, made[i].patch.clone(), cells, &others);
        fine[i] = None;
    }
}

/// The shortest side's chord over the longest's, of the sides not collapsed.
fn side_share(p: &EnvelopePatch) -> f64 {
    let (lo, hi) = p
        .coons
        .sides
        .iter()
        .filter(|s| !s.collapsed)
        .map(|s| s.point(0.0).distance(s.point(1.0)))
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), c| {
            (lo.min(c), hi.max(c))
        });
    if hi > 0.0 { lo / hi } else { 1.0 }
}

/// A patch with a corner narrower than this (radians, 20°; the sides leaving it, not a collapsed
/// tip) is checked for folded cells at 16 and 32 a side too ([`unfolded`]): the Coons twist
/// near such a corner outweighs `S_u × S_v` within a few hundredths of the patch.
const NARROW_CHECKED_FINER: f64 = 20.0 * std::f64::consts::PI / 180.0;

/// A patch with a cell of its 8 × 8 grid this nearly flattened ([`least_sine`]: the sine of
/// the cell's corner angle, tilted from the normal expected there) is checked for folded cells
/// at 16 and 32 a side too ([`unfolded`]; envelope.md, "Patches through themselves", *Nearly
/// flat cells*): of the mixed survey's patches 4.8 % have one under this, and they held 183 of
/// the 196 patches folding at 32 × 32 and all 8 folding at 16 × 16.
const FLAT_CHECKED_FINER: f64 = 0.3;

/// The least angle (radians) between the two sides leaving a corner of `p`, of the corners
/// with no collapsed side.
fn narrowest_corner(p: &EnvelopePatch) -> f64 {
    let sides = &p.coons.sides;
    (0..4)
        .filter(|&c| !sides[c].collapsed && !sides[(c + 3) % 4].collapsed)
        .map(|c| sides[c].d1(0.0).angle_between(-sides[(c + 3) % 4].d1(1.0)))
        .filter(|a| a.is_finite())
        .fold(std::f64::consts::PI, f64::min)
}

/// A patch as [`unfolded`] leaves it.
struct Unfolded {
    patch: EnvelopePatch,
    /// Its folded cells as the report samples them ([`FOLD_CELLS`] a side).
    folds: Vec<Fold>,
    /// How sharply the lines of that grid turn ([`largest_turn`]).
    turn: f64,
    /// Folded cells the rescaling search left between the report's samples (at twice `cells`
    /// a side, or at 16 and 32 for a patch checked finer); 0 where it was not needed.
    between: usize,
}

/// The β tried on a folded patch's sides ([`unfolded`], [`Side::scaled`]): the cross
/// derivative's middle drawn in (β > 0) or pushed out (β < 0; at −4 to five times the fitted
/// one, tried last: a crease along a long side of heap 500132 needed more than −2, envelope.md,
/// *Pushed out further*).
const SQUEEZES: [f64; 9] = [0.25, 0.5, 0.75, 0.9, -0.25, -0.5, -1.0, -2.0, -4.0];

/// What the rescaling search ([`unfolded`]) may change on a side.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Moves {
    /// Its cross derivative's scale ([`SQUEEZES`]).
    Scales,
    /// That, or a lean across the side ([`LEANS`]).
    ScalesAndLeans,
    /// Those, or a scale pushing further out ([`FAR_SQUEEZES`]).
    Further,
}

/// The leans tried on a folded patch's sides after the β ([`unfolded`], [`Side::leaned`]):
/// `c·|X(½)|/|g(½)|·4s(1 − s)·g(s)` added to the cross derivative, c of these.
const LEANS: [f64; 6] = [0.25, 0.5, 1.0, 2.0, -0.25, -0.5];

/// The β tried after [`SQUEEZES`] and the leans on a patch still folding at the report's
/// samples after every other move ([`unfolded`], [`Moves::Further`]): the cross derivative's
/// middle pushed out to 9 and 17 times the fitted one (envelope.md, *Pushed out further
/// still*).
const FAR_SQUEEZES: [f64; 2] = [-8.0, -16.0];

/// `side` leaned across by each of [`LEANS`] ([`Side::leaned`]), those that keep its cross
/// derivative's part across it pointing the way it did ([`Side::lean_keeps_its_side`]); none
/// for a collapsed side.
fn leans(side: &Side) -> Vec<Side> {
    if side.collapsed {
        return Vec::new();
    }
    let unit = side.cross(0.5).0.length() / side.basis(0.5).0.length().max(1e-300);
    LEANS
        .iter()
        .map(|c| 4.0 * c * unit)
        .filter(|m| m.is_finite())
        .map(|m| side.clone().leaned((m, -m)))
        .filter(Side::lean_keeps_its_side)
        .collect()
}

/// `p`, or where it folds (as the report samples it, or `cells` a side) or passes through
/// itself ([`super::folds::self_crossings`] at 8 cells a side) — and where it folds at 16 or
/// 32 if it is checked finer: its 8 × 8 grid lines turn by more than [`TURN_CHECKED_FINER`]
/// (then passing through itself at 16 counts too), a side is under [`SHORT_CHECKED_FINER`] of
/// the longest, a corner narrower than [`NARROW_CHECKED_FINER`] or a cell of its 8 × 8 grid
/// flatter than [`FLAT_CHECKED_FINER`] — or passes through one of the grids `others` (16 × 16
/// grids of its neighbours, [`kept_apart`]), the same patch with its sides' cross derivatives
/// scaled between their corners (envelope.md, "Folded patches: cross derivatives rescaled");
/// with its folded cells as the report samples them. The scale is 1 at the corners and
/// positive, so the fits there, the normal along every border and G1 with the patch across
/// hold whatever it is. Round by round, of every side not yet scaled and every β of
/// [`SQUEEZES`], the one change is kept that leaves fewest folded cells sampled at twice
/// `cells` (at 32 and 16 a side for a patch checked finer) and at the report's [`FOLD_CELLS`]
/// together (a fold at the samples is not traded for one between them, nor one between them
/// left because it shows only at the report's samples; envelope.md, "At the report's samples
/// too") and then, where the patch crossed itself or a neighbour, fewest crossing triangle
/// pairs at 8 and 16 cells a side; among changes alike the longest side's and the least |β|
/// come first (never the listing's order). Other patches are kept as built.
fn unfolded(net: &Network, p: EnvelopePatch, cells: usize, others: &[Vec<DVec3>]) -> Unfolded {
    let folds = |p: &EnvelopePatch, k: usize| {
        super::folds::folds_past_corners(net, std::slice::from_ref(p), k)
    };
    let grid = p.coons.grid(FOLD_CELLS);
    let reported = grid_folds(net, &p, 0, &grid, FOLD_CELLS);
    // The crossings of a 16 × 16 grid with the other patches given.
    let apart = |g: &[DVec3]| -> usize {
        others
            .iter()
            .map(|o| grids_crossing(g, o, 2 * FOLD_CELLS))
            .sum()
    };
    // A patch whose grid lines turn sharply between the samples, beside a very short side or a
    // very narrow corner, or with a nearly flattened cell, may fold or bulge through itself
    // between them: checked at 16 and 32 a side.
    let turn = largest_turn(&grid, FOLD_CELLS);
    let bends = turn > TURN_CHECKED_FINER;
    let finer = bends
        || side_share(&p) < SHORT_CHECKED_FINER
        || narrowest_corner(&p) < NARROW_CHECKED_FINER
        || least_sine(net, &p, &grid, FOLD_CELLS) < FLAT_CHECKED_FINER;
    // Its grid 32 a side, and the one 16 a side within it (the same points).
    let finest = finer.then(|| p.coons.grid(4 * FOLD_CELLS));
    let twice = match &finest {
        Some(g) => Some(every_nth_line(g, 4 * FOLD_CELLS, 2 * FOLD_CELLS)),
        None => (!others.is_empty()).then(|| p.coons.grid(2 * FOLD_CELLS)),
    };
    let crossing = grid_crossings(&grid, FOLD_CELLS) > 0
        || twice
            .as_ref()
            .is_some_and(|g| (bends && grid_crossings(g, 2 * FOLD_CELLS) > 0) || apart(g) > 0);
    let folded_between = finest.as_ref().is_some_and(|g| {
        !grid_folds(net, &p, 0, g, 4 * FOLD_CELLS).is_empty()
            || twice
                .as_ref()
                .is_some_and(|h| !grid_folds(net, &p, 0, h, 2 * FOLD_CELLS).is_empty())
    });
    if !crossing
        && !folded_between
        && reported.is_empty()
        && (cells == FOLD_CELLS || folds(&p, cells).is_empty())
    {
        return Unfolded {
            patch: p,
            folds: reported,
            turn,
            between: 0,
        };
    }
    // Twice `cells` a side; four times the report's where the patch was checked finer (a fold
    // cleared at 16 a side was left in a strip thinner than that: 5 and 12 cells at 24 and 32),
    // and then at 16 too.
    let fine = if finer { 4 * FOLD_CELLS } else { 2 * cells };
    // Folded cells first (twice as fine and at the report's samples), then the crossing pairs:
    // a fold is never traded for fewer crossings.
    // One grid evaluated `fine` a side; the report's 8 × 8 (and 16 × 16) are every few of its
    // lines, the same points.
    // A change is kept only if it scores below `beat` (the best so far): where its folded cells
    // already reach past `beat`'s, or its crossings counted so far reach `beat`'s, it cannot,
    // and the rest is not counted (it scores `usize::MAX` crossings then).
    let score = |q: &EnvelopePatch, beat: Option<(usize, usize)>| {
        let g = q.coons.grid(fine);
        let coarse = every_nth_line(&g, fine, FOLD_CELLS);
        // At 16 a side too where the patch was checked finer (`fine` is 32): a fold there can
        // lie between the samples at 32 (heap 400183 at t = 0.1 folded in one cell at 16, none
        // at 32).
        let middle = finer.then(|| every_nth_line(&g, fine, 2 * FOLD_CELLS));
        let folded = grid_folds(net, q, 0, &g, fine).len()
            + middle
                .as_ref()
                .map_or(0, |m| grid_folds(net, q, 0, m, 2 * FOLD_CELLS).len())
            + grid_folds(net, q, 0, &coarse, FOLD_CELLS).len();
        if !crossing {
            return (folded, 0);
        }
        let lost = |crossings: usize| beat.is_some_and(|b| (folded, crossings) >= b);
        if lost(0) {
            return (folded, usize::MAX);
        }
        let twice = if fine == 2 * FOLD_CELLS {
            g
        } else if fine % (2 * FOLD_CELLS) == 0 {
            every_nth_line(&g, fine, 2 * FOLD_CELLS)
        } else {
            q.coons.grid(2 * FOLD_CELLS)
        };
        let mut crossings = grid_crossings(&coarse, FOLD_CELLS);
        if lost(crossings) {
            return (folded, usize::MAX);
        }
        crossings += grid_crossings(&twice, 2 * FOLD_CELLS);
        if lost(crossings) {
            return (folded, usize::MAX);
        }
        (folded, crossings + apart(&twice))
    };
    let search = |p: &EnvelopePatch, moves: Moves| -> (EnvelopePatch, (usize, usize)) {
        let p = p.clone();
        let mut least = score(&p, None);
        let mut best = None;
        // Sides in an order of their own (longest first, then by their middle's position), never
        // the region's listing, so that the surface does not depend on it.
        let key = |k: usize| {
            let s = &p.sides[k];
            let mid = net.curves[s.curve].bezier.eval(0.5 * (s.t0 + s.t1));
            [-chord(net, s), mid.x, mid.y, mid.z]
        };
        let mut order = [0, 1, 2, 3];
        order.sort_by(|&a, &b| by_keys(&key(a), &key(b)));
        // Best first: each round every side not yet scaled tries every β from the patch so far,
        // and the one change that helps most is kept (a side scaled once stays so).
        let mut scaled = [false; 4];
        while least != (0, 0) {
            let mut round: Option<((usize, usize), usize, EnvelopePatch)> = None;
            for side in order.into_iter().filter(|&k| !scaled[k]) {
                let here = &best.as_ref().unwrap_or(&p).coons.sides[side];
                let squeezed = SQUEEZES.map(|beta| here.clone().scaled(beta));
                let further: Vec<Side> = match moves {
                    Moves::Scales => Vec::new(),
                    Moves::ScalesAndLeans => leans(here),
                    Moves::Further => leans(here)
                        .into_iter()
                        .chain(FAR_SQUEEZES.map(|beta| here.clone().scaled(beta)))
                        .collect(),
                };
                for changed in squeezed.into_iter().chain(further) {
                    let mut q = best.as_ref().unwrap_or(&p).clone();
                    q.coons.sides[side] = changed;
                    let beat = round.as_ref().map_or(least, |r| r.0);
                    let n = score(&q, Some(beat));
                    if n < beat {
                        round = Some((n, side, q));
                    }
                }
            }
            let Some((n, side, q)) = round else {
                break;
            };
            (least, best) = (n, Some(q));
            scaled[side] = true;
        }
        match best {
            Some(q) => (q, least),
            None => (p.clone(), least),
        }
    };
    let (mut best, mut least) = search(&p, Moves::Scales);
    // Still folding: the sides run by arc length, and the search again from there.
    for run in [Run::ArcLength, Run::Matched, Run::MatchedToFaster] {
        if least.0 == 0 {
            break;
        }
        let (q, n) = search(&run_along(&p, run), Moves::Scales);
        if n < least {
            (best, least) = (q, n);
        }
    }
    // Still folding: the search again with the sides' cross derivatives leaned across them too;
    // and where the report's own samples still fold, pushed out further still (between them
    // alone, as on the slider's steps, the push clears nothing and costs a search).
    if least.0 > 0 {
        let (q, n) = search(&p, Moves::ScalesAndLeans);
        if n < least {
            (best, least) = (q, n);
        }
    }
    let mut grid = best.coons.grid(FOLD_CELLS);
    let mut folds = grid_folds(net, &best, 0, &grid, FOLD_CELLS);
    if least.0 > 0 && !folds.is_empty() {
        let (q, n) = search(&p, Moves::Further);
        if n < least {
            (best, least) = (q, n);
            grid = best.coons.grid(FOLD_CELLS);
            folds = grid_folds(net, &best, 0, &grid, FOLD_CELLS);
        }
    }
    Unfolded {
        // The search's score counts the report's samples once more.
        between: least.0.saturating_sub(folds.len()),
        folds,
        turn: largest_turn(&grid, FOLD_CELLS),
        patch: best,
    }
}

/// The grid `m` cells a side within the grid `g` of `k` ([`Coons::grid`]; `k` a multiple of
/// `m`): every `k / m`-th line of it. The points are those `Coons::grid(m)` evaluates, bit for
/// bit (i·(k/m)/k and i/m are the same double).
fn every_nth_line(g: &[DVec3], k: usize, m: usize) -> Vec<DVec3> {
    debug_assert_eq!(k % m, 0);
    let step = k / m;
    (0..=m)
        .flat_map(|j| (0..=m).map(move |i| g[i * step + (k + 1) * j * step]))
        .collect()
}

/// How a still-folding patch's sides are run along their curves ([`run_along`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Run {
    /// Every side at nearly even speed.
    ArcLength,
    /// Of each two opposite sides, the one slower at its ends (for its length) as it is, the
    /// other so that it covers its length in the same shares.
    Matched,
    /// The same with the faster one kept.
    MatchedToFaster,
}

/// `p` with its sides run along their curves as `run` says ([`Reparam`]; envelope.md, "Sides
/// run along their curves"), the cross derivatives fitted again to the legs that follow; scales
/// left out (the search starts again from there).
fn run_along(p: &EnvelopePatch, run: Run) -> EnvelopePatch {
    let mut sides: Vec<Side> = p
        .coons
        .sides
        .iter()
        .map(|s| {
            let mut s = s.clone();
            s.squeeze = 0.0;
            if !s.collapsed && run == Run::ArcLength {
                s.reparam = Reparam::arc_length(&s.curve);
            }
            s
        })
        .collect();
    if run != Run::ArcLength {
        // How slow a side is at its ends for its length.
        let crowd = |s: &Side| {
            let len = s
                .curve
                .eval(0.0)
                .distance(s.curve.eval(1.0))
                .max(f64::MIN_POSITIVE);
            (s.curve.derivatives(0.0).d1.length() + s.curve.derivatives(1.0).d1.length()) / len
        };
        for (a, b) in [(0, 2), (1, 3)] {
            if sides[a].collapsed || sides[b].collapsed {
                continue;
            }
            let (ca, cb) = (crowd(&sides[a]), crowd(&sides[b]));
            // Alike (a patch with a symmetry): neither is chosen over the other.
            if (ca - cb).abs() <= 1e-9 * ca.max(cb) {
                continue;
            }
            let slower_kept = run == Run::Matched;
            let (keep, follow) = if (ca < cb) == slower_kept {
                (a, b)
            } else {
                (b, a)
            };
            let kept = sides[keep].curve.clone();
            if let Some(share) = super::reparam::arc_share(&kept) {
                // Side `follow` at s faces side `keep` at 1 − s.
                let target = |s: f64| {
                    let (a, da) = share(1.0 - s);
                    (1.0 - a, da)
                };
                sides[follow].reparam = Reparam::following(&sides[follow].curve, target);
            }
        }
    }
    let ends: Vec<(DVec3, DVec3)> = sides.iter().map(|s| (s.d1(0.0), s.d1(1.0))).collect();
    for k in 0..4 {
        let a0 = -ends[(k + 3) % 4].1;
        let a1 = ends[(k + 1) % 4].0;
        sides[k] = sides[k].clone().refitted(a0, a1);
    }
    let mut q = p.clone();
    q.coons.sides = sides.try_into().expect("four sides");
    q
}

/// The largest angle (degrees) between the two sides' normals along every border, sampled at
/// `samples` + 1 points per patch side: `C′ × X` on each side (analytic, outward).
pub fn largest_border_jump(net: &Network, patches: &[EnvelopePatch], samples: usize) -> f64 {
    largest_border_jump_on(net, patches, samples, |_| true)
}

/// [`largest_border_jump`] along the curves that a side of a patch in region `r` with
/// `near(r)` lies on.
pub fn largest_border_jump_on(
    net: &Network,
    patches: &[EnvelopePatch],
    samples: usize,
    near: impl Fn(usize) -> bool,
) -> f64 {
    // Per curve, the (side range, normal function) of every patch side on it.
    let mut on: Vec<Vec<(usize, usize)>> = vec![Vec::new(); net.curves.len()];
    for (p, patch) in patches.iter().enumerate() {
        for (k, s) in patch.sides.iter().enumerate() {
            on[s.curve].push((p, k));
        }
    }
    for users in &mut on {
        if !users.iter().any(|&(p, _)| near(patches[p].region)) {
            users.clear();
        }
    }
    let normal = |p: usize, k: usize, tau: f64| -> Option<DVec3> {
        let sp = patches[p].side_parameter(k, tau)?;
        let side = &patches[p].coons.sides[k];
        Some(side.d1(sp).cross(side.cross(sp).0).normalize_or_zero())
    };
    let mut worst = 0.0f64;
    for users in &on {
        for &(p, k) in users {
            for j in 0..=samples {
                let tau = patches[p].tau(k, j as f64 / samples as f64);
                let n0 = normal(p, k, tau).unwrap_or(DVec3::ZERO);
                for &(q, l) in users {
                    if q == p {
                        continue;
                    }
                    if let Some(n1) = normal(q, l, tau)
                        && n0 != DVec3::ZERO
                        && n1 != DVec3::ZERO
                    {
                        let angle = n0.cross(n1).length().atan2(n0.dot(n1));
                        worst = worst.max(angle.to_degrees());
                    }
                }
            }
        }
    }
    worst
}
