//! Per-edge attributes: crease sharpness, an own fillet radius and the radius the overlap
//! clamp found to fit.
//!
//! Keyed by the edge's two vertex indices (smaller first), so they survive any reordering
//! of faces and are what the files store. A step hands them down with
//! [`crate::refine::propagate`]: through a biquadratic step every new edge lies on exactly
//! one EDGE-face and inherits its parent edge's attributes; through a primal step each half
//! of an edge inherits them with the crease decayed.

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
    /// The largest radius that fits this edge's faces, written by the overlap clamp
    /// (`--clamp`): later rounding steps take the smaller of it and the radius they would
    /// use, so a clamped edge never rounds wider than a later, smaller r asks.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fits: Option<f64>,
}

impl EdgeAttr {
    /// A crease of sharpness `s` (no own radius).
    pub fn creased(s: f64) -> Self {
        EdgeAttr {
            crease: s,
            ..EdgeAttr::default()
        }
    }

    /// An own fillet radius `r` (no crease).
    pub fn rounded(r: f64) -> Self {
        EdgeAttr {
            radius: Some(r),
            ..EdgeAttr::default()
        }
    }

    /// Nothing set: no crease, no own radius, no cap. Such an edge is left out of the map.
    pub fn is_empty(&self) -> bool {
        self.crease == 0.0 && self.radius.is_none() && self.fits.is_none()
    }
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

/// Attributes of the edges that have any.
pub type EdgeAttrs = BTreeMap<EdgeKey, EdgeAttr>;
