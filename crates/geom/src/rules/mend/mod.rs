//! The rounding step's mending stage: named strategies, each for one fault the construction
//! can leave, run after the rule has placed its points and the level is split
//! (docs/algorithms/cylindrical.md, "Mending"). The step is construction → mend → report
//! ([`crate::step`]); every strategy here changes points only where its fault is seen, says
//! what it changed in the [`MendReport`], and where nothing is wrong does nothing — every
//! solid the paper shows is built by the construction alone.
//!
//! | strategy | fault it treats | what it does | file |
//! | --- | --- | --- | --- |
//! | [`Mend::FoldGuard`] | cut points that would fold a new face (the combination rule's sharp strip ends) | the faces join the vertex blend (Doo–Sabin points); blend faces beside a fold take the width offset or points nearer their corners | `fold_guard.rs` |
//! | [`Mend::Untangle`] | new faces still flipped (slivers of a smoothed input) | their points smoothed until none is flipped, each move at most 1 % of the diagonal | `untangle.rs` |
//! | [`Mend::SmallChamfers`] | new faces still flipped after the untangling | the parent vertices round them take small angle-bisector chamfers | `small_chamfers.rs` |
//! | [`Mend::GuardCrossings`] | new faces beside the fold guard's moves that pass through others (none flipped) | they seed the small chamfers | `crossings.rs` |
//! | [`Mend::ConcaveVertexCrossings`] | VERTEX-faces at concave vertices passing through a face round them | they seed the small chamfers | `crossings.rs` |
//! | [`Mend::SelfCrossings`] | new faces whose outline crosses itself (bow-ties the flip test cannot see) | they seed the small chamfers | `crossings.rs` |
//! | [`Mend::EveryCrossing`] | any two faces of the level that pass through each other | they seed the small chamfers (the whole level searched) | `crossings.rs` |
//!
//! Which strategies a rule takes is the rule's own declaration ([`crate::rules::CornerRule::mends`]);
//! their tolerances are [`MendOptions`], part of the step's
//! [`RoundingOptions`](crate::rules::RoundingOptions).

mod crossings;
mod fold_guard;
mod small_chamfers;
mod untangle;

pub use untangle::Untangled;

use crate::child_check::ChildCheck;
use crate::mesh::PolyMesh;
use crate::refine::Provenance;
use crate::rules::RuleInput;
use glam::DVec3;

/// One mending strategy: the fault it treats is in its doc and in the table of the module.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Mend {
    /// Before the split: faces whose cut points would fold a new face move into the vertex
    /// blend; blend faces beside a fold the guard still sees are re-placed (`fold_guard.rs`).
    FoldGuard,
    /// New faces still flipped: their points smoothed (`untangle.rs`).
    Untangle,
    /// New faces still flipped: the parent vertices round them take small chamfers
    /// (`small_chamfers.rs`).
    SmallChamfers,
    /// With no face flipped, new faces round the fold guard's moves that pass through a face
    /// near them seed the small chamfers (`crossings.rs`, [`crossings::guard_crossings`]).
    GuardCrossings,
    /// Where the guard acted, VERTEX-faces at parent vertices with a concave edge that pass
    /// through a face round them seed the small chamfers
    /// ([`crossings::concave_vertex_crossings`]).
    ConcaveVertexCrossings,
    /// With no face flipped, new faces that cross themselves seed the small chamfers
    /// ([`crossings::self_crossing_faces`]).
    SelfCrossings,
    /// With no face flipped, every crossing left on the level seeds the small chamfers (the
    /// whole level searched: several times a step's time; [`MendOptions::crossings`]).
    EveryCrossing,
}

/// The mending stage's tolerances, each with its default.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MendOptions {
    /// Whether the rules that mend ([`crate::rules::CornerRule::mends`]) also search the whole
    /// level for faces that pass through each other ([`Mend::EveryCrossing`]). On by default
    /// in the library, the CLI and the app alike: a rounding that leaves faces through each
    /// other is not a sound solid. It costs several times the step of a rule that mends
    /// (docs/algorithms/cylindrical.md, "Options"); `--no-mend-crossings` and the Model tab's
    /// checkbox turn it off.
    pub crossings: bool,
    /// Rounds of the fold guard's re-placing of blend faces (default 4).
    pub reoffset_rounds: usize,
    /// The shares of the way from their corners to eq. (1)'s points at which the re-placing
    /// also tries a blend face's points (default ½ and ¼).
    pub drawn: [f64; 2],
    /// Rounds of smoothing before the untangling gives up (default 64).
    pub untangle_rounds: usize,
    /// The untangling keeps its points only when none moved farther than this share of the
    /// bounding-box diagonal (default 0.01): it mends folds at the scale of noise.
    pub untangle_most_move: f64,
    /// Rounds of halving before the small chamfers give up (default 16).
    pub small_chamfer_rounds: usize,
    /// A small chamfer's first length as a share of the shortest edge at its vertex
    /// (default 0.1).
    pub small_chamfer_share: f64,
}

impl Default for MendOptions {
    fn default() -> Self {
        MendOptions {
            crossings: true,
            reoffset_rounds: 4,
            drawn: [0.5, 0.25],
            untangle_rounds: 64,
            untangle_most_move: 1e-2,
            small_chamfer_rounds: 16,
            small_chamfer_share: 0.1,
        }
    }
}

/// What the mending stage changed, for the step's report.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MendReport {
    /// Faces moved into the vertex blend because their cut points would have folded a new
    /// face ([`Mend::FoldGuard`]).
    pub unfolded_faces: usize,
    /// Blend faces re-placed (Doo–Sabin's width offset, or their points drawn towards their
    /// corners) because a new face beside them still folded ([`Mend::FoldGuard`]).
    pub reoffset_faces: usize,
    /// Points of new faces still flipped after the fold guard, smoothed until none is, and
    /// how far ([`Mend::Untangle`]).
    pub untangled: Untangled,
    /// Parent vertices where the rule's points gave way to a small chamfer because a new
    /// face round them was still flipped, passed through another or crossed itself
    /// ([`Mend::SmallChamfers`] and the crossings that seed it).
    pub small_chamfers: usize,
}

