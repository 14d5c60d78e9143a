//! The winding number of a closed mesh about a point: the signed solid angle its faces
//! subtend there over 4π (Van Oosterom & Strackee's formula for a triangle's solid angle,
//! `tan(Ω/2) = a·(b × c) / (abc + (a·b)c + (b·c)a + (c·a)b)`, each face fanned from its first
//! corner). 1 inside an outward closed mesh, 0 outside; on a face it is not defined.
//! [`Inside`] answers the same question for many points faster, by the parity of a ray's
//! crossings.

use crate::mesh::PolyMesh;
use glam::{DVec2, DVec3};

/// Signed solid angle sum / 4π of the faces of `m` about `p`.
pub fn winding_number(m: &PolyMesh, p: DVec3) -> f64 {
    let mut w = 0.0;
    for f in 0..m.num_faces() {
        let mut corners = m
            .face_corners(f)
            .map(|c| m.positions[m.corner_verts[c] as usize] - p);
        let Some(a) = corners.next() else { continue };
        let Some(mut b) = corners.next() else {
            continue;
        };
        let la = a.length();
        for c in corners {
            let (lb, lc) = (b.length(), c.length());
            let num = a.dot(b.cross(c));
            let den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
            w += 2.0 * num.atan2(den);
            b = c;
        }
    }
    w / (4.0 * std::f64::consts::PI)
}

/// A closed mesh's triangles (faces fanned from their first corner), for asking of many
/// points whether they lie inside: a ray from the point in a fixed direction, chosen off every
/// axis and diagonal, crosses the surface an odd number of times (Möller & Trumbore's
/// ray–triangle test). A ray through an edge or a corner is counted once on each face beside
/// it, so a point whose ray grazes the mesh exactly may be misjudged; the direction makes that
/// a set of measure zero. The triangles are binned on a grid over their projections along
/// the ray, so a point meets only those of its cell: about √T per side for T triangles.
pub struct Inside {
    triangles: Vec<[DVec3; 3]>,
    /// Two unit vectors spanning the plane normal to the ray.
    frame: [DVec3; 2],
    /// The grid's corner, cell size and cells a side, in the plane normal to the ray.
    origin: DVec2,
    cell: f64,
    side: usize,
    /// The triangles of each cell, row by row.
    bins: Vec<Vec<u32>>,
}

/// The ray's direction: unit, on no axis, face diagonal or space diagonal.
const RAY: DVec3 = DVec3::new(
    0.539_163_866_017_192_8,
    0.574_061_574_136_009_4,
    0.616_314_432_069_866,
);

/// Coordinates in the plane normal to [`RAY`], on the unit vectors `frame`.
fn across(frame: [DVec3; 2], p: DVec3) -> DVec2 {
    DVec2::new(p.dot(frame[0]), p.dot(frame[1]))
}

impl Inside {
    pub fn new(m: &PolyMesh) -> Inside {
        let u = RAY.any_orthonormal_vector();
        let frame = [u, RAY.cross(u)];
        let mut triangles = Vec::with_capacity(2 * m.num_faces());
        for f in 0..m.num_faces() {
            let c: Vec<DVec3> = m
                .face_corners(f)
                .map(|c| m.positions[m.corner_verts[c] as usize])
                .collect();
            for k in 1..c.len().saturating_sub(1) {
                triangles.push([c[0], c[k], c[k + 1]]);
            }
        }
        let boxes: Vec<(DVec2, DVec2)> = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|p| across(frame, p));
                (a.min(b).min(c), a.max(b).max(c))
            })
            .collect();
        let lo = boxes.iter().fold(DVec2::INFINITY, |m, b| m.min(b.0));
        let hi = boxes.iter().fold(DVec2::NEG_INFINITY, |m, b| m.max(b.1));
        let side = ((triangles.len() as f64).sqrt().ceil() as usize).max(1);
        let cell = ((hi - lo).max_element() / side as f64).max(f64::MIN_POSITIVE);
        let mut bins = vec![Vec::new(); side * side];
        if lo.is_finite() {
            let at = |x: f64| ((x / cell) as usize).min(side - 1);
            for (i, (a, b)) in boxes.iter().enumerate() {
                let (a, b) = (*a - lo, *b - lo);
                for y in at(a.y)..=at(b.y) {
                    for x in at(a.x)..=at(b.x) {
                        bins[y * side + x].push(i as u32);
                    }
                }
            }
        }
        Inside {
            triangles,
            frame,
            origin: lo,
            cell,
            side,
            bins,
        }
    }

    /// Whether `p` lies inside the mesh.
    pub fn contains(&self, p: DVec3) -> bool {
        let q = (across(self.frame, p) - self.origin) / self.cell;
        if !(q.x >= 0.0 && q.y >= 0.0 && q.x < self.side as f64 && q.y < self.side as f64) {
            return false;
        }
        let bin = &self.bins[q.y as usize * self.side + q.x as usize];
        let mut crossings = 0usize;
        for &i in bin {
            let [a, b, c] = self.triangles[i as usize];
            let (e1, e2) = (b - a, c - a);
            let pv = RAY.cross(e2);
            let det = e1.dot(pv);
            if det == 0.0 {
                continue;
            }
            let inv = 1.0 / det;
            let tv = p - a;
            let u = tv.dot(pv) * inv;
            if !(0.0..=1.0).contains(&u) {
                continue;
            }
            let qv = tv.cross(e1);
            let v = RAY.dot(qv) * inv;
            if v < 0.0 || u + v > 1.0 {
                continue;
            }
            if e2.dot(qv) * inv > 0.0 {
                crossings += 1;
            }
        }
        crossings % 2 == 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;

    #[test]
    fn a_box_winds_once_about_its_inside_and_not_about_its_outside() {
        let m = primitives::cuboid(DVec3::ZERO, DVec3::new(1.0, 2.0, 3.0));
        assert!((winding_number(&m, DVec3::new(0.5, 1.0, 1.5)) - 1.0).abs() < 1e-12);
        assert!(winding_number(&m, DVec3::new(1.5, 1.0, 1.5)).abs() < 1e-12);
        let inside = Inside::new(&m);
        assert!(inside.contains(DVec3::new(0.5, 1.0, 1.5)));
        assert!(inside.contains(DVec3::new(0.01, 1.99, 2.99)));
        assert!(!inside.contains(DVec3::new(1.5, 1.0, 1.5)));
        assert!(!inside.contains(DVec3::new(-0.01, 1.0, 1.5)));
        // The ray's parity agrees with the winding number on an L-shaped block's
        // neighbourhood (concave, faces of six corners).
        let l = primitives::l_block();
        let inside = Inside::new(&l);
        let (lo, hi) = l
            .positions
            .iter()
            .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(a, b), &p| {
                (a.min(p), b.max(p))
            });
        for i in 0..1000 {
            let f = |k: u32| ((i * 7919 + k * 104_729) % 1000) as f64 / 1000.0;
            // Off every face plane: the winding number is not defined on a face.
            let s = (DVec3::new(f(1), f(2), f(3)) + 3.7e-4) * 1.2 - 0.1;
            let p = lo + (hi - lo) * s;
            assert_eq!(inside.contains(p), winding_number(&l, p) > 0.5, "{p}");
        }
    }
}
