//! One biquadratic step with a corner rule, from a mesh to the next level, with everything a
//! user needs to see: counts, flipped and degenerate faces, time (docs/algorithms/biquadratic.md).
//!
//! The generic driver: validate the rule's parameter; let the rule prepare the level
//! ([`CornerRule::prepare`]: closed topology and normals for every rule, flat-edge merge and
//! cut widths for the cylindrical family, the combination run's state); refuse a step that
//! would not fit; place the corner points; split ([`dual_quad`]); hand down edge attributes
//! ([`refine::propagate`]) and the combination state; check and report.
//!
//! A new face is **flipped** when its Newell normal points against its parent element's
//! normal (`n_f`, `n_L + n_R`, or Σ n_f around the vertex) and **degenerate** when its area is
//! within rounding noise, so that which way it faces cannot be told: twice the area below
//! `DEGENERATE_NOISE · P · S` (P the face's perimeter, S the larger of the bounding-box
//! diagonal and the largest coordinate). Neither is hidden: both are listed.

use crate::dissolve::DissolveError;
use crate::edge_attrs::EdgeAttrs;
use crate::error::{MeshError, OverBudget};
use crate::geometry::{face_normal_and_volume6, loop_newell};
use crate::mesh::PolyMesh;
use crate::refine::{self, FaceKind, Numbering, Provenance, dual_quad};
use crate::rules::{self, CombinationState, CornerRule, ParamError, RuleError};
use crate::topology::Topology;
use glam::DVec3;
use std::borrow::Cow;
use std::time::Instant;
use thiserror::Error;

mod crossings;
use crossings::{concave_vertex_crossings, guard_crossings, guarded_faces, self_crossing_faces};

/// A face is degenerate when twice its area is below this × its perimeter × the level's
/// scale S (the larger of the bounding-box diagonal and the largest coordinate): a thousand
/// times the rounding error of a Newell normal, whose terms each carry an error of about
/// ε·S·(the edge's length). Below it, which way the face faces cannot be told; above it, a
/// face is sound however small (a round of a nearly flat edge is a face 10⁻⁸ of the solid
/// across, facing the right way).
pub const DEGENERATE_NOISE: f64 = 1e3 * f64::EPSILON;

/// Tunables of a step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepOptions {
    /// Edges with |bend angle| below this (radians) are flat and dissolved before a
    /// cylindrical-family step.
    pub flat_tolerance: f64,
    /// A step whose result would need more bytes than this is refused before it starts.
    pub memory_budget: u64,
    /// What a cylindrical-family step does with radii whose rounds do not fit their faces.
    pub overlap: rules::Overlap,
    /// Whether a step whose last resorts run (the combination rule; the minimum type and the
    /// chamfers when clamping) also searches its whole level for faces that pass through
    /// each other and lets them seed the small chamfers (`rules::retreat`): about ten times
    /// the step's time, so off by default.
    pub mend_crossings: bool,
}

impl Default for StepOptions {
    fn default() -> Self {
        StepOptions {
            flat_tolerance: 1e-6,
            memory_budget: 8 << 30,
            overlap: rules::Overlap::Refuse,
            mend_crossings: false,
        }
    }
}

