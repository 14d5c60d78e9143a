//! The newest build a tab wants, made on a worker thread so that the window keeps drawing:
//! one build runs at a time; a spec that comes while it runs waits as the next (a newer one
//! replaces it, so a drag never queues more than one); the tab shows its last answer until
//! the next comes. A build that answers within the wait given is shown in the same frame.
//! Each build counts its work in a [`Progress`] the tab shows as a bar; Cancel stops it at its
//! next check and is remembered, so that the same spec is not built again until it changes.

use prism_geom::progress::Progress;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, RecvTimeoutError, TryRecvError};
use std::time::{Duration, Instant};

/// How long a frame waits for the worker's build before it shows the last one instead.
pub const BUILD_WAIT: Duration = Duration::from_millis(40);

/// A build under way.
struct Running<S, B> {
    spec: S,
    answer: Receiver<B>,
    progress: Arc<Progress>,
    started: Instant,
}

pub struct Latest<S, B> {
    running: Option<Running<S, B>>,
    next: Option<S>,
    /// The spec whose build was cancelled: not built again while it is the one wanted.
    cancelled: Option<S>,
    build: fn(&S, &Progress) -> B,
}

impl<S: Clone + PartialEq + Send + 'static, B: Send + 'static> Latest<S, B> {
    pub fn new(build: fn(&S, &Progress) -> B) -> Latest<S, B> {
        Latest {
            running: None,
            next: None,
            cancelled: None,
            build,
        }
    }

    /// Whether a build is under way or waiting.
    pub fn busy(&self) -> bool {
        self.running.is_some() || self.next.is_some()
    }

    /// The running build's part done (of its current stage) and how long it has run.
    pub fn progress(&self) -> Option<(f32, Duration)> {
        let r = self.running.as_ref()?;
        Some((r.progress.fraction() as f32, r.started.elapsed()))
    }

    /// Stops the running build at its next check and forgets the waiting one; the spec last
    /// wanted is not built again until another is wanted.
    pub fn cancel(&mut self) {
        let wanted = self
            .next
            .take()
            .or_else(|| self.running.as_ref().map(|r| r.spec.clone()));
        self.clear();
        self.cancelled = wanted;
    }

    /// Whether the spec last wanted was cancelled (and so not built).
    pub fn was_cancelled(&self) -> bool {
        self.cancelled.is_some()
    }

    /// Forgets a cancel: the spec wanted next is built, even the cancelled one.
    pub fn retry(&mut self) {
        self.cancelled = None;
    }

    /// Drops what is under way (it is told to stop; its answer is never taken) and what waits.
    pub fn clear(&mut self) {
        if let Some(r) = self.running.take() {
            r.progress.cancel();
        }
        self.next = None;
    }

    /// Asks for the build of `spec` and returns an answer that has come: `spec`'s own
    /// (waited for up to `wait`), or that of an earlier spec, newer than anything the tab
    /// has shown. A cancelled spec is not built again.
    pub fn want(&mut self, spec: &S, wait: Duration) -> Option<B> {
        if self.cancelled.as_ref() == Some(spec) {
            return None;
        }
        self.cancelled = None;
        match &self.running {
            Some(r) if &r.spec == spec => self.next = None,
            Some(_) => self.next = Some(spec.clone()),
            None => self.start(spec.clone()),
        }
        let r = self.running.as_ref()?;
        let answer = if &r.spec == spec {
            match r.answer.recv_timeout(wait) {
                Ok(b) => Some(b),
                Err(RecvTimeoutError::Timeout) => return None,
                Err(RecvTimeoutError::Disconnected) => None,
            }
        } else {
            match r.answer.try_recv() {
                Ok(b) => Some(b),
                Err(TryRecvError::Empty) => return None,
                Err(TryRecvError::Disconnected) => None,
            }
        };
        self.running = None;
        if let Some(next) = self.next.take() {
            self.start(next);
        }
        answer
    }

    fn start(&mut self, spec: S) {
        let (tx, rx) = std::sync::mpsc::channel();
        let progress = Arc::new(Progress::default());
        let (s, build, p) = (spec.clone(), self.build, progress.clone());
        std::thread::spawn(move || {
            let _ = tx.send(build(&s, &p));
        });
        self.running = Some(Running {
            spec,
            answer: rx,
            progress,
            started: Instant::now(),
        });
    }
}

