//! The rounding step's options: every tolerance of a biquadratic step with its doc and default,
//! in one place (docs/algorithms/biquadratic.md, "Options"). The construction reads
//! `flat_tolerance` and `overlap`; the step refuses by `memory_budget`; the mending stage
//! reads [`MendOptions`](super::mend::MendOptions).

use super::mend::MendOptions;
use super::overlap::{Overlap, ReachOptions};

/// Tunables of a rounding (biquadratic) step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoundingOptions {
    /// Edges with |bend angle| below this (radians) are flat and dissolved before a
    /// cylindrical-family step (default 1e-6).
    pub flat_tolerance: f64,
    /// A step whose result would need more bytes than this is refused before it starts
    /// (default 8 GiB; the CLI and the app give half of the memory available).
    pub memory_budget: u64,
    /// What a step does with radii whose rounds do not fit their faces, and with chamfer
    /// parameters too large for a face (default: refuse, naming them).
    pub overlap: Overlap,
    /// The combination rule's room: each cut face keeps at least `1 − step_room` of every
    /// edge when the step fits its cut widths to the faces (default 0.9: a tenth). Lower
    /// values fold less on chains of chamfers but stop the paper's fillets converging to r.
    pub step_room: f64,
    /// `|sin φ|` from which a corner of the cylindrical family takes its own plane whole
    /// (the corner plane, docs/algorithms/conventions.md); straighter corners blend towards
    /// the face normal made square to the corner's line (default 0.1).
    pub corner_plane_sin: f64,
    /// A corner is reflex enough for Doo–Sabin's width offset when `sin φ` is below minus
    /// this (default 0.17, about 10°; biquadratic.md, "Concave faces").
    pub reflex_sin: f64,
    /// The share a clamped chamfer or Doo–Sabin's offset keeps: of the face's narrowest width
    /// (the new outline), of each side's length, and of the shorter edge at a convex corner
    /// (default 0.25, what a triangle keeps at α = ¼).
    pub kept_share: f64,
    /// Passes of the overlap fit before it stops (default 64; one is the usual case).
    pub overlap_passes: usize,
    /// The mending stage's tolerances ([`super::mend`]).
    pub mend: MendOptions,
    /// How a clamped run makes sure the combination rule reaches the clamped radii.
    pub reach: ReachOptions,
}

impl Default for RoundingOptions {
    fn default() -> Self {
        RoundingOptions {
            flat_tolerance: 1e-6,
            memory_budget: 8 << 30,
            overlap: Overlap::Refuse,
            step_room: 0.9,
            corner_plane_sin: 0.1,
            reflex_sin: 0.17,
            kept_share: 0.25,
            overlap_passes: 64,
            mend: MendOptions::default(),
            reach: ReachOptions::default(),
        }
    }
}
