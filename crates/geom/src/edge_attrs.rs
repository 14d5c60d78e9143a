//! Per-edge attributes: crease sharpness and an own fillet radius.
//!
//! Keyed by the edge's two vertex indices (smaller first), so they survive any reordering
//! of faces and are what the files store. Through a biquadratic step every new edge lies on
//! exactly one EDGE-face (docs/algorithms/biquadratic.md: FACE- and VERTEX-faces only touch EDGE-faces),
//! so each new edge inherits the attributes of that EDGE-face's parent edge.

use crate::mesh::PolyMesh;
use crate::topology::Topology;
use std::collections::BTreeMap;

/// An undirected edge by its vertices, smaller index first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct EdgeKey(pub u32, pub u32);

impl EdgeKey {
    pub fn new(a: u32, b: u32) -> Self {
        if a < b { EdgeKey(a, b) } else { EdgeKey(b, a) }
    }
}

/// What the user set on one edge.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct EdgeAttr {
    /// Crease sharpness (0 smooth, ≥ 10 infinitely sharp), used by Catmull–Clark and Loop.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub crease: f64,
    /// Fillet radius of this edge for the cylindrical rules, overriding the step's r.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

/// Attributes of the edges that have any.
pub type EdgeAttrs = BTreeMap<EdgeKey, EdgeAttr>;

/// Attributes of the edges of a biquadratic child, given those of the parent.
pub fn propagate_biquadratic(parent: &PolyMesh, topo: &Topology, attrs: &EdgeAttrs) -> EdgeAttrs {
    let mut out = EdgeAttrs::new();
    if attrs.is_empty() {
        return out;
    }
    for &c in &topo.edge_corner {
        let c = c as usize;
        let t = topo.twin[c] as usize;
        let key = EdgeKey::new(
            parent.corner_verts[c],
            parent.corner_verts[topo.next[c] as usize],
        );
        if let Some(a) = attrs.get(&key) {
            // EDGE-face (next(c), c, next(t), t): new vertex ids are parent corner ids.
            let q = [topo.next[c], c as u32, topo.next[t], t as u32];
            for i in 0..4 {
                out.insert(EdgeKey::new(q[i], q[(i + 1) % 4]), *a);
            }
        }
    }
    out
}

/// Per-edge radius for the edges of `topo`: the edge's own radius or `default`.
pub fn edge_radii(mesh: &PolyMesh, topo: &Topology, attrs: &EdgeAttrs, default: f64) -> Vec<f64> {
    topo.edge_corner
        .iter()
        .map(|&c| {
            let c = c as usize;
            let key = EdgeKey::new(
                mesh.corner_verts[c],
                mesh.corner_verts[topo.next[c] as usize],
            );
            attrs.get(&key).and_then(|a| a.radius).unwrap_or(default)
        })
        .collect()
}
