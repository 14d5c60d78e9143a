//! One split per topology, and where every child element comes from, as data.
//!
//! A refinement step is a rule placing points (the biquadratic corner rules in
//! [`crate::rules`], the primal masks in [`crate::rules::primal`]) and a *split* building the
//! child's faces from them. Prism has three splits, each written once:
//!
//! - [`dual_quad`]: one child vertex per parent corner; FACE-, EDGE- and VERTEX-faces
//!   (PRISM's biquadratic step, seed 000 §2; CGAL's DQQ);
//! - [`quad`]: vertex, edge and face points; one quad per parent corner (Catmull–Clark);
//! - [`tri`]: vertex and edge points; four triangles per parent triangle (Loop).
//!
//! The child numbering is [`Numbering`]: every user of a child index (the point rules, the
//! splits, the written-down child topology, attribute propagation, ancestry, the viewport's
//! corner overlay, the memory estimate) asks it instead of spelling out `V + e`. What a level
//! records about its parent is [`Provenance`]: the numbering, the parent of every face and
//! the parent edge of every child edge lying on one.

pub mod dual_quad;
pub mod quad;
mod ring_order;
pub mod tri;

pub use dual_quad::FaceKind;
pub use ring_order::RingOrder;

use crate::edge_attrs::{EdgeAttr, EdgeAttrs, EdgeKey};
use crate::mesh::PolyMesh;
use crate::topology::Topology;

/// The parent element a child vertex stands for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Parent {
    /// The vertex point of a parent vertex (primal splits).
    Vertex(u32),
    /// The edge point of a parent edge (primal splits).
    Edge(u32),
    /// The face point of a parent face (quad split).
    Face(u32),
    /// The new point of a parent face corner (dual quad split).
    Corner(u32),
}

/// Child numbering of the primal splits: vertex points keep their parent's index
/// (`0..V`), then one edge point per parent edge (`V + e`), then, for the quad split, one
/// face point per parent face (`V + E + f`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PrimalNumbering {
    pub vertices: u32,
    pub edges: u32,
    /// Parent faces with a face point (0 for the triangle split).
    pub face_points: u32,
}

impl PrimalNumbering {
    #[inline]
    pub fn vertex(self, v: u32) -> u32 {
        v
    }
    #[inline]
    pub fn edge_point(self, e: u32) -> u32 {
        self.vertices + e
    }
    #[inline]
    pub fn face_point(self, f: u32) -> u32 {
        debug_assert!(f < self.face_points);
        self.vertices + self.edges + f
    }
    /// Number of child vertices.
    pub fn len(self) -> usize {
        (self.vertices + self.edges + self.face_points) as usize
    }
    pub fn is_empty(self) -> bool {
        self.len() == 0
    }
}

/// The two primal splits, each with its own file: what the primal driver calls instead of
/// choosing between [`quad`] and [`tri`] at every use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PrimalSplit {
    /// Catmull–Clark's ([`quad`]).
    Quad,
    /// Loop's ([`tri`]).
    Tri,
}

impl PrimalSplit {
    /// The child numbering of `mesh`.
    pub fn numbering(self, mesh: &PolyMesh, topo: &Topology) -> PrimalNumbering {
        match self {
            PrimalSplit::Quad => quad::numbering(mesh, topo),
            PrimalSplit::Tri => tri::numbering(mesh, topo),
        }
    }

    /// Sizes of the child of `mesh` with `edges` edges.
    pub fn counts(self, mesh: &PolyMesh, edges: usize) -> ChildCounts {
        match self {
            PrimalSplit::Quad => quad::counts(mesh, edges),
            PrimalSplit::Tri => tri::counts(mesh, edges),
        }
    }

    /// The child's faces (no positions yet).
    pub fn faces(self, mesh: &PolyMesh, topo: &Topology, n: PrimalNumbering) -> PolyMesh {
        match self {
            PrimalSplit::Quad => quad::faces(mesh, topo, n),
            PrimalSplit::Tri => tri::faces(mesh, topo, n),
        }
    }

