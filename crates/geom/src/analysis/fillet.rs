//! The fillet radius actually reached along an edge (docs/algorithms/cylindrical.md).
//!
//! The refined mesh is sliced with the plane through the midpoint of the original edge and
//! normal to it. The section points of the fillet are those within the tangent length
//! `r·tan(|ψ|/2)` of the edge (ψ its bend angle): the arc between the two tangent points.
//! A circle is fitted to them (algebraic fit, then Gauss–Newton on the geometric distance),
//! and each point's distance to the *ideal* axis — on the bisector at `r/cos(ψ/2)` from the
//! edge, inside for a convex edge, outside for a concave one — is compared with r. Repeated
//! cylindrical cutting gives a polygon circumscribing the arc whose vertices lie at
//! `r/cos(ψ/2^(k+1))` after k steps: the error falls by about 4 per level.

use crate::geometry::{face_normal_raw, unit_or_zero};
use crate::mesh::PolyMesh;
use crate::topology::Topology;
use glam::{DVec2, DVec3};
use thiserror::Error;

#[derive(Debug, Clone, PartialEq, Error)]
pub enum FilletError {
    #[error("the original mesh has no edge {a}-{b}")]
    NoSuchEdge { a: u32, b: u32 },
    #[error("edge {a}-{b} is flat: it has no fillet")]
    FlatEdge { a: u32, b: u32 },
    #[error(
        "the section through edge {a}-{b} has only {points} fillet point(s); at least 2 are needed"
    )]
    TooFewPoints { a: u32, b: u32, points: usize },
    #[error(transparent)]
    Mesh(#[from] crate::error::MeshError),
}

/// What the section through one edge shows.
#[derive(Debug, Clone, PartialEq)]
pub struct FilletMeasure {
    /// Section points used.
    pub points: usize,
    /// Radius of the best-fitting circle (with only 2 points: their mean distance to the
    /// ideal axis).
    pub fitted_radius: f64,
    /// Distance of the fitted centre from the ideal axis.
    pub centre_offset: f64,
    /// max over the points of (distance to the ideal axis − r) / r.
    pub max_radial_error: f64,
    /// min over the points of the same (negative: some point inside the ideal cylinder).
    pub min_radial_error: f64,
    /// Whether the edge was concave (the fillet adds material).
    pub concave: bool,
}

/// Measures the fillet of original edge `a`-`b` (vertex indices of `original`) in `refined`,
/// for target radius `r`.
pub fn measure_fillet(
    original: &PolyMesh,
    a: u32,
    b: u32,
    refined: &PolyMesh,
    r: f64,
) -> Result<FilletMeasure, FilletError> {
    let topo = Topology::build(original)?;
    let cv = &original.corner_verts;
    let c = (0..original.num_corners())
        .find(|&c| cv[c] == a && cv[topo.next[c] as usize] == b)
        .or_else(|| {
            (0..original.num_corners()).find(|&c| cv[c] == b && cv[topo.next[c] as usize] == a)
        })
        .ok_or(FilletError::NoSuchEdge { a, b })?;
    let t = topo.twin[c];
    if t == crate::topology::NONE {
        return Err(FilletError::NoSuchEdge { a, b });
    }
    let nl = unit_or_zero(face_normal_raw(original, topo.corner_face[c] as usize));
    let nr = unit_or_zero(face_normal_raw(
        original,
        topo.corner_face[t as usize] as usize,
    ));
    let pa = original.positions[cv[c] as usize];
    let pb = original.positions[cv[topo.next[c] as usize] as usize];
    let psi = crate::geometry::angle_between(nl, nr);
    if psi < 1e-9 {
        return Err(FilletError::FlatEdge { a, b });
    }
    let concave = nl.cross(nr).dot(pb - pa) < 0.0;
    let mid = 0.5 * (pa + pb);
    let axis = (pb - pa).normalize();
    let bis = unit_or_zero(nl + nr);
    let centre = if concave {
        mid + bis * r / (psi / 2.0).cos()
    } else {
        mid - bis * r / (psi / 2.0).cos()
    };
    let reach = r * (psi / 2.0).tan() * (1.0 + 1e-6) + 1e-12 * refined.bbox_diagonal();

    // Slice: every undirected edge once (a < b), plus vertices on the plane.
    let mut pts: Vec<DVec3> = Vec::new();
    let side = |p: DVec3| (p - mid).dot(axis);
    for l in 0..refined.num_loops() {
        let vs = refined.loop_verts(l);
        for i in 0..vs.len() {
            let (u, w) = (vs[i], vs[(i + 1) % vs.len()]);
            let (pu, pw) = (refined.positions[u as usize], refined.positions[w as usize]);
            let (su, sw) = (side(pu), side(pw));
            if u < w && ((su < 0.0 && sw > 0.0) || (su > 0.0 && sw < 0.0)) {
                pts.push(pu + (pw - pu) * (su / (su - sw)));
            }
        }
    }
    let mut seen = vec![false; refined.num_vertices()];
    for (v, p) in refined.positions.iter().enumerate() {
        if side(*p) == 0.0 && !seen[v] {
            seen[v] = true;
            pts.push(*p);
        }
    }
    pts.retain(|p| (*p - mid).length() <= reach);
    if pts.len() < 2 {
        return Err(FilletError::TooFewPoints {
            a,
            b,
            points: pts.len(),
        });
    }
    let u = bis;
    let w = axis.cross(u);
    let to2 = |p: DVec3| DVec2::new((p - mid).dot(u), (p - mid).dot(w));
    let p2: Vec<DVec2> = pts.iter().map(|&p| to2(p)).collect();
    // Two points (level 1: the chord's ends) do not fix a circle: report their mean
    // distance to the ideal axis instead.
    let (cfit, rfit) = if p2.len() >= 3 {
        fit_circle(&p2)
    } else {
        let c2 = to2(centre);
        (
            c2,
            p2.iter().map(|p| (*p - c2).length()).sum::<f64>() / p2.len() as f64,
        )
    };
    let mut max_e = f64::NEG_INFINITY;
    let mut min_e = f64::INFINITY;
    for p in &pts {
        let d = *p - centre;
        let radial = (d - axis * d.dot(axis)).length();
        let e = (radial - r) / r;
        max_e = max_e.max(e);
        min_e = min_e.min(e);
    }
    Ok(FilletMeasure {
        points: pts.len(),
        fitted_radius: rfit,
        centre_offset: (cfit - to2(centre)).length(),
        max_radial_error: max_e,
        min_radial_error: min_e,
        concave,
    })
}

