//! The checks of a step's new faces (docs/algorithms/biquadratic.md): a new face is
//! **flipped** when its Newell normal points against its parent element's normal (`n_f`,
//! `n_L + n_R`, or Σ n_f around the vertex) and **degenerate** when its area is within
//! rounding noise, so that which way it faces cannot be told: twice the area below
//! `DEGENERATE_NOISE · P · S` (P the face's perimeter, S the larger of the bounding-box
//! diagonal and the largest coordinate). The step's report and its mending stage
//! ([`crate::rules::mend`]) both judge by them.

use crate::geometry::{face_normal_and_volume6, loop_newell};
use crate::mesh::PolyMesh;
use crate::refine::{self, FaceKind, Provenance};
use crate::topology::Topology;
use glam::DVec3;

/// A face is degenerate when twice its area is below this × its perimeter × the level's
/// scale S (the larger of the bounding-box diagonal and the largest coordinate): a thousand
/// times the rounding error of a Newell normal, whose terms each carry an error of about
/// ε·S·(the edge's length). Below it, which way the face faces cannot be told; above it, a
/// face is sound however small (a round of a nearly flat edge is a face 10⁻⁸ of the solid
/// across, facing the right way).
pub const DEGENERATE_NOISE: f64 = 1e3 * f64::EPSILON;

/// Flipped and degenerate new faces, and the signed volume of the child: one pass over the
/// child's faces.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ChildCheck {
    pub flipped: Vec<u32>,
    pub degenerate: Vec<u32>,
    pub volume: f64,
}

/// Checks every new face against its parent element's normal (docs/algorithms/biquadratic.md) and sums
/// the child's signed volume.
pub fn check_children(
    parent: &PolyMesh,
    topo: &Topology,
    parent_normals: &[DVec3],
    child: &PolyMesh,
    prov: &Provenance,
) -> ChildCheck {
    use rayon::prelude::*;
    let vsum = crate::geometry::vertex_normal_sums(parent, topo, parent_normals);
    let s = scale(child);
    let single_loop = child.num_loops() == child.num_faces();
    let nf = child.num_faces();
    // Blocks of faces on every core, each summing its share of the volume in face order;
    // the blocks' sums are added in block order, so the volume is the same bits on any
    // number of threads.
    let blocks: Vec<ChildCheck> = (0..nf.div_ceil(CHECK_BLOCK))
        .into_par_iter()
        .map(|b| {
            let mut out = ChildCheck::default();
            for f in b * CHECK_BLOCK..((b + 1) * CHECK_BLOCK).min(nf) {
                let (n, fv) = if single_loop {
                    // Hole-free child (the usual case): the loop is the face.
                    let vs = child.loop_verts(f);
                    let n = loop_newell(child, vs);
                    (n, 2.0 * child.positions[vs[0] as usize].dot(n))
                } else {
                    face_normal_and_volume6(child, f)
                };
                out.volume += fv;
                let p = prov.face_parent[f] as usize;
                let np = match prov.face_kind[f] {
                    FaceKind::Face => parent_normals[p],
                    FaceKind::Edge => {
                        let [a, b] = topo.edge_faces(p);
                        parent_normals[a as usize] + parent_normals[b as usize]
                    }
                    FaceKind::Vertex => vsum[p],
                };
                if is_degenerate(child, f, n, s) {
                    out.degenerate.push(f as u32);
                } else if n.dot(np) < 0.0 {
                    out.flipped.push(f as u32);
                }
            }
            out
        })
        .collect();
    let mut out = ChildCheck::default();
    let mut v6 = 0.0;
    for b in blocks {
        out.flipped.extend(b.flipped);
        out.degenerate.extend(b.degenerate);
        v6 += b.volume;
    }
    out.volume = v6 / 6.0;
    out
}