/// A build shows its progress row once it has run this long: the many short builds of a drag
/// never move the panel's widgets under the pointer.
pub const SHOW_PROGRESS_AFTER: Duration = Duration::from_millis(300);

/// The row a tab shows while `latest` builds (once it has run [`SHOW_PROGRESS_AFTER`]): a bar
/// of the part done (of the build's current stage) with its seconds, saying whether the last
/// answer stays in view (`last_shown`), and Cancel; after a cancel, what the view shows and
/// Build.
pub fn progress_row<S, B>(ui: &mut egui::Ui, latest: &mut Latest<S, B>, last_shown: bool)
where
    S: Clone + PartialEq + Send + 'static,
    B: Send + 'static,
{
    match latest.progress() {
        Some((_, took)) if took < SHOW_PROGRESS_AFTER => {
            ui.ctx().request_repaint_after(SHOW_PROGRESS_AFTER - took);
        }
        Some((part, took)) => {
            let text = format!(
                "Building… {:.1} s{}",
                took.as_secs_f32(),
                if last_shown {
                    " (the last one is shown)"
                } else {
                    ""
                }
            );
            ui.horizontal(|ui| {
                ui.add(egui::ProgressBar::new(part).text(text).desired_width(230.0));
                if ui
                    .button("Cancel")
                    .on_hover_text("Stop this build; the view keeps what it shows")
                    .clicked()
                {
                    latest.cancel();
                }
            });
            ui.ctx().request_repaint_after(Duration::from_millis(30));
        }
        None if latest.was_cancelled() => {
            ui.horizontal(|ui| {
                ui.label(egui::RichText::new(if last_shown {
                    "Cancelled: the view shows the last one built"
                } else {
                    "Cancelled: nothing built"
                }));
                if ui
                    .button("Build")
                    .on_hover_text("Build what the panel says after all")
                    .clicked()
                {
                    latest.retry();
                }
            });
        }
        None => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn slow(x: &u32, _: &Progress) -> u32 {
        std::thread::sleep(Duration::from_millis(30));
        x * 10
    }

    /// Counts to `x` in steps of a millisecond, stopping when cancelled (0 then).
    fn counting(x: &u32, p: &Progress) -> u32 {
        p.restart(u64::from(*x));
        for _ in 0..*x {
            if p.check().is_err() {
                return 0;
            }
            std::thread::sleep(Duration::from_millis(1));
            p.add(1);
        }
        *x
    }

    #[test]
    fn a_drag_builds_the_first_and_the_last_spec_only() {
        let mut l = Latest::new(slow);
        let wait = Duration::ZERO;
        let mut answers = Vec::new();
        for x in 1..=5 {
            answers.extend(l.want(&x, wait));
        }
        while l.busy() {
            answers.extend(l.want(&5, Duration::from_secs(5)));
        }
        assert_eq!(answers, [10, 50]);
        assert!(
            l.want(&5, Duration::from_secs(5)).is_some(),
            "asked again: built again"
        );
    }

    #[test]
    fn a_cancelled_build_stops_and_is_not_started_again_until_the_spec_changes() {
        let mut l = Latest::new(counting);
        assert_eq!(l.want(&2, Duration::from_secs(5)), Some(2));
        assert!(l.want(&100_000, Duration::ZERO).is_none());
        assert!(l.busy() && l.progress().is_some());
        l.cancel();
        assert!(!l.busy() && l.was_cancelled() && l.progress().is_none());
        // Asked again for the same spec: nothing starts.
        assert!(l.want(&100_000, Duration::ZERO).is_none());
        assert!(!l.busy());
        // Another spec: built, and the cancel forgotten.
        assert_eq!(l.want(&3, Duration::from_secs(5)), Some(3));
        assert!(!l.was_cancelled());
        // The progress of a build runs to 1.
        assert!(l.want(&200, Duration::ZERO).is_none());
        std::thread::sleep(Duration::from_millis(50));
        let (part, _) = l.progress().unwrap();
        assert!(part > 0.0 && part < 1.0, "{part}");
    }
}
