//! One biquadratic step with a corner rule, from a mesh to the next level, with everything a
//! user needs to see: counts, flipped and degenerate faces, time (docs/algorithms/biquadratic.md).
//!
//! Order of work: build and check the topology (closed solids only, §1.4); validate the
//! rule's parameter; for the cylindrical family dissolve flat edges (§2.5) and compute the
//! per-edge cut widths from the bend angles of the *current* mesh; place the corner points;
//! split (§1.2); carry edge attributes and vertex-neighbourhood flags; report.
//!
//! A new face is **flipped** when its Newell normal points against its parent element's
//! normal (`n_f`, `n_L + n_R`, or Σ n_f around the vertex) and **degenerate** when its area is
//! below 1e-14·D² (D the bounding-box diagonal). Neither is hidden: both are listed.

use crate::biquadratic::{self, FaceKind, Provenance};
use crate::dissolve::{DissolveError, dissolve_flat_edges};
use crate::edge_attrs::{self, EdgeAttrs};
use crate::error::{MeshError, OverBudget};
use crate::geometry::{
    face_normal_and_volume6, face_normals_raw, loop_newell, signed_bend_angles, unit_or_zero,
};
use crate::mesh::PolyMesh;
use crate::rules::{self, CornerRule, ParamError, RuleError, RuleInput};
use crate::topology::Topology;
use glam::DVec3;
use std::time::Instant;
use thiserror::Error;

/// Faces whose area is below this × D² are degenerate.
pub const DEGENERATE_AREA: f64 = 1e-14;

/// Tunables of a step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepOptions {
    /// Edges with |bend angle| below this (radians) are flat and dissolved before a
    /// cylindrical-family step.
    pub flat_tolerance: f64,
    /// A step whose result would need more bytes than this is refused before it starts.
    pub memory_budget: u64,
}

