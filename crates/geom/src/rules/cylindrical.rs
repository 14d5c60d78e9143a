//! The cylindrical family of seed 000 §3.2 (docs/algorithms/cylindrical.md): its
//! preparation of a level ([`prepare`]: flat-edge merge, cut widths) and its corner points.
//!
//! **Cut width** (eq. 3): to round an edge of bend angle ψ (θ = π − ψ between the faces) to
//! radius r, each face is cut parallel to the edge at width `x = 2r(1 − sin(θ/2))/sin θ`.
//! Prism uses only the stable equivalent `x = r·tan(|ψ|/4)/cos(|ψ|/2)` (eq. 3 is 0/0 at a
//! flat edge and returns exactly 0 for ψ ≤ 1e-8). The absolute value makes concave edges
//! fill: the points still move into the faces and the EDGE-face bridges the notch.
//!
//! **Simple type** (eq. 4): each corner goes to where the two lines drawn inside the face
//! parallel to its edges at their widths `x₁ = x(E₁)`, `x₂ = x(E₂)` meet. Printed as
//! `V' = V + (x₂/sin φ)u₁ + (x₁/sin φ)u₂` (the crossed indices are right); implemented in the
//! split form `V' = V + x̄(m₁ + m₂)/(1 + c) + δ(m₁ − m₂)/(1 − c)` with x̄ = (x₁+x₂)/2,
//! δ = (x₁−x₂)/2, whose first term is finite for every φ ∈ (0, 2π) and whose second is
//! singular only at a straight corner with unequal widths: there the along-edge shift is
//! capped at ¼ of the shorter adjacent edge and the corner is counted. In a combination
//! run, an acute corner beside a vertex blend is set back by the blend edge's width x, not
//! x/sin φ (equal at 90°), so oblique strip ends turn square instead of shearing until the
//! surface folds (cylindrical.md, "Set-back beside a blend").
//!
//! **Minimum type** (eq. 5): `V' = V + u₁·min(x₂/sin φ, ¼|e₁|) + u₂·min(x₁/sin φ, ¼|e₂|)`;
//! at reflex corners the magnitude is capped and the sign kept. It never flips in the
//! paper's tests but does not converge to r (it stalls near 0.2 % of r, §2.7).

use super::RoundingOptions;
use super::StepError;
use super::overlap::{EdgeFit, Overlap, fitting_scales};
use super::prepared::Prepared;
use super::{CornerRule, RuleError, RuleInput, RuleReport, corner_frame_on_edges};
use crate::dissolve::dissolve_flat_edges;
use crate::edge_attrs::{EdgeAttrs, EdgeKey};
use crate::geometry::signed_bend_angles;
use crate::mesh::PolyMesh;
use crate::topology::Topology;
use glam::DVec3;
use rayon::prelude::*;
use std::borrow::Cow;

/// Straight-corner threshold on 1 − c (c = m₁·m₂ = −cos φ) for the δ term (§2.6).
const STRAIGHT_CORNER: f64 = 1e-12;

/// Edges a task of rayon's pool takes at least in the per-edge passes.
const PAR_MIN: usize = 4096;

/// Below this cos(ψ/2) an edge is a knife edge (faces folded onto each other): the cut
/// width would exceed 1e12 r.
const KNIFE_EDGE_COS: f64 = 1e-12;

/// Cut width of an edge of bend angle `psi` for radius `r`: `r·tan(|ψ|/4)/cos(|ψ|/2)`.
/// Infinite for a knife edge (ψ = π).
pub fn cut_width(r: f64, psi: f64) -> f64 {
    let a = psi.abs();
    let c = (a / 2.0).cos();
    if c < KNIFE_EDGE_COS {
        return f64::INFINITY;
    }
    r * (a / 4.0).tan() / c
}

/// Each edge's radius: its own where `attrs` gives one, else the rule's r
/// ([`CornerRule::edge_radius`]). The marked edges are few beside the others (a clamped edge
/// and its descendants: 4,096 of 64,512 edges at the Computer room's fourth rounding level), so
/// each mark finds its edge in its first vertex's ring ([`Topology::find_edge`]) instead of
/// every edge searching the ordered map (2 ms of an edit at that level); a mark naming no edge
/// of `mesh` is ignored.
fn edge_radii(rule: &CornerRule, mesh: &PolyMesh, topo: &Topology, attrs: &EdgeAttrs) -> Vec<f64> {
    let radius = |attr| {
        rule.edge_radius(attr)
            .expect("the cylindrical family has a radius")
    };
    let mut radii = crate::parallel::filled(topo.num_edges(), radius(None));
    for (key, attr) in attrs {
        if let Some(e) = topo.find_edge(mesh, key.0, key.1) {
            radii[e as usize] = radius(Some(attr));
        }
    }
    radii
}

