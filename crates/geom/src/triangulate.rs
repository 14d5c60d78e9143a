//! Triangles of polygon faces, concave faces and faces with holes included, for drawing and
//! for the triangle-only file formats (STL, glTF, OBJ faces with holes).
//!
//! A face is projected onto its own plane (Newell normal, [`crate::geometry::face_normal_raw`])
//! and cut into triangles by ear clipping with hole bridging (`earcutr`, the Rust port of
//! Mapbox's earcut); triangles come back oriented like the face. A triangle is returned as
//! it is; a quad is cut along the diagonal that leaves both halves facing like the face (the
//! one through its reflex corner when it is concave; 0–2 when both do), without the ear
//! clipper's allocations — most faces of a refined level are quads; a face whose outline is
//! too degenerate for ear clipping (or with a coordinate that is not finite) falls back to a
//! fan, so it stays visible and keeps its area.

use crate::geometry::{face_normal_raw, unit_or_zero};
use crate::mesh::PolyMesh;
use glam::DVec3;

/// Triangles of face `f` as *corner* indices (into `mesh.corner_verts`), oriented like
/// `normal` (the face's unit normal).
pub fn face_triangles(mesh: &PolyMesh, f: usize, normal: DVec3) -> Vec<[u32; 3]> {
    let mut out = Vec::new();
    push_face_triangles(mesh, f, normal, &mut out);
    out
}

/// As [`face_triangles`], appended to `out`: a triangle or a quad allocates nothing (the
/// scene of a level pushes every face's triangles into one buffer a chunk of faces).
pub fn push_face_triangles(mesh: &PolyMesh, f: usize, normal: DVec3, out: &mut Vec<[u32; 3]>) {
    let loops = mesh.face_loops(f);
    let outer = mesh.loop_corners(loops.start);
    let n = outer.len();
    if loops.len() == 1 && n == 3 {
        let s = outer.start as u32;
        out.push([s, s + 1, s + 2]);
        return;
    }
    if loops.len() == 1 && n == 4 {
        let s = outer.start as u32;
        let p = |i: u32| mesh.positions[mesh.corner_verts[(s + i) as usize] as usize];
        let faces_up = |a: u32, b: u32, c: u32| (p(b) - p(a)).cross(p(c) - p(a)).dot(normal) > 0.0;
        if faces_up(0, 1, 2) && faces_up(0, 2, 3) {
            out.extend([[s, s + 1, s + 2], [s, s + 2, s + 3]]);
            return;
        }
        if faces_up(1, 2, 3) && faces_up(1, 3, 0) {
            out.extend([[s + 1, s + 2, s + 3], [s + 1, s + 3, s]]);
            return;
        }
    }
    let u = normal.any_orthonormal_vector();
    let w = normal.cross(u);
    let mut coords = Vec::new();
    let mut corners = Vec::new();
    let mut holes = Vec::new();
    for (k, l) in loops.enumerate() {
        if k > 0 {
            holes.push(corners.len());
        }
        for c in mesh.loop_corners(l) {
            let p = mesh.positions[mesh.corner_verts[c] as usize];
            coords.extend([p.dot(u), p.dot(w)]);
            corners.push(c as u32);
        }
    }
    // Ear clipping panics on a coordinate that is not finite (its leftmost point is never
    // found); such a face gets the fan.
    let tris = if coords.iter().all(|x| x.is_finite()) {
        earcutr::earcut(&coords, &holes, 2).unwrap_or_default()
    } else {
        Vec::new()
    };
    if tris.is_empty() {
        let s = outer.start as u32;
        out.extend((1..n as u32 - 1).map(|i| [s, s + i, s + i + 1]));
        return;
    }
    let p = |c: u32| mesh.positions[mesh.corner_verts[c as usize] as usize];
    out.extend(tris.chunks_exact(3).map(|t| {
        let [a, b, c] = [corners[t[0]], corners[t[1]], corners[t[2]]];
        if (p(b) - p(a)).cross(p(c) - p(a)).dot(normal) < 0.0 {
            [a, c, b]
        } else {
            [a, b, c]
        }
    }));
}

