//! A pipeline: a list of steps applied one after the other, every level kept.
//!
//! Level 0 is the input; level k is the result of step k−1. Changing step k drops the
//! levels after k only, so the next [`Pipeline::compute`] recomputes from level k
//! (seed 000 fig. 7 is such a pipeline: vector-sum α = 0.2, then Doo–Sabin twice). A level
//! made by a combination step carries the run's [`CombinationState`] to the next step
//! (docs/algorithms/cylindrical.md).

use crate::analysis::{FilletError, FilletSummary, measure_fillets};
use crate::edge_attrs::{EdgeAttrs, EdgeKey};
use crate::geometry::signed_volume;
use crate::mesh::PolyMesh;
use crate::primal::refine_primal;
use crate::refine::Provenance;
use crate::rules::Overlap;
use crate::rules::{CombinationState, CornerRule};
use crate::scheme::Scheme;
use crate::step::{StepError, StepOptions, StepReport, biquadratic_step_carrying};
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

/// Steps and the levels computed so far.
#[derive(Debug, Clone)]
pub struct Pipeline {
    steps: Vec<Scheme>,
    levels: Vec<Level>,
    pub options: StepOptions,
}

impl Pipeline {
    pub fn new(mesh: PolyMesh, edge_attrs: EdgeAttrs, steps: Vec<Scheme>) -> Self {
        Self::with_tags(mesh, edge_attrs, SubdivTags::default(), steps)
    }

    /// A pipeline whose input carries corners, holes and options for the primal schemes.
    pub fn with_tags(
        mesh: PolyMesh,
        edge_attrs: EdgeAttrs,
        tags: SubdivTags,
        steps: Vec<Scheme>,
    ) -> Self {
        Pipeline {
            steps,
            levels: vec![Level {
                mesh,
                edge_attrs,
                tags,
                provenance: None,
                combination: None,
                report: None,
            }],
            options: StepOptions::default(),
        }
    }

    pub fn steps(&self) -> &[Scheme] {
        &self.steps
    }
    /// Levels computed so far (level 0 is the input).
    pub fn levels(&self) -> &[Level] {
        &self.levels
    }
    pub fn input(&self) -> &Level {
        &self.levels[0]
    }

    /// A pipeline of `steps` on the same input that keeps (clones) the levels both share:
    /// those before the first step that differs. The app computes a changed pipeline from it
    /// on a worker thread while the old one stays on screen.
    pub fn rebased(&self, steps: Vec<Scheme>) -> Pipeline {
        let same = self
            .steps
            .iter()
            .zip(&steps)
            .take_while(|(a, b)| a == b)
            .count();
        let keep = (same + 1).min(self.levels.len());
        Pipeline {
            steps,
            levels: self.levels[..keep].to_vec(),
            options: self.options,
        }
    }

    /// Computes levels up to `upto` (at most the number of steps), calling `each` after every
    /// new level. Levels already computed are kept. A step that turns a solid of positive
    /// volume inside out fails ([`StepError::InsideOut`]) after its level has been kept, so
    /// that the failure can be looked at (its flipped faces); the steps after it are not
    /// computed.
    pub fn compute_with(
        &mut self,
        upto: usize,
        mut each: impl FnMut(usize, &Level),
    ) -> Result<&Level, PipelineError> {
        let upto = upto.min(self.steps.len());
        // The topology a biquadratic split wrote down, for the biquadratic step after it.
        let mut carried = None;
        while self.levels.len() <= upto {
            let k = self.levels.len() - 1;
            // A level kept after its step failed is not stepped from.
            self.check_inside_out(k)?;
            let scheme = self.steps[k];
            let prev = &self.levels[k];
            let err = |source: StepError| PipelineError {
                step: k + 1,
                scheme: scheme.to_string(),
                source,
            };
            let level = match scheme {
                Scheme::Biquadratic(rule) => {
                    let next_is_biquadratic =
                        k + 1 < upto && matches!(self.steps[k + 1], Scheme::Biquadratic(_));
                    // The radii are checked against the faces when a run of
                    // cylindrical-family steps begins (docs/algorithms/cylindrical.md).
                    let continues_run = k > 0
                        && matches!(self.steps[k - 1], Scheme::Biquadratic(r) if r.is_cylindrical_family());
                    let options = StepOptions {
                        overlap: if continues_run {
                            Overlap::Unchecked
                        } else {
                            self.options.overlap
                        },
                        ..self.options
                    };
                    let (out, topo) = biquadratic_step_carrying(
                        &prev.mesh,
                        &prev.edge_attrs,
                        &rule,
                        prev.combination.as_ref(),
                        &options,
                        carried.take(),
                        next_is_biquadratic,
                    )
                    .map_err(err)?;
                    carried = topo;
                    Level {
                        mesh: out.mesh,
                        edge_attrs: out.edge_attrs,
                        tags: SubdivTags {
                            corners: Default::default(),
                            holes: Default::default(),
                            ..prev.tags.clone()
                        },
                        provenance: Some(out.provenance),
                        combination: out.combination,
                        report: Some(out.report),
                    }
                }
                Scheme::Primal(p) => {
                    let out = refine_primal(
                        &prev.mesh,
                        &prev.edge_attrs,
                        &prev.tags,
                        p,
                        self.options.memory_budget,
                    )
                    .map_err(|e| err(e.into()))?;
                    let r = &out.report;
                    let report = StepReport {
                        vertices: r.vertices,
                        edges: r.edges,
                        faces: r.faces,
                        volume: signed_volume(&out.mesh),
                        millis: r.millis,
                        ..StepReport::default()
                    };
                    Level {
                        mesh: out.mesh,
                        edge_attrs: out.edge_attrs,
                        tags: out.tags,
                        provenance: out.provenance,
                        combination: None,
                        report: Some(report),
                    }
                }
            };
            self.levels.push(level);
            each(k + 1, self.levels.last().expect("just pushed"));
            self.check_inside_out(k + 1)?;
        }
        Ok(&self.levels[upto])
    }

