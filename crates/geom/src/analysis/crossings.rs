//! Where a surface crosses itself: pairs of faces whose interiors intersect. The flip test of a step ([`crate::step::check_children`]) sees a face turned
//! against its parent; it cannot see two faces that pass through each other while both
//! still face outward — the spikes two vector-sum steps leave under the tripod's arms, the
//! ears of vector sum as printed at a reflex corner (docs/algorithms/chamfers.md).
//!
//! Faces are triangulated as the renderer does ([`crate::triangulate`]), once for the whole
//! search (one flat list, each triangle with its unit normal); candidate pairs are the faces
//! whose boxes overlap, found by a bounding volume hierarchy walked against itself
//! ([`super::box_pairs`]; a uniform grid before it met 36 million candidates on the Computer
//! room's 129,066 faces after five combination steps, whose boxes overlap in 516,316 pairs);
//! each pair of their triangles is tested as Möller (1997, "A fast triangle–triangle
//! intersection test") does: each triangle must straddle the other's plane, and the two
//! segments in which they cut the line where the planes meet must overlap by more than a
//! relative 1e-9. A triangle of one face whose plane has the whole other face on one side is
//! dropped before its pairs are tested, and triangles that share an edge are not tested
//! (they only touch). Coplanar pairs and pairs that only touch are not counted — so
//! neighbours that share an edge never count, and faces that share a vertex count only when
//! they pass through each other beyond it (a fold at that vertex). The whole search on that
//! level and the next (516,138 faces): 130–145 ms and 0.53–0.64 s on two threads, against
//! 205 ms and 1.0–1.15 s with the grid and a triangulation per pair of faces.

use super::box_pairs::{boxes_meet, overlapping_pairs};
use super::face_grid::{FaceGrid, face_box};
use crate::geometry::{face_normal_raw, unit_or_zero};
use crate::mesh::PolyMesh;
use crate::triangulate::push_face_triangles;
use glam::DVec3;

/// Relative tolerance of the plane sides and of the overlap (× the pair's size).
const TOL: f64 = 1e-9;

/// The pairs of faces `(f, g)`, `f < g`, that cross each other, ascending. A face of more
/// than [`WHOLE`] triangles (a skin's cap, a big polygon) takes part as its triangles, each
/// with its own box: such a face's box meets every face near it, and testing all of its
/// triangles against each of them was quadratic (two caps of 20,000 points: 20 s).
pub fn crossings(mesh: &PolyMesh) -> Vec<(u32, u32)> {
    use rayon::prelude::*;

    let tris = FaceTris::new(mesh);
    // The search's items: a face, or one triangle of a big face; (face, its triangles).
    let mut items: Vec<(u32, std::ops::Range<u32>)> = Vec::with_capacity(mesh.num_faces());
    for f in 0..mesh.num_faces() as u32 {
        let r = tris.range(f);
        if r.len() > WHOLE {
            items.extend(r.map(|t| (f, t..t + 1)));
        } else {
            items.push((f, r));
        }
    }
    let boxes: Vec<(DVec3, DVec3)> = items
        .par_iter()
        .map(|(f, r)| {
            if r.len() == 1 && tris.range(*f).len() > WHOLE {
                let t = &tris.tris[r.start as usize];
                let p = t.v.map(|v| mesh.positions[v as usize]);
                (p[0].min(p[1]).min(p[2]), p[0].max(p[1]).max(p[2]))
            } else {
                face_box(mesh, *f as usize)
            }
        })
        .collect();
    let of = |i: u32| {
        let r = &items[i as usize].1;
        &tris.tris[r.start as usize..r.end as usize]
    };
    let mut out: Vec<(u32, u32)> = overlapping_pairs(&boxes, |i, j| {
        items[i as usize].0 != items[j as usize].0 && faces_cross(mesh, of(i), of(j))
    })
    .into_iter()
    .map(|(i, j)| {
        let (f, g) = (items[i as usize].0, items[j as usize].0);
        (f.min(g), f.max(g))
    })
    .collect();
    out.sort_unstable();
    out.dedup();
    out
}

/// Faces of more triangles than this take part in [`crossings`] triangle by triangle.
const WHOLE: usize = 16;