/// The new faces of a Catmull–Clark or Loop step that the step turned over
/// (docs/algorithms/biquadratic.md, "Faces a smoothing step turns over"): a face that faces
/// against its parent face (child quad c of the quad split lies in the face of parent corner
/// c, child triangle 4f + k in triangle f) *and* against the sum of the normals round one of
/// its own vertices — a pleat in the child, not just a thin parent face whose children follow
/// their neighbours (a 0.004-wide strip on OpenSubdiv's car turns 94° from its children, and
/// the surface there is smooth). Neither scheme folds a convex face, but the face point of a
/// concave face (its vertex centroid) can lie outside it, and a vertex point at a reflex
/// corner can move farther than a thin face beside it is wide: the quads there turn over —
/// the scheme as printed, which the step reports rather than mends. Faces of no area
/// ([`is_degenerate`]) are not counted; a child whose face count does not match the split's
/// is not judged (empty).
pub fn primal_flipped(parent: &PolyMesh, child: &PolyMesh, split: refine::PrimalSplit) -> Vec<u32> {
    use rayon::prelude::*;
    let expected = match split {
        refine::PrimalSplit::Quad => parent.num_corners(),
        refine::PrimalSplit::Tri => 4 * parent.num_faces(),
    };
    if child.num_faces() != expected {
        return Vec::new();
    }
    let s = scale(child);
    // Against the parent face, each parent face's children at once (in face order: rayon's
    // collect keeps it); few are, so the child's vertex normal sums are found only when
    // some are.
    let against: Vec<usize> = (0..parent.num_faces())
        .into_par_iter()
        .with_min_len(1024)
        .flat_map_iter(|f| {
            let np = crate::geometry::face_normal_raw(parent, f);
            let children = match split {
                refine::PrimalSplit::Quad => parent.face_corners(f),
                refine::PrimalSplit::Tri => 4 * f..4 * f + 4,
            };
            children.filter(move |&c| {
                let n = crate::geometry::face_normal_raw(child, c);
                n.dot(np) < 0.0 && !is_degenerate(child, c, n, s)
            })
        })
        .collect();
    if against.is_empty() {
        return Vec::new();
    }
    let normals = crate::geometry::face_normals_raw(child);
    let mut vsum = vec![DVec3::ZERO; child.num_vertices()];
    for (f, n) in normals.iter().enumerate() {
        let u = n.normalize_or_zero();
        for c in child.face_corners(f) {
            vsum[child.corner_verts[c] as usize] += u;
        }
    }
    against
        .into_iter()
        .filter(|&f| {
            child
                .face_corners(f)
                .any(|c| normals[f].dot(vsum[child.corner_verts[c] as usize]) < 0.0)
        })
        .map(|f| f as u32)
        .collect()
}

/// The level's scale S of [`DEGENERATE_NOISE`]: the larger of the bounding-box diagonal and
/// the largest coordinate's magnitude.
pub fn scale(mesh: &PolyMesh) -> f64 {
    if mesh.positions.is_empty() {
        return 0.0;
    }
    let (lo, hi) = mesh.bbox();
    (hi - lo).length().max(lo.abs().max(hi.abs()).max_element())
}

/// Whether face `f` of Newell normal `n` (twice its area) is degenerate on a level of
/// [`scale`] `s`: below [`DEGENERATE_NOISE`] × its perimeter × `s`. The perimeter is summed
/// only for faces that could be (it is at most the face's corner count × `s`).
pub fn is_degenerate(mesh: &PolyMesh, f: usize, n: DVec3, s: f64) -> bool {
    let a2 = n.length();
    let tiny = DEGENERATE_NOISE * s;
    if a2 >= tiny * s * mesh.face_corners(f).len() as f64 {
        return false;
    }
    let perimeter = crate::geometry::face_perimeter(mesh, f);
    // A face collapsed to a point (no perimeter either) and a NaN one are degenerate.
    a2.is_nan() || a2 <= tiny * perimeter
}

/// Faces a task of [`check_children`] takes (fixed, so that the volume's sum does not
/// depend on the number of threads).
const CHECK_BLOCK: usize = 1 << 12;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;

    /// Degenerate means "which way it faces cannot be told", not "small": a well-shaped square
    /// 10⁻⁸ of the solid across, far from the origin, is not degenerate; a square 10⁻¹⁵
    /// across, a sliver 10⁻¹⁴ wide, a face collapsed to a point and one with a NaN are.
    #[test]
    fn degenerate_faces_are_those_of_no_area_not_small_ones() {
        let at = DVec3::new(10.0, -5.0, 3.0);
        let square = |side: f64, width: f64| {
            let q = [
                DVec3::ZERO,
                DVec3::new(side, 0.0, 0.0),
                DVec3::new(side, width, 0.0),
                DVec3::new(0.0, width, 0.0),
            ];
            // A unit box beside it sets the scale.
            let mut m = primitives::cuboid(at - DVec3::ONE, at);
            let base = m.num_vertices() as u32;
            m.positions.extend(q.iter().map(|p| at + *p));
            m.push_polygon(&[base, base + 1, base + 2, base + 3]);
            let f = m.num_faces() - 1;
            let n = loop_newell(&m, m.loop_verts(f));
            is_degenerate(&m, f, n, scale(&m))
        };
        assert!(!square(1e-8, 1e-8));
        assert!(!square(1.0, 1e-9));
        assert!(square(1e-15, 1e-15));
        assert!(square(1.0, 1e-14));
        assert!(square(0.0, 0.0));
        assert!(square(f64::NAN, 1.0));
        // A unit face of the box is not.
        let m = primitives::cuboid(DVec3::ZERO, DVec3::ONE);
        assert!(!is_degenerate(
            &m,
            0,
            loop_newell(&m, m.loop_verts(0)),
            scale(&m)
        ));
    }
}