/// Whether an edge of bend angle `psi` is flat under tolerance `tol` and must be dissolved
/// before a cylindrical-family step.
pub fn dissolve_needed(psi: f64, tol: f64) -> bool {
    psi.abs() < tol
}

/// The family's preparation of a level (§2.5, eq. 3): the faces of flat edges
/// (|ψ| < the flat tolerance) are merged first, carrying the combination run's `flags`
/// along; then every edge gets its radius ([`CornerRule::edge_radius`]) and from it and its
/// bend angle its cut width. A knife edge (ψ = π) is refused, naming it.
///
/// Overlap ([`super::overlap`]): unless `options.overlap` is `Unchecked`, the finished
/// fillets' tangent lengths `r·tan(|ψ|/2)` must fit every face; the edges that do not are
/// refused or clamped (their lowered radius written as a cap, `fits`). The combination rule
/// then also fits this step's cut widths to its cut faces, counting the edges it lowers.
pub(super) fn prepare<'a>(
    rule: &CornerRule,
    mesh: &'a PolyMesh,
    attrs: &'a EdgeAttrs,
    flags: Option<&[bool]>,
    options: &RoundingOptions,
    known: Option<Topology>,
) -> Result<Prepared<'a>, StepError> {
    let tol = options.flat_tolerance;
    let level = |m: &PolyMesh, known| -> Result<_, StepError> {
        let (topo, raw, normals) = super::prepared::checked_level(m, known)?;
        let bends = signed_bend_angles(m, &topo, &normals);
        Ok((topo, raw, normals, bends))
    };
    let (mut topo, raw, mut normals, mut bends) = level(mesh, known)?;
    let mut p_mesh = Cow::Borrowed(mesh);
    let mut p_attrs = Cow::Borrowed(attrs);
    let mut p_flags = flags.map(<[bool]>::to_vec);
    let mut dissolved_edges = 0;
    let mut old_vertex = None;
    let flat = flat_edges(mesh, &topo, &bends, flags.unwrap_or(&[]), tol);
    let d = dissolve_flat_edges(mesh, &topo, &flat, &raw, flags.unwrap_or(&[]), attrs)?;
    if let Some(d) = d {
        (topo, _, normals, bends) = level(&d.mesh, None)?;
        dissolved_edges = d.dissolved_edges;
        p_flags = flags.map(|_| d.face_flags);
        p_mesh = Cow::Owned(d.mesh);
        p_attrs = Cow::Owned(d.edge_attrs);
        old_vertex = Some(d.old_vertex);
    }
    // Each edge's radius and its cut width's check on every core; the first knife edge in
    // edge order is named.
    let mut radii = edge_radii(rule, &p_mesh, &topo, &p_attrs);
    if let Some(e) =
        crate::parallel::first_where(bends.len(), |e| !cut_width(radii[e], bends[e]).is_finite())
    {
        let (a, b) = topo.edge_verts(&p_mesh, e);
        return Err(RuleError::KnifeEdge {
            a,
            b,
            bend_deg: bends[e].to_degrees(),
        }
        .into());
    }
    let skip = p_flags.as_deref().unwrap_or(&[]);
    let input = RuleInput {
        mesh: &p_mesh,
        topo: &topo,
        normals: &normals,
        cut_widths: &[],
        face_params: &[],
        vertex_neighbourhood: skip,
        options,
    };
    let mut clamped = Vec::new();
    if !matches!(options.overlap, Overlap::Unchecked { .. }) {
        let tangents: Vec<f64> = radii
            .par_iter()
            .with_min_len(PAR_MIN)
            .zip(&bends)
            .map(|(r, psi)| {
                if psi.abs() < tol {
                    0.0
                } else {
                    r * (psi.abs() / 2.0).tan()
                }
            })
            .collect();
        let scales = fitting_scales(&input, &tangents, skip, 1.0);
        let name = |v: u32| old_vertex.as_ref().map_or(v, |o: &Vec<u32>| o[v as usize]);
        for (e, &s) in scales.iter().enumerate() {
            if s < 1.0 {
                let (a, b) = topo.edge_verts(&p_mesh, e);
                let fit = EdgeFit {
                    a: name(a),
                    b: name(b),
                    radius: radii[e],
                    fits: radii[e] * s,
                };
                radii[e] = fit.fits;
                clamped.push(fit);
                // The lowered radius caps the edge's from now on, so the levels after keep
                // it (and a later step of a smaller r rounds it with that r).
                let attr = p_attrs.to_mut().entry(EdgeKey::new(a, b)).or_default();
                attr.fits = Some(fit.fits);
            }
        }
        if !clamped.is_empty() && options.overlap == Overlap::Refuse {
            return Err(RuleError::Overlap { edges: clamped }.into());
        }
    }
    let mut cut_widths: Vec<f64> = radii
        .par_iter()
        .with_min_len(PAR_MIN)
        .zip(&bends)
        .map(|(&r, &psi)| cut_width(r, psi))
        .collect();
    let mut capped_edges = Vec::new();
    if matches!(rule, CornerRule::Combination { .. }) {
        let scales = fitting_scales(&input, &cut_widths, skip, options.step_room);
        for (e, (x, s)) in cut_widths.iter_mut().zip(scales).enumerate() {
            if s < 1.0 {
                *x *= s;
                capped_edges.push(e as u32);
            }
        }
    }
    Ok(Prepared {
        mesh: p_mesh,
        edge_attrs: p_attrs,
        topo,
        normals,
        cut_widths,
        face_params: Vec::new(),
        clamped_faces: 0,
        offset_faces: 0,
        combination: p_flags,
        dissolved_edges,
        clamped,
        capped_edges,
        options: *options,
    })
}

