//! No lost work: while the document has changes that are not saved, a copy is written every
//! two minutes — on a timer, whether or not the user touches the window — and when the window
//! closes, into Prism's state folder (`$XDG_STATE_HOME/prism`, else `~/.local/state/prism`).
//! Saving the document removes it. At the next start a copy left behind (the app was killed,
//! or closed without saving) is offered for restore. The copy is written like every save: to a
//! temporary file renamed into place, so a crash while writing it leaves the previous copy.
//!
//! Every window has a copy of its own, `autosave-PID-N.prism.json`, and holds an exclusive
//! lock on `autosave-PID-N.lock` while it lives: a copy whose lock can be taken is one that no
//! running window owns — left behind — and only such a copy is offered (the newest; an older
//! Prism's `autosave.prism.json` too). The window that offers a copy takes its lock, so two
//! windows never offer the same one, and "Discard" removes only that copy. While the offer is
//! unanswered the window's own work goes to its own copy; restored, the offered copy becomes
//! the window's.

use super::document::Document;
use prism_geom::io;
use std::fs::File;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant, SystemTime};

/// How often unsaved changes are copied.
pub const EVERY: Duration = Duration::from_secs(120);

/// The copy an older Prism wrote (one for every window).
const LEGACY: &str = "autosave.prism.json";
const PREFIX: &str = "autosave-";
const SUFFIX: &str = ".prism.json";

/// A copy and the lock that says a window owns it.
struct Owned {
    copy: PathBuf,
    /// Held while the window lives (none for a legacy copy, which has no lock file).
    lock: Option<File>,
}

impl Owned {
    /// The lock file of a copy `autosave-ID.prism.json`: `autosave-ID.lock`.
    fn lock_path(copy: &Path) -> Option<PathBuf> {
        let name = copy.file_name()?.to_str()?;
        let id = name.strip_prefix(PREFIX)?.strip_suffix(SUFFIX)?;
        Some(copy.with_file_name(format!("{PREFIX}{id}.lock")))
    }

    /// Takes the lock of `copy` when no running window holds it.
    fn take(copy: PathBuf) -> Option<Owned> {
        let Some(lock_path) = Owned::lock_path(&copy) else {
            return Some(Owned { copy, lock: None });
        };
        let lock = File::options()
            .create(true)
            .truncate(false)
            .write(true)
            .open(&lock_path)
            .ok()?;
        lock.try_lock().ok()?;
        Some(Owned {
            copy,
            lock: Some(lock),
        })
    }

    /// Where the document came from, beside its copy: `COPY.origin`.
    fn origin_path(copy: &Path) -> PathBuf {
        let mut name = copy.as_os_str().to_owned();
        name.push(".origin");
        PathBuf::from(name)
    }

    /// Removes the copy and its lock file (the lock goes with the window).
    fn remove(&self) {
        let _ = std::fs::remove_file(&self.copy);
        let _ = std::fs::remove_file(Owned::origin_path(&self.copy));
        if self.lock.is_some()
            && let Some(l) = Owned::lock_path(&self.copy)
        {
            let _ = std::fs::remove_file(l);
        }
    }
}

/// A fresh copy name for this window: the process id and a number unique within it, its lock
/// taken.
fn own_copy(dir: &Path) -> Option<Owned> {
    use std::sync::atomic::{AtomicU64, Ordering};
    static NEXT: AtomicU64 = AtomicU64::new(0);
    std::fs::create_dir_all(dir).ok()?;
    (0..64).find_map(|_| {
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let copy = dir.join(format!("{PREFIX}{}-{n}{SUFFIX}", std::process::id()));
        if copy.exists() {
            return None;
        }
        Owned::take(copy)
    })
}

/// The newest copy in `dir` that no running window owns, its lock taken, and when it was
/// written.
fn left_behind(dir: &Path) -> Option<(Owned, SystemTime)> {
    let mut copies: Vec<(SystemTime, PathBuf)> = std::fs::read_dir(dir)
        .ok()?
        .flatten()
        .filter(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            name == LEGACY || (name.starts_with(PREFIX) && name.ends_with(SUFFIX))
        })
        .map(|e| {
            let when = e
                .metadata()
                .and_then(|m| m.modified())
                .unwrap_or_else(|_| SystemTime::now());
            (when, e.path())
        })
        .collect();
    copies.sort_by_key(|c| std::cmp::Reverse(c.0));
    copies
        .into_iter()
        .find_map(|(when, copy)| Owned::take(copy).map(|o| (o, when)))
}

pub struct Autosave {
    /// The folder (none: autosave off, as in tests and screenshot runs).
    dir: Option<PathBuf>,
    /// This window's copy and its lock.
    own: Option<Owned>,
    /// The document generation that is saved (opened or saved by the user).
    saved: u64,
    /// The generation the copy holds.
    written: Option<u64>,
    last: Instant,
    /// A copy left by an earlier run, offered for restore, and when it was written.
    offered: Option<(Owned, SystemTime)>,
}

