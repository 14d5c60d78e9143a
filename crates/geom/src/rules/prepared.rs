//! A level made ready for a rule ([`Prepared`]) and the checks every rule's preparation
//! starts with; `prepare.rs` chooses each rule's preparation.

use super::RuleInput;
use crate::edge_attrs::EdgeAttrs;
use crate::error::MeshError;
use crate::geometry::{face_normals_raw, unit_or_zero};
use crate::mesh::PolyMesh;
use crate::topology::Topology;
use glam::DVec3;
use std::borrow::Cow;

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
    /// Per-face l, d or α of a clamped chamfer, or Doo–Sabin's width-offset share (negative:
    /// eq. (1)); empty otherwise ([`super::RuleInput::face_params`]).
    pub face_params: Vec<f64>,
    /// Faces whose l or d the clamp lowered.
    pub clamped_faces: usize,
    /// Faces whose Doo–Sabin points the clamp took from the width offset (concave.rs).
    pub offset_faces: usize,
    /// The combination run's flags on `mesh`, when this step continues a run.
    pub combination: Option<Vec<bool>>,
    /// Flat edges merged away.
    pub dissolved_edges: usize,
    /// Edges whose radius was lowered to fit their faces ([`super::overlap`]), named in the
    /// input's numbering.
    pub clamped: Vec<super::EdgeFit>,
    /// Edges whose cut width this step lowered so that its cut faces keep their edges (the
    /// combination rule's guard), ascending.
    pub capped_edges: Vec<u32>,
    /// The step's tolerances, which the rule reads through [`RuleInput::options`].
    pub options: super::RoundingOptions,
}

impl<'a> Prepared<'a> {
    /// What the rule's point function reads.
    pub fn input(&self) -> RuleInput<'_> {
        RuleInput {
            mesh: &self.mesh,
            topo: &self.topo,
            normals: &self.normals,
            cut_widths: &self.cut_widths,
            face_params: &self.face_params,
            vertex_neighbourhood: self.combination.as_deref().unwrap_or(&[]),
            options: &self.options,
        }
    }
}

/// What every rule reads of `mesh`: its topology (`known` when the split that made it wrote
/// it down, else built and checked closed), its raw Newell normals and their unit vectors.
pub(super) fn checked_level(
    mesh: &PolyMesh,
    known: Option<Topology>,
) -> Result<(Topology, Vec<DVec3>, Vec<DVec3>), MeshError> {
    let topo = match known {
        Some(t) => t,
        None => {
            let t = Topology::build(mesh)?;
            t.require_closed(mesh)?;
            t
        }
    };
    let raw = face_normals_raw(mesh);
    let normals = {
        use rayon::prelude::*;
        raw.par_iter()
            .with_min_len(4096)
            .map(|&n| unit_or_zero(n))
            .collect()
    };
    Ok((topo, raw, normals))
}
