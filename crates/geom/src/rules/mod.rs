//! PRISM corner rules: where the new point of each face corner goes (docs/algorithms/: biquadratic.md, chamfers.md, cylindrical.md).
//!
//! PRISM's biquadratic step is CGAL's DQQ (dual quad quadrisection) with a *corner mask*:
//! every rule here maps one face corner to one new point, and [`crate::refine::dual_quad`]
//! builds the FACE-, EDGE- and VERTEX-faces from those points, the same for every rule. A
//! rule first prepares the level ([`CornerRule::prepare`]: the cylindrical family merges flat
//! faces and computes cut widths; the combination rule continues its [`CombinationState`]).
//!
//! | rule | formula | paper |
//! | --- | --- | --- |
//! | [`CornerRule::DooSabin`] | `V_i' = Σ_j W_ij V_j`, `W_ii = (n+5)/4n`, `W_ij = (3 + 2cos(2π(i−j)/n))/4n` | seed 000 eq. (1) |
//! | [`CornerRule::AngleBisector`] | `V' = V + l·unit(m₁ + m₂)` | §3.1(1), fig. 3 |
//! | [`CornerRule::CutWidth`] | `V' = V + d(m₁ + m₂)/(1 + c)` | §3.1(2), fig. 4 |
//! | [`CornerRule::VectorSum`] | `V' = V + α(V₊ − V) + α(V₋ − V)` | eq. (2) |
//! | [`CornerRule::Cylindrical`] | two-width corner at the cut widths `x = r·tan(ψ/4)/cos(ψ/2)` | eq. (3), (4) |
//! | [`CornerRule::Minimum`] | eq. (4) with each displacement capped at ¼ of its edge | eq. (5) |
//! | [`CornerRule::Combination`] | Doo–Sabin on vertex-neighbourhood faces, cylindrical elsewhere | §3.2(3) |
//!
//! Notation (§0.3): at corner V of face f with unit normal n, `u₁ = unit(V₊ − V)`,
//! `u₂ = unit(V₋ − V)`, `m₁ = unit(n × u₁)` and `m₂ = unit(u₂ × n)` are the inward normals of
//! the two edges, `c = m₁·m₂ = −cos φ`, `sin φ = n·(u₁ × u₂)` (negative at reflex corners).
//! On a warped face the cylindrical family takes for n the normal of the corner's own plane,
//! on the face normal's side (docs/algorithms/conventions.md, "The corner plane").

mod chamfer;
pub mod combination;
mod concave;
mod cylindrical;
mod doo_sabin;
pub mod mend;
mod options;
pub mod overlap;
mod prepare;
mod prepared;
pub mod primal;

pub use combination::CombinationState;
pub use cylindrical::{cut_width, dissolve_needed};
pub use mend::{Mend, MendOptions, MendReport, Untangled};
pub use options::RoundingOptions;
pub use overlap::{EdgeFit, Overlap, ReachOptions, Reached};
pub use prepared::Prepared;

use crate::mesh::PolyMesh;
use crate::topology::Topology;
use glam::DVec3;
use thiserror::Error;

/// What the vector-sum rule does at a reflex corner (docs/algorithms/chamfers.md).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
pub enum ReflexMode {
    /// Eq. (2) as printed: the displacement points out of the face at reflex corners.
    #[default]
    AsPrinted,
    /// The paper's remark read as an option: `V' = V − α(e₁ + e₂)` when `sin φ < 0`.
    Inward,
}

/// Where each new corner point of a biquadratic step goes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CornerRule {
    DooSabin,
    AngleBisector { l: f64 },
    CutWidth { d: f64 },
    VectorSum { alpha: f64, reflex: ReflexMode },
    Cylindrical { r: f64 },
    Minimum { r: f64 },
    Combination { r: f64 },
}

/// A parameter outside its admissible range.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{name} = {value} is out of range: {expected}")]
pub struct ParamError {
    pub name: &'static str,
    pub value: f64,
    pub expected: &'static str,
}

impl CornerRule {
    /// Whether the rule needs per-edge cut widths (and so the flat-edge dissolve first).
    pub fn is_cylindrical_family(&self) -> bool {
        matches!(
            self,
            CornerRule::Cylindrical { .. }
                | CornerRule::Minimum { .. }
                | CornerRule::Combination { .. }
        )
    }

