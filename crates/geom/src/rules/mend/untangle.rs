//! The combination rule's last resort, and the minimum type's and the chamfers' when clamped
//! (docs/algorithms/cylindrical.md, "Untangling", "Mending"): new
//! faces that are still flipped after the fold guard ([`super::fold_guard`]) get their points
//! smoothed until they face the right way (a face whose outline crosses itself counts as
//! flipped here, as in the fold guard).
//!
//! Where the input was smoothed before the rounding (Catmull–Clark then combination), some
//! faces are slivers — four nearly collinear points — whose Newell normals are noise. Their
//! Doo–Sabin points are no better than their cut points: the EDGE-face between two such
//! faces can cross itself by a few 10⁻⁵ of the solid, and the guard has nothing left to
//! move. Mesh untangling (as in CGAL's and Mesquite's optimisers) moves the vertices of such
//! faces, not the connectivity: each point of a flipped new face goes the shortest of ⅛, ¼, ½
//! or all of the way to the mean of its four neighbours in the child (a dual-quad vertex has
//! four: `next c`, `prev c`, `next(twin c)`, `twin(prev c)`) — first no farther in one round
//! than its nearest neighbour (the mean of a long strip's points lies far along it), and then,
//! where that fails, the whole way as before — that unflips its four faces (where none does,
//! all the way; under the local steps only if one of its faces is flipped), all
//! points judged against the same state, and the faces around the moved points are checked
//! again; every 16 rounds the smoothed region grows by one ring. The result is kept only when
//! no face is left flipped and no point moved more than 1 % of the bounding-box diagonal
//! (the largest move is reported); the counts never change, and where nothing is flipped —
//! every solid of the paper — it does not run.

use super::MendOptions;
use super::fold_guard::newell_at;
use crate::geometry::points_cross_themselves;
use crate::mesh::PolyMesh;
use crate::topology::Topology;
use glam::DVec3;

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

