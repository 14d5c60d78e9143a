//! What panels, keys, menus and view input ask for. A tab's `ui` returns these and the frame
//! loop carries them out after drawing, so no panel writes the document: an [`Edit`] goes to
//! [`super::document::Document::apply`], the only writer (and the only place history is
//! recorded); the other commands act on files, jobs and the views.
//!
//! Adding an edit (e.g. for the Skin or Envelope tab): a variant here, its case in `edits::apply_to`,
//! and a test in `document.rs` that it undoes.

use super::doc_state::{DocState, Origin, Part};
use glam::{DVec2, DVec3};
use prism_geom::curve::{CurveScheme, Polyline};
use prism_geom::freeform::SkinSpec;
use prism_geom::freeform::envelope::EnvelopeSpec;
use prism_geom::{EdgeKey, Scheme};
use std::path::PathBuf;

/// A change of the document. Every edit that changes something is one undo step, except
/// that consecutive edits with the same [`Edit::coalesce_key`] (one drag, one slider
/// gesture) share one.
#[derive(Debug, Clone, PartialEq)]
pub enum Edit {
    /// Step >>: appends `scheme`, or, after a step of the same absolute chamfer, that
    /// step's l or d divided by `shrink` (the chamfer's schedule, seed 000 §3.1).
    PushStep {
        view: usize,
        scheme: Scheme,
        shrink: f64,
    },
    /// Removes the last step of view `view`'s pipeline.
    PopStep {
        view: usize,
    },
    /// Replaces step `index` (a scheme picker or a parameter slider; a slider's drag
    /// coalesces).
    SetStep {
        view: usize,
        index: usize,
        scheme: Scheme,
    },
    /// Swaps steps `index` and `index + 1`.
    SwapSteps {
        view: usize,
        index: usize,
    },
    RemoveStep {
        view: usize,
        index: usize,
    },
    /// Keeps the first `len` steps (the budget question's "Remove the step").
    TruncateSteps {
        view: usize,
        len: usize,
    },
    /// Replaces a whole pipeline.
    SetPipeline {
        view: usize,
        steps: Vec<Scheme>,
    },
    /// Splits the window into `n` (1, 2 or 4) views; new views start with the main pipeline.
    SetViews(usize),
    /// Creases (sharpness; 0 clears) or gives an own radius (None: the step's) to control
    /// edges.
    MarkEdges {
        edges: Vec<EdgeKey>,
        mark: EdgeMark,
    },
    /// Moves control vertices by a vector (typed coordinates).
    MoveVertices {
        verts: Vec<u32>,
        by: DVec3,
    },
    /// Puts control vertices at positions during drag number `drag` (coalesces).
    DragVertices {
        drag: u64,
        to: Vec<(u32, DVec3)>,
    },
    /// An edit of the Curves tab's sketch.
    Curve(CurveEdit),
    /// The Skin tab's sections as they are after a change (a sample, add, delete, reorder,
    /// typed numbers); edits of one gesture (a slider or a drag, number `gesture`) coalesce.
    SetSkin {
        spec: Option<SkinSpec>,
        gesture: Option<u64>,
    },
    /// The Envelope tab's scene as it is after a change (a primitive, a move, t); edits of
    /// one gesture coalesce.
    SetEnvelope {
        spec: Option<EnvelopeSpec>,
        gesture: Option<u64>,
    },
    /// A whole new document with its name and save target (File ▸ Open, a sample,
    /// drag-and-drop); undoable.
    Replace {
        state: Box<DocState>,
        origin: Origin,
    },
}

/// What [`Edit::MarkEdges`] puts on the edges.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EdgeMark {
    Crease(f64),
    Radius(Option<f64>),
}

/// An edit of the curve sketch.
#[derive(Debug, Clone, PartialEq)]
pub enum CurveEdit {
    /// Inserts a control point before index `index` (`index` = length appends).
    Insert {
        index: usize,
        at: DVec2,
    },
    /// Moves point `index` during drag number `drag` (coalesces).
    Move {
        index: usize,
        to: DVec2,
        drag: u64,
    },
    Delete {
        index: usize,
    },
    SetClosed(bool),
    SetScheme(CurveScheme),
    SetLevels(usize),
    /// A preset or a typed polyline.
    SetControl(Polyline),
}

