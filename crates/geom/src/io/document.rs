//! The native document `.prism.json`: what OBJ cannot hold (faces with holes, per-edge
//! radii and creases, the pipeline). Versioned; an unknown version is refused.
//!
//! ```json
//! { "version": 1,
//!   "vertices": [[0, 0, 0], ...],
//!   "faces": [[[0, 1, 2, 3]], [[4, 5, 6, 7], [8, 9, 10, 11]]],
//!   "edges": [{ "a": 0, "b": 1, "radius": 0.3 }, { "a": 1, "b": 2, "crease": 10 }],
//!   "subdivision": { "boundary": "edge-and-corner", "crease_method": "chaikin",
//!                    "corners": { "4": 10 }, "holes": [2] },
//!   "pipeline": "combination:r=0.2,combination:r=0.2",
//!   "curve": { "closed": false, "points": [[0, 0], [1, 0], ...], "scheme": "circle",
//!              "levels": 4 } }
//! ```
//! The optional `"curve"` block is the Curves tab's sketch ([`CurveSketch`]), the optional
//! `"skin"` block the Skin tab's sections ([`SkinSpec`]: `{"sections": [{"points": [[x, y, z],
//! ...], "corners": [...], "polygon": false}, ...], "resolution": 8, "caps": true}`), the
//! optional `"envelope"` block the Envelope tab's scene ([`EnvelopeSpec`]: `{"t": 1.0,
//! "primitives": [{"vertices": [[x, y, z], ...], "faces": [[i, ...], ...], "t": optional,
//! "vertex_t": optional}], "resolution": 8}`).
//! A face is a list of loops, the outer loop first; indices are 0-based.

use super::{IoError, write_atomically_with};
use crate::curve::CurveSketch;
use crate::edge_attrs::{EdgeAttr, EdgeAttrs, EdgeKey};
use crate::freeform::SkinSpec;
use crate::freeform::envelope::EnvelopeSpec;
use crate::mesh::PolyMesh;
use crate::scheme::{Scheme, format_pipeline, parse_pipeline};
use crate::tags::SubdivTags;
use glam::DVec3;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// The version this build writes and reads.
pub const DOCUMENT_VERSION: u64 = 1;

/// A solid with its edge attributes and, optionally, a pipeline.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Document {
    pub mesh: PolyMesh,
    pub edge_attrs: EdgeAttrs,
    /// Corners, holes and options of the primal schemes.
    pub tags: SubdivTags,
    pub pipeline: Option<Vec<Scheme>>,
    /// The curve sketch of the Curves tab, when the document has one.
    pub curve: Option<CurveSketch>,
    /// The Skin tab's sections, when the document has them.
    pub skin: Option<SkinSpec>,
    /// The Envelope tab's scene, when the document has one.
    pub envelope: Option<EnvelopeSpec>,
}

#[derive(Serialize, Deserialize)]
struct EdgeRecord {
    a: u32,
    b: u32,
    #[serde(flatten)]
    attr: EdgeAttr,
}

#[derive(Serialize, Deserialize)]
struct FileV1 {
    version: u64,
    vertices: Vec<[f64; 3]>,
    faces: Vec<Vec<Vec<u32>>>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    edges: Vec<EdgeRecord>,
    #[serde(default, skip_serializing_if = "SubdivTags::is_default")]
    subdivision: SubdivTags,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pipeline: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    curve: Option<CurveSketch>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    skin: Option<SkinSpec>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    envelope: Option<EnvelopeSpec>,
}

#[derive(Deserialize)]
struct VersionOnly {
    version: u64,
}

/// A bare envelope scene (`{"t": …, "primitives": […]}`, the `.envelope.json` samples) or
/// skin specification (`{"sections": […], …}`, `.skin.json`) without a document's `version`:
/// a document holding just that block, so that the app opens what `prism envelope` and
/// `prism skin` read. None when the text is anything else (read as a document).
fn bare_spec(path: &Path, text: &str) -> Result<Option<Document>, IoError> {
    #[derive(Deserialize)]
    struct Keys {
        version: Option<serde::de::IgnoredAny>,
        primitives: Option<serde::de::IgnoredAny>,
        sections: Option<serde::de::IgnoredAny>,
    }
    let Ok(k) = serde_json::from_str::<Keys>(text) else {
        return Ok(None);
    };
    if k.version.is_some() {
        return Ok(None);
    }
    Ok(if k.primitives.is_some() {
        Some(Document {
            envelope: Some(super::scene_from_str(path, text)?),
            ..Document::default()
        })
    } else if k.sections.is_some() {
        let spec = serde_json::from_str(text).map_err(|e| json_err(path, e))?;
        Some(Document {
            skin: Some(spec),
            ..Document::default()
        })
    } else {
        None
    })
}