impl Default for StepOptions {
    fn default() -> Self {
        StepOptions {
            flat_tolerance: 1e-6,
            memory_budget: 8 << 30,
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
    /// Corners with a zero-length edge that stayed at their vertex.
    pub collapsed_corners: usize,
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
    /// Vertex-neighbourhood flags of the new faces (combination rule only).
    pub vertex_neighbourhood: Option<Vec<bool>>,
    /// The parent after the flat-edge dissolve, when that changed it (provenance refers
    /// to it).
    pub dissolved_parent: Option<PolyMesh>,
    pub report: StepReport,
}

/// One biquadratic step of `mesh` with `rule`. `vn` are the vertex-neighbourhood flags of
/// `mesh` when the previous step was a combination step too (else `None`: first step of a
/// combination run).
pub fn biquadratic_step(
    mesh: &PolyMesh,
    attrs: &EdgeAttrs,
    rule: &CornerRule,
    vn: Option<&[bool]>,
    options: &StepOptions,
) -> Result<StepOutput, StepError> {
    let start = Instant::now();
    rule.validate()?;
    let mut topo = Topology::build(mesh)?;
    topo.require_closed(mesh)?;
    let mut raw = face_normals_raw(mesh);
    let mut normals: Vec<DVec3> = raw.iter().map(|&n| unit_or_zero(n)).collect();

    let mut dissolved: Option<crate::dissolve::Dissolved> = None;
    let mut bends = Vec::new();
    if rule.is_cylindrical_family() {
        bends = signed_bend_angles(mesh, &topo, &normals);
        let flags = vn.unwrap_or(&[]);
        if let Some(d) = dissolve_flat_edges(
            mesh,
            &topo,
            &bends,
            &raw,
            flags,
            attrs,
            options.flat_tolerance,
        )? {
            topo = Topology::build(&d.mesh)?;
            topo.require_closed(&d.mesh)?;
            raw = face_normals_raw(&d.mesh);
            normals = raw.iter().map(|&n| unit_or_zero(n)).collect();
            bends = signed_bend_angles(&d.mesh, &topo, &normals);
            dissolved = Some(d);
        }
    }
    let (cur, cur_attrs, cur_vn): (&PolyMesh, &EdgeAttrs, Option<&[bool]>) = match &dissolved {
        Some(d) => (&d.mesh, &d.edge_attrs, vn.map(|_| d.face_flags.as_slice())),
        None => (mesh, attrs, vn),
    };

    OverBudget::check(
        biquadratic::estimated_bytes(cur, topo.num_edges()),
        options.memory_budget,
        (cur.num_faces() + topo.num_edges() + cur.num_vertices()) as u64,
    )?;

    let mut widths = Vec::new();
    if let Some(r) = rule.radius() {
        let radii = edge_attrs::edge_radii(cur, &topo, cur_attrs, r);
        widths = Vec::with_capacity(bends.len());
        for (e, (&psi, &re)) in bends.iter().zip(&radii).enumerate() {
            let x = rules::cut_width(re, psi);
            if !x.is_finite() {
                let (a, b) = topo.edge_verts(cur, e);
                return Err(RuleError::KnifeEdge {
                    a,
                    b,
                    bend_deg: psi.to_degrees(),
                }
                .into());
            }
            widths.push(x);
        }
    }
    let first_vn;
    let vn_in: &[bool] = match (rule, cur_vn) {
        (CornerRule::Combination { .. }, Some(f)) => f,
        _ => {
            first_vn = Vec::new();
            &first_vn
        }
    };
    let input = RuleInput {
        mesh: cur,
        topo: &topo,
        normals: &normals,
        cut_widths: &widths,
        vertex_neighbourhood: vn_in,
    };
    let (points, rule_report) = rules::corner_points(rule, &input)?;
    let (out, prov) = biquadratic::split(cur, &topo, points);
    let new_attrs = edge_attrs::propagate_biquadratic(cur, &topo, cur_attrs);
    let new_vn = matches!(rule, CornerRule::Combination { .. })
        .then(|| biquadratic::vertex_neighbourhood_flags(cur, &topo, &prov, cur_vn));
    let checked = check_children(cur, &topo, &normals, &out, &prov);
    let report = StepReport {
        vertices: out.num_vertices(),
        edges: 4 * topo.num_edges(),
        faces: out.num_faces(),
        flipped: checked.flipped,
        degenerate: checked.degenerate,
        dissolved_edges: dissolved.as_ref().map_or(0, |d| d.dissolved_edges),
        guarded_corners: rule_report.guarded_corners,
        collapsed_corners: rule_report.collapsed_corners,
        volume: checked.volume,
        millis: start.elapsed().as_secs_f64() * 1e3,
    };
    Ok(StepOutput {
        mesh: out,
        provenance: prov,
        edge_attrs: new_attrs,
        vertex_neighbourhood: new_vn,
        dissolved_parent: dissolved.map(|d| d.mesh),
        report,
    })
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
    let mut vsum = vec![DVec3::ZERO; parent.num_vertices()];
    for c in 0..parent.num_corners() {
        vsum[parent.corner_verts[c] as usize] += parent_normals[topo.corner_face[c] as usize];
    }
    let d = child.bbox_diagonal();
    let tiny = DEGENERATE_AREA * d * d;
    let mut out = ChildCheck::default();
    let mut v6 = 0.0;
    let single_loop = child.num_loops() == child.num_faces();
    for f in 0..child.num_faces() {
        let (n, fv) = if single_loop {
            // Hole-free child (the usual case): the loop is the face.
            let vs = child.loop_verts(f);
            let n = loop_newell(child, vs);
            (n, 2.0 * child.positions[vs[0] as usize].dot(n))
        } else {
            face_normal_and_volume6(child, f)
        };
        v6 += fv;
        let p = prov.face_parent[f] as usize;
        let np = match prov.face_kind[f] {
            FaceKind::Face => parent_normals[p],
            FaceKind::Edge => {
                let c = topo.edge_corner[p] as usize;
                parent_normals[topo.corner_face[c] as usize]
                    + parent_normals[topo.corner_face[topo.twin[c] as usize] as usize]
            }
            FaceKind::Vertex => vsum[p],
        };
        if n.length_squared() < tiny * tiny {
            out.degenerate.push(f as u32);
        } else if n.dot(np) < 0.0 {
            out.flipped.push(f as u32);
        }
    }
    out.volume = v6 / 6.0;
    out
}
