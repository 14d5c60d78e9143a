//! Files: OBJ (read in one pass, polygons kept as they are), STL (its facets welded into a
//! solid), PLY (read only: its vertices and polygons), the native `.prism.json` document, and the JSON inputs of the curve, skin and envelope commands. Every write goes to a temporary file in the same folder that is renamed into
//! place, so a failed save never destroys the previous file.

mod atomic;
mod document;
mod export;
mod inputs;
mod obj;
mod obj_lines;
mod obj_tags;
mod ply;
mod stl;
mod validate;

pub use atomic::{check_writable, forced, save_target, write_atomically, write_atomically_with};
pub use document::{DOCUMENT_VERSION, Document, document_from_str, read_document, write_document};
pub use export::{ExportFormat, Normals, export, glb_bytes, stl_bytes};
pub use inputs::{
    POLYLINE_SHAPE, SCENE_SHAPE, SECTIONS_SHAPE, polyline_from_str, scene_from_str,
    sections_from_str,
};
pub use obj::{
    ObjModel, obj_to_string, read_obj, read_obj_str, read_obj_with, write_obj,
    write_obj_with_normals, write_point_lines,
};
pub use obj_lines::polylines_from_str as obj_polylines_from_str;
pub use validate::validate_model;

pub use crate::numbering::Numbering;
use crate::progress::Progress;
use std::path::{Path, PathBuf};
use thiserror::Error;

#[derive(Debug, Error)]
pub enum IoError {
    #[error("cannot read {path}: {source}")]
    Read {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("cannot write {path}: {source}")]
    Write {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{path}{}: {message}", line.map(|l| format!(", line {l}")).unwrap_or_default())]
    Obj {
        path: PathBuf,
        line: Option<usize>,
        message: String,
    },
    #[error("{path}, line {line}, column {column}: {message}")]
    Json {
        path: PathBuf,
        line: usize,
        column: usize,
        message: String,
    },
    #[error(
        "{path}: document version {found} is not supported (this Prism reads version {DOCUMENT_VERSION})"
    )]
    UnknownVersion { path: PathBuf, found: u64 },
    #[error("{path}: {message}")]
    Invalid { path: PathBuf, message: String },
    #[error("{path}: unknown file type (use .obj, .stl, .ply or .prism.json)")]
    UnknownExtension { path: PathBuf },
    #[error(
        "{path}: Prism reads PLY but does not write it: save as .prism.json or .obj, or export .stl or .glb"
    )]
    ReadOnlyKind { path: PathBuf },
    #[error("opening {path} was cancelled")]
    Cancelled { path: PathBuf },
}

/// The kinds of file Prism reads and writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    Obj,
    Document,
    /// Read as a solid (its facets welded); written as the export writes it.
    Stl,
    /// Read only (ASCII or binary; its vertices and faces).
    Ply,
}

impl FileKind {
    pub fn of(path: &Path) -> Result<FileKind, IoError> {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().to_lowercase())
            .unwrap_or_default();
        if name.ends_with(".obj") {
            Ok(FileKind::Obj)
        } else if name.ends_with(".stl") {
            Ok(FileKind::Stl)
        } else if name.ends_with(".ply") {
            Ok(FileKind::Ply)
        } else if name.ends_with(".prism.json") || name.ends_with(".json") {
            Ok(FileKind::Document)
        } else {
            Err(IoError::UnknownExtension { path: path.into() })
        }
    }
}

/// Loads an OBJ or a `.prism.json` as a document (an OBJ gives no pipeline); also returns
/// how the file counts its vertices and faces, for messages about them.
pub fn load(path: &Path) -> Result<(Document, Numbering), IoError> {
    load_with(path, &Progress::default())
}

/// As [`load`], adding to `progress` as it reads and parses, and stopping with
/// [`IoError::Cancelled`] between blocks and chunks once it is cancelled (the app's Open of a
/// big file runs it on a thread behind a progress bar with Cancel).
pub fn load_with(path: &Path, progress: &Progress) -> Result<(Document, Numbering), IoError> {
    let loaded = match FileKind::of(path)? {
        FileKind::Obj => from_obj(read_obj_with(path, progress)?),
        FileKind::Document => {
            let bytes = read_bytes(path, progress, 1)?;
            let text = String::from_utf8(bytes).map_err(|e| IoError::Read {
                path: path.into(),
                source: std::io::Error::new(std::io::ErrorKind::InvalidData, e),
            })?;
            (document_from_str(path, &text)?, Numbering::default())
        }
        FileKind::Stl => stl::read_stl_bytes(path, &read_bytes(path, progress, 1)?)?,
        FileKind::Ply => ply::read_ply_bytes(path, &read_bytes(path, progress, 1)?)?,
    };
    progress
        .check()
        .map_err(|_| IoError::Cancelled { path: path.into() })?;
    checked(path, loaded)
}

