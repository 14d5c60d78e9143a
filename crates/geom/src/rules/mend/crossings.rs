//! Crossings a rounding step looks for beside what it did, without searching its whole level
//! (docs/algorithms/cylindrical.md, "Crossings that seed the small chamfers"). The new faces of
//! some parent faces and vertices are tried against the new faces of the parent faces, edges
//! and vertices round them (by the split's provenance and numbering, with the renderer's
//! triangles and Möller's test as in `--check-crossings`, over that neighbourhood only); the
//! faces of any crossing pair seed the small chamfers ([`super::small_chamfers`]) as flipped
//! faces do. After a clamped minimum-type or chamfer step, new faces that cross themselves
//! seed them too ([`self_crossing_faces`], "Crossings that seed the small chamfers": one pass over the new faces, two
//! triple products a quad).

use crate::mesh::PolyMesh;
use crate::refine::{FaceKind, Provenance};
use crate::topology::Topology;
use glam::DVec3;

/// The parent faces the combination rule's guard moved: those it `unfolded` and the two
/// beside each edge whose cut width it `capped`, ascending.
pub(super) fn guarded_faces(topo: &Topology, unfolded: &[u32], capped: &[u32]) -> Vec<u32> {
    let mut faces: Vec<u32> = unfolded.to_vec();
    for &e in capped {
        faces.extend(topo.edge_faces(e as usize));
    }
    faces.sort_unstable();
    faces.dedup();
    faces
}

/// The new faces round the parent faces the guard moved (`guarded`: the fold guard's
/// unfolded faces and those beside an edge it cut narrower; [`guarded_faces`]) that pass
/// through a face near them: the new faces of a moved face, its edges and its vertices, tried
/// against the new faces of the parent faces, edges and vertices within one ring of a moved
/// vertex.
pub(super) fn guard_crossings(
    parent: &PolyMesh,
    topo: &Topology,
    child: &PolyMesh,
    prov: &Provenance,
    guarded: &[u32],
) -> Vec<u32> {
    let mut moved = vec![false; parent.num_faces()];
    let mut moved_vertex = vec![false; parent.num_vertices()];
    for &f in guarded {
        moved[f as usize] = true;
        for c in parent.face_corners(f as usize) {
            moved_vertex[parent.corner_verts[c] as usize] = true;
        }
    }
    // The faces round moved vertices (one ring), then their vertices.
    let mut near = moved.clone();
    for c in 0..topo.num_corners() {
        if moved_vertex[parent.corner_verts[c] as usize] {
            near[topo.corner_face(c) as usize] = true;
        }
    }
    let mut near_vertex = vec![false; parent.num_vertices()];
    for c in 0..topo.num_corners() {
        if near[topo.corner_face(c) as usize] {
            near_vertex[parent.corner_verts[c] as usize] = true;
        }
    }
    let (mut touched, mut among) = (Vec::new(), Vec::new());
    for f in 0..child.num_faces() {
        let p = prov.face_parent[f] as usize;
        let (is_touched, is_near) = match prov.face_kind[f] {
            FaceKind::Face => (moved[p], near[p]),
            FaceKind::Edge => {
                let [a, b] = topo.edge_faces(p).map(|f| f as usize);
                (moved[a] || moved[b], near[a] || near[b])
            }
            FaceKind::Vertex => (moved_vertex[p], near_vertex[p]),
        };
        if is_touched {
            touched.push(f as u32);
        }
        if is_near {
            among.push(f as u32);
        }
    }
    crate::analysis::crossing_faces(&crate::analysis::crossings_of(
        child,
        &touched,
        Some(&among),
    ))
}

