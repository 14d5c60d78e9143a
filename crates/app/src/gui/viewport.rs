//! The 3D view inside the egui window: the viewport crate's renderer drawn in egui's own
//! render pass through an `egui_wgpu` paint callback (same device, same pass: no copies).

use prism_viewport::{Camera, GpuScene, Renderer, Scene};
use std::sync::Arc;

/// What the callback needs for one frame.
pub struct ViewCallback {
    pub scene: Arc<Scene>,
    /// Bumped whenever `scene` changes, so the upload happens once per change.
    pub version: u64,
    pub camera: Camera,
    pub aspect: f32,
}

/// GPU state kept in egui's callback resources.
struct Resources {
    renderer: Renderer,
    uploaded: Option<(u64, GpuScene)>,
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
            uploaded: None,
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
        if res.uploaded.as_ref().map(|(v, _)| *v) != Some(self.version) {
            res.uploaded = Some((self.version, res.renderer.upload(device, &self.scene)));
        }
        res.renderer.set_camera(queue, &self.camera, self.aspect);
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &egui_wgpu::CallbackResources,
    ) {
        if let Some(res) = resources.get::<Resources>()
            && let Some((_, gpu)) = &res.uploaded
        {
            res.renderer.draw(pass, gpu);
        }
    }
}
