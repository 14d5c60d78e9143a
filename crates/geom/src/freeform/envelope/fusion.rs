//! Vertex pairs and fusion edges between two primitives' facing sections (seed 004 §5.2;
//! docs/algorithms/envelope.md, "The network for two primitives").
//!
//! Both sections lie in planes normal to d: whole silhouette loops (two primitives, or
//! centres on a line) or chains between the same two rays (the straight edges where the
//! neighbours' cuts cross them, which project onto one line in both, `hull.rs`). In one frame `X = unit(d × a)` (a the world axis least
//! parallel to d), `Y = d × X`, every loop vertex has a polar angle about its own primitive's
//! centre; vertices of equal angle (1e-9 rad) pair up, and an angle one loop lacks is inserted
//! on it — at the root of `(C(τ) − G)·(−sin α X + cos α Y)` on the silhouette edge spanning it.
//! An inserted vertex is a **T-point**: a corner of the fusion quads only; the primitive's
//! region keeps the whole silhouette edge as one side (§11.4(a)). Its tangent plane is spanned by
//! the edge's tangent and d (every silhouette edge's basis is ±d).
//!
//! The **fusion edge** from P (on A's loop) to Q (on B's) is the polynomial cubic
//! `P, P + λ_P(L/3)T_P, Q − λ_Q(L/3)T_Q, Q` with `T_P = unit((Q − P) − ((Q − P)·n_P)n_P)`, n_P
//! the tangent-plane normal at P (T_Q likewise), L = |Q − P|, λ = min(1, 2t) of the end's t
//! (λ = 1 at t ≥ ½; shorter below t = ½ so that the edge tends to its chord as
//! t → 0, like the primitives' edges: envelope.md, "Fusion edges at small t"): it leaves each
//! end in that end's tangent plane (§8.1), and for equal polar angles along d. Consecutive
//! pairs bound a fusion quad: A's loop from angle α_k to α_(k+1), the fusion edge there, B's
//! loop back, the fusion edge at α_k backwards — counter-clockwise seen from outside. A chain
//! is paired the same way from its first ray to its last, which are a vertex pair of their own
//! (the paper's straight-edge vertices, §5.2 b): the paper pairs the curved chains by a
//! normalised parameter, which it leaves open; the polar angle is one over the same angular
//! range on both chains, and it makes the two-primitive rule a special case (and the fusion
//! surface of equal aligned primitives exactly translational).

use super::edges::legs_for;
use super::network::{CurveKind, Network, PatchSide, Region, RegionKind};
use crate::freeform::bezier::RationalBezier;
use crate::freeform::envelope::tolerances::TOLERANCES;
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// [`TOLERANCES`]`.same_angle`.
const SAME_ANGLE: f64 = TOLERANCES.same_angle;

/// [`TOLERANCES`]`.near_angle`.
pub const NEAR_ANGLE: f64 = TOLERANCES.near_angle;

/// [`TOLERANCES`]`.end_angle`.
const END_ANGLE: f64 = TOLERANCES.end_angle;

/// The frame of polar angles about d.
fn frame(d: DVec3) -> (DVec3, DVec3) {
    super::chart::frame::plane_axes(d)
}

fn angle_of(v: DVec3, (x, y): (DVec3, DVec3)) -> f64 {
    v.dot(y).atan2(v.dot(x)).rem_euclid(TAU)
}

/// Whether two angles are one (mod 2π).
fn same(a: f64, b: f64) -> bool {
    let d = (a - b).rem_euclid(TAU);
    !(SAME_ANGLE..=TAU - SAME_ANGLE).contains(&d)
}

/// One section vertex: its angle and network vertex.
#[derive(Debug, Clone, Copy)]
struct LoopPoint {
    angle: f64,
    vertex: usize,
}

/// The section as pieces in the direction of increasing angle, each from one point to the
/// next: (piece, start point, end vertex).
struct Walk {
    pieces: Vec<(PatchSide, LoopPoint, usize)>,
}

/// Angle offset from `start`, with offsets a hair below 2π (rounding) taken as 0.
fn offset(angle: f64, start: f64) -> f64 {
    let o = (angle - start).rem_euclid(TAU);
    if o > TAU - SAME_ANGLE { 0.0 } else { o }
}

