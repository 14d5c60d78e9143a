//! Derived topology: half-edges with twins, edges, vertex rings.
//!
//! Half-edge `c` is the directed edge from corner `c`'s vertex to the next corner of its
//! loop, so half-edges and corners share one index. [`Topology::build`] is the one place
//! that checks a mesh: indices in range, finite coordinates, loops of at least three
//! distinct vertices, no vertex twice in a face, no edge used by more than two faces,
//! consistent orientation. Open meshes are accepted here (a boundary half-edge has no
//! twin); [`Topology::require_closed`] refuses them for the schemes that need a closed
//! solid, and checks that every vertex ring is a single closed fan.
//!
//! Cost: O(corners · valence); twins are found through a per-vertex list of outgoing
//! half-edges (CSR), not a hash map.

use crate::error::{MeshError, MeshWarning};
use crate::mesh::PolyMesh;
use outgoing::Outgoing;
use rayon::prelude::*;

mod by_vertex;
mod edges;
mod loops;
mod outgoing;

pub(crate) use loops::with_loops;
pub use loops::{CornerLoops, Listed, Loops, QuadLoops, TriLoops};

/// Marks a missing index (no twin, unused vertex).
pub const NONE: u32 = u32::MAX;

/// Half-edge topology of a [`PolyMesh`].
#[derive(Debug, Clone, Default)]
pub struct Topology {
    /// Face, next and previous corner of each corner ([`Topology::corner_face`],
    /// [`Topology::next`], [`Topology::prev`]).
    loops: Loops,
    /// The opposite half-edge, or [`NONE`] on a boundary.
    pub twin: Vec<u32>,
    /// Edge of each half-edge.
    pub corner_edge: Vec<u32>,
    /// One half-edge of each edge: the one with the smaller corner index.
    pub edge_corner: Vec<u32>,
    /// One outgoing half-edge per vertex, or [`NONE`] for an unused vertex.
    pub vert_corner: Vec<u32>,
    /// Problems that do not stop the work.
    pub warnings: Vec<MeshWarning>,
    /// Whether [`Topology::build`] found every vertex ring a single fan (it walks them while
    /// pairing twins), so that [`Topology::require_single_fans`] need not walk them again.
    fans_checked: bool,
    /// Half-edges without a twin: the boundary edges.
    open_edges: usize,
}

/// Number of distinct vertex indices in a loop.
fn distinct_count(verts: &[u32]) -> u32 {
    let mut d = verts.to_vec();
    d.sort_unstable();
    d.dedup();
    d.len() as u32
}

/// The full check of one face's loops: indices in range, at least three distinct
/// vertices per loop, no vertex twice in the face (`stamp` holds the last face that used
/// each vertex).
fn check_face(mesh: &PolyMesh, f: usize, stamp: &mut [u32]) -> Result<(), MeshError> {
    let nv = stamp.len();
    let loops = mesh.face_loops(f);
    for l in loops.clone() {
        let vs = mesh.loop_verts(l);
        let lp = (l - loops.start) as u32;
        if let Some(&v) = vs.iter().find(|&&v| v as usize >= nv) {
            return Err(MeshError::IndexOutOfRange {
                face: f as u32,
                index: v,
                count: nv as u32,
            });
        }
        let distinct = distinct_count(vs);
        if distinct < 3 {
            return Err(MeshError::DegenerateLoop {
                face: f as u32,
                lp,
                distinct,
            });
        }
        for &v in vs {
            if stamp[v as usize] == f as u32 {
                return Err(MeshError::RepeatedVertex {
                    face: f as u32,
                    vertex: v,
                });
            }
            stamp[v as usize] = f as u32;
        }
    }
    Ok(())
}

