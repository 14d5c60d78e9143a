//! How messages name the elements of an input: as its file counts them.
//!
//! Prism numbers vertices and faces from 0 inside. An OBJ file counts them from 1 in its
//! `f` lines and has a line for each, so a message about an OBJ input says `vertex 4 (line
//! 7)` for Prism's vertex 3; a `.prism.json` lists them in arrays, counted from 0, and its
//! messages use Prism's numbers. (OBJ `t` tag lines count vertices from 0, as OpenSubdiv
//! writes them; the reader names the line of a bad tag itself.)

use crate::error::{MeshError, MeshWarning};

/// How a file counts its vertices and faces, and the line of each (empty when it has none).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Numbering {
    /// The number of the first element: 1 for OBJ, 0 otherwise.
    pub base: u32,
    /// 1-based line of each vertex.
    pub vertex_lines: Vec<usize>,
    /// 1-based line of each face.
    pub face_lines: Vec<usize>,
}

impl Numbering {
    /// An OBJ file's: from 1, with the lines of its `v` and `f` records.
    pub fn obj(vertex_lines: Vec<usize>, face_lines: Vec<usize>) -> Numbering {
        Numbering {
            base: 1,
            vertex_lines,
            face_lines,
        }
    }

    fn number(&self, i: u32) -> u64 {
        i as u64 + self.base as u64
    }

    /// `vertex 4 (line 7)`, or `vertex 3` without lines.
    pub fn vertex(&self, v: u32) -> String {
        match self.vertex_lines.get(v as usize) {
            Some(l) => format!("vertex {} (line {l})", self.number(v)),
            None => format!("vertex {}", self.number(v)),
        }
    }

    /// `face 2 (line 9)`, or `face 1` without lines.
    pub fn face(&self, f: u32) -> String {
        format!("face {}", self.face_number(f))
    }

    /// A face's number with its line: `2 (line 9)`.
    fn face_number(&self, f: u32) -> String {
        match self.face_lines.get(f as usize) {
            Some(l) => format!("{} (line {l})", self.number(f)),
            None => self.number(f).to_string(),
        }
    }

    /// `edge 1-2`: its two vertices.
    pub fn edge(&self, a: u32, b: u32) -> String {
        format!("edge {}-{}", self.number(a), self.number(b))
    }

    /// The message of a mesh error, elements named as the file counts them.
    pub fn describe(&self, e: &MeshError) -> String {
        let n = |i: u32| self.number(i);
        match e {
            MeshError::NonFinite { vertex, x, y, z } => format!(
                "{} has a non-finite coordinate ({x}, {y}, {z})",
                self.vertex(*vertex)
            ),
            MeshError::IndexOutOfRange { face, index, count } => format!(
                "{} refers to vertex {}, but the mesh has only {count} vertices",
                self.face(*face),
                n(*index)
            ),
            MeshError::EmptyFace { face } => format!("{} has no loop", self.face(*face)),
            MeshError::DegenerateLoop { face, lp, distinct } => format!(
                "{}, loop {lp}: a loop needs at least 3 distinct vertices, this one has {distinct}",
                self.face(*face)
            ),
            MeshError::RepeatedVertex { face, vertex } => {
                format!("{} uses vertex {} twice", self.face(*face), n(*vertex))
            }
            MeshError::NonManifoldEdge { a, b, faces } => format!(
                "{} is used by more than two faces (faces {})",
                self.edge(*a, *b),
                faces
                    .iter()
                    .map(|&f| self.face_number(f))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            MeshError::InconsistentOrientation { a, b, f1, f2 } => format!(
                "{} is traversed {}→{} by both {} and {}: the faces are inconsistently oriented",
                self.edge(*a, *b),
                n(*a),
                n(*b),
                self.face(*f1),
                self.face(*f2)
            ),
            MeshError::BoundaryEdge { a, b, face } => format!(
                "the mesh is open: {} of {} has no face on its other side",
                self.edge(*a, *b),
                self.face(*face)
            ),
            MeshError::NonManifoldVertex { vertex, fans } => format!(
                "{} is non-manifold: its faces form {fans} separate fans",
                self.vertex(*vertex)
            ),
            MeshError::NoFaces => "the mesh has no faces".to_string(),
            MeshError::TooLarge { what } => {
                format!("the mesh is too large: {what} exceeds the 32-bit index range")
            }
        }
    }

    /// The message of a mesh warning, elements named as the file counts them.
    pub fn describe_warning(&self, w: &MeshWarning) -> String {
        match w {
            MeshWarning::UnusedVertices { count, first } => format!(
                "{count} vertex(es) are used by no face (the first is {}); they are ignored",
                self.vertex(*first)
            ),
        }
    }
}

impl std::fmt::Display for MeshError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&Numbering::default().describe(self))
    }
}

impl std::fmt::Display for MeshWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&Numbering::default().describe_warning(self))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn obj_counts_from_one_with_lines_and_json_from_zero() {
        let e = MeshError::InconsistentOrientation {
            a: 0,
            b: 1,
            f1: 0,
            f2: 1,
        };
        let obj = Numbering::obj(vec![1, 2, 3, 4], vec![5, 6]);
        assert_eq!(
            obj.describe(&e),
            "edge 1-2 is traversed 1→2 by both face 1 (line 5) and face 2 (line 6): \
             the faces are inconsistently oriented"
        );
        assert_eq!(
            Numbering::default().describe(&e),
            "edge 0-1 is traversed 0→1 by both face 0 and face 1: the faces are \
             inconsistently oriented"
        );
        let w = MeshWarning::UnusedVertices { count: 2, first: 3 };
        assert!(
            obj.describe_warning(&w)
                .contains("the first is vertex 4 (line 4)")
        );
        // Past the lines known (or u32::MAX), no line and no overflow.
        assert_eq!(obj.vertex(u32::MAX), "vertex 4294967296");
    }
}
