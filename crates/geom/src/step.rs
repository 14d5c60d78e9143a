//! One biquadratic step with a corner rule, from a mesh to the next level, with everything a
//! user needs to see: counts, flipped and degenerate faces, time (docs/algorithms/biquadratic.md).
//!
//! The step is construction → mend → report, the same for every rule:
//! 1. **construction**: validate the rule's parameter; let the rule prepare the level
//!    ([`CornerRule::prepare`]: closed topology and normals for every rule, flat-edge merge
//!    and cut widths for the cylindrical family, the combination run's state); refuse a step
//!    that would not fit; place the corner points; split ([`dual_quad`]); hand down edge
//!    attributes ([`refine::propagate`]) and the combination state;
//! 2. **mend**: the strategies the rule declares ([`CornerRule::mends`], [`rules::mend`]),
//!    each where its fault is seen, under [`RoundingOptions::mend`];
//! 3. **report**: the new faces checked ([`check_children`]: flipped and degenerate faces are
//!    listed, never hidden), and what the preparation and the mending changed, in words
//!    ([`StepReport::notes`]) that the CLI and the app both print.

use crate::edge_attrs::EdgeAttrs;
use crate::error::OverBudget;
use crate::mesh::PolyMesh;
use crate::refine::{self, Numbering, Provenance, dual_quad};
use crate::rules::{self, CombinationState, CornerRule, MendReport, mend};
use crate::topology::Topology;
use std::borrow::Cow;
use std::time::Instant;

pub use crate::child_check::{
    ChildCheck, DEGENERATE_NOISE, check_children, is_degenerate, primal_flipped, scale,
};
pub use crate::rules::{RoundingOptions, StepError};
pub use notes::{StepNote, Topic};

mod notes;

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
    /// What the clamp's reach search did, when the first step of a clamped combination run
    /// missed a clamped radius (`Pipeline::compute_with`).
    pub reached: Option<rules::Reached>,
    /// Edges whose cut width the combination rule lowered so its cut faces keep their edges.
    pub capped_edges: usize,
    /// Faces whose chamfer distance or width (l, d) the clamp lowered.
    pub clamped_faces: usize,
    /// Concave faces whose Doo–Sabin points the clamp took from the width offset, where eq. (1)
    /// would turn a strip over (docs/algorithms/biquadratic.md, "Concave faces").
    pub offset_faces: usize,
    /// Corners with a zero-length edge that stayed at their vertex.
    pub collapsed_corners: usize,
    /// What the mending stage changed ([`rules::mend`]).
    pub mend: MendReport,
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
    options: &RoundingOptions,
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
    options: &RoundingOptions,
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
    let plan = rule.mends(options);
    let parent = mend::Parent {
        input: prep.input(),
        capped_edges: &prep.capped_edges,
    };
    // Mend, before the split: the child's vertex c is the parent's corner c.
    let (unfolded, reoffset_faces) = mend::before_split(&plan, &parent, &mut points);
    let (mut out, prov) = dual_quad::split(cur, topo, points);
    let new_attrs = refine::propagate(
        cur,
        topo,
        &prep.edge_attrs,
        Numbering::DualQuad,
        |_, a, _| Some(*a),
    );
    let combination = rule
        .carries_state()
        .then(|| CombinationState::next(cur, topo, &prov, prep.combination.as_deref(), &unfolded));
    let recheck = |m: &PolyMesh| check_children(cur, topo, &prep.normals, m, &prov);
    let mut checked = recheck(&out);
    // Mend, after the split.
    let mut mended = mend::after_split(
        &plan,
        &parent,
        &prov,
        &unfolded,
        &mut out,
        &mut checked,
        recheck,
    );
    mended.unfolded_faces = unfolded.len();
    mended.reoffset_faces = reoffset_faces;
    let report = StepReport {
        vertices: out.num_vertices(),
        edges: 4 * topo.num_edges(),
        faces: out.num_faces(),
        flipped: checked.flipped,
        degenerate: checked.degenerate,
        dissolved_edges: prep.dissolved_edges,
        guarded_corners: rule_report.guarded_corners,
        clamped: prep.clamped.clone(),
        reached: None,
        capped_edges: prep.capped_edges.len(),
        clamped_faces: prep.clamped_faces,
        offset_faces: prep.offset_faces,
        collapsed_corners: rule_report.collapsed_corners,
        mend: mended,
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;
    use crate::rules::RuleError;

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
        let clamp = RoundingOptions {
            overlap: rules::Overlap::Clamp,
            ..RoundingOptions::default()
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
