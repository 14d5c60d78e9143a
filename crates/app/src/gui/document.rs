//! What the user edits — the control mesh with its edge marks and tags, the pipeline of
//! every view, the curve sketch — with where it came from and its history.
//!
//! [`Document::apply`] is the only writer: every tab returns [`Edit`]s and the frame loop
//! applies them here, where the state before is recorded for undo. History is **global**:
//! Ctrl+Z undoes the last change of the document whichever tab made it (a crease in the
//! Model tab, then a curve drag in the Curves tab: the first Ctrl+Z restores the curve, the
//! second removes the crease). The document's name and save target are part of what undo
//! restores. Views and caches compare [`Document::generation`], bumped by every change, to
//! know when to recompute; nothing keeps a dirty flag.

use super::command::{CoalesceKey, Edit};
pub use super::doc_state::{DocState, Origin, Part};
use super::edits::apply_to;
use prism_geom::io;
use std::path::Path;

/// Loads a file as a document.
pub fn open(path: &Path) -> Result<(DocState, Origin), String> {
    open_with(path, &Default::default())
}

/// As [`open`], adding to `progress` and stopping when it is cancelled (opening.rs).
pub fn open_with(
    path: &Path,
    progress: &prism_geom::progress::Progress,
) -> Result<(DocState, Origin), String> {
    let (doc, numbering) = io::load_with(path, progress).map_err(|e| e.to_string())?;
    // A file with nothing to show (an OBJ of no faces: text that is not a mesh) leaves the
    // document as it is, as the command line refuses it.
    let nothing = doc.mesh.num_faces() == 0
        && doc.skin.is_none()
        && doc.envelope.is_none()
        && doc.curve.is_none();
    if nothing {
        return Err(format!(
            "{}: the mesh has no faces (is it a mesh?); the document is as it was",
            path.display()
        ));
    }
    let native = io::FileKind::of(path).ok() == Some(io::FileKind::Document);
    Ok((
        DocState::from_document(doc),
        Origin {
            path: native.then(|| path.to_path_buf()),
            name: path.display().to_string(),
            numbering: std::sync::Arc::new(numbering),
        },
    ))
}

/// One snapshot of the history: the document before a change, and the part that change
/// touched (what undo names).
type Snapshot = (DocState, Origin, Part);

/// Undo and redo stacks of whole document states (control meshes are small next to their
/// refined levels; the stacks hold at most [`History::LIMIT`] states each).
#[derive(Debug, Default)]
struct History {
    undo: Vec<Snapshot>,
    redo: Vec<Snapshot>,
    /// The key of the last recorded edit, while edits with that key keep coming.
    open: Option<CoalesceKey>,
}

impl History {
    const LIMIT: usize = 200;

    fn record(&mut self, before: Snapshot, key: Option<CoalesceKey>) {
        let coalesced = key.is_some() && key == self.open;
        self.open = key;
        if coalesced {
            return;
        }
        self.undo.push(before);
        if self.undo.len() > Self::LIMIT {
            self.undo.remove(0);
        }
        self.redo.clear();
    }
}

/// The document with its origin, history and generation.
#[derive(Debug, Default)]
pub struct Document {
    state: DocState,
    origin: Origin,
    history: History,
    generation: u64,
    /// Whether the last change was a live one (a drag).
    live: bool,
}

impl Document {
    pub fn new(state: DocState, origin: Origin) -> Document {
        let mut d = Document {
            state,
            origin,
            ..Document::default()
        };
        d.normalise();
        d
    }

    pub fn state(&self) -> &DocState {
        &self.state
    }
    pub fn origin(&self) -> &Origin {
        &self.origin
    }
    /// Bumped by every change (edits, undo, redo, a new origin).
    pub fn generation(&self) -> u64 {
        self.generation
    }
    /// Whether the last change was a drag, which views follow live.
    pub fn live(&self) -> bool {
        self.live
    }
    /// What the next undo would take back.
    pub fn next_undo(&self) -> Option<Part> {
        self.history.undo.last().map(|s| s.2)
    }