impl MendReport {
    /// One sentence for each thing the stage changed, as the CLI and the app print them.
    pub fn notes(&self) -> Vec<String> {
        let mut out = Vec::new();
        if self.unfolded_faces > 0 {
            out.push(format!(
                "{} face(s) joined the vertex blend (Doo–Sabin) because their cut points would have folded a new face",
                self.unfolded_faces
            ));
        }
        if self.reoffset_faces > 0 {
            out.push(format!(
                "{} blend face(s) took Doo–Sabin's width offset or points nearer their corners because a new face beside them would have folded",
                self.reoffset_faces
            ));
        }
        if self.untangled.points > 0 {
            out.push(format!(
                "{} point(s) of folded sliver faces smoothed until none was flipped (largest move {:.3e})",
                self.untangled.points, self.untangled.largest_move
            ));
        }
        if self.small_chamfers > 0 {
            out.push(format!(
                "the rule's points gave way to a small chamfer at {} vertex(es) where a new face would still have been flipped, passed through another or crossed itself",
                self.small_chamfers
            ));
        }
        out
    }
}

/// The level a step split, as the mending stage reads it: what the rule read, and the edges
/// whose cut width the preparation lowered (the combination rule's guard).
pub struct Parent<'a> {
    pub input: RuleInput<'a>,
    pub capped_edges: &'a [u32],
}

/// [`Mend::FoldGuard`] on the corner points `points` before the split, when `plan` has it:
/// the faces moved into the blend, ascending (the combination run keeps them there), and how
/// many blend faces were re-placed.
pub fn before_split(plan: &[Mend], parent: &Parent, points: &mut [DVec3]) -> (Vec<u32>, usize) {
    if !plan.contains(&Mend::FoldGuard) {
        return (Vec::new(), 0);
    }
    let i = &parent.input;
    fold_guard::fold_guard(
        i.mesh,
        i.topo,
        i.normals,
        i.vertex_neighbourhood,
        i.options,
        points,
    )
}

/// The strategies of `plan` after the split, in their order, on the child `out` (its vertex c
/// is the parent's corner c) whose last check is `checked`; `recheck` checks a child again.
/// `unfolded` are the faces [`before_split`] moved. Returns what was changed; `checked` is the
/// check of `out` as it is left.
pub fn after_split(
    plan: &[Mend],
    parent: &Parent,
    prov: &Provenance,
    unfolded: &[u32],
    out: &mut PolyMesh,
    checked: &mut ChildCheck,
    recheck: impl Fn(&PolyMesh) -> ChildCheck,
) -> MendReport {
    let has = |m: Mend| plan.contains(&m);
    let i = &parent.input;
    let (cur, topo, normals, options) = (i.mesh, i.topo, i.normals, &i.options.mend);
    let mut report = MendReport::default();
    if has(Mend::Untangle) && !checked.flipped.is_empty() {
        let corners: Vec<u32> = checked
            .flipped
            .iter()
            .flat_map(|&f| out.face_corners(f as usize).map(|c| out.corner_verts[c]))
            .collect();
        report.untangled =
            untangle::untangle(cur, topo, normals, &mut out.positions, corners, options);
        if report.untangled.points > 0 {
            *checked = recheck(out);
        }
    }
    let retreat = |out: &mut PolyMesh, checked: &mut ChildCheck, seeds: &[u32]| {
        // The strategy's own last check is the step's when it keeps its points.
        let mut last = None;
        let n = small_chamfers::retreat(
            cur,
            topo,
            normals,
            out,
            (seeds, checked.degenerate.len()),
            options,
            |m| {
                let c = recheck(m);
                let seen = (c.flipped.clone(), c.degenerate.len());
                last = Some(c);
                seen
            },
        );
        if n > 0 {
            *checked = last.expect("the strategy checks the points it keeps");
        }
        n
    };
    // The parent faces the guard moved: the faces it unfolded and those beside the edges it
    // cut narrower.
    let guarded = crossings::guarded_faces(topo, unfolded, parent.capped_edges);
    if has(Mend::SmallChamfers) {
        if !checked.flipped.is_empty() {
            let seeds = checked.flipped.clone();
            report.small_chamfers += retreat(out, checked, &seeds);
        } else if has(Mend::GuardCrossings) && !guarded.is_empty() {
            let seeds = crossings::guard_crossings(cur, topo, out, prov, &guarded);
            if !seeds.is_empty() {
                report.small_chamfers += retreat(out, checked, &seeds);
            }
        }
    }
    if has(Mend::ConcaveVertexCrossings) && checked.flipped.is_empty() && !guarded.is_empty() {
        let seeds = crossings::concave_vertex_crossings(cur, topo, normals, out, prov);
        if !seeds.is_empty() {
            report.small_chamfers += retreat(out, checked, &seeds);
        }
    }
    if has(Mend::SelfCrossings) && checked.flipped.is_empty() {
        let seeds = crossings::self_crossing_faces(out);
        if !seeds.is_empty() {
            report.small_chamfers += retreat(out, checked, &seeds);
        }
    }
    if has(Mend::EveryCrossing) && checked.flipped.is_empty() {
        let seeds = crate::analysis::crossing_faces(&crate::analysis::crossings(out));
        if !seeds.is_empty() {
            report.small_chamfers += retreat(out, checked, &seeds);
        }
    }
    report
}

#[cfg(test)]
mod tests;
