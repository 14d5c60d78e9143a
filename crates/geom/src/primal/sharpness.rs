//! The sharpness of one level, boundary rules applied, and its decay one level down
//! (docs/algorithms/primal.md; the masks and rules are [`crate::rules::primal::crease`]).
//!
//! Boundaries: boundary edges are infinitely sharp; with [`BoundaryInterpolation::EdgeAndCorner`]
//! a vertex with one face and two edges is a sharp corner; with `None` the faces around a
//! boundary vertex whose boundary edges are not all tagged infinitely sharp become holes.

// Vertices, edges and corners are indices into parallel arrays here.
#![allow(clippy::needless_range_loop)]

use crate::edge_attrs::EdgeAttrs;
use crate::mesh::PolyMesh;
use crate::parallel::filled;
use crate::rules::primal::crease::{self, INFINITE, is_semi_sharp, is_sharp};
use crate::tags::{BoundaryInterpolation, CreaseMethod, SubdivTags};
use crate::topology::{NONE, Topology};
use rayon::prelude::*;

/// Sharpness of every edge and vertex of one level, boundary rules applied. An empty array
/// stands for all zeros: a smooth closed level (the usual one: no crease, corner or hole
/// tagged, no boundary) holds none, and is told in one look.
pub(crate) struct Sharpness {
    edge: Vec<f32>,
    vert: Vec<f32>,
    /// Number of sharp edges at each vertex.
    sharp_edges: Vec<u32>,
    /// Vertex semi-sharp or touching a semi-sharp edge: its rule may change.
    semi: Vec<bool>,
    hole: Vec<bool>,
}

impl Sharpness {
    /// The sharpness of edge `e`.
    #[inline]
    pub(crate) fn edge(&self, e: usize) -> f32 {
        self.edge.get(e).copied().unwrap_or(0.0)
    }

    /// The sharpness of vertex `v`.
    #[inline]
    pub(crate) fn vert(&self, v: usize) -> f32 {
        self.vert.get(v).copied().unwrap_or(0.0)
    }

    /// The number of sharp edges at vertex `v`.
    #[inline]
    pub(crate) fn sharp_edges(&self, v: usize) -> usize {
        self.sharp_edges.get(v).map_or(0, |&k| k as usize)
    }

    /// Whether vertex `v` is semi-sharp or touches a semi-sharp edge.
    #[inline]
    pub(crate) fn semi(&self, v: usize) -> bool {
        self.semi.get(v).copied().unwrap_or(false)
    }

    /// Whether face `f` is a hole.
    #[inline]
    pub(crate) fn hole(&self, f: usize) -> bool {
        self.hole.get(f).copied().unwrap_or(false)
    }

    /// Whether any face is a hole.
    pub(crate) fn any_hole(&self) -> bool {
        self.hole.par_iter().with_min_len(1 << 14).any(|&h| h)
    }
}

