//! Analysis that the app shows and the tests assert: counts, the fillet radius reached
//! along an edge, mean curvature per vertex, faces that pass through each other, the winding number about a point, a section plane. Flipped and
//! degenerate faces are found by each step ([`crate::step::check_children`]).

mod box_pairs;
mod counts;
mod crossings;
mod curvature;
pub(crate) mod face_grid;
mod fillet;
mod section;
mod winding;

pub use counts::{MeshCounts, counts};
pub use crossings::{
    crossed_by, crossing_faces, crossing_points, crossings, crossings_of, triangles_cross,
};
pub use curvature::mean_curvature;
pub use fillet::{
    FilletError, FilletMeasure, FilletSummary, measure_edges, measure_fillet, measure_fillets,
};
pub use section::{HalfSpace, Section, section};
pub use winding::{Inside, winding_number};
