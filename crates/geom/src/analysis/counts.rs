//! Element counts of a mesh.

use crate::mesh::PolyMesh;

/// Vertices, edges (half the corners of a closed mesh), faces and the faces that are not quads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MeshCounts {
    pub vertices: usize,
    pub edges: usize,
    pub faces: usize,
    pub holed_faces: usize,
    pub non_quads: usize,
}

impl MeshCounts {
    /// V − E + F (the Euler characteristic when every face is a disc).
    pub fn euler(&self) -> i64 {
        self.vertices as i64 - self.edges as i64 + self.faces as i64
    }
}

/// Counts of a closed mesh (edges = corners / 2).
pub fn counts(m: &PolyMesh) -> MeshCounts {
    let non_quads = (0..m.num_faces())
        .filter(|&f| m.face_has_holes(f) || m.face_corners(f).len() != 4)
        .count();
    MeshCounts {
        vertices: m.num_vertices(),
        edges: m.num_corners() / 2,
        faces: m.num_faces(),
        holed_faces: m.num_holed_faces(),
        non_quads,
    }
}