impl Topology {
    /// Builds and checks the topology of `mesh`.
    pub fn build(mesh: &PolyMesh) -> Result<Topology, MeshError> {
        let nv = mesh.num_vertices();
        let nc = mesh.num_corners();
        let nf = mesh.num_faces();
        if nv >= NONE as usize || nc >= NONE as usize / 2 {
            return Err(MeshError::TooLarge {
                what: "vertex or corner count",
            });
        }
        if nf == 0 {
            return Err(MeshError::NoFaces);
        }
        check_finite(mesh)?;

        // The faces that need the full check (not a plain triangle or quad of distinct
        // in-range vertices) are checked after a parallel look, in order, so the first bad
        // face is named as one pass would name it. A mesh of one-loop faces of three or four
        // corners (then the loops are arithmetic) is told by its offsets alone, and its
        // faces are looked at while their corners are counted.
        let (first_faces, bounds) = crate::parallel::face_chunks(mesh);
        let cv = &mesh.corner_verts;
        let uniform = uniform_layout(mesh);
        let loops = Loops::of(mesh, uniform, &first_faces, &bounds);

        // Outgoing half-edges per vertex (CSR). Every face one loop of k corners, k = 3 or
        // 4: the faces are looked at as their corners are counted; the first that is not
        // plain, if any, gets the full check below, which names it.
        let counted = match uniform {
            Some(4) => Outgoing::of_uniform::<4>(nv, cv, &loops),
            Some(_) => Outgoing::of_uniform::<3>(nv, cv, &loops),
            None => None,
        };
        let outgoing = match counted {
            Some(outgoing) => outgoing,
            None => {
                // Per-vertex stamp of the last face that used it: detects a vertex repeated
                // in a face with more than four corners (smaller ones compare their corners
                // directly).
                let mut stamp = Vec::new();
                for f in general_faces(mesh, &first_faces) {
                    if mesh.face_loops(f as usize).is_empty() {
                        return Err(MeshError::EmptyFace { face: f });
                    }
                    if stamp.is_empty() {
                        stamp = vec![NONE; nv];
                    }
                    check_face(mesh, f as usize, &mut stamp)?;
                }
                drop(stamp);
                Outgoing::new(nv, cv, &loops)
            }
        };

        // Every vertex pairs its outgoing half-edges with their twins, picks its ring start
        // and walks its fan, on every core; when every pair is mutual and unique those are the
        // twins. Otherwise the serial pass below runs and names the first bad edge.
        let (twin, vert_corner, fans_checked, leads) = match by_vertex::twins(cv, &loops, &outgoing)
        {
            Some(found) => (
                found.twin,
                found.ring_start,
                found.single_fans,
                Some(found.leads),
            ),
            None => {
                let twin = serial_twins(cv, &loops, &outgoing, nc)?;
                let starts = ring_starts(&twin, &outgoing, nv);
                (twin, starts, false, None)
            }
        };
        let unused = vert_corner
            .par_iter()
            .with_min_len(1 << 14)
            .filter(|&&c| c == NONE)
            .count() as u32;
        let mut warnings = Vec::new();
        if unused > 0 {
            let first = vert_corner
                .par_iter()
                .position_first(|&c| c == NONE)
                .expect("counted") as u32;
            warnings.push(MeshWarning::UnusedVertices {
                count: unused,
                first,
            });
        }

        let mut topo = Topology::numbered(twin, loops, vert_corner, leads.as_ref());
        topo.warnings = warnings;
        topo.fans_checked = fans_checked;
        Ok(topo)
    }

    /// The half-edge topology from twins, loops and ring starts (found by
    /// [`Topology::build`] or written down by a split): edges numbered in the order of their
    /// smaller half-edge.
    pub(crate) fn from_twins(twin: Vec<u32>, loops: Loops, vert_corner: Vec<u32>) -> Topology {
        Topology::numbered(twin, loops, vert_corner, None)
    }

    /// [`Topology::from_twins`], with the leading half-edges per block of the numbering
    /// and the open ones when the pairing counted them.
    fn numbered(
        twin: Vec<u32>,
        loops: Loops,
        vert_corner: Vec<u32>,
        counted: Option<&edges::Leads>,
    ) -> Topology {
        let numbered = edges::number_edges(&twin, counted);
        Topology {
            loops,
            twin,
            corner_edge: numbered.corner_edge,
            edge_corner: numbered.edge_corner,
            vert_corner,
            warnings: Vec::new(),
            fans_checked: false,
            open_edges: numbered.open,
        }
    }

    /// Whether every half-edge has a twin (no boundary edge), counted while the edges were
    /// numbered.
    pub fn is_closed(&self) -> bool {
        self.open_edges == 0
    }

    /// The face of corner `c`.
    #[inline]
    pub fn corner_face(&self, c: usize) -> u32 {
        self.loops.face(c)
    }

    /// The next corner of corner `c`'s loop.
    #[inline]
    pub fn next(&self, c: usize) -> u32 {
        self.loops.next(c)
    }

    /// The previous corner of corner `c`'s loop.
    #[inline]
    pub fn prev(&self, c: usize) -> u32 {
        self.loops.prev(c)
    }

    /// The loops: faces and neighbours of the corners, stored or arithmetic.
    pub fn loops(&self) -> &Loops {
        &self.loops
    }

