//! The primal schemes, Catmull–Clark and Loop, with creases, corners, boundaries and holes,
//! written once: one driver classifies every vertex and edge (smooth, dart, crease, corner,
//! and the blend where a semi-sharp feature runs out) and splits the faces, and only the
//! smooth masks ([`crate::rules::primal`]) and the split ([`crate::refine`]) differ per scheme.
//!
//! Seeds: Loop with discontinuities, seed 001 §2 (crease masks eq. 3–4, limit eq. 5–7);
//! Catmull–Clark, the reference scheme of seeds 000 and 002. Semi-sharp creases follow
//! DeRose, Kass & Truong (1998) as OpenSubdiv implements them, so that results equal
//! OpenSubdiv's (tests/opensubdiv.rs): new vertex = blend of the parent's and the child's
//! rule masks with the fractional weight of [`crease::fractional_weight`].
//!
//! One level is: sharpness (`sharpness.rs`, boundary rules applied) → points (`points.rs`, the
//! masks of [`crate::rules::primal`]) → split ([`crate::refine::quad`] or
//! [`crate::refine::tri`], whose numbering every index here comes from) → attributes (one
//! [`crate::refine::propagate`] for creases and radii; corners decay; holes stay holes: they
//! are refined like any face, as they shape their neighbours).

pub mod limit;
mod points;
pub(crate) mod sharpness;

pub use crate::refine::RingOrder;
pub use limit::{LimitPoints, limit_points, limit_points_ordered};
pub use points::PARALLEL_FACES;

use crate::edge_attrs::{EdgeAttr, EdgeAttrs};
use crate::error::{MeshError, OverBudget};
use crate::mesh::PolyMesh;
use crate::refine::{self, Numbering, PrimalSplit, Provenance};
use crate::rules::primal::crease;
use crate::tags::SubdivTags;
use crate::topology::{Loops, Topology};
use sharpness::ChildSharpness;
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
    /// The split pattern and smooth masks: Catmull–Clark for both of its variants.
    pub fn family(self) -> PrimalScheme {
        match self {
            PrimalScheme::CatmullClarkCircle => PrimalScheme::CatmullClark,
            s => s,
        }
    }

    /// The split that builds its child's faces.
    pub fn split(self) -> PrimalSplit {
        match self.family() {
            PrimalScheme::Loop => PrimalSplit::Tri,
            _ => PrimalSplit::Quad,
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
    #[error(
        "face {face} has {corners} corners: the Catmull–Clark limit masks need quads (refine one level first)"
    )]
    NotQuad { face: u32, corners: usize },
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
    /// Where its vertices, faces and edges come from (not recorded by
    /// [`refine_primal_levels`], whose levels are not kept).
    pub provenance: Option<Provenance>,
    pub report: PrimalReport,
}

/// Refuses faces with holes, and non-triangles under Loop, naming the face.
pub(crate) fn check_faces(mesh: &PolyMesh, scheme: PrimalScheme) -> Result<(), PrimalError> {
    let misfit = |f: usize| {
        mesh.face_has_holes(f) || (scheme == PrimalScheme::Loop && mesh.face_corners(f).len() != 3)
    };
    let Some(f) = crate::parallel::first_where(mesh.num_faces(), misfit) else {
        return Ok(());
    };
    if mesh.face_has_holes(f) {
        return Err(PrimalError::HoledFace {
            face: f as u32,
            scheme: scheme.name(),
        });
    }
    Err(PrimalError::NotTriangle {
        face: f as u32,
        corners: mesh.face_corners(f).len(),
    })
}

/// One level of Catmull–Clark or Loop, with its [`Provenance`].
pub fn refine_primal(
    mesh: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    scheme: PrimalScheme,
    memory_budget: u64,
) -> Result<PrimalOutput, PrimalError> {
    refine_primal_with(mesh, attrs, tags, scheme, memory_budget, true)
}

/// [`refine_primal`], recording the provenance only when asked (the command line, which
/// writes the level and nothing of where its elements came from, saves about a third of the
/// step's memory without it).
pub fn refine_primal_with(
    mesh: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    scheme: PrimalScheme,
    memory_budget: u64,
    provenance: bool,
) -> Result<PrimalOutput, PrimalError> {
    let with = With {
        provenance,
        ..With::default()
    };
    refine_primal_carrying(mesh, attrs, tags, scheme, memory_budget, with).map(|(o, _, _)| o)
}

