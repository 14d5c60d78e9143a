//! Primitives nested in another (docs/algorithms/envelope.md, "Nested primitives").
//!
//! The paper joins two primitives A and B by a fusion strip from A's section, on the plane
//! through G_A normal to G_B − G_A, to B's, on the parallel plane through G_B (§5.1): the
//! hull of two spheres when their radii are equal. Where B's sphere holds A's centre and A is
//! the smaller, `|G_A − G_B| < r_B`, the strip runs from a loop about r_A wide to one about
//! r_B wide less than r_B apart: it leaves B's silhouette almost along B's radius, across the
//! tangent plane the patches must meet there, and they fold (the survey of mixed heaps: five
//! of the six folded at t = 1). A primitive adds nothing to the envelope where its curved shape
//! lies inside the envelope of the others, so such an A is left out, as the paper leaves out
//! a primitive swallowed by the others (§5.1.3: "automatically removed"): the envelope is the
//! one of the scene without it. The test: every primitive whose centre lies in a larger one's
//! sphere is a candidate; the envelope of the scene without *all* candidates (so that the
//! outcome does not depend on the order in which they are judged or listed) is tessellated,
//! [`NESTED_K`] quads a patch side, and so is each candidate alone ([`CANDIDATE_K`]); a
//! candidate goes where every vertex of its tessellation lies inside the others'
//! ([`Inside`]); when all go, that envelope is the answer. The chords of the convex-ish
//! envelope lie inside it, so the test errs towards keeping. Inside the holder's curved shape
//! alone is not enough: below t ≈ 0.6 the fusion strips do not hold every part of the
//! primitives they join (envelope.md, "Enclosure"), and the box of the test's heap at
//! t = 0.3, inside the curved tetrahedron, had a corner outside the surface without it.

use super::{Envelope, EnvelopeSpec, Primitive, assemble};
use crate::analysis::Inside;
use crate::freeform::envelope::tolerances::TOLERANCES;

/// [`TOLERANCES`]`.nested_resolution`.
pub const NESTED_K: usize = TOLERANCES.nested_resolution;

/// [`TOLERANCES`]`.candidate_resolution`.
pub const CANDIDATE_K: usize = TOLERANCES.candidate_resolution;

/// The primitives (indices, ascending) whose centre lies in a larger one's sphere.
pub(super) fn candidates(primitives: &[Primitive]) -> Vec<usize> {
    (0..primitives.len())
        .filter(|&a| {
            let pa = &primitives[a];
            primitives
                .iter()
                .any(|pb| pa.radius < pb.radius && pa.centre.distance(pb.centre) < pb.radius)
        })
        .collect()
}

/// The `candidates` whose curved shape lies inside `rest`, the envelope of the scene without
/// all of them.
pub(super) fn inside(
    spec: &EnvelopeSpec,
    primitives: &[Primitive],
    rest: &Envelope,
    candidates: &[usize],
) -> Vec<usize> {
    let Ok(rest) = rest.tessellate(NESTED_K) else {
        return Vec::new();
    };
    let rest = Inside::new(&rest);
    candidates
        .iter()
        .copied()
        .filter(|&a| {
            assemble(spec, primitives.to_vec(), vec![a])
                .and_then(|e| e.tessellate(CANDIDATE_K))
                .is_ok_and(|m| m.positions.iter().all(|&p| rest.contains(p)))
        })
        .collect()
}
