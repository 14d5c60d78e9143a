//! Normals per face corner for drawing and export: **smooth** shading averages the
//! area-weighted (Newell) normals of the faces around a vertex within each fan between
//! *sharp* edges — crease edges (`crease > 0`), boundary edges, and edges whose faces meet at
//! more than a crease angle — so that creases, chamfers and rounds' borders stay crisp; a
//! mesh without valid topology gets its faces' normals (flat).

use crate::edge_attrs::{EdgeAttrs, EdgeKey};
use crate::geometry::unit_or_zero;
use crate::mesh::PolyMesh;
use crate::topology::{NONE, Topology};
use glam::DVec3;

/// The unit normal of every face corner, smooth within fans between sharp edges
/// (`crease_angle_deg`: faces meeting at more than this keep their edge sharp); `raw` are
/// the faces' Newell normals ([`crate::geometry::face_normals_raw`]), which the caller has
/// for its triangulation too.
pub fn smooth_corner_normals(
    mesh: &PolyMesh,
    raw: &[DVec3],
    attrs: &EdgeAttrs,
    crease_angle_deg: f64,
) -> Vec<DVec3> {
    let Ok(topo) = Topology::build(mesh) else {
        return flat_corner_normals(mesh, raw);
    };
    let cos_limit = crease_angle_deg.to_radians().cos();
    let sharp: Vec<bool> = topo
        .edge_corner
        .iter()
        .map(|&c| {
            let tw = topo.twin[c as usize];
            if tw == NONE {
                return true;
            }
            let (a, b) = (
                mesh.corner_verts[c as usize],
                mesh.corner_verts[topo.next(c as usize) as usize],
            );
            if attrs
                .get(&EdgeKey::new(a, b))
                .is_some_and(|x| x.crease > 0.0)
            {
                return true;
            }
            let n1 = unit_or_zero(raw[topo.corner_face(c as usize) as usize]);
            let n2 = unit_or_zero(raw[topo.corner_face(tw as usize) as usize]);
            n1.dot(n2) < cos_limit
        })
        .collect();
    fans(mesh, &topo, raw, &sharp)
}

/// Every corner gets its face's unit normal, written on every core in chunks of faces (one
/// thread filling the corners of a 129k-face level was 2 ms of an edit's scene).
pub fn flat_corner_normals(mesh: &PolyMesh, raw: &[DVec3]) -> Vec<DVec3> {
    use crate::parallel::{face_chunks, filled, split_at_bounds};
    use rayon::prelude::*;
    let (faces, bounds) = face_chunks(mesh);
    let mut n = filled(mesh.num_corners(), DVec3::ZERO);
    split_at_bounds(&mut n, &bounds)
        .into_par_iter()
        .zip(faces.par_windows(2))
        .for_each(|(piece, w)| {
            let first = mesh.face_corners(w[0]).start;
            for (f, &r) in (w[0]..w[1]).zip(&raw[w[0]..w[1]]) {
                let c = mesh.face_corners(f);
                piece[c.start - first..c.end - first].fill(unit_or_zero(r));
            }
        });
    n
}

/// Faces around a vertex averaged within each fan between sharp edges.
fn fans(mesh: &PolyMesh, topo: &Topology, raw: &[DVec3], sharp: &[bool]) -> Vec<DVec3> {
    let mut out: Vec<DVec3> = (0..topo.num_corners())
        .map(|c| unit_or_zero(raw[topo.corner_face(c) as usize]))
        .collect();
    let (mut ring_e, mut ring_c) = (Vec::new(), Vec::new());
    for v in 0..mesh.num_vertices() {
        topo.vertex_ring_from(mesh, topo.vert_corner[v], &mut ring_e, &mut ring_c);
        let n = ring_c.len();
        if n == 0 {
            continue;
        }
        // Face i lies between edges i and i + 1; a sharp edge i + 1 ends a group.
        let closed = ring_e.len() == n;
        // Start a group after a sharp edge if there is one, so no group wraps around.
        let first = if closed {
            (0..n).find(|&i| sharp[ring_e[i].0 as usize]).unwrap_or(0)
        } else {
            0
        };
        let mut group: Vec<u32> = Vec::new();
        let mut sum = DVec3::ZERO;
        for k in 0..n {
            let i = (first + k) % n;
            let c = ring_c[i];
            group.push(c);
            sum += raw[topo.corner_face(c as usize) as usize];
            let next_edge = ring_e[(i + 1) % ring_e.len()].0 as usize;
            let ends = k + 1 == n || sharp[next_edge];
            if ends {
                let nrm = unit_or_zero(sum);
                for &g in &group {
                    out[g as usize] = nrm;
                }
                group.clear();
                sum = DVec3::ZERO;
            }
        }
    }
    out
}
