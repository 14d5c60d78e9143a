//! The child's points of one primal level: face points, edge points and vertex points, each
//! by the rule its sharpness selects (smooth, dart, crease, corner, or the blend of the
//! parent's and the child's rule where a semi-sharp feature runs out), written to the
//! indices of the split's [`PrimalNumbering`]. The masks are in [`crate::rules::primal`].

// Vertices, edges and corners are indices into parallel arrays here.
#![allow(clippy::needless_range_loop)]

use super::PrimalScheme;
use super::sharpness::{ChildSharpness, Sharpness, child_sharpness_around};
use crate::mesh::PolyMesh;
use crate::refine::PrimalNumbering;
use crate::rules::primal::crease::{self, Rule, is_sharp, vertex_rule};
use crate::rules::primal::{catmark, r#loop};
use crate::tags::SubdivTags;
use crate::topology::{CornerLoops, NONE, Topology, with_loops};
use glam::DVec3;
use rayon::prelude::*;
use std::mem::MaybeUninit;

/// Meshes with at least this many faces are refined on rayon's thread pool (when it has
/// more than one thread).
pub const PARALLEL_FACES: usize = 50_000;

/// Points a task of rayon's pool computes at least.
const MIN_BLOCK: usize = 4096;

/// Writes `f(i)` into slot i of `slots`, on rayon's pool when `parallel`. Each point is
/// written once where it belongs, with no zeroed buffer filled in first: zeroing the ~100 MB
/// of a 1M-quad level's points took one thread longer than computing them on two.
#[inline(always)]
fn fill<T: Send>(
    slots: &mut [MaybeUninit<T>],
    parallel: bool,
    f: impl Fn(usize) -> T + Sync + Send,
) {
    if parallel {
        slots
            .par_chunks_mut(MIN_BLOCK)
            .enumerate()
            .for_each(|(k, chunk)| {
                for (i, s) in chunk.iter_mut().enumerate() {
                    s.write(f(k * MIN_BLOCK + i));
                }
            });
    } else {
        for (i, s) in slots.iter_mut().enumerate() {
            s.write(f(i));
        }
    }
}

/// What the point rules read of one level.
pub(crate) struct Level<'a> {
    pub mesh: &'a PolyMesh,
    pub topo: &'a Topology,
    pub tags: &'a SubdivTags,
    pub sh: &'a Sharpness,
    pub child: &'a ChildSharpness<'a>,
    /// The corner each vertex's ring starts at.
    pub ring_start: &'a (dyn Fn(usize) -> u32 + Sync),
}

/// Every child point of `lv` under `scheme`, at the indices of `n`.
pub(crate) fn child_points(lv: &Level, scheme: PrimalScheme, n: PrimalNumbering) -> Vec<DVec3> {
    with_loops!(lv.topo.loops(), l => child_points_in(lv, scheme, n, l))
}