/// The parent vertices with a concave edge: one whose signed bend angle
/// ([`crate::geometry::signed_bend_angles`]) is below −1e-9.
fn concave_vertices(parent: &PolyMesh, topo: &Topology, normals: &[DVec3]) -> Vec<bool> {
    let mut concave = vec![false; parent.num_vertices()];
    let bends = crate::geometry::signed_bend_angles(parent, topo, normals);
    for (e, &psi) in bends.iter().enumerate() {
        if psi < -1e-9 {
            let (a, b) = topo.edge_verts(parent, e);
            concave[a as usize] = true;
            concave[b as usize] = true;
        }
    }
    concave
}

/// The VERTEX-faces at parent vertices with a concave edge that pass through a new face round
/// them — of a parent face at the vertex, an edge of such a face or a vertex of one — with
/// those faces (where the faces round a vertex turn toward each other, its corner points'
/// polygon is not held on the solid's side of its neighbours as at a convex vertex). Each
/// such vertex is tried on its own, without a search: the split writes FACE-faces, then
/// EDGE-faces, then VERTEX-faces, each in its parent's order — a VERTEX-face for each vertex
/// that a face uses, so a vertex's is found by the provenance, not by its number (a vertex no
/// face uses has none, and those after it are numbered one lower).
pub(super) fn concave_vertex_crossings(
    parent: &PolyMesh,
    topo: &Topology,
    normals: &[DVec3],
    child: &PolyMesh,
    prov: &Provenance,
) -> Vec<u32> {
    use rayon::prelude::*;
    let concave = concave_vertices(parent, topo, normals);
    let (nf, ne) = (parent.num_faces(), topo.num_edges());
    let mut vertex_face = vec![u32::MAX; parent.num_vertices()];
    for f in nf + ne..child.num_faces() {
        if prov.face_kind[f] == FaceKind::Vertex {
            vertex_face[prov.face_parent[f] as usize] = f as u32;
        }
    }
    let mut out: Vec<u32> = (0..parent.num_vertices())
        .into_par_iter()
        .with_min_len(1 << 10)
        .filter(|&v| concave[v] && vertex_face[v] != u32::MAX)
        .flat_map_iter(|v| {
            let vf = vertex_face[v];
            let mut ring = Vec::new();
            for c in topo.corners_around(v) {
                let f = topo.corner_face(c as usize) as usize;
                ring.push(f as u32);
                for k in parent.face_corners(f) {
                    ring.push((nf + topo.corner_edge[k] as usize) as u32);
                    ring.push(vertex_face[parent.corner_verts[k] as usize]);
                }
            }
            ring.sort_unstable();
            ring.dedup();
            let crossed = crate::analysis::crossed_by(child, vf, &ring);
            let found = !crossed.is_empty();
            crossed.into_iter().chain(found.then_some(vf))
        })
        .collect();
    out.sort_unstable();
    out.dedup();
    out
}

/// The new faces whose outline crosses itself seen along their own Newell normal (a bow-tie:
/// [`crate::geometry::points_cross_themselves`]). The minimum type's capped displacements can
/// swap a VERTEX-face's points round a warped vertex, and such a face keeps a normal that
/// agrees with its parent's, so the flip test does not see it; the roundings after it turn
/// its children over.
pub(super) fn self_crossing_faces(child: &PolyMesh) -> Vec<u32> {
    use rayon::prelude::*;
    (0..child.num_faces())
        .into_par_iter()
        .with_min_len(1 << 12)
        .filter(|&f| {
            // A face with a hole (a FACE-face of a holed face) is not one outline.
            if child.face_has_holes(f) {
                return false;
            }
            let at = |c: usize| child.positions[child.corner_verts[c] as usize];
            let n = crate::geometry::face_normal_raw(child, f);
            let corners = child.face_corners(f);
            if corners.len() == 4 {
                let c = corners.start;
                // Every face of a dual split is a quad but a VERTEX-face of another valence.
                crate::geometry::quad_crosses_itself([at(c), at(c + 1), at(c + 2), at(c + 3)], n)
            } else {
                let pts: Vec<DVec3> = corners.map(at).collect();
                crate::geometry::points_cross_themselves(&pts, n)
            }
        })
        .map(|f| f as u32)
        .collect()
}
