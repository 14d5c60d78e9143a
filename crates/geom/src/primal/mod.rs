//! The primal schemes, Catmull–Clark and Loop, with creases, corners, boundaries and holes,
//! written once: one driver classifies every vertex and edge (smooth, dart, crease, corner,
//! and the blend where a semi-sharp feature runs out) and splits the faces, and only the
//! smooth masks ([`masks`]) and the split pattern differ per scheme.
//!
//! Seeds: Loop with discontinuities, seed 001 §2 (crease masks eq. 3–4, limit eq. 5–7);
//! Catmull–Clark, the reference scheme of seeds 000 and 002. Semi-sharp creases follow
//! DeRose, Kass & Truong (1998) as OpenSubdiv implements them, so that results equal
//! OpenSubdiv's (tests/opensubdiv.rs): new vertex = blend of the parent's and the child's
//! rule masks with the fractional weight of [`crease::fractional_weight`].
//!
//! Child numbering: vertex points keep their parent's index (`0..V`), then one edge point
//! per parent edge (`V + e`), then (Catmull–Clark) one face point per face (`V + E + f`).
//! Catmull–Clark writes one quad per parent corner (child face = parent corner index);
//! Loop four triangles per parent triangle (corner triangles, then the middle one).
//!
//! Boundaries: boundary edges are infinitely sharp; with [`BoundaryInterpolation::EdgeAndCorner`]
//! a vertex with one face and two edges is a sharp corner; with `None` the faces around a
//! boundary vertex whose boundary edges are not all tagged infinitely sharp become holes.
//! Holes are refined like any face (they shape their neighbours) and their children stay
//! holes.

// Vertices, edges and corners are indices into parallel arrays here; iterator chains over
// three arrays at once read worse than the index.
#![allow(clippy::needless_range_loop)]

mod child_topology;
pub mod crease;
pub mod limit;
pub mod masks;

pub use limit::{LimitPoints, limit_points, limit_points_ordered};

use crate::edge_attrs::{EdgeAttr, EdgeAttrs, EdgeKey};
use crate::error::{MeshError, OverBudget};
use crate::mesh::PolyMesh;
use crate::tags::{BoundaryInterpolation, CreaseMethod, SubdivTags};
use crate::topology::{NONE, Topology};
use crease::{INFINITE, Rule, is_semi_sharp, is_sharp, vertex_rule};
use glam::DVec3;
use rayon::prelude::*;
use std::time::Instant;
use thiserror::Error;

/// Which primal scheme.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PrimalScheme {
    CatmullClark,
    Loop,
    /// Catmull–Clark whose crease curves (chains of sharp edges, boundaries included) are
    /// refined by seed 002's circle-preserving curve rule (method 1) instead of the cubic
    /// B-spline rule: a crease vertex moves to `(1 − ω) v + ω/2 (a + b)` with
    /// `ω = 1/(4 cos²(θ₀/4))`, θ₀ the turning angle of the crease at v (`ω = 1/4`, the
    /// B-spline's `¾ v + ⅛ (a + b)`, on a straight crease). A crease that is a regular polygon
    /// becomes a circle (docs/curves.md, "On surfaces").
    CatmullClarkCircle,
}

impl PrimalScheme {
    /// Its kind in the scheme catalogue.
    pub fn kind(self) -> crate::scheme::SchemeKind {
        use crate::scheme::SchemeKind;
        match self {
            PrimalScheme::CatmullClark => SchemeKind::CatmullClark,
            PrimalScheme::Loop => SchemeKind::Loop,
            PrimalScheme::CatmullClarkCircle => SchemeKind::CatmullClarkCircle,
        }
    }

    pub fn name(self) -> &'static str {
        self.kind().name()
    }

    /// The split pattern and smooth masks: Catmull–Clark for both of its variants.
    pub fn family(self) -> PrimalScheme {
        match self {
            PrimalScheme::CatmullClarkCircle => PrimalScheme::CatmullClark,
            s => s,
        }
    }

    /// Whether crease vertices use the circle-preserving weight.
    pub fn circle_creases(self) -> bool {
        self == PrimalScheme::CatmullClarkCircle
    }
}

