//! The 3D views inside the egui window: the viewport crate's renderer drawn in egui's own
//! render pass through `egui_wgpu` paint callbacks (same device, same pass: no copies). Each
//! view (one, or two or four in the compare split) has its own camera slot and buffers.

use prism_viewport::{Camera, CameraSlot, GpuScene, Renderer, Scene};
use std::collections::HashMap;
use std::sync::Arc;

/// What the callback of one view needs for one frame.
pub struct ViewCallback {
    pub view: usize,
    pub scene: Arc<Scene>,
    /// Lines and points drawn over the scene (same origin).
    pub overlay: Arc<Scene>,
    /// Bumped whenever `scene` or `overlay` changes, so the upload happens once per change.
    pub version: u64,
    pub camera: Camera,
    pub aspect: f32,
}

struct ViewGpu {
    slot: CameraSlot,
    uploaded: Option<(u64, GpuScene, GpuScene)>,
}

/// GPU state kept in egui's callback resources.
struct Resources {
    renderer: Renderer,
    views: HashMap<usize, ViewGpu>,
}

/// Creates the renderer once, for the window's colour format and sample count.
pub fn install(render_state: &egui_wgpu::RenderState, samples: u32) {
    let renderer = Renderer::new(&render_state.device, render_state.target_format, samples);
    render_state
        .renderer
        .write()
        .callback_resources
        .insert(Resources {
            renderer,
            views: HashMap::new(),
        });
}

impl egui_wgpu::CallbackTrait for ViewCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen: &egui_wgpu::ScreenDescriptor,
        _encoder: &mut wgpu::CommandEncoder,
        resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Some(res) = resources.get_mut::<Resources>() else {
            return Vec::new();
        };
        let renderer = &res.renderer;
        let v = res.views.entry(self.view).or_insert_with(|| ViewGpu {
            slot: renderer.camera_slot(device),
            uploaded: None,
        });
        if v.uploaded.as_ref().map(|u| u.0) != Some(self.version) {
            v.uploaded = Some((
                self.version,
                renderer.upload(device, &self.scene),
                renderer.upload(device, &self.overlay),
            ));
        }
        renderer.set_slot_camera(queue, &v.slot, &self.camera, self.aspect);
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &egui_wgpu::CallbackResources,
    ) {
        if let Some(res) = resources.get::<Resources>()
            && let Some(v) = res.views.get(&self.view)
            && let Some((_, scene, overlay)) = &v.uploaded
        {
            res.renderer.draw_in(pass, &v.slot, scene);
            res.renderer.draw_in(pass, &v.slot, overlay);
        }
    }
}
