//! The 3D view the Skin and Envelope tabs share: its camera, scene and overlay, framing, the
//! mouse (orbit with the primary button, or with the secondary while the primary edits), the
//! paint callback and the hint line at its foot.

use super::viewport;
use glam::DVec3;
use prism_geom::PolyMesh;
use prism_viewport::{Camera, ColorBy, Scene, SceneOptions, Shading, View};
use std::sync::Arc;

/// How a 3D tab draws its surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Look {
    /// Iso-parameter lines.
    pub wireframe: bool,
    /// Mean-curvature colours.
    pub curvature: bool,
    pub smooth: bool,
    /// The overlay's lines drawn through the surface (a trajectory or section inside it).
    pub xray: bool,
}

impl Default for Look {
    fn default() -> Self {
        Look {
            wireframe: false,
            curvature: false,
            smooth: true,
            xray: false,
        }
    }
}

impl Look {
    /// Its checkboxes.
    pub fn ui(&mut self, ui: &mut egui::Ui) {
        ui.checkbox(&mut self.wireframe, "Iso-parameter lines");
        ui.checkbox(&mut self.curvature, "Mean-curvature colours");
        ui.checkbox(&mut self.smooth, "Smooth shading");
        ui.checkbox(&mut self.xray, "X-ray: lines through the surface")
            .on_hover_text(
                "Draw the curves, sections and trajectories even where the surface hides them",
            );
    }

    /// The scene options that draw it.
    pub fn options(&self) -> SceneOptions {
        SceneOptions {
            shading: if self.smooth {
                Shading::Smooth
            } else {
                Shading::Flat
            },
            wireframe: self.wireframe,
            color_by: if self.curvature {
                ColorBy::Curvature
            } else {
                ColorBy::Uniform
            },
            ..SceneOptions::default()
        }
    }
}

/// A scene that draws nothing, framed on the finite `points`: a tab whose surface cannot be
/// built still frames what it was given.
pub fn framing(points: impl IntoIterator<Item = DVec3>) -> Scene {
    let mut m = PolyMesh::new();
    m.positions = points.into_iter().filter(|p| p.is_finite()).collect();
    let mut s = Scene::plain(&PolyMesh::new());
    if !m.positions.is_empty() {
        let (lo, hi) = m.bbox();
        s.origin = 0.5 * (lo + hi);
        s.bbox = (lo, hi);
    }
    s
}

/// An empty overlay in the frame of `scene`, and the length of its box's diagonal (what
/// marker sizes are measured in).
pub fn overlay_for(scene: &Scene) -> (Scene, f64) {
    let overlay = Scene {
        origin: scene.origin,
        bbox: scene.bbox,
        ..Scene::default()
    };
    let size = (overlay.bbox.1 - overlay.bbox.0).length().max(1e-9);
    (overlay, size)
}

/// `n` segments along the curve `eval` on [0, 1].
pub fn sampled(eval: impl Fn(f64) -> DVec3, n: usize) -> Vec<(DVec3, DVec3)> {
    (0..n)
        .map(|j| (eval(j as f64 / n as f64), eval((j + 1) as f64 / n as f64)))
        .collect()
}

pub struct View3d {
    pub camera: Camera,
    framed: bool,
    pub scene: Arc<Scene>,
    pub overlay: Arc<Scene>,
    /// Bumped whenever the scenes change, so the upload happens once per change.
    pub version: u64,
    pub has_gpu: bool,
    /// The view slot of its camera and GPU buffers (the Model tab's views use 0–3).
    slot: usize,
}

impl View3d {
    pub fn new(slot: usize) -> View3d {
        View3d {
            camera: Camera::default(),
            framed: false,
            scene: Arc::new(Scene::default()),
            overlay: Arc::new(Scene::default()),
            version: 0,
            has_gpu: false,
            slot,
        }
    }

    /// New scenes to draw. The camera stays where it is in the world: a scene about another
    /// origin (a section dragged moves the box its positions are measured from) moves the
    /// camera's target by the difference, so the picture does not jump under the cursor.
    pub fn show(&mut self, (scene, overlay): (Arc<Scene>, Arc<Scene>)) {
        let drawn = |s: &Scene| !(s.vertices.is_empty() && s.lines.is_empty());
        if self.framed && drawn(&self.scene) && drawn(&scene) {
            self.camera.target += (self.scene.origin - scene.origin).as_vec3();
        }
        self.scene = scene;
        self.overlay = overlay;
        self.version += 1;
    }