    /// The number of corners (half-edges).
    pub fn num_corners(&self) -> usize {
        self.twin.len()
    }

    /// Bytes its arrays hold.
    pub fn heap_bytes(&self) -> u64 {
        let listed = match &self.loops {
            Loops::Listed(l) => l.corner_face.len() + l.next.len() + l.prev.len(),
            Loops::Quads | Loops::Triangles => 0,
        };
        4 * (listed
            + self.twin.len()
            + self.corner_edge.len()
            + self.edge_corner.len()
            + self.vert_corner.len()) as u64
    }

    pub fn num_edges(&self) -> usize {
        self.edge_corner.len()
    }

    /// The next half-edge around the vertex of half-edge `c`, turning so that the faces are
    /// visited in the order of docs/algorithms/biquadratic.md (VERTEX-face order): from `c` (v→x) go to
    /// the half-edge that leaves v along the edge preceding `c` in its loop. [`NONE`] at a
    /// boundary.
    #[inline]
    pub fn ring_next(&self, c: u32) -> u32 {
        self.twin[self.prev(c as usize) as usize]
    }

    /// The corners of vertex `v` in [`Topology::ring_next`] order from `vert_corner[v]`, once
    /// round a closed ring (none for an unused vertex): the dual-quad rules' walk round a
    /// VERTEX-face, without a list.
    pub fn corners_around(&self, v: usize) -> impl Iterator<Item = u32> + Clone + '_ {
        let start = self.vert_corner[v];
        std::iter::successors((start != NONE).then_some(start), move |&c| {
            let n = self.ring_next(c);
            (n != start).then_some(n)
        })
    }

    /// Refuses an open mesh (naming a boundary edge) and a vertex whose faces do not form a
    /// single closed fan.
    pub fn require_closed(&self, mesh: &PolyMesh) -> Result<(), MeshError> {
        for (c, &t) in self.twin.iter().enumerate() {
            if t == NONE {
                return Err(MeshError::BoundaryEdge {
                    a: mesh.corner_verts[c],
                    b: mesh.corner_verts[self.next(c) as usize],
                    face: self.corner_face(c),
                });
            }
        }
        self.require_single_fans(mesh)
    }

    /// Refuses a vertex whose faces do not form a single fan (closed around an interior
    /// vertex, open at a boundary vertex): two cones touching at a tip, two sheets touching
    /// at a corner.
    pub fn require_single_fans(&self, mesh: &PolyMesh) -> Result<(), MeshError> {
        // A fan walk visits distinct corners of its vertex (`ring_next` is one-to-one), so
        // it never counts more than the vertex's valence; the fans' sizes add up to the
        // number of corners exactly when every vertex is a single fan. Only then is the
        // per-vertex count below skipped.
        if self.fans_checked {
            return Ok(());
        }
        let nc = mesh.num_corners();
        let fan = |start: u32, bound: usize| {
            let mut k = 0usize;
            let mut c = start;
            loop {
                k += 1;
                c = self.ring_next(c);
                if c == NONE || c == start || k > bound {
                    return k;
                }
            }
        };
        let total: usize = self
            .vert_corner
            .par_iter()
            .with_min_len(1 << 12)
            .map(|&start| if start == NONE { 0 } else { fan(start, nc) })
            .sum();
        if total == nc {
            return Ok(());
        }
        let mut valence = vec![0u32; mesh.num_vertices()];
        for &v in &mesh.corner_verts {
            valence[v as usize] += 1;
        }
        for (v, &start) in self.vert_corner.iter().enumerate() {
            if start == NONE {
                continue;
            }
            let k = fan(start, valence[v] as usize) as u32;
            if k != valence[v] {
                return Err(MeshError::NonManifoldVertex {
                    vertex: v as u32,
                    fans: valence[v].div_ceil(k.max(1)).max(2),
                });
            }
        }
        Ok(())
    }

    /// The edges around a vertex in ring order from its corner `start` (an interior
    /// vertex's ring may start at any of its corners; `vert_corner[v]` is the usual one,
    /// [`NONE`] gives an empty ring), each as (edge, other vertex), and the corners of the
    /// vertex in the faces between them: the face of corner i lies between edges i and
    /// i + 1. At a boundary vertex the ring from `vert_corner[v]` starts at the boundary
    /// edge with the fan on its left and ends at the other boundary edge (one edge more than
    /// faces), as OpenSubdiv orders it.
    pub fn vertex_ring_from(
        &self,
        mesh: &PolyMesh,
        start: u32,
        edges: &mut Vec<(u32, u32)>,
        corners: &mut Vec<u32>,
    ) {
        edges.clear();
        corners.clear();
        self.walk_ring(mesh, start, |edge, other, corner| {
            edges.push((edge, other));
            corners.extend(corner);
            false
        });
    }

    /// Walks the ring from corner `start` in [`Topology::vertex_ring_from`]'s order, calling
    /// `visit(edge, other vertex, corner)` for each edge (no corner for the closing boundary
    /// edge) until it returns true; returns whether it did. The one walk both the listing and
    /// [`Topology::find_edge`] use.
    fn walk_ring(
        &self,
        mesh: &PolyMesh,
        start: u32,
        mut visit: impl FnMut(u32, u32, Option<u32>) -> bool,
    ) -> bool {
        if start == NONE {
            return false;
        }
        let cv = &mesh.corner_verts;
        let (mut c, mut walked) = (start, 0);
        loop {
            let edge = self.corner_edge[c as usize];
            if visit(edge, cv[self.next(c as usize) as usize], Some(c)) {
                return true;
            }
            walked += 1;
            let n = self.ring_next(c);
            if n == NONE {
                let p = self.prev(c as usize) as usize;
                return visit(self.corner_edge[p], cv[p], None);
            }
            if n == start || walked > self.num_corners() {
                return false;
            }
            c = n;
        }
    }

    /// The edge joining vertices `a` and `b`, if there is one: the first in `a`'s ring
    /// ([`Topology::vertex_ring_from`] from `vert_corner[a]`), walked without a list (edge
    /// marks are handed down level by level through thousands of these).
    pub fn find_edge(&self, mesh: &PolyMesh, a: u32, b: u32) -> Option<u32> {
        if a as usize >= self.vert_corner.len() || b as usize >= self.vert_corner.len() {
            return None;
        }
        let mut found = None;
        self.walk_ring(mesh, self.vert_corner[a as usize], |edge, other, _| {
            found = (other == b).then_some(edge);
            found.is_some()
        });
        found
    }

    /// The two faces of edge `e` of a closed mesh: its first half-edge's, then its twin's.
    pub fn edge_faces(&self, e: usize) -> [u32; 2] {
        let c = self.edge_corner[e] as usize;
        [self.corner_face(c), self.corner_face(self.twin[c] as usize)]
    }

    /// The two vertices of edge `e` as (a, b) in the direction of its first half-edge.
    pub fn edge_verts(&self, mesh: &PolyMesh, e: usize) -> (u32, u32) {
        let c = self.edge_corner[e] as usize;
        (
            mesh.corner_verts[c],
            mesh.corner_verts[self.next(c) as usize],
        )
    }
}

