//! The combination rule's fold guard (docs/algorithms/cylindrical.md, "Folds at a vertex
//! blend").
//!
//! The combination type places Doo–Sabin points on the faces of the vertex neighbourhoods and
//! cut points (eq. 4) everywhere else. Where a blend meets a strip with a sharp corner at its
//! end — fillets of different radii meeting at a vertex, a tilted face beside a round — the
//! corner's cut point lies `x/sin φ` along the strip while the blend's point moves towards
//! its centroid, and a new face built from both can come out reversed. No edge of any face
//! is out of order there, so the overlap guard cannot see it.
//!
//! The guard looks at every new face before the split, with the same test the step's report
//! uses (Newell normal against the parent element's normal), and for an outline that crosses
//! itself (a bow-tie keeps a normal that agrees with its parent;
//! [`crate::geometry::points_cross_themselves`]). A new face that would be
//! flipped and has cut points in it joins the vertex neighbourhood: the faces that gave it
//! cut points take Doo–Sabin points instead, which the blend uses anyway (with the width
//! offset on a face with a reflex corner where eq. (1) would leave it and the offset's points
//! stay near it, [`crate::rules::concave`]), and the check
//! repeats until no such face is left (each face moves at most once, so it ends). The moved
//! faces stay in the neighbourhood for the rest of the run ([`crate::rules::CombinationState`]), as
//! the paper's own marking would keep them. Where nothing folds — every solid the paper
//! shows — nothing changes.
//!
//! Where a new face still folds after the moves, [`reoffset`] tries the blend's own faces
//! around it with the width offset and with their points drawn towards their corners, keeping
//! a placement where fewer new faces fold. [`fold_guard`] runs both, on one set of checks.
//!
//! A VERTEX-face of five or more corners must also be star-shaped about its vertex centroid
//! (cylindrical.md, "Fold guard"): acute corners make it a spiked star that is not
//! flipped but whose Doo–Sabin points, at the next step, fold the edge faces beside it.

use crate::geometry::points_cross_themselves;
use crate::mesh::PolyMesh;
use crate::topology::Topology;
use glam::DVec3;

/// Newell normal of the polygon through `pts[c]` for the corners `cs`.
fn newell(pts: &[DVec3], cs: impl Iterator<Item = u32>) -> DVec3 {
    newell_at(cs, |c| pts[c as usize])
}

/// Newell normal of the polygon through `at(c)` for the corners `cs` (the untangling pass
/// tries a point at several places without writing it).
pub(super) fn newell_at(cs: impl Iterator<Item = u32>, at: impl Fn(u32) -> DVec3) -> DVec3 {
    let mut it = cs.map(at);
    let Some(o) = it.next() else {
        return DVec3::ZERO;
    };
    let mut acc = DVec3::ZERO;
    let mut prev = DVec3::ZERO;
    for p in it {
        let cur = p - o;
        acc += prev.cross(cur);
        prev = cur;
    }
    0.5 * acc
}

/// Whether the polygon through `pts[c]` for the corners `cs` (Newell normal `n`) is
/// star-shaped about its vertex centroid: no fan triangle from the centroid turns against `n`.
fn star_shaped(ring: &[DVec3], n: DVec3) -> bool {
    if ring.len() < 5 {
        return true;
    }
    let o = ring.iter().sum::<DVec3>() / ring.len() as f64;
    let tol = 1e-9 * n.length_squared();
    (0..ring.len()).all(|i| {
        let b = ring[(i + 1) % ring.len()];
        (ring[i] - o).cross(b - o).dot(n) >= -tol
    })
}

/// The new faces' checks, on the points `pts` (indexed by corner) of one level.
struct Elements<'a> {
    mesh: &'a PolyMesh,
    topo: &'a Topology,
    normals: &'a [DVec3],
    vsum: Vec<DVec3>,
}

