//! Which primitives meet which: the convex hull of the primitives' centres (seed 004 §5.1.3,
//! §5.2; docs/algorithms/envelope.md, "Three or more primitives").
//!
//! The paper cuts every primitive A by the plane through its centre normal to the view vector
//! towards every other primitive B and keeps `(x − G_A)·(G_B − G_A) ≤ 0` for all B: the cone
//! `K_A` of directions in which no other centre lies ahead — the **normal cone** of the hull of
//! the centres at G_A. So:
//! - A keeps a part only where G_A is a **vertex** of the hull; a centre inside the hull, or on
//!   a hull edge or facet between its corners, has a cone without interior, and the primitive
//!   is swallowed (§5.1.3: "automatically removed"). A swallowed centre is a convex combination
//!   of the others, so its cuts are implied by theirs and the others do not change.
//! - Only the cuts towards A's **hull neighbours** bound `K_A`; the others touch it along a ray
//!   at most (a diagonal of a square of centres), so they are left out.
//! - A's section facing B has area exactly when A–B is a **hull edge**; it is a pie slice
//!   between the rays of the two facets beside that edge, and B's section facing A spans the
//!   same rays (the third primitive's cut lines project to one line: `d_AB × (G_C − G_A)` ∥
//!   `d_AB × (G_C − G_B)`), so the sections pair up across the fusion strip.
//! - Each **facet** of the hull is a lid: the region bounded by the fusion edges at its ray.
//!
//! Collinear centres give the two ends and no facet (the two-primitive case: whole silhouette
//! loops); coplanar centres give the polygon with two facets, `+n` and `−n`.

pub use super::facet::Facet;
use super::facet::{hull_2d, on_plane, plane_frame, supports, triple_normal};
use crate::geometry::segment_distance;
use glam::DVec3;

/// A hull edge between primitives `a < b`, with the facets on either side (none when the
/// centres are collinear: then the sections are whole loops).
#[derive(Debug, Clone, PartialEq)]
pub struct HullEdge {
    pub a: usize,
    pub b: usize,
    pub facets: Option<[usize; 2]>,
    /// A direction normal to `G_B − G_A` inside the edge's normal cone (outwards).
    pub outward: DVec3,
}

/// The layout of a scene's primitives.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Layout {
    /// Primitives whose centre is a hull vertex, ascending.
    pub kept: Vec<usize>,
    /// Swallowed primitives, ascending.
    pub removed: Vec<usize>,
    pub edges: Vec<HullEdge>,
    pub facets: Vec<Facet>,
}

impl Layout {
    /// The centres that share a facet or an edge with `a`, ascending, `a` left out. The hull
    /// of the others is the hull of these where it is nearest to `a`: the facets that replace
    /// `a`'s when it is left out are the only ones it sees, and their corners are all among
    /// these (every other centre stays a corner), so `a`'s distance to the hull of the rest is
    /// its distance to the hull of these — a few centres instead of all of them.
    pub fn around(&self, a: usize) -> Vec<usize> {
        let mut n = self.neighbours(a);
        for f in &self.facets {
            if f.corners.contains(&a) {
                n.extend(f.corners.iter().copied().filter(|&q| q != a));
            }
        }
        n.sort_unstable();
        n.dedup();
        n
    }

    /// The hull neighbours of primitive `a`, ascending.
    pub fn neighbours(&self, a: usize) -> Vec<usize> {
        let mut n: Vec<usize> = self
            .edges
            .iter()
            .filter_map(|e| {
                if e.a == a {
                    Some(e.b)
                } else if e.b == a {
                    Some(e.a)
                } else {
                    None
                }
            })
            .collect();
        n.sort_unstable();
        n
    }
}

