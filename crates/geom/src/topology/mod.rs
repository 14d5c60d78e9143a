//! Derived topology: half-edges with twins, edges, vertex rings.
//!
//! Half-edge `c` is the directed edge from corner `c`'s vertex to the next corner of its
//! loop, so half-edges and corners share one index. [`Topology::build`] is the one place
//! that checks a mesh: indices in range, finite coordinates, loops of at least three
//! distinct vertices, no vertex twice in a face, no edge used by more than two faces,
//! consistent orientation. Open meshes are accepted here (a boundary half-edge has no
//! twin); [`Topology::require_closed`] refuses them for the schemes that need a closed
//! solid, and checks that every vertex ring is a single closed fan.
//!
//! Cost: O(corners · valence); twins are found through a per-vertex list of outgoing
//! half-edges (CSR), not a hash map.

use crate::error::{MeshError, MeshWarning};
use crate::mesh::PolyMesh;
use rayon::prelude::*;

mod build;
mod by_vertex;
mod edges;
mod loops;
mod outgoing;

pub(crate) use build::check_finite;
pub(crate) use loops::with_loops;
pub use loops::{CornerLoops, Listed, Loops, QuadLoops, TriLoops};

/// Marks a missing index (no twin, unused vertex).
pub const NONE: u32 = u32::MAX;

/// Half-edge topology of a [`PolyMesh`].
#[derive(Debug, Clone, Default)]
pub struct Topology {
    /// Face, next and previous corner of each corner ([`Topology::corner_face`],
    /// [`Topology::next`], [`Topology::prev`]).
    loops: Loops,
    /// The opposite half-edge, or [`NONE`] on a boundary.
    pub twin: Vec<u32>,
    /// Edge of each half-edge.
    pub corner_edge: Vec<u32>,
    /// One half-edge of each edge: the one with the smaller corner index.
    pub edge_corner: Vec<u32>,
    /// One outgoing half-edge per vertex, or [`NONE`] for an unused vertex.
    pub vert_corner: Vec<u32>,
    /// Problems that do not stop the work.
    pub warnings: Vec<MeshWarning>,
    /// Whether [`Topology::build`] found every vertex ring a single fan (it walks them while
    /// pairing twins), so that [`Topology::require_single_fans`] need not walk them again.
    fans_checked: bool,
    /// Half-edges without a twin: the boundary edges.
    open_edges: usize,
}

impl Topology {
    /// The half-edge topology from twins, loops and ring starts (found by
    /// [`Topology::build`] or written down by a split): edges numbered in the order of their
    /// smaller half-edge.
    pub(crate) fn from_twins(twin: Vec<u32>, loops: Loops, vert_corner: Vec<u32>) -> Topology {
        Topology::numbered(twin, loops, vert_corner, None)
    }

    /// [`Topology::from_twins`], with the leading half-edges per block of the numbering
    /// and the open ones when the pairing counted them.
    fn numbered(
        twin: Vec<u32>,
        loops: Loops,
        vert_corner: Vec<u32>,
        counted: Option<&edges::Leads>,
    ) -> Topology {
        let numbered = edges::number_edges(&twin, counted);
        Topology {
            loops,
            twin,
            corner_edge: numbered.corner_edge,
            edge_corner: numbered.edge_corner,
            vert_corner,
            warnings: Vec::new(),
            fans_checked: false,
            open_edges: numbered.open,
        }
    }

    /// Whether every half-edge has a twin (no boundary edge), counted while the edges were
    /// numbered.
    pub fn is_closed(&self) -> bool {
        self.open_edges == 0
    }

    /// The face of corner `c`.
    #[inline]
    pub fn corner_face(&self, c: usize) -> u32 {
        self.loops.face(c)
    }

    /// The next corner of corner `c`'s loop.
    #[inline]
    pub fn next(&self, c: usize) -> u32 {
        self.loops.next(c)
    }

    /// The previous corner of corner `c`'s loop.
    #[inline]
    pub fn prev(&self, c: usize) -> u32 {
        self.loops.prev(c)
    }

    /// The loops: faces and neighbours of the corners, stored or arithmetic.
    pub fn loops(&self) -> &Loops {
        &self.loops
    }

    /// The number of corners (half-edges).
    pub fn num_corners(&self) -> usize {
        self.twin.len()
    }

    /// Bytes its arrays hold.
    pub fn heap_bytes(&self) -> u64 {
        let listed = match &self.loops {
            Loops::Listed(l) => l.corner_face.len() + l.next.len() + l.prev.len(),
            Loops::Quads | Loops::Triangles => 0,
        };
        4 * (listed
            + self.twin.len()
            + self.corner_edge.len()
            + self.edge_corner.len()
            + self.vert_corner.len()) as u64
    }

    pub fn num_edges(&self) -> usize {
        self.edge_corner.len()
    }

    /// The next half-edge around the vertex of half-edge `c`, turning so that the faces are
    /// visited in the order of docs/algorithms/biquadratic.md (VERTEX-face order): from `c` (v→x) go to
    /// the half-edge that leaves v along the edge preceding `c` in its loop. [`NONE`] at a
    /// boundary.
    #[inline]
    pub fn ring_next(&self, c: u32) -> u32 {
        self.twin[self.prev(c as usize) as usize]
    }

