//! STL in (ASCII or binary, by the `stl_io` crate): the facets welded into a solid by their
//! corners' exact coordinates, so that a closed STL opens as a closed mesh to round.
//!
//! STL stores every facet's three corners as `f32` and no topology: corners are one vertex
//! where their coordinates are equal bit for bit (−0 taken as +0), in the order they first
//! appear; facets keep their corner order (STL's counter-clockwise from outside). A facet with
//! two equal corners (no area) is refused by number, as is a corner that is not finite; the
//! welded mesh then goes through the model checks every reader's output goes through
//! (closed or with boundaries, edges in at most two faces in opposite directions).

use super::{Document, IoError, Numbering};
use crate::mesh::PolyMesh;
use glam::DVec3;
use std::collections::HashMap;
use std::path::Path;

/// The solid of an STL file's bytes.
pub fn read_stl_bytes(path: &Path, bytes: &[u8]) -> Result<(Document, Numbering), IoError> {
    let invalid = |message: String| IoError::Invalid {
        path: path.into(),
        message,
    };
    let mut cursor = std::io::Cursor::new(bytes);
    let facets = stl_io::create_stl_reader(&mut cursor)
        .map_err(|e| invalid(format!("not an STL file ({e})")))?;
    let mut index: HashMap<[u32; 3], u32> = HashMap::new();
    let mut positions: Vec<DVec3> = Vec::new();
    let mut faces: Vec<[u32; 3]> = Vec::new();
    for (f, facet) in facets.enumerate() {
        let facet = facet.map_err(|e| invalid(format!("facet {f}: {e}")))?;
        let mut corners = [0u32; 3];
        for (k, v) in facet.vertices.iter().enumerate() {
            if v.0.iter().any(|x| !x.is_finite()) {
                return Err(invalid(format!(
                    "facet {f}: corner {k} is not a finite point"
                )));
            }
            // −0 and +0 are one coordinate.
            let key = v.0.map(|x| (x + 0.0).to_bits());
            corners[k] = *index.entry(key).or_insert_with(|| {
                positions.push(DVec3::from_array(v.0.map(f64::from)));
                (positions.len() - 1) as u32
            });
        }
        if corners[0] == corners[1] || corners[1] == corners[2] || corners[2] == corners[0] {
            return Err(invalid(format!(
                "facet {f} has two equal corners (no area): repair the file (e.g. merge or remove degenerate facets)"
            )));
        }
        faces.push(corners);
    }
    if faces.is_empty() {
        return Err(invalid("the STL file has no facets".into()));
    }
    let polys: Vec<Vec<u32>> = faces.iter().map(|f| f.to_vec()).collect();
    let mesh = PolyMesh::from_polygons(positions, &polys);
    Ok((
        Document {
            mesh,
            ..Document::default()
        },
        Numbering::default(),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit cube's 12 facets as binary STL, with −0 in some corners.
    fn cube_stl() -> Vec<u8> {
        let mesh = crate::primitives::fan_triangulated(&crate::primitives::cube3());
        let mut bytes = crate::io::stl_bytes(&mesh, &|_| false);
        // Turn the first facet's first corner's x into −0 where it is +0.
        let at = 84 + 12;
        if f32::from_le_bytes(bytes[at..at + 4].try_into().unwrap()) == 0.0 {
            bytes[at..at + 4].copy_from_slice(&(-0.0f32).to_le_bytes());
        }
        bytes
    }

    #[test]
    fn a_closed_stl_opens_as_a_closed_solid() {
        let (doc, _) = read_stl_bytes(Path::new("cube.stl"), &cube_stl()).unwrap();
        assert_eq!((doc.mesh.num_vertices(), doc.mesh.num_faces()), (8, 12));
        let topo = crate::Topology::build(&doc.mesh).unwrap();
        topo.require_closed(&doc.mesh).unwrap();
    }

    #[test]
    fn ascii_stl_and_bad_facets_are_named() {
        let ascii = "solid t
facet normal 0 0 1
outer loop
vertex 0 0 0
vertex 1 0 0
vertex 1 0 0
endloop
endfacet
endsolid t
";
        let e = read_stl_bytes(Path::new("t.stl"), ascii.as_bytes())
            .unwrap_err()
            .to_string();
        assert!(e.contains("facet 0 has two equal corners"), "{e}");
        let e = read_stl_bytes(Path::new("t.stl"), b"hello")
            .unwrap_err()
            .to_string();
        assert!(e.contains("t.stl"), "{e}");
    }
}
