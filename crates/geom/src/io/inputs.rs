//! The JSON inputs besides the document: a control polyline for the curve schemes, the
//! cross-sections of a skin (seed 003) and the primitives of an envelope (seed 004). Each is
//! read from text by one function that the command line, the app and the fuzz targets
//! share; a file that is not of the shape is named with the line and column where it stops
//! fitting and the shape that was expected.

use super::IoError;
use crate::curve::Polyline;
use crate::freeform::SectionInput;
use crate::freeform::envelope::EnvelopeSpec;
use std::path::Path;

/// The shape of a polyline file.
pub const POLYLINE_SHAPE: &str = r#"{"closed": bool, "points": [[x, y], ...]}"#;
/// The shape of a sections file (or the `"skin"` block of a `.prism.json`).
pub const SECTIONS_SHAPE: &str = r#"{"sections": [{"points": [[x, y, z], ...]}, ...]}"#;
/// The shape of an envelope scene (or the `"envelope"` block of a `.prism.json`).
pub const SCENE_SHAPE: &str =
    r#"{"t": 1.0, "primitives": [{"vertices": [[x, y, z], ...], "faces": [[i, ...], ...]}]}"#;

/// `e` as an error about `path`, its message without serde's own "at line L column C" (the
/// error says the line and column once).
pub(super) fn json_error(path: &Path, e: &serde_json::Error, what: &str) -> IoError {
    let full = e.to_string();
    let message = match full.rfind(" at line ") {
        Some(at) if e.line() > 0 => &full[..at],
        _ => &full,
    };
    IoError::Json {
        path: path.into(),
        line: e.line(),
        column: e.column(),
        message: format!("{what}{message}"),
    }
}

fn parse<T: serde::de::DeserializeOwned>(
    path: &Path,
    text: &str,
    what: &str,
    shape: &str,
) -> Result<T, IoError> {
    serde_json::from_str(text.trim_start_matches('\u{feff}'))
        .map_err(|e| json_error(path, &e, &format!("not {what} ({shape}): ")))
}

#[derive(serde::Deserialize)]
struct PolylineFile {
    closed: bool,
    points: Vec<[f64; 2]>,
}

/// A control polyline `{"closed": bool, "points": [[x, y], ...]}`.
pub fn polyline_from_str(path: &Path, text: &str) -> Result<Polyline, IoError> {
    let c: PolylineFile = parse(path, text, "a polyline", POLYLINE_SHAPE)?;
    Ok(Polyline::new(
        c.points.iter().map(|&p| p.into()).collect(),
        c.closed,
    ))
}

#[derive(serde::Deserialize)]
struct SectionsFile {
    #[serde(alias = "skin")]
    sections: SectionsOrBlock,
}

#[derive(serde::Deserialize)]
#[serde(untagged)]
enum SectionsOrBlock {
    List(Vec<SectionInput>),
    Block { sections: Vec<SectionInput> },
}

/// The sections of a sections file, or of the `"skin"` block of a `.prism.json`.
pub fn sections_from_str(path: &Path, text: &str) -> Result<Vec<SectionInput>, IoError> {
    let f: SectionsFile = parse(path, text, "a sections file", SECTIONS_SHAPE)?;
    Ok(match f.sections {
        SectionsOrBlock::List(s) | SectionsOrBlock::Block { sections: s } => s,
    })
}

/// The scene of a scene file, or of the `"envelope"` block of a `.prism.json`.
pub fn scene_from_str(path: &Path, text: &str) -> Result<EnvelopeSpec, IoError> {
    let mut v: serde_json::Value = parse(path, text, "JSON", SCENE_SHAPE)?;
    let scene = match v.get_mut("envelope") {
        Some(block) => block.take(),
        None => v,
    };
    serde_json::from_value(scene).map_err(|e| IoError::Invalid {
        path: path.into(),
        message: format!("not a scene ({e}); expected {SCENE_SHAPE}"),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_input_reads_its_shape_and_names_where_another_stops() {
        let p = Path::new("in.json");
        let c = polyline_from_str(p, r#"{"closed": true, "points": [[0, 0], [1, 0], [0, 1]]}"#)
            .unwrap();
        assert!(c.closed);
        assert_eq!(c.points.len(), 3);
        let e = polyline_from_str(p, "{\"closed\": true,\n \"points\": [[0, \"a\"]]}")
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("in.json, line 2, column"), "{e}");
        assert!(
            e.contains("not a polyline") && !e.contains(" at line "),
            "{e}"
        );

        let s =
            sections_from_str(p, r#"{"skin": {"sections": [{"points": [[0, 0, 0]]}]}}"#).unwrap();
        assert_eq!(s.len(), 1);
        let e = sections_from_str(p, "[1, 2]").unwrap_err().to_string();
        assert!(e.contains("not a sections file"), "{e}");

        let sc = scene_from_str(
            p,
            r#"{"envelope": {"primitives": [{"vertices": [[0, 0, 0]], "faces": [[0]]}]}}"#,
        )
        .unwrap();
        assert_eq!(sc.primitives.len(), 1);
        let e = scene_from_str(p, r#"{"primitives": 3}"#)
            .unwrap_err()
            .to_string();
        assert!(e.contains("not a scene"), "{e}");
    }
}