/// The edges a cylindrical-family step merges away first (cylindrical.md, "Flat edges"): those
/// with |ψ| below the flat tolerance. In a combination run an edge with a vertex-blend face on
/// either side stays: the blend's Doo–Sabin points need no cut width, so nothing divides by
/// zero there, and merging blend faces made rings (a torus's flat top) where Doo–Sabin is
/// undefined — unless keeping it would leave a vertex with two edges at 120° or less (a blend
/// face kept as an island inside a merged face), whose VERTEX-face would have two corners.
fn flat_edges(
    mesh: &PolyMesh,
    topo: &Topology,
    bends: &[f64],
    flags: &[bool],
    tol: f64,
) -> Vec<bool> {
    let blend = |c: u32| {
        c != crate::topology::NONE
            && flags
                .get(topo.corner_face(c as usize) as usize)
                .copied()
                .unwrap_or(false)
    };
    let flat_by_bend: Vec<bool> = bends.iter().map(|&psi| dissolve_needed(psi, tol)).collect();
    let mut flat: Vec<bool> = flat_by_bend
        .iter()
        .zip(&topo.edge_corner)
        .map(|(&f, &c)| f && !(blend(c) || blend(topo.twin[c as usize])))
        .collect();
    // A vertex the merge would leave with two edges at 120° or less (a blend face kept as an
    // island in a merged face) would give a two-cornered VERTEX-face of no area: its flat
    // blend edges are merged after all. Only the ends of flat edges kept for a blend can be
    // such vertices; every one is judged on the same flags (no order).
    let mut ends: Vec<u32> = (0..flat.len())
        .filter(|&e| flat_by_bend[e] && !flat[e])
        .flat_map(|e| {
            let (a, b) = topo.edge_verts(mesh, e);
            [a, b]
        })
        .collect();
    ends.sort_unstable();
    ends.dedup();
    let mut merge = Vec::new();
    for v in ends {
        let kept: Vec<usize> = topo
            .corners_around(v as usize)
            .map(|c| topo.corner_edge[c as usize] as usize)
            .filter(|&e| !flat[e])
            .collect();
        if kept.len() != 2 {
            continue;
        }
        let p = mesh.positions[v as usize];
        let dir = |e: usize| {
            let (a, b) = topo.edge_verts(mesh, e);
            let o = if a == v { b } else { a };
            (mesh.positions[o as usize] - p).normalize_or_zero()
        };
        if dir(kept[0]).dot(dir(kept[1])) >= crate::dissolve::KINK_COS {
            merge.extend(kept);
        }
    }
    for e in merge {
        flat[e] |= flat_by_bend[e];
    }
    flat
}

