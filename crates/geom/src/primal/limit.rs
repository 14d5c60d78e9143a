//! Limit positions and normals of the vertices of a level (seed 001 eq. 5–7 for Loop;
//! Halstead, Kass & DeRose 1993 for Catmull–Clark), as OpenSubdiv's `Sdc` limit masks give
//! them, so that they equal `PrimvarRefiner::Limit`.
//!
//! Each vertex gets a position mask and two tangent masks over itself, the far ends of its
//! edges (`e_i`, ring order) and — Catmull–Clark only — the vertex diagonally opposite in
//! each face (`d_i`, the face between edges i and i + 1). The normal is `t₁ × t₂`, unit.
//!
//! Position masks:
//! - corner (and a Catmull–Clark valence-2 vertex): the vertex itself;
//! - crease or boundary: `⅔ v + ⅙ (e_a + e_b)` along the two crease edges;
//! - smooth Catmull–Clark, valence n: `(n² v + 4 Σ e_i + Σ d_i) / (n (n + 5))` (quads only:
//!   a level with another polygon is refused, its limit is that of the level after it);
//! - smooth Loop: `e_w = 1/(n + 3/(8β))` per neighbour, `1 − n e_w` for the vertex.
//!
//! Tangents: smooth vertices use the cosine masks (`t₁ = Σ cos(iθ)·…`, `t₂` the same rotated
//! one step); a crease uses `t₁ = ½(e_a − e_b)` along it and a cross tangent over the
//! faces from `e_a` counter-clockwise to `e_b` (Biermann et al. 2000 for irregular
//! valence). So **across a crease the normal is one-sided: it is the normal of the side
//! swept counter-clockwise (seen from outside) from the first crease edge to the second in
//! the vertex's ring**, which starts at the vertex's first outgoing half-edge — at a
//! boundary vertex, the boundary edge with the faces on its left, so the one side there is.
//! A corner uses the edges before and after its first face. A vertex with no faces, with
//! a tangent that vanishes to rounding (|t| ≤ 1e-10 of its longest edge: coincident
//! neighbours, e.g. two faces back to back) or with parallel tangents gets a zero normal.

use super::sharpness::sharpness;
use super::{PrimalError, PrimalScheme, RingOrder};
use crate::edge_attrs::EdgeAttrs;
use crate::mesh::PolyMesh;
use crate::rules::primal::crease::{Rule, crease_ends, vertex_rule};
use crate::tags::SubdivTags;
use crate::topology::Topology;
use glam::DVec3;
use std::f64::consts::PI;

/// Limit positions and unit limit normals, one per vertex.
#[derive(Debug, Clone, PartialEq)]
pub struct LimitPoints {
    pub positions: Vec<DVec3>,
    pub normals: Vec<DVec3>,
}

/// Limit position and unit normal of every vertex of `mesh` under `scheme`, rings in their
/// natural order (the mesh is an input).
pub fn limit_points(
    mesh: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    scheme: PrimalScheme,
) -> Result<LimitPoints, PrimalError> {
    limit_points_ordered(mesh, attrs, tags, scheme, None)
}

