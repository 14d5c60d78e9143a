//! Each mending strategy on a small synthetic case: the fault planted in a split cube, the
//! strategy run alone, the fault gone (or, where it cannot be mended, nothing moved).

use super::*;
use crate::child_check::check_children;
use crate::geometry::{face_normals_raw, unit_or_zero};
use crate::primitives;
use crate::refine::dual_quad;
use crate::topology::Topology;

/// A parent level with everything the stage reads.
struct Level {
    mesh: PolyMesh,
    topo: Topology,
    normals: Vec<DVec3>,
    options: crate::rules::RoundingOptions,
}

impl Level {
    fn new(mesh: PolyMesh) -> Level {
        let topo = Topology::build(&mesh).unwrap();
        let normals = face_normals_raw(&mesh)
            .into_iter()
            .map(unit_or_zero)
            .collect();
        Level {
            mesh,
            topo,
            normals,
            options: crate::rules::RoundingOptions::default(),
        }
    }

    fn parent<'a>(&'a self, capped: &'a [u32]) -> Parent<'a> {
        Parent {
            input: RuleInput {
                mesh: &self.mesh,
                topo: &self.topo,
                normals: &self.normals,
                cut_widths: &[],
                face_params: &[],
                vertex_neighbourhood: &[],
                options: &self.options,
            },
            capped_edges: capped,
        }
    }

    /// The vector sum's corner points, `V + α(V₊ − V) + α(V₋ − V)`.
    fn points(&self, alpha: f64) -> Vec<DVec3> {
        let m = &self.mesh;
        (0..m.num_corners())
            .map(|c| {
                let at = |c: usize| m.positions[m.corner_verts[c] as usize];
                let v = at(c);
                let (next, prev) = (
                    at(self.topo.next(c) as usize),
                    at(self.topo.prev(c) as usize),
                );
                v + alpha * (next - v) + alpha * (prev - v)
            })
            .collect()
    }

    /// The points split, with the check of the child.
    fn split(&self, points: Vec<DVec3>) -> (PolyMesh, Provenance, ChildCheck) {
        let (child, prov) = dual_quad::split(&self.mesh, &self.topo, points);
        let check = self.check(&child, &prov);
        (child, prov, check)
    }

    fn check(&self, child: &PolyMesh, prov: &Provenance) -> ChildCheck {
        check_children(&self.mesh, &self.topo, &self.normals, child, prov)
    }

    /// `plan` run after the split on `child`; its report and the check it leaves.
    fn mend(
        &self,
        plan: &[Mend],
        child: &mut PolyMesh,
        prov: &Provenance,
        unfolded: &[u32],
    ) -> (MendReport, ChildCheck) {
        let mut checked = self.check(child, prov);
        let report = after_split(
            plan,
            &self.parent(&[]),
            prov,
            unfolded,
            child,
            &mut checked,
            |m| self.check(m, prov),
        );
        (report, checked)
    }
}

/// The corners round vertex 0 of the cube: their points form its VERTEX-face. Two of them
/// swapped turn it over.
fn swap_at_vertex_0(level: &Level, points: &mut [DVec3]) {
    let cs: Vec<usize> = level.topo.corners_around(0).map(|c| c as usize).collect();
    points.swap(cs[0], cs[1]);
}

fn cube() -> Level {
    Level::new(primitives::cuboid(DVec3::ZERO, DVec3::ONE))
}

/// The untangling clears a fold at the scale of noise (two points of a vertex face 0.005 of
/// the edge from their corner swapped) with every move under 1 % of the diagonal, and leaves
/// a fold it cannot clear that way (the same swap 0.1 from the corner) as it was.
#[test]
fn the_untangling_clears_small_folds_and_leaves_large_ones() {
    let level = cube();
    let diagonal = 3f64.sqrt();
    let mut points = level.points(0.005);
    swap_at_vertex_0(&level, &mut points);
    let (mut child, prov, check) = level.split(points);
    assert!(!check.flipped.is_empty());
    let (r, after) = level.mend(&[Mend::Untangle], &mut child, &prov, &[]);
    assert!(after.flipped.is_empty(), "{after:?}");
    assert!(r.untangled.points > 0);
    assert!(r.untangled.largest_move <= 0.01 * diagonal);
    assert_eq!(r.small_chamfers, 0);

    let mut points = level.points(0.1);
    swap_at_vertex_0(&level, &mut points);
    let (mut child, prov, check) = level.split(points);
    let before = child.positions.clone();
    let (r, after) = level.mend(&[Mend::Untangle], &mut child, &prov, &[]);
    assert_eq!(r.untangled, Untangled::default());
    assert_eq!(after.flipped, check.flipped);
    assert_eq!(child.positions, before);
}

