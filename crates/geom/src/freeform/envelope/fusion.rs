//! Vertex pairs and fusion edges between two primitives' silhouette loops (seed 004 §5.2;
//! ALGORITHMS §11.4(a), §11.5; docs/algorithms/envelope.md).
//!
//! Both loops lie in planes normal to d. In one frame `X = unit(d × a)` (a the world axis least
//! parallel to d), `Y = d × X`, every loop vertex has a polar angle about its own primitive's
//! centre; vertices of equal angle (1e-9 rad) pair up, and an angle one loop lacks is inserted
//! on it — at the root of `(C(τ) − G)·(−sin α X + cos α Y)` on the silhouette edge spanning it.
//! An inserted vertex is a **T-point**: a corner of the fusion quads only; the primitive's
//! region keeps the whole silhouette edge as one side (§11.4(a)). Its tangent plane is spanned by
//! the edge's tangent and d (every silhouette edge's basis is ±d).
//!
//! The **fusion edge** from P (on A's loop) to Q (on B's) is the polynomial cubic
//! `P, P + (L/3)T_P, Q − (L/3)T_Q, Q` with `T_P = unit((Q − P) − ((Q − P)·n_P)n_P)`, n_P the
//! tangent-plane normal at P (T_Q likewise), L = |Q − P|: it leaves each end in that end's
//! tangent plane (§8.1), and for equal polar angles along d. Consecutive pairs bound a fusion
//! quad: A's loop from angle α_k to α_(k+1), the fusion edge there, B's loop back, the fusion
//! edge at α_k backwards — counter-clockwise seen from outside.

use super::network::{CurveKind, Network, PatchSide, Region, RegionKind};
use super::trim::SilhouetteLoop;
use crate::freeform::bezier::RationalBezier;
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// Angles closer than this (radians) are one.
const SAME_ANGLE: f64 = 1e-9;

/// The frame of polar angles about d.
fn frame(d: DVec3) -> (DVec3, DVec3) {
    let a = [DVec3::X, DVec3::Y, DVec3::Z]
        .into_iter()
        .min_by(|p, q| p.dot(d).abs().total_cmp(&q.dot(d).abs()))
        .expect("three axes");
    let x = d.cross(a).normalize();
    (x, d.cross(x))
}

fn angle_of(v: DVec3, (x, y): (DVec3, DVec3)) -> f64 {
    v.dot(y).atan2(v.dot(x)).rem_euclid(TAU)
}

/// Whether two angles are one (mod 2π).
fn same(a: f64, b: f64) -> bool {
    let d = (a - b).rem_euclid(TAU);
    !(SAME_ANGLE..=TAU - SAME_ANGLE).contains(&d)
}

/// One loop vertex: angle, network vertex, and where it lies (curve, τ).
#[derive(Debug, Clone, Copy)]
struct LoopPoint {
    angle: f64,
    vertex: usize,
}

/// The loop as pieces in the direction of increasing angle, each from one loop point to the
/// next: (piece, start point).
struct Walk {
    pieces: Vec<(PatchSide, LoopPoint)>,
}

/// The loop's edges turned to run with increasing angle about G (`forward` tells whether the
/// kept faces run that way), cut at `extra` angles (T-points, added to `net`).
fn walk(
    net: &mut Network,
    lp: &SilhouetteLoop,
    g: DVec3,
    fr: (DVec3, DVec3),
    d: DVec3,
    extra: &[f64],
) -> Walk {
    let mut pieces = Vec::new();
    for e in &lp.edges {
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
            let rho = net.vertices[va].rho; // unused by fusion regions; kept for completeness
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
            ));
        }
    }
    pieces.sort_by(|a, b| a.1.angle.total_cmp(&b.1.angle));
    Walk { pieces }
}

/// Joins the silhouette loops of A (centre `ga`, its loop `la`) and B with fusion edges and
/// fusion quads; `d` = unit(G_B − G_A).
pub fn fuse(
    net: &mut Network,
    (ga, la): (DVec3, &SilhouetteLoop),
    (gb, lb): (DVec3, &SilhouetteLoop),
    d: DVec3,
) {
    let fr = frame(d);
    let angles = |net: &Network, lp: &SilhouetteLoop, g: DVec3| -> Vec<f64> {
        lp.edges
            .iter()
            .map(|e| angle_of(net.vertices[net.curves[e.curve].ends[0]].position - g, fr))
            .collect()
    };
    let (aa, ab) = (angles(net, la, ga), angles(net, lb, gb));
    let missing = |have: &[f64], other: &[f64]| -> Vec<f64> {
        other
            .iter()
            .copied()
            .filter(|&x| !have.iter().any(|&h| same(h, x)))
            .collect()
    };
    let (for_a, for_b) = (missing(&aa, &ab), missing(&ab, &aa));
    let wa = walk(net, la, ga, fr, d, &for_a);
    let wb = walk(net, lb, gb, fr, d, &for_b);
    let n = wa.pieces.len();
    if n == 0 || wb.pieces.len() != n {
        return;
    }
    // Fusion edges at each angle, A's point to B's.
    let start = wb
        .pieces
        .iter()
        .position(|(_, q)| same(q.angle, wa.pieces[0].1.angle))
        .unwrap_or(0);
    let mut fusion = Vec::with_capacity(n);
    for k in 0..n {
        let p = wa.pieces[k].1.vertex;
        let q = wb.pieces[(start + k) % n].1.vertex;
        let (pp, pq) = (net.vertices[p].position, net.vertices[q].position);
        let (np, nq) = (net.vertices[p].normal, net.vertices[q].normal);
        let pq_v = pq - pp;
        let l = pq_v.length();
        let tp = (pq_v - pq_v.dot(np) * np).normalize_or(d);
        let tq = (pq_v - pq_v.dot(nq) * nq).normalize_or(d);
        let bez = RationalBezier::polynomial(vec![pp, pp + l / 3.0 * tp, pq - l / 3.0 * tq, pq])
            .expect("finite points");
        fusion.push(net.add_curve(bez, p, q, CurveKind::Fusion));
    }
    for k in 0..n {
        let j = (k + 1) % n;
        let a_piece = wa.pieces[k].0;
        let b_piece = wb.pieces[(start + k) % n].0;
        net.regions.push(Region {
            sides: vec![
                a_piece,
                PatchSide::whole(fusion[j], true),
                b_piece.reversed(),
                PatchSide::whole(fusion[k], false),
            ],
            kind: RegionKind::Fusion,
        });
    }
}