    /// The corners of vertex `v` in [`Topology::ring_next`] order from `vert_corner[v]`, once
    /// round a closed ring (none for an unused vertex): the dual-quad rules' walk round a
    /// VERTEX-face, without a list.
    pub fn corners_around(&self, v: usize) -> impl Iterator<Item = u32> + Clone + '_ {
        let start = self.vert_corner[v];
        std::iter::successors((start != NONE).then_some(start), move |&c| {
            let n = self.ring_next(c);
            (n != start).then_some(n)
        })
    }

    /// Refuses an open mesh (naming a boundary edge) and a vertex whose faces do not form a
    /// single closed fan.
    pub fn require_closed(&self, mesh: &PolyMesh) -> Result<(), MeshError> {
        for (c, &t) in self.twin.iter().enumerate() {
            if t == NONE {
                return Err(MeshError::BoundaryEdge {
                    a: mesh.corner_verts[c],
                    b: mesh.corner_verts[self.next(c) as usize],
                    face: self.corner_face(c),
                });
            }
        }
        self.require_single_fans(mesh)
    }

    /// Refuses a vertex whose faces do not form a single fan (closed around an interior
    /// vertex, open at a boundary vertex): two cones touching at a tip, two sheets touching
    /// at a corner.
    pub fn require_single_fans(&self, mesh: &PolyMesh) -> Result<(), MeshError> {
        // A fan walk visits distinct corners of its vertex (`ring_next` is one-to-one), so
        // it never counts more than the vertex's valence; the fans' sizes add up to the
        // number of corners exactly when every vertex is a single fan. Only then is the
        // per-vertex count below skipped.
        if self.fans_checked {
            return Ok(());
        }
        let nc = mesh.num_corners();
        let fan = |start: u32, bound: usize| {
            let mut k = 0usize;
            let mut c = start;
            loop {
                k += 1;
                c = self.ring_next(c);
                if c == NONE || c == start || k > bound {
                    return k;
                }
            }
        };
        let total: usize = self
            .vert_corner
            .par_iter()
            .with_min_len(1 << 12)
            .map(|&start| if start == NONE { 0 } else { fan(start, nc) })
            .sum();
        if total == nc {
            return Ok(());
        }
        let mut valence = vec![0u32; mesh.num_vertices()];
        for &v in &mesh.corner_verts {
            valence[v as usize] += 1;
        }
        for (v, &start) in self.vert_corner.iter().enumerate() {
            if start == NONE {
                continue;
            }
            let k = fan(start, valence[v] as usize) as u32;
            if k != valence[v] {
                return Err(MeshError::NonManifoldVertex {
                    vertex: v as u32,
                    fans: valence[v].div_ceil(k.max(1)).max(2),
                });
            }
        }
        Ok(())
    }

    /// The edges around a vertex in ring order from its corner `start` (an interior
    /// vertex's ring may start at any of its corners; `vert_corner[v]` is the usual one,
    /// [`NONE`] gives an empty ring), each as (edge, other vertex), and the corners of the
    /// vertex in the faces between them: the face of corner i lies between edges i and
    /// i + 1. At a boundary vertex the ring from `vert_corner[v]` starts at the boundary
    /// edge with the fan on its left and ends at the other boundary edge (one edge more than
    /// faces), as OpenSubdiv orders it.
    pub fn vertex_ring_from(
        &self,
        mesh: &PolyMesh,
        start: u32,
        edges: &mut Vec<(u32, u32)>,
        corners: &mut Vec<u32>,
    ) {
        edges.clear();
        corners.clear();
        self.walk_ring(mesh, start, |edge, other, corner| {
            edges.push((edge, other));
            corners.extend(corner);
            false
        });
    }

    /// Walks the ring from corner `start` in [`Topology::vertex_ring_from`]'s order, calling
    /// `visit(edge, other vertex, corner)` for each edge (no corner for the closing boundary
    /// edge) until it returns true; returns whether it did. The one walk both the listing and
    /// [`Topology::find_edge`] use.
    fn walk_ring(
        &self,
        mesh: &PolyMesh,
        start: u32,
        mut visit: impl FnMut(u32, u32, Option<u32>) -> bool,
    ) -> bool {
        if start == NONE {
            return false;
        }
        let cv = &mesh.corner_verts;
        let (mut c, mut walked) = (start, 0);
        loop {
            let edge = self.corner_edge[c as usize];
            if visit(edge, cv[self.next(c as usize) as usize], Some(c)) {
                return true;
            }
            walked += 1;
            let n = self.ring_next(c);
            if n == NONE {
                let p = self.prev(c as usize) as usize;
                return visit(self.corner_edge[p], cv[p], None);
            }
            if n == start || walked > self.num_corners() {
                return false;
            }
            c = n;
        }
    }

    /// The edge joining vertices `a` and `b`, if there is one: the first in `a`'s ring
    /// ([`Topology::vertex_ring_from`] from `vert_corner[a]`), walked without a list (edge
    /// marks are handed down level by level through thousands of these).
    pub fn find_edge(&self, mesh: &PolyMesh, a: u32, b: u32) -> Option<u32> {
        if a as usize >= self.vert_corner.len() || b as usize >= self.vert_corner.len() {
            return None;
        }
        let mut found = None;
        self.walk_ring(mesh, self.vert_corner[a as usize], |edge, other, _| {
            found = (other == b).then_some(edge);
            found.is_some()
        });
        found
    }

    /// The two faces of edge `e` of a closed mesh: its first half-edge's, then its twin's.
    pub fn edge_faces(&self, e: usize) -> [u32; 2] {
        let c = self.edge_corner[e] as usize;
        [self.corner_face(c), self.corner_face(self.twin[c] as usize)]
    }

    /// The two vertices of edge `e` as (a, b) in the direction of its first half-edge.
    pub fn edge_verts(&self, mesh: &PolyMesh, e: usize) -> (u32, u32) {
        let c = self.edge_corner[e] as usize;
        (
            mesh.corner_verts[c],
            mesh.corner_verts[self.next(c) as usize],
        )
    }
}

#[cfg(test)]
mod tests;