fn widths(input: &RuleInput, c: usize) -> (f64, f64) {
    let t = input.topo;
    let x1 = input.cut_widths[t.corner_edge[c] as usize];
    let x2 = input.cut_widths[t.corner_edge[t.prev(c) as usize] as usize];
    (x1, x2)
}

pub(super) fn simple(
    input: &RuleInput,
    c: usize,
    report: &mut RuleReport,
) -> Result<DVec3, RuleError> {
    let fr = corner_frame_on_edges(input, c)?;
    let (x1, x2) = widths(input, c);
    if 1.0 + fr.c < STRAIGHT_CORNER {
        return Err(RuleError::NeedleCorner {
            face: input.topo.corner_face(c),
            vertex: input.mesh.corner_verts[c],
        });
    }
    if fr.c < 0.0 && fr.sin_phi > 0.0 && !input.vertex_neighbourhood.is_empty() {
        // An acute corner beside a vertex blend: the set-back along the other edge is the
        // blend edge's width itself, not width / sin φ (docs/algorithms/cylindrical.md,
        // "Set-back beside a blend"). Equal to eq. 4 at φ = 90°.
        let t = input.topo;
        let blend = |k: u32| {
            let tw = t.twin[k as usize];
            tw != crate::topology::NONE
                && input.vertex_neighbourhood[t.corner_face(tw as usize) as usize]
        };
        let (b1, b2) = (blend(c as u32), blend(t.prev(c)));
        if b1 || b2 {
            let a1 = if b2 { x2 } else { x2 / fr.sin_phi };
            let a2 = if b1 { x1 } else { x1 / fr.sin_phi };
            return Ok(fr.v + fr.u1 * a1 + fr.u2 * a2);
        }
    }
    let xbar = 0.5 * (x1 + x2);
    let delta = 0.5 * (x1 - x2);
    let mut p = fr.v + xbar * (fr.m1 + fr.m2) / (1.0 + fr.c);
    if delta == 0.0 {
        return Ok(p);
    }
    if 1.0 - fr.c < STRAIGHT_CORNER {
        // Straight corner with unequal widths: the two offset lines are parallel. Shift along
        // the edge, in the direction eq. (4) gives, capped at ¼ of the shorter edge.
        let cap = 0.25 * fr.e1.length().min(fr.e2.length());
        let s = fr.sin_phi.abs().max(f64::MIN_POSITIVE);
        let shift = ((x2 - x1).abs() / s).min(cap);
        let sign = (x2 - x1).signum() * if fr.sin_phi < 0.0 { -1.0 } else { 1.0 };
        p += sign * shift * fr.u1;
        report.guarded_corners += 1;
        return Ok(p);
    }
    p += delta * (fr.m1 - fr.m2) / (1.0 - fr.c);
    Ok(p)
}

