//! What a corner rule computes from a level before it places points: the topology and face
//! normals every rule reads, and what only some rules need — the cylindrical family merges
//! coplanar faces and turns bend angles and edge radii into per-edge cut widths
//! ([`super::cylindrical::prepare`]); the combination rule continues its run's
//! [`CombinationState`]. The step ([`crate::step`]) stays generic: prepare, place, split.

use super::RoundingOptions;
use super::StepError;
use super::cylindrical;
use super::prepared::{Prepared, checked_level};
use super::{CornerRule, combination::CombinationState};
use crate::edge_attrs::EdgeAttrs;
use crate::error::MeshError;
use crate::mesh::PolyMesh;
use crate::topology::Topology;
use std::borrow::Cow;

/// The level with its checked topology and normals, as every rule needs it.
fn plain<'a>(
    mesh: &'a PolyMesh,
    edge_attrs: &'a EdgeAttrs,
    known: Option<Topology>,
    options: &RoundingOptions,
) -> Result<Prepared<'a>, MeshError> {
    let (topo, _, normals) = checked_level(mesh, known)?;
    Ok(Prepared {
        mesh: Cow::Borrowed(mesh),
        edge_attrs: Cow::Borrowed(edge_attrs),
        topo,
        normals,
        cut_widths: Vec::new(),
        face_params: Vec::new(),
        clamped_faces: 0,
        offset_faces: 0,
        combination: None,
        dissolved_edges: 0,
        clamped: Vec::new(),
        capped_edges: Vec::new(),
        options: *options,
    })
}

impl CornerRule {
    /// Prepares `mesh` (checked closed) for this rule. `state` is the combination state of
    /// `mesh` when the step before was a combination step; only the combination rule reads
    /// it. `options` give the bend angle below which the cylindrical family merges an edge's
    /// faces and what it does with radii that do not fit ([`super::Overlap`]). `known` is
    /// `mesh`'s topology when the split that made it wrote it down
    /// ([`crate::refine::dual_quad::topology`]); else it is built and checked.
    pub fn prepare<'a>(
        &self,
        mesh: &'a PolyMesh,
        attrs: &'a EdgeAttrs,
        state: Option<&CombinationState>,
        options: &RoundingOptions,
        known: Option<Topology>,
    ) -> Result<Prepared<'a>, StepError> {
        let state = match self {
            CornerRule::Combination { .. } => state.map(|s| s.flags.as_slice()),
            _ => None,
        };
        if self.is_cylindrical_family() {
            return cylindrical::prepare(self, mesh, attrs, state, options, known);
        }
        let mut prep = plain(mesh, attrs, known, options)?;
        if options.overlap == super::Overlap::Clamp {
            let (params, lowered) = super::chamfer::face_params(&prep.input(), self);
            prep.face_params = params;
            if matches!(self, CornerRule::DooSabin) {
                prep.offset_faces = lowered;
            } else {
                prep.clamped_faces = lowered;
            }
        }
        Ok(prep)
    }

    /// The radius this rule rounds an edge with attributes `attr` to: the edge's own radius,
    /// else the rule's r (`None` for rules without one).
    pub fn edge_radius(&self, attr: Option<&crate::EdgeAttr>) -> Option<f64> {
        let r = self.radius()?;
        let own = attr.and_then(|a| a.radius).unwrap_or(r);
        Some(attr.and_then(|a| a.fits).map_or(own, |fits| own.min(fits)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::edge_attrs::{EdgeAttr, EdgeKey};
    use crate::primitives;
    use crate::rules::cut_width;
    use std::f64::consts::FRAC_PI_2;

    /// The cylindrical family's preparation: one width per edge from its bend angle and its
    /// radius (the edge's own overriding the rule's r); the other rules get none.
    #[test]
    fn cut_widths_follow_the_edge_radius() {
        let m = primitives::cube3();
        let topo = Topology::build(&m).unwrap();
        let (a, b) = topo.edge_verts(&m, 0);
        let mut attrs = EdgeAttrs::new();
        let own = EdgeAttr::rounded(0.05);
        attrs.insert(EdgeKey::new(a, b), own);
        let rule = CornerRule::Cylindrical { r: 0.2 };
        let p = rule
            .prepare(&m, &attrs, None, &RoundingOptions::default(), None)
            .unwrap();
        assert_eq!(p.dissolved_edges, 0);
        assert_eq!(p.cut_widths.len(), 12);
        for (e, &x) in p.cut_widths.iter().enumerate() {
            let r = if e == 0 { 0.05 } else { 0.2 };
            assert!((x - cut_width(r, FRAC_PI_2)).abs() < 1e-15, "edge {e}: {x}");
        }
        assert_eq!(rule.edge_radius(Some(&own)), Some(0.05));
        assert_eq!(rule.edge_radius(None), Some(0.2));
        assert_eq!(CornerRule::DooSabin.edge_radius(Some(&own)), None);
        let q = CornerRule::DooSabin
            .prepare(&m, &attrs, None, &RoundingOptions::default(), None)
            .unwrap();
        assert!(q.cut_widths.is_empty() && matches!(q.mesh, Cow::Borrowed(_)));
    }

    /// Only the combination rule reads the run's state; flat edges are merged first and
    /// the state follows the merged faces — except flat edges beside a vertex-blend face,
    /// which stay (cylindrical.md, "Flat edges": Doo–Sabin needs no cut width there).
    #[test]
    fn the_combination_state_is_read_by_the_combination_rule_only() {
        // A triangulated cube: each face's diagonal is flat.
        let m = primitives::fan_triangulated(&primitives::cube3());
        let attrs = EdgeAttrs::new();
        let comb = CornerRule::Combination { r: 0.1 };
        let prepared = |flag: bool| {
            let state = CombinationState {
                flags: vec![flag; m.num_faces()],
            };
            comb.prepare(&m, &attrs, Some(&state), &RoundingOptions::default(), None)
                .unwrap()
        };
        // Outside the blend the diagonals are merged away.
        let p = prepared(false);
        let flags = p.combination.as_ref().expect("continues the run");
        assert_eq!(flags.len(), p.mesh.num_faces());
        assert!(flags.iter().all(|&f| !f));
        assert_eq!(p.dissolved_edges, 6);
        assert_eq!((p.mesh.num_faces(), p.topo.num_edges()), (6, 12));
        assert_eq!(p.cut_widths.len(), 12);
        // Blend faces keep them.
        let p = prepared(true);
        assert!(p.combination.as_ref().unwrap().iter().all(|&f| f));
        assert_eq!(p.dissolved_edges, 0);
        assert_eq!((p.mesh.num_faces(), p.topo.num_edges()), (12, 18));
        let state = CombinationState {
            flags: vec![true; m.num_faces()],
        };
        let cyl = CornerRule::Cylindrical { r: 0.1 };
        assert!(
            cyl.prepare(&m, &attrs, Some(&state), &RoundingOptions::default(), None)
                .unwrap()
                .combination
                .is_none()
        );
    }
}