    /// The parent face of each child face (asked for only where it is used: provenance,
    /// holes).
    pub fn face_parent(self, mesh: &PolyMesh, topo: &Topology) -> Vec<u32> {
        match self {
            PrimalSplit::Quad => quad::face_parent(topo),
            PrimalSplit::Tri => tri::face_parent(mesh),
        }
    }

    /// The child's topology, written down.
    pub(crate) fn topology(self, mesh: &PolyMesh, topo: &Topology) -> Topology {
        match self {
            PrimalSplit::Quad => quad::topology(mesh, topo),
            PrimalSplit::Tri => tri::topology(mesh, topo),
        }
    }

    /// OpenSubdiv's ring order of the child, given the parent's.
    pub(crate) fn ring_order(
        self,
        order: &RingOrder,
        mesh: &PolyMesh,
        topo: &Topology,
    ) -> RingOrder {
        match self {
            PrimalSplit::Quad => quad::ring_order(order, mesh, topo),
            PrimalSplit::Tri => tri::ring_order(order, mesh, topo),
        }
    }
}

/// How a child's vertices are numbered from its parent's elements: the parent → child maps of
/// one split.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Numbering {
    /// Child vertex c is the new point of parent corner c.
    DualQuad,
    /// Vertex, edge and face points ([`PrimalNumbering`]).
    Primal(PrimalNumbering),
}

impl Numbering {
    /// The parent element of child vertex `i`.
    pub fn vertex_parent(self, i: u32) -> Parent {
        match self {
            Numbering::DualQuad => Parent::Corner(i),
            Numbering::Primal(n) => {
                if i < n.vertices {
                    Parent::Vertex(i)
                } else if i < n.vertices + n.edges {
                    Parent::Edge(i - n.vertices)
                } else {
                    Parent::Face(i - n.vertices - n.edges)
                }
            }
        }
    }

    /// The parent vertex a child vertex stands for or was cut from (a corner's vertex), if
    /// any: what the corner overlay draws an arrow from.
    pub fn parent_vertex(self, parent: &PolyMesh, i: u32) -> Option<u32> {
        match self.vertex_parent(i) {
            Parent::Vertex(v) => Some(v),
            Parent::Corner(c) => parent.corner_verts.get(c as usize).copied(),
            Parent::Edge(_) | Parent::Face(_) => None,
        }
    }

    /// Calls `f(child edge, end)` for every child edge lying on parent edge `e`; `end` is the
    /// parent vertex a primal half touches (`None` for the four sides of an EDGE-face, which
    /// run along the whole edge or cross it).
    pub fn edge_children(
        self,
        parent: &PolyMesh,
        topo: &Topology,
        e: u32,
        mut f: impl FnMut(EdgeKey, Option<u32>),
    ) {
        match self {
            Numbering::DualQuad => {
                for key in dual_quad::edge_face_sides(topo, e) {
                    f(key, None);
                }
            }
            Numbering::Primal(n) => {
                let (a, b) = topo.edge_verts(parent, e as usize);
                let mid = n.edge_point(e);
                f(EdgeKey::new(n.vertex(a), mid), Some(a));
                f(EdgeKey::new(n.vertex(b), mid), Some(b));
            }
        }
    }
}

/// Where a level's elements come from.
#[derive(Debug, Clone, PartialEq)]
pub struct Provenance {
    pub numbering: Numbering,
    /// Kind of each child face of a dual quad split (empty for the primal splits, whose
    /// faces all lie in one parent face each).
    pub face_kind: Vec<FaceKind>,
    /// The parent face, edge or vertex (by kind) of each child face.
    pub face_parent: Vec<u32>,
    /// Every child edge lying on a parent edge, with that parent edge, both by their
    /// vertices; edges inside a parent face (to face points, Loop's middle triangles) have
    /// none.
    pub edge_parent: Vec<(EdgeKey, EdgeKey)>,
}

impl Provenance {
    /// The FACE/EDGE/VERTEX kind of every face, for a dual quad split.
    pub fn face_kinds(&self) -> Option<&[FaceKind]> {
        (!self.face_kind.is_empty()).then_some(self.face_kind.as_slice())
    }

