//! Whether the level shown passes through itself ([`prism_geom::analysis::crossings`]):
//! faces that cut through each other while every one still faces outward, which the step's
//! flip test cannot see (a thin plate whose two sides meet after Catmull–Clark and three
//! combination steps on the Computer room; docs/algorithms/cylindrical.md, "Random mixes").
//!
//! The check runs on a thread once the pipeline has finished, one at a time per view: a
//! check for a level no longer shown is left to finish and its answer dropped before the
//! next starts, so dragging a vertex never piles up checks. It takes about 0.3 s for 130,000
//! faces on two cores (1.5 s and 35 MB for 516,000), so levels over [`AUTO_FACES`]
//! faces are checked when the status bar's button asks. The faces found are painted red over
//! the scene and listed in the status bar.

use prism_geom::Level;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, TryRecvError};

/// Levels with at most this many faces are checked without being asked.
pub const AUTO_FACES: usize = 1_000_000;

/// A level of a given result: (generation, level).
pub type LevelKey = (u64, usize);

/// Pairs of faces `(f, g)`, `f < g`, that pass through each other.
pub type Pairs = Arc<Vec<(u32, u32)>>;

enum Slot {
    Computing(Receiver<Vec<(u32, u32)>>),
    Ready(Pairs),
}

/// What the status bar says of the level shown.
#[derive(Debug, Clone, PartialEq)]
pub enum Crossings {
    /// Not checked yet (the pipeline is still computing, or another check is finishing).
    Waiting,
    /// Being checked.
    Checking,
    /// Over [`CrossingCheck::auto_faces`] faces: checked when asked.
    Ask {
        faces: usize,
    },
    Done(Pairs),
}

/// One view's check.
pub struct CrossingCheck {
    /// Levels with more faces are checked when asked ([`AUTO_FACES`]).
    pub auto_faces: usize,
    state: Option<(LevelKey, Slot)>,
    /// The big level the user asked to check.
    asked: Option<LevelKey>,
    /// The scene (by its serial) the faces were painted on.
    pub painted: Option<u64>,
}

impl Default for CrossingCheck {
    fn default() -> Self {
        CrossingCheck {
            auto_faces: AUTO_FACES,
            state: None,
            asked: None,
            painted: None,
        }
    }
}

impl CrossingCheck {
    /// Takes a finished check's answer; starts one for `key` (level `lv`) when none runs,
    /// `idle` (no pipeline job) and the level is small enough or was asked for.
    pub fn poll(
        &mut self,
        key: LevelKey,
        lv: &Level,
        idle: bool,
        wake: &crate::gui::waker::Waker,
    ) -> Crossings {
        if let Some((k, Slot::Computing(rx))) = &mut self.state {
            let k = *k;
            match rx.try_recv() {
                Ok(pairs) => self.state = Some((k, Slot::Ready(Arc::new(pairs)))),
                Err(TryRecvError::Empty) if k == key => return Crossings::Checking,
                Err(TryRecvError::Empty) => return Crossings::Waiting,
                Err(TryRecvError::Disconnected) => self.state = None,
            }
        }
        if let Some((k, Slot::Ready(p))) = &self.state
            && *k == key
        {
            return Crossings::Done(p.clone());
        }
        if !idle {
            return Crossings::Waiting;
        }
        let faces = lv.mesh.num_faces();
        if faces > self.auto_faces && self.asked != Some(key) {
            return Crossings::Ask { faces };
        }
        let (tx, rx) = std::sync::mpsc::channel();
        let (mesh, w) = (lv.mesh.clone(), wake.clone());
        std::thread::spawn(move || {
            let _ = tx.send(prism_geom::analysis::crossings(&mesh));
            w();
        });
        self.state = Some((key, Slot::Computing(rx)));
        self.painted = None;
        Crossings::Checking
    }

    /// The answer for `key` as it stands, without polling.
    pub fn state(&self, key: LevelKey, faces: usize) -> Crossings {
        match &self.state {
            Some((k, Slot::Ready(p))) if *k == key => Crossings::Done(p.clone()),
            Some((k, Slot::Computing(_))) if *k == key => Crossings::Checking,
            _ if faces > self.auto_faces && self.asked != Some(key) => Crossings::Ask { faces },
            _ => Crossings::Waiting,
        }
    }

    /// Checks the big level `key` at the next poll.
    pub fn ask(&mut self, key: LevelKey) {
        self.asked = Some(key);
    }
}