/// [`child_points`], compiled for one kind of loops.
fn child_points_in<L: CornerLoops>(
    lv: &Level,
    scheme: PrimalScheme,
    n: PrimalNumbering,
    l: L,
) -> Vec<DVec3> {
    let (mesh, topo, sh) = (lv.mesh, lv.topo, lv.sh);
    let nv = mesh.num_vertices();
    let nf = mesh.num_faces();
    let p = &mesh.positions;
    let cv = &mesh.corner_verts;
    let cc = scheme.family() == PrimalScheme::CatmullClark;
    let parallel = nf >= PARALLEL_FACES && rayon::current_num_threads() > 1;

    // Face points, first, in their places at the end of the child's points: the edge and
    // vertex points read them.
    let ne = n.edges as usize;
    let total = n.len();
    debug_assert_eq!(n.edge_point(0) as usize, nv);
    debug_assert_eq!(total, nv + ne + n.face_points as usize);
    let mut out: Vec<DVec3> = Vec::with_capacity(total);
    let (head, tail) = out.spare_capacity_mut()[..total].split_at_mut(nv + ne);
    let face_point = |f: usize| {
        let r = l.face_corners(mesh, f);
        let k = r.len();
        catmark::face_point(cv[r].iter().map(|&v| p[v as usize]).sum(), k)
    };
    fill(tail, parallel, face_point);
    // SAFETY: `fill` wrote every slot of `tail`.
    let face_pts: &[DVec3] = unsafe { &*(tail as *const [MaybeUninit<DVec3>] as *const [DVec3]) };
    let face_size = |f: u32| l.face_corners(mesh, f as usize).len();

    // Edge points.
    let edge_point = |e: usize| {
        let c = topo.edge_corner[e] as usize;
        let t = topo.twin[c];
        let (a, b) = (cv[c] as usize, cv[l.next(c) as usize] as usize);
        let s = sh.edge(e);
        let crease_pt = 0.5 * (p[a] + p[b]);
        if t == NONE {
            return crease_pt;
        }
        let t = t as usize;
        let (f0, f1) = (l.face(c), l.face(t));
        // Smooth mask as vertex weight, face weight and the two face terms.
        let (vw, fw, fsum) = if cc {
            let (vw, fw) =
                catmark::edge_weights(lv.tags.triangles, || (face_size(f0), face_size(f1)));
            (vw, fw, face_pts[f0 as usize] + face_pts[f1 as usize])
        } else {
            let o0 = cv[l.prev(c) as usize] as usize;
            let o1 = cv[l.prev(t) as usize] as usize;
            let (vw, fw) = r#loop::EDGE_WEIGHTS;
            (vw, fw, p[o0] + p[o1])
        };
        if !is_sharp(s) {
            return vw * (p[a] + p[b]) + fw * fsum;
        }
        // The child vertex's rule decides (as OpenSubdiv's refiner passes it): a crease
        // when both child edges stay sharp, else the blend with the parent's sharpness as
        // the weight.
        if is_sharp(lv.child.edge(e, a)) && is_sharp(lv.child.edge(e, b)) {
            crease_pt
        } else {
            let pw = s as f64;
            let cw = 1.0 - pw;
            (pw * 0.5 + cw * vw) * (p[a] + p[b]) + cw * fw * fsum
        }
    };

    // Vertex points. A smooth vertex (always interior: boundary vertices are creases or
    // corners) needs the sums of its neighbours and of its face points, gathered around its
    // ring from its ring start, on one thread as on several (the order of the sums fixes the
    // last bits).
    let smooth_point = |v: usize| -> DVec3 {
        let start = topo.vert_corner[v];
        let (mut esum, mut fsum, mut k) = (DVec3::ZERO, DVec3::ZERO, 0usize);
        let mut c = start;
        loop {
            esum += p[cv[l.next(c as usize) as usize] as usize];
            if cc {
                fsum += face_pts[l.face(c as usize) as usize];
            }
            k += 1;
            c = topo.twin[l.prev(c as usize) as usize];
            if c == start || c == NONE {
                break;
            }
        }
        if cc {
            catmark::vertex_point(p[v], esum, fsum, k)
        } else {
            let (vw, ew) = r#loop::vertex_weights(k);
            vw * p[v] + ew * esum
        }
    };
    let vertex_point = |v: usize| {
        if topo.vert_corner[v] == NONE {
            return p[v];
        }
        let p_rule = vertex_rule(sh.vert(v), sh.sharp_edges(v));
        if matches!(p_rule, Rule::Smooth | Rule::Dart) {
            return smooth_point(v);
        }
        sharp_vertex_point(lv, v, p_rule, scheme.circle_creases(), &smooth_point)
    };

    // The child's points in the numbering's order: vertices, edges, then the face points
    // already in place.
    let (vert_slots, edge_slots) = head.split_at_mut(nv);
    if parallel {
        rayon::join(
            || fill(vert_slots, true, vertex_point),
            || fill(edge_slots, true, edge_point),
        );
    } else {
        fill(vert_slots, false, vertex_point);
        fill(edge_slots, false, edge_point);
    }
    // SAFETY: every one of the first `total` slots was written above (vertices, edges,
    // faces).
    unsafe { out.set_len(total) };
    out
}

/// The point of a crease or corner vertex, blended with its child's rule where a
/// semi-sharp feature runs out.
fn sharp_vertex_point(
    lv: &Level,
    v: usize,
    p_rule: Rule,
    circle: bool,
    smooth_point: &dyn Fn(usize) -> DVec3,
) -> DVec3 {
    let (mesh, sh) = (lv.mesh, lv.sh);
    let method = lv.tags.crease_method;
    let p = &mesh.positions;
    let (mut ring_e, mut ring_c) = (Vec::new(), Vec::new());
    lv.topo
        .vertex_ring_from(mesh, (lv.ring_start)(v), &mut ring_e, &mut ring_c);
    let ps: Vec<f32> = ring_e.iter().map(|&(e, _)| sh.edge(e as usize)).collect();
    let rule_point = |rule: Rule, sharp: &[f32]| -> DVec3 {
        match rule {
            Rule::Smooth | Rule::Dart => smooth_point(v),
            Rule::Crease => {
                let [i, j] = crease::crease_ends(sharp);
                let (a, b) = (p[ring_e[i].1 as usize], p[ring_e[j].1 as usize]);
                crease::crease_point(p[v], a, b, circle)
            }
            Rule::Corner => p[v],
        }
    };
    let parent_pt = rule_point(p_rule, &ps);
    if !sh.semi(v) {
        return parent_pt;
    }
    let mut cs = Vec::new();
    child_sharpness_around(method, &ps, &mut cs);
    let c_vert = crease::decrement(sh.vert(v));
    let c_rule = vertex_rule(c_vert, cs.iter().filter(|&&s| is_sharp(s)).count());
    if c_rule == p_rule {
        return parent_pt;
    }
    let child_pt = rule_point(c_rule, &cs);
    let pw = crease::fractional_weight(method, sh.vert(v), c_vert, &ps, &cs) as f64;
    pw * parent_pt + (1.0 - pw) * child_pt
}