pub(super) fn minimum(input: &RuleInput, c: usize) -> Result<DVec3, RuleError> {
    let fr = corner_frame_on_edges(input, c)?;
    let (x1, x2) = widths(input, c);
    let cap1 = 0.25 * fr.e1.length();
    let cap2 = 0.25 * fr.e2.length();
    let capped = |x: f64, cap: f64| {
        if fr.sin_phi == 0.0 {
            return if x == 0.0 { 0.0 } else { cap };
        }
        let a = x / fr.sin_phi;
        a.signum() * a.abs().min(cap)
    };
    Ok(fr.v + fr.u1 * capped(x2, cap1) + fr.u2 * capped(x1, cap2))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::PolyMesh;
    use crate::rules::{CornerRule, corner_points};
    use crate::topology::Topology;
    use std::f64::consts::{FRAC_PI_2, PI};

    #[test]
    fn stable_cut_width_equals_eq3() {
        for k in 1..100 {
            let theta = 0.05 + (PI - 0.1) * k as f64 / 100.0;
            let r = 0.7;
            let eq3 = 2.0 * r * (1.0 - (theta / 2.0).sin()) / theta.sin();
            let x = cut_width(r, PI - theta);
            assert!(((x - eq3) / eq3).abs() < 1e-12, "θ={theta}: {x} vs {eq3}");
        }
        assert_eq!(cut_width(1.0, 0.0), 0.0);
        // 90° edge: x = r(√2 − 1)·√2 = (2 − √2) r.
        assert!((cut_width(1.0, FRAC_PI_2) - (2.0 - 2f64.sqrt())).abs() < 1e-15);
        // Concave 90° edge: the same width (θ = 270°: +0.586 r).
        assert!((cut_width(1.0, -FRAC_PI_2) - 0.585_786_437_626_905).abs() < 1e-12);
        assert!(cut_width(1.0, PI).is_infinite());
    }

    /// A 45° corner beside a vertex blend (docs/algorithms/cylindrical.md, "Strip ends beside a
    /// blend"): the set-back along the strip is the blend edge's width x₂, not x₂/sin φ; the
    /// offset from the strip's long edge stays x₁. Without the blend it is eq. 4.
    #[test]
    fn an_acute_corner_beside_a_blend_is_set_back_by_the_width() {
        let (c, sn) = (FRAC_PI_2 / 2.0).sin_cos();
        let p = vec![
            DVec3::ZERO,
            DVec3::X,
            DVec3::new(1.0 + c, sn, 0.0),
            DVec3::new(c, sn, 0.0),
            DVec3::new(-1.0, 0.5, 0.0),
        ];
        let m = PolyMesh::from_polygons(p, &[vec![0, 1, 2, 3], vec![0, 3, 4]]);
        let t = Topology::build(&m).unwrap();
        let (x1, x2) = (0.01, 0.03);
        let mut widths = vec![0.0; t.num_edges()];
        widths[t.find_edge(&m, 0, 1).unwrap() as usize] = x1;
        widths[t.find_edge(&m, 3, 0).unwrap() as usize] = x2;
        let at_origin = |flags: &[bool]| {
            let input = RuleInput {
                mesh: &m,
                topo: &t,
                normals: &[DVec3::Z, DVec3::Z],
                cut_widths: &widths,
                face_params: &[],
                vertex_neighbourhood: flags,
                options: &crate::rules::RoundingOptions::default(),
            };
            let corner = m.face_corners(0).start;
            simple(&input, corner, &mut RuleReport::default()).unwrap()
        };
        let u2 = DVec3::new(c, sn, 0.0);
        let s = sn;
        let beside = at_origin(&[false, true]);
        assert!(
            (beside - (DVec3::X * x2 + u2 * x1 / s)).length() < 1e-15,
            "{beside}"
        );
        assert!((beside.y - x1).abs() < 1e-15, "the strip's offset stays x1");
        let alone = at_origin(&[false, false]);
        assert!(
            (alone - (DVec3::X * x2 / s + u2 * x1 / s)).length() < 1e-15,
            "{alone}"
        );
    }

    /// A unit square face with per-edge widths, corner 0 at the origin.
    fn square(widths: [f64; 4], rule: CornerRule) -> Vec<DVec3> {
        let p = vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
        let m = PolyMesh::from_polygons(p, &[vec![0, 1, 2, 3]]);
        let t = Topology::build(&m).unwrap();
        // Edge ids follow corner order on an open single face.
        let input = RuleInput {
            mesh: &m,
            topo: &t,
            normals: &[DVec3::Z],
            cut_widths: &widths,
            face_params: &[],
            vertex_neighbourhood: &[],
            options: &crate::rules::RoundingOptions::default(),
        };
        corner_points(&rule, &input).unwrap().0
    }

    fn assert_at(p: DVec3, want: DVec3) {
        assert!((p - want).length() < 1e-15, "{p} is not {want}");
    }

    #[test]
    fn simple_type_meets_the_offset_lines() {
        // Edge 0 (bottom, y=0) width 0.1, edge 3 (left, x=0) width 0.3.
        let p = square([0.1, 0.2, 0.05, 0.3], CornerRule::Cylindrical { r: 1.0 });
        assert_at(p[0], DVec3::new(0.3, 0.1, 0.0));
        assert_at(p[1], DVec3::new(0.8, 0.1, 0.0));
        assert_at(p[2], DVec3::new(0.8, 0.95, 0.0));
    }

    #[test]
    fn minimum_type_caps_at_a_quarter_edge() {
        let p = square([0.1, 0.2, 0.05, 0.3], CornerRule::Minimum { r: 1.0 });
        // Corner 0: shift along u1 (x) is x2 = 0.3 → capped at 0.25; along u2 (y) 0.1.
        assert_at(p[0], DVec3::new(0.25, 0.1, 0.0));
    }
}
