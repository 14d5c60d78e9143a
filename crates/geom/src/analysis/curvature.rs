//! Discrete mean curvature per vertex of a polygon mesh, for the curvature colour map.
//!
//! The total mean curvature of a polyhedral surface is `∫H = ½ Σ_e |e| ψ_e` (Steiner's
//! formula for the parallel surface; ψ_e the signed bend angle, positive on a convex edge).
//! Half of each edge's share goes to either end and is divided by the vertex's area, the
//! face areas shared equally among their corners:
//!
//! `H_v = (¼ Σ_(e ∋ v) |e| ψ_e) / (Σ_(f ∋ v) A_f / n_f)`.
//!
//! On a cylinder of radius R sampled by an n-gon prism this gives `1/(2R)` exactly, on a
//! sphere `1/R` in the limit. It works on any polygon (no triangulation, so no diagonal
//! bias), is signed (concave regions negative), and a crease shows as a band of large
//! values whose width is one ring — the map is read away from creases.

use crate::error::MeshError;
use crate::geometry::{face_normals_raw, signed_bend_angles, unit_or_zero};
use crate::mesh::PolyMesh;
use crate::topology::Topology;

/// Mean curvature `H = (κ₁ + κ₂)/2` at every vertex (0 at unused vertices).
pub fn mean_curvature(mesh: &PolyMesh) -> Result<Vec<f64>, MeshError> {
    let topo = Topology::build(mesh)?;
    let raw = face_normals_raw(mesh);
    let normals: Vec<_> = raw.iter().map(|&n| unit_or_zero(n)).collect();
    let bends = signed_bend_angles(mesh, &topo, &normals);
    let nv = mesh.num_vertices();
    let mut integral = vec![0.0; nv];
    for (e, &psi) in bends.iter().enumerate() {
        let (a, b) = topo.edge_verts(mesh, e);
        let len = (mesh.positions[a as usize] - mesh.positions[b as usize]).length();
        let share = 0.25 * len * psi;
        integral[a as usize] += share;
        integral[b as usize] += share;
    }
    let mut area = vec![0.0; nv];
    for (f, n) in raw.iter().enumerate() {
        // The Newell vector's length is the face's area (holes subtracted).
        let corners = mesh.face_corners(f);
        let each = n.length() / corners.len() as f64;
        for c in corners {
            area[mesh.corner_verts[c] as usize] += each;
        }
    }
    Ok(integral
        .iter()
        .zip(&area)
        .map(|(&i, &a)| if a > 0.0 { i / a } else { 0.0 })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;

    /// A fine torus: at the outer equator H = (1/r + 1/(R + r))/2, at the inner one
    /// H = (1/r − 1/(R − r))/2 (smaller, the saddle region).
    #[test]
    fn a_torus_has_its_analytic_mean_curvature_at_both_equators() {
        let (big, small) = (3.0, 1.0);
        let m = primitives::torus(240, 120, big, small);
        let h = mean_curvature(&m).unwrap();
        let rho = |i: usize| m.positions[i].truncate().length();
        let outer = (0..m.num_vertices())
            .max_by(|&a, &b| rho(a).total_cmp(&rho(b)))
            .unwrap();
        let inner = (0..m.num_vertices())
            .min_by(|&a, &b| rho(a).total_cmp(&rho(b)))
            .unwrap();
        let want_outer = 0.5 * (1.0 / small + 1.0 / (big + small));
        let want_inner = 0.5 * (1.0 / small - 1.0 / (big - small));
        // The torus is oriented outward or inward; the sign follows the orientation.
        let s = h[outer].signum();
        assert!(
            (s * h[outer] - want_outer).abs() < 0.01 * want_outer,
            "{} vs {want_outer}",
            h[outer]
        );
        assert!(
            (s * h[inner] - want_inner).abs() < 0.01,
            "{} vs {want_inner}",
            h[inner]
        );
    }

    #[test]
    fn a_cube_is_convex_everywhere_and_a_flat_region_has_none() {
        let h = mean_curvature(&primitives::cube3()).unwrap();
        assert!(h.iter().all(|&x| x > 0.0));
        // The L-block's concave edge makes its two ends' vertices saddle-like: smaller.
        let l = mean_curvature(&primitives::l_block()).unwrap();
        assert!(l.iter().any(|&x| x < h[0]));
    }
}
