//! The triangle split of Loop: parent triangle f (corners `3f + k`, all faces triangles)
//! gives the corner triangles `4f + k = (v_k, e_k, e_(k−1))` and the middle one
//! `4f + 3 = (e₀, e₁, e₂)` in the numbering of [`PrimalNumbering`] (no face points), with
//! child corners `3(4f + k) + j`. Closed-input counts: `V' = V + E`, `E' = 2E + 3F`,
//! `F' = 4F`.
//!
//! As for the quad split, the child's topology is written down from the pattern
//! (`topology`) and equals [`Topology::build`] of the child.

// Vertices, edges and corners are indices into parallel arrays here.
#![allow(clippy::needless_range_loop)]

use super::RingOrder;
use super::{ChildCounts, PrimalNumbering};
use crate::mesh::PolyMesh;
use crate::topology::{CornerLoops, Loops, NONE, Topology, with_loops};

/// The numbering of the triangle split of `mesh`.
pub fn numbering(mesh: &PolyMesh, topo: &Topology) -> PrimalNumbering {
    PrimalNumbering {
        vertices: mesh.num_vertices() as u32,
        edges: topo.num_edges() as u32,
        face_points: 0,
    }
}

/// Sizes of the child of the triangle mesh `mesh` with `edges` edges.
pub fn counts(mesh: &PolyMesh, edges: usize) -> ChildCounts {
    let (v, e, f) = (
        mesh.num_vertices() as u64,
        edges as u64,
        mesh.num_faces() as u64,
    );
    ChildCounts {
        vertices: v + e,
        edges: 2 * e + 3 * f,
        faces: 4 * f,
        corners: 12 * f,
    }
}

/// Face and position in it of a parent corner.
#[inline]
fn at(c: u32) -> (u32, u32) {
    (c / 3, c % 3)
}

/// The child's faces (no positions yet), on rayon's pool.
pub fn faces(mesh: &PolyMesh, topo: &Topology, n: PrimalNumbering) -> PolyMesh {
    let cv = &mesh.corner_verts;
    let ce = &topo.corner_edge;
    with_loops!(topo.loops(), l => super::uniform_faces(mesh.num_faces(), 3, |f| {
        let c0 = l.face_corners(mesh, f).start;
        let v = [0, 1, 2].map(|k| n.vertex(cv[c0 + k]));
        let e = [0, 1, 2].map(|k| n.edge_point(ce[c0 + k]));
        [
            v[0], e[0], e[2], v[1], e[1], e[0], v[2], e[2], e[1], e[0], e[1], e[2],
        ]
    }))
}

/// The parent face of each child face: four children a triangle, in order.
pub fn face_parent(mesh: &PolyMesh) -> Vec<u32> {
    use rayon::prelude::*;
    (0..4 * mesh.num_faces())
        .into_par_iter()
        .with_min_len(1 << 14)
        .map(|i| (i / 4) as u32)
        .collect()
}

/// Topology of the child of the triangle mesh `mesh` (with topology `topo`).
pub(crate) fn topology(mesh: &PolyMesh, topo: &Topology) -> Topology {
    let nf = mesh.num_faces();
    let n = 12 * nf;
    let mut twin = vec![NONE; n];
    for f in 0..nf as u32 {
        for k in 0..3u32 {
            let c = 3 * f + k;
            let tri = 3 * (4 * f + k);
            let t = topo.twin[c as usize];
            twin[tri as usize] = if t == NONE {
                NONE
            } else {
                let (g, m) = at(t);
                3 * (4 * g + (m + 1) % 3) + 2
            };
            twin[tri as usize + 1] = 3 * (4 * f + 3) + (k + 2) % 3;
            let tp = topo.twin[topo.prev(c as usize) as usize];
            twin[tri as usize + 2] = if tp == NONE {
                NONE
            } else {
                let (g, m) = at(tp);
                3 * (4 * g + m)
            };
            twin[(3 * (4 * f + 3) + k) as usize] = 3 * (4 * f + (k + 1) % 3) + 1;
        }
    }
    let mut vert_corner = Vec::with_capacity(mesh.num_vertices() + topo.num_edges());
    vert_corner.extend(topo.vert_corner.iter().map(|&s| {
        if s == NONE {
            NONE
        } else {
            let (f, m) = at(s);
            3 * (4 * f + m)
        }
    }));
    // Outgoing child corners of the edge point in the face of half-edge c.
    let around = |c: u32| {
        let (f, k) = at(c);
        [
            3 * (4 * f + k) + 1,
            3 * (4 * f + (k + 1) % 3) + 2,
            3 * (4 * f + 3) + k,
        ]
    };
    for &c in &topo.edge_corner {
        let t = topo.twin[c as usize];
        let mine = around(c);
        vert_corner.push(if t == NONE {
            mine[1]
        } else {
            let theirs = around(t);
            mine.into_iter().chain(theirs).min().expect("six corners")
        });
    }
    Topology::from_twins(twin, Loops::Triangles, vert_corner)
}

/// OpenSubdiv's ring order of the child (`Vtr::TriRefinement`), given the parent's.
pub(crate) fn ring_order(order: &RingOrder, mesh: &PolyMesh, topo: &Topology) -> RingOrder {
    let nc = mesh.num_corners();
    let first = &order.first_half_edge;
    // Corner triangle k of face f is child face 4f + k: (v_k, e_k, e_(k−1)).
    let tri = |c: u32| {
        let (f, k) = at(c);
        4 * f + k
    };
    let mut ring_start = Vec::with_capacity(mesh.num_vertices() + topo.num_edges());
    ring_start.extend(
        order
            .ring_start
            .iter()
            .map(|&s| if s == NONE { NONE } else { 3 * tri(s) }),
    );
    ring_start.extend(
        (0..topo.num_edges())
            .map(|e| 3 * tri(topo.next(order.first_of_edge(topo, e) as usize)) + 2),
    );
    let mut first_half_edge = vec![false; 4 * nc];
    for c in 0..nc {
        let t = 3 * tri(c as u32) as usize;
        first_half_edge[t] = first[c];
        first_half_edge[t + 1] = true;
        first_half_edge[t + 2] = first[topo.prev(c) as usize];
    }
    RingOrder {
        ring_start,
        first_half_edge,
    }
}