/// The bytes of a file, read in blocks of 8 MiB: each adds its length to `progress`, whose
/// total is set to `parts` times the file's size (the reading is one part of the job), and
/// the reading stops between blocks once `progress` is cancelled.
fn read_bytes(path: &Path, progress: &Progress, parts: u64) -> Result<Vec<u8>, IoError> {
    use std::io::Read;
    const BLOCK: u64 = 8 << 20;
    let read_err = |source| IoError::Read {
        path: path.into(),
        source,
    };
    let mut file = std::fs::File::open(path).map_err(read_err)?;
    let size = file.metadata().map_err(read_err)?.len();
    progress.set_total(parts * size.max(1));
    let mut bytes = Vec::new();
    bytes
        .try_reserve_exact(size as usize + 1)
        .map_err(|e| read_err(std::io::Error::new(std::io::ErrorKind::OutOfMemory, e)))?;
    loop {
        progress
            .check()
            .map_err(|_| IoError::Cancelled { path: path.into() })?;
        let n = (&mut file)
            .take(BLOCK)
            .read_to_end(&mut bytes)
            .map_err(read_err)?;
        if n == 0 {
            return Ok(bytes);
        }
        progress.add(n as u64);
    }
}

/// As [`load`], for bytes already in memory (STL may be binary; the other kinds are text).
pub fn load_bytes(path: &Path, bytes: &[u8]) -> Result<(Document, Numbering), IoError> {
    match FileKind::of(path)? {
        FileKind::Stl => checked(path, stl::read_stl_bytes(path, bytes)?),
        FileKind::Ply => checked(path, ply::read_ply_bytes(path, bytes)?),
        _ => load_str(path, &String::from_utf8_lossy(bytes)),
    }
}

/// As [`load`], for text already in memory (the app's bundled samples); the kind comes
/// from `path`'s name, which messages quote.
pub fn load_str(path: &Path, text: &str) -> Result<(Document, Numbering), IoError> {
    let loaded = match FileKind::of(path)? {
        FileKind::Obj => from_obj(read_obj_str(path, text)?),
        FileKind::Document => (document_from_str(path, text)?, Numbering::default()),
        FileKind::Stl => stl::read_stl_bytes(path, text.as_bytes())?,
        FileKind::Ply => ply::read_ply_bytes(path, text.as_bytes())?,
    };
    checked(path, loaded)
}

/// A document read from OBJ, and how the file numbers its vertices and faces.
fn from_obj(m: ObjModel) -> (Document, Numbering) {
    (
        Document {
            mesh: m.mesh,
            edge_attrs: m.edge_attrs,
            tags: m.tags,
            ..Document::default()
        },
        Numbering::obj(m.vertex_lines, m.face_lines),
    )
}

/// `loaded`, once the one validation of a model (either reader's) accepts it.
fn checked(path: &Path, loaded: (Document, Numbering)) -> Result<(Document, Numbering), IoError> {
    let d = &loaded.0;
    validate_model(&d.mesh, &d.edge_attrs, &d.tags, &loaded.1).map_err(|message| {
        IoError::Invalid {
            path: path.into(),
            message,
        }
    })?;
    Ok(loaded)
}

/// Saves a document as OBJ or `.prism.json` by the file name; returns warnings (e.g. holed
/// faces triangulated for OBJ).
/// Every writer's first check (OBJ, `.prism.json`, STL, glTF): no point of `mesh` is NaN or
/// infinite — a file holding one is refused by every reader, Prism's own included, so nothing
/// is written and the first bad vertex is named.
pub(crate) fn check_finite_points(
    path: &Path,
    mesh: &crate::mesh::PolyMesh,
) -> Result<(), IoError> {
    match mesh.positions.iter().position(|p| !p.is_finite()) {
        None => Ok(()),
        Some(v) => Err(IoError::Invalid {
            path: path.into(),
            message: format!(
                "vertex {v} is not a finite point ({}): nothing was written",
                mesh.positions[v]
            ),
        }),
    }
}

pub fn save(path: &Path, doc: &Document) -> Result<Vec<String>, IoError> {
    match FileKind::of(path)? {
        FileKind::Obj => write_obj(path, &doc.mesh, &doc.edge_attrs, &doc.tags),
        FileKind::Document => write_document(path, doc).map(|_| Vec::new()),
        FileKind::Stl => {
            check_finite_points(path, &doc.mesh)?;
            write_atomically(path, &stl_bytes(&doc.mesh, &|_| false)).map(|_| {
                vec![
                    "STL keeps the facets only: the pipeline, creases and tags are not in it"
                        .into(),
                ]
            })
        }
        FileKind::Ply => Err(IoError::ReadOnlyKind { path: path.into() }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// No writer writes a point that is not finite: OBJ, `.prism.json`, STL and glTF each
    /// refuse the mesh, name the vertex and leave no file.
    #[test]
    fn no_writer_writes_a_nan() {
        let scratch = tempfile::tempdir().unwrap();
        let mut doc = Document {
            mesh: crate::primitives::cube3(),
            ..Document::default()
        };
        doc.mesh.positions[5].y = f64::NAN;
        for name in ["m.obj", "m.prism.json", "m.stl", "m.glb"] {
            let path = scratch.path().join(name);
            let e = match ExportFormat::of(&path) {
                Some(_) => export(&path, &doc.mesh, &|_| false, Normals::Smooth).unwrap_err(),
                None => save(&path, &doc).unwrap_err(),
            };
            assert!(
                e.to_string().contains("vertex 5 is not a finite point"),
                "{name}: {e}"
            );
            assert!(!path.exists(), "{name}");
        }
        assert_eq!(std::fs::read_dir(scratch.path()).unwrap().count(), 0);
    }
}