#[cfg(test)]
mod tests;

/// One outgoing half-edge per vertex, or [`NONE`] for an unused one: on a boundary the first
/// without a twin, so that walking the ring with `ring_next` from it visits the whole fan;
/// otherwise the first (the lists are in corner order).
fn ring_starts(twin: &[u32], outgoing: &Outgoing, nv: usize) -> Vec<u32> {
    (0..nv)
        .into_par_iter()
        .with_min_len(1 << 14)
        .map(|v| {
            let mut ring = outgoing.of(v as u32);
            ring.clone()
                .find(|&(d, _)| twin[d as usize] == NONE)
                .or_else(|| ring.next())
                .map_or(NONE, |(d, _)| d)
        })
        .collect()
}

/// One pass in corner order pairs every half-edge with its twin, or names the first edge
/// used three times or run the same way by two faces.
fn serial_twins(
    cv: &[u32],
    loops: &Loops,
    outgoing: &Outgoing,
    nc: usize,
) -> Result<Vec<u32>, MeshError> {
    let mut twin = vec![NONE; nc];
    for c in 0..nc {
        if twin[c] != NONE {
            continue;
        }
        let a = cv[c];
        let b = cv[loops.next(c) as usize];
        let mut found = NONE;
        let mut count = 0;
        for (d, dst) in outgoing.of(b) {
            if dst == a {
                found = d;
                count += 1;
            }
        }
        // A third use of the edge: a second b→a half-edge, or a b→a half-edge that an
        // earlier a→b half-edge already took.
        if count > 1 || (found != NONE && twin[found as usize] != NONE) {
            let mut faces: Vec<u32> = outgoing
                .of(b)
                .filter(|&(_, dst)| dst == a)
                .chain(outgoing.of(a).filter(|&(_, dst)| dst == b))
                .map(|(e, _)| loops.face(e as usize))
                .collect();
            faces.sort_unstable();
            faces.dedup();
            return Err(MeshError::NonManifoldEdge {
                a: a.min(b),
                b: a.max(b),
                faces,
            });
        }
        if found != NONE {
            twin[c] = found;
            twin[found as usize] = c as u32;
        } else {
            // Without a twin, another a→b half-edge means two faces run the edge the
            // same way: inconsistent orientation.
            for (d, dst) in outgoing.of(a) {
                if d as usize != c && dst == b {
                    let (f1, f2) = (loops.face(c), loops.face(d as usize));
                    return Err(MeshError::InconsistentOrientation {
                        a,
                        b,
                        f1: f1.min(f2),
                        f2: f1.max(f2),
                    });
                }
            }
        }
    }
    Ok(twin)
}