/// [`refine_primal_with`] with what [`With`] asks besides the child: from the parent's
/// topology when the split before wrote it down, writing the child's down too (the pipeline
/// passes it on from one primal step to the next, as [`refine_primal_levels`] does). Returns
/// the child, the child's topology (when asked for) and the parent's (when `keep_topology`:
/// the app keeps it to move points without looking for the topology again, [`repoint`]).
pub(crate) fn refine_primal_carrying(
    mesh: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    scheme: PrimalScheme,
    memory_budget: u64,
    with: With<'static>,
) -> Result<(PrimalOutput, Option<Topology>, Option<Topology>), PrimalError> {
    refine(mesh, attrs, tags, scheme, memory_budget, with).map(|r| (r.0, r.2, r.3))
}

/// The child's points of `mesh` under `scheme`, from the topology a step of the same
/// connectivity, marks and tags found before (`topo`, [`refine_primal_carrying`]): where a
/// designer drags a cage vertex, each level's faces, marks and topology stay, and only the
/// points are evaluated again (OpenSubdiv's split of Far, the topology, from Osd, the
/// evaluation). The points equal those of a full step bit for bit (tested).
pub(crate) fn repoint(
    mesh: &PolyMesh,
    topo: &Topology,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    scheme: PrimalScheme,
) -> Result<Vec<glam::DVec3>, PrimalError> {
    crate::topology::check_finite(mesh)?;
    let ring_start = |v: usize| topo.vert_corner[v];
    let sh = sharpness::sharpness(mesh, topo, attrs, tags);
    let child_sharpness = ChildSharpness::new(mesh, topo, &sh, tags.crease_method, &ring_start);
    let level = points::Level {
        mesh,
        topo,
        tags,
        sh: &sh,
        child: &child_sharpness,
        ring_start: &ring_start,
    };
    Ok(points::child_points(
        &level,
        scheme,
        scheme.split().numbering(mesh, topo),
    ))
}

/// `levels` levels at once, only the last one kept. From the second level on the topology
/// is not searched for but written down from the split (`refine::quad::topology`), which saves a
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
    let with = |known_topology, k: usize| With {
        known_topology,
        child_topology: k < levels,
        ..With::default()
    };
    let (mut out, _, mut topo, _) =
        refine(mesh, attrs, tags, scheme, memory_budget, with(None, 1))?;
    for k in 2..=levels {
        let (o, _, t, _) = refine(
            &out.mesh,
            &out.edge_attrs,
            &out.tags,
            scheme,
            memory_budget,
            with(topo.take(), k),
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
    let with = With {
        order: Some(parent),
        provenance: true,
        ..With::default()
    };
    refine(mesh, attrs, tags, scheme, memory_budget, with).map(|r| (r.0, r.1.expect("tracked")))
}

/// What a caller of [`refine`] wants besides the child.
#[derive(Default)]
pub(crate) struct With<'a> {
    /// Pass on OpenSubdiv's ring order (`Some(None)`: the parent is an input).
    pub order: Option<Option<&'a RingOrder>>,
    /// The parent's topology when the split already wrote it down.
    pub known_topology: Option<Topology>,
    /// Write down the child's topology too.
    pub child_topology: bool,
    /// Record the child's [`Provenance`].
    pub provenance: bool,
    /// Return the parent's topology.
    pub keep_topology: bool,
}

