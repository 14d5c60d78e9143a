//! PLY in (ASCII and both binary byte orders, by the `ply-rs-bw` crate): the `vertex`
//! element's `x`, `y`, `z` (any numeric type) and the `face` element's `vertex_indices` (or
//! `vertex_index`) lists, polygons kept as they are; every other element and property (colours,
//! normals, texture coordinates, edges) is skipped. Faces and vertices are numbered from 0 as the
//! file lists them; a face naming a vertex that is not there, a repeated corner, a point that
//! is not finite or a file with no face is refused by number, and the mesh then goes through
//! the model checks every reader's output goes through.

use super::{Document, IoError, Numbering};
use crate::mesh::PolyMesh;
use glam::DVec3;
use ply_rs_bw::parser::{Parser, Reader};
use ply_rs_bw::ply::{DefaultElement, Property, PropertyAccess, PropertyAccessResult};
use std::path::Path;

/// A vertex: its coordinates.
struct PlyVertex([f64; 3]);

impl PropertyAccess for PlyVertex {
    fn new() -> Self {
        PlyVertex([0.0; 3])
    }

    fn set_property(&mut self, key: &str, property: Property) -> PropertyAccessResult {
        let axis = match key {
            "x" => 0,
            "y" => 1,
            "z" => 2,
            _ => return PropertyAccessResult::Ignored,
        };
        self.0[axis] = match property {
            Property::Float(v) => f64::from(v),
            Property::Double(v) => v,
            Property::Char(v) => f64::from(v),
            Property::UChar(v) => f64::from(v),
            Property::Short(v) => f64::from(v),
            Property::UShort(v) => f64::from(v),
            Property::Int(v) => f64::from(v),
            Property::UInt(v) => f64::from(v),
            _ => return PropertyAccessResult::UnsupportedType,
        };
        PropertyAccessResult::Set
    }
}

/// A face: its corners (negative where the file's index is).
struct PlyFace(Vec<i64>);

impl PropertyAccess for PlyFace {
    fn new() -> Self {
        PlyFace(Vec::new())
    }

    fn set_property(&mut self, key: &str, property: Property) -> PropertyAccessResult {
        if key != "vertex_indices" && key != "vertex_index" {
            return PropertyAccessResult::Ignored;
        }
        self.0 = match property {
            Property::ListChar(v) => v.into_iter().map(i64::from).collect(),
            Property::ListUChar(v) => v.into_iter().map(i64::from).collect(),
            Property::ListShort(v) => v.into_iter().map(i64::from).collect(),
            Property::ListUShort(v) => v.into_iter().map(i64::from).collect(),
            Property::ListInt(v) => v.into_iter().map(i64::from).collect(),
            Property::ListUInt(v) => v.into_iter().map(i64::from).collect(),
            _ => return PropertyAccessResult::UnsupportedType,
        };
        PropertyAccessResult::Set
    }
}

