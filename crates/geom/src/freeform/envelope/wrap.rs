//! The facets of the hull of the primitives' centres, by gift wrapping (Chand & Kapur 1970;
//! Preparata & Shamos, *Computational Geometry*, §3.4.1; docs/algorithms/envelope.md, "Three or
//! more primitives").
//!
//! From one facet, the facet across each of its edges is found by turning the facet's plane
//! about that edge until it meets a centre: the plane turned by the least angle ψ over the
//! centres off the edge's line still has every centre behind it. With the facet's outward
//! normal `n` and `f` the direction into the facet square to the edge, a centre at `d` from
//! the edge has `ψ = atan2(−d·n, −d·f)` and the turned normal is `cos ψ · n − sin ψ · f`. One
//! turn reads every centre once, so the hull costs O(n) a facet edge, O(n²) in all, where the
//! search over every plane through three centres took O(n⁴) (60 primitives: 0.2 s;
//! docs/performance.md).
//!
//! Centres within `tol` of a facet's plane are on it, as in [`super::hull::layout`]; each facet
//! found is then written exactly as that search writes it — its normal from the first triple of
//! its centres (in index order) whose plane has every centre behind it, the centres on it, its
//! strict corners — and the facets are listed in the order of those triples, so the layout is
//! the same one, bit for bit (tested against the search on random and lattice centres). Where
//! the wrap does not close (an edge not shared by exactly two facets, a facet with no such
//! triple: centres within rounding of the tolerance), the caller falls back to the search.

use super::facet::{Facet, on_plane, supports, triple_normal};
use glam::DVec3;
use std::collections::HashMap;

/// The plane through the edge `p → q` turned from the one with outward normal `n` away from
/// the side `f` (unit, square to the edge, in the plane) until it meets a centre: its outward
/// unit normal, through a centre off the edge's line. None if every centre is on that line.
fn turn(c: &[DVec3], p: usize, q: usize, n: DVec3, f: DVec3, tol: f64) -> Option<DVec3> {
    let mut best: Option<(f64, usize)> = None;
    for (x, &pt) in c.iter().enumerate() {
        let d = pt - c[p];
        let (a, b) = (-d.dot(f), (-d.dot(n)).max(0.0));
        if a.hypot(b) <= tol {
            continue;
        }
        let psi = b.atan2(a);
        if best.is_none_or(|(bp, _)| psi < bp) {
            best = Some((psi, x));
        }
    }
    // The plane through the edge and that centre, facing as the turned one.
    let (psi, x) = best?;
    let turned = psi.cos() * n - psi.sin() * f;
    let m = (c[q] - c[p]).cross(c[x] - c[p]).normalize();
    Some(if m.dot(turned) >= 0.0 { m } else { -m })
}

/// One facet written as the exhaustive search writes it: the first triple of `on` (ascending)
/// that spans a plane with every centre behind it gives the normal; the key orders the facets.
fn canonical(
    c: &[DVec3],
    on: &[usize],
    tol: f64,
    extent: f64,
) -> Option<((usize, usize, usize, u8), Facet)> {
    for (a, &i) in on.iter().enumerate() {
        for (b, &j) in on.iter().enumerate().skip(a + 1) {
            for &k in &on[b + 1..] {
                let Some(m) = triple_normal(c, [i, j, k], tol) else {
                    continue;
                };
                for (s, nrm) in [m, -m].into_iter().enumerate() {
                    if supports(c, i, nrm, tol) {
                        let (_, corners) = on_plane(c, i, nrm, tol, extent);
                        return Some((
                            (i, j, k, s as u8),
                            Facet {
                                normal: nrm,
                                corners,
                            },
                        ));
                    }
                }
            }
        }
    }
    None
}

/// The facets of the hull of `c`, which must span space (not all within `tol` of one plane),
/// in the exhaustive search's order; None where the wrap does not close.
pub(super) fn facets(c: &[DVec3], tol: f64, extent: f64) -> Option<Vec<Facet>> {
    let n = c.len();
    // A first supporting plane: vertical through the lowest centre in x (then y, z) and the
    // next corner of the hull of the centres seen from above, turned about that line.
    let lex = |p: DVec3| p.to_array();
    let a = (0..n).min_by(|&i, &j| {
        let (p, q) = (lex(c[i]), lex(c[j]));
        p[0].total_cmp(&q[0])
            .then(p[1].total_cmp(&q[1]))
            .then(p[2].total_cmp(&q[2]))
    })?;
    let flat = |i: usize| (c[i] - c[a]).truncate();
    let mut b = (0..n).find(|&i| flat(i).length() > tol)?;
    for i in 0..n {
        let (d, q) = (flat(b), flat(i));
        if q.length() <= tol {
            continue; // straight above or below `a`
        }
        let cross = d.perp_dot(q);
        if cross < 0.0 || (cross == 0.0 && q.length() > d.length()) {
            b = i;
        }
    }
    let d = flat(b).normalize();
    let n0 = DVec3::new(d.y, -d.x, 0.0);
    let e0 = (c[b] - c[a]).normalize();
    let first = turn(c, a, b, n0, n0.cross(e0), tol)?;
    // Facets found so far: (normal, centres on it, corners), keyed by the centres on it.
    let mut found: Vec<(DVec3, Vec<usize>, Vec<usize>)> = Vec::new();
    let mut index: HashMap<Vec<usize>, usize> = HashMap::new();
    let (on, corners) = on_plane(c, a, first, tol, extent);
    index.insert(on.clone(), 0);
    found.push((first, on, corners));
    let mut owner: HashMap<(usize, usize), usize> = HashMap::new();
    let mut next = 0;
    while next < found.len() {
        if found.len() > 2 * n + 8 {
            return None;
        }
        let (nrm, corners) = (found[next].0, found[next].2.clone());
        let m = corners.len();
        for k in 0..m {
            let (p, q) = (corners[k], corners[(k + 1) % m]);
            if owner.insert((p, q), next).is_some() {
                return None;
            }
            if owner.contains_key(&(q, p)) {
                continue;
            }
            let e = (c[q] - c[p]).normalize();
            let turned = turn(c, p, q, nrm, nrm.cross(e), tol)?;
            let (on, corners) = on_plane(c, p, turned, tol, extent);
            if !index.contains_key(&on) {
                index.insert(on.clone(), found.len());
                found.push((turned, on, corners));
            }
        }
        next += 1;
    }
    // Closed: every edge is in two facets, once each way.
    if owner.keys().any(|&(p, q)| !owner.contains_key(&(q, p))) {
        return None;
    }
    let mut out: Vec<((usize, usize, usize, u8), Facet)> = found
        .iter()
        .map(|(_, on, _)| canonical(c, on, tol, extent))
        .collect::<Option<_>>()?;
    out.sort_by_key(|f| f.0);
    Some(out.into_iter().map(|f| f.1).collect())
}