    /// The mending strategies a step of the rule takes, in the order they run
    /// ([`mend`]): the combination rule always takes the fold guard, the untangling and the
    /// small chamfers with the crossings beside the guard's moves; the minimum type and the
    /// chamfers take the untangling and the small chamfers with the bow-ties when `options`
    /// clamp (the simple type's folds are the paper's lesson, Doo–Sabin's the scheme as
    /// printed, so neither is mended); every rule that mends also searches the whole level
    /// for crossings when [`MendOptions::crossings`] asks.
    pub fn mends(&self, options: &RoundingOptions) -> Vec<Mend> {
        let mut plan = match self {
            CornerRule::Combination { .. } => vec![
                Mend::FoldGuard,
                Mend::Untangle,
                Mend::SmallChamfers,
                Mend::GuardCrossings,
                Mend::ConcaveVertexCrossings,
            ],
            CornerRule::Minimum { .. }
            | CornerRule::AngleBisector { .. }
            | CornerRule::CutWidth { .. }
            | CornerRule::VectorSum { .. }
                if options.overlap.clamps() =>
            {
                vec![Mend::Untangle, Mend::SmallChamfers, Mend::SelfCrossings]
            }
            _ => Vec::new(),
        };
        if !plan.is_empty() && options.mend.crossings {
            plan.push(Mend::EveryCrossing);
        }
        plan
    }

    /// Whether the rule carries a run's state from step to step ([`CombinationState`]).
    pub fn carries_state(&self) -> bool {
        matches!(self, CornerRule::Combination { .. })
    }

    /// The default radius of the cylindrical family.
    pub fn radius(&self) -> Option<f64> {
        match *self {
            CornerRule::Cylindrical { r }
            | CornerRule::Minimum { r }
            | CornerRule::Combination { r } => Some(r),
            _ => None,
        }
    }
}

/// Why corner points could not be placed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RuleError {
    #[error(
        "face {face} has a hole: Doo–Sabin is not defined on faces with holes (seed 000 §2.1); use a chamfer or cylindrical rule, or split the face"
    )]
    HoledFace { face: u32 },
    #[error(
        "face {face} has a zero-angle (needle) corner at vertex {vertex}: its bisector is undefined"
    )]
    NeedleCorner { face: u32, vertex: u32 },
    #[error("face {face} has a zero-length edge at vertex {vertex}")]
    ZeroLengthEdge { face: u32, vertex: u32 },
    #[error("face {face} has no area (its normal is undefined)")]
    ZeroAreaFace { face: u32 },
    #[error(
        "edge {a}-{b} is a knife edge (bend angle {bend_deg:.3}°): the radius needs an infinite cut width there"
    )]
    KnifeEdge { a: u32, b: u32, bend_deg: f64 },
    #[error("the new point of face {face} at vertex {vertex} is not finite")]
    NonFinite { face: u32, vertex: u32 },
    #[error(
        "the rounds of {} edge(s) do not fit their faces (neighbouring rounds would overlap); a radius of at most {} fits them all: {}; lower the radius or clamp it",
        .edges.len(),
        overlap::largest_fit(.edges),
        overlap::list(.edges)
    )]
    Overlap { edges: Vec<EdgeFit> },
}

