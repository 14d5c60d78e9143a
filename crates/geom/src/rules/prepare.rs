//! What a corner rule computes from a level before it places points: the topology and face
//! normals every rule reads, and what only some rules need — the cylindrical family merges
//! coplanar faces and turns bend angles and edge radii into per-edge cut widths
//! ([`super::cylindrical::prepare`]); the combination rule continues its run's
//! [`CombinationState`]. The step ([`crate::step`]) stays generic: prepare, place, split.

use super::cylindrical;
use super::{CornerRule, RuleError, RuleInput, combination::CombinationState};
use crate::dissolve::DissolveError;
use crate::edge_attrs::EdgeAttrs;
use crate::error::MeshError;
use crate::geometry::{face_normals_raw, unit_or_zero};
use crate::mesh::PolyMesh;
use crate::topology::Topology;
use glam::DVec3;
use std::borrow::Cow;
use thiserror::Error;

/// Why a rule could not prepare a level.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PrepareError {
    #[error(transparent)]
    Mesh(#[from] MeshError),
    #[error(transparent)]
    Dissolve(#[from] DissolveError),
    #[error(transparent)]
    Rule(#[from] RuleError),
}

/// A level made ready for a rule.
#[derive(Debug, Clone)]
pub struct Prepared<'a> {
    /// The level the points are placed on: the input, or (owned) the input after the
    /// cylindrical family merged its flat edges.
    pub mesh: Cow<'a, PolyMesh>,
    pub edge_attrs: Cow<'a, EdgeAttrs>,
    /// Topology of `mesh`, checked closed.
    pub topo: Topology,
    /// Unit face normals of `mesh`.
    pub normals: Vec<DVec3>,
    /// Per-edge cut widths (cylindrical family; empty otherwise).
    pub cut_widths: Vec<f64>,
    /// The combination run's flags on `mesh`, when this step continues a run.
    pub combination: Option<Vec<bool>>,
    /// Flat edges merged away.
    pub dissolved_edges: usize,
}

impl<'a> Prepared<'a> {
    /// What the rule's point function reads.
    pub fn input(&self) -> RuleInput<'_> {
        RuleInput {
            mesh: &self.mesh,
            topo: &self.topo,
            normals: &self.normals,
            cut_widths: &self.cut_widths,
            vertex_neighbourhood: self.combination.as_deref().unwrap_or(&[]),
        }
    }
}

/// The level with its checked topology and normals, as every rule needs it.
fn plain<'a>(mesh: &'a PolyMesh, edge_attrs: &'a EdgeAttrs) -> Result<Prepared<'a>, MeshError> {
    let topo = Topology::build(mesh)?;
    topo.require_closed(mesh)?;
    let normals = face_normals_raw(mesh)
        .into_iter()
        .map(unit_or_zero)
        .collect();
    Ok(Prepared {
        mesh: Cow::Borrowed(mesh),
        edge_attrs: Cow::Borrowed(edge_attrs),
        topo,
        normals,
        cut_widths: Vec::new(),
        combination: None,
        dissolved_edges: 0,
    })
}

impl CornerRule {
    /// Prepares `mesh` (checked closed) for this rule. `state` is the combination state of
    /// `mesh` when the step before was a combination step; only the combination rule reads
    /// it. `flat_tolerance` is the bend angle (radians) below which the cylindrical family
    /// merges an edge's faces.
    pub fn prepare<'a>(
        &self,
        mesh: &'a PolyMesh,
        attrs: &'a EdgeAttrs,
        state: Option<&CombinationState>,
        flat_tolerance: f64,
    ) -> Result<Prepared<'a>, PrepareError> {
        let state = match self {
            CornerRule::Combination { .. } => state.map(|s| s.flags.as_slice()),
            _ => None,
        };
        match self.radius() {
            Some(_) => cylindrical::prepare(self, mesh, attrs, state, flat_tolerance),
            None => Ok(plain(mesh, attrs)?),
        }
    }

    /// The radius this rule rounds an edge with attributes `attr` to: the edge's own radius,
    /// else the rule's r (`None` for rules without one).
    pub fn edge_radius(&self, attr: Option<&crate::EdgeAttr>) -> Option<f64> {
        let r = self.radius()?;
        Some(attr.and_then(|a| a.radius).unwrap_or(r))
    }
}