/// The pairs `(f, g)`, `f` one of `faces`, in which it crosses a face `g` of `mesh` (one of
/// them — then both ways — or another), ascending: the same test as [`crossings`], for a few
/// faces without a grid of all of them; `among`, when given, lists the faces g tried (the
/// neighbourhood where a crossing is looked for), else every face is. The listed faces go into
/// a [`FaceGrid`] of their own (at most `LOCAL_CELLS` cells); one pass over the faces tried
/// skips those whose box misses the listed faces' joint box and tries the listed faces whose
/// boxes overlap theirs ([`FaceGrid::for_each_overlapping`]).
pub fn crossings_of(mesh: &PolyMesh, faces: &[u32], among: Option<&[u32]>) -> Vec<(u32, u32)> {
    use rayon::prelude::*;
    if faces.is_empty() {
        return Vec::new();
    }
    let boxes: Vec<(DVec3, DVec3)> = faces.iter().map(|&f| face_box(mesh, f as usize)).collect();
    if let Some(i) = boxes
        .iter()
        .position(|b| !(b.0.is_finite() && b.1.is_finite()))
    {
        // A face with a NaN point: counted as crossing itself.
        return vec![(faces[i], faces[i])];
    }
    let joint = boxes.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), b| (lo.min(b.0), hi.max(b.1)),
    );
    let grid = FaceGrid::of_boxes(boxes, LOCAL_CELLS);
    let listed: Vec<Vec<Tri>> = faces.iter().map(|&f| Tri::of_face(mesh, f)).collect();
    let all: Vec<u32>;
    let among = match among {
        Some(a) => a,
        None => {
            all = (0..mesh.num_faces() as u32).collect();
            &all
        }
    };
    let mut out: Vec<(u32, u32)> = among
        .par_iter()
        .with_min_len(1 << 12)
        .flat_map_iter(|&g| {
            let gb = face_box(mesh, g as usize);
            let mut hits = Vec::new();
            // A face with a NaN point overlaps nothing here; `crossings` names it.
            if !boxes_meet(&joint, &gb) {
                return hits;
            }
            let mut tg = None;
            grid.for_each_overlapping(gb, |i| {
                if faces[i] != g {
                    let tg = tg.get_or_insert_with(|| Tri::of_face(mesh, g));
                    if faces_cross(mesh, &listed[i], tg) {
                        hits.push((faces[i], g));
                    }
                }
            });
            hits
        })
        .collect();
    out.sort_unstable();
    out
}

/// The most cells [`crossings_of`]'s grid has.
const LOCAL_CELLS: f64 = (1 << 18) as f64;

/// Those of faces `others` of `mesh` that face `f` crosses (the test of [`crossings`], for a
/// face and its neighbours without a search): `f`'s triangles found once, each other face's
/// only where its box meets `f`'s.
pub fn crossed_by(mesh: &PolyMesh, f: u32, others: &[u32]) -> Vec<u32> {
    let fb = face_box(mesh, f as usize);
    let tf = Tri::of_face(mesh, f);
    let mut tg = Vec::new();
    others
        .iter()
        .copied()
        .filter(|&g| {
            let gb = face_box(mesh, g as usize);
            if g == f || !boxes_meet(&fb, &gb) {
                return false;
            }
            tg.clear();
            Tri::push_face(mesh, g as usize, &mut tg);
            faces_cross(mesh, &tf, &tg)
        })
        .collect()
}

/// The midpoint of each pair of `pairs` (the mean of the two faces' centroids): where a view
/// marks them.
pub fn crossing_points(mesh: &PolyMesh, pairs: &[(u32, u32)]) -> Vec<DVec3> {
    let centroid = |f: u32| {
        let c = mesh.face_corners(f as usize);
        let n = c.len().max(1) as f64;
        c.map(|c| mesh.positions[mesh.corner_verts[c] as usize])
            .sum::<DVec3>()
            / n
    };
    pairs
        .iter()
        .map(|&(f, g)| 0.5 * (centroid(f) + centroid(g)))
        .collect()
}

/// The faces of crossing `pairs`, each once, ascending (what is drawn red).
pub fn crossing_faces(pairs: &[(u32, u32)]) -> Vec<u32> {
    let mut faces: Vec<u32> = pairs.iter().flat_map(|&(f, g)| [f, g]).collect();
    faces.sort_unstable();
    faces.dedup();
    faces
}

/// One triangle of a face as [`crossings`] tests it: its vertices and its unit normal (none
/// for a triangle of no area), found once per face rather than per pair.
struct Tri {
    v: [u32; 3],
    n: Option<DVec3>,
}

impl Tri {
    /// Face `f`'s triangles, as the renderer draws them.
    fn of_face(mesh: &PolyMesh, f: u32) -> Vec<Tri> {
        let mut t = Vec::new();
        Tri::push_face(mesh, f as usize, &mut t);
        t
    }

