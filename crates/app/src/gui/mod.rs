//! The desktop app (eframe/egui, wgpu): a pipeline panel on the left — the steps, each a
//! scheme with its parameter, Step >> (S) and << Back (B), a level slider —, display options,
//! the 3D view in the middle (drag to orbit, right-drag to pan, scroll to zoom, F flat/smooth,
//! W wireframe), counts and timings in the status bar.
//!
//! `prism --screenshot OUT.png [FILE] [--pipeline P]` opens the window, lets it settle, saves
//! a picture of the whole window (egui's screenshot command) and exits: the test under Xvfb
//! and the pictures in docs/ use it.

mod viewport;

use glam::Vec3;
use prism_geom::biquadratic::FaceKind;
use prism_geom::io::{self, Document};
use prism_geom::scheme::{BIQUADRATIC_NAMES, PRIMAL_NAMES};
use prism_geom::{Pipeline, ReflexMode, Scheme};
use prism_viewport::{Camera, ColorBy, Scene, SceneOptions, Shading, View};
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

/// Window multisampling (and the renderer's, which must match).
const SAMPLES: u16 = 4;

/// How the app was started.
pub struct Launch {
    pub file: Option<PathBuf>,
    pub pipeline: Vec<Scheme>,
    pub screenshot: Option<PathBuf>,
}

/// Where the screenshot callback leaves the picture for the next frame.
type ScreenshotSlot = Arc<Mutex<Option<Arc<egui::ColorImage>>>>;

/// The bundled sample opened when no file is given.
const TRIPOD: &str = include_str!("../../../../assets/tripod.obj");

struct PrismApp {
    name: String,
    pipeline: Pipeline,
    /// The level shown (0 = input).
    level: usize,
    opts: SceneOptions,
    cage: bool,
    camera: Camera,
    scene: Arc<Scene>,
    version: u64,
    dirty: bool,
    /// The scheme Step >> appends.
    next: Scheme,
    error: Option<String>,
    screenshot: Option<(PathBuf, u32, ScreenshotSlot)>,
}

fn default_param(name: &str) -> Scheme {
    let v = |x| Some(x);
    Scheme::from_name(name, v(0.2), v(0.2), v(0.1), v(0.1), ReflexMode::AsPrinted)
        .expect("known scheme with its default parameter")
}

/// The parameter of a scheme, by name and value, if it has one.
fn param(s: &Scheme) -> Option<(&'static str, f64)> {
    use prism_geom::CornerRule::*;
    match s {
        Scheme::Biquadratic(r) => match *r {
            DooSabin => None,
            AngleBisector { l } => Some(("l", l)),
            CutWidth { d } => Some(("d", d)),
            VectorSum { alpha, .. } => Some(("α", alpha)),
            Cylindrical { r } | Minimum { r } | Combination { r } => Some(("r", r)),
        },
        Scheme::Primal(_) => None,
    }
}

fn with_param(s: &Scheme, x: f64) -> Scheme {
    use prism_geom::CornerRule::*;
    match *s {
        Scheme::Biquadratic(r) => Scheme::Biquadratic(match r {
            AngleBisector { .. } => AngleBisector { l: x },
            CutWidth { .. } => CutWidth { d: x },
            VectorSum { reflex, .. } => VectorSum { alpha: x, reflex },
            Cylindrical { .. } => Cylindrical { r: x },
            Minimum { .. } => Minimum { r: x },
            Combination { .. } => Combination { r: x },
            DooSabin => DooSabin,
        }),
        p => p,
    }
}