/// The section's edges turned to run with increasing angle about G, cut at `extra` angles
/// (T-points, added to `net`), sorted by angle: a chain from `chain_start` along its links.
fn walk(
    net: &mut Network,
    edges: &[PatchSide],
    g: DVec3,
    fr: (DVec3, DVec3),
    d: DVec3,
    extra: &[f64],
    chain_start: Option<f64>,
) -> Walk {
    let start = chain_start.unwrap_or(0.0);
    let mut pieces = Vec::new();
    for e in edges {
        let c = e.curve;
        let curve = net.curves[c].bezier.clone();
        // Orient the edge by increasing angle: compare the angle just after its start.
        let a0 = angle_of(curve.eval(0.0) - g, fr);
        let a1 = angle_of(curve.eval(1.0) - g, fr);
        let span = (a1 - a0).rem_euclid(TAU);
        let forward = span < PI;
        let (start_a, span) = if forward {
            (a0, span)
        } else {
            (a1, TAU - span)
        };
        // T-points on it: angles strictly inside its span.
        let mut cuts: Vec<(f64, f64)> = Vec::new(); // (offset angle, τ)
        for &alpha in extra {
            let off = (alpha - start_a).rem_euclid(TAU);
            if off > SAME_ANGLE && off < span - SAME_ANGLE {
                let dir = -alpha.sin() * fr.0 + alpha.cos() * fr.1;
                let f = |tau: f64| (curve.eval(tau) - g).dot(dir);
                let (mut lo, mut hi) = (0.0, 1.0);
                let flo = f(lo);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if (f(mid) > 0.0) == (flo > 0.0) {
                        lo = mid
                    } else {
                        hi = mid
                    }
                }
                cuts.push((off, 0.5 * (lo + hi)));
            }
        }
        cuts.sort_by(|a, b| a.0.total_cmp(&b.0));
        // Pins along the edge in the direction of increasing angle.
        let (ta, tb) = if forward { (0.0, 1.0) } else { (1.0, 0.0) };
        let va = net.curves[c].ends[if forward { 0 } else { 1 }];
        let mut stops = vec![(ta, va, start_a)];
        for &(off, tau) in &cuts {
            let p = curve.eval(tau);
            let tangent = curve.derivatives(tau).d1;
            let mut n = tangent.cross(d).normalize_or_zero();
            if n.dot(p - g) < 0.0 {
                n = -n;
            }
            // t between the edge's ends by its parameter (the same whichever way round the
            // edge or the scene is listed); the fusion edge's leg there reads it.
            let [e0, e1] = net.curves[c].ends.map(|e| net.vertices[e].t_about(g));
            let rho = (e0 + (e1 - e0) * tau) * p.distance(g);
            let v = net.add_vertex(p, n, rho);
            net.pin(c, tau, v);
            stops.push((tau, v, (start_a + off).rem_euclid(TAU)));
        }
        let vb = net.curves[c].ends[if forward { 1 } else { 0 }];
        stops.push((tb, vb, (start_a + span).rem_euclid(TAU)));
        for w in stops.windows(2) {
            pieces.push((
                PatchSide {
                    curve: c,
                    t0: w[0].0,
                    t1: w[1].0,
                },
                LoopPoint {
                    angle: w[0].2,
                    vertex: w[0].1,
                },
                w[1].1,
            ));
        }
    }
    pieces.sort_by(|a, b| offset(a.1.angle, start).total_cmp(&offset(b.1.angle, start)));
    if chain_start.is_some() {
        // A chain runs from its one start that no piece ends at (its first point may sit a
        // hair before the start ray, by rounding).
        let head = pieces
            .iter()
            .position(|p| !pieces.iter().any(|q| q.2 == p.1.vertex));
        if let Some(h) = head {
            let mut ordered = vec![pieces.swap_remove(h)];
            while let Some(i) = pieces
                .iter()
                .position(|p| p.1.vertex == ordered[ordered.len() - 1].2)
            {
                ordered.push(pieces.swap_remove(i));
            }
            ordered.append(&mut pieces);
            pieces = ordered;
        }
    }
    Walk { pieces }
}

