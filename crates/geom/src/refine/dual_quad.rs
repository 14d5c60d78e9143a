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
use crate::topology::{Listed, Loops, NONE, Topology};
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
    let q = [topo.next(c), c as u32, topo.next(t), t as u32];
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
            .extend_from_slice(&[topo.next(c as usize), c, topo.next(t as usize), t]);
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

/// Topology of the child of the closed mesh `mesh` (with topology `topo`), written down from
/// the split instead of searched for; it equals [`Topology::build`] of the child (tested).
///
/// Child corners: FACE-face corner c is parent corner c; EDGE-face e has corners
/// `C + 4e + k` for its sides `(next c₀ → c₀, c₀ → next t, next t → t, t → next c₀)`;
/// VERTEX-face corners follow in vertex order, ring order within. Twins: FACE side c ↔ EDGE
/// side 0 (c = c₀) or 2 (c = t) of edge(c); EDGE side 1 ↔ the VERTEX side at `next t`, side 3
/// ↔ the VERTEX side at `next c₀` (the ring steps from corner x to `twin(prev x)`).
pub fn topology(mesh: &PolyMesh, topo: &Topology) -> Topology {
    let nc = mesh.num_corners();
    let ne = topo.num_edges();
    let edge_base = |e: u32| nc as u32 + 4 * e;
    // VERTEX-face position of every parent corner, faces and cycles as the split writes them.
    let mut vpos = vec![NONE; nc];
    let mut corner_face: Vec<u32> = Vec::with_capacity(nc + 4 * ne + nc);
    corner_face.extend((0..nc).map(|c| topo.corner_face(c)));
    let mut next: Vec<u32> = Vec::with_capacity(nc + 4 * ne + nc);
    next.extend((0..nc).map(|c| topo.next(c)));
    let mut prev: Vec<u32> = Vec::with_capacity(nc + 4 * ne + nc);
    prev.extend((0..nc).map(|c| topo.prev(c)));
    let nf = mesh.num_faces() as u32;
    for e in 0..ne as u32 {
        let b = edge_base(e);
        corner_face.extend([nf + e; 4]);
        next.extend([b + 1, b + 2, b + 3, b]);
        prev.extend([b + 3, b, b + 1, b + 2]);
    }
    let mut k = nc as u32 + 4 * ne as u32;
    let mut face = nf + ne as u32;
    for &start in &topo.vert_corner {
        if start == NONE {
            continue;
        }
        let first = k;
        let mut c = start;
        loop {
            vpos[c as usize] = k;
            corner_face.push(face);
            next.push(k + 1);
            prev.push(if k == first { NONE } else { k - 1 });
            k += 1;
            c = topo.ring_next(c);
            if c == start {
                break;
            }
        }
        let last = k - 1;
        next[last as usize] = first;
        prev[first as usize] = last;
        face += 1;
    }
    let n = k as usize;
    let mut twin = vec![NONE; n];
    for c in 0..nc as u32 {
        let e = topo.corner_edge[c as usize];
        let side = if topo.edge_corner[e as usize] == c {
            0
        } else {
            2
        };
        twin[c as usize] = edge_base(e) + side;
        twin[(edge_base(e) + side) as usize] = c;
    }
    for (e, &c0) in topo.edge_corner.iter().enumerate() {
        let b = edge_base(e as u32) as usize;
        let t = topo.twin[c0 as usize];
        let at_next_t = vpos[topo.next(t as usize) as usize];
        let at_next_c0 = vpos[topo.next(c0 as usize) as usize];
        twin[b + 1] = at_next_t;
        twin[at_next_t as usize] = b as u32 + 1;
        twin[b + 3] = at_next_c0;
        twin[at_next_c0 as usize] = b as u32 + 3;
    }
    // Child vertex c's lowest corner is FACE-face corner c.
    let vert_corner = (0..nc as u32).collect();
    let loops = Loops::Listed(Listed {
        corner_face,
        next,
        prev,
    });
    Topology::from_twins(twin, loops, vert_corner)
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
            // Written down, the child's topology equals the searched one.
            let wt = topology(&m, &t);
            assert_eq!(wt.twin, rt.twin);
            assert!(wt.loops().same(rt.loops(), rt.num_corners()));
            assert_eq!(
                (&wt.corner_edge, &wt.edge_corner),
                (&rt.corner_edge, &rt.edge_corner)
            );
            assert_eq!(wt.vert_corner, rt.vert_corner);
        }
    }
}