/// The layout of primitives with centres `c` (pairwise distinct: checked by the caller).
/// `tol` is the distance below which a centre counts as on a line or plane.
pub fn layout(c: &[DVec3], tol: f64) -> Layout {
    let n = c.len();
    if n < 2 {
        return Layout {
            kept: (0..n).collect(),
            ..Layout::default()
        };
    }
    // Affine dimension: the farthest point from c[0], then from that line, then that plane.
    let far = |f: &dyn Fn(DVec3) -> f64| {
        (0..n)
            .max_by(|&i, &j| f(c[i]).total_cmp(&f(c[j])))
            .expect("points")
    };
    let i1 = far(&|p| p.distance(c[0]));
    let extent = c[i1].distance(c[0]);
    let dir = (c[i1] - c[0]).normalize();
    let off_line = |p: DVec3| (p - c[0]).reject_from_normalized(dir).length();
    let i2 = far(&off_line);
    if off_line(c[i2]) <= tol {
        // Collinear: the two ends.
        let along = |i: usize| (c[i] - c[0]).dot(dir);
        let lo = (0..n)
            .min_by(|&i, &j| along(i).total_cmp(&along(j)))
            .unwrap();
        let hi = (0..n)
            .max_by(|&i, &j| along(i).total_cmp(&along(j)))
            .unwrap();
        let (a, b) = (lo.min(hi), lo.max(hi));
        return finish(
            n,
            vec![HullEdge {
                a,
                b,
                facets: None,
                outward: DVec3::ZERO,
            }],
            Vec::new(),
        );
    }
    let normal = dir.cross(c[i2] - c[0]).normalize();
    let off_plane = |p: DVec3| (p - c[0]).dot(normal).abs();
    let i3 = far(&off_plane);
    if off_plane(c[i3]) <= tol {
        // Coplanar: the polygon, with a facet on each side.
        let (x, y) = plane_frame(normal);
        let pts: Vec<(f64, f64, usize)> = (0..n)
            .map(|i| ((c[i] - c[0]).dot(x), (c[i] - c[0]).dot(y), i))
            .collect();
        let ring = hull_2d(&pts, tol * extent);
        let m = ring.len();
        let edges = (0..m)
            .map(|k| {
                let (p, q) = (ring[k], ring[(k + 1) % m]);
                // Counter-clockwise about `normal`: the outside is on the right of p → q.
                let outward = (c[q] - c[p]).cross(normal).normalize();
                HullEdge {
                    a: p.min(q),
                    b: p.max(q),
                    facets: Some([0, 1]),
                    outward,
                }
            })
            .collect();
        let facets = vec![
            Facet {
                normal,
                corners: ring.clone(),
            },
            Facet {
                normal: -normal,
                corners: ring.into_iter().rev().collect(),
            },
        ];
        return finish(n, edges, facets);
    }
    // Spatial: the facets by gift wrapping, or by trying every triple where the wrap does not
    // close (super::wrap).
    let facets = super::wrap::facets(c, tol, extent).unwrap_or_else(|| exhaustive(c, tol, extent));
    // Edges from the facets' sides; each side is in two facets.
    let mut edges: Vec<HullEdge> = Vec::new();
    for (fi, f) in facets.iter().enumerate() {
        let m = f.corners.len();
        for k in 0..m {
            let (p, q) = (f.corners[k], f.corners[(k + 1) % m]);
            let (a, b) = (p.min(q), p.max(q));
            match edges.iter_mut().find(|e| e.a == a && e.b == b) {
                Some(e) => {
                    let first = e.facets.expect("set")[0];
                    e.facets = Some([first, fi]);
                    e.outward = (facets[first].normal + f.normal).normalize();
                }
                None => edges.push(HullEdge {
                    a,
                    b,
                    facets: Some([fi, fi]),
                    outward: f.normal,
                }),
            }
        }
    }
    finish(n, edges, facets)
}

/// The facets of the hull of `c` (spanning space): every plane through three centres with all
/// the others behind it (within `tol`), merged when two triples span one plane, in the order of
/// their first triples; each facet's corners are the strict 2D hull of the centres on it.
/// O(n⁴): [`super::wrap::facets`] finds the same ones in O(n²) and falls back to this.
pub(super) fn exhaustive(c: &[DVec3], tol: f64, extent: f64) -> Vec<Facet> {
    let n = c.len();
    let mut facets: Vec<Facet> = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                let Some(m) = triple_normal(c, [i, j, k], tol) else {
                    continue;
                };
                for nrm in [m, -m] {
                    if facets.iter().any(|f| {
                        f.normal.dot(nrm) > 1.0 - 1e-12
                            && (c[i] - c[f.corners[0]]).dot(nrm).abs() <= tol
                    }) {
                        continue;
                    }
                    if supports(c, i, nrm, tol) {
                        let (_, corners) = on_plane(c, i, nrm, tol, extent);
                        facets.push(Facet {
                            normal: nrm,
                            corners,
                        });
                    }
                }
            }
        }
    }
    facets
}

