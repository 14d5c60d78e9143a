//! Prism's geometry kernels: pure functions over plain data, no GUI or GPU.
//!
//! - [`mesh`]: polygon meshes whose faces may be concave and have holes, stored flat;
//! - [`topology`]: half-edges, twins, rings, and every check of bad input;
//! - [`refine`]: the three splits (dual quad, quad, triangle), each written once, with the
//!   child numbering and the provenance of every child element as data;
//! - [`rules`] + [`step`]: PRISM's biquadratic subdivision (seed 000) — the dual quad split
//!   (CGAL's DQQ) with pluggable corner rules: Doo–Sabin, three chamfers, the cylindrical
//!   family (simple, minimum, combination);
//! - [`rules::primal`] + [`primal`]: Catmull–Clark and Loop with creases, corners and holes;
//! - [`dissolve`]: merging coplanar faces before the cylindrical rules;
//! - [`scheme`] + [`pipeline`]: steps as values, levels kept per step;
//! - [`analysis`]: counts, the fillet radius reached;
//! - [`io`]: OBJ and the `.prism.json` document;
//! - [`primitives`]: the test solids and the bundled samples;
//! - [`freeform`]: the free-form family (rational Bézier curves; Gregory patches, skinning and
//!   envelopes next).
//!
//! The formulas, the papers' equation numbers and the resolved ambiguities are in
//! `docs/algorithms/` (one page per family, indexed in `docs/index.md`) and in each module's doc.

pub mod analysis;
pub mod ancestry;
pub mod child_check;
pub mod curve;
pub mod curve_study;
pub mod dissolve;
pub mod edge_attrs;
pub mod error;
pub mod freeform;
pub mod geometry;
pub mod io;
pub mod memory;
pub mod mesh;
pub mod normals;
pub mod numbering;
mod parallel;
pub mod pipeline;
pub mod primal;
pub mod primitives;
pub mod progress;
pub mod refine;
pub mod rules;
pub mod scheme;
pub mod solid;
pub mod step;
mod stream;
pub mod tags;
pub mod topology;
pub mod triangulate;

pub use edge_attrs::{EdgeAttr, EdgeAttrs, EdgeKey};
pub use error::{MeshError, MeshWarning};
pub use glam::DVec3;
pub use mesh::PolyMesh;
pub use pipeline::{Level, Pipeline, PipelineError, RoundingRun};
pub use primal::{
    LimitPoints, PrimalError, PrimalOutput, PrimalScheme, RingOrder, limit_points,
    limit_points_ordered, refine_primal, refine_primal_levels, refine_primal_ordered,
    refine_primal_with,
};
pub use rules::RoundingOptions;
pub use rules::{CornerRule, ReflexMode};
pub use scheme::{Scheme, parse_pipeline};
pub use step::{StepError, StepReport, biquadratic_step};
pub use tags::{BoundaryInterpolation, CreaseMethod, SubdivTags, TriangleSubdivision};
pub use topology::Topology;
