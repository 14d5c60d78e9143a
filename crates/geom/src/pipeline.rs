//! A pipeline: a list of steps applied one after the other, every level kept.
//!
//! Level 0 is the input; level k is the result of step k−1. Changing step k drops the
//! levels after k only, so the next [`Pipeline::compute`] recomputes from level k
//! (seed 000 fig. 7 is such a pipeline: vector-sum α = 0.2, then Doo–Sabin twice). A level
//! made by a combination step carries the run's [`crate::rules::CombinationState`] to the next step
//! (docs/algorithms/cylindrical.md).

use crate::analysis::{FilletError, FilletSummary, measure_fillets};
use crate::edge_attrs::{EdgeAttrs, EdgeKey};
use crate::error::OverBudget;
use crate::geometry::signed_volume;
use crate::memory;
use crate::mesh::PolyMesh;
use crate::primal::{With, refine_primal_carrying, repoint};
use crate::rules::Overlap;
use crate::rules::RoundingOptions;

use crate::scheme::Scheme;
use crate::step::{StepError, StepReport, biquadratic_step_carrying, primal_flipped};
use crate::tags::SubdivTags;
use crate::topology::Topology;
use glam::DVec3;
use std::sync::Arc;

mod estimate;
mod level;
mod reach;

pub use level::{Keep, Level, PipelineError, RoundingRun};

/// Steps and the levels computed so far.
#[derive(Debug, Clone)]
pub struct Pipeline {
    steps: Vec<Scheme>,
    levels: Vec<Level>,
    pub options: RoundingOptions,
    pub keep: Keep,
    /// The topology of level k, kept where step k is primal and every level is kept
    /// ([`Keep::All`], the app): what [`Pipeline::moved`] hands on.
    topologies: Vec<Option<Arc<Topology>>>,
    /// For a pipeline made by [`Pipeline::moved`]: for the first primal steps, the
    /// topology of level k and the level k + 1 computed before, whose faces, marks and tags
    /// step k keeps, evaluating only the points again.
    reuse: Vec<Option<Reused>>,
}