#[derive(Debug, Clone, PartialEq, Error)]
pub enum PrimalError {
    #[error(transparent)]
    Mesh(#[from] MeshError),
    #[error("face {face} has holes: {scheme} needs faces without holes")]
    HoledFace { face: u32, scheme: &'static str },
    #[error("face {face} has {corners} corners: Loop subdivides triangles only")]
    NotTriangle { face: u32, corners: usize },
    #[error(transparent)]
    TooLarge(#[from] OverBudget),
    #[error(
        "{scheme} has no limit masks: its crease curves are not B-splines (refine more levels instead)"
    )]
    NoLimitMasks { scheme: &'static str },
}

/// What one primal step did.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PrimalReport {
    pub vertices: usize,
    pub edges: usize,
    pub faces: usize,
    /// Faces of the result that are holes.
    pub holes: usize,
    pub millis: f64,
}

/// The next level with its creases, corners and holes.
#[derive(Debug, Clone)]
pub struct PrimalOutput {
    pub mesh: PolyMesh,
    pub edge_attrs: EdgeAttrs,
    pub tags: SubdivTags,
    pub report: PrimalReport,
}

/// The order OpenSubdiv gives the edges and faces around each vertex, which decides the
/// side of a one-sided crease normal and which two edges a corner's tangents follow. At
/// the input it is the natural one (each ring starts in the vertex's lowest-numbered face,
/// each edge's first face is its lower-numbered one); refinement passes it on as
/// OpenSubdiv's refiner does (`Vtr::QuadRefinement`, `Vtr::TriRefinement`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RingOrder {
    /// The corner each vertex's ring starts at ([`NONE`] for a vertex without faces).
    pub ring_start: Vec<u32>,
    /// Whether each corner's half-edge lies in its edge's first face.
    pub first_half_edge: Vec<bool>,
}

impl RingOrder {
    /// The natural order of a mesh's topology.
    pub fn natural(topo: &Topology) -> RingOrder {
        RingOrder {
            ring_start: topo.vert_corner.clone(),
            first_half_edge: (0..topo.corner_edge.len())
                .map(|c| topo.edge_corner[topo.corner_edge[c] as usize] == c as u32)
                .collect(),
        }
    }

    /// The order of the child of a mesh with this order.
    fn child(&self, mesh: &PolyMesh, topo: &Topology, scheme: PrimalScheme) -> RingOrder {
        let nv = mesh.num_vertices();
        let ne = topo.num_edges();
        let nc = mesh.num_corners();
        let first = &self.first_half_edge;
        let first_of_edge = |e: usize| {
            let c = topo.edge_corner[e];
            let t = topo.twin[c as usize];
            if t != NONE && first[t as usize] { t } else { c }
        };
        // Position of corner c in its (single-loop) face.
        let local = |c: u32| {
            c - mesh
                .face_corners(topo.corner_face[c as usize] as usize)
                .start as u32
        };
        let mut ring_start = Vec::new();
        let mut first_half_edge;
        match scheme {
            PrimalScheme::CatmullClark | PrimalScheme::CatmullClarkCircle => {
                ring_start.reserve(nv + ne + mesh.num_faces());
                ring_start.extend(
                    self.ring_start
                        .iter()
                        .map(|&s| if s == NONE { NONE } else { 4 * s }),
                );
                ring_start.extend((0..ne).map(|e| 4 * topo.next[first_of_edge(e) as usize] + 3));
                ring_start.extend(
                    (0..mesh.num_faces()).map(|f| 4 * mesh.face_corners(f).start as u32 + 2),
                );
                first_half_edge = vec![false; 4 * nc];
                for c in 0..nc {
                    first_half_edge[4 * c] = first[c];
                    first_half_edge[4 * c + 1] = true;
                    first_half_edge[4 * c + 3] = first[topo.prev[c] as usize];
                }
            }
            PrimalScheme::Loop => {
                // Corner triangle k of face f is child face 4f + k: (v_k, e_k, e_(k−1)).
                let tri = |c: u32| 4 * topo.corner_face[c as usize] + local(c);
                ring_start.reserve(nv + ne);
                ring_start.extend(
                    self.ring_start
                        .iter()
                        .map(|&s| if s == NONE { NONE } else { 3 * tri(s) }),
                );
                ring_start
                    .extend((0..ne).map(|e| 3 * tri(topo.next[first_of_edge(e) as usize]) + 2));
                first_half_edge = vec![false; 4 * nc];
                for c in 0..nc {
                    let t = 3 * tri(c as u32) as usize;
                    first_half_edge[t] = first[c];
                    first_half_edge[t + 1] = true;
                    first_half_edge[t + 2] = first[topo.prev[c] as usize];
                }
            }
        }
        RingOrder {
            ring_start,
            first_half_edge,
        }
    }
}