/// The places of `ua` and `ub` (angles when `circular`, else normalised parameters) closer than
/// `near` but not equal, each the other's nearest in the other list, with no place of either
/// list between them: (A's, B's). Symmetric in the two lists, so independent of which
/// primitive is A.
fn nearly_equal(ua: &[f64], ub: &[f64], near: f64, circular: bool) -> Vec<(f64, f64)> {
    let gap = |x: f64, y: f64| {
        if circular {
            let o = (x - y).rem_euclid(TAU);
            o.min(TAU - o)
        } else {
            (x - y).abs()
        }
    };
    let nearest = |x: f64, set: &[f64]| {
        set.iter()
            .copied()
            .min_by(|p, q| gap(x, *p).total_cmp(&gap(x, *q)))
    };
    let mut out = Vec::new();
    for &a in ua {
        let Some(b) = nearest(a, ub) else { continue };
        let g = gap(a, b);
        // Either one equal to a place of the other list pairs as equal, not as near.
        if g >= near || ub.iter().any(|&x| same(x, a)) || ua.iter().any(|&x| same(x, b)) {
            continue;
        }
        if nearest(b, ua).is_none_or(|back| !same(back, a)) {
            continue;
        }
        let between = ua
            .iter()
            .chain(ub)
            .any(|&z| !same(z, a) && !same(z, b) && gap(z, a) < g && gap(z, b) < g);
        if !between {
            out.push((a, b));
        }
    }
    out
}

/// The fusion edge from network vertex p (on A's section, centre `ga`) to q (on B's, `gb`).
/// `along_axis` (the charts, which pair equal angles only): both legs along d — the one
/// direction that lies both in each end's tangent plane (it holds d) and in the half-plane
/// through the axis at their common angle — so that the edge lies in that half-plane even
/// where the two sections' radii differ and their tangent planes are not normal to it.
fn fusion_edge(
    net: &mut Network,
    (p, q): (usize, usize),
    d: DVec3,
    (ga, gb): (DVec3, DVec3),
    along_axis: bool,
) -> usize {
    let (pp, pq) = (net.vertices[p].position, net.vertices[q].position);
    // Each leg a third of the chord, shorter below t = ½ (`legs_for`, t of its own end).
    let lp = legs_for(net.vertices[p].t_about(ga));
    let lq = legs_for(net.vertices[q].t_about(gb));
    let (np, nq) = (net.vertices[p].normal, net.vertices[q].normal);
    let pq_v = pq - pp;
    // A third of the chord; along the axis, no more than a third of the way along d: the edge
    // then runs one way along the axis (its z control values increase), as the axial chart
    // needs.
    let l = if along_axis {
        pq_v.length().min(pq_v.dot(d).abs())
    } else {
        pq_v.length()
    };
    let (tp, tq) = if along_axis {
        (d, d)
    } else {
        (
            (pq_v - pq_v.dot(np) * np).normalize_or(d),
            (pq_v - pq_v.dot(nq) * nq).normalize_or(d),
        )
    };
    let bez =
        RationalBezier::polynomial(vec![pp, pp + lp * l / 3.0 * tp, pq - lq * l / 3.0 * tq, pq])
            .expect("finite points");
    net.add_curve(bez, p, q, CurveKind::Fusion)
}