    pub fn can_undo(&self) -> bool {
        !self.history.undo.is_empty()
    }
    pub fn can_redo(&self) -> bool {
        !self.history.redo.is_empty()
    }

    /// Applies one edit. Returns whether it changed the document (then it is recorded for
    /// undo), or why it was refused (the document is then as it was).
    pub fn apply(&mut self, edit: Edit) -> Result<bool, String> {
        let (key, live, part) = (edit.coalesce_key(), edit.is_live(), edit.part());
        let mut next = self.state.clone();
        let mut origin = self.origin.clone();
        apply_to(&mut next, &mut origin, edit)?;
        if next == self.state && origin == self.origin {
            return Ok(false);
        }
        let before = (
            std::mem::replace(&mut self.state, next),
            std::mem::replace(&mut self.origin, origin),
            part,
        );
        self.history.record(before, key);
        self.normalise();
        self.live = live;
        self.generation += 1;
        Ok(true)
    }

    /// Goes back one change; returns whether there was one.
    pub fn undo(&mut self) -> bool {
        self.travel(false)
    }

    /// Goes forward one undone change; returns whether there was one.
    pub fn redo(&mut self) -> bool {
        self.travel(true)
    }

    /// Swaps the state with the top of the redo (`forward`) or undo stack, pushing the
    /// current one onto the other.
    fn travel(&mut self, forward: bool) -> bool {
        let h = &mut self.history;
        let (from, to) = if forward {
            (&mut h.redo, &mut h.undo)
        } else {
            (&mut h.undo, &mut h.redo)
        };
        let Some((state, origin, part)) = from.pop() else {
            return false;
        };
        to.push((
            std::mem::replace(&mut self.state, state),
            std::mem::replace(&mut self.origin, origin),
            part,
        ));
        h.open = None;
        self.live = false;
        self.generation += 1;
        true
    }

    /// Records that the document now lives in `path` (after Save as): not an edit, so not
    /// undone on its own, but part of every later snapshot.
    pub fn saved_as(&mut self, path: &Path, native: bool) {
        if native {
            self.origin.path = Some(path.to_path_buf());
        }
        self.origin.name = path.display().to_string();
        // Messages now count as the saved file does: a document's arrays from 0, an OBJ's
        // records from 1 (its lines are not known until it is read).
        self.origin.numbering = std::sync::Arc::new(io::Numbering {
            base: u32::from(!native),
            ..Default::default()
        });
        self.generation += 1;
    }