/// `Some(k)` when every face of `mesh` is one loop of k = 3 or 4 corners, laid out in order
/// (face f owns loop f, loop l corners k·l … k·l + k − 1): a test of the offsets alone, on
/// every core.
fn uniform_layout(mesh: &PolyMesh) -> Option<usize> {
    let (nf, nc) = (mesh.num_faces(), mesh.num_corners());
    let k = nc / nf.max(1);
    if !(3..=4).contains(&k) || k * nf != nc || mesh.loop_starts.len() != nf + 1 {
        return None;
    }
    // Every element compared, no early exit within a chunk: vector code.
    let arithmetic = |a: &[u32], step: u32| {
        a.par_chunks(1 << 16).enumerate().all(|(i, chunk)| {
            let first = (i << 16) as u32;
            (first..)
                .zip(chunk)
                .fold(true, |ok, (j, &x)| ok & (x == step.wrapping_mul(j)))
        })
    };
    (arithmetic(&mesh.face_starts, 1) && arithmetic(&mesh.loop_starts, k as u32)).then_some(k)
}

/// Whether the corners `vs` of a one-loop face are anything but a plain triangle or quad of
/// distinct vertices below `nv`: such a face gets [`check_face`], which names what is wrong.
/// No branch per compare: vector code over many faces.
#[inline(always)]
fn needs_full_check(vs: &[u32], nv: usize) -> bool {
    match *vs {
        [a, b, c] => (a.max(b).max(c) as usize >= nv) | (a == b) | (a == c) | (b == c),
        [a, b, c, d] => {
            (a.max(b).max(c).max(d) as usize >= nv)
                | (a == b)
                | (a == c)
                | (a == d)
                | (b == c)
                | (b == d)
                | (c == d)
        }
        _ => true,
    }
}

/// Refuses a mesh with a coordinate that is not finite, naming the first such vertex (on
/// every core; the one place both the topology build and a repointed step look).
pub(crate) fn check_finite(mesh: &PolyMesh) -> Result<(), MeshError> {
    // Every coordinate of a block at once (vector code), the blocks on every core; only a
    // mesh that fails is looked through for the first bad vertex.
    let finite = |p: &glam::DVec3| p.x.is_finite() & p.y.is_finite() & p.z.is_finite();
    let sound = mesh
        .positions
        .par_chunks(1 << 14)
        .all(|chunk| chunk.iter().fold(true, |ok, p| ok & finite(p)));
    if sound {
        return Ok(());
    }
    match mesh.positions.iter().position(|p| !finite(p)) {
        Some(i) => {
            let p = mesh.positions[i];
            Err(MeshError::NonFinite {
                vertex: i as u32,
                x: p.x,
                y: p.y,
                z: p.z,
            })
        }
        None => Ok(()),
    }
}

/// The faces that need the full check (not a plain triangle or quad of distinct in-range
/// vertices), in order, found on every core in chunks of faces.
fn general_faces(mesh: &PolyMesh, first_faces: &[usize]) -> Vec<u32> {
    let nv = mesh.num_vertices();
    let chunks: Vec<Vec<u32>> = (0..first_faces.len() - 1)
        .into_par_iter()
        .map(|i| {
            let mut flagged = Vec::new();
            for f in first_faces[i]..first_faces[i + 1] {
                let vs = &mesh.corner_verts[mesh.face_corners(f)];
                if mesh.face_loops(f).len() != 1 || needs_full_check(vs, nv) {
                    flagged.push(f as u32);
                }
            }
            flagged
        })
        .collect();
    chunks.concat()
}
