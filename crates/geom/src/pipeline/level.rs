//! A pipeline's levels and what it says of them: [`Level`], the error of a failed step
//! ([`PipelineError`]), a run of rounding steps ([`RoundingRun`]) and which levels are kept
//! ([`Keep`]).

use crate::edge_attrs::{EdgeAttrs, EdgeKey};
use crate::mesh::PolyMesh;
use crate::refine::Provenance;
use crate::rules::{CombinationState, CornerRule};
use crate::step::{StepError, StepReport};
use crate::tags::SubdivTags;
use thiserror::Error;

/// One computed level.
#[derive(Debug, Clone)]
pub struct Level {
    pub mesh: PolyMesh,
    pub edge_attrs: EdgeAttrs,
    /// Corners, holes and options for the primal schemes. A biquadratic step keeps the
    /// options and drops corners and holes (its vertices and faces are new).
    pub tags: SubdivTags,
    /// Where its vertices, faces and edges came from (none for the input).
    pub provenance: Option<Provenance>,
    /// The combination run's state, after a combination step.
    pub combination: Option<CombinationState>,
    /// The step's report (none for the input).
    pub report: Option<StepReport>,
}

impl Level {
    /// Bytes the level holds now (its arrays' capacities, its edge marks, tags and provenance;
    /// the memory guard's accounting, [`crate::memory`]).
    pub fn bytes(&self) -> u64 {
        let m = &self.mesh;
        let mesh = 24 * m.positions.capacity()
            + 4 * (m.corner_verts.capacity() + m.loop_starts.capacity() + m.face_starts.capacity());
        // A B-tree entry: key, value and about a third again of node overhead.
        let marks =
            48 * self.edge_attrs.len() + 24 * (self.tags.corners.len() + self.tags.holes.len());
        let prov = self.provenance.as_ref().map_or(0, |p| {
            p.face_kind.capacity() + 4 * p.face_parent.capacity() + 16 * p.edge_parent.capacity()
        });
        let comb = self.combination.as_ref().map_or(0, |c| c.flags.capacity());
        (mesh + marks + prov + comb) as u64
    }
}

#[derive(Debug, Clone, PartialEq, Error)]
#[error("step {step} ({scheme}): {source}")]
pub struct PipelineError {
    /// 1-based step number.
    pub step: usize,
    pub scheme: String,
    #[source]
    pub source: StepError,
}

impl PipelineError {
    /// The message, with a mesh error of step 1 (one about the input) naming vertices and
    /// faces as `input` says its file counts them.
    pub fn describe(&self, input: &crate::numbering::Numbering) -> String {
        use crate::primal::PrimalError;
        match &self.source {
            StepError::Mesh(m) | StepError::Primal(PrimalError::Mesh(m)) if self.step == 1 => {
                format!(
                    "step {} ({}): {}",
                    self.step,
                    self.scheme,
                    input.describe(m)
                )
            }
            _ => self.to_string(),
        }
    }
}

impl Level {
    /// Frees the level's mesh, marks and provenance, keeping its report ([`Keep::Needed`]).
    pub(super) fn release(&mut self) {
        self.mesh = PolyMesh::new();
        self.edge_attrs = EdgeAttrs::new();
        self.tags.corners.clear();
        self.tags.holes.clear();
        self.provenance = None;
    }
}

/// A run of cylindrical-family steps: the level it started from, its (last) rule and the
/// radii its first step clamped (edges in that level's numbering).
#[derive(Debug, Clone, PartialEq)]
pub struct RoundingRun {
    pub start: usize,
    pub rule: CornerRule,
    pub clamped: std::collections::HashMap<EdgeKey, f64>,
}

impl RoundingRun {
    /// The radius edge `e` of the start level was rounded to: clamped, else its own, else
    /// the rule's.
    pub fn radius(&self, attrs: &EdgeAttrs, e: EdgeKey) -> Option<f64> {
        self.clamped
            .get(&e)
            .copied()
            .or_else(|| self.rule.edge_radius(attrs.get(&e)))
    }
}

/// Which levels a pipeline keeps once the level after them exists.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Keep {
    /// Every level (the app shows any of them).
    #[default]
    All,
    /// The input, the level each run of cylindrical-family steps starts from (its fillets
    /// are measured against it) and the newest level; the others are released as soon as
    /// the next level exists (the command line writes the last level only).
    Needed,
}