#[derive(Debug, Clone, PartialEq, Error)]
pub enum StepError {
    #[error(transparent)]
    Mesh(#[from] MeshError),
    #[error(transparent)]
    Param(#[from] ParamError),
    #[error(transparent)]
    Rule(#[from] RuleError),
    #[error(transparent)]
    Dissolve(#[from] DissolveError),
    #[error(transparent)]
    Primal(#[from] crate::primal::PrimalError),
    #[error(transparent)]
    TooLarge(#[from] OverBudget),
    /// The step turned a solid of positive volume inside out: its faces point inwards
    /// (the pipeline keeps the level, so that it can be looked at, and stops there).
    #[error(
        "the solid has turned inside out (signed volume {before:.4e} before the step, {after:.4e} after): {flipped} face(s) flipped; lower the radius or parameter, or clamp"
    )]
    InsideOut {
        before: f64,
        after: f64,
        flipped: usize,
    },
}

/// What a step did, for the summary line, the status bar and the tests.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StepReport {
    pub vertices: usize,
    pub edges: usize,
    pub faces: usize,
    /// Indices of the flipped new faces.
    pub flipped: Vec<u32>,
    /// Indices of the new faces of (almost) no area.
    pub degenerate: Vec<u32>,
    /// Flat edges dissolved before the step.
    pub dissolved_edges: usize,
    /// Straight corners whose along-edge shift was capped (simple cylindrical type).
    pub guarded_corners: usize,
    /// Edges whose radius was lowered to fit their faces (clamping; input numbering).
    pub clamped: Vec<rules::EdgeFit>,
    /// Edges whose cut width the combination rule lowered so its cut faces keep their edges.
    pub capped_edges: usize,
    /// Faces whose chamfer distance or width (l, d) the clamp lowered.
    pub clamped_faces: usize,
    /// Concave faces whose Doo–Sabin points the clamp took from the width offset, where eq. (1)
    /// would turn a strip over (docs/algorithms/biquadratic.md, "Concave faces").
    pub offset_faces: usize,
    /// Corners with a zero-length edge that stayed at their vertex.
    pub collapsed_corners: usize,
    /// Faces the combination rule moved into the vertex blend because their cut points
    /// would have folded a new face ([`rules::fold_guard`]).
    pub unfolded_faces: usize,
    /// Blend faces that the combination rule re-placed (Doo–Sabin's width offset, or their
    /// points drawn towards their corners) because a new face beside them still folded
    /// ([`rules::fold_guard`]).
    pub reoffset_faces: usize,
    /// What the combination rule's last resort did ([`rules::untangle`]): points of new
    /// faces still flipped after the fold guard, smoothed until none is, and how far.
    pub untangled: rules::Untangled,
    /// Parent vertices where the final resort gave up the rounding (or, clamped, the minimum
    /// type's or a chamfer's points) for a small chamfer because a new face round them was
    /// still flipped, passed through another or crossed itself ([`rules::retreat`]).
    pub small_chamfers: usize,
    /// Signed volume of the result (negative: inside out).
    pub volume: f64,
    /// Wall time of the step in milliseconds.
    pub millis: f64,
}

/// The next level.
#[derive(Debug, Clone)]
pub struct StepOutput {
    pub mesh: PolyMesh,
    pub provenance: Provenance,
    pub edge_attrs: EdgeAttrs,
    /// The combination run's state after this step (combination rule only).
    pub combination: Option<CombinationState>,
    /// The parent after the flat-edge dissolve, when that changed it (provenance refers
    /// to it).
    pub dissolved_parent: Option<PolyMesh>,
    pub report: StepReport,
}

/// One biquadratic step of `mesh` with `rule`. `state` is the combination state of `mesh`
/// when the step before was a combination step (only a combination rule reads it).
pub fn biquadratic_step(
    mesh: &PolyMesh,
    attrs: &EdgeAttrs,
    rule: &CornerRule,
    state: Option<&CombinationState>,
    options: &StepOptions,
) -> Result<StepOutput, StepError> {
    biquadratic_step_carrying(mesh, attrs, rule, state, options, None, false).map(|(o, _)| o)
}

/// [`biquadratic_step`] that takes `mesh`'s topology when the split before wrote it down
/// (`known`) and, when `child_topology`, writes the child's down for the next step
/// ([`dual_quad::topology`], from the level the points were placed on: the merged one when
/// flat edges were merged, whose split the child is).
pub fn biquadratic_step_carrying(
    mesh: &PolyMesh,
    attrs: &EdgeAttrs,
    rule: &CornerRule,
    state: Option<&CombinationState>,
    options: &StepOptions,
    known: Option<Topology>,
    child_topology: bool,
) -> Result<(StepOutput, Option<Topology>), StepError> {
    let start = Instant::now();
    rule.validate()?;
    let prep = rule.prepare(mesh, attrs, state, options, known)?;
    let (cur, topo) = (prep.mesh.as_ref(), &prep.topo);
    OverBudget::check(
        dual_quad::estimated_bytes(cur, topo.num_edges()),
        options.memory_budget,
        (cur.num_faces() + topo.num_edges() + cur.num_vertices()) as u64,
    )?;
    let (mut points, rule_report) = rules::corner_points(rule, &prep.input())?;
    let is_combination = matches!(rule, CornerRule::Combination { .. });
    // The combination rule's fold guard, on the points before the split (the child's vertex c
    // is the parent's corner c): faces whose cut points would fold a new face move into the
    // blend, then the blend's faces beside a fold the guard still sees are re-placed — on
    // every combination step, since a bow-tie lying in a plane is not flipped by the report's
    // test, and its children are (rules::fold_guard).
    let (unfolded, reoffset_faces) = if is_combination {
        rules::fold_guard(
            cur,
            topo,
            &prep.normals,
            prep.input().vertex_neighbourhood,
            &mut points,
        )
    } else {
        (Vec::new(), 0)
    };
    let (mut out, prov) = dual_quad::split(cur, topo, points);
    let new_attrs = refine::propagate(
        cur,
        topo,
        &prep.edge_attrs,
        Numbering::DualQuad,
        |_, a, _| Some(*a),
    );
    let combination = is_combination
        .then(|| CombinationState::next(cur, topo, &prov, prep.combination.as_deref(), &unfolded));
    let recheck = |m: &PolyMesh| check_children(cur, topo, &prep.normals, m, &prov);
    let mut checked = recheck(&out);
    // The combination rule's last resorts, only where a new face is still flipped, all in
    // place: the points are smoothed (rules::untangle), then the vertices round what is left
    // take small chamfers (rules::retreat).
    let mut untangled = rules::Untangled::default();
    // The minimum type and the chamfers, when clamping asks for a sound solid, take the
    // last two resorts too.
    let resorts = rule.takes_resorts(options.overlap.clamps());
    if resorts && !checked.flipped.is_empty() {
        let corners: Vec<u32> = checked
            .flipped
            .iter()
            .flat_map(|&f| out.face_corners(f as usize).map(|c| out.corner_verts[c]))
            .collect();
        untangled = rules::untangle(cur, topo, &prep.normals, &mut out.positions, corners);
        if untangled.points > 0 {
            checked = recheck(&out);
        }
    }
    let mut small_chamfers = 0;
    // New faces round the guard's moves — the faces it unfolded and those beside the edges it
    // cut narrower — that pass through others though none is flipped: they seed the small
    // chamfers as flipped ones do.
    let guarded = guarded_faces(topo, &unfolded, &prep.capped_edges);
    let crossing_seeds = if is_combination && checked.flipped.is_empty() && !guarded.is_empty() {
        guard_crossings(cur, topo, &out, &prov, &guarded)
    } else {
        Vec::new()
    };
    let retreat = |out: &mut PolyMesh, checked: &mut ChildCheck, seeds: &[u32]| {
        // The resort's own last check is the step's when it keeps its points.
        let mut last = None;
        let n = rules::retreat(
            cur,
            topo,
            &prep.normals,
            out,
            (seeds, checked.degenerate.len()),
            |m| {
                let c = recheck(m);
                let seen = (c.flipped.clone(), c.degenerate.len());
                last = Some(c);
                seen
            },
        );
        if n > 0 {
            *checked = last.expect("the resort checks the points it keeps");
        }
        n
    };
    if resorts && !checked.flipped.is_empty() {
        let seeds = checked.flipped.clone();
        small_chamfers += retreat(&mut out, &mut checked, &seeds);
    } else if resorts && !crossing_seeds.is_empty() {
        small_chamfers += retreat(&mut out, &mut checked, &crossing_seeds);
    }
    // Where the guard acted, VERTEX-faces at parent vertices with a concave edge that pass
    // through a face round them seed them too (docs/algorithms/cylindrical.md, "Crossings at
    // concave vertices").
    if is_combination && checked.flipped.is_empty() && !guarded.is_empty() {
        let seeds = concave_vertex_crossings(cur, topo, &prep.normals, &out, &prov);
        if !seeds.is_empty() {
            small_chamfers += retreat(&mut out, &mut checked, &seeds);
        }
    }
    // The minimum type and the chamfers: new faces that cross themselves seed them too.
    if resorts && !is_combination && checked.flipped.is_empty() {
        let seeds = self_crossing_faces(&out);
        if !seeds.is_empty() {
            small_chamfers += retreat(&mut out, &mut checked, &seeds);
        }
    }
    // Asked for, crossings left anywhere on the level seed them too (the whole level
    // searched: about ten times the step; docs/algorithms/cylindrical.md, "Mending every
    // crossing").
    if options.mend_crossings && resorts && checked.flipped.is_empty() {
        let seeds = crate::analysis::crossing_faces(&crate::analysis::crossings(&out));
        if !seeds.is_empty() {
            small_chamfers += retreat(&mut out, &mut checked, &seeds);
        }
    }
    let report = StepReport {
        vertices: out.num_vertices(),
        edges: 4 * topo.num_edges(),
        faces: out.num_faces(),
        flipped: checked.flipped,
        degenerate: checked.degenerate,
        dissolved_edges: prep.dissolved_edges,
        guarded_corners: rule_report.guarded_corners,
        clamped: prep.clamped.clone(),
        capped_edges: prep.capped_edges.len(),
        clamped_faces: prep.clamped_faces,
        offset_faces: prep.offset_faces,
        collapsed_corners: rule_report.collapsed_corners,
        unfolded_faces: unfolded.len(),
        reoffset_faces,
        untangled,
        small_chamfers,
        volume: checked.volume,
        millis: start.elapsed().as_secs_f64() * 1e3,
    };
    let child_topo = child_topology.then(|| dual_quad::topology(cur, topo));
    let dissolved_parent = match prep.mesh {
        Cow::Owned(m) => Some(m),
        Cow::Borrowed(_) => None,
    };
    let output = StepOutput {
        mesh: out,
        provenance: prov,
        edge_attrs: new_attrs,
        combination,
        dissolved_parent,
        report,
    };
    Ok((output, child_topo))
}

/// Flipped and degenerate new faces, and the signed volume of the child: one pass over the
/// child's faces.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ChildCheck {
    pub flipped: Vec<u32>,
    pub degenerate: Vec<u32>,
    pub volume: f64,
}

/// Checks every new face against its parent element's normal (docs/algorithms/biquadratic.md) and sums
/// the child's signed volume.
pub fn check_children(
    parent: &PolyMesh,
    topo: &Topology,
    parent_normals: &[DVec3],
    child: &PolyMesh,
    prov: &Provenance,
) -> ChildCheck {
    use rayon::prelude::*;
    let vsum = crate::geometry::vertex_normal_sums(parent, topo, parent_normals);
    let s = scale(child);
    let single_loop = child.num_loops() == child.num_faces();
    let nf = child.num_faces();
    // Blocks of faces on every core, each summing its share of the volume in face order;
    // the blocks' sums are added in block order, so the volume is the same bits on any
    // number of threads.
    let blocks: Vec<ChildCheck> = (0..nf.div_ceil(CHECK_BLOCK))
        .into_par_iter()
        .map(|b| {
            let mut out = ChildCheck::default();
            for f in b * CHECK_BLOCK..((b + 1) * CHECK_BLOCK).min(nf) {
                let (n, fv) = if single_loop {
                    // Hole-free child (the usual case): the loop is the face.
                    let vs = child.loop_verts(f);
                    let n = loop_newell(child, vs);
                    (n, 2.0 * child.positions[vs[0] as usize].dot(n))
                } else {
                    face_normal_and_volume6(child, f)
                };
                out.volume += fv;
                let p = prov.face_parent[f] as usize;
                let np = match prov.face_kind[f] {
                    FaceKind::Face => parent_normals[p],
                    FaceKind::Edge => {
                        let [a, b] = topo.edge_faces(p);
                        parent_normals[a as usize] + parent_normals[b as usize]
                    }
                    FaceKind::Vertex => vsum[p],
                };
                if is_degenerate(child, f, n, s) {
                    out.degenerate.push(f as u32);
                } else if n.dot(np) < 0.0 {
                    out.flipped.push(f as u32);
                }
            }
            out
        })
        .collect();
    let mut out = ChildCheck::default();
    let mut v6 = 0.0;
    for b in blocks {
        out.flipped.extend(b.flipped);
        out.degenerate.extend(b.degenerate);
        v6 += b.volume;
    }
    out.volume = v6 / 6.0;
    out
}

/// The new faces of a Catmull–Clark or Loop step that the step turned over
/// (docs/algorithms/biquadratic.md, "Faces a smoothing step turns over"): a face that faces
/// against its parent face (child quad c of the quad split lies in the face of parent corner
/// c, child triangle 4f + k in triangle f) *and* against the sum of the normals round one of
/// its own vertices — a pleat in the child, not just a thin parent face whose children follow
/// their neighbours (a 0.004-wide strip on OpenSubdiv's car turns 94° from its children, and
/// the surface there is smooth). Neither scheme folds a convex face, but the face point of a
/// concave face (its vertex centroid) can lie outside it, and a vertex point at a reflex
/// corner can move farther than a thin face beside it is wide: the quads there turn over —
/// the scheme as printed, which the step reports rather than mends. Faces of no area
/// ([`is_degenerate`]) are not counted; a child whose face count does not match the split's
/// is not judged (empty).
pub fn primal_flipped(parent: &PolyMesh, child: &PolyMesh, split: refine::PrimalSplit) -> Vec<u32> {
    use rayon::prelude::*;
    let expected = match split {
        refine::PrimalSplit::Quad => parent.num_corners(),
        refine::PrimalSplit::Tri => 4 * parent.num_faces(),
    };
    if child.num_faces() != expected {
        return Vec::new();
    }
    let s = scale(child);
    // Against the parent face, each parent face's children at once (in face order: rayon's
    // collect keeps it); few are, so the child's vertex normal sums are found only when
    // some are.
    let against: Vec<usize> = (0..parent.num_faces())
        .into_par_iter()
        .with_min_len(1024)
        .flat_map_iter(|f| {
            let np = crate::geometry::face_normal_raw(parent, f);
            let children = match split {
                refine::PrimalSplit::Quad => parent.face_corners(f),
                refine::PrimalSplit::Tri => 4 * f..4 * f + 4,
            };
            children.filter(move |&c| {
                let n = crate::geometry::face_normal_raw(child, c);
                n.dot(np) < 0.0 && !is_degenerate(child, c, n, s)
            })
        })
        .collect();
    if against.is_empty() {
        return Vec::new();
    }
    let normals = crate::geometry::face_normals_raw(child);
    let mut vsum = vec![DVec3::ZERO; child.num_vertices()];
    for (f, n) in normals.iter().enumerate() {
        let u = n.normalize_or_zero();
        for c in child.face_corners(f) {
            vsum[child.corner_verts[c] as usize] += u;
        }
    }
    against
        .into_iter()
        .filter(|&f| {
            child
                .face_corners(f)
                .any(|c| normals[f].dot(vsum[child.corner_verts[c] as usize]) < 0.0)
        })
        .map(|f| f as u32)
        .collect()
}

/// The level's scale S of [`DEGENERATE_NOISE`]: the larger of the bounding-box diagonal and
/// the largest coordinate's magnitude.
pub fn scale(mesh: &PolyMesh) -> f64 {
    if mesh.positions.is_empty() {
        return 0.0;
    }
    let (lo, hi) = mesh.bbox();
    (hi - lo).length().max(lo.abs().max(hi.abs()).max_element())
}

/// Whether face `f` of Newell normal `n` (twice its area) is degenerate on a level of
/// [`scale`] `s`: below [`DEGENERATE_NOISE`] × its perimeter × `s`. The perimeter is summed
/// only for faces that could be (it is at most the face's corner count × `s`).
pub fn is_degenerate(mesh: &PolyMesh, f: usize, n: DVec3, s: f64) -> bool {
    let a2 = n.length();
    let tiny = DEGENERATE_NOISE * s;
    if a2 >= tiny * s * mesh.face_corners(f).len() as f64 {
        return false;
    }
    let perimeter = crate::geometry::face_perimeter(mesh, f);
    // A face collapsed to a point (no perimeter either) and a NaN one are degenerate.
    a2.is_nan() || a2 <= tiny * perimeter
}

/// Faces a task of [`check_children`] takes (fixed, so that the volume's sum does not
/// depend on the number of threads).
const CHECK_BLOCK: usize = 1 << 12;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;

    /// Degenerate means "which way it faces cannot be told", not "small": a well-shaped square
    /// 10⁻⁸ of the solid across, far from the origin, is not degenerate; a square 10⁻¹⁵
    /// across, a sliver 10⁻¹⁴ wide, a face collapsed to a point and one with a NaN are.
    #[test]
    fn degenerate_faces_are_those_of_no_area_not_small_ones() {
        let at = DVec3::new(10.0, -5.0, 3.0);
        let square = |side: f64, width: f64| {
            let q = [
                DVec3::ZERO,
                DVec3::new(side, 0.0, 0.0),
                DVec3::new(side, width, 0.0),
                DVec3::new(0.0, width, 0.0),
            ];
            // A unit box beside it sets the scale.
            let mut m = primitives::cuboid(at - DVec3::ONE, at);
            let base = m.num_vertices() as u32;
            m.positions.extend(q.iter().map(|p| at + *p));
            m.push_polygon(&[base, base + 1, base + 2, base + 3]);
            let f = m.num_faces() - 1;
            let n = loop_newell(&m, m.loop_verts(f));
            is_degenerate(&m, f, n, scale(&m))
        };
        assert!(!square(1e-8, 1e-8));
        assert!(!square(1.0, 1e-9));
        assert!(square(1e-15, 1e-15));
        assert!(square(1.0, 1e-14));
        assert!(square(0.0, 0.0));
        assert!(square(f64::NAN, 1.0));
        // A unit face of the box is not.
        let m = primitives::cuboid(DVec3::ZERO, DVec3::ONE);
        assert!(!is_degenerate(
            &m,
            0,
            loop_newell(&m, m.loop_verts(0)),
            scale(&m)
        ));
    }

    /// Every biquadratic rule gives the same child, provenance and report (flipped and
    /// degenerate faces, the volume to the last bit, the radii lowered where rounds would
    /// overlap) on one thread as on three, on meshes cut into many chunks; the first face a
    /// rule refuses is named the same way.
    #[test]
    fn a_step_is_the_same_on_any_number_of_threads() {
        let torus = primitives::torus(150, 100, 3.0, 1.0);
        let tripods = primitives::union_disjoint(&[
            primitives::tripod(),
            torus.clone(),
            primitives::tripod(),
        ]);
        let clamp = StepOptions {
            overlap: rules::Overlap::Clamp,
            ..StepOptions::default()
        };
        let on = |threads: usize, m: &PolyMesh, rule: CornerRule| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            pool.install(|| biquadratic_step(m, &EdgeAttrs::new(), &rule, None, &clamp))
        };
        for (m, rule) in [
            (&torus, CornerRule::DooSabin),
            (&tripods, CornerRule::DooSabin),
            (&tripods, CornerRule::CutWidth { d: 0.05 }),
            (
                &tripods,
                CornerRule::VectorSum {
                    alpha: 0.2,
                    reflex: crate::rules::ReflexMode::Inward,
                },
            ),
            (&tripods, CornerRule::Combination { r: 0.1 }),
            // Radii too large for the tripods' arms: lowered where the rounds would overlap.
            (&tripods, CornerRule::Combination { r: 0.9 }),
        ] {
            let (a, b) = (on(1, m, rule).unwrap(), on(3, m, rule).unwrap());
            assert_eq!(a.mesh, b.mesh, "{rule:?}");
            assert_eq!(a.provenance, b.provenance, "{rule:?}");
            let same = |r: &StepReport| StepReport {
                millis: 0.0,
                ..r.clone()
            };
            assert_eq!(same(&a.report), same(&b.report), "{rule:?}");
            assert_eq!(a.report.volume.to_bits(), b.report.volume.to_bits());
            if rule == (CornerRule::Combination { r: 0.9 }) {
                assert!(!a.report.clamped.is_empty());
            }
        }
        // Doo–Sabin refuses faces with holes: the first one is named.
        let holed = primitives::union_disjoint(&[
            torus.clone(),
            primitives::holed_block(),
            torus.clone(),
            primitives::holed_block(),
        ]);
        for threads in [1, 3] {
            match on(threads, &holed, CornerRule::DooSabin) {
                Err(StepError::Rule(RuleError::HoledFace { face })) => {
                    assert!(holed.face_has_holes(face as usize));
                    assert!((0..face as usize).all(|f| !holed.face_has_holes(f)));
                }
                other => panic!("{threads} threads: {:?}", other.map(|_| ())),
            }
        }
    }
}
