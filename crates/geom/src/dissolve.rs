//! Dissolving flat edges before a cylindrical-family step (docs/algorithms/cylindrical.md, flat edges).
//!
//! A flat edge (bend angle below a tolerance) gets cut width 0, so its EDGE-face would have
//! zero area, and at a T-junction eq. (4) divides by sin φ = 0. Coplanar splits do not change
//! the solid, so Prism merges the faces on either side of every flat edge (the union may
//! acquire holes: supported), then removes vertices left with two edges that meet at more
//! than 120°. A merged face carries the vertex-neighbourhood flag if any part had it. A
//! region whose boundary touches itself at a vertex (a pinch) cannot be one face: refused
//! with the vertex named.

use crate::edge_attrs::{EdgeAttrs, EdgeKey};
use crate::mesh::PolyMesh;
use crate::topology::{NONE, Topology};
use glam::DVec3;
use thiserror::Error;

/// A vertex left with two edges is removed when they are straighter than this (cosine of
/// their angle: 120°). Collinear ones change nothing; a kink (a merged face that is not quite
/// planar meets its neighbour along a bent chain) would give a two-cornered VERTEX-face of
/// no area in the child, so its vertex goes too and the chain becomes one edge.
pub(crate) const KINK_COS: f64 = -0.5;

#[derive(Debug, Clone, PartialEq, Error)]
pub enum DissolveError {
    #[error(
        "merging the coplanar faces around face {face} would make a face whose boundary touches itself at vertex {vertex}"
    )]
    Pinch { face: u32, vertex: u32 },
    #[error("the coplanar faces around face {face} do not form one region with holes")]
    NotARegion { face: u32 },
}

/// The result of a dissolve that changed something.
#[derive(Debug, Clone)]
pub struct Dissolved {
    pub mesh: PolyMesh,
    pub face_flags: Vec<bool>,
    pub edge_attrs: EdgeAttrs,
    pub dissolved_edges: usize,
    pub removed_vertices: usize,
    /// The input's index of each vertex of `mesh` (kept vertices are renumbered in order).
    pub old_vertex: Vec<u32>,
}

fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        parent[x as usize] = parent[parent[x as usize] as usize];
        x = parent[x as usize];
    }
    x
}

