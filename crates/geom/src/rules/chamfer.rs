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
        face: input.topo.corner_face[c],
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

pub(super) fn vector_sum(
    input: &RuleInput,
    c: usize,
    alpha: f64,
    reflex: ReflexMode,
) -> Result<DVec3, RuleError> {
    let fr = corner_frame(input, c)?;
    let sign = if reflex == ReflexMode::Inward && fr.sin_phi < 0.0 {
        -1.0
    } else {
        1.0
    };
    Ok(fr.v + sign * alpha * (fr.e1 + fr.e2))
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
