//! The combination rule's last resort (docs/algorithms/cylindrical.md, "Untangling"): new
//! faces that are still flipped after the fold guard ([`super::unfold`]) get their points
//! smoothed until they face the right way.
//!
//! Where the input was smoothed before the rounding (Catmull–Clark then combination), some
//! faces are slivers — four nearly collinear points — whose Newell normals are noise. Their
//! Doo–Sabin points are no better than their cut points: the EDGE-face between two such
//! faces can cross itself by a few 10⁻⁵ of the solid, and the guard has nothing left to
//! move. Mesh untangling (as in CGAL's and Mesquite's optimisers) moves the vertices of such
//! faces, not the connectivity: each point of a flipped new face goes the shortest of ⅛, ¼, ½
//! or all of the way to the mean of its four neighbours in the child (a dual-quad vertex has
//! four: `next c`, `prev c`, `next(twin c)`, `twin(prev c)`) that unflips its four faces, all
//! points judged against the same state, and the faces around the moved points are checked
//! again; every 16 rounds the smoothed region grows by one ring. The result is kept only when
//! no face is left flipped and no point moved more than 1 % of the bounding-box diagonal
//! (the largest move is reported); the counts never change, and where nothing is flipped —
//! every solid of the paper — it does not run.

use crate::mesh::PolyMesh;
use crate::topology::Topology;
use glam::DVec3;

/// Rounds of smoothing before the step gives up (the faces still flipped are reported).
const ROUNDS: usize = 64;

/// No point moves farther than this × the bounding-box diagonal: untangling mends folds at
/// the scale of noise, it does not reshape.
const MOST_MOVE: f64 = 1e-2;

/// What [`untangle`] did.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Untangled {
    /// Points moved (corners of the parent).
    pub points: usize,
    /// The largest distance a point moved.
    pub largest_move: f64,
}

/// The new faces of the dual-quad split as corner lists (the split's own order), each with
/// the parent element's normal the step's check uses.
struct NewFaces<'a> {
    mesh: &'a PolyMesh,
    topo: &'a Topology,
    normals: &'a [DVec3],
    vsum: Vec<DVec3>,
}

/// Twice the Newell normal of the polygon through `at(c)` for the corners `cs`.
fn newell_by(cs: &[u32], at: impl Fn(u32) -> DVec3) -> DVec3 {
    let o = at(cs[0]);
    let mut acc = DVec3::ZERO;
    for w in cs[1..].windows(2) {
        acc += (at(w[0]) - o).cross(at(w[1]) - o);
    }
    acc
}

impl NewFaces<'_> {
    fn newell(pts: &[DVec3], cs: &[u32]) -> DVec3 {
        newell_by(cs, |k| pts[k as usize])
    }

    /// Whether the FACE-face of face `f` is flipped.
    fn face_flipped(&self, pts: &[DVec3], f: usize) -> bool {
        let n: DVec3 = self
            .mesh
            .face_loops(f)
            .map(|l| {
                let cs: Vec<u32> = self.mesh.loop_corners(l).map(|c| c as u32).collect();
                Self::newell(pts, &cs)
            })
            .sum();
        n.dot(self.normals[f]) < 0.0
    }

    fn edge_corners(&self, e: usize) -> [u32; 4] {
        let t = self.topo;
        let c = t.edge_corner[e];
        let tw = t.twin[c as usize];
        [t.next[c as usize], c, t.next[tw as usize], tw]
    }

    fn edge_flipped(&self, pts: &[DVec3], e: usize) -> bool {
        let t = self.topo;
        let c = t.edge_corner[e] as usize;
        let np = self.normals[t.corner_face[c] as usize]
            + self.normals[t.corner_face[t.twin[c] as usize] as usize];
        Self::newell(pts, &self.edge_corners(e)).dot(np) < 0.0
    }

    fn vertex_corners(&self, v: usize) -> Vec<u32> {
        let t = self.topo;
        let start = t.vert_corner[v];
        std::iter::successors(Some(start), |&c| {
            let n = t.ring_next(c);
            (n != start).then_some(n)
        })
        .collect()
    }

    fn vertex_flipped(&self, pts: &[DVec3], v: usize) -> bool {
        Self::newell(pts, &self.vertex_corners(v)).dot(self.vsum[v]) < 0.0
    }

    /// How many of the four new faces at corner `c` are flipped with `c`'s point at `q`.
    fn flipped_around(&self, pts: &[DVec3], c: usize, q: DVec3) -> usize {
        let t = self.topo;
        let at = |k: u32| if k as usize == c { q } else { pts[k as usize] };
        let newell = |cs: &[u32]| newell_by(cs, at);
        let f = t.corner_face[c] as usize;
        let mut n = 0;
        if self.normals[f] != DVec3::ZERO {
            let nf: DVec3 = self
                .mesh
                .face_loops(f)
                .map(|l| {
                    let cs: Vec<u32> = self.mesh.loop_corners(l).map(|k| k as u32).collect();
                    newell(&cs)
                })
                .sum();
            n += usize::from(nf.dot(self.normals[f]) < 0.0);
        }
        for e in [t.corner_edge[c], t.corner_edge[t.prev[c] as usize]] {
            let e = e as usize;
            let k = t.edge_corner[e] as usize;
            let np = self.normals[t.corner_face[k] as usize]
                + self.normals[t.corner_face[t.twin[k] as usize] as usize];
            n += usize::from(newell(&self.edge_corners(e)).dot(np) < 0.0);
        }
        let v = self.mesh.corner_verts[c] as usize;
        n += usize::from(newell(&self.vertex_corners(v)).dot(self.vsum[v]) < 0.0);
        n
    }

    /// The corners of every flipped new face that has one of `members` among its corners.
    fn flipped_near(&self, pts: &[DVec3], members: &[u32]) -> Vec<u32> {
        let t = self.topo;
        let (mut fs, mut es, mut vs) = (Vec::new(), Vec::new(), Vec::new());
        for &c in members {
            let c = c as usize;
            fs.push(t.corner_face[c]);
            es.push(t.corner_edge[c]);
            es.push(t.corner_edge[t.prev[c] as usize]);
            vs.push(self.mesh.corner_verts[c]);
        }
        for l in [&mut fs, &mut es, &mut vs] {
            l.sort_unstable();
            l.dedup();
        }
        let mut out = Vec::new();
        for f in fs {
            let f = f as usize;
            if self.normals[f] != DVec3::ZERO && self.face_flipped(pts, f) {
                out.extend(self.mesh.face_corners(f).map(|c| c as u32));
            }
        }
        for e in es {
            if self.edge_flipped(pts, e as usize) {
                out.extend(self.edge_corners(e as usize));
            }
        }
        for v in vs {
            if self.vertex_flipped(pts, v as usize) {
                out.extend(self.vertex_corners(v as usize));
            }
        }
        out
    }
}