/// Merges the faces across every edge marked in `flat` (one flag an edge of `topo`); `None`
/// when there is none. `face_flags` are the combination run's vertex-neighbourhood flags,
/// carried to the merged faces.
pub fn dissolve_flat_edges(
    mesh: &PolyMesh,
    topo: &Topology,
    flat: &[bool],
    raw_normals: &[DVec3],
    face_flags: &[bool],
    attrs: &EdgeAttrs,
) -> Result<Option<Dissolved>, DissolveError> {
    let dissolved_edges = flat.iter().filter(|&&f| f).count();
    if dissolved_edges == 0 {
        return Ok(None);
    }
    let nf = mesh.num_faces();
    let mut uf: Vec<u32> = (0..nf as u32).collect();
    for (e, &c) in topo.edge_corner.iter().enumerate() {
        if flat[e] {
            let a = find(&mut uf, topo.corner_face(c as usize));
            let b = find(&mut uf, topo.corner_face(topo.twin[c as usize] as usize));
            if a != b {
                let (lo, hi) = (a.min(b), a.max(b));
                uf[hi as usize] = lo;
            }
        }
    }
    let is_boundary = |c: usize| !flat[topo.corner_edge[c] as usize];
    // Successor of a boundary half-edge: turn around its end vertex across flat edges.
    let succ = |c: usize| -> usize {
        let mut h = topo.next(c) as usize;
        while !is_boundary(h) {
            h = topo.next(topo.twin[h] as usize) as usize;
        }
        h
    };

    // Group members, by representative (the smallest face index).
    let mut groups: Vec<Vec<u32>> = vec![Vec::new(); nf];
    for f in 0..nf as u32 {
        let r = find(&mut uf, f);
        groups[r as usize].push(f);
    }
    let mut visited = vec![false; mesh.num_corners()];
    let mut out = PolyMesh::new();
    out.positions = mesh.positions.clone();
    let mut out_flags = Vec::new();
    for (rep, members) in groups.iter().enumerate() {
        if members.is_empty() {
            continue;
        }
        if members.len() == 1 {
            let f = members[0] as usize;
            let loops: Vec<&[u32]> = mesh.face_loops(f).map(|l| mesh.loop_verts(l)).collect();
            out.push_face(&loops);
            out_flags.push(face_flags.get(f).copied().unwrap_or(false));
            continue;
        }
        let normal: DVec3 = members.iter().map(|&f| raw_normals[f as usize]).sum();
        let mut loops: Vec<(f64, Vec<u32>)> = Vec::new();
        for &f in members {
            for c0 in mesh.face_corners(f as usize) {
                if visited[c0] || !is_boundary(c0) {
                    continue;
                }
                let mut lp = Vec::new();
                let mut c = c0;
                loop {
                    visited[c] = true;
                    lp.push(mesh.corner_verts[c]);
                    c = succ(c);
                    if c == c0 {
                        break;
                    }
                }
                let mut area = DVec3::ZERO;
                let o = mesh.positions[lp[0] as usize];
                for i in 0..lp.len() {
                    let a = mesh.positions[lp[i] as usize] - o;
                    let b = mesh.positions[lp[(i + 1) % lp.len()] as usize] - o;
                    area += a.cross(b);
                }
                loops.push((area.dot(normal), lp));
            }
        }
        let outer: Vec<usize> = (0..loops.len()).filter(|&i| loops[i].0 > 0.0).collect();
        if outer.len() != 1 {
            return Err(DissolveError::NotARegion { face: rep as u32 });
        }
        let mut seen = std::collections::HashSet::new();
        for (_, lp) in &loops {
            for &v in lp {
                if !seen.insert(v) {
                    return Err(DissolveError::Pinch {
                        face: rep as u32,
                        vertex: v,
                    });
                }
            }
        }
        let mut ordered: Vec<&[u32]> = vec![loops[outer[0]].1.as_slice()];
        ordered.extend(
            loops
                .iter()
                .enumerate()
                .filter(|(i, _)| *i != outer[0])
                .map(|(_, l)| l.1.as_slice()),
        );
        out.push_face(&ordered);
        out_flags.push(
            members
                .iter()
                .any(|&f| face_flags.get(f as usize).copied().unwrap_or(false)),
        );
    }

    // Remove vertices with exactly two corners whose edges meet at more than 120°.
    let nv = out.num_vertices();
    let mut count = vec![0u32; nv];
    for &v in &out.corner_verts {
        count[v as usize] += 1;
    }
    let mut remove = vec![false; nv];
    for l in 0..out.num_loops() {
        let vs = out.loop_verts(l);
        let n = vs.len();
        for i in 0..n {
            let v = vs[i] as usize;
            if count[v] != 2 {
                continue;
            }
            let p = out.positions[v];
            let a = (out.positions[vs[(i + n - 1) % n] as usize] - p).normalize_or_zero();
            let b = (out.positions[vs[(i + 1) % n] as usize] - p).normalize_or_zero();
            if a.dot(b) < KINK_COS {
                remove[v] = true;
            }
        }
    }
    // Attributes: an edge a-v-b that loses v keeps the attribute of a-v (or v-b).
    let mut new_attrs = attrs.clone();
    let mut compact = PolyMesh::new();
    for f in 0..out.num_faces() {
        let mut loops = Vec::new();
        for l in out.face_loops(f) {
            let vs = out.loop_verts(l);
            let n = vs.len();
            let kept: Vec<u32> = vs
                .iter()
                .copied()
                .filter(|&v| !remove[v as usize])
                .collect();
            for i in 0..n {
                if remove[vs[i] as usize] {
                    let (a, v) = (vs[(i + n - 1) % n], vs[i]);
                    let mut j = (i + 1) % n;
                    while remove[vs[j] as usize] {
                        j = (j + 1) % n;
                    }
                    let b = vs[j];
                    if let Some(at) = attrs
                        .get(&EdgeKey::new(a, v))
                        .or_else(|| attrs.get(&EdgeKey::new(v, b)))
                    {
                        new_attrs.insert(EdgeKey::new(a, b), *at);
                    }
                }
            }
            loops.push(kept);
        }
        let refs: Vec<&[u32]> = loops.iter().map(|l| l.as_slice()).collect();
        compact.push_face(&refs);
    }
    // Renumber the vertices still in use, in their old order.
    let mut used = vec![NONE; nv];
    for &v in &compact.corner_verts {
        used[v as usize] = 0;
    }
    let mut removed_vertices = 0;
    let mut old_vertex = Vec::new();
    for (old, (slot, &pos)) in used.iter_mut().zip(&out.positions).enumerate() {
        if *slot == 0 {
            *slot = compact.positions.len() as u32;
            compact.positions.push(pos);
            old_vertex.push(old as u32);
        } else {
            removed_vertices += 1;
        }
    }
    for v in compact.corner_verts.iter_mut() {
        *v = used[*v as usize];
    }
    let edge_attrs = new_attrs
        .into_iter()
        .filter_map(|(k, a)| {
            let (x, y) = (used[k.0 as usize], used[k.1 as usize]);
            (x != NONE && y != NONE).then(|| (EdgeKey::new(x, y), a))
        })
        .collect();
    Ok(Some(Dissolved {
        mesh: compact,
        face_flags: out_flags,
        edge_attrs,
        dissolved_edges,
        removed_vertices,
        old_vertex,
    }))
}