/// Which consecutive edits share an undo step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CoalesceKey {
    VertexDrag(u64),
    CurveDrag(u64),
    SkinGesture(u64),
    EnvelopeGesture(u64),
    Step { view: usize, index: usize },
}

impl Edit {
    /// The part of the document this edit changes (what undo names).
    pub fn part(&self) -> Part {
        match self {
            Edit::PushStep { .. }
            | Edit::PopStep { .. }
            | Edit::SetStep { .. }
            | Edit::SwapSteps { .. }
            | Edit::RemoveStep { .. }
            | Edit::TruncateSteps { .. }
            | Edit::SetPipeline { .. }
            | Edit::SetViews(_) => Part::Pipeline,
            Edit::MarkEdges { .. } | Edit::MoveVertices { .. } | Edit::DragVertices { .. } => {
                Part::Solid
            }
            Edit::Curve(_) => Part::Curve,
            Edit::SetSkin { .. } => Part::Skin,
            Edit::SetEnvelope { .. } => Part::Envelope,
            Edit::Replace { .. } => Part::File,
        }
    }

    /// Edits with the same key, one right after the other, are one undo step.
    pub fn coalesce_key(&self) -> Option<CoalesceKey> {
        match self {
            Edit::DragVertices { drag, .. } => Some(CoalesceKey::VertexDrag(*drag)),
            Edit::Curve(CurveEdit::Move { drag, .. }) => Some(CoalesceKey::CurveDrag(*drag)),
            Edit::SetSkin {
                gesture: Some(g), ..
            } => Some(CoalesceKey::SkinGesture(*g)),
            Edit::SetEnvelope {
                gesture: Some(g), ..
            } => Some(CoalesceKey::EnvelopeGesture(*g)),
            Edit::SetStep { view, index, .. } => Some(CoalesceKey::Step {
                view: *view,
                index: *index,
            }),
            _ => None,
        }
    }

    /// Whether the views should follow it live (queue behind a running job instead of
    /// cancelling it): drags.
    pub fn is_live(&self) -> bool {
        matches!(
            self,
            Edit::DragVertices { .. } | Edit::Curve(CurveEdit::Move { .. })
        )
    }
}

/// Everything a tab, a key or a menu can ask for.
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    Edit(Edit),
    Undo,
    Redo,
    /// Opens a file (as an undoable [`Edit::Replace`]).
    Open(PathBuf),
    OpenSample(usize),
    /// Puts bundled skin sample k into the Skin tab (undoable) and shows the tab.
    OpenSkinSample(usize),
    /// Puts bundled envelope scene k into the Envelope tab (undoable) and shows the tab.
    OpenEnvelopeSample(usize),
    /// Opens paper figure k of Help ▸ Paper figures (`paper_figures::FIGURES`): its input,
    /// steps, tab and display.
    OpenFigure(usize),
    /// Makes the copy of unsaved work an earlier run left the document (undoable).
    RestoreAutosave,
    /// Drops that copy.
    DiscardAutosave,
    /// Asks where, then opens.
    OpenDialog,
    /// Stops opening the file being read on a thread; the document stays.
    CancelOpening,
    /// Saves to the document's file, or asks where (`as_new`: always asks).
    SaveDialog {
        as_new: bool,
    },
    /// Asks where, then exports the shown level as `ext` (obj, stl, glb).
    ExportDialog(&'static str),
    /// Stops view `view`'s running computation.
    Cancel {
        view: usize,
    },
    /// Answers the memory question: compute anyway.
    ComputeAnyway,
    /// Answers the memory question: remove the step.
    RemoveOverBudgetStep,
    /// The answer "keep only the last level" to the memory question: the view frees its
    /// intermediate levels and computes on within the budget.
    DropKeptLevels,
    /// A message for the status bar (what an action did, or why it did nothing).
    Say(String),
    /// Opens the New solid window (`extrude`: on the sketch's extrusion).
    ShowNewSolid {
        extrude: bool,
    },
    /// Makes a new solid the document (undoable), keeping the pipelines and the sketch.
    NewSolid(prism_geom::solid::Solid),
}

impl From<Edit> for Command {
    fn from(e: Edit) -> Command {
        Command::Edit(e)
    }
}

impl From<CurveEdit> for Command {
    fn from(e: CurveEdit) -> Command {
        Command::Edit(Edit::Curve(e))
    }
}