fn json_err(path: &Path, e: serde_json::Error) -> IoError {
    super::inputs::json_error(path, &e, "")
}

/// Parses a document from text.
pub fn document_from_str(path: &Path, text: &str) -> Result<Document, IoError> {
    if let Some(d) = bare_spec(path, text)? {
        return Ok(d);
    }
    let v: VersionOnly = serde_json::from_str(text).map_err(|e| json_err(path, e))?;
    if v.version != DOCUMENT_VERSION {
        return Err(IoError::UnknownVersion {
            path: path.into(),
            found: v.version,
        });
    }
    let f: FileV1 = serde_json::from_str(text).map_err(|e| json_err(path, e))?;
    let mut mesh = PolyMesh::new();
    mesh.positions = f.vertices.iter().map(|&p| DVec3::from(p)).collect();
    for face in &f.faces {
        let loops: Vec<&[u32]> = face.iter().map(|l| l.as_slice()).collect();
        mesh.push_face(&loops);
    }
    let edge_attrs = f
        .edges
        .into_iter()
        .map(|r| (EdgeKey::new(r.a, r.b), r.attr))
        .collect();
    let pipeline = match f.pipeline {
        Some(p) => Some(parse_pipeline(&p).map_err(|e| IoError::Json {
            path: path.into(),
            line: 0,
            column: 0,
            message: format!("pipeline: {e}"),
        })?),
        None => None,
    };
    if let Some(c) = &f.curve {
        c.validate().map_err(|e| IoError::Json {
            path: path.into(),
            line: 0,
            column: 0,
            message: format!("curve: {e}"),
        })?;
    }
    Ok(Document {
        mesh,
        edge_attrs,
        tags: f.subdivision,
        pipeline,
        curve: f.curve,
        skin: f.skin,
        envelope: f.envelope,
    })
}

/// Reads a `.prism.json` document.
pub fn read_document(path: &Path) -> Result<Document, IoError> {
    let text = std::fs::read_to_string(path).map_err(|source| IoError::Read {
        path: path.into(),
        source,
    })?;
    document_from_str(path, &text)
}

/// The document in its file form.
fn file_of(doc: &Document) -> FileV1 {
    let m = &doc.mesh;
    FileV1 {
        version: DOCUMENT_VERSION,
        vertices: m.positions.iter().map(|p| p.to_array()).collect(),
        faces: (0..m.num_faces())
            .map(|f| m.face_loops(f).map(|l| m.loop_verts(l).to_vec()).collect())
            .collect(),
        edges: doc
            .edge_attrs
            .iter()
            .map(|(k, a)| EdgeRecord {
                a: k.0,
                b: k.1,
                attr: *a,
            })
            .collect(),
        subdivision: doc.tags.clone(),
        pipeline: doc.pipeline.as_deref().map(format_pipeline),
        curve: doc.curve.clone(),
        skin: doc.skin.clone(),
        envelope: doc.envelope.clone(),
    }
}

/// The document as JSON text (the tests read it back). Compact: one vertex or face per line
/// would be nicer to diff, but serde_json's pretty printer puts every number on its own line;
/// plain is smaller and as exact.
#[cfg(test)]
fn document_to_string(doc: &Document) -> String {
    serde_json::to_string(&file_of(doc)).expect("a document always serialises")
}

