//! How [`Topology::build`] finds and checks the topology of a mesh: indices in range, finite
//! coordinates, loops of at least three distinct vertices, no vertex twice in a face, no edge
//! used by more than two faces, consistent orientation; twins paired through the per-vertex
//! lists of outgoing half-edges, in parallel by vertex when the faces allow it.

use super::outgoing::{Outgoing, needs_full_check};
use super::*;

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
}

/// One outgoing half-edge per vertex, or [`NONE`] for an unused one: on a boundary the first
/// without a twin, so that walking the ring with `ring_next` from it visits the whole fan;
/// otherwise the first (the lists are in corner order).
pub(super) fn ring_starts(twin: &[u32], outgoing: &Outgoing, nv: usize) -> Vec<u32> {
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
pub(super) fn serial_twins(
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
pub(super) fn uniform_layout(mesh: &PolyMesh) -> Option<usize> {
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
