//! The quad split of Catmull–Clark: parent corner c (face f, vertex v) gives child quad c =
//! `(v, E(edge c), F(f), E(edge prev c))` in the numbering of [`PrimalNumbering`], with child
//! corners `4c + k`. Closed-input counts: `V' = V + E + F`, `E' = 2E + C`, `F' = C`.
//!
//! The child's half-edge topology is written down from this pattern instead of searched for
//! (`topology`): every twin is known by construction. It equals [`Topology::build`] of the
//! child (same edge numbering, same ring starts), which a test checks, and costs one pass
//! over the child's corners instead of a bucket sort and a search.

// Vertices, edges and corners are indices into parallel arrays here.
#![allow(clippy::needless_range_loop)]

use super::RingOrder;
use super::{ChildCounts, PrimalNumbering};
use crate::mesh::PolyMesh;
use crate::topology::{CornerLoops, Loops, NONE, Topology, with_loops};

/// The numbering of the quad split of `mesh`.
pub fn numbering(mesh: &PolyMesh, topo: &Topology) -> PrimalNumbering {
    PrimalNumbering {
        vertices: mesh.num_vertices() as u32,
        edges: topo.num_edges() as u32,
        face_points: mesh.num_faces() as u32,
    }
}

/// Sizes of the child of `mesh` with `edges` edges.
pub fn counts(mesh: &PolyMesh, edges: usize) -> ChildCounts {
    let (v, e, f, c) = (
        mesh.num_vertices() as u64,
        edges as u64,
        mesh.num_faces() as u64,
        mesh.num_corners() as u64,
    );
    ChildCounts {
        vertices: v + e + f,
        edges: 2 * e + c,
        faces: c,
        corners: 4 * c,
    }
}

/// The child's faces (no positions yet), on rayon's pool.
pub fn faces(mesh: &PolyMesh, topo: &Topology, n: PrimalNumbering) -> PolyMesh {
    let cv = &mesh.corner_verts;
    let ce = &topo.corner_edge;
    with_loops!(topo.loops(), l => super::uniform_faces(mesh.num_corners(), 4, |c| {
        [
            n.vertex(cv[c]),
            n.edge_point(ce[c]),
            n.face_point(l.face(c)),
            n.edge_point(ce[l.prev(c) as usize]),
        ]
    }))
}

/// The parent face of each child face: child face c lies in the face of parent corner c.
pub fn face_parent(topo: &Topology) -> Vec<u32> {
    use rayon::prelude::*;
    (0..topo.num_corners())
        .into_par_iter()
        .with_min_len(1 << 14)
        .map(|c| topo.corner_face(c))
        .collect()
}

/// Topology of the child of `mesh` (with topology `topo`).
pub(crate) fn topology(mesh: &PolyMesh, topo: &Topology) -> Topology {
    let nc = mesh.num_corners();
    let n = 4 * nc;
    let mut twin = vec![NONE; n];
    for c in 0..nc {
        let t = topo.twin[c];
        let tp = topo.twin[topo.prev(c) as usize];
        twin[4 * c] = if t == NONE {
            NONE
        } else {
            4 * topo.next(t as usize) + 3
        };
        twin[4 * c + 1] = 4 * topo.next(c) + 2;
        twin[4 * c + 2] = 4 * topo.prev(c) + 1;
        twin[4 * c + 3] = if tp == NONE { NONE } else { 4 * tp };
    }
    let mut vert_corner =
        Vec::with_capacity(mesh.num_vertices() + topo.num_edges() + mesh.num_faces());
    vert_corner.extend(
        topo.vert_corner
            .iter()
            .map(|&s| if s == NONE { NONE } else { 4 * s }),
    );
    for &c in &topo.edge_corner {
        let t = topo.twin[c as usize];
        let a = (4 * c + 1).min(4 * topo.next(c as usize) + 3);
        vert_corner.push(if t == NONE {
            4 * topo.next(c as usize) + 3
        } else {
            a.min(4 * t + 1).min(4 * topo.next(t as usize) + 3)
        });
    }
    vert_corner.extend((0..mesh.num_faces()).map(|f| 4 * mesh.face_corners(f).start as u32 + 2));
    Topology::from_twins(twin, Loops::Quads, vert_corner)
}

/// OpenSubdiv's ring order of the child (`Vtr::QuadRefinement`), given the parent's.
pub(crate) fn ring_order(order: &RingOrder, mesh: &PolyMesh, topo: &Topology) -> RingOrder {
    let nc = mesh.num_corners();
    let first = &order.first_half_edge;
    let mut ring_start =
        Vec::with_capacity(mesh.num_vertices() + topo.num_edges() + mesh.num_faces());
    ring_start.extend(
        order
            .ring_start
            .iter()
            .map(|&s| if s == NONE { NONE } else { 4 * s }),
    );
    ring_start.extend(
        (0..topo.num_edges()).map(|e| 4 * topo.next(order.first_of_edge(topo, e) as usize) + 3),
    );
    ring_start.extend((0..mesh.num_faces()).map(|f| 4 * mesh.face_corners(f).start as u32 + 2));
    let mut first_half_edge = vec![false; 4 * nc];
    for c in 0..nc {
        first_half_edge[4 * c] = first[c];
        first_half_edge[4 * c + 1] = true;
        first_half_edge[4 * c + 3] = first[topo.prev(c) as usize];
    }
    RingOrder {
        ring_start,
        first_half_edge,
    }
}
