//! The order OpenSubdiv gives the edges and faces around each vertex, which decides the side
//! of a one-sided crease normal and which two edges a corner's tangents follow. At the input
//! it is the natural one (each ring starts in the vertex's lowest-numbered face, each edge's
//! first face is its lower-numbered one); refinement passes it on as OpenSubdiv's refiner
//! does (`Vtr::QuadRefinement`, `Vtr::TriRefinement`): each split says how
//! ([`crate::refine::quad::ring_order`], [`crate::refine::tri::ring_order`]).

use super::PrimalSplit;
use crate::mesh::PolyMesh;
use crate::topology::{NONE, Topology};

/// Ring starts and first half-edges of one level, in OpenSubdiv's order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RingOrder {
    /// The corner each vertex's ring starts at ([`NONE`] for a vertex without faces).
    pub ring_start: Vec<u32>,
    /// Whether each corner's half-edge lies in its edge's first face.
    pub first_half_edge: Vec<bool>,
}

impl RingOrder {
    /// The natural order of a mesh's topology.
    pub fn natural(topo: &Topology) -> RingOrder {
        RingOrder {
            ring_start: topo.vert_corner.clone(),
            first_half_edge: (0..topo.corner_edge.len())
                .map(|c| topo.edge_corner[topo.corner_edge[c] as usize] == c as u32)
                .collect(),
        }
    }

    /// The half-edge of edge `e` that lies in its first face.
    pub(crate) fn first_of_edge(&self, topo: &Topology, e: usize) -> u32 {
        let c = topo.edge_corner[e];
        let t = topo.twin[c as usize];
        if t != NONE && self.first_half_edge[t as usize] {
            t
        } else {
            c
        }
    }

    /// The order of the child of a mesh with this order, split by `split`.
    pub(crate) fn child(&self, mesh: &PolyMesh, topo: &Topology, split: PrimalSplit) -> RingOrder {
        split.ring_order(self, mesh, topo)
    }
}