/// The small chamfers clear the large fold the untangling leaves: the vertex of the flipped
/// faces takes one, and nothing else moves.
#[test]
fn small_chamfers_clear_a_fold_at_its_vertex() {
    let level = cube();
    let mut points = level.points(0.1);
    swap_at_vertex_0(&level, &mut points);
    let (mut child, prov, check) = level.split(points.clone());
    assert!(!check.flipped.is_empty());
    let plan = [Mend::Untangle, Mend::SmallChamfers];
    let (r, after) = level.mend(&plan, &mut child, &prov, &[]);
    assert!(after.flipped.is_empty() && after.degenerate.is_empty());
    assert_eq!(r.small_chamfers, 1);
    let at_0: Vec<usize> = level.topo.corners_around(0).map(|c| c as usize).collect();
    for (c, p) in child.positions.iter().enumerate() {
        if !at_0.contains(&c) {
            assert_eq!(*p, points[c]);
        }
    }
    assert!(crate::analysis::crossings(&child).is_empty());
}

/// A FACE-face whose outline crosses itself keeps a normal that agrees with its parent's (the
/// flip test cannot see it); the bow-tie strategy finds it and the small chamfers mend it.
#[test]
fn bow_ties_are_found_and_mended() {
    let level = cube();
    let mut points = level.points(0.1);
    // Face 0's FACE-face p0 p1 p2 p3 with p2 and p3 slid past each other along their side.
    let cs: Vec<usize> = level.mesh.face_corners(0).collect();
    let (p2, p3) = (points[cs[2]], points[cs[3]]);
    points[cs[2]] = p3.lerp(p2, 0.25);
    points[cs[3]] = p3.lerp(p2, 0.75);
    let (mut child, prov, check) = level.split(points);
    assert!(check.flipped.is_empty(), "{check:?}");
    assert!(crossings::self_crossing_faces(&child).contains(&0));
    // Without the bow-tie strategy nothing is mended.
    let (r, _) = level.mend(
        &[Mend::Untangle, Mend::SmallChamfers],
        &mut child,
        &prov,
        &[],
    );
    assert_eq!(r, MendReport::default());
    let plan = [Mend::Untangle, Mend::SmallChamfers, Mend::SelfCrossings];
    let (r, after) = level.mend(&plan, &mut child, &prov, &[]);
    assert!(r.small_chamfers > 0);
    assert!(after.flipped.is_empty());
    assert!(crossings::self_crossing_faces(&child).is_empty());
}

/// The whole-level search sees faces that pass through each other with none flipped: two
/// cubes that overlap in space. A small chamfer cannot part them, so nothing moves and the
/// crossings stay for the report.
#[test]
fn every_crossing_is_looked_for_and_left_when_it_cannot_be_mended() {
    let level = Level::new(primitives::union_disjoint(&[
        primitives::cuboid(DVec3::ZERO, DVec3::ONE),
        primitives::cuboid(DVec3::splat(0.5), DVec3::splat(1.5)),
    ]));
    let (mut child, prov, check) = level.split(level.points(0.1));
    assert!(check.flipped.is_empty());
    assert!(!crate::analysis::crossings(&child).is_empty());
    let before = child.positions.clone();
    let plan = [Mend::Untangle, Mend::SmallChamfers, Mend::EveryCrossing];
    let (r, after) = level.mend(&plan, &mut child, &prov, &[]);
    assert_eq!(r.small_chamfers, 0);
    assert!(after.flipped.is_empty());
    assert_eq!(child.positions, before);
}

