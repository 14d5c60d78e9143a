//! A section plane through a mesh, for looking inside a model (the viewport's and `prism
//! render`'s `--section`): the part on the kept side of the plane, every face cut where the
//! plane crosses it, and the outline the plane draws on the surface.
//!
//! A face is clipped as a polygon against the half-space `n·x ≤ d` (Sutherland–Hodgman: a
//! corner is kept when it lies on the kept side, and where an edge crosses the plane the
//! point `a + (b − a)·(d − n·a)/(n·(b − a))` is added). A non-convex face gives one polygon
//! that runs along the plane between its kept pieces, which is what a drawing needs. The
//! outline is, for every face that crosses the plane, the segments between its crossing
//! points in the order the polygon meets them (first and second, third and fourth, …).

use crate::mesh::PolyMesh;
use glam::DVec3;

/// The half-space `normal·x ≤ offset` that a section keeps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HalfSpace {
    pub normal: DVec3,
    pub offset: f64,
}

impl HalfSpace {
    /// The signed distance-like value `n·x − d` (≤ 0 kept).
    fn side(&self, x: DVec3) -> f64 {
        self.normal.dot(x) - self.offset
    }
}

/// What a section keeps of a mesh.
#[derive(Debug, Clone)]
pub struct Section {
    /// The kept part: whole faces and clipped ones, each with its own corners (faces that
    /// share a cut edge do not share the point on it).
    pub mesh: PolyMesh,
    /// For each face of `mesh`, the face of the input it was cut from.
    pub from_face: Vec<u32>,
    /// The outline: segments on the plane where it cuts the surface.
    pub outline: Vec<(DVec3, DVec3)>,
}

/// `mesh` cut by the plane of `keep`, the part in `keep` kept ([`Section`]).
pub fn section(mesh: &PolyMesh, keep: HalfSpace) -> Section {
    let mut positions = Vec::new();
    let mut faces: Vec<Vec<u32>> = Vec::new();
    let mut from_face = Vec::new();
    let mut outline = Vec::new();
    for f in 0..mesh.num_faces() {
        let pts: Vec<DVec3> = mesh
            .face_corners(f)
            .map(|c| mesh.positions[mesh.corner_verts[c] as usize])
            .collect();
        let sides: Vec<f64> = pts.iter().map(|&p| keep.side(p)).collect();
        if sides.iter().all(|&s| s > 0.0) {
            continue;
        }
        let mut poly = Vec::with_capacity(pts.len() + 2);
        let mut cuts = Vec::new();
        for i in 0..pts.len() {
            let j = (i + 1) % pts.len();
            let (a, b, sa, sb) = (pts[i], pts[j], sides[i], sides[j]);
            if sa <= 0.0 {
                poly.push(a);
            }
            if (sa <= 0.0) != (sb <= 0.0) {
                let x = a + (b - a) * (sa / (sa - sb));
                poly.push(x);
                cuts.push(x);
            }
        }
        for pair in cuts.chunks_exact(2) {
            outline.push((pair[0], pair[1]));
        }
        if poly.len() < 3 {
            continue;
        }
        let start = positions.len() as u32;
        faces.push((start..start + poly.len() as u32).collect());
        positions.extend(poly);
        from_face.push(f as u32);
    }
    Section {
        mesh: PolyMesh::from_polygons(positions, &faces),
        from_face,
        outline,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;

    /// The cube of side 3 cut at x = 1 (kept x ≤ 1): every kept point in the half-space, the
    /// four side faces cut, the outline a square of side 3 on the plane (length 12); turned
    /// round (x ≥ 1) the rest; a plane missing the cube keeps all of it or nothing.
    #[test]
    fn a_cube_cut_through_its_middle() {
        let cube = primitives::cube3();
        let keep = HalfSpace {
            normal: DVec3::X,
            offset: 1.0,
        };
        let s = section(&cube, keep);
        assert!(s.mesh.positions.iter().all(|p| p.x <= 1.0 + 1e-12));
        // The face at x = 0 whole, four faces cut, the face at x = 3 gone.
        assert_eq!(s.mesh.num_faces(), 5);
        let length: f64 = s.outline.iter().map(|(a, b)| a.distance(*b)).sum();
        assert!((length - 12.0).abs() < 1e-12, "{length}");
        assert!(
            s.outline
                .iter()
                .all(|(a, b)| (a.x - 1.0).abs() < 1e-12 && (b.x - 1.0).abs() < 1e-12)
        );
        let rest = section(
            &cube,
            HalfSpace {
                normal: -DVec3::X,
                offset: -1.0,
            },
        );
        assert!(rest.mesh.positions.iter().all(|p| p.x >= 1.0 - 1e-12));
        assert_eq!(rest.mesh.num_faces(), 5);
        let all = section(
            &cube,
            HalfSpace {
                normal: DVec3::X,
                offset: 10.0,
            },
        );
        assert_eq!(all.mesh.num_faces(), 6);
        assert!(all.outline.is_empty());
        assert_eq!(all.from_face, vec![0, 1, 2, 3, 4, 5]);
        let none = section(
            &cube,
            HalfSpace {
                normal: DVec3::X,
                offset: -10.0,
            },
        );
        assert_eq!(none.mesh.num_faces(), 0);
    }
}