/// Triangles of face `f` as *vertex* indices, oriented like the face.
pub fn face_vertex_triangles(mesh: &PolyMesh, f: usize) -> Vec<[u32; 3]> {
    let n = unit_or_zero(face_normal_raw(mesh, f));
    face_triangles(mesh, f, n)
        .into_iter()
        .map(|t| t.map(|c| mesh.corner_verts[c as usize]))
        .collect()
}

/// Every face's triangles as vertex indices, skipping the faces `skip` says (holes).
pub fn mesh_triangles(mesh: &PolyMesh, skip: &dyn Fn(usize) -> bool) -> Vec<[u32; 3]> {
    (0..mesh.num_faces())
        .filter(|&f| !skip(f))
        .flat_map(|f| face_vertex_triangles(mesh, f))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area(m: &PolyMesh, tris: &[[u32; 3]]) -> f64 {
        let p = |v: u32| m.positions[v as usize];
        tris.iter()
            .map(|t| 0.5 * (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0])).z)
            .sum()
    }

    #[test]
    fn concave_face_with_a_hole_keeps_its_area_and_orientation() {
        // An L (area 3) with a square hole of area 0.25 in its corner square.
        let mut pts = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(2.0, 1.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(1.0, 2.0, 0.0),
            DVec3::new(0.0, 2.0, 0.0),
        ];
        pts.extend([
            DVec3::new(0.25, 0.25, 0.0),
            DVec3::new(0.25, 0.75, 0.0),
            DVec3::new(0.75, 0.75, 0.0),
            DVec3::new(0.75, 0.25, 0.0),
        ]);
        let mut m = PolyMesh::new();
        m.positions = pts;
        m.push_face(&[&[0, 1, 2, 3, 4, 5], &[6, 7, 8, 9]]);
        let tris = mesh_triangles(&m, &|_| false);
        // n + 2h − 2 triangles for n outline and h hole vertices with one hole.
        assert_eq!(tris.len(), 6 + 4 + 2 - 2);
        assert!((area(&m, &tris) - 2.75).abs() < 1e-12);
        let p = |v: u32| m.positions[v as usize];
        for t in &tris {
            assert!((p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0])).z > 0.0);
        }
        assert!(mesh_triangles(&m, &|_| true).is_empty());
    }

    /// A concave quad (a dart) is cut through its reflex corner, whichever corner is first.
    #[test]
    fn a_concave_quad_is_cut_through_its_reflex_corner() {
        let dart = [
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(2.0, 1.0, 0.0),
            DVec3::new(0.0, 2.0, 0.0),
            DVec3::new(0.5, 1.0, 0.0), // reflex
        ];
        for shift in 0..4 {
            let mut m = PolyMesh::new();
            m.positions = (0..4).map(|i| dart[(i + shift) % 4]).collect();
            m.push_polygon(&[0, 1, 2, 3]);
            let tris = mesh_triangles(&m, &|_| false);
            assert_eq!(tris.len(), 2);
            // Shoelace area of the dart: 1.5.
            assert!((area(&m, &tris) - 1.5).abs() < 1e-12, "shift {shift}");
            let p = |v: u32| m.positions[v as usize];
            for t in &tris {
                assert!((p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0])).z > 0.0);
            }
        }
    }

    /// A pentagon with a coordinate that is not finite (a result gone wrong upstream) gets the
    /// fan: with one, the ear clipper cut it at random; with every point NaN, it panicked.
    #[test]
    fn a_face_with_a_nan_coordinate_gets_the_fan() {
        let mut m = PolyMesh::new();
        m.positions = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(2.0, 1.0, 0.0),
            DVec3::new(f64::NAN, 1.5, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
        ];
        m.push_polygon(&[0, 1, 2, 3, 4]);
        let fan = vec![[0, 1, 2], [0, 2, 3], [0, 3, 4]];
        assert_eq!(face_triangles(&m, 0, DVec3::Z), fan);
        m.positions.iter_mut().for_each(|p| *p = DVec3::NAN);
        assert_eq!(face_triangles(&m, 0, DVec3::Z), fan);
    }
}