/// Sharpness of every edge and vertex of one level, boundary rules applied.
pub(crate) struct Sharpness {
    edge: Vec<f32>,
    vert: Vec<f32>,
    /// Number of sharp edges at each vertex.
    sharp_edges: Vec<u32>,
    /// Vertex semi-sharp or touching a semi-sharp edge: its rule may change.
    semi: Vec<bool>,
    /// Edges carrying a user attribute, with it.
    tagged: Vec<(u32, EdgeAttr)>,
    hole: Vec<bool>,
}

pub(crate) fn sharpness(
    mesh: &PolyMesh,
    topo: &Topology,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
) -> Sharpness {
    let nv = mesh.num_vertices();
    let ne = topo.num_edges();
    let mut edge = vec![0.0f32; ne];
    let mut tagged = Vec::new();
    for (k, a) in attrs {
        if let Some(e) = topo.find_edge(mesh, k.0, k.1) {
            edge[e as usize] = (a.crease as f32).max(0.0);
            tagged.push((e, *a));
        }
    }
    let mut vert = vec![0.0f32; nv];
    for (&v, &s) in &tags.corners {
        if (v as usize) < nv {
            vert[v as usize] = (s as f32).max(0.0);
        }
    }
    let mut hole = vec![false; mesh.num_faces()];
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
        for v in 0..nv {
            let c = topo.vert_corner[v];
            if c == NONE || topo.twin[c as usize] != NONE {
                continue;
            }
            topo.vertex_ring(mesh, v as u32, &mut ring_e, &mut ring_f);
            match tags.boundary {
                BoundaryInterpolation::None => {
                    let open = ring_e.iter().any(|&(e, _)| {
                        let c = topo.edge_corner[e as usize] as usize;
                        topo.twin[c] == NONE && !crease::is_infinite(edge[e as usize])
                    });
                    if open {
                        for &c in &ring_f {
                            hole[topo.corner_face[c as usize] as usize] = true;
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
    for (e, s) in edge.iter_mut().enumerate() {
        if topo.twin[topo.edge_corner[e] as usize] == NONE {
            *s = INFINITE;
        }
    }
    let mut sharp_edges = vec![0u32; nv];
    let mut semi: Vec<bool> = vert.iter().map(|&s| is_semi_sharp(s)).collect();
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
    Sharpness {
        edge,
        vert,
        sharp_edges,
        semi,
        tagged,
        hole,
    }
}

/// Child sharpness of each edge around a vertex, in ring order (`parent` in ring order).
fn child_sharpness_around(method: CreaseMethod, parent: &[f32], out: &mut Vec<f32>) {
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
        if !sh.semi[v] {
            continue;
        }
        topo.vertex_ring_from(mesh, ring_start(v), &mut ring_e, &mut ring_f);
        let (sum, count) = crease::semi_sharp_sum(ring_e.iter().map(|&(e, _)| sh.edge[e as usize]));
        out[v] = (sum, count, ring_e.len() as u32);
    }
    out
}

/// Refuses faces with holes, and non-triangles under Loop, naming the face.
pub(crate) fn check_faces(mesh: &PolyMesh, scheme: PrimalScheme) -> Result<(), PrimalError> {
    for f in 0..mesh.num_faces() {
        if mesh.face_has_holes(f) {
            return Err(PrimalError::HoledFace {
                face: f as u32,
                scheme: scheme.name(),
            });
        }
        if scheme == PrimalScheme::Loop && mesh.face_corners(f).len() != 3 {
            return Err(PrimalError::NotTriangle {
                face: f as u32,
                corners: mesh.face_corners(f).len(),
            });
        }
    }
    Ok(())
}

/// Meshes with at least this many faces are refined on rayon's thread pool (when it has
/// more than one thread).
pub const PARALLEL_FACES: usize = 50_000;

/// `out[i] = f(i)` for every i, in chunks on rayon's pool when `parallel`. `f` is called
/// from one loop only, so that it is inlined into it.
#[inline(always)]
fn fill<T: Send>(out: &mut [T], parallel: bool, f: impl Fn(usize) -> T + Sync + Send) {
    let chunk = if parallel {
        (out.len() / (8 * rayon::current_num_threads())).max(4096)
    } else {
        out.len().max(1)
    };
    let run = |(k, q): (usize, &mut [T])| {
        for (i, o) in q.iter_mut().enumerate() {
            *o = f(k * chunk + i);
        }
    };
    if parallel {
        out.par_chunks_mut(chunk).enumerate().for_each(run);
    } else {
        out.chunks_mut(chunk).enumerate().for_each(run);
    }
}

/// Seed 002's method-1 weight `ω = 1/(4 cos²(θ₀/4))` for a crease turning from direction
/// `d1` to `d2` (as [`crate::curve::circle_weight`], in space).
fn circle_weight_3d(d1: DVec3, d2: DVec3) -> f64 {
    let den = d1.length() * d2.length();
    if den == 0.0 {
        return 0.25;
    }
    let c = (d1.dot(d2) / den).clamp(-1.0, 1.0);
    1.0 / (2.0 + 2.0 * ((1.0 + c) * 0.5).sqrt())
}

/// The point of a crease or corner vertex, blended with its child's rule where a
/// semi-sharp feature runs out.
#[allow(clippy::too_many_arguments)]
fn sharp_vertex_point(
    mesh: &PolyMesh,
    topo: &Topology,
    sh: &Sharpness,
    method: CreaseMethod,
    v: usize,
    ring_start: u32,
    p_rule: Rule,
    circle: bool,
    smooth_point: &dyn Fn(usize) -> DVec3,
) -> DVec3 {
    let p = &mesh.positions;
    let (mut ring_e, mut ring_c) = (Vec::new(), Vec::new());
    topo.vertex_ring_from(mesh, ring_start, &mut ring_e, &mut ring_c);
    let ps: Vec<f32> = ring_e.iter().map(|&(e, _)| sh.edge[e as usize]).collect();
    let rule_point = |rule: Rule, sharp: &[f32]| -> DVec3 {
        match rule {
            Rule::Smooth | Rule::Dart => smooth_point(v),
            Rule::Crease => {
                let [i, j] = crease::crease_ends(sharp);
                let (a, b) = (p[ring_e[i].1 as usize], p[ring_e[j].1 as usize]);
                let w = if circle {
                    circle_weight_3d(p[v] - a, b - p[v])
                } else {
                    0.25
                };
                (1.0 - w) * p[v] + 0.5 * w * (a + b)
            }
            Rule::Corner => p[v],
        }
    };
    let parent_pt = rule_point(p_rule, &ps);
    if !sh.semi[v] {
        return parent_pt;
    }
    let mut cs = Vec::new();
    child_sharpness_around(method, &ps, &mut cs);
    let c_vert = crease::decrement(sh.vert[v]);
    let c_rule = vertex_rule(c_vert, cs.iter().filter(|&&s| is_sharp(s)).count());
    if c_rule == p_rule {
        return parent_pt;
    }
    let child_pt = rule_point(c_rule, &cs);
    let pw = crease::fractional_weight(method, sh.vert[v], c_vert, &ps, &cs) as f64;
    pw * parent_pt + (1.0 - pw) * child_pt
}

/// Bytes of the child of a mesh (positions, corners, offsets), to refuse a step that would
/// not fit.
pub fn estimated_bytes(mesh: &PolyMesh, edges: usize, scheme: PrimalScheme) -> (u64, u64) {
    let (v, e, f, c) = (
        mesh.num_vertices() as u64,
        edges as u64,
        mesh.num_faces() as u64,
        mesh.num_corners() as u64,
    );
    let (verts, faces, corners) = match scheme {
        PrimalScheme::CatmullClark | PrimalScheme::CatmullClarkCircle => (v + e + f, c, 4 * c),
        PrimalScheme::Loop => (v + e, 4 * f, 12 * f),
    };
    (verts * 24 + corners * 4 + faces * 8, faces)
}

/// One level of Catmull–Clark or Loop.
pub fn refine_primal(
    mesh: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    scheme: PrimalScheme,
    memory_budget: u64,
) -> Result<PrimalOutput, PrimalError> {
    refine(mesh, attrs, tags, scheme, memory_budget, None, None, false).map(|(o, _, _)| o)
}

/// `levels` levels at once, only the last one kept. From the second level on the topology
/// is not searched for but written down from the split (`child_topology`), which saves a
/// third of a level's time.
pub fn refine_primal_levels(
    mesh: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    scheme: PrimalScheme,
    levels: usize,
    memory_budget: u64,
) -> Result<PrimalOutput, PrimalError> {
    assert!(levels >= 1, "at least one level");
    let (mut out, _, mut topo) = refine(
        mesh,
        attrs,
        tags,
        scheme,
        memory_budget,
        None,
        None,
        levels > 1,
    )?;
    for k in 2..=levels {
        let (o, _, t) = refine(
            &out.mesh,
            &out.edge_attrs,
            &out.tags,
            scheme,
            memory_budget,
            None,
            topo.take(),
            k < levels,
        )?;
        out = o;
        topo = t;
    }
    Ok(out)
}

/// One level, also passing on OpenSubdiv's ring order (`parent` `None`: the mesh is an
/// input, its order the natural one). What [`limit_points`] needs after several levels.
pub fn refine_primal_ordered(
    mesh: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    scheme: PrimalScheme,
    memory_budget: u64,
    parent: Option<&RingOrder>,
) -> Result<(PrimalOutput, RingOrder), PrimalError> {
    refine(
        mesh,
        attrs,
        tags,
        scheme,
        memory_budget,
        Some(parent),
        None,
        false,
    )
    .map(|(o, r, _)| (o, r.expect("tracked")))
}

#[allow(clippy::too_many_arguments)]
fn refine(
    mesh: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    scheme: PrimalScheme,
    memory_budget: u64,
    order: Option<Option<&RingOrder>>,
    known_topology: Option<Topology>,
    derive_child_topology: bool,
) -> Result<(PrimalOutput, Option<RingOrder>, Option<Topology>), PrimalError> {
    let start = Instant::now();
    let topo = match known_topology {
        Some(t) => t,
        None => {
            let t = Topology::build(mesh)?;
            t.require_single_fans(mesh)?;
            t
        }
    };
    check_faces(mesh, scheme)?;
    let (needed, faces) = estimated_bytes(mesh, topo.num_edges(), scheme);
    OverBudget::check(needed, memory_budget, faces)?;
    let natural;
    let order: Option<&RingOrder> = match order {
        Some(Some(o)) => Some(o),
        Some(None) => {
            natural = RingOrder::natural(&topo);
            Some(&natural)
        }
        None => None,
    };
    let ring_start = |v: usize| order.map_or(topo.vert_corner[v], |o| o.ring_start[v]);
    let sh = sharpness(mesh, &topo, attrs, tags);
    let method = tags.crease_method;
    let chaikin = method == CreaseMethod::Chaikin;
    let sums = if chaikin {
        semi_sums(mesh, &topo, &sh, &ring_start)
    } else {
        Vec::new()
    };
    // Child sharpness of edge `e` at its end vertex `v`.
    let child_edge = |e: usize, v: usize| -> f32 {
        let s = sh.edge[e];
        if chaikin {
            let (sum, count, edges) = sums[v];
            crease::child_edge_sharpness(method, s, edges as usize, sum, count)
        } else {
            crease::decrement(s)
        }
    };

    let nv = mesh.num_vertices();
    let ne = topo.num_edges();
    let nf = mesh.num_faces();
    let p = &mesh.positions;
    let cv = &mesh.corner_verts;
    let cc = scheme.family() == PrimalScheme::CatmullClark;
    let n_child_verts = nv + ne + if cc { nf } else { 0 };
    let mut out = vec![DVec3::ZERO; n_child_verts];
    let parallel = nf >= PARALLEL_FACES && rayon::current_num_threads() > 1;

    // Face points.
    fill(&mut out[nv + ne..], parallel, |f| {
        let r = mesh.face_corners(f);
        let n = r.len() as f64;
        let s: DVec3 = cv[r].iter().map(|&v| p[v as usize]).sum();
        s / n
    });
    let face_size = |f: u32| mesh.face_corners(f as usize).len();

    // Edge points.
    let (head, face_pts) = out.split_at_mut(nv + ne);
    let face_pts: &[DVec3] = face_pts;
    fill(&mut head[nv..], parallel, |e| {
        let c = topo.edge_corner[e] as usize;
        let t = topo.twin[c];
        let (a, b) = (cv[c] as usize, cv[topo.next[c] as usize] as usize);
        let s = sh.edge[e];
        let crease_pt = 0.5 * (p[a] + p[b]);
        if t == NONE {
            return crease_pt;
        }
        let t = t as usize;
        let (f0, f1) = (topo.corner_face[c], topo.corner_face[t]);
        // Smooth mask as vertex weight, face weight and the two face terms.
        let (vw, fw, fsum) = if cc {
            let (vw, fw) =
                masks::catmark_edge_weights(tags.triangles, face_size(f0), face_size(f1));
            (vw, fw, face_pts[f0 as usize] + face_pts[f1 as usize])
        } else {
            let o0 = cv[topo.prev[c] as usize] as usize;
            let o1 = cv[topo.prev[t] as usize] as usize;
            (0.375, 0.125, p[o0] + p[o1])
        };
        if !is_sharp(s) {
            return vw * (p[a] + p[b]) + fw * fsum;
        }
        // The child vertex's rule decides (as OpenSubdiv's refiner passes it): a crease
        // when both child edges stay sharp, else the blend with the parent's sharpness as
        // the weight.
        if is_sharp(child_edge(e, a)) && is_sharp(child_edge(e, b)) {
            crease_pt
        } else {
            let pw = s as f64;
            let cw = 1.0 - pw;
            (pw * 0.5 + cw * vw) * (p[a] + p[b]) + cw * fw * fsum
        }
    });

    // Vertex points. A smooth vertex (always interior: boundary vertices are creases or
    // corners) needs the sums of its neighbours and of its face points. On one thread they
    // are accumulated in one streaming pass over the corners; on several, each vertex
    // gathers them around its ring.
    let scattered = (!parallel).then(|| {
        let mut esum = vec![DVec3::ZERO; nv];
        let mut fsum = vec![DVec3::ZERO; if cc { nv } else { 0 }];
        let mut count = vec![0u32; nv];
        for c in 0..mesh.num_corners() {
            let v = cv[c] as usize;
            esum[v] += p[cv[topo.next[c] as usize] as usize];
            if cc {
                fsum[v] += face_pts[topo.corner_face[c] as usize];
            }
            count[v] += 1;
        }
        (esum, fsum, count)
    });
    let smooth_point = |v: usize| -> DVec3 {
        let (esum, fsum, n) = match &scattered {
            Some((e, f, n)) => (e[v], if cc { f[v] } else { DVec3::ZERO }, n[v] as usize),
            None => {
                let start = topo.vert_corner[v];
                let (mut esum, mut fsum, mut n) = (DVec3::ZERO, DVec3::ZERO, 0usize);
                let mut c = start;
                loop {
                    esum += p[cv[topo.next[c as usize] as usize] as usize];
                    if cc {
                        fsum += face_pts[topo.corner_face[c as usize] as usize];
                    }
                    n += 1;
                    c = topo.ring_next(c);
                    if c == start || c == NONE {
                        break;
                    }
                }
                (esum, fsum, n)
            }
        };
        if cc {
            masks::catmark_vertex(p[v], esum, fsum, n)
        } else {
            let (vw, ew) = masks::loop_vertex_weights(n);
            vw * p[v] + ew * esum
        }
    };
    fill(&mut head[..nv], parallel, |v| {
        if topo.vert_corner[v] == NONE {
            return p[v];
        }
        let p_rule = vertex_rule(sh.vert[v], sh.sharp_edges[v] as usize);
        if matches!(p_rule, Rule::Smooth | Rule::Dart) {
            return smooth_point(v);
        }
        sharp_vertex_point(
            mesh,
            &topo,
            &sh,
            method,
            v,
            ring_start(v),
            p_rule,
            scheme.circle_creases(),
            &smooth_point,
        )
    });
    drop(scattered);

    // Faces.
    let mut child = PolyMesh::new();
    let mut child_hole = Vec::new();
    if cc {
        let nc = mesh.num_corners();
        child.corner_verts.reserve(4 * nc);
        child.loop_starts = (0..=nc as u32).map(|i| 4 * i).collect();
        child.face_starts = (0..=nc as u32).collect();
        for c in 0..nc {
            let f = topo.corner_face[c];
            child.corner_verts.extend_from_slice(&[
                cv[c],
                (nv as u32) + topo.corner_edge[c],
                (nv + ne) as u32 + f,
                (nv as u32) + topo.corner_edge[topo.prev[c] as usize],
            ]);
            if sh.hole[f as usize] {
                child_hole.push(c as u32);
            }
        }
    } else {
        child.corner_verts.reserve(12 * nf);
        child.loop_starts = (0..=4 * nf as u32).map(|i| 3 * i).collect();
        child.face_starts = (0..=4 * nf as u32).collect();
        for f in 0..nf {
            let c0 = mesh.face_corners(f).start;
            let v = [cv[c0], cv[c0 + 1], cv[c0 + 2]];
            let e = [0, 1, 2].map(|k| nv as u32 + topo.corner_edge[c0 + k]);
            child.corner_verts.extend_from_slice(&[
                v[0], e[0], e[2], v[1], e[1], e[0], v[2], e[2], e[1], e[0], e[1], e[2],
            ]);
            if sh.hole[f] {
                child_hole.extend((0..4).map(|k| (4 * f + k) as u32));
            }
        }
    }
    child.positions = out;

    // Creases and corners one level down.
    let mut child_attrs = EdgeAttrs::new();
    for &(e, a) in &sh.tagged {
        let (va, vb) = topo.edge_verts(mesh, e as usize);
        let mid = (nv + e as usize) as u32;
        for (end, s) in [
            (va, child_edge(e as usize, va as usize)),
            (vb, child_edge(e as usize, vb as usize)),
        ] {
            let attr = EdgeAttr {
                crease: s as f64,
                ..a
            };
            if attr.crease > 0.0 || attr.radius.is_some() {
                child_attrs.insert(EdgeKey::new(end, mid), attr);
            }
        }
    }
    let mut child_tags = SubdivTags {
        boundary: tags.boundary,
        crease_method: tags.crease_method,
        triangles: tags.triangles,
        ..SubdivTags::default()
    };
    for (&v, &s) in &tags.corners {
        let d = crease::decrement((s as f32).max(0.0));
        if (v as usize) < nv && d > 0.0 {
            child_tags.corners.insert(v, d as f64);
        }
    }
    child_tags.holes = child_hole.iter().copied().collect();

    let report = PrimalReport {
        vertices: child.num_vertices(),
        edges: match scheme {
            PrimalScheme::CatmullClark | PrimalScheme::CatmullClarkCircle => {
                2 * ne + mesh.num_corners()
            }
            PrimalScheme::Loop => 2 * ne + 3 * nf,
        },
        faces: child.num_faces(),
        holes: child_tags.holes.len(),
        millis: start.elapsed().as_secs_f64() * 1e3,
    };
    let child_order = order.map(|o| o.child(mesh, &topo, scheme));
    let child_topo =
        derive_child_topology.then(|| child_topology::child_topology(mesh, &topo, scheme));
    Ok((
        PrimalOutput {
            mesh: child,
            edge_attrs: child_attrs,
            tags: child_tags,
            report,
        },
        child_order,
        child_topo,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;

    /// The written-down child topology equals the searched one, on open and closed meshes
    /// of both schemes.
    #[test]
    fn child_topology_equals_the_built_one() {
        let mut open = primitives::torus(6, 5, 3.0, 1.0);
        // Drop the last faces: a boundary.
        open.truncate_faces(open.num_faces() - 4);
        let tri = primitives::fan_triangulated;
        let cases = [
            (primitives::tripod(), PrimalScheme::CatmullClark),
            (open.clone(), PrimalScheme::CatmullClark),
            (tri(&primitives::torus(5, 4, 3.0, 1.0)), PrimalScheme::Loop),
            (tri(&open), PrimalScheme::Loop),
        ];
        for (m, scheme) in cases {
            let topo = Topology::build(&m).unwrap();
            let out = refine_primal(
                &m,
                &EdgeAttrs::new(),
                &SubdivTags::default(),
                scheme,
                u64::MAX,
            )
            .unwrap();
            let built = Topology::build(&out.mesh).unwrap();
            let derived = child_topology::child_topology(&m, &topo, scheme);
            assert_eq!(derived.twin, built.twin, "{scheme:?}");
            assert_eq!(derived.next, built.next);
            assert_eq!(derived.corner_face, built.corner_face);
            assert_eq!(derived.corner_edge, built.corner_edge);
            assert_eq!(derived.edge_corner, built.edge_corner);
            assert_eq!(derived.vert_corner, built.vert_corner, "{scheme:?}");
            // And several levels at once equal level after level.
            let two = refine_primal_levels(
                &m,
                &EdgeAttrs::new(),
                &SubdivTags::default(),
                scheme,
                3,
                u64::MAX,
            )
            .unwrap();
            let mut step = out;
            for _ in 0..2 {
                step = refine_primal(&step.mesh, &step.edge_attrs, &step.tags, scheme, u64::MAX)
                    .unwrap();
            }
            assert_eq!(two.mesh, step.mesh);
        }
    }
}