/// The fractions of the way to the neighbours' mean a point tries, shortest first.
const STEPS: [f64; 4] = [0.125, 0.25, 0.5, 1.0];

/// The four neighbours of corner `c`'s point in the child.
fn neighbours(t: &Topology, c: u32) -> [u32; 4] {
    let p = t.prev[c as usize];
    [
        t.next[c as usize],
        p,
        t.next[t.twin[c as usize] as usize],
        t.twin[p as usize],
    ]
}

/// Smooths the points (indexed by corner of `mesh`) of the new faces that are flipped against
/// their parent element's normal (`normals`: unit face normals of `mesh`); `flipped` are the
/// corners of the faces the step's check found flipped.
pub(crate) fn untangle(
    mesh: &PolyMesh,
    topo: &Topology,
    normals: &[DVec3],
    pts: &mut [DVec3],
    mut flipped: Vec<u32>,
) -> Untangled {
    let mut vsum = vec![DVec3::ZERO; mesh.num_vertices()];
    for c in 0..mesh.num_corners() {
        vsum[mesh.corner_verts[c] as usize] += normals[topo.corner_face[c] as usize];
    }
    let faces = NewFaces {
        mesh,
        topo,
        normals,
        vsum,
    };
    let mut done = Untangled::default();
    if flipped.is_empty() {
        return done;
    }
    let original = pts.to_vec();
    let nc = mesh.num_corners();
    let mut moved = vec![false; nc];
    let mut set = vec![false; nc];
    for round in 0..ROUNDS {
        if flipped.is_empty() {
            break;
        }
        // The points to smooth: those of the flipped faces, one ring wider every few rounds.
        set.fill(false);
        let mut members: Vec<u32> = Vec::new();
        for &c in &flipped {
            if !set[c as usize] {
                set[c as usize] = true;
                members.push(c);
            }
        }
        for _ in 0..round / 16 {
            for i in 0..members.len() {
                for k in neighbours(topo, members[i]) {
                    if !set[k as usize] {
                        set[k as usize] = true;
                        members.push(k);
                    }
                }
            }
        }
        // Each point goes the shortest of ⅛, ¼, ½ or all of the way to the mean of its
        // neighbours that leaves none of its four faces flipped (or the least flipped),
        // every point judged against the same state so that the order does not matter.
        let new: Vec<DVec3> = members
            .iter()
            .map(|&c| {
                let c = c as usize;
                let p = pts[c];
                let target = 0.25
                    * neighbours(topo, c as u32)
                        .iter()
                        .map(|&k| pts[k as usize])
                        .sum::<DVec3>();
                let mut best = (faces.flipped_around(pts, c, p), p);
                for t in STEPS {
                    let q = p + t * (target - p);
                    let n = faces.flipped_around(pts, c, q);
                    if n < best.0 {
                        best = (n, q);
                    }
                    if n == 0 {
                        break;
                    }
                }
                if best.1 == p {
                    best.1 = target;
                }
                best.1
            })
            .collect();
        for (&c, p) in members.iter().zip(new) {
            pts[c as usize] = p;
            moved[c as usize] = true;
        }
        flipped = faces.flipped_near(pts, &members);
    }
    // Accepted only when it cleared every face and no point moved farther than MOST_MOVE of
    // the diagonal; otherwise the points stay as the guard left them.
    let mut ok = flipped.is_empty();
    let diagonal = mesh.bbox_diagonal();
    for c in 0..nc {
        if moved[c] {
            let d = (pts[c] - original[c]).length();
            ok &= d <= MOST_MOVE * diagonal;
            done.points += 1;
            done.largest_move = done.largest_move.max(d);
        }
    }
    if !ok {
        pts.copy_from_slice(&original);
        return Untangled::default();
    }
    done
}