    /// The failure of step `k` when it turned a solid of positive volume inside out.
    fn check_inside_out(&self, k: usize) -> Result<(), PipelineError> {
        let (Some(prev), Some(r)) = (
            k.checked_sub(1).map(|j| &self.levels[j]),
            self.levels[k].report.as_ref(),
        ) else {
            return Ok(());
        };
        let before = prev
            .report
            .as_ref()
            .map_or_else(|| signed_volume(&prev.mesh), |p| p.volume);
        if before > 0.0 && r.volume < 0.0 {
            return Err(PipelineError {
                step: k,
                scheme: self.steps[k - 1].to_string(),
                source: StepError::InsideOut {
                    before,
                    after: r.volume,
                    flipped: r.flipped.len(),
                },
            });
        }
        Ok(())
    }

    /// The run of cylindrical-family steps whose rounds level `k` shows: the last such run
    /// that starts before level `k`, or `None` when no step up to `k` rounds edges.
    pub fn rounding_run(&self, k: usize) -> Option<RoundingRun> {
        let k = k.min(self.levels.len() - 1);
        let rounds = |s: &Scheme| matches!(s, Scheme::Biquadratic(r) if r.is_cylindrical_family());
        let last = (0..k).rev().find(|&i| rounds(&self.steps[i]))?;
        let start = (0..=last)
            .rev()
            .take_while(|&i| rounds(&self.steps[i]))
            .last()
            .unwrap_or(last);
        let Scheme::Biquadratic(rule) = self.steps[last] else {
            unreachable!("a rounding step is biquadratic")
        };
        let clamped = self.levels[start + 1]
            .report
            .as_ref()
            .map(|r| {
                r.clamped
                    .iter()
                    .map(|f| (EdgeKey::new(f.a, f.b), f.fits))
                    .collect()
            })
            .unwrap_or_default();
        Some(RoundingRun {
            start,
            rule,
            clamped,
        })
    }

    /// The fillets level `k` reached on every rounded edge of the level its rounding run
    /// started from ([`Pipeline::rounding_run`]; `None` when there is none).
    pub fn measure_fillets(
        &self,
        k: usize,
    ) -> Option<Result<(RoundingRun, Option<FilletSummary>), FilletError>> {
        let run = self.rounding_run(k)?;
        let base = &self.levels[run.start];
        let refined = &self.levels[k.min(self.levels.len() - 1)].mesh;
        Some(
            measure_fillets(&base.mesh, refined, &|e| run.radius(&base.edge_attrs, e))
                .map(|s| (run, s)),
        )
    }

    /// Whether every step has its level.
    pub fn is_complete(&self) -> bool {
        self.levels.len() == self.steps.len() + 1
    }

    /// Computes every step.
    pub fn compute(&mut self) -> Result<&Level, PipelineError> {
        let n = self.steps.len();
        self.compute_with(n, |_, _| {})
    }
}