impl<'a> Elements<'a> {
    fn new(mesh: &'a PolyMesh, topo: &'a Topology, normals: &'a [DVec3]) -> Elements<'a> {
        Elements {
            mesh,
            topo,
            normals,
            vsum: crate::geometry::vertex_normal_sums(mesh, topo, normals),
        }
    }

    /// The faces that give a point to a folding new face, and how many new faces fold: one
    /// pass over every FACE-, EDGE- and VERTEX-face, each kind on every core.
    fn folded(&self, pts: &[DVec3]) -> (Vec<bool>, usize) {
        use rayon::prelude::*;
        const PAR_MIN: usize = 4096;
        let (m, topo) = (self.mesh, self.topo);
        let mut near: Vec<bool> = (0..m.num_faces())
            .into_par_iter()
            .with_min_len(PAR_MIN)
            .map(|f| self.face_folds(f, pts))
            .collect();
        let mut count = near.iter().filter(|&&n| n).count();
        let edges: Vec<u32> = topo
            .edge_corner
            .par_iter()
            .with_min_len(PAR_MIN)
            .copied()
            .filter(|&c| self.edge_folds(c, pts))
            .collect();
        for c in edges {
            count += 1;
            near[topo.corner_face(c as usize) as usize] = true;
            near[topo.corner_face(topo.twin[c as usize] as usize) as usize] = true;
        }
        let vertices: Vec<usize> = (0..m.num_vertices())
            .into_par_iter()
            .with_min_len(PAR_MIN)
            .filter(|&v| self.vertex_folds(v, pts))
            .collect();
        for v in vertices {
            count += 1;
            for c in self.ring(v) {
                near[topo.corner_face(c as usize) as usize] = true;
            }
        }
        (near, count)
    }

    /// Whether face `f`'s FACE-face folds: its Newell normal against the face's, or (one
    /// loop) an outline that crosses itself. A face of no area has nothing to fold.
    fn face_folds(&self, f: usize, pts: &[DVec3]) -> bool {
        let m = self.mesh;
        if self.normals[f] == DVec3::ZERO {
            return false;
        }
        let n = m
            .face_loops(f)
            .map(|l| newell(pts, m.loop_corners(l).map(|c| c as u32)))
            .sum::<DVec3>();
        n.dot(self.normals[f]) < 0.0
            || (m.face_loops(f).len() == 1 && points_cross_themselves(&pts[m.face_corners(f)], n))
    }

    /// Whether the EDGE-face of the edge whose first half-edge is `c` folds:
    /// (next c, c, next t, t).
    fn edge_folds(&self, c: u32, pts: &[DVec3]) -> bool {
        let topo = self.topo;
        let t = topo.twin[c as usize];
        let (fa, fb) = (topo.corner_face(c as usize), topo.corner_face(t as usize));
        let q = [topo.next(c as usize), c, topo.next(t as usize), t];
        let n = newell(pts, q.iter().copied());
        n.dot(self.normals[fa as usize] + self.normals[fb as usize]) < 0.0
            || points_cross_themselves(&q.map(|c| pts[c as usize]), n)
    }

    /// The corners around vertex `v` in ring order (none for an unused vertex).
    fn ring(&self, v: usize) -> impl Iterator<Item = u32> + Clone + '_ {
        self.topo.corners_around(v)
    }

    /// Whether vertex `v`'s VERTEX-face folds: reversed, not star-shaped about its centroid
    /// (five corners or more), or crossing itself.
    fn vertex_folds(&self, v: usize, pts: &[DVec3]) -> bool {
        let at: Vec<DVec3> = self.ring(v).map(|c| pts[c as usize]).collect();
        if at.is_empty() {
            return false;
        }
        let n = newell_at(0..at.len() as u32, |i| at[i as usize]);
        n.dot(self.vsum[v]) < 0.0 || !star_shaped(&at, n) || points_cross_themselves(&at, n)
    }

    /// How many of the new faces that take a point of face `f` fold: its FACE-face, the
    /// EDGE-faces of its edges and the VERTEX-faces of its corners.
    fn folds_around(&self, f: usize, pts: &[DVec3]) -> usize {
        let m = self.mesh;
        let mut n = usize::from(self.face_folds(f, pts));
        for c in m.face_corners(f) {
            let e = self.topo.corner_edge[c] as usize;
            n += usize::from(self.edge_folds(self.topo.edge_corner[e], pts));
            n += usize::from(self.vertex_folds(m.corner_verts[c] as usize, pts));
        }
        n
    }
}