/// Why a step failed: the errors of its preparation, its rule and its budget, and a result
/// turned inside out.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum StepError {
    #[error(transparent)]
    Mesh(#[from] crate::error::MeshError),
    #[error(transparent)]
    Param(#[from] ParamError),
    #[error(transparent)]
    Rule(#[from] RuleError),
    #[error(transparent)]
    Dissolve(#[from] crate::dissolve::DissolveError),
    #[error(transparent)]
    Primal(#[from] crate::primal::PrimalError),
    #[error(transparent)]
    TooLarge(#[from] crate::error::OverBudget),
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

/// What a rule needs besides the mesh.
pub struct RuleInput<'a> {
    pub mesh: &'a PolyMesh,
    pub topo: &'a Topology,
    /// Unit face normals.
    pub normals: &'a [DVec3],
    /// Per-edge cut width for the cylindrical family (empty otherwise).
    pub cut_widths: &'a [f64],
    /// Per-face l, d or α of a clamped chamfer (empty: the rule's own everywhere); for a clamped
    /// Doo–Sabin step, the share of the width offset a concave face takes (concave.rs), negative
    /// where eq. (1) holds.
    pub face_params: &'a [f64],
    /// Per-face vertex-neighbourhood flag for the combination rule.
    pub vertex_neighbourhood: &'a [bool],
    /// The step's tolerances.
    pub options: &'a RoundingOptions,
}

/// Counters reported by a rule.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct RuleReport {
    /// Straight corners with unequal cut widths whose along-edge shift was capped (§2.6).
    pub guarded_corners: usize,
    /// Corners with a zero-length edge (faces collapsed by an earlier step): their
    /// direction is undefined, so the new point stays at the vertex.
    pub collapsed_corners: usize,
}

/// A corner's frame (docs/algorithms/conventions.md).
#[derive(Debug, Clone, Copy)]
pub(crate) struct CornerFrame {
    pub v: DVec3,
    pub e1: DVec3,
    pub e2: DVec3,
    pub u1: DVec3,
    pub u2: DVec3,
    pub m1: DVec3,
    pub m2: DVec3,
    /// m₁·m₂ = −cos φ.
    pub c: f64,
    /// Signed sin φ: > 0 convex, < 0 reflex.
    pub sin_phi: f64,
}

/// Below this `|n·u|` on both edges the face is flat at the corner and `n` is used as it is.
const FLAT_CORNER: f64 = 1e-12;

/// The normal of a corner's frame (docs/algorithms/conventions.md, "The corner plane"): the
/// face normal `n` made square to both edges at the corner — the normal of the plane through
/// the corner's two edges, on `n`'s side. `n` itself on a planar face; on a warped face (any
/// level after Catmull–Clark, a VERTEX-face of valence four or more) the cut lines then run
/// along the edges instead of along their shadows on the face's mean plane. At a nearly
/// straight corner (`|sin φ|` below `plane_sin`, [`RoundingOptions::corner_plane_sin`]) the
/// plane of the two edges is ill-defined, so the normal blends, by `|sin φ|/plane_sin`, from
/// `n` made square to the corner's line `u₁ − u₂`; a corner whose plane stands square to the
/// face's (no side to take) takes that one whole.
fn corner_normal(n: DVec3, u1: DVec3, u2: DVec3, plane_sin: f64) -> DVec3 {
    use crate::geometry::unit_or_zero;
    if n.dot(u1).abs() < FLAT_CORNER && n.dot(u2).abs() < FLAT_CORNER {
        return n;
    }
    let cross = u1.cross(u2);
    let side = n.dot(cross);
    if side == 0.0 {
        return square_to_line(n, u1, u2);
    }
    let sin = cross.length();
    let plane = cross * (side.signum() / sin);
    if sin >= plane_sin {
        return plane;
    }
    let k = sin / plane_sin;
    let out = unit_or_zero(square_to_line(n, u1, u2) * (1.0 - k) + plane * k);
    if out == DVec3::ZERO { n } else { out }
}

/// `n` made square to a corner's line `unit(u₁ − u₂)` (the corner plane's limit at a straight
/// corner); `n` itself if that leaves nothing.
fn square_to_line(n: DVec3, u1: DVec3, u2: DVec3) -> DVec3 {
    use crate::geometry::unit_or_zero;
    let line = unit_or_zero(u1 - u2);
    let out = unit_or_zero(n - n.dot(line) * line);
    if out == DVec3::ZERO { n } else { out }
}

/// The corner frame on the face normal: the chamfers' (their reference figures, flips on
/// warped faces included, are measured in it).
pub(crate) fn corner_frame(input: &RuleInput, corner: usize) -> Result<CornerFrame, RuleError> {
    frame(input, corner, false)
}

/// The corner frame on the plane of the corner's own two edges ([`corner_normal`]): the
/// cylindrical family's, whose cut lines must follow the edges they round.
pub(crate) fn corner_frame_on_edges(
    input: &RuleInput,
    corner: usize,
) -> Result<CornerFrame, RuleError> {
    frame(input, corner, true)
}

fn frame(input: &RuleInput, corner: usize, own_plane: bool) -> Result<CornerFrame, RuleError> {
    let m = input.mesh;
    let t = input.topo;
    let f = t.corner_face(corner) as usize;
    let v = m.positions[m.corner_verts[corner] as usize];
    let vp = m.positions[m.corner_verts[t.next(corner) as usize] as usize];
    let vm = m.positions[m.corner_verts[t.prev(corner) as usize] as usize];
    let n = input.normals[f];
    let (e1, e2) = (vp - v, vm - v);
    let (l1, l2) = (e1.length(), e2.length());
    if l1 == 0.0 || l2 == 0.0 {
        return Err(RuleError::ZeroLengthEdge {
            face: f as u32,
            vertex: m.corner_verts[corner],
        });
    }
    if n == DVec3::ZERO {
        return Err(RuleError::ZeroAreaFace { face: f as u32 });
    }
    let (u1, u2) = (e1 / l1, e2 / l2);
    let n = if own_plane {
        corner_normal(n, u1, u2, input.options.corner_plane_sin)
    } else {
        n
    };
    let m1 = crate::geometry::unit_or_zero(n.cross(u1));
    let m2 = crate::geometry::unit_or_zero(u2.cross(n));
    Ok(CornerFrame {
        v,
        e1,
        e2,
        u1,
        u2,
        m1,
        m2,
        c: m1.dot(m2),
        sin_phi: n.dot(u1.cross(u2)),
    })
}

/// The new point of every corner of `input.mesh` under `rule`, indexed by corner.
pub fn corner_points(
    rule: &CornerRule,
    input: &RuleInput,
) -> Result<(Vec<DVec3>, RuleReport), RuleError> {
    use rayon::prelude::*;
    let m = input.mesh;
    let mut pts = crate::parallel::filled(m.num_corners(), DVec3::ZERO);
    // Chunks of faces on every core, each owning its faces' corners; the first error in
    // face order is the one reported, as one pass would.
    let (faces, bounds) = crate::parallel::face_chunks(m);
    let chunks: Vec<Result<RuleReport, RuleError>> =
        crate::parallel::split_at_bounds(&mut pts, &bounds)
            .into_par_iter()
            .enumerate()
            .map(|(i, out)| {
                let mut report = RuleReport::default();
                for f in faces[i]..faces[i + 1] {
                    face_points(rule, input, f, out, bounds[i], &mut report)?;
                }
                Ok(report)
            })
            .collect();
    let mut report = RuleReport::default();
    for r in chunks {
        let r = r?;
        report.guarded_corners += r.guarded_corners;
        report.collapsed_corners += r.collapsed_corners;
    }
    if let Some(c) = crate::parallel::first_where(pts.len(), |c| !pts[c].is_finite()) {
        return Err(RuleError::NonFinite {
            face: input.topo.corner_face(c),
            vertex: m.corner_verts[c],
        });
    }
    Ok((pts, report))
}

/// The new points of face `f`'s corners, written to `out` (which starts at corner `base`).
fn face_points(
    rule: &CornerRule,
    input: &RuleInput,
    f: usize,
    out: &mut [DVec3],
    base: usize,
    report: &mut RuleReport,
) -> Result<(), RuleError> {
    let m = input.mesh;
    let use_doo_sabin = match rule {
        CornerRule::DooSabin => true,
        // A blend face with a hole (flat blend faces merged into a ring, e.g. around the
        // top of a torus) keeps the cylindrical points: Doo–Sabin is not defined there.
        CornerRule::Combination { .. } => {
            input.vertex_neighbourhood.get(f).copied().unwrap_or(false) && !m.face_has_holes(f)
        }
        _ => false,
    };
    if use_doo_sabin {
        if m.face_has_holes(f) {
            return Err(RuleError::HoledFace { face: f as u32 });
        }
        let l = m.face_loops(f).start;
        match input.face_params.get(f) {
            Some(&s) if s >= 0.0 => {
                let from = concave::corners(m, f);
                let moves = concave::width_offset(&from, input.normals[f]);
                let start = m.loop_corners(l).start - base;
                for (i, (v, d)) in from.iter().zip(&moves).enumerate() {
                    out[start + i] = *v + s * *d;
                }
            }
            _ => doo_sabin::loop_points(m, l, out, base),
        }
        return Ok(());
    }
    for c in m.face_corners(f) {
        let placed = match *rule {
            CornerRule::AngleBisector { l } => {
                chamfer::angle_bisector(input, c, input.face_params.get(f).copied().unwrap_or(l))
            }
            CornerRule::CutWidth { d } => {
                chamfer::cut_width(input, c, input.face_params.get(f).copied().unwrap_or(d))
            }
            CornerRule::VectorSum { alpha, reflex } => Ok(chamfer::vector_sum(
                input,
                c,
                input.face_params.get(f).copied().unwrap_or(alpha),
                reflex,
            )),
            CornerRule::Cylindrical { .. } | CornerRule::Combination { .. } => {
                cylindrical::simple(input, c, report)
            }
            CornerRule::Minimum { .. } => cylindrical::minimum(input, c),
            CornerRule::DooSabin => unreachable!("handled above"),
        };
        out[c - base] = match placed {
            Ok(p) => p,
            Err(RuleError::ZeroLengthEdge { .. }) => {
                report.collapsed_corners += 1;
                m.positions[m.corner_verts[c] as usize]
            }
            Err(e) => return Err(e),
        };
    }
    Ok(())
}