fn finish(n: usize, mut edges: Vec<HullEdge>, facets: Vec<Facet>) -> Layout {
    edges.sort_by_key(|e| (e.a, e.b));
    let mut kept: Vec<usize> = edges.iter().flat_map(|e| [e.a, e.b]).collect();
    kept.sort_unstable();
    kept.dedup();
    let removed = (0..n).filter(|i| kept.binary_search(i).is_err()).collect();
    Layout {
        kept,
        removed,
        edges,
        facets,
    }
}

/// The layout of the primitives `active` (indices into `c`), with indices into `c`.
fn layout_of(c: &[DVec3], active: &[usize], tol: f64) -> Layout {
    let sub: Vec<DVec3> = active.iter().map(|&i| c[i]).collect();
    let l = layout(&sub, tol);
    let map = |v: &[usize]| -> Vec<usize> { v.iter().map(|&i| active[i]).collect() };
    Layout {
        kept: map(&l.kept),
        removed: map(&l.removed),
        edges: l
            .edges
            .into_iter()
            .map(|e| {
                let (a, b) = (active[e.a], active[e.b]);
                HullEdge {
                    a: a.min(b),
                    b: a.max(b),
                    ..e
                }
            })
            .collect(),
        facets: l
            .facets
            .into_iter()
            .map(|f| Facet {
                normal: f.normal,
                corners: map(&f.corners),
            })
            .collect(),
    }
}

/// The distance from `p` to the convex hull the layout describes (0 inside).
fn hull_distance(p: DVec3, c: &[DVec3], l: &Layout) -> f64 {
    if l.facets.is_empty() {
        return match l.edges.first() {
            Some(e) => segment_distance(p, c[e.a], c[e.b]),
            None => l.kept.first().map_or(f64::INFINITY, |&k| p.distance(c[k])),
        };
    }
    let side = |f: &Facet| (p - c[f.corners[0]]).dot(f.normal);
    if l.facets.len() > 2 && l.facets.iter().all(|f| side(f) <= 0.0) {
        return 0.0;
    }
    l.facets
        .iter()
        .map(|f| {
            let m = f.corners.len();
            let q = p - side(f) * f.normal;
            let inside = (0..m).all(|k| {
                let (a, b) = (c[f.corners[k]], c[f.corners[(k + 1) % m]]);
                (b - a).cross(q - a).dot(f.normal) >= 0.0
            });
            if inside {
                side(f).abs()
            } else {
                (0..m)
                    .map(|k| segment_distance(p, c[f.corners[k]], c[f.corners[(k + 1) % m]]))
                    .fold(f64::INFINITY, f64::min)
            }
        })
        .fold(f64::INFINITY, f64::min)
}

/// The layout of the primitives `active` (ascending; the others are removed) with centres `c`
/// and sphere radii `r`, where a primitive whose
/// centre lies within `swallow × r` of the hull of the others' centres is swallowed too: its
/// cone would be a sliver (a centre a hair off the line or plane of its neighbours) and its
/// faces and the lids beside it thin strips that no patch split survives (envelope.md). One
/// at a time, the nearest (relative to its r) first, so two close centres do not take each
/// other out.
pub fn layout_swallowing(
    c: &[DVec3],
    r: &[f64],
    mut active: Vec<usize>,
    tol: f64,
    swallow: f64,
) -> Layout {
    loop {
        let l = layout_of(c, &active, tol);
        if l.kept.len() <= 2 {
            return finish_removed(l, c.len());
        }
        let nearest = l
            .kept
            .iter()
            .map(|&i| {
                let d = hull_distance(c[i], c, &layout_of(c, &l.around(i), tol));
                (d / r[i], i)
            })
            .min_by(|a, b| {
                a.0.total_cmp(&b.0).then_with(|| {
                    let (p, q) = (c[a.1].to_array(), c[b.1].to_array());
                    p[0].total_cmp(&q[0])
                        .then(p[1].total_cmp(&q[1]))
                        .then(p[2].total_cmp(&q[2]))
                })
            })
            .expect("kept");
        if nearest.0 >= swallow {
            return finish_removed(l, c.len());
        }
        active = l.kept.iter().copied().filter(|&j| j != nearest.1).collect();
    }
}

/// The layout with every primitive it does not keep listed as removed.
fn finish_removed(mut l: Layout, n: usize) -> Layout {
    l.removed = (0..n)
        .filter(|i| l.kept.binary_search(i).is_err())
        .collect();
    l
}

#[cfg(test)]
mod tests;