/// The combination rule's fold guard on the points `pts` (indexed by corner) of a step of
/// `mesh` (unit face normals `normals`, the run's vertex-neighbourhood `flags`, empty: none):
/// [`unfold`], then [`reoffset`], both judged by one set of the new faces' checks. Returns the
/// faces moved into the blend, ascending, and how many blend faces were re-placed.
pub(super) fn fold_guard(
    mesh: &PolyMesh,
    topo: &Topology,
    normals: &[DVec3],
    flags: &[bool],
    options: &crate::rules::RoundingOptions,
    pts: &mut [DVec3],
) -> (Vec<u32>, usize) {
    let el = Elements::new(mesh, topo, normals);
    let moved = unfold(&el, flags, options, pts);
    let replaced = reoffset(&el, flags, &moved, options, pts);
    (moved, replaced)
}

/// Moves to Doo–Sabin the faces of `mesh` whose cut points would fold a new face, rewriting
/// their points in `pts` (indexed by corner). `flags` are the run's vertex-neighbourhood
/// flags (empty: none); `normals` the unit face normals. A moved face with a reflex corner
/// where eq. (1) would leave it takes the width offset instead
/// ([`crate::rules::chamfer::offset_doo_sabin_points`]); so, afterwards, does a face already in the
/// blend where that leaves fewer of the new faces around it folded ([`reoffset`]). Returns
/// the faces moved, ascending.
fn unfold(
    el: &Elements,
    flags: &[bool],
    options: &crate::rules::RoundingOptions,
    pts: &mut [DVec3],
) -> Vec<u32> {
    let (mesh, topo, normals) = (el.mesh, el.topo, el.normals);
    let nf = mesh.num_faces();
    let mut blend: Vec<bool> = (0..nf)
        .map(|f| flags.get(f).copied().unwrap_or(false))
        .collect();
    let mut moved = Vec::new();
    loop {
        let mut to_move = vec![false; nf];
        let mut any = false;
        // A face that can still move (not in the blend, no hole: Doo–Sabin needs one loop).
        let movable = |f: usize, blend: &[bool]| !blend[f] && mesh.face_loops(f).len() == 1;
        let mark = |f: usize, to_move: &mut [bool], any: &mut bool| {
            if movable(f, &blend) && !to_move[f] {
                to_move[f] = true;
                *any = true;
            }
        };
        for (f, &b) in blend.iter().enumerate() {
            if !b && el.face_folds(f, pts) {
                mark(f, &mut to_move, &mut any);
            }
        }
        for &c in &topo.edge_corner {
            let t = topo.twin[c as usize];
            let (fa, fb) = (
                topo.corner_face(c as usize) as usize,
                topo.corner_face(t as usize) as usize,
            );
            if !(blend[fa] && blend[fb]) && el.edge_folds(c, pts) {
                mark(fa, &mut to_move, &mut any);
                mark(fb, &mut to_move, &mut any);
            }
        }
        for v in 0..mesh.num_vertices() {
            let ring = el.ring(v);
            if ring
                .clone()
                .all(|c| blend[topo.corner_face(c as usize) as usize])
            {
                continue;
            }
            if el.vertex_folds(v, pts) {
                for c in ring {
                    mark(
                        topo.corner_face(c as usize) as usize,
                        &mut to_move,
                        &mut any,
                    );
                }
            }
        }
        if !any {
            break;
        }
        for f in 0..nf {
            if to_move[f] {
                crate::rules::chamfer::offset_doo_sabin_points(mesh, normals[f], f, options, pts);
                blend[f] = true;
                moved.push(f as u32);
            }
        }
    }
    moved.sort_unstable();
    moved
}

