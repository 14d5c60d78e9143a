//! The three chamfer rules of seed 000 §3.1 (docs/algorithms/chamfers.md).
//!
//! - angle bisector, distance l: `V' = V + l·unit(m₁ + m₂)` (|m₁ + m₂| = 2 sin(φ/2), so the
//!   bisector exists for every φ in (0, 2π), reflex corners included);
//! - cut width d (every edge moved inwards by d): `V' = V + d(m₁ + m₂)/(1 + c)`, a point at
//!   distance d/sin(φ/2) along the bisector;
//! - vector sum α (eq. 2): `V' = V + α(e₁ + e₂)`; with [`ReflexMode::Inward`] the
//!   displacement is reversed at reflex corners.
//!
//! l and d are absolute: repeated at a constant value the new faces (about d wide) are cut
//! from both sides and flip from level 2; a pipeline shrinks them about 4× per step (§2.3).

use super::{ReflexMode, RuleError, RuleInput, corner_frame};
use glam::DVec3;

/// Below this |m₁ + m₂| (= 2 sin(φ/2)) a corner is a needle and has no bisector.
const NEEDLE_BISECTOR: f64 = 1e-12;

fn needle(input: &RuleInput, c: usize) -> RuleError {
    RuleError::NeedleCorner {
        face: input.topo.corner_face(c),
        vertex: input.mesh.corner_verts[c],
    }
}

pub(super) fn angle_bisector(input: &RuleInput, c: usize, l: f64) -> Result<DVec3, RuleError> {
    let fr = corner_frame(input, c)?;
    let s = fr.m1 + fr.m2;
    let len = s.length();
    if len < NEEDLE_BISECTOR {
        return Err(needle(input, c));
    }
    Ok(fr.v + l * s / len)
}

pub(super) fn cut_width(input: &RuleInput, c: usize, d: f64) -> Result<DVec3, RuleError> {
    let fr = corner_frame(input, c)?;
    if 1.0 + fr.c < NEEDLE_BISECTOR {
        return Err(needle(input, c));
    }
    Ok(fr.v + d * (fr.m1 + fr.m2) / (1.0 + fr.c))
}

/// Eq. (2) needs no face normal: only the reflex-inward option asks which corners are
/// reflex, and a face of no area has none (its corners keep the printed rule). So faces a
/// previous step flattened (α > ¼ folds them) do not stop the rule.
pub(super) fn vector_sum(
    input: &RuleInput,
    c: usize,
    alpha: f64,
    reflex: ReflexMode,
) -> Result<DVec3, RuleError> {
    let (m, t) = (input.mesh, input.topo);
    let at = |corner: u32| m.positions[m.corner_verts[corner as usize] as usize];
    let v = at(c as u32);
    let (e1, e2) = (at(t.next(c)) - v, at(t.prev(c)) - v);
    let face_normal = input.normals[t.corner_face(c) as usize];
    let reflex_corner = face_normal != DVec3::ZERO && face_normal.dot(e1.cross(e2)) < 0.0;
    let sign = if reflex == ReflexMode::Inward && reflex_corner {
        -1.0
    } else {
        1.0
    };
    Ok(v + sign * alpha * (e1 + e2))
}