/// The solid of a PLY file's bytes.
pub fn read_ply_bytes(path: &Path, bytes: &[u8]) -> Result<(Document, Numbering), IoError> {
    let invalid = |message: String| IoError::Invalid {
        path: path.into(),
        message,
    };
    // The parser's messages name the line ("Line 12: …").
    let parse = |e: ply_rs_bw::parser::ParseError| invalid(e.to_string());
    let mut reader = Reader::new(std::io::BufReader::new(bytes));
    let vertex_parser = Parser::<PlyVertex>::new();
    let face_parser = Parser::<PlyFace>::new();
    let other_parser = Parser::<DefaultElement>::new();
    let header = vertex_parser
        .read_header(&mut reader)
        .map_err(|e| invalid(format!("not a PLY file Prism reads ({e})")))?;
    let (mut vertices, mut faces) = (Vec::new(), Vec::new());
    for element in header.elements.values() {
        match element.name.as_str() {
            "vertex" => {
                vertices = vertex_parser
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(parse)?;
            }
            "face" => {
                faces = face_parser
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(parse)?;
            }
            // Read past in file order (edges, materials, …).
            _ => {
                other_parser
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(parse)?;
            }
        }
    }
    let positions: Vec<DVec3> = vertices
        .iter()
        .enumerate()
        .map(|(i, v)| {
            let p = DVec3::from_array(v.0);
            p.is_finite()
                .then_some(p)
                .ok_or_else(|| invalid(format!("vertex {i} is not a finite point")))
        })
        .collect::<Result<_, _>>()?;
    if faces.is_empty() {
        return Err(invalid("the PLY file has no faces".into()));
    }
    let n = positions.len() as i64;
    let mut polys: Vec<Vec<u32>> = Vec::with_capacity(faces.len());
    for (f, face) in faces.iter().enumerate() {
        if face.0.len() < 3 {
            return Err(invalid(format!(
                "face {f} has {} corner(s): a face needs at least 3",
                face.0.len()
            )));
        }
        if let Some(&v) = face.0.iter().find(|&&v| !(0..n).contains(&v)) {
            return Err(invalid(format!(
                "face {f} names vertex {v}, which is not there ({n} vertices, numbered from 0)"
            )));
        }
        let corners: Vec<u32> = face.0.iter().map(|&v| v as u32).collect();
        let mut sorted = corners.clone();
        sorted.sort_unstable();
        if sorted.windows(2).any(|w| w[0] == w[1]) {
            return Err(invalid(format!("face {f} names a vertex twice")));
        }
        polys.push(corners);
    }
    Ok((
        Document {
            mesh: PolyMesh::from_polygons(positions, &polys),
            ..Document::default()
        },
        Numbering::default(),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    const CUBE_ASCII: &str = "ply
format ascii 1.0
comment a unit cube, quads, with a colour per vertex
element vertex 8
property float x
property float y
property double z
property uchar red
property uchar green
property uchar blue
element face 6
property list uchar int vertex_indices
end_header
0 0 0 255 0 0
1 0 0 255 0 0
1 1 0 255 0 0
0 1 0 255 0 0
0 0 1 255 0 0
1 0 1 255 0 0
1 1 1 255 0 0
0 1 1 255 0 0
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 1 2 6 5
4 2 3 7 6
4 3 0 4 7
";

    /// The same cube, binary little endian, with an `edge` element after the faces.
    fn cube_binary() -> Vec<u8> {
        let mut b = b"ply\nformat binary_little_endian 1.0\nelement vertex 8\nproperty double x\nproperty double y\nproperty double z\nelement face 6\nproperty list uchar uint vertex_index\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n".to_vec();
        for v in 0..8u32 {
            for axis in [v & 1, (v >> 1) & 1, (v >> 2) & 1] {
                b.extend_from_slice(&f64::from(axis).to_le_bytes());
            }
        }
        // Corners by the bits above: x = bit 0, y = bit 1, z = bit 2.
        for f in [
            [0u32, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [1, 3, 7, 5],
            [3, 2, 6, 7],
            [2, 0, 4, 6],
        ] {
            b.push(4);
            for v in f {
                b.extend_from_slice(&v.to_le_bytes());
            }
        }
        b.extend_from_slice(&0i32.to_le_bytes());
        b.extend_from_slice(&1i32.to_le_bytes());
        b
    }

    #[test]
    fn ascii_and_binary_cubes_read_as_closed_solids() {
        for bytes in [CUBE_ASCII.as_bytes().to_vec(), cube_binary()] {
            let (doc, _) = read_ply_bytes(Path::new("cube.ply"), &bytes).unwrap();
            assert_eq!((doc.mesh.num_vertices(), doc.mesh.num_faces()), (8, 6));
            let topo = crate::Topology::build(&doc.mesh).unwrap();
            topo.require_closed(&doc.mesh).unwrap();
            assert!(crate::geometry::signed_volume(&doc.mesh) > 0.99);
        }
    }

    #[test]
    fn bad_files_are_named() {
        let with = |from: &str, to: &str| CUBE_ASCII.replacen(from, to, 1);
        for (text, says) in [
            (with("4 0 3 2 1", "4 0 3 2 9"), "face 0 names vertex 9"),
            (
                with("4 0 3 2 1", "4 0 3 3 1"),
                "face 0 names a vertex twice",
            ),
            (with("4 0 3 2 1", "2 0 3"), "face 0 has 2 corner(s)"),
            (with("element face 6", "element face 0"), "no faces"),
            ("solid x\n".to_string(), "not a PLY file"),
            (with("1 1 1 255", "1 1 x 255"), "Line 20"),
        ] {
            let e = read_ply_bytes(Path::new("c.ply"), text.as_bytes())
                .map(|_| ())
                .unwrap_err()
                .to_string();
            assert!(e.contains(says), "{says}: {e}");
        }
    }
}