/// Least-squares circle: Kåsa's algebraic fit refined by Gauss–Newton on the geometric
/// distances. Returns (centre, radius).
pub fn fit_circle(p: &[DVec2]) -> (DVec2, f64) {
    // Centre the data for conditioning.
    let mean: DVec2 = p.iter().copied().sum::<DVec2>() / p.len() as f64;
    let q: Vec<DVec2> = p.iter().map(|&x| x - mean).collect();
    // Solve [Σxx Σxy Σx; Σxy Σyy Σy; Σx Σy n] [D E F]ᵀ = −[Σx z, Σy z, Σz], z = x² + y².
    let mut m = [[0.0f64; 3]; 3];
    let mut rhs = [0.0f64; 3];
    for v in &q {
        let row = [v.x, v.y, 1.0];
        let z = v.length_squared();
        for i in 0..3 {
            for j in 0..3 {
                m[i][j] += row[i] * row[j];
            }
            rhs[i] -= row[i] * z;
        }
    }
    let sol = solve3(m, rhs);
    let mut c = DVec2::new(-sol[0] / 2.0, -sol[1] / 2.0);
    let mut r = (c.length_squared() - sol[2]).max(0.0).sqrt();
    for _ in 0..20 {
        // Gauss–Newton on residuals |q − c| − r, unknowns (cx, cy, r).
        let mut jtj = [[0.0f64; 3]; 3];
        let mut jtr = [0.0f64; 3];
        for v in &q {
            let d = *v - c;
            let len = d.length();
            if len == 0.0 {
                continue;
            }
            let res = len - r;
            let jrow = [-d.x / len, -d.y / len, -1.0];
            for i in 0..3 {
                for j in 0..3 {
                    jtj[i][j] += jrow[i] * jrow[j];
                }
                jtr[i] -= jrow[i] * res;
            }
        }
        let step = solve3(jtj, jtr);
        if !step.iter().all(|s| s.is_finite()) {
            break;
        }
        c += DVec2::new(step[0], step[1]);
        r += step[2];
        if step.iter().map(|s| s.abs()).fold(0.0, f64::max) < 1e-15 * r.max(1.0) {
            break;
        }
    }
    (c + mean, r)
}

fn solve3(m: [[f64; 3]; 3], b: [f64; 3]) -> [f64; 3] {
    let det = |m: &[[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(&m);
    let mut out = [0.0; 3];
    for (k, o) in out.iter_mut().enumerate() {
        let mut mk = m;
        for i in 0..3 {
            mk[i][k] = b[i];
        }
        *o = det(&mk) / d;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn circle_fit_recovers_a_circle() {
        let pts: Vec<DVec2> = (0..7)
            .map(|k| {
                let t = 0.2 * k as f64;
                DVec2::new(3.0 + 0.45 * t.cos(), -1.0 + 0.45 * t.sin())
            })
            .collect();
        let (c, r) = fit_circle(&pts);
        assert!((c - DVec2::new(3.0, -1.0)).length() < 1e-12);
        assert!((r - 0.45).abs() < 1e-12);
    }
}