/// The per-face clamp of the absolute chamfers (seed 000 §3.1, docs/algorithms/chamfers.md,
/// "Clamp"): a face's parameter is lowered so that no convex corner moves along either of its
/// edges by more than a quarter of the shorter one — along an edge, the cut-width point
/// moves `d·cot(φ/2)` and the bisector point `l·cos(φ/2)`. Returns the parameter of every
/// face and how many were lowered.
pub(super) fn face_params(input: &RuleInput, rule: &super::CornerRule) -> (Vec<f64>, usize) {
    let m = input.mesh;
    let p = match *rule {
        super::CornerRule::CutWidth { d } => d,
        super::CornerRule::AngleBisector { l } => l,
        _ => return (Vec::new(), 0),
    };
    // Along-edge move per unit of the parameter at a convex corner (c = m₁·m₂ = −cos φ):
    // cot(φ/2) = (1 − c)/sin φ for the cut width, cos(φ/2) = √((1 − c)/2) for the bisector.
    let along = |fr: &super::CornerFrame| match rule {
        super::CornerRule::CutWidth { .. } => (1.0 - fr.c) / fr.sin_phi,
        _ => ((1.0 - fr.c) / 2.0).max(0.0).sqrt(),
    };
    let mut lowered = 0;
    let params = (0..m.num_faces())
        .map(|f| {
            let mut x = p;
            for c in m.face_corners(f) {
                let Ok(fr) = corner_frame(input, c) else {
                    continue;
                };
                if fr.sin_phi <= 0.0 {
                    continue;
                }
                let room = 0.25 * fr.e1.length().min(fr.e2.length());
                let a = along(&fr);
                if a > 0.0 {
                    x = x.min(room / a);
                }
            }
            if x < p {
                lowered += 1;
            }
            x
        })
        .collect();
    (params, lowered)
}

#[cfg(test)]
mod tests {
    use crate::rules::{CornerRule, ReflexMode, RuleInput, corner_points};
    use crate::{mesh::PolyMesh, topology::Topology};
    use glam::DVec3;

    /// An L-shaped hexagon in the plane z = 0 (one reflex corner at (1,1)), as a single face.
    fn l_face() -> PolyMesh {
        let p = [(0., 0.), (2., 0.), (2., 1.), (1., 1.), (1., 2.), (0., 2.)]
            .map(|(x, y)| DVec3::new(x, y, 0.0))
            .to_vec();
        PolyMesh::from_polygons(p, &[vec![0, 1, 2, 3, 4, 5]])
    }

    fn points(rule: CornerRule) -> Vec<DVec3> {
        let m = l_face();
        let t = Topology::build(&m).unwrap();
        let n = vec![DVec3::Z];
        let input = RuleInput {
            mesh: &m,
            topo: &t,
            normals: &n,
            cut_widths: &[],
            face_params: &[],
            vertex_neighbourhood: &[],
        };
        corner_points(&rule, &input).unwrap().0
    }

    #[test]
    fn cut_width_by_hand() {
        let p = points(CornerRule::CutWidth { d: 0.1 });
        assert!((p[0] - DVec3::new(0.1, 0.1, 0.0)).length() < 1e-15);
        assert!((p[2] - DVec3::new(1.9, 0.9, 0.0)).length() < 1e-15);
        // Reflex corner (1,1): the offset lines meet at (0.9, 0.9).
        assert!((p[3] - DVec3::new(0.9, 0.9, 0.0)).length() < 1e-15);
    }

    #[test]
    fn angle_bisector_by_hand() {
        let l = 0.2;
        let p = points(CornerRule::AngleBisector { l });
        let h = l / 2f64.sqrt();
        assert!((p[0] - DVec3::new(h, h, 0.0)).length() < 1e-15);
        assert!((p[3] - DVec3::new(1.0 - h, 1.0 - h, 0.0)).length() < 1e-15);
    }

    #[test]
    fn vector_sum_by_hand() {
        let p = points(CornerRule::VectorSum {
            alpha: 0.25,
            reflex: ReflexMode::AsPrinted,
        });
        // Corner (0,0): e1 = (2,0), e2 = (0,2) → (0.5, 0.5).
        assert!((p[0] - DVec3::new(0.5, 0.5, 0.0)).length() < 1e-15);
        // Reflex corner (1,1): e1 = (0,1), e2 = (1,0) → (1.25, 1.25), outside the face.
        assert!((p[3] - DVec3::new(1.25, 1.25, 0.0)).length() < 1e-15);
        let p = points(CornerRule::VectorSum {
            alpha: 0.25,
            reflex: ReflexMode::Inward,
        });
        assert!((p[3] - DVec3::new(0.75, 0.75, 0.0)).length() < 1e-15);
        assert!((p[0] - DVec3::new(0.5, 0.5, 0.0)).length() < 1e-15);
    }
}
