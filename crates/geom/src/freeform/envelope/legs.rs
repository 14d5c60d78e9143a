//! Short legs given back where a patch folds (docs/algorithms/envelope.md, "Short legs given
//! back where a patch folds").
//!
//! Below t = ½ the polynomial network curves — fusion edges and the cubics that replace hooked
//! edge pieces — take legs of only `2t` thirds of their chord ([`super::edges`]'s `legs_for`),
//! so that they hug their chords as the curved edges beside them do. Where such a curve leaves
//! its ends far from its chord (a fusion edge climbing 0.62 over 0.67 between ends whose
//! tangent planes lie along the facet), its tangent plane turns fast within the short leg, the
//! Coons patch carries that turn across a thin strip beside the next side, and the strip
//! folds. Lengthening every such curve's legs moved the fold to other heaps (a sliver strip
//! bulged through its neighbour); lengthening only the curves around a folded patch does not:
//!
//! 1. Build the patches. If none folds, that is the envelope: at the report's samples, nor
//!    between them where the rescaling search looked (16 and 32 cells a side for a patch
//!    checked finer, `patches.rs`, `unfolded`).
//! 2. Otherwise, for each share `s` of [`SHARES`] in turn, give every polynomial curve on a
//!    side of a folded patch's region legs of at least `s` × a third of its chord (directions
//!    kept, so its end tangents — and the tangent planes and G1 — are unchanged) and build the
//!    patches again; keep the first build that folds nowhere, or else the one that folds
//!    least (fewest cells at the report's samples, then between them).
//! 3. If that still folds at the report's samples, build it once more with every way to patch
//!    a region that still folds tried rescaled (`patches.rs`, `build`; envelope.md, "Every
//!    way, rescaled").
//!
//! A curve with a T-point or a split point on it keeps its legs (the point would leave it).
//! The curves chosen come from the folded regions, not from the listing, so the surface does
//! not depend on the order of the input. The change is discrete: as t or a primitive moves
//! across the place where a fold would appear, the curves around it lengthen at once.

use super::folds::Fold;
use super::network::{CurveKind, Network};
use super::patches::{self, EnvelopePatch};
use super::primitive::Primitive;
use crate::freeform::skin::Basis;
use std::collections::BTreeSet;

/// The shares of a third of the chord tried, in order, as the least legs of the curves
/// around a fold (the survey's two folds went at the first).
const SHARES: [f64; 2] = [0.5, 1.0];

/// The network with its bases, the patches, their folded cells as the report samples them,
/// and the regions still folding between those samples with how many cells
/// ([`patches::build`]).
type Built = (Network, Vec<EnvelopePatch>, Vec<Fold>, Vec<(usize, usize)>);

fn build(mut net: Network, basis: Basis, prims: &[Primitive], every_way: bool) -> Built {
    net.assign_bases(basis);
    let (patches, folded, between) = patches::build(&mut net, prims, every_way);
    (net, patches, folded, between)
}

/// How much `b` folds: its folded cells at the report's samples, then those between them (a
/// fold at the samples is never traded for folds between them).
fn folding(b: &Built) -> (usize, usize) {
    (b.2.len(), b.3.iter().map(|&(_, cells)| cells).sum())
}

/// The patches of `net` (regions complete, no basis assigned yet), with the short legs around
/// a fold given back as the module says.
pub(super) fn patched(net: Network, basis: Basis, prims: &[Primitive]) -> Built {
    let first = build(net.clone(), basis, prims, false);
    if folding(&first) == (0, 0) {
        return first;
    }
    let around: BTreeSet<usize> = first
        .2
        .iter()
        .map(|f| f.region)
        .chain(first.3.iter().map(|&(r, _)| r))
        .flat_map(|r| net.regions[r].sides.iter().map(|s| s.curve))
        .collect();
    let mut best = first;
    let mut input = net.clone();
    for share in SHARES {
        let mut lengthened = net.clone();
        let mut changed = false;
        for &c in &around {
            changed |= lengthen(&mut lengthened, c, share);
        }
        if !changed {
            continue;
        }
        let got = build(lengthened.clone(), basis, prims, false);
        if folding(&got) < folding(&best) {
            best = got;
            input = lengthened;
            if folding(&best) == (0, 0) {
                return best;
            }
        }
    }
    if best.2.is_empty() {
        return best;
    }
    // Still folding at the report's samples: every way to patch a region that folds there,
    // each rescaled.
    let last = build(input, basis, prims, true);
    if folding(&last) < folding(&best) {
        best = last;
    }
    best
}

/// Gives curve `c` legs of at least `share` × a third of its chord when it is a polynomial
/// cubic with no point but its ends on it; whether it changed.
fn lengthen(net: &mut Network, c: usize, share: f64) -> bool {
    let curve = &mut net.curves[c];
    if curve.kind == CurveKind::Insertion
        || curve.pins.len() > 2
        || curve.bezier.points.len() != 4
        || curve.bezier.weights.iter().any(|&w| w != 1.0)
    {
        return false;
    }
    let p = &mut curve.bezier.points;
    let least = share * p[0].distance(p[3]) / 3.0;
    let mut changed = false;
    for (end, inner) in [(0, 1), (3, 2)] {
        let leg = p[inner] - p[end];
        let length = leg.length();
        if length > 0.0 && length < least {
            p[inner] = p[end] + leg * (least / length);
            changed = true;
        }
    }
    changed
}