    /// A document always has at least one view.
    fn normalise(&mut self) {
        if self.state.pipelines.is_empty() {
            self.state.pipelines.push(Vec::new());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gui::command::{CurveEdit, EdgeMark};
    use glam::{DVec2, DVec3};
    use prism_geom::{CornerRule, EdgeKey, Scheme, primitives};

    fn doc() -> Document {
        Document::new(
            DocState {
                mesh: primitives::cube3(),
                ..Default::default()
            },
            Origin::default(),
        )
    }
    const DS: Scheme = Scheme::Biquadratic(CornerRule::DooSabin);

    #[test]
    fn undo_and_redo_walk_the_changes() {
        let mut d = doc();
        let g0 = d.generation();
        for _ in 0..2 {
            d.apply(Edit::PushStep {
                view: 0,
                scheme: DS,
                shrink: 1.0,
            })
            .unwrap();
        }
        assert!(d.generation() > g0);
        assert!(d.undo());
        assert_eq!(d.state().pipelines[0].len(), 1);
        assert!(d.undo());
        assert_eq!(d.state().pipelines[0].len(), 0);
        assert!(!d.can_undo());
        assert!(d.redo());
        assert_eq!(d.state().pipelines[0].len(), 1);
        // A new change drops the redo stack.
        d.apply(Edit::PopStep { view: 0 }).unwrap();
        assert!(!d.can_redo());
        // An edit that changes nothing is not a step.
        assert_eq!(d.apply(Edit::PopStep { view: 0 }), Ok(false));
    }

    #[test]
    fn saving_keeps_the_main_pipeline_and_a_changed_curve() {
        let mut d = doc();
        d.apply(Edit::PushStep {
            view: 0,
            scheme: DS,
            shrink: 1.0,
        })
        .unwrap();
        d.apply(Edit::SetViews(2)).unwrap();
        let f = d.state().to_document();
        assert_eq!(f.pipeline.unwrap().len(), 1);
        assert!(f.curve.is_none(), "the default sketch is not written");
        d.apply(CurveEdit::SetLevels(2).into_edit()).unwrap();
        let back = DocState::from_document(d.state().to_document());
        assert_eq!(back.pipelines.len(), 1);
        assert_eq!(back.curve.levels, 2);
    }

    #[test]
    fn a_drag_is_one_undo_step_and_a_new_drag_another() {
        let mut d = doc();
        let p0 = d.state().mesh.positions[0];
        for k in 1..=5 {
            let to = vec![(0, p0 + DVec3::Z * k as f64)];
            d.apply(Edit::DragVertices { drag: 1, to }).unwrap();
            assert!(d.live());
        }
        let to = vec![(0, p0 + DVec3::X)];
        d.apply(Edit::DragVertices { drag: 2, to }).unwrap();
        d.undo();
        assert_eq!(d.state().mesh.positions[0], p0 + DVec3::Z * 5.0);
        d.undo();
        assert_eq!(d.state().mesh.positions[0], p0);
        assert!(!d.can_undo());
    }

    /// The seam the architecture issue found: a crease in the Model tab, then a curve drag
    /// in the Curves tab; Ctrl+Z must restore the curve and keep the crease.
    #[test]
    fn history_is_global_across_tabs() {
        let mut d = doc();
        let e = EdgeKey::new(0, 1);
        d.apply(Edit::MarkEdges {
            edges: vec![e],
            mark: EdgeMark::Crease(10.0),
        })
        .unwrap();
        let p = d.state().curve.control.points[1];
        for k in 0..3 {
            let to = p + DVec2::splat(0.1 * (k + 1) as f64);
            d.apply(
                CurveEdit::Move {
                    index: 1,
                    to,
                    drag: 7,
                }
                .into_edit(),
            )
            .unwrap();
        }
        d.undo();
        assert_eq!(d.state().curve.control.points[1], p);
        assert_eq!(d.state().edge_attrs[&e].crease, 10.0);
        d.undo();
        assert!(d.state().edge_attrs.is_empty());
    }

    #[test]
    fn bad_edits_are_refused_and_change_nothing() {
        let mut d = doc();
        let g = d.generation();
        let bad = [
            Edit::MoveVertices {
                verts: vec![0],
                by: DVec3::new(f64::NAN, 0.0, 0.0),
            },
            Edit::MoveVertices {
                verts: vec![99],
                by: DVec3::X,
            },
            Edit::MarkEdges {
                edges: vec![EdgeKey::new(0, 1)],
                mark: EdgeMark::Radius(Some(-1.0)),
            },
            Edit::RemoveStep { view: 0, index: 0 },
            Edit::SetViews(3),
            Edit::PushStep {
                view: 5,
                scheme: DS,
                shrink: 1.0,
            },
            CurveEdit::SetLevels(40).into_edit(),
            CurveEdit::Delete { index: 100 }.into_edit(),
        ];
        for e in bad {
            assert!(d.apply(e.clone()).is_err(), "{e:?}");
        }
        assert_eq!(d.generation(), g);
        assert!(!d.can_undo());
    }

    #[test]
    fn undo_restores_the_name_and_save_target() {
        let mut d = doc();
        d.apply(Edit::Replace {
            state: Box::new(DocState {
                mesh: primitives::tripod(),
                ..Default::default()
            }),
            origin: Origin {
                path: Some("t.prism.json".into()),
                name: "t.prism.json".into(),
                ..Default::default()
            },
        })
        .unwrap();
        assert_eq!(d.origin().name, "t.prism.json");
        d.undo();
        assert_eq!(d.origin(), &Origin::default());
        assert_eq!(d.state().mesh, primitives::cube3());
    }

    impl CurveEdit {
        fn into_edit(self) -> Edit {
            Edit::Curve(self)
        }
    }
}
