//! The menu bar, the side panel (pipeline, tools, vertices, edges, display, compare) and
//! the status bar.

use super::scheme_editor::scheme_editor;
use super::{Coloring, PrismApp, SAMPLES_FILES, Tab, Tool};
use glam::DVec3;
use prism_geom::Scheme;

/// A change to one pipeline, decided inside the step rows and applied after them.
type StepEdit = Box<dyn FnOnce(&mut Vec<Scheme>)>;

impl PrismApp {
    pub(super) fn menu_bar(&mut self, ui: &mut egui::Ui) {
        egui::MenuBar::new().ui(ui, |ui| {
            ui.menu_button("File", |ui| {
                if ui.button("Open… (Ctrl+O)").clicked() {
                    self.open_dialog();
                }
                ui.menu_button("Samples", |ui| {
                    for (k, (name, _, _)) in SAMPLES_FILES.iter().enumerate() {
                        if ui.button(*name).clicked() {
                            self.open_sample(k);
                        }
                    }
                });
                ui.separator();
                if ui.button("Save (Ctrl+S)").clicked() {
                    self.save_dialog(false);
                }
                if ui.button("Save as…").clicked() {
                    self.save_dialog(true);
                }
                ui.menu_button("Export the shown level", |ui| {
                    for ext in ["obj", "stl", "glb"] {
                        if ui.button(format!("{}…", ext.to_uppercase())).clicked() {
                            self.export_dialog(ext);
                        }
                    }
                });
            });
            ui.menu_button("Edit", |ui| {
                if ui
                    .add_enabled(self.history.can_undo(), egui::Button::new("Undo (Ctrl+Z)"))
                    .clicked()
                {
                    self.undo();
                }
                if ui
                    .add_enabled(
                        self.history.can_redo(),
                        egui::Button::new("Redo (Ctrl+Shift+Z)"),
                    )
                    .clicked()
                {
                    self.redo();
                }
            });
            ui.separator();
            ui.selectable_value(&mut self.tab, Tab::Model, "Model");
            ui.selectable_value(&mut self.tab, Tab::Curves, "Curves");
        });
    }

    pub(super) fn side_panel(&mut self, ui: &mut egui::Ui) {
        ui.label(egui::RichText::new(&self.origin.name).strong());
        ui.separator();
        self.pipeline_section(ui);
        ui.separator();
        self.tool_section(ui);
        ui.separator();
        self.display_section(ui);
        ui.separator();
        ui.heading("Compare");
        let mut n = self.doc.pipelines.len();
        ui.horizontal(|ui| {
            for k in [1, 2, 4] {
                ui.radio_value(
                    &mut n,
                    k,
                    format!("{k} view{}", if k > 1 { "s" } else { "" }),
                );
            }
        });
        if n != self.doc.pipelines.len() {
            self.set_compare(n);
        }
        if n > 1 {
            ui.label("Click a view to edit its pipeline here; cameras are linked.");
        }
    }

