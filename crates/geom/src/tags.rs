//! Subdivision tags beyond per-edge creases: corner vertices, hole faces and the options of
//! the primal schemes (boundary interpolation, crease decay, triangles under Catmull–Clark),
//! as OpenSubdiv names them (`Sdc::Options`, `Far::TopologyDescriptor`).
//!
//! Edge creases live in [`crate::EdgeAttrs`] (`crease`); everything else a primal step needs
//! is here. Files: OBJ `t` lines (`t corner 1/1/0 v s`, `t hole n/0/0 f…`,
//! `t interpolateboundary 1/0/0 k`, `t creasemethod 0/0/1 chaikin`,
//! `t smoothtriangles 0/0/1 smooth`) and `.prism.json`.

use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, BTreeSet};

/// How boundary vertices are treated (OpenSubdiv `VtxBoundaryInterpolation`). OBJ tag
/// values: 0 none, 1 edge and corner, 2 edge only.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum BoundaryInterpolation {
    /// No boundary interpolation: the faces around a boundary vertex whose boundary edges
    /// are not all infinitely sharp become holes (their vertices still shape the surface).
    None,
    /// Boundary edges are infinitely sharp creases (the default without a tag).
    #[default]
    EdgeOnly,
    /// As `EdgeOnly`, and a vertex with one face and two edges is a sharp corner.
    EdgeAndCorner,
}

impl BoundaryInterpolation {
    /// From the OBJ tag's integer (0 none, 1 edge and corner, 2 edge only).
    pub fn from_obj(k: i64) -> Option<Self> {
        match k {
            0 => Some(Self::None),
            1 => Some(Self::EdgeAndCorner),
            2 => Some(Self::EdgeOnly),
            _ => None,
        }
    }
    pub fn to_obj(self) -> i64 {
        match self {
            Self::None => 0,
            Self::EdgeAndCorner => 1,
            Self::EdgeOnly => 2,
        }
    }
}

/// How semi-sharp crease sharpness decays from level to level.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum CreaseMethod {
    /// `s − 1` per level (OpenSubdiv "uniform", OBJ `normal`).
    #[default]
    Uniform,
    /// Chaikin: `¾ s + ¼ (mean of the other semi-sharp edges at the vertex) − 1`.
    Chaikin,
}

/// Edge weights next to triangles under Catmull–Clark.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum TriangleSubdivision {
    /// The plain Catmull–Clark masks.
    #[default]
    Catmark,
    /// OpenSubdiv's "smooth triangle" edge weights (face weight 0.47 next to a triangle).
    Smooth,
}

/// Corners, holes and options of a mesh for the primal schemes.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct SubdivTags {
    #[serde(default)]
    pub boundary: BoundaryInterpolation,
    #[serde(default)]
    pub crease_method: CreaseMethod,
    #[serde(default)]
    pub triangles: TriangleSubdivision,
    /// Vertex sharpness (0 smooth, ≥ 10 infinitely sharp corner) by vertex index.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub corners: BTreeMap<u32, f64>,
    /// Faces that are holes: refined like the others (they shape their neighbours) but not
    /// drawn or written as faces.
    #[serde(default, skip_serializing_if = "BTreeSet::is_empty")]
    pub holes: BTreeSet<u32>,
}

impl SubdivTags {
    /// Whether nothing differs from the defaults.
    pub fn is_default(&self) -> bool {
        *self == SubdivTags::default()
    }
}
