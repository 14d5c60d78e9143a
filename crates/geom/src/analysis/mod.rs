//! Analysis that the app shows and the tests assert: counts, the fillet radius reached
//! along an edge. Flipped and degenerate faces are found by each step
//! ([`crate::step::check_children`]).

mod counts;
mod fillet;

pub use counts::{MeshCounts, counts};
pub use fillet::{FilletError, FilletMeasure, measure_fillet};