    /// Nothing to draw.
    pub fn clear(&mut self) {
        self.show((Arc::new(Scene::default()), Arc::new(Scene::default())));
    }

    /// Frames the scene again on the next frame (a new sample).
    pub fn reframe(&mut self) {
        self.framed = false;
    }

    /// Frames the scene's box from the iso direction now.
    pub fn frame(&mut self) {
        let (lo, hi) = self.scene.bbox;
        let r = (0.5 * (hi - lo).length()).max(1e-6) as f32;
        let c = self.scene.to_local(0.5 * (lo + hi));
        self.camera = Camera::looking(View::Iso, c, r * 1.1);
        self.framed = true;
    }

    /// The view's response in `rect` after the camera's mouse: orbit with the primary button
    /// when `primary_orbits`, else with the secondary (the primary then edits); pan with the
    /// others; wheel zooms. Frames a scene seen for the first time.
    pub fn interact(
        &mut self,
        ui: &mut egui::Ui,
        rect: egui::Rect,
        id: &str,
        primary_orbits: bool,
    ) -> egui::Response {
        if !self.framed && self.scene.bbox.0 != self.scene.bbox.1 {
            self.frame();
        }
        let resp = ui.interact(rect, ui.scope_id().with(id), egui::Sense::click_and_drag());
        let (orbit, pan) = if primary_orbits {
            (
                egui::PointerButton::Primary,
                [egui::PointerButton::Secondary, egui::PointerButton::Middle],
            )
        } else {
            (
                egui::PointerButton::Secondary,
                [egui::PointerButton::Middle, egui::PointerButton::Middle],
            )
        };
        viewport::camera_input(&mut self.camera, ui, &resp, rect, orbit, &pan);
        resp
    }

    /// Paints `scene` and `overlay` into `rect` with `camera`, in slot `slot` (the view's own
    /// or one beside it).
    pub fn paint_scene(
        &self,
        ui: &egui::Ui,
        rect: egui::Rect,
        slot_offset: usize,
        scenes: (&Arc<Scene>, &Arc<Scene>),
        camera: Camera,
    ) {
        if self.has_gpu {
            ui.painter().add(egui_wgpu::Callback::new_paint_callback(
                rect,
                viewport::ViewCallback {
                    view: self.slot + slot_offset,
                    scene: scenes.0.clone(),
                    overlay: scenes.1.clone(),
                    version: self.version,
                    camera,
                    aspect: rect.width() / rect.height().max(1.0),
                },
            ));
            viewport::paint_refusal(ui, rect, self.slot + slot_offset);
        }
    }

    /// The background and the view's own scenes.
    pub fn paint(&self, ui: &egui::Ui, rect: egui::Rect) {
        viewport::paint_background(ui, rect);
        self.paint_scene(ui, rect, 0, (&self.scene, &self.overlay), self.camera);
    }

    /// The line of help at the view's foot.
    pub fn hint(ui: &egui::Ui, rect: egui::Rect, text: &str) {
        let at = rect.left_bottom() + egui::vec2(8.0, -8.0);
        viewport::caption(ui, (at, egui::Align2::LEFT_BOTTOM), text, 12.0, 170);
    }
}

/// Bytes the view's copy of a surface of these counts takes: three vertices of 36 bytes and
/// three indices a triangle (flat shading; smooth shares fewer).
pub fn view_bytes(counts: &prism_geom::memory::Counts) -> u64 {
    120 * counts.triangles()
}

/// Refuses a surface that would hold `need` bytes, more than `budget` (the Model tab's
/// memory budget), naming what would help.
pub fn within_budget(need: u64, budget: u64, what: &str, smaller: &str) -> Result<(), String> {
    use prism_geom::memory::mib;
    if need > budget {
        return Err(format!(
            "{what} would need about {} MiB, more than the memory budget of {} MiB (Model tab): \
             give {smaller}, or raise the budget if the machine has it",
            mib(need),
            mib(budget)
        ));
    }
    Ok(())
}