    /// The provenance of a split with numbering `numbering` of `parent`, whose faces came
    /// from `face_kind`/`face_parent`.
    pub fn new(
        parent: &PolyMesh,
        topo: &Topology,
        numbering: Numbering,
        face_kind: Vec<FaceKind>,
        face_parent: Vec<u32>,
    ) -> Provenance {
        // Each parent edge's children, on every core, in edge order.
        let children = |e: u32, out: &mut [(EdgeKey, EdgeKey)]| {
            let (a, b) = topo.edge_verts(parent, e as usize);
            let pk = EdgeKey::new(a, b);
            let mut i = 0;
            numbering.edge_children(parent, topo, e, |k, _| {
                out[i] = (k, pk);
                i += 1;
            });
            debug_assert_eq!(i, out.len());
        };
        let edge_parent = match numbering {
            Numbering::DualQuad => per_edge::<4>(topo.num_edges(), children),
            Numbering::Primal(_) => per_edge::<2>(topo.num_edges(), children),
        };
        Provenance {
            numbering,
            face_kind,
            face_parent,
            edge_parent,
        }
    }
}

/// `[f(0), f(1), …]` flattened, `f(e)` filling edge e's `K` entries, on rayon's pool.
fn per_edge<const K: usize>(
    edges: usize,
    f: impl Fn(u32, &mut [(EdgeKey, EdgeKey)]) + Sync,
) -> Vec<(EdgeKey, EdgeKey)> {
    use rayon::prelude::*;
    (0..edges as u32)
        .into_par_iter()
        .with_min_len(1 << 12)
        .map(|e| {
            let mut out = [(EdgeKey(0, 0), EdgeKey(0, 0)); K];
            f(e, &mut out);
            out
        })
        .collect::<Vec<[(EdgeKey, EdgeKey); K]>>()
        .into_flattened()
}

/// The child faces of a primal split: `parents` × `W` corner indices, `fill(p)` giving
/// parent `p`'s children, cut into one-loop faces of `corners` corners each. Written on
/// rayon's pool in blocks of parents (each parent's children depend on it alone), so the
/// fresh pages are also first touched on every core.
pub(crate) fn uniform_faces<const W: usize>(
    parents: usize,
    corners: u32,
    fill: impl Fn(usize) -> [u32; W] + Sync,
) -> PolyMesh {
    // Every slot is written once, where it belongs, with no zeroed buffer first (64 MB for
    // a million quads' children).
    let by_parent = crate::stream::collect(parents, fill);
    let mut child = PolyMesh::new();
    child.corner_verts = by_parent.into_flattened();
    let faces = parents * W / corners as usize;
    child.loop_starts = multiples(faces + 1, corners);
    child.face_starts = multiples(faces + 1, 1);
    child
}

/// `[0, step, 2·step, …]`, `n` of them, written in blocks of eight past the cache on every
/// core (the offsets of a million quads' children are 32 MB).
fn multiples(n: usize, step: u32) -> Vec<u32> {
    const LANES: usize = 8;
    let v = crate::stream::collect(n.div_ceil(LANES), |b| {
        std::array::from_fn::<u32, LANES, _>(|k| step * (b * LANES + k) as u32)
    });
    let mut v = v.into_flattened();
    v.truncate(n);
    v
}

/// Hands edge attributes down one split: every child edge lying on an attributed parent edge
/// gets `child(attribute, end)` when that is `Some` (`end` as in
/// [`Numbering::edge_children`]). The one propagation for both families: the biquadratic
/// step copies, the primal step decays the crease towards the end the half touches.
pub fn propagate(
    parent: &PolyMesh,
    topo: &Topology,
    attrs: &EdgeAttrs,
    numbering: Numbering,
    mut child: impl FnMut(u32, &EdgeAttr, Option<u32>) -> Option<EdgeAttr>,
) -> EdgeAttrs {
    // Collected, then sorted and built at once: inserting each of thousands of child marks
    // into the ordered map cost more than finding them.
    let mut out = Vec::new();
    for (k, a) in attrs {
        let Some(e) = topo.find_edge(parent, k.0, k.1) else {
            continue;
        };
        numbering.edge_children(parent, topo, e, |key, end| {
            if let Some(c) = child(e, a, end) {
                out.push((key, c));
            }
        });
    }
    // Equal keys keep the last, as inserting them one by one did.
    out.into_iter().collect()
}

