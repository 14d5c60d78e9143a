//! What the user edits — the control mesh with its edge marks and tags, and the pipeline of
//! every view — and its history. Every change goes through [`History::record`] with the
//! state before it, so Ctrl+Z undoes any document change (a vertex drag is one change).

use prism_geom::io::{self, Document};
use prism_geom::{EdgeAttrs, PolyMesh, Scheme, SubdivTags};
use std::path::{Path, PathBuf};

/// The document: one input, one pipeline per view (view 0 is the main one and the one saved
/// with the document; the others exist in the compare split).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DocState {
    pub mesh: PolyMesh,
    pub edge_attrs: EdgeAttrs,
    pub tags: SubdivTags,
    pub pipelines: Vec<Vec<Scheme>>,
}

impl DocState {
    pub fn from_document(doc: Document) -> DocState {
        DocState {
            mesh: doc.mesh,
            edge_attrs: doc.edge_attrs,
            tags: doc.tags,
            pipelines: vec![doc.pipeline.unwrap_or_default()],
        }
    }

    /// The document as saved: the main pipeline goes with it.
    pub fn to_document(&self) -> Document {
        Document {
            mesh: self.mesh.clone(),
            edge_attrs: self.edge_attrs.clone(),
            tags: self.tags.clone(),
            pipeline: self.pipelines.first().filter(|p| !p.is_empty()).cloned(),
        }
    }
}

/// Where the document came from and whether it has unsaved changes.
#[derive(Debug, Clone, Default)]
pub struct Origin {
    /// A file the document can be saved back to (`.prism.json` only: saving an OBJ would lose
    /// the pipeline, so an opened OBJ is saved with "Save as").
    pub path: Option<PathBuf>,
    /// What the title bar and panel show.
    pub name: String,
}

/// Loads a file as a document.
pub fn open(path: &Path) -> Result<(DocState, Origin), String> {
    let (doc, _) = io::load(path).map_err(|e| e.to_string())?;
    if !doc.mesh.all_finite() {
        return Err(format!(
            "{}: a vertex has a coordinate that is not a number",
            path.display()
        ));
    }
    let native = io::FileKind::of(path).ok() == Some(io::FileKind::Document);
    Ok((
        DocState::from_document(doc),
        Origin {
            path: native.then(|| path.to_path_buf()),
            name: path.display().to_string(),
        },
    ))
}

/// Undo and redo stacks of whole document states (control meshes are small next to their
/// refined levels; the stacks hold at most [`History::LIMIT`] states each).
#[derive(Debug, Default)]
pub struct History {
    undo: Vec<DocState>,
    redo: Vec<DocState>,
}

impl History {
    pub const LIMIT: usize = 200;

    /// Records `before`, the state a change is about to leave.
    pub fn record(&mut self, before: DocState) {
        if self.undo.last() == Some(&before) {
            return;
        }
        self.undo.push(before);
        if self.undo.len() > Self::LIMIT {
            self.undo.remove(0);
        }
        self.redo.clear();
    }

    /// The state before the last change; `current` goes to the redo stack.
    pub fn undo(&mut self, current: DocState) -> Option<DocState> {
        let s = self.undo.pop()?;
        self.redo.push(current);
        Some(s)
    }

    pub fn redo(&mut self, current: DocState) -> Option<DocState> {
        let s = self.redo.pop()?;
        self.undo.push(current);
        Some(s)
    }

    pub fn can_undo(&self) -> bool {
        !self.undo.is_empty()
    }
    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use prism_geom::primitives;

    fn state(steps: usize) -> DocState {
        DocState {
            mesh: primitives::cube3(),
            pipelines: vec![vec![
                Scheme::Biquadratic(prism_geom::CornerRule::DooSabin);
                steps
            ]],
            ..Default::default()
        }
    }

    #[test]
    fn undo_and_redo_walk_the_changes() {
        let mut h = History::default();
        h.record(state(0));
        h.record(state(1));
        let now = state(2);
        let back = h.undo(now.clone()).unwrap();
        assert_eq!(back, state(1));
        let back2 = h.undo(back).unwrap();
        assert_eq!(back2, state(0));
        assert!(!h.can_undo());
        let fwd = h.redo(back2).unwrap();
        assert_eq!(fwd, state(1));
        // A new change drops the redo stack.
        h.record(fwd);
        assert!(!h.can_redo());
    }

    #[test]
    fn saving_keeps_the_main_pipeline_only() {
        let mut s = state(2);
        s.pipelines.push(vec![]);
        let d = s.to_document();
        assert_eq!(d.pipeline.unwrap().len(), 2);
        assert_eq!(DocState::from_document(s.to_document()).pipelines.len(), 1);
    }
}
