//! The coordinates an envelope is built in (docs/algorithms/envelope.md, "Where the scene
//! lies"): the scene's own, moved to the centre of its primitives' bounding box (rounded to a
//! multiple of 16 scales: zero for a scene near the origin) and divided by the power of two
//! nearest its size. The construction then works on numbers of order one wherever the scene
//! sits and however large it is — a chart's angle about an axis far from the origin keeps its
//! digits, squared lengths of a huge scene do not overflow — and the meshes are mapped back,
//! `x = centre + scale·x_local`. A power of two scales exactly, so a scene near the origin is
//! divided exactly and one scaled by a power of two builds the same local surface to the bit.

use super::primitive::PrimitiveInput;
use glam::DVec3;

/// World = `centre + scale · local`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocalFrame {
    pub centre: DVec3,
    /// A power of two.
    pub scale: f64,
}

impl Default for LocalFrame {
    fn default() -> Self {
        LocalFrame::IDENTITY
    }
}

impl LocalFrame {
    pub const IDENTITY: LocalFrame = LocalFrame {
        centre: DVec3::ZERO,
        scale: 1.0,
    };

    /// The frame of a scene: the centre of its finite vertices' bounding box rounded to a
    /// multiple of 16 scales, the scale the power of two nearest the box's largest half side
    /// (the identity when no vertex is finite or the box is a point: the primitives' own
    /// checks then name what is wrong).
    pub fn of(primitives: &[PrimitiveInput]) -> LocalFrame {
        let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
        for v in primitives.iter().flat_map(|p| &p.vertices) {
            let v = DVec3::from_array(*v);
            if v.is_finite() {
                (lo, hi) = (lo.min(v), hi.max(v));
            }
        }
        if !(lo.is_finite() && hi.is_finite()) {
            return LocalFrame::IDENTITY;
        }
        // Halves first: hi − lo may overflow where hi/2 − lo/2 does not.
        let (half_lo, half_hi) = (0.5 * lo, 0.5 * hi);
        let centre = half_lo + half_hi;
        let size = (half_hi - half_lo).max_element();
        if !(size.is_finite() && size > 0.0) {
            return LocalFrame::IDENTITY;
        }
        let scale = 2f64.powi(size.log2().round() as i32);
        // The centre on a grid of 16 scales: zero for a scene near the origin, so that its
        // local coordinates are its own divided by a power of two, exactly; and a scene moved
        // by a little keeps its frame.
        let grid = 16.0 * scale;
        LocalFrame {
            centre: (centre / grid).round() * grid,
            scale,
        }
    }

    pub fn to_local(&self, x: DVec3) -> DVec3 {
        (x - self.centre) / self.scale
    }

    pub fn to_world(&self, x: DVec3) -> DVec3 {
        self.centre + self.scale * x
    }

    /// A primitive in local coordinates (its t unchanged: t is a ratio).
    pub(super) fn input_to_local(&self, p: &PrimitiveInput) -> PrimitiveInput {
        PrimitiveInput {
            vertices: p
                .vertices
                .iter()
                .map(|v| self.to_local(DVec3::from_array(*v)).to_array())
                .collect(),
            faces: p.faces.clone(),
            t: p.t,
            vertex_t: p.vertex_t.clone(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(vertices: Vec<[f64; 3]>) -> PrimitiveInput {
        PrimitiveInput {
            vertices,
            faces: Vec::new(),
            t: None,
            vertex_t: None,
        }
    }

    #[test]
    fn the_frame_centres_the_box_and_scales_by_a_power_of_two() {
        let f = LocalFrame::of(&[
            input(vec![[1e8, 1e8 + 2.0, -3.0]]),
            input(vec![[1e8 + 6.0, 1e8, 5.0], [f64::NAN, 0.0, 0.0]]),
        ]);
        assert_eq!(f.scale, 4.0, "largest half side 4");
        assert_eq!(
            f.centre,
            DVec3::new(1e8, 1e8, 0.0),
            "a multiple of 64 near the centre"
        );
        // Near the origin, no move: coordinates are divided by the scale, exactly.
        let near = LocalFrame::of(&[input(vec![[-1.0, 0.0, 0.0], [5.0, 1.0, 0.0]])]);
        assert_eq!((near.centre, near.scale), (DVec3::ZERO, 4.0));
        let x = DVec3::new(1e8 + 0.5, 1e8 + 1.25, 2.0);
        assert_eq!(f.to_world(f.to_local(x)), x);
        // Huge and tiny scenes do not overflow or vanish.
        let huge = LocalFrame::of(&[input(vec![[-1e300; 3], [1e300; 3]])]);
        assert_eq!(huge.centre, DVec3::ZERO);
        assert!(huge.scale.is_finite() && (huge.scale / 1e300 - 1.0).abs() < 0.5);
        let tiny = LocalFrame::of(&[input(vec![[-1e-300; 3], [1e-300; 3]])]);
        assert!(tiny.scale > 0.0 && (tiny.scale / 1e-300 - 1.0).abs() < 0.5);
        // Nothing finite, or a point: the identity.
        assert_eq!(
            LocalFrame::of(&[input(vec![[f64::NAN; 3]])]),
            LocalFrame::IDENTITY
        );
        assert_eq!(
            LocalFrame::of(&[input(vec![[2.0; 3]])]),
            LocalFrame::IDENTITY
        );
    }
}