    /// Face `f`'s triangles, as the renderer draws them, appended to `out` (`corners` a
    /// buffer for the triangles' corners).
    fn push_face(mesh: &PolyMesh, f: usize, out: &mut Vec<Tri>) {
        let mut corners = Vec::new();
        push_face_triangles(
            mesh,
            f,
            unit_or_zero(face_normal_raw(mesh, f)),
            &mut corners,
        );
        out.extend(corners.into_iter().map(|t| {
            let v = t.map(|c| mesh.corner_verts[c as usize]);
            Tri {
                v,
                n: plane(&v.map(|v| mesh.positions[v as usize])),
            }
        }));
    }
}

/// Every face's triangles in one list (a chunk of faces at a time, in parallel): face f's
/// are `tris[first[f]..first[f + 1]]`.
struct FaceTris {
    tris: Vec<Tri>,
    first: Vec<u32>,
}

impl FaceTris {
    fn new(mesh: &PolyMesh) -> FaceTris {
        use rayon::prelude::*;
        let n = mesh.num_faces();
        let chunks: Vec<(Vec<Tri>, Vec<u32>)> = (0..n.div_ceil(CHUNK))
            .into_par_iter()
            .map(|k| {
                let mut tris = Vec::new();
                let mut ends = Vec::new();
                for f in k * CHUNK..((k + 1) * CHUNK).min(n) {
                    Tri::push_face(mesh, f, &mut tris);
                    ends.push(tris.len() as u32);
                }
                (tris, ends)
            })
            .collect();
        let mut out = FaceTris {
            tris: Vec::with_capacity(chunks.iter().map(|c| c.0.len()).sum()),
            first: Vec::with_capacity(n + 1),
        };
        out.first.push(0);
        for (tris, ends) in chunks {
            let base = out.tris.len() as u32;
            out.first.extend(ends.iter().map(|e| base + e));
            out.tris.extend(tris);
        }
        out
    }

    fn range(&self, f: u32) -> std::ops::Range<u32> {
        self.first[f as usize]..self.first[f as usize + 1]
    }
}

/// Faces a thread triangulates at a time.
const CHUNK: usize = 1 << 12;

/// The unit normal of triangle `t`, none when it has no area.
fn plane(t: &[DVec3; 3]) -> Option<DVec3> {
    let n = (t[1] - t[0]).cross(t[2] - t[0]);
    let l = n.length();
    (l > 0.0).then(|| n / l)
}

fn faces_cross(mesh: &PolyMesh, a: &[Tri], b: &[Tri]) -> bool {
    let p = |t: &Tri| t.v.map(|v| mesh.positions[v as usize]);
    a.iter().any(|ta| {
        // A triangle of `a` whose plane has all of `b` on one side crosses none of b's
        // triangles (the test below needs each to straddle it): one pass over b's points
        // instead of one per triangle. Its own vertices, shared, count as on the plane.
        let Some(n) = ta.n else {
            return false;
        };
        let o = mesh.positions[ta.v[0] as usize];
        let (mut above, mut below) = (false, false);
        for v in b.iter().flat_map(|tb| tb.v) {
            if !ta.v.contains(&v) {
                let d = n.dot(mesh.positions[v as usize] - o);
                above |= d > 0.0;
                below |= d < 0.0;
            }
        }
        above
            && below
            && b.iter().any(|tb| {
                // Triangles on one edge only touch (or lie in one plane): the test below says
                // no for them; this says it without the arithmetic (most pairs of neighbours).
                let shared = ta.v.iter().filter(|v| tb.v.contains(v)).count();
                shared < 2 && planes_cross(p(ta), ta.n, p(tb), tb.n)
            })
    })
}

/// Whether two triangles' interiors intersect (not merely touch; coplanar pairs: no). Two
/// triangles that share a vertex cross only when both cut the other's plane and the two cuts
/// leave the shared vertex the same way.
pub fn triangles_cross(a: [DVec3; 3], b: [DVec3; 3]) -> bool {
    planes_cross(a, plane(&a), b, plane(&b))
}

