//! Writing a file through a temporary file renamed into place, keeping what the user set up
//! around the target (docs/reliability.md "Saves").
//!
//! - The bytes go to a temporary file of its own beside the target,
//!   `.NAME.PID-N.prism-tmp` (the process id and a number unique within the process, created
//!   only if it does not exist), flushed and synced, then renamed over the target, and the
//!   directory is synced after the rename. Two saves to one target never share a temporary:
//!   the target ends as one of the two whole outputs. The target is the final one when the
//!   path is a symbolic link: the link stays a link and its target gets the new contents.
//!   A save killed half-way leaves the old file whole and, at worst, its temporary file, which
//!   a later save to the same target removes once it is an hour old (a temporary being written
//!   is younger); every error path removes its own.
//! - The new file gets the old one's permission bits (a 0600 file stays 0600).
//! - A read-only target is refused; [`forced`] runs a save that may replace one (the
//!   commands' `--force`), giving the file its bits back after.
//!
//! What it cannot keep: hard links (an atomic rename makes a new inode), and the owner when
//! another user's file is written.

use super::IoError;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The file a save to `path` writes: `path` itself, or the final target of a symbolic link
/// (a dangling link's target, resolved beside the link).
pub fn save_target(path: &Path) -> PathBuf {
    match std::fs::symlink_metadata(path) {
        Ok(m) if m.file_type().is_symlink() => std::fs::canonicalize(path).unwrap_or_else(|_| {
            let link = std::fs::read_link(path).unwrap_or_default();
            match path.parent() {
                Some(dir) if link.is_relative() => dir.join(link),
                _ => link,
            }
        }),
        _ => path.to_path_buf(),
    }
}

fn parent_dir(path: &Path) -> PathBuf {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// The name of a temporary of `target` starts with this, and ends with [`TEMP_SUFFIX`].
fn temp_prefix(target: &Path) -> String {
    let name = target
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    format!(".{name}.")
}

const TEMP_SUFFIX: &str = ".prism-tmp";

/// A temporary file of its own for a save to `target`, created empty beside it: the process
/// id and a number unique within the process, tried until the name is free.
fn new_temp(target: &Path) -> std::io::Result<(PathBuf, std::fs::File)> {
    use std::sync::atomic::{AtomicU64, Ordering};
    static NEXT: AtomicU64 = AtomicU64::new(0);
    let dir = parent_dir(target);
    let prefix = temp_prefix(target);
    loop {
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let path = dir.join(format!("{prefix}{}-{n}{TEMP_SUFFIX}", std::process::id()));
        match std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&path)
        {
            Ok(f) => return Ok((path, f)),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        }
    }
}

/// How old an unrenamed temporary must be before a save to the same target removes it: a save
/// streams its temporary from start to end, so one being written is far younger.
const STALE: std::time::Duration = std::time::Duration::from_secs(3600);

/// Removes the temporaries of saves to `target` that were killed half-way (older than
/// [`STALE`]); a temporary another save is writing is left alone.
fn remove_stale_temps(target: &Path) {
    let prefix = temp_prefix(target);
    let Ok(entries) = std::fs::read_dir(parent_dir(target)) else {
        return;
    };
    for e in entries.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        if !(name.starts_with(&prefix) && name.ends_with(TEMP_SUFFIX)) {
            continue;
        }
        let old = e
            .metadata()
            .and_then(|m| m.modified())
            .ok()
            .and_then(|t| t.elapsed().ok())
            .is_some_and(|age| age > STALE);
        if old {
            let _ = std::fs::remove_file(e.path());
        }
    }
}

fn write_error(path: &Path, source: std::io::Error) -> IoError {
    IoError::Write {
        path: path.into(),
        source,
    }
}

