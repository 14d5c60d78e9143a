//! Files: OBJ (read in one pass, polygons kept as they are) and the native `.prism.json`
//! document. Every write goes to a temporary file in the same folder that is renamed into
//! place, so a failed save never destroys the previous file.

mod atomic;
mod document;
mod export;
mod obj;
mod obj_tags;
mod validate;

pub use atomic::{check_writable, forced, save_target, write_atomically, write_atomically_with};
pub use document::{DOCUMENT_VERSION, Document, document_from_str, read_document, write_document};
pub use export::{ExportFormat, Normals, export, glb_bytes, stl_bytes};
pub use obj::{ObjModel, obj_to_string, read_obj, read_obj_str, write_obj, write_obj_with_normals};
pub use validate::validate_model;

pub use crate::numbering::Numbering;
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
    #[error("{path}: unknown file type (use .obj or .prism.json)")]
    UnknownExtension { path: PathBuf },
}

/// The kinds of file Prism reads and writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    Obj,
    Document,
}

impl FileKind {
    pub fn of(path: &Path) -> Result<FileKind, IoError> {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().to_lowercase())
            .unwrap_or_default();
        if name.ends_with(".obj") {
            Ok(FileKind::Obj)
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
    FileKind::of(path)?;
    let text = std::fs::read_to_string(path).map_err(|source| IoError::Read {
        path: path.into(),
        source,
    })?;
    load_str(path, &text)
}

/// As [`load`], for text already in memory (the app's bundled samples); the kind comes
/// from `path`'s name, which messages quote.
pub fn load_str(path: &Path, text: &str) -> Result<(Document, Numbering), IoError> {
    let loaded = load_unchecked(path, text)?;
    let d = &loaded.0;
    validate_model(&d.mesh, &d.edge_attrs, &d.tags, &loaded.1).map_err(|message| {
        IoError::Invalid {
            path: path.into(),
            message,
        }
    })?;
    Ok(loaded)
}

fn load_unchecked(path: &Path, text: &str) -> Result<(Document, Numbering), IoError> {
    match FileKind::of(path)? {
        FileKind::Obj => {
            let m = read_obj_str(path, text)?;
            Ok((
                Document {
                    mesh: m.mesh,
                    edge_attrs: m.edge_attrs,
                    tags: m.tags,
                    ..Document::default()
                },
                Numbering::obj(m.vertex_lines, m.face_lines),
            ))
        }
        FileKind::Document => Ok((document_from_str(path, text)?, Numbering::default())),
    }
}

/// Saves a document as OBJ or `.prism.json` by the file name; returns warnings (e.g. holed
/// faces triangulated for OBJ).
pub fn save(path: &Path, doc: &Document) -> Result<Vec<String>, IoError> {
    match FileKind::of(path)? {
        FileKind::Obj => write_obj(path, &doc.mesh, &doc.edge_attrs, &doc.tags),
        FileKind::Document => write_document(path, doc).map(|_| Vec::new()),
    }
}