/// As [`limit_points`] for a refined level whose ring order
/// [`super::refine_primal_ordered`] passed on.
pub fn limit_points_ordered(
    mesh: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    scheme: PrimalScheme,
    order: Option<&RingOrder>,
) -> Result<LimitPoints, PrimalError> {
    if scheme.circle_creases() {
        return Err(PrimalError::NoLimitMasks {
            scheme: scheme.name(),
        });
    }
    let topo = Topology::build(mesh)?;
    topo.require_single_fans(mesh)?;
    super::check_faces(mesh, scheme)?;
    // The masks' diagonal vertex d_i is the quad's fourth corner: an n-gon has none (its
    // limit comes from the level after it, where every face is a quad).
    if scheme == PrimalScheme::CatmullClark
        && let Some(f) = (0..mesh.num_faces()).find(|&f| mesh.face_corners(f).len() != 4)
    {
        return Err(PrimalError::NotQuad {
            face: f as u32,
            corners: mesh.face_corners(f).len(),
        });
    }
    let sh = sharpness(mesh, &topo, attrs, tags);
    let p = &mesh.positions;
    let cv = &mesh.corner_verts;
    let nv = mesh.num_vertices();
    let mut positions = Vec::with_capacity(nv);
    let mut normals = Vec::with_capacity(nv);
    let mut ring_e = Vec::new();
    let mut ring_c = Vec::new();
    let mut e_pts: Vec<DVec3> = Vec::new();
    let mut d_pts: Vec<DVec3> = Vec::new();
    let mut es = Vec::new();
    for v in 0..nv {
        let start = order.map_or(topo.vert_corner[v], |o| o.ring_start[v]);
        topo.vertex_ring_from(mesh, start, &mut ring_e, &mut ring_c);
        let pv = p[v];
        if ring_c.is_empty() {
            positions.push(pv);
            normals.push(DVec3::ZERO);
            continue;
        }
        e_pts.clear();
        e_pts.extend(ring_e.iter().map(|&(_, o)| p[o as usize]));
        d_pts.clear();
        d_pts.extend(ring_c.iter().map(|&c| {
            let n2 = topo.next(topo.next(c as usize) as usize);
            p[cv[n2 as usize] as usize]
        }));
        es.clear();
        es.extend(ring_e.iter().map(|&(e, _)| sh.edge(e as usize)));
        let n_faces = ring_c.len();
        let rule = vertex_rule(sh.vert(v), sh.sharp_edges(v));
        let cc = scheme.family() == PrimalScheme::CatmullClark;
        let (pos, t1, t2) = match rule {
            Rule::Smooth | Rule::Dart if cc && n_faces == 2 => corner(pv, &e_pts, 1.0),
            Rule::Smooth | Rule::Dart => {
                if cc {
                    catmark_smooth(pv, &e_pts, &d_pts)
                } else {
                    loop_smooth(pv, &e_pts)
                }
            }
            Rule::Crease => {
                let ends = crease_ends(&es);
                let pos = (2.0 / 3.0) * pv + (1.0 / 6.0) * (e_pts[ends[0]] + e_pts[ends[1]]);
                let (t1, t2) = if cc {
                    catmark_crease_tangents(pv, &e_pts, &d_pts, ends)
                } else {
                    loop_crease_tangents(pv, &e_pts, ends)
                };
                (pos, t1, t2)
            }
            Rule::Corner => corner(pv, &e_pts, if cc { 1.0 } else { 3.0 }),
        };
        positions.push(pos);
        // Tangents parallel to rounding (degenerate geometry such as two faces back to
        // back) give no normal, as in OpenSubdiv, rather than one picked by rounding noise.
        let scale = e_pts.iter().map(|&e| (e - pv).length()).fold(0.0, f64::max);
        let n = t1.cross(t2);
        let defined = t1.length() > 1e-10 * scale
            && t2.length() > 1e-10 * scale
            && n.length() > 1e-12 * t1.length() * t2.length();
        normals.push(if defined { n.normalize() } else { DVec3::ZERO });
    }
    Ok(LimitPoints { positions, normals })
}

/// Corner: the vertex itself; tangents along the first two edges.
fn corner(v: DVec3, e: &[DVec3], scale: f64) -> (DVec3, DVec3, DVec3) {
    (v, scale * (e[0] - v), scale * (e[1] - v))
}

fn catmark_smooth(v: DVec3, e: &[DVec3], d: &[DVec3]) -> (DVec3, DVec3, DVec3) {
    let n = e.len();
    let nf = n as f64;
    let (fw, ew, vw) = if n == 4 {
        (1.0 / 36.0, 1.0 / 9.0, 4.0 / 9.0)
    } else {
        let fw = 1.0 / (nf * (nf + 5.0));
        (fw, 4.0 * fw, 1.0 - nf * 5.0 * fw)
    };
    let pos = vw * v + ew * e.iter().sum::<DVec3>() + fw * d.iter().sum::<DVec3>();
    // t₁ weights; t₂ is t₁ turned by one step.
    let (ew1, fw1): (Vec<f64>, Vec<f64>) = if n == 4 {
        (vec![4.0, 0.0, -4.0, 0.0], vec![1.0, -1.0, -1.0, 1.0])
    } else {
        let theta = 2.0 * PI / nf;
        let (c, ch) = (theta.cos(), (0.5 * theta).cos());
        let lambda = 5.0 / 16.0 + (c + ch * (2.0 * (9.0 + c)).sqrt()) / 16.0;
        let fs = 1.0 / (4.0 * lambda - 1.0);
        (0..n)
            .map(|i| {
                let (ci, ci1) = ((i as f64 * theta).cos(), ((i + 1) as f64 * theta).cos());
                (4.0 * ci, fs * (ci + ci1))
            })
            .unzip()
    };
    let mut t1 = DVec3::ZERO;
    let mut t2 = DVec3::ZERO;
    for i in 0..n {
        let j = (i + n - 1) % n;
        t1 += ew1[i] * e[i] + fw1[i] * d[i];
        t2 += ew1[j] * e[i] + fw1[j] * d[i];
    }
    (pos, t1, t2)
}