/// The crossings beside the guard's moves are looked for only among the new faces round the
/// faces the guard moved (one ring), not across the level: the overlapping cubes cross each
/// other, far apart in the mesh, and no moved face of either sees it, where the whole-level
/// search does.
#[test]
fn guard_crossings_look_round_the_moved_faces_only() {
    let level = Level::new(primitives::union_disjoint(&[
        primitives::cuboid(DVec3::ZERO, DVec3::ONE),
        primitives::cuboid(DVec3::splat(0.5), DVec3::splat(1.5)),
    ]));
    let (child, prov, _) = level.split(level.points(0.1));
    assert!(!crate::analysis::crossings(&child).is_empty());
    assert!(crossings::guarded_faces(&level.topo, &[], &[]).is_empty());
    // An edge cut narrower moves both faces beside it.
    assert_eq!(crossings::guarded_faces(&level.topo, &[3], &[0]).len(), 3);
    for f in 0..12 {
        let seen = crossings::guard_crossings(&level.mesh, &level.topo, &child, &prov, &[f]);
        assert!(seen.is_empty(), "face {f}: {seen:?}");
    }
}

/// The fold guard moves the faces whose cut points would fold a new face into the vertex
/// blend, before the split: with two points of vertex 0's face swapped, the faces round vertex
/// 0 take Doo–Sabin points and no new face folds; a plan without it moves nothing.
#[test]
fn the_fold_guard_moves_folding_faces_into_the_blend() {
    let level = cube();
    let mut points = level.points(0.1);
    swap_at_vertex_0(&level, &mut points);
    let mut unguarded = points.clone();
    assert_eq!(
        before_split(&[Mend::Untangle], &level.parent(&[]), &mut unguarded),
        (Vec::new(), 0)
    );
    assert_eq!(unguarded, points);
    let (moved, _) = before_split(&[Mend::FoldGuard], &level.parent(&[]), &mut points);
    let at_0: Vec<u32> = level
        .topo
        .corners_around(0)
        .map(|c| level.topo.corner_face(c as usize))
        .collect();
    assert!(
        !moved.is_empty() && moved.iter().all(|f| at_0.contains(f)),
        "{moved:?}"
    );
    let (_, _, check) = level.split(points);
    assert!(check.flipped.is_empty(), "{check:?}");
}

/// The plan each rule declares: the combination rule's guard and crossings, the clamped
/// chamfers' and minimum type's bow-ties, nothing for Doo–Sabin, the simple type or an
/// unclamped chamfer, and the whole-level search only when asked.
#[test]
fn each_rule_declares_its_strategies() {
    use crate::rules::{CornerRule, Overlap, RoundingOptions};
    let every = RoundingOptions {
        overlap: Overlap::Clamp,
        ..RoundingOptions::default()
    };
    assert!(
        every.mend.crossings,
        "the whole-level search is the default"
    );
    let mut clamp = every;
    clamp.mend.crossings = false;
    let plain = RoundingOptions {
        overlap: Overlap::Refuse,
        ..clamp
    };
    let comb = CornerRule::Combination { r: 0.1 };
    assert_eq!(comb.mends(&plain)[0], Mend::FoldGuard);
    assert!(!comb.mends(&plain).contains(&Mend::EveryCrossing));
    assert!(comb.mends(&every).contains(&Mend::EveryCrossing));
    for rule in [CornerRule::DooSabin, CornerRule::Cylindrical { r: 0.1 }] {
        assert!(rule.mends(&every).is_empty(), "{rule:?}");
    }
    let chamfer = CornerRule::CutWidth { d: 0.1 };
    assert!(chamfer.mends(&plain).is_empty());
    assert_eq!(
        chamfer.mends(&clamp),
        [Mend::Untangle, Mend::SmallChamfers, Mend::SelfCrossings]
    );
    // Every plan runs in the stage's order.
    for rule in [comb, chamfer, CornerRule::Minimum { r: 0.1 }] {
        let plan = rule.mends(&every);
        assert!(plan.windows(2).all(|w| w[0] < w[1]), "{plan:?}");
    }
}