fn refine(
    mesh: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    scheme: PrimalScheme,
    memory_budget: u64,
    with: With,
) -> Result<Refined, PrimalError> {
    let start = Instant::now();
    let order = with.order;
    let topo = match with.known_topology {
        Some(t) => t,
        None => {
            let t = Topology::build(mesh)?;
            t.require_single_fans(mesh)?;
            t
        }
    };
    // One-loop quads pass Catmull–Clark's check and one-loop triangles either scheme's,
    // as the loops already say.
    let passes = match topo.loops() {
        Loops::Triangles => true,
        Loops::Quads => scheme.family() == PrimalScheme::CatmullClark,
        Loops::Listed(_) => false,
    };
    if !passes {
        check_faces(mesh, scheme)?;
    }
    let split = scheme.split();
    // The child's sizes: a step that would not fit is refused before any work.
    let counts = split.counts(mesh, topo.num_edges());
    OverBudget::check(counts.bytes(), memory_budget, counts.faces)?;
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

    // Sharpness, then points.
    let sh = sharpness::sharpness(mesh, &topo, attrs, tags);
    let child_sharpness = ChildSharpness::new(mesh, &topo, &sh, tags.crease_method, &ring_start);
    let numbering = split.numbering(mesh, &topo);
    let level = points::Level {
        mesh,
        topo: &topo,
        tags,
        sh: &sh,
        child: &child_sharpness,
        ring_start: &ring_start,
    };
    let positions = points::child_points(&level, scheme, numbering);

    // Split.
    let mut child = split.faces(mesh, &topo, numbering);
    child.positions = positions;

    // Creases, corners and holes one level down.
    let child_attrs = refine::propagate(
        mesh,
        &topo,
        attrs,
        Numbering::Primal(numbering),
        |e, a, end| {
            let end = end.expect("a primal child edge is half of its parent");
            let crease = child_sharpness.edge(e as usize, end as usize) as f64;
            let child = EdgeAttr { crease, ..*a };
            (!child.is_empty()).then_some(child)
        },
    );
    let mut child_tags = SubdivTags {
        boundary: tags.boundary,
        crease_method: tags.crease_method,
        triangles: tags.triangles,
        ..SubdivTags::default()
    };
    for (&v, &s) in &tags.corners {
        let d = crease::decrement((s as f32).max(0.0));
        if (v as usize) < mesh.num_vertices() && d > 0.0 {
            child_tags.corners.insert(numbering.vertex(v), d as f64);
        }
    }
    // Only a parent with holes has child faces to look for (a pass over every child face).
    if sh.any_hole() {
        let face_parent = split.face_parent(mesh, &topo);
        child_tags.holes = (0..face_parent.len() as u32)
            .filter(|&f| sh.hole(face_parent[f as usize] as usize))
            .collect();
    }

    let report = PrimalReport {
        vertices: child.num_vertices(),
        edges: counts.edges as usize,
        faces: child.num_faces(),
        holes: child_tags.holes.len(),
        millis: start.elapsed().as_secs_f64() * 1e3,
    };
    let child_order = order.map(|o| o.child(mesh, &topo, scheme.split()));
    let child_topo = with.child_topology.then(|| split.topology(mesh, &topo));
    let keep = with.keep_topology;
    let provenance = with.provenance.then(|| {
        Provenance::new(
            mesh,
            &topo,
            Numbering::Primal(numbering),
            Vec::new(),
            split.face_parent(mesh, &topo),
        )
    });
    Ok((
        PrimalOutput {
            mesh: child,
            edge_attrs: child_attrs,
            tags: child_tags,
            provenance,
            report,
        },
        child_order,
        child_topo,
        keep.then_some(topo),
    ))
}

/// What [`refine`] gives: the child, OpenSubdiv's ring order of the child (when tracked),
/// the child's topology (when written down) and the parent's (when kept).
type Refined = (
    PrimalOutput,
    Option<RingOrder>,
    Option<Topology>,
    Option<Topology>,
);

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
            let plain = |levels| {
                let (attrs, tags) = (EdgeAttrs::new(), SubdivTags::default());
                refine_primal_levels(&m, &attrs, &tags, scheme, levels, u64::MAX).unwrap()
            };
            let out = plain(1);
            let built = Topology::build(&out.mesh).unwrap();
            let derived = scheme.split().topology(&m, &topo);
            assert_eq!(derived.twin, built.twin, "{scheme:?}");
            assert!(derived.loops().same(built.loops(), built.num_corners()));
            assert_eq!(derived.corner_edge, built.corner_edge);
            assert_eq!(derived.edge_corner, built.edge_corner);
            assert_eq!(derived.vert_corner, built.vert_corner, "{scheme:?}");
            // And several levels at once equal level after level.
            let two = plain(3);
            let mut step = out;
            for _ in 0..2 {
                step = refine_primal(&step.mesh, &step.edge_attrs, &step.tags, scheme, u64::MAX)
                    .unwrap();
            }
            assert_eq!(two.mesh, step.mesh);
        }
    }
}
