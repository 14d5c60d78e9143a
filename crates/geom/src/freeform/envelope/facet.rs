//! Hull facets of the primitives' centres and the plane helpers both ways of finding them
//! share — the search over every triple (`hull.rs`) and gift wrapping (`wrap.rs`):
//! docs/algorithms/envelope.md, "Three or more primitives".

use glam::DVec3;

/// A hull facet: its outward unit normal and its corners, counter-clockwise about it.
#[derive(Debug, Clone, PartialEq)]
pub struct Facet {
    pub normal: DVec3,
    pub corners: Vec<usize>,
}

/// Strict 2D convex hull (no point on an edge between corners), counter-clockwise, by
/// Andrew's monotone chain; `pts` are (x, y, index).
pub fn hull_2d(pts: &[(f64, f64, usize)], tol: f64) -> Vec<usize> {
    // `+ 0.0` turns −0 into +0, which `total_cmp` would order apart: a centre on an edge
    // between two others then sorted out of its column and stayed a corner.
    let mut p: Vec<(f64, f64, usize)> =
        pts.iter().map(|&(x, y, i)| (x + 0.0, y + 0.0, i)).collect();
    p.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    let cross = |o: &(f64, f64, usize), a: &(f64, f64, usize), b: &(f64, f64, usize)| {
        (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
    };
    let chain = |iter: &mut dyn Iterator<Item = &(f64, f64, usize)>| {
        let mut h: Vec<(f64, f64, usize)> = Vec::new();
        for q in iter {
            while h.len() >= 2 && cross(&h[h.len() - 2], &h[h.len() - 1], q) <= tol {
                h.pop();
            }
            h.push(*q);
        }
        h.pop();
        h
    };
    let mut lower = chain(&mut p.iter());
    let upper = chain(&mut p.iter().rev());
    lower.extend(upper);
    lower.into_iter().map(|q| q.2).collect()
}

/// Two unit vectors spanning the plane normal to unit `n`.
pub fn plane_frame(n: DVec3) -> (DVec3, DVec3) {
    let a = if n.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let x = n.cross(a).normalize();
    (x, n.cross(x))
}

/// The centres within `tol` of the plane through `c[i]` with normal `nrm`, ascending, and
/// their strict corners counter-clockwise about `nrm`.
pub fn on_plane(
    c: &[DVec3],
    i: usize,
    nrm: DVec3,
    tol: f64,
    extent: f64,
) -> (Vec<usize>, Vec<usize>) {
    let on: Vec<usize> = (0..c.len())
        .filter(|&q| (c[q] - c[i]).dot(nrm).abs() <= tol)
        .collect();
    let (x, y) = plane_frame(nrm);
    let pts: Vec<(f64, f64, usize)> = on
        .iter()
        .map(|&q| ((c[q] - c[i]).dot(x), (c[q] - c[i]).dot(y), q))
        .collect();
    let corners = hull_2d(&pts, tol * extent);
    (on, corners)
}

/// The unit normal of the plane through centres `i`, `j`, `k` (the order fixes its sign), or
/// None where the three lie within `tol` of a line. The search and the wrap's canonical form
/// ([`super::wrap`]) both take facet normals from here, so they agree bit for bit.
pub fn triple_normal(c: &[DVec3], [i, j, k]: [usize; 3], tol: f64) -> Option<DVec3> {
    let m = (c[j] - c[i]).cross(c[k] - c[i]);
    (m.length() > tol * (c[j] - c[i]).length().max((c[k] - c[i]).length())).then(|| m.normalize())
}

/// Whether the plane through `c[i]` with unit normal `nrm` has every centre behind it.
pub fn supports(c: &[DVec3], i: usize, nrm: DVec3, tol: f64) -> bool {
    c.iter().all(|&q| (q - c[i]).dot(nrm) <= tol)
}
