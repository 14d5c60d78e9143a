//! The 3D views inside the egui window: the viewport crate's renderer drawn in egui's own
//! render pass through `egui_wgpu` paint callbacks (same device, same pass: no copies). Each
//! view (one, or two or four in the compare split) has its own camera slot and buffers.

use prism_viewport::{Camera, CameraSlot, GpuScene, Renderer, Scene};
use std::collections::{BTreeMap, HashMap};
use std::sync::{Arc, Mutex};

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
    /// The version the device could not hold, so that it is not tried again every frame.
    refused: Option<u64>,
}

/// GPU state kept in egui's callback resources.
struct Resources {
    renderer: Renderer,
    views: HashMap<usize, ViewGpu>,
    /// To draw the next frame when a view's scene was refused.
    ctx: egui::Context,
}

/// Why each view draws nothing: the scene its device could not hold (set by the paint
/// callback, read by the view's own drawing on the next frame).
static REFUSED: Mutex<BTreeMap<usize, String>> = Mutex::new(BTreeMap::new());

/// The message of a view whose scene the graphics device could not hold.
pub fn refusal(view: usize) -> Option<String> {
    REFUSED.lock().ok()?.get(&view).cloned()
}

/// Creates the renderer once, for the window's colour format and sample count.
pub fn install(render_state: &egui_wgpu::RenderState, samples: u32, ctx: &egui::Context) {
    let renderer = Renderer::new(&render_state.device, render_state.target_format, samples);
    render_state
        .renderer
        .write()
        .callback_resources
        .insert(Resources {
            renderer,
            views: HashMap::new(),
            ctx: ctx.clone(),
        });
}

/// What the window asks of its graphics device: the adapter's own limits rather than
/// wgpu's portable defaults, whose largest buffer (256 MiB) a level of 1.5 M faces passes.
/// Scenes larger still are drawn in parts ([`prism_viewport::parts`]).
pub fn device_descriptor(adapter: &wgpu::Adapter) -> wgpu::DeviceDescriptor<'static> {
    wgpu::DeviceDescriptor {
        label: Some("prism window"),
        required_limits: adapter.limits(),
        ..Default::default()
    }
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
            refused: None,
        });
        let done = match &mut v.uploaded {
            Some((version, _, _)) if *version == self.version => Ok(()),
            _ if v.refused == Some(self.version) => Ok(()),
            // A new version: written over the buffers it fits (an edit keeps the counts).
            Some((version, scene, overlay)) => {
                *version = self.version;
                renderer
                    .refill(device, queue, scene, &self.scene)
                    .and_then(|()| renderer.refill(device, queue, overlay, &self.overlay))
            }
            None => renderer.upload(device, &self.scene).and_then(|scene| {
                let overlay = renderer.upload(device, &self.overlay)?;
                v.uploaded = Some((self.version, scene, overlay));
                Ok(())
            }),
        };
        if let Ok(mut refused) = REFUSED.lock() {
            match done {
                Err(e) => {
                    v.uploaded = None;
                    v.refused = Some(self.version);
                    refused.insert(self.view, format!("{e}. Nothing is drawn in this view: show a lower level or a coarser surface."));
                    res.ctx.request_repaint();
                }
                Ok(()) if v.refused != Some(self.version) => {
                    v.refused = None;
                    refused.remove(&self.view);
                }
                Ok(()) => {}
            }
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

/// Whether the side panels are hidden so that the views fill the window (F11).
pub fn full_view(ctx: &egui::Context) -> bool {
    ctx.data(|d| d.get_temp(full_view_id())).unwrap_or(false)
}

/// Hides or shows the side panels.
pub fn toggle_full_view(ctx: &egui::Context) {
    let on = !full_view(ctx);
    ctx.data_mut(|d| d.insert_temp(full_view_id(), on));
}

fn full_view_id() -> egui::Id {
    egui::Id::unique("prism-full-view")
}

/// The standard view a number key asks for, as Blender's numpad has them: 1 front, 3 right,
/// 7 top, 0 the three-quarter view (none while a text field has the keyboard).
pub fn standard_view_key(ctx: &egui::Context) -> Option<prism_viewport::View> {
    use egui::Key;
    use prism_viewport::View;
    if ctx.egui_wants_keyboard_input() {
        return None;
    }
    let keys = [
        (Key::Num1, View::Front),
        (Key::Num3, View::Right),
        (Key::Num7, View::Top),
        (Key::Num0, View::Iso),
    ];
    ctx.input(|i| {
        keys.iter()
            .find(|(k, _)| i.modifiers.is_none() && i.key_pressed(*k))
            .map(|(_, v)| *v)
    })
}

/// Orbit (drag with `orbit`), pan (drag with any of `pan`) and zoom (the wheel over the
/// view) of a view's camera: the mouse of every 3D view.
pub fn camera_input(
    camera: &mut Camera,
    ui: &egui::Ui,
    resp: &egui::Response,
    rect: egui::Rect,
    orbit: egui::PointerButton,
    pan: &[egui::PointerButton],
) {
    if resp.dragged_by(orbit) {
        let d = resp.drag_delta();
        camera.orbit(-d.x * 0.01, d.y * 0.01);
    }
    if pan.iter().any(|b| resp.dragged_by(*b)) {
        let d = resp.drag_delta();
        camera.pan(d.x / rect.height(), d.y / rect.height());
    }
    if resp.hovered() {
        let scroll = ui.input(|i| i.smooth_scroll_delta.y);
        if scroll != 0.0 {
            camera.zoom((-scroll * 0.002).exp());
        }
    }
}

/// The message of a view whose scene the graphics device refused, across its middle.
pub fn paint_refusal(ui: &egui::Ui, rect: egui::Rect, view: usize) {
    if let Some(text) = refusal(view) {
        let galley = ui.painter().layout(
            text,
            egui::FontId::proportional(14.0),
            egui::Color32::from_rgb(240, 170, 90),
            (rect.width() - 40.0).max(100.0),
        );
        ui.painter().galley(
            rect.center() - galley.size() / 2.0,
            galley,
            egui::Color32::WHITE,
        );
    }
}

/// Light text over a view: `text` placed at `at` by `align`, `size` points, grey `gray`.
pub fn caption(
    ui: &egui::Ui,
    (at, align): (egui::Pos2, egui::Align2),
    text: impl ToString,
    size: f32,
    gray: u8,
) {
    ui.painter().text(
        at,
        align,
        text,
        egui::FontId::proportional(size),
        egui::Color32::from_gray(gray),
    );
}

/// The renderer's background colour under a view (what shows without a GPU too).
pub fn paint_background(ui: &egui::Ui, rect: egui::Rect) {
    let bg = prism_viewport::renderer::BACKGROUND;
    let srgb = |x: f64| (255.0 * x.powf(1.0 / 2.2)) as u8;
    ui.painter().rect_filled(
        rect,
        0.0,
        egui::Color32::from_rgb(srgb(bg.r), srgb(bg.g), srgb(bg.b)),
    );
}
