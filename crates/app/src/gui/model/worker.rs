//! Computing levels off the UI thread. A job owns a [`Pipeline`] (the levels it shares with
//! the old one already in it, see [`Pipeline::rebased`]), computes the missing levels one by
//! one on its own thread, reports each finished level, prepares the scene of the level to be
//! shown (a million triangles take 0.3–0.5 s to prepare, docs/performance.md), and hands
//! both back. Cancel is checked between levels; the window stays live meanwhile and keeps
//! showing the old result.

use prism_geom::error::OverBudget;
use prism_geom::{Pipeline, PipelineError, StepError};
use prism_viewport::{Scene, SceneOptions};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, TryRecvError, channel};
use std::time::Instant;

/// What the job prepares after the levels: the scene of one level, with the level and the
/// display options it was made for.
pub type Prepared = (usize, SceneOptions, Scene);

enum Msg {
    Level,
    Done(Box<Pipeline>, Option<PipelineError>, Option<Box<Prepared>>),
}

/// A running computation.
pub struct Job {
    rx: Receiver<Msg>,
    cancel: Arc<AtomicBool>,
    pub started: Instant,
    /// Levels finished so far, and how many the job computes.
    pub done: usize,
    pub total: usize,
    /// The levels its pipeline had when it started (the input included), and its steps.
    first: usize,
    steps: usize,
}

/// What a finished job gives back.
pub struct Finished {
    /// None when the worker thread died (a bug): the old result stays.
    pub pipeline: Option<Pipeline>,
    pub error: Option<PipelineError>,
    pub cancelled: bool,
    pub prepared: Option<Box<Prepared>>,
}

impl Job {
    /// Starts computing every missing level of `pipeline`; `wake` is called after each
    /// level (the window asks for a repaint there).
    pub fn spawn(
        mut pipeline: Pipeline,
        prepare: impl FnOnce(&Pipeline) -> Option<Prepared> + Send + 'static,
        wake: impl Fn() + Send + 'static,
    ) -> Job {
        let (tx, rx) = channel();
        let cancel = Arc::new(AtomicBool::new(false));
        let flag = cancel.clone();
        let first = pipeline.levels().len();
        let pipeline_steps = pipeline.steps().len();
        let total = (pipeline_steps + 1).saturating_sub(first);
        std::thread::spawn(move || {
            let mut error = None;
            for k in first..=pipeline.steps().len() {
                if flag.load(Ordering::Relaxed) {
                    break;
                }
                if let Err(e) = pipeline.compute_with(k, |_, _| {}) {
                    error = Some(e);
                    break;
                }
                let _ = tx.send(Msg::Level);
                wake();
            }
            let prepared = if flag.load(Ordering::Relaxed) {
                None
            } else {
                prepare(&pipeline).map(Box::new)
            };
            let _ = tx.send(Msg::Done(Box::new(pipeline), error, prepared));
            wake();
        });
        Job {
            rx,
            cancel,
            started: Instant::now(),
            done: 0,
            total,
            first,
            steps: pipeline_steps,
        }
    }

    /// The level being computed and the pipeline's length, for "level k of n": k counts
    /// from the levels the job started with, so it never passes n (the view's previous
    /// result may be longer or shorter than the job's pipeline).
    pub fn computing(&self) -> (usize, usize) {
        ((self.first + self.done).min(self.steps), self.steps)
    }

    /// Asks the job to stop after the level it is computing.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    /// The result, once the job has finished.
    pub fn poll(&mut self) -> Option<Finished> {
        loop {
            match self.rx.try_recv() {
                Ok(Msg::Level) => self.done += 1,
                Ok(Msg::Done(p, error, prepared)) => {
                    return Some(Finished {
                        pipeline: Some(*p),
                        error,
                        cancelled: self.cancel.load(Ordering::Relaxed),
                        prepared,
                    });
                }
                Err(TryRecvError::Empty) => return None,
                Err(TryRecvError::Disconnected) => {
                    return Some(Finished {
                        pipeline: None,
                        error: None,
                        cancelled: true,
                        prepared: None,
                    });
                }
            }
        }
    }

    /// Blocks until the job has finished.
    #[cfg(test)]
    pub fn wait(mut self) -> Finished {
        loop {
            if let Some(f) = self.poll() {
                return f;
            }
            std::thread::sleep(std::time::Duration::from_millis(2));
        }
    }
}

/// The memory estimate that stopped a step, if that is what stopped it.
pub fn over_budget(e: &PipelineError) -> Option<&OverBudget> {
    match &e.source {
        StepError::TooLarge(o) => Some(o),
        StepError::Primal(prism_geom::primal::PrimalError::TooLarge(o)) => Some(o),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use prism_geom::scheme::parse_pipeline;
    use prism_geom::{EdgeAttrs, primitives};

    #[test]
    fn a_job_computes_every_level_and_reports_them() {
        let steps = parse_pipeline("combination:r=0.2,combination:r=0.2,doo-sabin").unwrap();
        let p = Pipeline::new(primitives::tripod(), EdgeAttrs::new(), steps);
        let f = Job::spawn(p, |_| None, || {}).wait();
        assert!(f.error.is_none() && !f.cancelled);
        assert!(f.pipeline.unwrap().is_complete());
    }

    /// "level k of n" counts from the levels the job started with and never passes n (it
    /// read "computing level 5 of 3" when S was pressed quickly).
    #[test]
    fn the_progress_label_counts_within_the_pipeline() {
        let steps = parse_pipeline(&["combination:r=0.2"; 5].join(",")).unwrap();
        let mut p = Pipeline::new(primitives::tripod(), EdgeAttrs::new(), steps);
        p.compute_with(2, |_, _| {}).unwrap();
        // A shorter pipeline sharing those levels, as after << Back.
        let shorter = p.rebased(parse_pipeline(&["combination:r=0.2"; 3].join(",")).unwrap());
        let mut job = Job::spawn(shorter, |_| None, || {});
        assert_eq!(job.computing(), (3, 3));
        let mut seen = Vec::new();
        while job.poll().is_none() {
            seen.push(job.computing());
        }
        assert!(
            seen.iter().all(|&(k, n)| n == 3 && (1..=3).contains(&k)),
            "{seen:?}"
        );
    }

    #[test]
    fn an_over_budget_step_says_how_much_it_needs() {
        let steps = parse_pipeline("doo-sabin,doo-sabin,doo-sabin").unwrap();
        let mut p = Pipeline::new(
            primitives::torus(100, 100, 3.0, 1.0),
            EdgeAttrs::new(),
            steps,
        );
        // The process's baseline and 24 MiB: level 1 fits, level 2 does not.
        p.options.memory_budget = prism_geom::memory::BASELINE + (24 << 20);
        let f = Job::spawn(p, |_| None, || {}).wait();
        let e = f.error.expect("over the budget");
        let o = over_budget(&e).expect("an estimate");
        assert!(o.needed_mib > o.budget_mib, "{o:?}");
        assert!(f.pipeline.unwrap().levels().len() >= 2);
    }

    #[test]
    fn a_cancelled_job_stops_between_levels() {
        let steps = parse_pipeline(&["catmull-clark"; 6].join(",")).unwrap();
        let p = Pipeline::new(primitives::torus(64, 64, 3.0, 1.0), EdgeAttrs::new(), steps);
        let job = Job::spawn(p, |_| None, || {});
        job.cancel();
        let f = job.wait();
        assert!(f.cancelled);
        assert!(!f.pipeline.unwrap().is_complete());
    }
}
