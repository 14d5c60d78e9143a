//! The free-form family: curves and patches evaluated exactly rather than refined — rational
//! Bézier curves ([`bezier`]) now; Gregory patches, skinning through cross-sections (seed 003)
//! and envelopes of primitives (seed 004) land beside them (docs/architecture.md, "Where the
//! free-form family goes").

pub mod bezier;

pub use bezier::RationalBezier;
