//! An orbit camera: it looks at a target from a distance, turned by yaw and pitch; pan moves
//! the target, zoom the distance. "Frame the model" fits a bounding sphere into the view.
//! Projection and view come from `glam::camera` (right-handed, depth 0..1 as wgpu wants).

use glam::{Mat4, Vec3};

/// Named views.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum View {
    /// From (1, 1, 1)-ish above the model: three faces of a box visible.
    #[default]
    Iso,
    /// Looking along −y.
    Front,
    /// Looking down −z.
    Top,
    /// Looking along −x (from the right).
    Right,
}

impl View {
    /// The orbit's yaw and pitch (radians) of this view.
    pub fn angles(self) -> (f32, f32) {
        match self {
            View::Iso => (35f32.to_radians(), 30f32.to_radians()),
            View::Front => (0.0, 0.0),
            View::Top => (0.0, 89.0f32.to_radians()),
            View::Right => (-90f32.to_radians(), 0.0),
        }
    }
}

/// An orbit camera around `target`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    pub target: Vec3,
    pub distance: f32,
    /// Turn about +z, radians.
    pub yaw: f32,
    /// Elevation above the xy plane, radians (kept inside ±89°).
    pub pitch: f32,
    /// Vertical field of view, radians.
    pub fov_y: f32,
}

impl Default for Camera {
    fn default() -> Self {
        Camera::looking(View::Iso, Vec3::ZERO, 1.0)
    }
}

impl Camera {
    /// A camera of view `view` that frames a sphere of `radius` around `target`.
    pub fn looking(view: View, target: Vec3, radius: f32) -> Camera {
        let (yaw, pitch) = view.angles();
        let mut c = Camera {
            target,
            distance: 1.0,
            yaw,
            pitch,
            fov_y: 35f32.to_radians(),
        };
        c.frame(target, radius);
        c
    }

    /// A camera at `eye` looking at `target` (both in the scene's coordinates) with a
    /// vertical field of view `fov_y` (radians): the orbit's yaw, pitch and distance that
    /// put the eye there (pitch kept inside ±89°, as orbiting does). `None` when the two
    /// points coincide or are not finite.
    pub fn from_eye(eye: Vec3, target: Vec3, fov_y: f32) -> Option<Camera> {
        let d = eye - target;
        let distance = d.length();
        if !distance.is_finite() || distance < 1e-9 || !target.is_finite() {
            return None;
        }
        let dir = d / distance;
        let pitch = dir.z.clamp(-1.0, 1.0).asin().clamp(-1.553, 1.553);
        let yaw = (-dir.x).atan2(-dir.y);
        Some(Camera {
            target,
            distance,
            yaw,
            pitch,
            fov_y,
        })
    }

    /// Fits a sphere of `radius` around `center` into the view (with a margin).
    pub fn frame(&mut self, center: Vec3, radius: f32) {
        self.target = center;
        self.distance = 1.05 * radius.max(1e-6) / (0.5 * self.fov_y).sin();
    }

    /// Where the eye is.
    pub fn eye(&self) -> Vec3 {
        let dir = Vec3::new(
            self.pitch.cos() * (-self.yaw).sin(),
            -self.pitch.cos() * self.yaw.cos(),
            self.pitch.sin(),
        );
        self.target + self.distance * dir
    }

    /// Turns to a standard view about the same target, from the same distance.
    pub fn turn_to(&mut self, view: View) {
        (self.yaw, self.pitch) = view.angles();
    }

    /// Orbit by screen-space drag (radians).
    pub fn orbit(&mut self, d_yaw: f32, d_pitch: f32) {
        self.yaw += d_yaw;
        self.pitch = (self.pitch + d_pitch).clamp(-1.55, 1.55);
    }

    /// Zoom by a factor (> 1 moves away).
    pub fn zoom(&mut self, factor: f32) {
        self.distance = (self.distance * factor).max(1e-6);
    }

    /// The view plane's right and up directions (up as the screen shows it).
    pub fn view_axes(&self) -> (Vec3, Vec3) {
        let fwd = (self.target - self.eye()).normalize();
        let right = fwd.cross(Vec3::Z).normalize_or(Vec3::X);
        (right, right.cross(fwd))
    }

    /// The height the view shows at the target, in model units.
    pub fn visible_height(&self) -> f32 {
        2.0 * self.distance * (0.5 * self.fov_y).tan()
    }

    /// A screen drag of (`dx`, `dy`) pixels in a view `height` pixels high, as a movement in
    /// the view plane at the target (screen y grows downwards).
    pub fn drag_in_view_plane(&self, dx: f32, dy: f32, height: f32) -> Vec3 {
        let (right, up) = self.view_axes();
        self.visible_height() / height.max(1.0) * (dx * right - dy * up)
    }

    /// Pan in the view plane by fractions of the visible height.
    pub fn pan(&mut self, dx: f32, dy: f32) {
        let (right, up) = self.view_axes();
        self.target += self.visible_height() * (-dx * right + dy * up);
    }

    /// View and projection for an aspect ratio (width / height); near and far planes are
    /// set from the distance so that depth precision follows the model.
    pub fn view_proj(&self, aspect: f32) -> Mat4 {
        let up = if self.pitch.abs() > 1.5 {
            Vec3::Y
        } else {
            Vec3::Z
        };
        let view = glam::camera::rh::view::look_at_mat4(self.eye(), self.target, up);
        let near = self.distance * 0.01;
        let far = self.distance * 10.0;
        let proj =
            glam::camera::rh::proj::directx::perspective(self.fov_y, aspect.max(1e-6), near, far);
        proj * view
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_camera_from_its_eye_puts_the_eye_there() {
        let t = Vec3::new(0.5, -1.0, 2.0);
        for e in [
            Vec3::new(4.0, 3.0, 5.0),
            Vec3::new(-2.0, 0.5, 1.0),
            Vec3::new(0.5, -6.0, 2.0),
        ] {
            let c = Camera::from_eye(e, t, 0.6).unwrap();
            assert!((c.eye() - e).length() < 1e-4, "{e} -> {}", c.eye());
            assert_eq!(c.target, t);
        }
        assert!(Camera::from_eye(t, t, 0.6).is_none());
    }

    #[test]
    fn framing_keeps_the_sphere_inside_the_view() {
        for view in [View::Iso, View::Front, View::Top] {
            let c = Camera::looking(view, Vec3::new(1.0, 2.0, 3.0), 2.0);
            let m = c.view_proj(1.0);
            // Points on the sphere project inside the clip square.
            for d in [Vec3::X, -Vec3::X, Vec3::Y, -Vec3::Y, Vec3::Z, -Vec3::Z] {
                let p = m.project_point3(c.target + 2.0 * d);
                assert!(
                    p.x.abs() < 1.0 && p.y.abs() < 1.0 && p.z > 0.0 && p.z < 1.0,
                    "{view:?} {p}"
                );
            }
        }
    }
}
