//! The document's state as it is saved and undone ([`DocState`]) and where it came from
//! ([`Origin`]): plain data below the commands, the history and the edits that use them.

use prism_geom::curve::CurveSketch;
use prism_geom::freeform::SkinSpec;
use prism_geom::freeform::envelope::EnvelopeSpec;
use prism_geom::io::{self, Document as FileDocument};
use prism_geom::{EdgeAttrs, PolyMesh, Scheme, SubdivTags};
use std::path::PathBuf;

/// The state that is saved and undone: one input, one pipeline per view (view 0 is the main
/// one and the one saved with the document; the others exist in the compare split), and the
/// curve sketch.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DocState {
    pub mesh: PolyMesh,
    pub edge_attrs: EdgeAttrs,
    pub tags: SubdivTags,
    pub pipelines: Vec<Vec<Scheme>>,
    pub curve: CurveSketch,
    /// The Skin tab's sections (none until a sample or a first section is placed).
    pub skin: Option<SkinSpec>,
    /// The Envelope tab's scene (none until a primitive is added or a sample opened).
    pub envelope: Option<EnvelopeSpec>,
}

impl DocState {
    pub fn from_document(doc: FileDocument) -> DocState {
        DocState {
            mesh: doc.mesh,
            edge_attrs: doc.edge_attrs,
            tags: doc.tags,
            pipelines: vec![doc.pipeline.unwrap_or_default()],
            curve: doc.curve.unwrap_or_default(),
            skin: doc.skin,
            envelope: doc.envelope,
        }
    }

    /// The document as saved: the main pipeline and the curve sketch go with it (the
    /// sketch only when it is not the default one).
    pub fn to_document(&self) -> FileDocument {
        FileDocument {
            mesh: self.mesh.clone(),
            edge_attrs: self.edge_attrs.clone(),
            tags: self.tags.clone(),
            pipeline: self.pipelines.first().filter(|p| !p.is_empty()).cloned(),
            curve: (self.curve != CurveSketch::default()).then(|| self.curve.clone()),
            skin: self.skin.clone(),
            envelope: self.envelope.clone(),
        }
    }
}

/// A part of the document, as undo names a change to it, with the tab that edits it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Part {
    /// Another document (a file opened, a sample, a new solid).
    File,
    Solid,
    Pipeline,
    Curve,
    Skin,
    Envelope,
}

impl Part {
    /// The change, in words.
    pub fn describe(self) -> &'static str {
        match self {
            Part::File => "opening a document",
            Part::Solid => "a change to the solid (vertices, creases, radii, tags)",
            Part::Pipeline => "a change to the pipeline",
            Part::Curve => "a change to the curve sketch",
            Part::Skin => "a change to the skin's sections",
            Part::Envelope => "a change to the envelope's scene",
        }
    }

    /// The tab that edits this part (a document opened: every tab's).
    pub fn tab_name(self) -> Option<&'static str> {
        match self {
            Part::File => None,
            Part::Solid | Part::Pipeline => Some("Model"),
            Part::Curve => Some("Curves"),
            Part::Skin => Some("Skin"),
            Part::Envelope => Some("Envelope"),
        }
    }
}

/// Where the document came from.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Origin {
    /// A file the document can be saved back to (`.prism.json` only: saving an OBJ would lose
    /// the pipeline, so an opened OBJ is saved with "Save as").
    pub path: Option<PathBuf>,
    /// What the title bar and panel show.
    pub name: String,
    /// How the file counts its vertices and faces: messages about the control mesh say
    /// them so (an OBJ's from 1, with lines).
    pub numbering: std::sync::Arc<io::Numbering>,
}