/// What every save to `path` checks first: the file it writes ([`save_target`]) has a name,
/// and, unless `force`, is not read-only. Returns that file and its metadata when it exists.
fn target_of(path: &Path, force: bool) -> Result<(PathBuf, Option<std::fs::Metadata>), IoError> {
    let target = save_target(path);
    if target.file_name().is_none() {
        return Err(write_error(path, std::io::Error::other("no file name")));
    }
    let old = std::fs::metadata(&target).ok();
    if !force && old.as_ref().is_some_and(|m| m.permissions().readonly()) {
        return Err(write_error(
            path,
            std::io::Error::other("the file is read-only"),
        ));
    }
    Ok((target, old))
}

/// Checks, before any work, that a save to `path` can happen: its directory exists and
/// takes a new file, and the target is not read-only (unless `force`).
pub fn check_writable(path: &Path, force: bool) -> Result<(), IoError> {
    let (target, _) = target_of(path, force)?;
    let dir = parent_dir(&target);
    if !dir.is_dir() {
        return Err(write_error(
            path,
            std::io::Error::other(format!("the directory {} does not exist", dir.display())),
        ));
    }
    // A temporary of its own, so that another save's is never touched.
    let (tmp, _) = new_temp(&target).map_err(|e| write_error(path, e))?;
    let _ = std::fs::remove_file(&tmp);
    Ok(())
}

/// Runs a save `f` to `path` that may replace a read-only target: the target is made
/// writable for the save and given its old permission bits back after (the `--force` of the
/// commands). Without a read-only target it is just `f`.
pub fn forced<T>(path: &Path, f: impl FnOnce() -> Result<T, IoError>) -> Result<T, IoError> {
    let target = save_target(path);
    let Ok(m) = std::fs::metadata(&target) else {
        return f();
    };
    if !m.permissions().readonly() {
        return f();
    }
    let old = m.permissions();
    let mut w = old.clone();
    #[allow(clippy::permissions_set_readonly_false)]
    w.set_readonly(false);
    let _ = std::fs::set_permissions(&target, w);
    let out = f();
    let _ = std::fs::set_permissions(&target, old);
    out
}

/// Writes `bytes` to `path` atomically; a read-only target is refused (see [`forced`]).
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), IoError> {
    write_atomically_with(path, |w| w.write_all(bytes))
}