/// A scheme picker with its parameter; returns the new scheme when the user changed it.
fn scheme_editor(
    ui: &mut egui::Ui,
    id: impl std::hash::Hash + std::fmt::Debug,
    s: &Scheme,
) -> Option<Scheme> {
    let mut out = None;
    ui.horizontal(|ui| {
        egui::ComboBox::from_id_salt(id)
            .selected_text(s.name())
            .show_ui(ui, |ui| {
                for name in BIQUADRATIC_NAMES.iter().chain(PRIMAL_NAMES.iter()) {
                    if ui.selectable_label(s.name() == *name, *name).clicked() && s.name() != *name
                    {
                        out = Some(default_param(name));
                    }
                }
            });
        if let Some((label, value)) = param(s) {
            let mut x = value;
            let max = if label == "α" { 0.499 } else { 10.0 };
            let resp = ui.add(
                egui::DragValue::new(&mut x)
                    .speed(0.005)
                    .range(1e-4..=max)
                    .prefix(format!("{label} = ")),
            );
            if resp.changed() && with_param(s, x).validate().is_ok() {
                out = Some(with_param(s, x));
            }
        }
    });
    out
}

impl PrismApp {
    fn new(cc: &eframe::CreationContext<'_>, launch: Launch) -> Result<PrismApp, String> {
        let rs = cc
            .wgpu_render_state
            .as_ref()
            .ok_or("the wgpu renderer is not available")?;
        viewport::install(rs, SAMPLES as u32);
        let (doc, name) = match &launch.file {
            Some(p) => (
                io::load(p).map_err(|e| e.to_string())?.0,
                p.display().to_string(),
            ),
            None => {
                let m = io::read_obj_str(std::path::Path::new("tripod.obj"), TRIPOD)
                    .map_err(|e| e.to_string())?;
                (
                    Document {
                        mesh: m.mesh,
                        edge_attrs: m.edge_attrs,
                        tags: m.tags,
                        pipeline: None,
                    },
                    "tripod (bundled sample)".to_string(),
                )
            }
        };
        let steps = if launch.pipeline.is_empty() {
            doc.pipeline.clone().unwrap_or_default()
        } else {
            launch.pipeline
        };
        let level = steps.len();
        let mut app = PrismApp {
            name,
            pipeline: Pipeline::with_tags(doc.mesh, doc.edge_attrs, doc.tags, steps),
            level,
            opts: SceneOptions::default(),
            cage: false,
            camera: Camera::default(),
            scene: Arc::new(Scene::default()),
            version: 0,
            dirty: true,
            next: default_param("combination"),
            error: None,
            screenshot: launch
                .screenshot
                .map(|p| (p, 0, Arc::new(Mutex::new(None)))),
        };
        app.compute();
        app.rebuild_scene();
        app.camera = Camera::looking(View::Iso, Vec3::ZERO, app.scene.radius());
        Ok(app)
    }

    /// Computes the levels up to the shown one; an error is shown, not fatal.
    fn compute(&mut self) {
        self.error = None;
        let upto = self.level.min(self.pipeline.steps().len());
        if let Err(e) = self.pipeline.compute_with(upto, |_, _| {}) {
            self.error = Some(e.to_string());
        }
        self.level = self.level.min(self.pipeline.levels().len() - 1);
        self.dirty = true;
    }

    fn rebuild_scene(&mut self) {
        let levels = self.pipeline.levels();
        let lv = &levels[self.level];
        let kinds: Option<&[FaceKind]> = lv.provenance.as_ref().map(|p| p.face_kind.as_slice());
        let holes = &lv.tags.holes;
        let mut scene = Scene::build(
            &lv.mesh,
            &lv.edge_attrs,
            kinds,
            &|f| holes.contains(&(f as u32)),
            &self.opts,
        );
        if self.cage && self.level > 0 {
            scene.add_cage(&levels[self.level - 1].mesh, [0.95, 0.75, 0.25]);
        }
        // Keep the camera's target where it was: scenes are centred on their own box.
        self.scene = Arc::new(scene);
        self.version += 1;
        self.dirty = false;
    }

    fn step(&mut self) {
        self.pipeline.push_step(self.next);
        self.level = self.pipeline.steps().len();
        self.compute();
    }