fn loop_smooth(v: DVec3, e: &[DVec3]) -> (DVec3, DVec3, DVec3) {
    let n = e.len();
    let nf = n as f64;
    let (vw, ew) = if n == 6 {
        (0.5, 1.0 / 12.0)
    } else {
        // Loop's limit position: `ω = 1/(n + 3/(8β))` per neighbour.
        let ew = 1.0 / (nf + 3.0 / (8.0 * crate::rules::primal::r#loop::beta(n)));
        (1.0 - ew * nf, ew)
    };
    let pos = vw * v + ew * e.iter().sum::<DVec3>();
    let mut t1 = DVec3::ZERO;
    let mut t2 = DVec3::ZERO;
    let alpha = 2.0 * PI / nf;
    for (i, &ei) in e.iter().enumerate() {
        let a = alpha * i as f64;
        t1 += a.cos() * ei;
        t2 += a.sin() * ei;
    }
    (pos, t1, t2)
}

/// Catmull–Clark crease tangents: along the crease, and across the faces from the first
/// crease edge to the second.
fn catmark_crease_tangents(
    v: DVec3,
    e: &[DVec3],
    d: &[DVec3],
    [a, b]: [usize; 2],
) -> (DVec3, DVec3) {
    let t1 = 0.5 * (e[a] - e[b]);
    let interior = b - a - 1;
    let t2 = match interior {
        0 => -6.0 * v + 3.0 * (e[a] + e[b]),
        1 => (-4.0 * v - e[a] + 4.0 * e[a + 1] - e[b] + d[a] + d[a + 1]) / 6.0,
        _ => {
            let k = (interior + 1) as f64;
            let theta = PI / k;
            let (c, s) = (theta.cos(), theta.sin());
            let denom = 1.0 / (k * (3.0 + c));
            let r = (c + 1.0) / s;
            let mut t2 = denom * (4.0 * r * (c - 1.0) * v - r * (1.0 + 2.0 * c) * (e[a] + e[b]));
            t2 += denom * s * d[a];
            for i in 1..interior + 1 {
                let si = (i as f64 * theta).sin();
                let si1 = ((i + 1) as f64 * theta).sin();
                t2 += denom * (4.0 * si * e[a + i] + (si + si1) * d[a + i]);
            }
            t2
        }
    };
    (t1, t2)
}

/// Loop crease tangents (scaled as OpenSubdiv scales them; only directions matter here).
fn loop_crease_tangents(v: DVec3, e: &[DVec3], [a, b]: [usize; 2]) -> (DVec3, DVec3) {
    let t1 = 1.5 * (e[a] - e[b]);
    let interior = b - a - 1;
    let t2 = match interior {
        0 => -6.0 * v + 3.0 * (e[a] + e[b]),
        1 => -3.0 * v + 3.0 * e[a + 1],
        2 => {
            let r3 = 3f64.sqrt();
            -r3 * v - 0.5 * r3 * (e[a] + e[b]) + r3 * (e[a + 1] + e[a + 2])
        }
        _ => {
            let theta = PI / (interior + 1) as f64;
            let cw = -3.0 * theta.sin();
            let ec = -3.0 * (2.0 * theta.cos() - 2.0);
            let mut t2 = cw * (e[a] + e[b]);
            for i in 1..=interior {
                t2 += ec * (i as f64 * theta).sin() * e[a + i];
            }
            t2
        }
    };
    (t1, t2)
}