/// Sizes of a child, to estimate its memory before building it and to report it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ChildCounts {
    pub vertices: u64,
    pub edges: u64,
    pub faces: u64,
    pub corners: u64,
}

impl ChildCounts {
    /// Bytes of the child's positions, corners and face offsets, and of its
    /// [`Provenance`] (a face's kind and parent, a parent edge per child edge at most).
    pub fn bytes(&self) -> u64 {
        self.vertices * 24 + self.corners * 4 + self.faces * (8 + 5) + self.edges * 16
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;

    /// Every split's provenance: the parent of each child vertex by the numbering, and the
    /// recorded edge map covers exactly the child edges lying on parent edges.
    #[test]
    fn numbering_and_edge_maps_of_the_three_splits() {
        let m = primitives::cube3();
        let topo = Topology::build(&m).unwrap();
        let (nv, ne, nf) = (m.num_vertices(), topo.num_edges(), m.num_faces());

        // Dual quad: child vertex c is corner c; every child edge is on an EDGE-face.
        let pts = (0..m.num_corners())
            .map(|c| m.positions[m.corner_verts[c] as usize])
            .collect();
        let (child, prov) = dual_quad::split(&m, &topo, pts);
        let ct = Topology::build(&child).unwrap();
        assert_eq!(prov.edge_parent.len(), ct.num_edges());
        for i in 0..child.num_vertices() as u32 {
            assert_eq!(prov.numbering.vertex_parent(i), Parent::Corner(i));
            assert_eq!(
                prov.numbering.parent_vertex(&m, i),
                Some(m.corner_verts[i as usize])
            );
        }

        // Quad and triangle splits: V vertex points, E edge points, F face points (quad).
        let tri_mesh = primitives::fan_triangulated(&m);
        let tri_topo = Topology::build(&tri_mesh).unwrap();
        for (mesh, t, n, faces) in [
            (
                &m,
                &topo,
                quad::numbering(&m, &topo),
                (
                    quad::faces(&m, &topo, quad::numbering(&m, &topo)),
                    quad::face_parent(&topo),
                ),
            ),
            (
                &tri_mesh,
                &tri_topo,
                tri::numbering(&tri_mesh, &tri_topo),
                (
                    tri::faces(&tri_mesh, &tri_topo, tri::numbering(&tri_mesh, &tri_topo)),
                    tri::face_parent(&tri_mesh),
                ),
            ),
        ] {
            let num = Numbering::Primal(n);
            let (v, e) = (mesh.num_vertices() as u32, t.num_edges() as u32);
            assert_eq!(num.vertex_parent(3), Parent::Vertex(3));
            assert_eq!(num.vertex_parent(v + 2), Parent::Edge(2));
            assert_eq!(num.parent_vertex(mesh, v + 2), None);
            if n.face_points > 0 {
                assert_eq!(num.vertex_parent(v + e + 1), Parent::Face(1));
            }
            let (mut child, face_parent) = faces;
            child.positions = vec![glam::DVec3::ZERO; n.len()];
            let ct = Topology::build(&child).unwrap();
            let prov = Provenance::new(mesh, t, num, Vec::new(), face_parent);
            // Two halves per parent edge, each an edge of the child touching its end.
            assert_eq!(prov.edge_parent.len(), 2 * t.num_edges());
            for (c, p) in &prov.edge_parent {
                assert!(ct.find_edge(&child, c.0, c.1).is_some());
                assert!(c.0 == p.0 || c.0 == p.1, "{c:?} on {p:?}");
            }
        }
        assert_eq!(quad::counts(&m, ne).vertices as usize, nv + ne + nf);
    }
}