    fn back(&mut self) {
        if self.pipeline.pop_step().is_some() {
            self.level = self.level.min(self.pipeline.steps().len());
            self.compute();
        }
    }

    fn pipeline_panel(&mut self, ui: &mut egui::Ui) {
        ui.heading("Pipeline");
        ui.label(&self.name);
        ui.separator();
        let mut changed: Option<(usize, Scheme)> = None;
        for (k, s) in self.pipeline.steps().iter().enumerate() {
            ui.horizontal(|ui| {
                ui.label(format!("{}.", k + 1));
                if let Some(n) = scheme_editor(ui, ("step", k), s) {
                    changed = Some((k, n));
                }
            });
        }
        if let Some((k, s)) = changed {
            self.pipeline.set_step(k, s);
            self.level = self.level.max(k + 1);
            self.compute();
        }
        ui.separator();
        ui.label("Next step:");
        if let Some(n) = scheme_editor(ui, "next", &self.next) {
            self.next = n;
        }
        ui.horizontal(|ui| {
            if ui.button("Step >> (S)").clicked() {
                self.step();
            }
            if ui.button("<< Back (B)").clicked() {
                self.back();
            }
        });
        let n = self.pipeline.steps().len();
        if n > 0 {
            let mut lv = self.level;
            if ui
                .add(egui::Slider::new(&mut lv, 0..=n).text("level"))
                .changed()
            {
                self.level = lv;
                self.compute();
            }
        }
        ui.separator();
        ui.heading("Display");
        let mut smooth = self.opts.shading == Shading::Smooth;
        let mut kind = self.opts.color_by == ColorBy::Kind;
        let before = (smooth, self.opts.wireframe, kind, self.cage);
        ui.checkbox(&mut smooth, "smooth shading (F)");
        ui.checkbox(&mut self.opts.wireframe, "wireframe (W)");
        ui.checkbox(&mut kind, "colour by face kind");
        ui.checkbox(&mut self.cage, "previous level as cage");
        if before != (smooth, self.opts.wireframe, kind, self.cage) {
            self.opts.shading = if smooth {
                Shading::Smooth
            } else {
                Shading::Flat
            };
            self.opts.color_by = if kind {
                ColorBy::Kind
            } else {
                ColorBy::Uniform
            };
            self.dirty = true;
        }
        if ui.button("Frame the model").clicked() {
            self.camera = Camera::looking(View::Iso, Vec3::ZERO, self.scene.radius());
        }
    }

    fn keys(&mut self, ui: &egui::Ui) {
        if ui.ctx().egui_wants_keyboard_input() {
            return;
        }
        let (s, b, f, w) = ui.input(|i| {
            (
                i.key_pressed(egui::Key::S),
                i.key_pressed(egui::Key::B),
                i.key_pressed(egui::Key::F),
                i.key_pressed(egui::Key::W),
            )
        });
        if s {
            self.step();
        }
        if b {
            self.back();
        }
        if f {
            self.opts.shading = match self.opts.shading {
                Shading::Flat => Shading::Smooth,
                Shading::Smooth => Shading::Flat,
            };
            self.dirty = true;
        }
        if w {
            self.opts.wireframe = !self.opts.wireframe;
            self.dirty = true;
        }
    }

    fn view(&mut self, ui: &mut egui::Ui) {
        let (rect, resp) = ui.allocate_exact_size(ui.available_size(), egui::Sense::drag());
        if resp.dragged_by(egui::PointerButton::Primary) {
            let d = resp.drag_delta();
            self.camera.orbit(-d.x * 0.01, d.y * 0.01);
        }
        if resp.dragged_by(egui::PointerButton::Secondary)
            || resp.dragged_by(egui::PointerButton::Middle)
        {
            let d = resp.drag_delta();
            self.camera.pan(d.x / rect.height(), d.y / rect.height());
        }
        if resp.hovered() {
            let scroll = ui.input(|i| i.smooth_scroll_delta.y);
            if scroll != 0.0 {
                self.camera.zoom((-scroll * 0.002).exp());
            }
        }
        let bg = prism_viewport::renderer::BACKGROUND;
        let srgb = |x: f64| (255.0 * x.powf(1.0 / 2.2)) as u8;
        ui.painter().rect_filled(
            rect,
            0.0,
            egui::Color32::from_rgb(srgb(bg.r), srgb(bg.g), srgb(bg.b)),
        );
        ui.painter().add(egui_wgpu::Callback::new_paint_callback(
            rect,
            viewport::ViewCallback {
                scene: self.scene.clone(),
                version: self.version,
                camera: self.camera,
                aspect: rect.width() / rect.height().max(1.0),
            },
        ));
    }

