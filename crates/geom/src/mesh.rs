//! The polygon mesh: faces that may be concave and may have holes, stored flat.
//!
//! A face is one outer loop followed by any number of inner loops (holes). Outer loops run
//! counter-clockwise seen from outside the solid, inner loops clockwise, so the face's
//! material lies to the left of every directed edge (docs/algorithms/conventions.md). Storage is
//! CSR-style, like OpenSubdiv's `Vtr::Level`: one array of corner vertex indices, one of loop
//! offsets into it, one of face offsets into the loops; a million faces is a handful of
//! allocations.

use glam::DVec3;
use std::ops::Range;

/// A polygon mesh with `f64` positions.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PolyMesh {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Vertex index of every corner, loop after loop.
    pub corner_verts: Vec<u32>,
    /// Loop `l` owns corners `loop_starts[l]..loop_starts[l + 1]`; length loops + 1.
    pub loop_starts: Vec<u32>,
    /// Face `f` owns loops `face_starts[f]..face_starts[f + 1]`; the first is the outer
    /// loop; length faces + 1.
    pub face_starts: Vec<u32>,
}

impl PolyMesh {
    /// An empty mesh.
    pub fn new() -> Self {
        PolyMesh {
            positions: Vec::new(),
            corner_verts: Vec::new(),
            loop_starts: vec![0],
            face_starts: vec![0],
        }
    }

    /// An empty mesh with room for the given numbers of elements.
    pub fn with_capacity(vertices: usize, faces: usize, loops: usize, corners: usize) -> Self {
        let mut loop_starts = Vec::with_capacity(loops + 1);
        loop_starts.push(0);
        let mut face_starts = Vec::with_capacity(faces + 1);
        face_starts.push(0);
        PolyMesh {
            positions: Vec::with_capacity(vertices),
            corner_verts: Vec::with_capacity(corners),
            loop_starts,
            face_starts,
        }
    }

    /// A mesh of hole-free faces, one vertex list each.
    pub fn from_polygons(positions: Vec<DVec3>, faces: &[Vec<u32>]) -> Self {
        let mut m = PolyMesh::new();
        m.positions = positions;
        for f in faces {
            m.push_face(&[f.as_slice()]);
        }
        m
    }

    /// Appends a face given as its loops (outer first).
    pub fn push_face(&mut self, loops: &[&[u32]]) {
        for l in loops {
            self.corner_verts.extend_from_slice(l);
            self.loop_starts.push(self.corner_verts.len() as u32);
        }
        self.face_starts.push((self.loop_starts.len() - 1) as u32);
    }

    /// Appends a hole-free face.
    pub fn push_polygon(&mut self, verts: &[u32]) {
        self.corner_verts.extend_from_slice(verts);
        self.loop_starts.push(self.corner_verts.len() as u32);
        self.face_starts.push((self.loop_starts.len() - 1) as u32);
    }

    pub fn num_vertices(&self) -> usize {
        self.positions.len()
    }
    pub fn num_faces(&self) -> usize {
        self.face_starts.len().saturating_sub(1)
    }
    pub fn num_loops(&self) -> usize {
        self.loop_starts.len().saturating_sub(1)
    }
    pub fn num_corners(&self) -> usize {
        self.corner_verts.len()
    }

    /// The loops of face `f` (outer first).
    pub fn face_loops(&self, f: usize) -> Range<usize> {
        self.face_starts[f] as usize..self.face_starts[f + 1] as usize
    }
    /// The corners of loop `l`.
    pub fn loop_corners(&self, l: usize) -> Range<usize> {
        self.loop_starts[l] as usize..self.loop_starts[l + 1] as usize
    }
    /// The vertex indices of loop `l`.
    pub fn loop_verts(&self, l: usize) -> &[u32] {
        &self.corner_verts[self.loop_corners(l)]
    }
    /// Whether face `f` has inner loops.
    pub fn face_has_holes(&self, f: usize) -> bool {
        self.face_loops(f).len() > 1
    }
    /// The corners of face `f`, all its loops together.
    pub fn face_corners(&self, f: usize) -> Range<usize> {
        let loops = self.face_loops(f);
        self.loop_starts[loops.start] as usize..self.loop_starts[loops.end] as usize
    }
    /// Number of faces with more than one loop.
    pub fn num_holed_faces(&self) -> usize {
        (0..self.num_faces())
            .filter(|&f| self.face_has_holes(f))
            .count()
    }

    /// Keeps the first `faces` faces and drops the rest (their corners and loops); the
    /// vertices stay. Opens a closed mesh for tests of boundaries.
    pub fn truncate_faces(&mut self, faces: usize) {
        if faces >= self.num_faces() {
            return;
        }
        self.face_starts.truncate(faces + 1);
        self.loop_starts
            .truncate(self.face_starts[faces] as usize + 1);
        self.corner_verts
            .truncate(*self.loop_starts.last().expect("loop offsets start at 0") as usize);
    }

    /// Diagonal of the axis-aligned bounding box (0 for an empty mesh).
    pub fn bbox_diagonal(&self) -> f64 {
        let (lo, hi) = self.bbox();
        if self.positions.is_empty() {
            0.0
        } else {
            (hi - lo).length()
        }
    }

    /// Axis-aligned bounding box (min, max).
    /// Computed on every core (the least and greatest coordinates do not depend on the
    /// order they are met in).
    pub fn bbox(&self) -> (DVec3, DVec3) {
        use rayon::prelude::*;
        let empty = || (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
        self.positions
            .par_iter()
            .with_min_len(1 << 14)
            .fold(empty, |(lo, hi), p| (lo.min(*p), hi.max(*p)))
            .reduce(empty, |(a, b), (c, d)| (a.min(c), b.max(d)))
    }

    /// Whether every coordinate is finite.
    pub fn all_finite(&self) -> bool {
        self.positions.iter().all(|p| p.is_finite())
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn truncating_faces_keeps_the_first_ones_and_every_vertex() {
        let mut m = crate::primitives::holed_block();
        let (v, f) = (m.num_vertices(), m.num_faces());
        let first_loops = m.face_loops(0).len() + m.face_loops(1).len();
        m.truncate_faces(2);
        assert_eq!(
            (m.num_faces(), m.num_vertices(), m.num_loops()),
            (2, v, first_loops)
        );
        assert_eq!(m.num_corners(), m.loop_starts[first_loops] as usize);
        m.truncate_faces(f);
        assert_eq!(m.num_faces(), 2);
    }
}