pub(crate) fn sharpness(
    mesh: &PolyMesh,
    topo: &Topology,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
) -> Sharpness {
    // Nothing tagged and no boundary: every array would be zeros.
    let smooth = topo.is_closed()
        && tags.holes.is_empty()
        && tags.corners.values().all(|&s| s.is_nan() || s <= 0.0)
        && attrs.values().all(|a| a.crease.is_nan() || a.crease <= 0.0);
    if smooth {
        return Sharpness {
            edge: Vec::new(),
            vert: Vec::new(),
            sharp_edges: Vec::new(),
            semi: Vec::new(),
            hole: Vec::new(),
        };
    }
    let nv = mesh.num_vertices();
    let ne = topo.num_edges();
    let mut edge = filled(ne, 0.0f32);
    for (k, a) in attrs {
        if let Some(e) = topo.find_edge(mesh, k.0, k.1) {
            edge[e as usize] = (a.crease as f32).max(0.0);
        }
    }
    let mut vert = filled(nv, 0.0f32);
    for (&v, &s) in &tags.corners {
        if (v as usize) < nv {
            vert[v as usize] = (s as f32).max(0.0);
        }
    }
    let mut hole = filled(mesh.num_faces(), false);
    for &f in &tags.holes {
        if (f as usize) < hole.len() {
            hole[f as usize] = true;
        }
    }
    let mut ring_e = Vec::new();
    let mut ring_f = Vec::new();
    // Boundary vertices: holes (no interpolation) and sharp corners, before the boundary
    // edges themselves are sharpened.
    if tags.boundary != BoundaryInterpolation::EdgeOnly {
        // The boundary vertices (their first half-edge has no twin), found on every core.
        let boundary: Vec<usize> = (0..nv)
            .into_par_iter()
            .with_min_len(1 << 14)
            .filter(|&v| {
                let c = topo.vert_corner[v];
                c != NONE && topo.twin[c as usize] == NONE
            })
            .collect();
        for v in boundary {
            topo.vertex_ring_from(mesh, topo.vert_corner[v], &mut ring_e, &mut ring_f);
            match tags.boundary {
                BoundaryInterpolation::None => {
                    let open = ring_e.iter().any(|&(e, _)| {
                        let c = topo.edge_corner[e as usize] as usize;
                        topo.twin[c] == NONE && !crease::is_infinite(edge[e as usize])
                    });
                    if open {
                        for &c in &ring_f {
                            hole[topo.corner_face(c as usize) as usize] = true;
                        }
                    }
                }
                BoundaryInterpolation::EdgeAndCorner => {
                    if ring_f.len() == 1 && ring_e.len() == 2 {
                        vert[v] = INFINITE;
                    }
                }
                BoundaryInterpolation::EdgeOnly => {}
            }
        }
    }
    edge.par_iter_mut()
        .with_min_len(1 << 14)
        .enumerate()
        .for_each(|(e, s)| {
            if topo.twin[topo.edge_corner[e] as usize] == NONE {
                *s = INFINITE;
            }
        });
    let mut sharp_edges = filled(nv, 0u32);
    let mut semi: Vec<bool> = vert
        .par_iter()
        .with_min_len(1 << 14)
        .map(|&s| is_semi_sharp(s))
        .collect();
    // A smooth closed level (the usual one) has no sharp edge to count: one look on
    // every core instead of a pass on one.
    let any_sharp = edge.par_iter().with_min_len(1 << 14).any(|&s| is_sharp(s));
    if any_sharp {
        for (e, &s) in edge.iter().enumerate() {
            if is_sharp(s) {
                let (a, b) = topo.edge_verts(mesh, e);
                sharp_edges[a as usize] += 1;
                sharp_edges[b as usize] += 1;
                if is_semi_sharp(s) {
                    semi[a as usize] = true;
                    semi[b as usize] = true;
                }
            }
        }
    }
    Sharpness {
        edge,
        vert,
        sharp_edges,
        semi,
        hole,
    }
}

/// Child sharpness of each edge around a vertex, in ring order (`parent` in ring order).
pub(crate) fn child_sharpness_around(method: CreaseMethod, parent: &[f32], out: &mut Vec<f32>) {
    let (sum, count) = crease::semi_sharp_sum(parent.iter().copied());
    out.clear();
    out.extend(
        parent
            .iter()
            .map(|&s| crease::child_edge_sharpness(method, s, parent.len(), sum, count)),
    );
}

/// Semi-sharp sum and count around each vertex that touches a semi-sharp edge (Chaikin
/// only needs them), summed in ring order.
fn semi_sums(
    mesh: &PolyMesh,
    topo: &Topology,
    sh: &Sharpness,
    ring_start: &dyn Fn(usize) -> u32,
) -> Vec<(f32, u32, u32)> {
    let mut out = vec![(0.0f32, 0u32, 0u32); mesh.num_vertices()];
    let mut ring_e = Vec::new();
    let mut ring_f = Vec::new();
    for v in 0..mesh.num_vertices() {
        if !sh.semi(v) {
            continue;
        }
        topo.vertex_ring_from(mesh, ring_start(v), &mut ring_e, &mut ring_f);
        let (sum, count) = crease::semi_sharp_sum(ring_e.iter().map(|&(e, _)| sh.edge(e as usize)));
        out[v] = (sum, count, ring_e.len() as u32);
    }
    out
}

/// The child sharpness of every edge at either end: the uniform decay, or Chaikin's with
/// the semi-sharp sums around each vertex.
pub(crate) struct ChildSharpness<'a> {
    sh: &'a Sharpness,
    method: CreaseMethod,
    sums: Vec<(f32, u32, u32)>,
}

impl<'a> ChildSharpness<'a> {
    pub(crate) fn new(
        mesh: &PolyMesh,
        topo: &Topology,
        sh: &'a Sharpness,
        method: CreaseMethod,
        ring_start: &dyn Fn(usize) -> u32,
    ) -> Self {
        let sums = if method == CreaseMethod::Chaikin {
            semi_sums(mesh, topo, sh, ring_start)
        } else {
            Vec::new()
        };
        ChildSharpness { sh, method, sums }
    }

    /// Child sharpness of edge `e` at its end vertex `v`.
    #[inline]
    pub(crate) fn edge(&self, e: usize, v: usize) -> f32 {
        let s = self.sh.edge(e);
        if self.method == CreaseMethod::Chaikin {
            let (sum, count, edges) = self.sums[v];
            crease::child_edge_sharpness(self.method, s, edges as usize, sum, count)
        } else {
            crease::decrement(s)
        }
    }
}
