//! No lost work (issue 15): while the document has changes that are not saved, a copy is
//! written every two minutes and when the window closes, to `autosave.prism.json` in Prism's
//! state folder (`$XDG_STATE_HOME/prism`, else `~/.local/state/prism`). Saving the document
//! removes it. At the next start a copy left behind (the app was killed, or closed without
//! saving) is offered for restore. The copy is written like every save: to a temporary file
//! renamed into place, so a crash while writing it leaves the previous copy.

use super::document::Document;
use prism_geom::io;
use std::path::PathBuf;
use std::time::{Duration, Instant, SystemTime};

/// How often unsaved changes are copied.
pub const EVERY: Duration = Duration::from_secs(120);

const FILE: &str = "autosave.prism.json";

pub struct Autosave {
    /// The folder (none: autosave off, as in tests and screenshot runs).
    dir: Option<PathBuf>,
    /// The document generation that is saved (opened or saved by the user).
    saved: u64,
    /// The generation the copy holds.
    written: Option<u64>,
    last: Instant,
    /// When a copy left by an earlier run was written: offered for restore.
    pub offer: Option<SystemTime>,
}

impl Autosave {
    /// Autosave into `dir`, for a document at `generation` as opened; a copy already there is
    /// offered.
    pub fn new(dir: Option<PathBuf>, generation: u64) -> Autosave {
        let offer = dir
            .as_ref()
            .and_then(|d| std::fs::metadata(d.join(FILE)).ok())
            .map(|m| m.modified().unwrap_or_else(|_| SystemTime::now()));
        Autosave {
            dir,
            saved: generation,
            written: None,
            last: Instant::now(),
            offer,
        }
    }

    /// Prism's state folder, if the environment names one.
    pub fn default_dir() -> Option<PathBuf> {
        let state = std::env::var_os("XDG_STATE_HOME")
            .filter(|s| !s.is_empty())
            .map(PathBuf::from)
            .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".local/state")))?;
        Some(state.join("prism"))
    }

    /// The copy's path (when autosave is on).
    pub fn path(&self) -> Option<PathBuf> {
        self.dir.as_ref().map(|d| d.join(FILE))
    }

    /// The user saved or opened the document: nothing is unsaved, and the copy goes.
    pub fn saved(&mut self, generation: u64) {
        self.saved = generation;
        self.written = None;
        if self.offer.is_none()
            && let Some(p) = self.path()
        {
            let _ = std::fs::remove_file(p);
        }
    }

    /// A file was opened as the document: that is saved work (a copy of earlier unsaved work
    /// stays for the next start).
    pub fn opened(&mut self, generation: u64) {
        self.saved = generation;
    }

    /// Writes the copy when the document has unsaved changes it does not hold yet, and two
    /// minutes have passed since the last one (`now`: at once, as on closing). Returns whether
    /// it wrote.
    pub fn tick(&mut self, doc: &Document, now: bool) -> Result<bool, String> {
        let generation = doc.generation();
        let Some(path) = self.path() else {
            return Ok(false);
        };
        if generation == self.saved
            || self.written == Some(generation)
            || (!now && self.last.elapsed() < EVERY)
            || self.offer.is_some()
        {
            return Ok(false);
        }
        self.last = Instant::now();
        if let Some(d) = &self.dir {
            std::fs::create_dir_all(d)
                .map_err(|e| format!("autosave: cannot make {}: {e}", d.display()))?;
        }
        io::save(&path, &doc.state().to_document()).map_err(|e| format!("autosave: {e}"))?;
        self.written = Some(generation);
        Ok(true)
    }

    /// Drops the copy left by an earlier run.
    pub fn discard(&mut self) {
        self.offer = None;
        if let Some(p) = self.path() {
            let _ = std::fs::remove_file(p);
        }
    }
}