    fn pipeline_section(&mut self, ui: &mut egui::Ui) {
        let a = self.active;
        if self.doc.pipelines.len() > 1 {
            ui.heading(format!("Pipeline of view {}", a + 1));
        } else {
            ui.heading("Pipeline");
        }
        let steps = self.doc.pipelines[a].clone();
        let mut edit: Option<StepEdit> = None;
        let n = steps.len();
        for (k, s) in steps.iter().enumerate() {
            ui.horizontal(|ui| {
                ui.label(format!("{}.", k + 1));
                let name = format!("scheme of step {}", k + 1);
                if let Some(new) = scheme_editor(ui, ("step", a, k), &name, s) {
                    edit = Some(Box::new(move |p| p[k] = new));
                }
                if ui
                    .add_enabled(
                        k > 0,
                        egui::Button::new(egui::RichText::new("▲").monospace()).small(),
                    )
                    .on_hover_text("move up")
                    .clicked()
                {
                    edit = Some(Box::new(move |p| p.swap(k - 1, k)));
                }
                if ui
                    .add_enabled(
                        k + 1 < n,
                        egui::Button::new(egui::RichText::new("▼").monospace()).small(),
                    )
                    .on_hover_text("move down")
                    .clicked()
                {
                    edit = Some(Box::new(move |p| p.swap(k, k + 1)));
                }
                if ui.small_button("×").on_hover_text("remove").clicked() {
                    edit = Some(Box::new(move |p| {
                        p.remove(k);
                    }));
                }
            });
        }
        if let Some(f) = edit {
            self.change(|d| f(&mut d.pipelines[a]));
        }
        ui.label("Next step:");
        if let Some(n) = scheme_editor(ui, "next", "scheme of the next step", &self.next) {
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
        let v = &mut self.views[a];
        let n = v.steps().len();
        if n > 0 {
            let mut lv = v.level.min(n);
            if ui
                .add(egui::Slider::new(&mut lv, 0..=n).text("level shown"))
                .changed()
            {
                v.level = lv;
                v.scene_dirty = true;
            }
        }
        if let Some(job) = &v.job {
            let done = v.pipeline.levels().len() - 1 + job.done;
            let secs = job.started.elapsed().as_secs_f32();
            let fraction = job.done as f32 / job.total.max(1) as f32;
            ui.horizontal(|ui| {
                ui.add(
                    egui::ProgressBar::new(fraction)
                        .text(format!("level {} of {n}, {secs:.1} s", done + 1))
                        .desired_width(170.0),
                );
                if ui.button("Cancel").clicked() {
                    v.cancel();
                }
            });
        }
        ui.horizontal(|ui| {
            ui.label("memory budget");
            ui.add(
                egui::DragValue::new(&mut self.budget_mib)
                    .range(64..=1 << 20)
                    .suffix(" MiB"),
            );
        });
    }

    fn tool_section(&mut self, ui: &mut egui::Ui) {
        ui.heading("Tool");
        let before = self.tool;
        ui.horizontal(|ui| {
            ui.selectable_value(&mut self.tool, Tool::Orbit, "Orbit");
            ui.selectable_value(&mut self.tool, Tool::Vertices, "Vertices");
            ui.selectable_value(&mut self.tool, Tool::Edges, "Edges");
        });
        if before != self.tool {
            self.mark_overlays();
        }
        match self.tool {
            Tool::Orbit => {
                ui.label("Drag to turn, right-drag to pan, scroll to zoom.");
            }
            Tool::Vertices => self.vertex_section(ui),
            Tool::Edges => self.edge_section(ui),
        }
    }

    fn vertex_section(&mut self, ui: &mut egui::Ui) {
        ui.label("Click, shift-click or drag a box to select control vertices; drag a selected one to move it (X, Y, Z hold it to an axis). Right-drag turns the view.");
        ui.horizontal(|ui| {
            ui.label("axis:");
            for (k, name) in ["x", "y", "z"].iter().enumerate() {
                let on = self.axis == Some(k);
                if ui.selectable_label(on, *name).clicked() {
                    self.axis = if on { None } else { Some(k) };
                }
            }
            if ui
                .selectable_label(self.axis.is_none(), "view plane")
                .clicked()
            {
                self.axis = None;
            }
        });
        let sel: Vec<u32> = self.sel_verts.iter().copied().collect();
        ui.label(format!("{} selected", sel.len()));
        if sel.is_empty() {
            return;
        }
        // Typed coordinates: the vertex, or the centre of several (moving it moves them all).
        let pts: Vec<DVec3> = sel
            .iter()
            .map(|&v| self.doc.mesh.positions[v as usize])
            .collect();
        let centre = pts.iter().copied().sum::<DVec3>() / pts.len() as f64;
        let mut c = centre;
        ui.horizontal(|ui| {
            ui.label(if sel.len() == 1 {
                format!("vertex {}", sel[0])
            } else {
                "centre".into()
            });
            for k in 0..3 {
                ui.add(egui::DragValue::new(&mut c[k]).speed(0.01).max_decimals(6));
            }
        });
        if c != centre {
            self.move_vertices(&sel, c - centre);
        }
    }

    fn edge_section(&mut self, ui: &mut egui::Ui) {
        ui.label("Click an edge on any level (shift-click adds, drag a box); marks go on the control edge it comes from. Right-drag turns the view.");
        ui.horizontal(|ui| {
            if ui.button("Select edges sharper than").clicked() {
                let add = ui.input(|i| i.modifiers.shift);
                self.select_sharper_than(self.sharper_deg, add);
            }
            ui.add(
                egui::DragValue::new(&mut self.sharper_deg)
                    .range(0.0..=180.0)
                    .suffix("°"),
            );
        });
        ui.label(format!("{} control edge(s) selected", self.sel_edges.len()));
        ui.horizontal(|ui| {
            if ui.button("Crease").clicked() {
                self.mark_crease(self.crease_value);
            }
            ui.add(
                egui::Slider::new(&mut self.crease_value, 0.0..=10.0)
                    .text("sharpness (10 = sharp)"),
            );
        });
        ui.horizontal(|ui| {
            if ui.button("Own radius").clicked() {
                self.mark_radius(Some(self.radius_value));
            }
            ui.add(
                egui::DragValue::new(&mut self.radius_value)
                    .speed(0.005)
                    .range(1e-4..=1e6),
            );
            if ui.button("Step's radius").clicked() {
                self.mark_radius(None);
            }
        });
        if ui.button("Clear crease").clicked() {
            self.mark_crease(0.0);
        }
        let marked = self.doc.edge_attrs.len();
        ui.label(format!(
            "{marked} control edge(s) marked (red: crease, cyan: own radius, yellow: selected)"
        ));
    }

    fn display_section(&mut self, ui: &mut egui::Ui) {
        ui.heading("Display");
        let before = self.display.clone();
        let d = &mut self.display;
        ui.checkbox(&mut d.smooth, "smooth shading (F)");
        ui.checkbox(&mut d.wireframe, "wireframe (W)");
        ui.horizontal(|ui| {
            ui.label("colour:");
            ui.radio_value(&mut d.color, Coloring::Uniform, "one");
            ui.radio_value(&mut d.color, Coloring::Kind, "face kind (F / E / V)");
            ui.radio_value(&mut d.color, Coloring::Curvature, "mean curvature");
            ui.radio_value(&mut d.color, Coloring::Scheme, "scheme");
        });
        ui.checkbox(&mut d.cage, "previous level as cage");
        ui.checkbox(&mut d.corners, "corner points and displacement vectors");
        ui.checkbox(
            &mut d.limit,
            "limit points and normals (Catmull–Clark, Loop)",
        );
        if d.color == Coloring::Curvature {
            let v = &self.views[self.active];
            if let Some((lo, hi)) = v.scene.color_range {
                ui.horizontal(|ui| {
                    ui.label(format!("H {lo:.3}"));
                    let (rect, _) =
                        ui.allocate_exact_size(egui::vec2(120.0, 12.0), egui::Sense::hover());
                    for k in 0..24 {
                        let [r, g, b] = prism_viewport::scene::curvature_color(k as f64 / 23.0);
                        let s = |x: f32| (255.0 * x) as u8;
                        let w = rect.width() / 24.0;
                        ui.painter().rect_filled(
                            egui::Rect::from_min_size(
                                rect.min + egui::vec2(k as f32 * w, 0.0),
                                egui::vec2(w + 0.5, rect.height()),
                            ),
                            0.0,
                            egui::Color32::from_rgb(s(r), s(g), s(b)),
                        );
                    }
                    ui.label(format!("{hi:.3}"));
                });
            }
        }
        if d.color == Coloring::Kind {
            ui.horizontal(|ui| {
                for (name, c) in ["FACE", "EDGE", "VERTEX"]
                    .iter()
                    .zip(prism_viewport::scene::KIND_COLORS)
                {
                    let s = |x: f32| (255.0 * x) as u8;
                    ui.colored_label(egui::Color32::from_rgb(s(c[0]), s(c[1]), s(c[2])), *name);
                }
            });
        }
        if *d != before {
            let shading = d.smooth != before.smooth
                || d.wireframe != before.wireframe
                || d.color != before.color;
            if shading {
                self.display_changed();
            } else {
                self.mark_overlays();
            }
        }
        if ui.button("Frame the model").clicked() {
            self.frame();
        }
    }

    pub(super) fn status(&mut self, ui: &mut egui::Ui) {
        let v = &self.views[self.active];
        let k = v.shown();
        let lv = &v.pipeline.levels()[k];
        let m = &lv.mesh;
        let mut text = format!(
            "level {} of {}: {} vertices, {} faces, {} triangles",
            k,
            v.steps().len(),
            m.num_vertices(),
            m.num_faces(),
            v.scene.triangles()
        );
        if let Some(r) = &lv.report {
            text += &format!(", {:.2} ms", r.millis);
            if !r.flipped.is_empty() {
                text += &format!(" — warning: {} flipped face(s)", r.flipped.len());
            }
            if !r.degenerate.is_empty() {
                text += &format!(" — warning: {} degenerate face(s)", r.degenerate.len());
            }
        }
        ui.horizontal(|ui| {
            ui.label(text);
            if let Some(e) = &v.error {
                ui.colored_label(egui::Color32::from_rgb(240, 110, 90), e);
            }
            if let Some(n) = &self.note {
                ui.separator();
                ui.label(n);
            }
        });
    }
}