/// A level's topology and the level a primal step made from it, for moved points.
#[derive(Debug, Clone)]
struct Reused {
    topo: Arc<Topology>,
    child: Level,
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
            options: RoundingOptions::default(),
            keep: Keep::All,
            topologies: Vec::new(),
            reuse: Vec::new(),
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
            keep: self.keep,
            topologies: self.topologies.iter().take(keep).cloned().collect(),
            reuse: self.reuse.iter().take(same).cloned().collect(),
        }
    }

    /// The same steps on the input with its vertices at `positions` (the same faces, marks
    /// and tags: a cage vertex dragged). Its levels are computed again, but each primal step
    /// from the input on (up to the first step of another family, whose faces may depend on
    /// where the points lie) keeps the faces, marks, tags and topology it found here and
    /// evaluates only the points ([`crate::primal::repoint`]): the same levels, bit for bit,
    /// as a fresh pipeline gives.
    pub fn moved(&self, positions: Vec<DVec3>) -> Pipeline {
        let mut input = self.levels[0].clone();
        assert_eq!(
            positions.len(),
            input.mesh.positions.len(),
            "moved points keep the vertex count"
        );
        input.mesh.positions = positions;
        let reuse = (0..self.steps.len())
            .map_while(|k| {
                let topo = self.topologies.get(k)?.as_ref()?;
                let child = self.levels.get(k + 1)?;
                matches!(self.steps[k], Scheme::Primal(_)).then(|| {
                    Some(Reused {
                        topo: topo.clone(),
                        child: child.clone(),
                    })
                })
            })
            .collect();
        Pipeline {
            steps: self.steps.clone(),
            levels: vec![input],
            options: self.options,
            keep: self.keep,
            topologies: Vec::new(),
            reuse,
        }
    }

    /// How many steps, from the first, a [`Pipeline::moved`] pipeline will compute by
    /// evaluating points only (those not computed yet).
    pub fn reused_steps(&self) -> usize {
        self.reuse.iter().filter(|r| r.is_some()).count()
    }

    /// Whether level `k` stays once the level after it exists ([`Keep`]).
    fn kept_after_next(&self, k: usize) -> bool {
        let rounds = |i: usize| self.steps.get(i).is_some_and(Scheme::rounds_edges);
        self.keep == Keep::All || k == 0 || (rounds(k) && !rounds(k - 1))
    }

    /// Releases every level [`Keep`] does not keep (after switching to [`Keep::Needed`]),
    /// and the topologies kept for moved points.
    pub fn release_unneeded(&mut self) {
        if self.keep == Keep::Needed {
            self.topologies.clear();
            self.reuse.clear();
        }
        for k in 0..self.levels.len().saturating_sub(1) {
            if !self.kept_after_next(k) {
                self.levels[k].release();
            }
        }
    }

    /// Whether level `k` was released ([`Keep::Needed`]): its mesh is empty.
    pub fn released(&self, k: usize) -> bool {
        k + 1 < self.levels.len() && !self.kept_after_next(k)
    }

    /// Whether some step rounds edges (a run of cylindrical-family steps: its fillets can
    /// be measured).
    pub fn rounds(&self) -> bool {
        self.steps.iter().any(Scheme::rounds_edges)
    }

    /// Whether a step of `scheme` records its level's provenance: a biquadratic one always
    /// (its combination state and face kinds come from it), a primal one for the app (picking
    /// an edge on any level), not for a pipeline that keeps only what it writes.
    fn provenance(&self, scheme: &Scheme) -> bool {
        matches!(scheme, Scheme::Biquadratic(_)) || self.keep == Keep::All
    }

    /// Whether step `k` writes its level's topology down for step `k + 1`: from one
    /// biquadratic split to the next, and from one primal split to the next (a step of the
    /// other family checks its input in its own way, so it builds the topology itself).
    fn carries(&self, k: usize) -> bool {
        matches!(
            (self.steps.get(k), self.steps.get(k + 1)),
            (Some(Scheme::Biquadratic(_)), Some(Scheme::Biquadratic(_)))
                | (Some(Scheme::Primal(_)), Some(Scheme::Primal(_)))
        )
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
        // The topology a split wrote down, for the step of its family after it.
        let mut carried = None;
        while self.levels.len() <= upto {
            let k = self.levels.len() - 1;
            // A level kept after its step failed is not stepped from.
            self.check_inside_out(k)?;
            let scheme = self.steps[k];
            let err = |source: StepError| PipelineError {
                step: k + 1,
                scheme: scheme.to_string(),
                source,
            };
            // The memory guard: the levels kept and what this step will hold, before any
            // of it is built; the step's own check then sees what is left.
            let kept = self.kept_bytes() + memory::BASELINE;
            let counts = memory::Counts::of(&self.levels[k].mesh, None);
            let step = self.step_bytes(&counts, &scheme, carried.is_none(), self.carries(k));
            OverBudget::check(
                kept + step,
                self.options.memory_budget,
                counts.after(&scheme).faces,
            )
            .map_err(|o| err(StepError::TooLarge(o)))?;
            let budget = self.options.memory_budget.saturating_sub(kept);
            let prev = &self.levels[k];
            let level = match scheme {
                Scheme::Biquadratic(rule) => {
                    let next_is_biquadratic =
                        k + 1 < upto && matches!(self.steps[k + 1], Scheme::Biquadratic(_));
                    // The radii are checked against the faces when a run of
                    // cylindrical-family steps begins, and again where a step of the run
                    // changes the radius (docs/algorithms/cylindrical.md, "Overlap").
                    let radius = |s: &Scheme| match s {
                        Scheme::Biquadratic(r) => r.radius(),
                        Scheme::Primal(_) => None,
                    };
                    let continues_run = k > 0
                        && self.steps[k - 1].rounds_edges()
                        && radius(&self.steps[k - 1]) == radius(&self.steps[k]);
                    let options = RoundingOptions {
                        overlap: if continues_run {
                            Overlap::Unchecked {
                                clamped: self.options.overlap.clamps(),
                            }
                        } else {
                            self.options.overlap
                        },
                        memory_budget: budget,
                        ..self.options
                    };
                    let (out, topo) = if continues_run {
                        biquadratic_step_carrying(
                            &prev.mesh,
                            &prev.edge_attrs,
                            &rule,
                            prev.combination.as_ref(),
                            &options,
                            carried.take(),
                            next_is_biquadratic,
                        )
                    } else {
                        // The steps of the run this one begins (the same rule after it).
                        let run = self.steps[k..].iter().take_while(|s| **s == scheme).count();
                        reach::first_step(
                            prev,
                            &rule,
                            &options,
                            carried.take(),
                            next_is_biquadratic,
                            run,
                        )
                    }
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
                    let started = std::time::Instant::now();
                    let keep_topology = self.keep == Keep::All;
                    let (level, topo) = match self.reuse.get_mut(k).and_then(Option::take) {
                        // The faces, marks and topology found before; the points again.
                        Some(Reused { topo, mut child }) => {
                            let prev = &self.levels[k];
                            child.mesh.positions =
                                repoint(&prev.mesh, &topo, &prev.edge_attrs, &prev.tags, p)
                                    .map_err(|e| err(e.into()))?;
                            if let Some(r) = child.report.as_mut() {
                                r.flipped = primal_flipped(&prev.mesh, &child.mesh, p.split());
                                r.volume = signed_volume(&child.mesh);
                                r.millis = started.elapsed().as_secs_f64() * 1e3;
                            }
                            carried = None;
                            (child, Some(topo))
                        }
                        None => {
                            let prev = &self.levels[k];
                            let provenance = self.provenance(&scheme);
                            let with = With {
                                provenance,
                                known_topology: carried.take(),
                                child_topology: k + 1 < upto && self.carries(k),
                                keep_topology,
                                order: None,
                            };
                            let (out, child_topo, topo) = refine_primal_carrying(
                                &prev.mesh,
                                &prev.edge_attrs,
                                &prev.tags,
                                p,
                                budget,
                                with,
                            )
                            .map_err(|e| err(e.into()))?;
                            carried = child_topo;
                            let r = &out.report;
                            let report = StepReport {
                                vertices: r.vertices,
                                edges: r.edges,
                                faces: r.faces,
                                flipped: primal_flipped(&prev.mesh, &out.mesh, p.split()),
                                volume: signed_volume(&out.mesh),
                                millis: r.millis,
                                ..StepReport::default()
                            };
                            let level = Level {
                                mesh: out.mesh,
                                edge_attrs: out.edge_attrs,
                                tags: out.tags,
                                provenance: out.provenance,
                                combination: None,
                                report: Some(report),
                            };
                            (level, topo.map(Arc::new))
                        }
                    };
                    if keep_topology {
                        self.topologies.resize(k + 1, None);
                        self.topologies[k] = topo;
                    }
                    level
                }
            };
            self.levels.push(level);
            if !self.kept_after_next(k) {
                self.levels[k].release();
            }
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
        let rounds = Scheme::rounds_edges;
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

    /// The clamped edges of level `k`'s rounding run whose fillet at level k misses the radius
    /// they were clamped to by more than the reach tolerance ([`crate::rules::ReachOptions`]):
    /// after j steps of the run, a fillet of radius r over an edge of bend ψ is the polygon
    /// whose fitted circle has radius `r/cos(ψ/2^(j+1))`. Each with its radius and the radius
    /// measured (`None`: the section had too few points), for the CLI's warning and the app's
    /// red edges. Empty where the run clamped nothing or the level is released.
    pub fn missed_radii(&self, k: usize) -> Vec<(EdgeKey, f64, Option<f64>)> {
        let Some(run) = self.rounding_run(k) else {
            return Vec::new();
        };
        let k = k.min(self.levels.len() - 1);
        let base = &self.levels[run.start].mesh;
        let refined = &self.levels[k].mesh;
        if run.clamped.is_empty() || refined.num_faces() == 0 {
            return Vec::new();
        }
        let mut edges: Vec<(EdgeKey, f64)> = run.clamped.iter().map(|(e, r)| (*e, *r)).collect();
        edges.sort_by_key(|e| e.0);
        let Ok(measured) = crate::analysis::measure_edges(base, refined, &edges) else {
            return Vec::new();
        };
        let steps = k - run.start;
        edges
            .iter()
            .zip(measured)
            .filter_map(|(&(e, r), m)| match m {
                Ok(m) => (m.polygon_error(r, steps).abs() > self.options.reach.tolerance)
                    .then_some((e, r, Some(m.fitted_radius))),
                Err(crate::analysis::FilletError::TooFewPoints { .. }) => Some((e, r, None)),
                Err(_) => None,
            })
            .collect()
    }

    /// The newest level, the pipeline given up (the command line writes it without a copy).
    pub fn into_last(mut self) -> Level {
        self.levels.pop().expect("a pipeline has its input level")
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