/// [`write_atomically`] with the contents streamed by `write` through a buffer into the
/// temporary file: nothing is built whole in memory.
pub fn write_atomically_with(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> Result<(), IoError> {
    let (target, old) = target_of(path, false)?;
    let (tmp, file) = new_temp(&target).map_err(|e| write_error(path, e))?;
    let result = (|| {
        let mut w = std::io::BufWriter::with_capacity(1 << 20, file);
        write(&mut w)?;
        let f = w.into_inner().map_err(|e| e.into_error())?;
        if let Some(m) = &old {
            // The old file's bits (a read-only file never gets here: `forced` makes it
            // writable for the save and gives it its bits back after).
            f.set_permissions(m.permissions())?;
        }
        f.sync_all()?;
        drop(f);
        std::fs::rename(&tmp, &target)?;
        // The rename is durable once the directory is synced (not possible everywhere).
        if let Ok(d) = std::fs::File::open(parent_dir(&target)) {
            let _ = d.sync_all();
        }
        remove_stale_temps(&target);
        Ok(())
    })();
    if let Err(e) = result {
        let _ = std::fs::remove_file(&tmp);
        return Err(write_error(path, e));
    }
    Ok(())
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;
    use std::os::unix::fs::PermissionsExt;

    #[test]
    fn permissions_links_read_only_and_stale_temporaries() {
        let scratch = tempfile::tempdir().unwrap();
        let d = scratch.path();
        // Permission bits are kept.
        let f = d.join("private.obj");
        std::fs::write(&f, "old").unwrap();
        std::fs::set_permissions(&f, std::fs::Permissions::from_mode(0o600)).unwrap();
        write_atomically(&f, b"new").unwrap();
        assert_eq!(std::fs::read_to_string(&f).unwrap(), "new");
        let mode = std::fs::metadata(&f).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o600);
        // A symbolic link stays a link; its target gets the contents.
        let real = d.join("real.obj");
        std::fs::write(&real, "old").unwrap();
        let link = d.join("link.obj");
        let _ = std::fs::remove_file(&link);
        std::os::unix::fs::symlink(&real, &link).unwrap();
        write_atomically(&link, b"through the link").unwrap();
        assert!(
            std::fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        assert_eq!(std::fs::read_to_string(&real).unwrap(), "through the link");
        // A read-only file is refused, then replaced when forced (and stays read-only).
        let ro = d.join("ro.obj");
        let _ = std::fs::remove_file(&ro);
        std::fs::write(&ro, "keep").unwrap();
        std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o444)).unwrap();
        let e = write_atomically(&ro, b"x").unwrap_err().to_string();
        assert!(e.contains("read-only"), "{e}");
        assert!(check_writable(&ro, false).is_err() && check_writable(&ro, true).is_ok());
        assert_eq!(std::fs::read_to_string(&ro).unwrap(), "keep");
        forced(&ro, || write_atomically(&ro, b"forced")).unwrap();
        assert_eq!(std::fs::read_to_string(&ro).unwrap(), "forced");
        assert!(std::fs::metadata(&ro).unwrap().permissions().readonly());
        // A stale temporary file of a killed save (an hour old) is removed by the next save to
        // the same target; a fresh one (another save under way) is left; no temporary of its
        // own is left.
        let t = d.join("t.obj");
        let stale = d.join(".t.obj.1-0.prism-tmp");
        let busy = d.join(".t.obj.2-0.prism-tmp");
        std::fs::write(&stale, "half a file").unwrap();
        std::fs::File::options()
            .write(true)
            .open(&stale)
            .unwrap()
            .set_modified(std::time::SystemTime::now() - 2 * STALE)
            .unwrap();
        std::fs::write(&busy, "being written").unwrap();
        write_atomically(&t, b"whole").unwrap();
        assert!(!stale.exists() && busy.exists());
        assert_eq!(std::fs::read_to_string(&t).unwrap(), "whole");
        let temps = |d: &Path| {
            std::fs::read_dir(d)
                .unwrap()
                .flatten()
                .filter(|e| e.file_name().to_string_lossy().ends_with(TEMP_SUFFIX))
                .count()
        };
        assert_eq!(temps(d), 1);
        // The pre-flight check of another save leaves the busy one alone.
        check_writable(&t, false).unwrap();
        assert!(busy.exists());
        // A missing directory is named before any work.
        let e = check_writable(&d.join("no/such/dir/x.obj"), false)
            .unwrap_err()
            .to_string();
        assert!(e.contains("does not exist"), "{e}");
    }
}

/// Two saves to one target at once: each writes its own temporary, so the target ends as one
/// of the two whole outputs, never a mix, and a third command's pre-flight check on the same
/// target leaves their temporaries alone.
#[cfg(test)]
#[test]
fn two_saves_to_one_target_never_mix() {
    let scratch = tempfile::tempdir().unwrap();
    let target = scratch.path().join("same.obj");
    let outputs: Vec<Vec<u8>> = (0..2u8)
        .map(|k| {
            (0..4_000_000u32)
                .map(|i| b'a' + k + (i % 7 == 0) as u8 * 2)
                .collect()
        })
        .collect();
    for _ in 0..5 {
        std::thread::scope(|s| {
            for out in &outputs {
                let target = &target;
                s.spawn(move || {
                    write_atomically_with(target, |w| {
                        for chunk in out.chunks(1 << 16) {
                            w.write_all(chunk)?;
                            std::thread::yield_now();
                        }
                        Ok(())
                    })
                    .unwrap()
                });
            }
            s.spawn(|| {
                for _ in 0..20 {
                    check_writable(&target, false).unwrap();
                }
            });
        });
        let written = std::fs::read(&target).unwrap();
        assert!(outputs.contains(&written), "a mix of the two outputs");
    }
}
