//! The half-edge topology of a refined level, written down from the split instead of
//! searched for: every twin of a Catmull–Clark or Loop child is known by construction.
//! The result equals [`Topology::build`] of the child (same edge numbering — edges in the
//! order of their smaller half-edge —, same ring starts), which a test checks; it costs one
//! pass over the child's corners instead of a bucket sort and a search.
//!
//! Catmull–Clark: parent corner c (face f, vertex v) gives child quad c =
//! `(v, E(edge c), F(f), E(edge prev c))`, child corners `4c + k`. Loop: parent triangle f
//! gives corner triangles `4f + k = (v_k, e_k, e_(k−1))` and the middle one
//! `4f + 3 = (e₀, e₁, e₂)`, child corners `3(4f + k) + j`.

use super::PrimalScheme;
use crate::mesh::PolyMesh;
use crate::topology::{NONE, Topology};

/// Topology of the child of `mesh` (with topology `topo`) under `scheme`.
pub(crate) fn child_topology(mesh: &PolyMesh, topo: &Topology, scheme: PrimalScheme) -> Topology {
    let nc = mesh.num_corners();
    let nv = mesh.num_vertices();
    let ne = topo.num_edges();
    let (twin, corner_face, next, prev, vert_corner) = match scheme {
        PrimalScheme::CatmullClark | PrimalScheme::CatmullClarkCircle => {
            let n = 4 * nc;
            let mut twin = vec![NONE; n];
            for c in 0..nc {
                let t = topo.twin[c];
                let tp = topo.twin[topo.prev[c] as usize];
                twin[4 * c] = if t == NONE {
                    NONE
                } else {
                    4 * topo.next[t as usize] + 3
                };
                twin[4 * c + 1] = 4 * topo.next[c] + 2;
                twin[4 * c + 2] = 4 * topo.prev[c] + 1;
                twin[4 * c + 3] = if tp == NONE { NONE } else { 4 * tp };
            }
            let corner_face: Vec<u32> = (0..n as u32).map(|i| i / 4).collect();
            let next: Vec<u32> = (0..n as u32).map(|i| (i & !3) | ((i + 1) & 3)).collect();
            let prev: Vec<u32> = (0..n as u32).map(|i| (i & !3) | ((i + 3) & 3)).collect();
            let mut vert_corner = Vec::with_capacity(nv + ne + mesh.num_faces());
            vert_corner.extend(
                topo.vert_corner
                    .iter()
                    .map(|&s| if s == NONE { NONE } else { 4 * s }),
            );
            for &c in &topo.edge_corner {
                let t = topo.twin[c as usize];
                let a = (4 * c + 1).min(4 * topo.next[c as usize] + 3);
                vert_corner.push(if t == NONE {
                    4 * topo.next[c as usize] + 3
                } else {
                    a.min(4 * t + 1).min(4 * topo.next[t as usize] + 3)
                });
            }
            vert_corner
                .extend((0..mesh.num_faces()).map(|f| 4 * mesh.face_corners(f).start as u32 + 2));
            (twin, corner_face, next, prev, vert_corner)
        }
        PrimalScheme::Loop => {
            let nf = mesh.num_faces();
            let n = 12 * nf;
            // Face and position of a parent corner.
            let at = |c: u32| (c / 3, c % 3);
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
                    let tp = topo.twin[topo.prev[c as usize] as usize];
                    twin[tri as usize + 2] = if tp == NONE {
                        NONE
                    } else {
                        let (g, m) = at(tp);
                        3 * (4 * g + m)
                    };
                    twin[(3 * (4 * f + 3) + k) as usize] = 3 * (4 * f + (k + 1) % 3) + 1;
                }
            }
            let corner_face: Vec<u32> = (0..n as u32).map(|i| i / 3).collect();
            let next: Vec<u32> = (0..n as u32).map(|i| i - i % 3 + (i % 3 + 1) % 3).collect();
            let prev: Vec<u32> = (0..n as u32).map(|i| i - i % 3 + (i % 3 + 2) % 3).collect();
            let mut vert_corner = Vec::with_capacity(nv + ne);
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
            (twin, corner_face, next, prev, vert_corner)
        }
    };
    let n = twin.len();
    let mut corner_edge = vec![NONE; n];
    let mut edge_corner = Vec::with_capacity(n / 2 + 1);
    for c in 0..n {
        let t = twin[c];
        if t == NONE || (c as u32) < t {
            let e = edge_corner.len() as u32;
            edge_corner.push(c as u32);
            corner_edge[c] = e;
            if t != NONE {
                corner_edge[t as usize] = e;
            }
        }
    }
    Topology {
        corner_face,
        next,
        prev,
        twin,
        corner_edge,
        edge_corner,
        vert_corner,
        warnings: Vec::new(),
    }
}