impl Autosave {
    /// Autosave into `dir`, for a document at `generation` as opened; a copy left behind there
    /// is offered.
    pub fn new(dir: Option<PathBuf>, generation: u64) -> Autosave {
        let offered = dir.as_deref().and_then(left_behind);
        let own = dir.as_deref().and_then(own_copy);
        Autosave {
            dir,
            own,
            saved: generation,
            written: None,
            last: Instant::now(),
            offered,
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

    /// This window's copy (when autosave is on).
    pub fn path(&self) -> Option<PathBuf> {
        self.own.as_ref().map(|o| o.copy.clone())
    }

    /// When the copy offered for restore was written (while the offer is open).
    pub fn offer(&self) -> Option<SystemTime> {
        self.offered.as_ref().map(|o| o.1)
    }

    /// The copy offered for restore (while the offer is open).
    pub fn offered_path(&self) -> Option<PathBuf> {
        self.offered.as_ref().map(|o| o.0.copy.clone())
    }

    /// The user saved or opened the document: nothing is unsaved, and the window's copy goes.
    pub fn saved(&mut self, generation: u64) {
        self.saved = generation;
        self.written = None;
        if let Some(p) = self.path() {
            let _ = std::fs::remove_file(p);
        }
    }

    /// A file was opened as the document: that is saved work (the copy of earlier unsaved work
    /// on offer stays for the next start).
    pub fn opened(&mut self, generation: u64) {
        self.saved = generation;
    }

    /// Whether the document has changes that no save or open holds.
    pub fn unsaved(&self, doc: &Document) -> bool {
        doc.generation() != self.saved
    }

    /// How long until the next copy is due, when the document has unsaved changes the copy
    /// does not hold (the window asks to be woken then, so an idle window copies too).
    pub fn due_in(&self, doc: &Document) -> Option<Duration> {
        let generation = doc.generation();
        (self.own.is_some() && generation != self.saved && self.written != Some(generation))
            .then(|| EVERY.saturating_sub(self.last.elapsed()))
    }

    /// Writes the window's copy when the document has unsaved changes it does not hold yet,
    /// and two minutes have passed since the last one (`now`: at once, as on closing). Returns
    /// whether it wrote.
    pub fn tick(&mut self, doc: &Document, now: bool) -> Result<bool, String> {
        let generation = doc.generation();
        let Some(path) = self.path() else {
            return Ok(false);
        };
        if generation == self.saved
            || self.written == Some(generation)
            || (!now && self.last.elapsed() < EVERY)
        {
            return Ok(false);
        }
        self.last = Instant::now();
        if let Some(d) = &self.dir {
            std::fs::create_dir_all(d)
                .map_err(|e| format!("autosave: cannot make {}: {e}", d.display()))?;
        }
        io::save(&path, &doc.state().to_document()).map_err(|e| format!("autosave: {e}"))?;
        // The document's name and save target, so that restored work keeps them: the name on
        // the first line, the `.prism.json` it saves to (if any) on the second.
        let origin = doc.origin();
        let target = origin.path.as_ref().map(|p| p.display().to_string());
        let text = format!("{}\n{}\n", origin.name, target.unwrap_or_default());
        io::write_atomically(&Owned::origin_path(&path), text.as_bytes())
            .map_err(|e| format!("autosave: {e}"))?;
        self.written = Some(generation);
        Ok(true)
    }

    /// The offered copy was restored into the document: it becomes the window's copy (its own,
    /// empty so far, goes), so a save removes it and a crash before the next copy keeps it.
    pub fn restored(&mut self) {
        if let Some((o, _)) = self.offered.take() {
            if let Some(own) = self.own.take() {
                own.remove();
            }
            self.own = Some(o);
            self.written = None;
        }
    }

    /// The name and save target of the work offered for restore, when its copy recorded
    /// them and they still name files (else "recovered work", with no target).
    pub fn offered_origin(&self) -> (String, Option<PathBuf>) {
        let recorded = self
            .offered_path()
            .and_then(|c| std::fs::read_to_string(Owned::origin_path(&c)).ok());
        let mut lines = recorded.as_deref().unwrap_or_default().lines();
        let name = lines.next().unwrap_or_default();
        let target = lines
            .next()
            .filter(|t| !t.is_empty())
            .map(PathBuf::from)
            .filter(|p| p.is_file());
        match target {
            Some(t) => (name.to_string(), Some(t)),
            None if Path::new(name).is_file() => (name.to_string(), None),
            None => ("recovered work".to_string(), None),
        }
    }

    /// Drops the copy that was offered (and only that one).
    pub fn discard(&mut self) {
        if let Some((o, _)) = self.offered.take() {
            o.remove();
        }
    }
}

impl Drop for Autosave {
    /// A window closing with nothing unsaved leaves no lock file behind.
    fn drop(&mut self) {
        if let Some(o) = &self.own
            && !o.copy.exists()
        {
            o.remove();
        }
    }
}