/// The fold guard's second pass (cylindrical.md, "Fold guard"),
/// run by every combination step after [`unfold`] ([`fold_guard`]; one pass over the new
/// faces where the guard's tests find no fold left, as on every bundled solid's default
/// rounds). The blend's
/// faces keep eq. (1), which on a face with a reflex corner can carry that corner's point out
/// of the face, and on a needle carries the points of its short side's corners far along it
/// — either can fold a new face beside it. Each blend face (`flags`) that gives a point to a
/// folding new face and has not been re-placed yet (nor moved by [`unfold`] this step) is
/// tried with the width offset ([`crate::rules::chamfer::offset_doo_sabin_points`]) and with its
/// points drawn to `MendOptions::drawn` of the way from their corners, every face against the same
/// points (the numbering does not matter), and keeps the placement after which fewest of the
/// new faces around it fold — its FACE-face, the EDGE-faces of its edges, the VERTEX-faces of
/// its corners, the only new faces its points are in — if that is fewer than before. A round
/// whose changes together fold more new faces than before is undone. `pts` are indexed by
/// corner (the child's vertices of a dual quad split are the parent's corners). Returns the
/// faces re-placed.
fn reoffset(
    el: &Elements,
    flags: &[bool],
    moved: &[u32],
    options: &crate::rules::RoundingOptions,
    pts: &mut [DVec3],
) -> usize {
    let mesh = el.mesh;
    let nf = mesh.num_faces();
    let mut blend: Vec<bool> = (0..nf)
        .map(|f| flags.get(f).copied().unwrap_or(false))
        .collect();
    for &f in moved {
        blend[f as usize] = true;
    }
    let mut replaced = 0;
    let mut done = vec![false; nf];
    for &f in moved {
        done[f as usize] = true;
    }
    let (mut near, mut before) = el.folded(pts);
    for _ in 0..options.mend.reoffset_rounds {
        let candidates: Vec<usize> = (0..nf)
            .filter(|&f| near[f] && blend[f] && !done[f] && mesh.face_loops(f).len() == 1)
            .collect();
        if candidates.is_empty() {
            return replaced;
        }
        let mut trial = pts.to_vec();
        let mut kept = Vec::new();
        for &f in &candidates {
            let corners = mesh.face_corners(f);
            let old: Vec<DVec3> = trial[corners.clone()].to_vec();
            let was = el.folds_around(f, &trial);
            crate::rules::chamfer::offset_doo_sabin_points(
                mesh,
                el.normals[f],
                f,
                options,
                &mut trial,
            );
            let offset: Vec<DVec3> = trial[corners.clone()].to_vec();
            let mut tries = vec![offset];
            for k in options.mend.drawn {
                tries.push(
                    corners
                        .clone()
                        .zip(&old)
                        .map(|(c, &p)| {
                            let v = mesh.positions[mesh.corner_verts[c] as usize];
                            v + k * (p - v)
                        })
                        .collect(),
                );
            }
            // The placement that leaves fewest folds round the face, the first of equals.
            let mut best: Option<(usize, Vec<DVec3>)> = None;
            for new in tries {
                if new == old {
                    continue;
                }
                trial[corners.clone()].copy_from_slice(&new);
                let after = el.folds_around(f, &trial);
                if after < best.as_ref().map_or(was, |b| b.0) {
                    best = Some((after, new));
                }
            }
            trial[corners.clone()].copy_from_slice(&old);
            if let Some((_, new)) = best {
                done[f] = true;
                kept.push((f, new));
            }
        }
        if kept.is_empty() {
            return replaced;
        }
        for (f, new) in &kept {
            pts[mesh.face_corners(*f)].copy_from_slice(new);
        }
        let (now, count) = el.folded(pts);
        if count >= before {
            // `trial` holds every point as the round found it.
            for (f, _) in &kept {
                let corners = mesh.face_corners(*f);
                pts[corners.clone()].copy_from_slice(&trial[corners]);
            }
            return replaced;
        }
        (near, before) = (now, count);
        replaced += kept.len();
    }
    replaced
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::quad_crosses_itself;

    /// The hexagon Catmull–Clark's tripod gave the first combination step (level 2, around
    /// the bottom's vertex 44, projected on z = 0): two spikes 0.48 long. It is not flipped
    /// but not star-shaped; a regular hexagon is.
    #[test]
    fn a_spiked_vertex_face_is_not_star_shaped() {
        let spiked: Vec<DVec3> = [
            (1.31921, 1.31921),
            (1.27115, 1.35581),
            (1.14227, 1.79732),
            (1.33541, 1.33541),
            (1.79732, 1.14227),
            (1.35581, 1.27115),
        ]
        .iter()
        .map(|&(x, y)| DVec3::new(x, y, 0.0))
        .collect();
        let cs = 0..6u32;
        let n = newell(&spiked, cs.clone());
        assert!(n.length() > 0.0);
        assert!(!star_shaped(&spiked, n));
        let regular: Vec<DVec3> = (0..6)
            .map(|k| {
                let a = k as f64 * std::f64::consts::PI / 3.0;
                DVec3::new(a.cos(), a.sin(), 0.0)
            })
            .collect();
        let n = newell(&regular, cs.clone());
        assert!(star_shaped(&regular, n));
    }

    /// A bow-tie quad keeps a normal along +z (its larger lobe) but crosses itself; a convex
    /// and a reflex (dart) quad, a needle and a pinched hexagon (two corners at one point:
    /// touching, not crossing) do not; the bow-tie as a hexagon does.
    #[test]
    fn outlines_that_cross_themselves_are_found() {
        let p = |v: &[(f64, f64)]| -> Vec<DVec3> {
            v.iter().map(|&(x, y)| DVec3::new(x, y, 0.0)).collect()
        };
        let check = |pts: &[DVec3]| {
            let n = newell(pts, 0..pts.len() as u32);
            (n.z > 0.0, points_cross_themselves(pts, n))
        };
        let bow_tie = p(&[(0.0, 0.0), (2.0, 0.0), (0.5, 1.0), (1.5, 1.0)]);
        assert_eq!(check(&bow_tie), (true, true));
        assert_eq!(
            check(&p(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)])),
            (true, false)
        );
        assert_eq!(
            check(&p(&[(0.0, 0.0), (2.0, 1.0), (0.0, 2.0), (0.5, 1.0)])),
            (true, false)
        );
        let needle = p(&[(0.0, 0.0), (1.0, 1e-7), (2.0, 0.0), (1.0, 2e-7)]);
        assert!(!check(&needle).1);
        let pinched = p(&[
            (0.6, 0.6),
            (0.2, 2.4),
            (0.8, 2.6),
            (0.6, 0.6),
            (2.6, 0.8),
            (2.4, 0.2),
        ]);
        assert!(!check(&pinched).1);
        // Random warped quads: the two-product test agrees with the four triangles' signs
        // (AB cuts CD, or BC cuts DA) wherever the margin is clear of the tolerance.
        let mut state = 7u64;
        let mut rnd = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let (mut crossing, mut agreed) = (0, 0);
        for _ in 0..2000 {
            let q: [DVec3; 4] = std::array::from_fn(|_| DVec3::new(rnd(), rnd(), 0.2 * rnd()));
            let n = newell(&q, 0..4);
            let o = |a: DVec3, b: DVec3, c: DVec3| n.dot((b - a).cross(c - a));
            let [a, b, c, d] = q;
            let four = (o(a, b, c) * o(a, b, d) < 0.0 && o(c, d, a) * o(c, d, b) < 0.0)
                || (o(b, c, d) * o(b, c, a) < 0.0 && o(d, a, b) * o(d, a, c) < 0.0);
            let least = [o(a, b, c), o(a, b, d), o(a, c, d), o(b, c, d)]
                .iter()
                .fold(f64::INFINITY, |m, x| m.min(x.abs()));
            if least > 1e-6 * n.length() {
                assert_eq!(quad_crosses_itself(q, n), four, "{q:?}");
                agreed += 1;
                crossing += four as usize;
            }
        }
        assert!(agreed > 1500 && crossing > 100, "{agreed} {crossing}");
        // The bow-tie with a corner inserted in each straight side.
        let eight = p(&[
            (0.0, 0.0),
            (1.0, 0.0),
            (2.0, 0.0),
            (0.5, 1.0),
            (1.0, 1.0),
            (1.5, 1.0),
        ]);
        assert_eq!(check(&eight), (true, true));
    }
}