    fn status(&self, ui: &mut egui::Ui) {
        let lv = &self.pipeline.levels()[self.level];
        let m = &lv.mesh;
        let mut text = format!(
            "level {} of {}: {} vertices, {} faces, {} triangles",
            self.level,
            self.pipeline.steps().len(),
            m.num_vertices(),
            m.num_faces(),
            self.scene.triangles()
        );
        if let Some(r) = &lv.report {
            text += &format!(", {:.2} ms", r.millis);
            if !r.flipped.is_empty() {
                text += &format!(" — warning: {} flipped face(s)", r.flipped.len());
            }
        }
        ui.horizontal(|ui| {
            ui.label(text);
            if let Some(e) = &self.error {
                ui.colored_label(egui::Color32::from_rgb(240, 110, 90), e);
            }
        });
    }

    fn screenshot(&mut self, ctx: &egui::Context) {
        let Some((path, frames, slot)) = &mut self.screenshot else {
            return;
        };
        *frames += 1;
        ctx.request_repaint();
        if *frames == 8 {
            let slot = slot.clone();
            ctx.send_viewport_cmd(egui::ViewportCommand::Screenshot(
                egui::ScreenshotCallback::new(move |img| {
                    *slot.lock().expect("screenshot slot") = Some(img);
                }),
            ));
        }
        let taken = slot.lock().expect("screenshot slot").take();
        if let Some(img) = taken {
            let [w, h] = img.size;
            let rgba: Vec<u8> = img.pixels.iter().flat_map(|c| c.to_array()).collect();
            let mut png = Vec::new();
            let ok = image::RgbaImage::from_raw(w as u32, h as u32, rgba)
                .map(|i| i.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png));
            match ok {
                Some(Ok(())) => match io::write_atomically(path, &png) {
                    Ok(()) => println!("wrote {} ({w}x{h})", path.display()),
                    Err(e) => eprintln!("error: {e}"),
                },
                _ => eprintln!("error: encoding the screenshot failed"),
            }
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
    }
}

impl eframe::App for PrismApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.keys(ui);
        egui::Panel::left("pipeline")
            .resizable(true)
            .default_size(280.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| self.pipeline_panel(ui));
            });
        egui::Panel::bottom("status").show(ui, |ui| self.status(ui));
        if self.dirty {
            self.rebuild_scene();
        }
        egui::CentralPanel::default()
            .frame(egui::Frame::NONE)
            .show(ui, |ui| self.view(ui));
        let ctx = ui.ctx().clone();
        self.screenshot(&ctx);
    }
}

/// Opens the window; returns when it is closed.
pub fn run(launch: Launch) -> Result<(), String> {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("Prism")
            .with_inner_size([1280.0, 800.0]),
        renderer: eframe::Renderer::Wgpu,
        multisampling: SAMPLES,
        depth_buffer: 32,
        ..Default::default()
    };
    eframe::run_native(
        "Prism",
        options,
        Box::new(move |cc| {
            PrismApp::new(cc, launch)
                .map(|a| Box::new(a) as Box<dyn eframe::App>)
                .map_err(|e| e.into())
        }),
    )
    .map_err(|e| format!("the window could not be opened: {e}"))
}
