//! The rounding step's options: every tolerance of a biquadratic step with its doc and default,
//! in one place (docs/algorithms/biquadratic.md, "Options"). The construction reads
//! `flat_tolerance` and `overlap`; the step refuses by `memory_budget`; the mending stage
//! reads [`MendOptions`](super::mend::MendOptions).

use super::mend::MendOptions;
use super::overlap::Overlap;

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
    /// The mending stage's tolerances ([`super::mend`]).
    pub mend: MendOptions,
}

impl Default for RoundingOptions {
    fn default() -> Self {
        RoundingOptions {
            flat_tolerance: 1e-6,
            memory_budget: 8 << 30,
            overlap: Overlap::Refuse,
            mend: MendOptions::default(),
        }
    }
}
