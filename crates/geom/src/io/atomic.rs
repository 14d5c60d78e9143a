//! Writing a file through a temporary file renamed into place, keeping what the user set up
//! around the target (docs/reliability.md "Saves").
//!
//! - The bytes go to `.NAME.prism-tmp` beside the target (the final target, when the path is
//!   a symbolic link: the link stays a link and its target gets the new contents), flushed
//!   and synced, then renamed over the target, and the directory is synced after the rename.
//!   A save killed half-way leaves the old file whole and, at worst, that temporary file,
//!   which the next save to the same target overwrites; every error path removes it.
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

fn temp_path(target: &Path) -> PathBuf {
    let name = target
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    parent_dir(target).join(format!(".{name}.prism-tmp"))
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
    let tmp = temp_path(&target);
    std::fs::File::create(&tmp).map_err(|e| write_error(path, e))?;
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
    let tmp = temp_path(&target);
    let result = (|| {
        let file = std::fs::File::create(&tmp)?;
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
        // A stale temporary file of a killed save is overwritten by the next save, and no
        // temporary file is left.
        let t = d.join("t.obj");
        std::fs::write(d.join(".t.obj.prism-tmp"), "half a file").unwrap();
        write_atomically(&t, b"whole").unwrap();
        assert!(!d.join(".t.obj.prism-tmp").exists());
        assert_eq!(std::fs::read_to_string(&t).unwrap(), "whole");
        // A missing directory is named before any work.
        let e = check_writable(&d.join("no/such/dir/x.obj"), false)
            .unwrap_err()
            .to_string();
        assert!(e.contains("does not exist"), "{e}");
    }
}