/// Joins A's section (centre `ga`, its edges `sa`) to B's with fusion edges and fusion quads;
/// `d` = unit(G_B − G_A). `span`: for chains, the rays (normal to d) of their first and last
/// points in the order of increasing angle about d; `None` for whole loops. Returns the fusion
/// edges at the chain's first and last rays (the lids' sides), or `None` for loops.
pub fn fuse(
    net: &mut Network,
    (ga, sa): (DVec3, &[PatchSide]),
    (gb, sb): (DVec3, &[PatchSide]),
    d: DVec3,
    span: Option<(DVec3, DVec3)>,
    (from, to, near_angle): (usize, usize, f64),
) -> Result<Option<(usize, usize)>, String> {
    let fr = frame(d);
    // Where each section's points lie: their polar angle for whole loops; for chains, the
    // angle normalised between the chain's own two ends (the points only one of its edges
    // reaches), which pair with the other chain's ends (the paper's normalised parameter,
    // §5.2 b; the ends lie on the same rays, so this is the polar angle up to rounding).
    let start = span.map_or(0.0, |(s, _)| angle_of(s, fr));
    let base = start - 0.5;
    let place = |net: &Network, edges: &[PatchSide], g: DVec3| -> (Vec<f64>, (f64, f64)) {
        let ends: Vec<usize> = edges
            .iter()
            .flat_map(|e| net.curves[e.curve].ends)
            .collect();
        let at = |v: usize| angle_of(net.vertices[v].position - g, fr);
        let range = if span.is_some() {
            let tips: Vec<f64> = ends
                .iter()
                .filter(|&&v| ends.iter().filter(|&&w| w == v).count() == 1)
                .map(|&v| offset(at(v), base))
                .collect();
            let lo = tips.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = tips.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            (lo, hi)
        } else {
            (0.0, TAU)
        };
        let mut u: Vec<f64> = Vec::new();
        for &v in &ends {
            if span.is_some() && ends.iter().filter(|&&w| w == v).count() == 1 {
                continue;
            }
            let x = if span.is_some() {
                (offset(at(v), base) - range.0) / (range.1 - range.0)
            } else {
                at(v)
            };
            if !u.iter().any(|&h| same(h, x)) {
                u.push(x);
            }
        }
        (u, range)
    };
    let ((ua, ra), (ub, rb)) = (place(net, sa, ga), place(net, sb, gb));
    // Nearly equal places of the two sections, paired as they are (A's, B's).
    let near = if span.is_some() {
        near_angle / (ra.1 - ra.0).max(rb.1 - rb.0).max(NEAR_ANGLE)
    } else {
        near_angle
    };
    let matched = nearly_equal(&ua, &ub, near, span.is_none());
    let missing = |have: &[f64], other: &[f64], r: (f64, f64)| -> Vec<f64> {
        other
            .iter()
            .copied()
            .filter(|&x| {
                !have.iter().any(|&h| same(h, x))
                    && !matched.iter().any(|&(a, b)| same(a, x) || same(b, x))
            })
            .map(|x| {
                if span.is_some() {
                    (base + r.0 + x * (r.1 - r.0)).rem_euclid(TAU)
                } else {
                    x
                }
            })
            .collect()
    };
    let (for_a, for_b) = (missing(&ua, &ub, ra), missing(&ub, &ua, rb));
    let wa = walk(net, sa, ga, fr, d, &for_a, span.map(|_| start));
    let wb = walk(net, sb, gb, fr, d, &for_b, span.map(|_| start));
    let n = wa.pieces.len();
    if n == 0 || wb.pieces.len() != n {
        return Err(format!(
            "the facing sections have {} and {} pieces after pairing",
            n,
            wb.pieces.len()
        ));
    }
    let chained = |w: &Walk| (1..n).all(|k| w.pieces[k - 1].2 == w.pieces[k].1.vertex);
    if !chained(&wa) || !chained(&wb) {
        return Err("a facing section is not one chain".into());
    }
    let (shift, count) = match span {
        None => {
            // Whole loops: start B where its angle is A's first.
            let a0 = wa.pieces[0].1.angle;
            let shift = wb
                .pieces
                .iter()
                .position(|(_, q, _)| {
                    same(q.angle, a0)
                        || matched
                            .iter()
                            .any(|&(a, b)| same(a, a0) && same(b, q.angle))
                })
                .unwrap_or(0);
            (shift, n)
        }
        Some((s, e)) => {
            let (s, e) = (angle_of(s, fr), angle_of(e, fr));
            let near = |x: f64, y: f64| {
                let o = (x - y).rem_euclid(TAU);
                o.min(TAU - o) <= END_ANGLE
            };
            let ends = |w: &Walk, g: DVec3| {
                let last = net.vertices[w.pieces[n - 1].2].position;
                (w.pieces[0].1.angle, angle_of(last - g, fr))
            };
            for (w, g) in [(&wa, ga), (&wb, gb)] {
                let (first, last) = ends(w, g);
                if !near(first, s) || !near(last, e) {
                    return Err(
                        "a facing section does not run between the rays of its neighbours' cuts"
                            .into(),
                    );
                }
            }
            (0, n + 1)
        }
    };
    // Fusion edges at each angle, A's point to B's.
    let point = |w: &Walk, k: usize| {
        if k < n {
            w.pieces[k].1.vertex
        } else {
            w.pieces[n - 1].2
        }
    };
    let mut fusion = Vec::with_capacity(count);
    for k in 0..count {
        let p = point(&wa, k);
        let q = if span.is_none() {
            wb.pieces[(shift + k) % n].1.vertex
        } else {
            point(&wb, k)
        };
        fusion.push(fusion_edge(net, (p, q), d, (ga, gb), near_angle == 0.0));
    }
    for k in 0..n {
        let j = (k + 1) % count;
        let a_piece = wa.pieces[k].0;
        let b_piece = wb.pieces[(shift + k) % n].0;
        net.regions.push(Region {
            sides: vec![
                a_piece,
                PatchSide::whole(fusion[j], true),
                b_piece.reversed(),
                PatchSide::whole(fusion[k], false),
            ],
            kind: RegionKind::Fusion { from, to },
        });
    }
    Ok(span.map(|_| (fusion[0], fusion[n])))
}