/// Writes a `.prism.json` document atomically.
pub fn write_document(path: &Path, doc: &Document) -> Result<(), IoError> {
    super::check_finite_points(path, &doc.mesh)?;
    let f = file_of(doc);
    write_atomically_with(path, |w| {
        serde_json::to_writer(w, &f).map_err(std::io::Error::other)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;

    #[test]
    fn round_trip_with_holes_edges_and_pipeline() {
        let mut edge_attrs = EdgeAttrs::new();
        edge_attrs.insert(
            EdgeKey::new(0, 1),
            EdgeAttr {
                crease: 10.0,
                radius: Some(0.3),
                fits: Some(0.2),
            },
        );
        let doc = Document {
            mesh: primitives::holed_block(),
            edge_attrs,
            tags: SubdivTags {
                boundary: crate::tags::BoundaryInterpolation::None,
                corners: [(3, 2.5)].into_iter().collect(),
                holes: [1].into_iter().collect(),
                ..SubdivTags::default()
            },
            pipeline: Some(parse_pipeline("combination:r=0.2,doo-sabin").unwrap()),
            curve: Some(CurveSketch {
                scheme: crate::curve::CurveScheme::LogSpiral,
                levels: 3,
                ..CurveSketch::default()
            }),
            skin: Some(crate::freeform::SkinSpec {
                sections: vec![
                    crate::freeform::SectionInput {
                        points: vec![DVec3::ZERO, DVec3::X, DVec3::Y],
                        corners: vec![1],
                        polygon: false,
                    },
                    crate::freeform::SectionInput {
                        points: vec![
                            DVec3::Z,
                            DVec3::new(1.0, 0.0, 1.0),
                            DVec3::new(0.0, 1.0, 1.0),
                        ],
                        corners: vec![],
                        polygon: true,
                    },
                ],
                resolution: 5,
                caps: false,
                basis: crate::freeform::Basis::OneSided,
                pairing: crate::freeform::Pairing::Paper,
            }),
            envelope: Some(EnvelopeSpec {
                t: 0.5,
                primitives: vec![
                    crate::freeform::envelope::Shape::Cube.placed(&Default::default()),
                ],
                resolution: 6,
                basis: Default::default(),
                patches: crate::freeform::envelope::Surfacing::Paper,
                enclosure: Default::default(),
            }),
        };
        let text = document_to_string(&doc);
        let back = document_from_str(Path::new("x.prism.json"), &text).unwrap();
        assert_eq!(back, doc);
    }

    /// Every double comes back bit for bit (serde_json's `float_roundtrip`; without it the
    /// last digit of e.g. 1.8660254037844386 came back wrong).
    #[test]
    fn coordinates_round_trip_bit_for_bit() {
        let mut mesh = primitives::cube3();
        for (k, p) in mesh.positions.iter_mut().enumerate() {
            *p += DVec3::new(0.1, 3f64.sqrt() / 2.0, 1e-17 * k as f64) * (k as f64 + 1.0) / 7.0;
        }
        let doc = Document {
            mesh,
            curve: Some(CurveSketch::default()),
            ..Document::default()
        };
        let back = document_from_str(Path::new("x.prism.json"), &document_to_string(&doc)).unwrap();
        assert_eq!(back, doc);
    }

    #[test]
    fn a_curve_block_with_bad_numbers_is_refused_naming_the_point() {
        let p = Path::new("x.prism.json");
        let text = r#"{"version": 1, "vertices": [], "faces": [],
            "curve": {"closed": true, "points": [[0, 0], [1, 0], [0, 1]], "scheme": "circle", "levels": 99}}"#;
        let e = document_from_str(p, text).unwrap_err().to_string();
        assert!(e.contains("curve") && e.contains("99 levels"), "{e}");
        let text = r#"{"version": 1, "vertices": [], "faces": [],
            "curve": {"closed": true, "points": [[0, 0], [1, 0]], "scheme": "spline", "levels": 2}}"#;
        let e = document_from_str(p, text).unwrap_err().to_string();
        assert!(e.contains("spline"), "{e}");
    }

    #[test]
    fn unknown_version_and_bad_json_are_refused() {
        let p = Path::new("x.prism.json");
        assert!(matches!(
            document_from_str(p, r#"{"version": 7, "vertices": [], "faces": []}"#),
            Err(IoError::UnknownVersion { found: 7, .. })
        ));
        match document_from_str(
            p,
            "{\"version\": 1,\n \"vertices\": [[0,0]], \"faces\": []}",
        ) {
            Err(IoError::Json { line: 2, .. }) => {}
            other => panic!("{other:?}"),
        }
    }
}