impl NewFaces<'_> {
    /// Whether the FACE-face of face `f` is flipped, the points read through `at`.
    fn face_flipped(&self, at: impl Fn(u32) -> DVec3 + Copy, f: usize) -> bool {
        let n: DVec3 = self
            .mesh
            .face_loops(f)
            .map(|l| newell_at(self.mesh.loop_corners(l).map(|c| c as u32), at))
            .sum();
        n.dot(self.normals[f]) < 0.0
            || (self.mesh.face_loops(f).len() == 1 && {
                let outline: Vec<DVec3> = self.mesh.face_corners(f).map(|c| at(c as u32)).collect();
                points_cross_themselves(&outline, n)
            })
    }

    fn edge_corners(&self, e: usize) -> [u32; 4] {
        let t = self.topo;
        let c = t.edge_corner[e];
        let tw = t.twin[c as usize];
        [t.next(c as usize), c, t.next(tw as usize), tw]
    }

    fn edge_flipped(&self, at: impl Fn(u32) -> DVec3, e: usize) -> bool {
        let t = self.topo;
        let [a, b] = t.edge_faces(e);
        let np = self.normals[a as usize] + self.normals[b as usize];
        let q = self.edge_corners(e).map(&at);
        let n = newell_at(0..4, |i| q[i as usize]);
        n.dot(np) < 0.0 || points_cross_themselves(&q, n)
    }

    fn vertex_corners(&self, v: usize) -> impl Iterator<Item = u32> + '_ {
        self.topo.corners_around(v)
    }

    fn vertex_flipped(&self, at: impl Fn(u32) -> DVec3, v: usize) -> bool {
        let ring: Vec<DVec3> = self.vertex_corners(v).map(&at).collect();
        let n = newell_at(0..ring.len() as u32, |i| ring[i as usize]);
        n.dot(self.vsum[v]) < 0.0 || points_cross_themselves(&ring, n)
    }

    /// How many of the four new faces at corner `c` are flipped with `c`'s point at `q`.
    fn flipped_around(&self, pts: &[DVec3], c: usize, q: DVec3) -> usize {
        let t = self.topo;
        let at = |k: u32| if k as usize == c { q } else { pts[k as usize] };
        let f = t.corner_face(c) as usize;
        let face = self.normals[f] != DVec3::ZERO && self.face_flipped(at, f);
        let edges = [t.corner_edge[c], t.corner_edge[t.prev(c) as usize]]
            .into_iter()
            .filter(|&e| self.edge_flipped(at, e as usize))
            .count();
        let vertex = self.vertex_flipped(at, self.mesh.corner_verts[c] as usize);
        usize::from(face) + edges + usize::from(vertex)
    }

    /// The corners of every flipped new face that has one of `members` among its corners.
    fn flipped_near(&self, pts: &[DVec3], members: &[u32]) -> Vec<u32> {
        let t = self.topo;
        let at = |k: u32| pts[k as usize];
        let (mut fs, mut es, mut vs) = (Vec::new(), Vec::new(), Vec::new());
        for &c in members {
            let c = c as usize;
            fs.push(t.corner_face(c));
            es.push(t.corner_edge[c]);
            es.push(t.corner_edge[t.prev(c) as usize]);
            vs.push(self.mesh.corner_verts[c]);
        }
        for l in [&mut fs, &mut es, &mut vs] {
            l.sort_unstable();
            l.dedup();
        }
        let mut out = Vec::new();
        for f in fs {
            let f = f as usize;
            if self.normals[f] != DVec3::ZERO && self.face_flipped(at, f) {
                out.extend(self.mesh.face_corners(f).map(|c| c as u32));
            }
        }
        for e in es {
            if self.edge_flipped(at, e as usize) {
                out.extend(self.edge_corners(e as usize));
            }
        }
        for v in vs {
            if self.vertex_flipped(at, v as usize) {
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
    let p = t.prev(c as usize);
    [
        t.next(c as usize),
        p,
        t.next(t.twin[c as usize] as usize),
        t.twin[p as usize],
    ]
}

/// Smooths the points (indexed by corner of `mesh`) of the new faces that are flipped against
/// their parent element's normal (`normals`: unit face normals of `mesh`); `flipped` are the
/// corners of the faces the step's check found flipped. Local steps first ([`Smoothing::Local`]);
/// where they leave a face flipped or move a point too far, the plain mean
/// ([`Smoothing::Mean`]), which clears some regions the local steps cannot.
pub(super) fn untangle(
    mesh: &PolyMesh,
    topo: &Topology,
    normals: &[DVec3],
    pts: &mut [DVec3],
    flipped: Vec<u32>,
    options: &MendOptions,
) -> Untangled {
    let faces = NewFaces {
        mesh,
        topo,
        normals,
        vsum: crate::geometry::vertex_normal_sums(mesh, topo, normals),
    };
    if flipped.is_empty() {
        return Untangled::default();
    }
    let original = pts.to_vec();
    for how in [Smoothing::Local, Smoothing::Mean] {
        if let Some(done) = smooth(&faces, pts, &original, flipped.clone(), how, options) {
            return done;
        }
        pts.copy_from_slice(&original);
    }
    Untangled::default()
}

/// How [`smooth`] moves a point.
#[derive(Clone, Copy, PartialEq)]
enum Smoothing {
    /// No farther in one round than its nearest neighbour (on a long strip the neighbours'
    /// mean lies far along it), and a point whose four faces are sound stays.
    Local,
    /// Towards the neighbours' mean, every point of the region.
    Mean,
}

/// One smoothing of `pts` from `original`: `Some` with what moved when it cleared every face
/// and no point moved farther than [`MendOptions::untangle_most_move`] of the diagonal.
fn smooth(
    faces: &NewFaces,
    pts: &mut [DVec3],
    original: &[DVec3],
    mut flipped: Vec<u32>,
    how: Smoothing,
    options: &MendOptions,
) -> Option<Untangled> {
    let (mesh, topo) = (faces.mesh, faces.topo);
    let nc = mesh.num_corners();
    let mut moved = vec![false; nc];
    let mut set = vec![false; nc];
    for round in 0..options.untangle_rounds {
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
        // Each point goes the shortest of ⅛, ¼, ½ or all of the way to its target that
        // leaves none of its four faces flipped (or the least flipped), every point judged
        // against the same state so that the order does not matter.
        let new: Vec<DVec3> = members
            .iter()
            .map(|&c| {
                let c = c as usize;
                let p = pts[c];
                let ns = neighbours(topo, c as u32);
                let mean = 0.25 * ns.iter().map(|&k| pts[k as usize]).sum::<DVec3>();
                let reach = ns
                    .iter()
                    .map(|&k| pts[k as usize].distance(p))
                    .filter(|&d| d > 0.0)
                    .fold(f64::INFINITY, f64::min);
                let d = mean - p;
                let target = if how == Smoothing::Local && d.length() > reach && reach.is_finite() {
                    p + d * (reach / d.length())
                } else {
                    mean
                };
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
                // No step helps: the point goes all the way (smoothing makes room) — under
                // the local steps only if a face of its own is flipped.
                if best.1 == p && (best.0 > 0 || how == Smoothing::Mean) {
                    best.1 = target;
                }
                best.1
            })
            .collect();
        for (&c, p) in members.iter().zip(new) {
            moved[c as usize] |= p != pts[c as usize];
            pts[c as usize] = p;
        }
        flipped = faces.flipped_near(pts, &members);
    }
    // Accepted only when it cleared every face and no point moved farther than `untangle_most_move` of
    // the diagonal; otherwise the points stay as the guard left them.
    let mut ok = flipped.is_empty();
    let diagonal = mesh.bbox_diagonal();
    let mut done = Untangled::default();
    for c in 0..nc {
        if moved[c] {
            let d = (pts[c] - original[c]).length();
            ok &= d <= options.untangle_most_move * diagonal;
            done.points += 1;
            done.largest_move = done.largest_move.max(d);
        }
    }
    ok.then_some(done)
}