/// [`triangles_cross`] with the triangles' unit normals known ([`plane`]).
fn planes_cross(a: [DVec3; 3], na: Option<DVec3>, b: [DVec3; 3], nb: Option<DVec3>) -> bool {
    let scale2 = a[1..]
        .iter()
        .chain(&b)
        .fold(0.0f64, |m, p| m.max(p.distance_squared(a[0])));
    if scale2 == 0.0 {
        return false;
    }
    let tol = TOL * scale2.sqrt();
    let (Some(na), Some(nb)) = (na, nb) else {
        return false;
    };
    // Signed distances of each triangle's vertices to the other's plane, tiny ones zeroed.
    let side = |t: &[DVec3; 3], n: DVec3, o: DVec3| {
        t.map(|p| {
            let d = n.dot(p - o);
            if d.abs() <= tol { 0.0 } else { d }
        })
    };
    let one_side = |d: [f64; 3]| d.iter().all(|&x| x >= 0.0) || d.iter().all(|&x| x <= 0.0);
    let da = side(&a, nb, b[0]);
    if one_side(da) {
        // Apart, touching at a vertex or edge, or coplanar.
        return false;
    }
    let db = side(&b, na, a[0]);
    if one_side(db) {
        return false;
    }
    let dir = na.cross(nb);
    if dir.length() <= TOL {
        return false;
    }
    let (ia, ib) = (segment(&a, da, dir), segment(&b, db, dir));
    ia.0.max(ib.0) < ia.1.min(ib.1) - tol
}

/// The interval, along `dir`, of the segment in which triangle `t` (signed distances `d` to
/// the other plane, both signs present) cuts that plane.
fn segment(t: &[DVec3; 3], d: [f64; 3], dir: DVec3) -> (f64, f64) {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    let mut add = |p: DVec3| {
        let s = p.dot(dir);
        lo = lo.min(s);
        hi = hi.max(s);
    };
    for i in 0..3 {
        let j = (i + 1) % 3;
        if d[i] == 0.0 {
            add(t[i]);
        }
        if d[i] * d[j] < 0.0 {
            add(t[i] + (t[j] - t[i]) * (d[i] / (d[i] - d[j])));
        }
    }
    (lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;

    #[test]
    fn two_triangles_through_each_other_cross_and_touching_ones_do_not() {
        let a = [DVec3::ZERO, DVec3::X * 2.0, DVec3::Y * 2.0];
        // Pierces a's interior.
        let b = [
            DVec3::new(0.5, 0.5, -1.0),
            DVec3::new(0.5, 0.5, 1.0),
            DVec3::new(3.0, 3.0, 0.5),
        ];
        assert!(triangles_cross(a, b));
        assert!(triangles_cross(b, a));
        // Stands on a's edge: touches, does not cross.
        let c = [
            DVec3::X,
            DVec3::new(1.0, 0.0, 1.0),
            DVec3::new(1.0, -1.0, 0.0),
        ];
        assert!(!triangles_cross(a, c));
        // Coplanar and overlapping: not counted.
        let d = [
            DVec3::new(0.5, 0.5, 0.0),
            DVec3::new(3.0, 0.5, 0.0),
            DVec3::new(0.5, 3.0, 0.0),
        ];
        assert!(!triangles_cross(a, d));
        // Apart.
        let e = b.map(|p| p + DVec3::Z * 5.0);
        assert!(!triangles_cross(a, e));
    }

    /// A closed solid does not cross itself; two boxes pushed into each other do, and the
    /// pairs found are faces of different boxes.
    #[test]
    fn overlapping_boxes_are_found_and_a_single_box_is_clean() {
        let one = primitives::cuboid(DVec3::ZERO, DVec3::ONE);
        assert!(crossings(&one).is_empty());
        assert!(crossings(&primitives::tripod()).is_empty());
        assert!(crossings(&primitives::torus(24, 12, 3.0, 1.0)).is_empty());
        let two = primitives::union_disjoint(&[
            one.clone(),
            primitives::cuboid(DVec3::splat(0.5), DVec3::splat(1.5)),
        ]);
        let pairs = crossings(&two);
        assert!(!pairs.is_empty());
        assert!(pairs.iter().all(|&(f, g)| f < 6 && g >= 6), "{pairs:?}");
        // The pairs of a few faces are the whole search's pairs that hold them.
        for faces in [vec![0u32, 3], vec![7, 9, 11], (0..12).collect()] {
            let mut want: Vec<(u32, u32)> = Vec::new();
            for &(f, g) in &pairs {
                if faces.contains(&f) {
                    want.push((f, g));
                }
                if faces.contains(&g) {
                    want.push((g, f));
                }
            }
            want.sort_unstable();
            assert_eq!(crossings_of(&two, &faces, None), want, "{faces:?}");
            let among: Vec<u32> = (0..12).collect();
            assert_eq!(crossings_of(&two, &faces, Some(&among)), want, "{faces:?}");
            let none: Vec<(u32, u32)> = want.iter().filter(|p| p.1 < 6).copied().collect();
            let first: Vec<u32> = (0..6).collect();
            assert_eq!(crossings_of(&two, &faces, Some(&first)), none, "{faces:?}");
        }
        assert!(crossings_of(&one, &[0, 1, 2, 3, 4, 5], None).is_empty());
    }
}
