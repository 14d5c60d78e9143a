//! The newest build a tab wants, made on a worker thread so that the window keeps drawing:
//! one build runs at a time; a spec that comes while it runs waits as the next (a newer one
//! replaces it, so a drag never queues more than one); the tab shows its last answer until
//! the next comes. A build that answers within the wait given is shown in the same frame.

use std::sync::mpsc::{Receiver, RecvTimeoutError, TryRecvError};
use std::time::Duration;

/// How long a frame waits for the worker's build before it shows the last one instead.
pub const BUILD_WAIT: Duration = Duration::from_millis(40);

pub struct Latest<S, B> {
    running: Option<(S, Receiver<B>)>,
    next: Option<S>,
    build: fn(&S) -> B,
}

impl<S: Clone + PartialEq + Send + 'static, B: Send + 'static> Latest<S, B> {
    pub fn new(build: fn(&S) -> B) -> Latest<S, B> {
        Latest {
            running: None,
            next: None,
            build,
        }
    }

    /// Whether a build is under way or waiting.
    pub fn busy(&self) -> bool {
        self.running.is_some() || self.next.is_some()
    }

    /// Drops what is under way (its answer is never taken) and what waits.
    pub fn clear(&mut self) {
        self.running = None;
        self.next = None;
    }

    /// Asks for the build of `spec` and returns an answer that has come: `spec`'s own
    /// (waited for up to `wait`), or that of an earlier spec, newer than anything the tab
    /// has shown.
    pub fn want(&mut self, spec: &S, wait: Duration) -> Option<B> {
        match &self.running {
            Some((s, _)) if s == spec => self.next = None,
            Some(_) => self.next = Some(spec.clone()),
            None => self.start(spec.clone()),
        }
        let (s, rx) = self.running.as_ref()?;
        let answer = if s == spec {
            match rx.recv_timeout(wait) {
                Ok(b) => Some(b),
                Err(RecvTimeoutError::Timeout) => return None,
                Err(RecvTimeoutError::Disconnected) => None,
            }
        } else {
            match rx.try_recv() {
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
        let (s, build) = (spec.clone(), self.build);
        std::thread::spawn(move || {
            let _ = tx.send(build(&s));
        });
        self.running = Some((spec, rx));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn slow(x: &u32) -> u32 {
        std::thread::sleep(Duration::from_millis(30));
        x * 10
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
}
