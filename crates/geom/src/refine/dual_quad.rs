//! The dual quad split of PRISM's biquadratic step, written once for every corner rule
//! (seed 000 §2, fig. 1; docs/algorithms/biquadratic.md).
//!
//! In CGAL's words this is DQQ, dual quad quadrisection: one new point per face corner
//! (inner-loop corners included), then
//! - the **FACE-face** of face f: f's new points in f's loops and order (a holed face
//!   gives a holed FACE-face);
//! - the **EDGE-face** of edge {a, b} with half-edges c (a→b) and t (b→a): the quad
//!   `(next(c), c, next(t), t)`;
//! - the **VERTEX-face** of vertex v: the corners at v in ring order (from corner c go to
//!   the twin of c's previous half-edge).
//!
//! New vertex i is the point of parent corner i ([`Numbering::DualQuad`]). Faces are written FACE-faces first (parent face order), then EDGE-faces
//! (edge order), then VERTEX-faces (vertex order). Counts on a closed input:
//! `V' = 2E, E' = 4E, F' = F + E + V`, and V − E + F is kept.
//!
//! Cost: one pass over corners for each kind of face; no hashing. The memory a step needs
//! is estimated first ([`estimated_bytes`]) so that a caller can refuse a step that would not
//! fit.

use super::{Numbering, Provenance};
use crate::edge_attrs::EdgeKey;
use crate::mesh::PolyMesh;
use crate::topology::{NONE, Topology};
use glam::DVec3;

/// Which of the three kinds a new face is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum FaceKind {
    Face,
    Edge,
    Vertex,
}

/// The four sides of the EDGE-face of edge `e` (half-edges c and t): `(next c, c, next t, t)`
/// as child vertices. Its long sides run along the edge inside one parent face, its short
/// sides cross it at a vertex; every child edge is a side of exactly one EDGE-face.
pub fn edge_face_sides(topo: &Topology, e: u32) -> [EdgeKey; 4] {
    let c = topo.edge_corner[e as usize] as usize;
    let t = topo.twin[c] as usize;
    let q = [topo.next[c], c as u32, topo.next[t], t as u32];
    [0, 1, 2, 3].map(|i| EdgeKey::new(q[i], q[(i + 1) % 4]))
}

/// Bytes the refined mesh of a closed mesh with `corners` corners and `edges` edges will take
/// (positions, corners, loops, faces, provenance), before its topology is built.
pub fn estimated_bytes(mesh: &PolyMesh, edges: usize) -> u64 {
    let c = mesh.num_corners() as u64;
    let e = edges as u64;
    let v = mesh.num_vertices() as u64;
    let faces = mesh.num_faces() as u64 + e + v;
    let loops = mesh.num_loops() as u64 + e + v;
    c * 24 + (2 * c + 4 * e) * 4 + loops * 4 + faces * (4 + 4 + 1) + 4 * e * 16
}

/// Builds the refined mesh from one new point per parent corner.
pub fn split(
    mesh: &PolyMesh,
    topo: &Topology,
    corner_points: Vec<DVec3>,
) -> (PolyMesh, Provenance) {
    debug_assert_eq!(corner_points.len(), mesh.num_corners());
    let nf = mesh.num_faces();
    let ne = topo.num_edges();
    let nc = mesh.num_corners();
    let used_v = topo.vert_corner.iter().filter(|&&c| c != NONE).count();
    let faces = nf + ne + used_v;
    let loops = mesh.num_loops() + ne + used_v;
    let mut out = PolyMesh::with_capacity(nc, faces, loops, nc + 4 * ne + nc);
    out.positions = corner_points;
    let mut kind = Vec::with_capacity(faces);
    let mut parent = Vec::with_capacity(faces);

    // FACE-faces: the parent's loops with corner ids as vertex ids.
    out.corner_verts.extend(0..nc as u32);
    out.loop_starts.clear();
    out.loop_starts.extend_from_slice(&mesh.loop_starts);
    out.face_starts.clear();
    out.face_starts.extend_from_slice(&mesh.face_starts);
    kind.resize(nf, FaceKind::Face);
    parent.extend(0..nf as u32);

    // EDGE-faces.
    let mut n_loops = mesh.num_loops() as u32;
    for (e, &c) in topo.edge_corner.iter().enumerate() {
        let t = topo.twin[c as usize];
        out.corner_verts
            .extend_from_slice(&[topo.next[c as usize], c, topo.next[t as usize], t]);
        out.loop_starts.push(out.corner_verts.len() as u32);
        n_loops += 1;
        out.face_starts.push(n_loops);
        kind.push(FaceKind::Edge);
        parent.push(e as u32);
    }

    // VERTEX-faces.
    for (v, &start) in topo.vert_corner.iter().enumerate() {
        if start == NONE {
            continue;
        }
        let mut c = start;
        loop {
            out.corner_verts.push(c);
            c = topo.ring_next(c);
            if c == start {
                break;
            }
        }
        out.loop_starts.push(out.corner_verts.len() as u32);
        n_loops += 1;
        out.face_starts.push(n_loops);
        kind.push(FaceKind::Vertex);
        parent.push(v as u32);
    }
    let prov = Provenance::new(mesh, topo, Numbering::DualQuad, kind, parent);
    (out, prov)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;

    #[test]
    fn counts_and_closedness_on_the_test_solids() {
        for m in [
            primitives::cube3(),
            primitives::l_block(),
            primitives::holed_block(),
            primitives::tripod(),
        ] {
            let t = Topology::build(&m).unwrap();
            let pts: Vec<DVec3> = (0..m.num_corners())
                .map(|c| m.positions[m.corner_verts[c] as usize])
                .collect();
            let (r, prov) = split(&m, &t, pts);
            let (v, e, f) = (m.num_vertices(), t.num_edges(), m.num_faces());
            assert_eq!(r.num_vertices(), 2 * e);
            assert_eq!(r.num_faces(), f + e + v);
            assert_eq!(prov.face_kind.len(), r.num_faces());
            let rt = Topology::build(&r).unwrap();
            rt.require_closed(&r).unwrap();
            assert_eq!(rt.num_edges(), 4 * e);
        }
    }
}
