//! The Model tab's side panel (pipeline, tools, vertices, edges, display, compare; its status
//! bar is `status.rs`). Panels read the document and queue commands; they write only the tab's own
//! state (selection, tool, display, the level shown).

use super::scheme_editor::{repeat_warning, scheme_editor};
use super::{Coloring, ModelTab, Tool};
use crate::gui::command::{Command, EdgeMark, Edit};
use crate::gui::document::{DocState, Document};
use glam::DVec3;

impl ModelTab {
    pub(super) fn side_panel(&mut self, ui: &mut egui::Ui, doc: &Document) {
        ui.label(egui::RichText::new(&doc.origin().name).strong());
        ui.separator();
        let d = doc.state();
        self.pipeline_section(ui, d);
        ui.separator();
        self.tool_section(ui, d);
        ui.separator();
        egui::CollapsingHeader::new(egui::RichText::new("Display").heading())
            .default_open(true)
            .show(ui, |ui| self.display_section(ui, d));
    }

    /// The compare split's view count (1, 2 or 4), shown in the menu bar.
    pub fn views_picker(&mut self, ui: &mut egui::Ui, views: usize) {
        let mut n = views;
        ui.label("Compare:");
        for k in [1, 2, 4] {
            ui.selectable_value(
                &mut n,
                k,
                format!("{k} view{}", if k > 1 { "s" } else { "" }),
            )
            .on_hover_text(
                "each view has its own pipeline on the same solid; click a view to edit \
                     its pipeline in the side panel; the cameras are linked",
            );
        }
        if n != views {
            self.push(Edit::SetViews(n));
        }
    }

    fn pipeline_section(&mut self, ui: &mut egui::Ui, doc: &DocState) {
        let a = self.active;
        let view = a;
        if doc.pipelines.len() > 1 {
            ui.heading(format!("Pipeline of view {}", a + 1));
        } else {
            ui.heading("Pipeline");
        }
        let steps = &doc.pipelines[a];
        let mut edit: Option<Edit> = None;
        let n = steps.len();
        for (k, s) in steps.iter().enumerate() {
            ui.horizontal(|ui| {
                ui.label(format!("{}.", k + 1));
                let name = format!("scheme of step {}", k + 1);
                if let Some(scheme) = scheme_editor(ui, ("step", a, k), &name, s) {
                    edit = Some(Edit::SetStep {
                        view,
                        index: k,
                        scheme,
                    });
                }
                if ui
                    .add_enabled(
                        k > 0,
                        egui::Button::new(egui::RichText::new("▲").monospace()).small(),
                    )
                    .on_hover_text("move up")
                    .on_disabled_hover_text("the first step cannot move up")
                    .clicked()
                {
                    edit = Some(Edit::SwapSteps { view, index: k - 1 });
                }
                if ui
                    .add_enabled(
                        k + 1 < n,
                        egui::Button::new(egui::RichText::new("▼").monospace()).small(),
                    )
                    .on_hover_text("move down")
                    .on_disabled_hover_text("the last step cannot move down")
                    .clicked()
                {
                    edit = Some(Edit::SwapSteps { view, index: k });
                }
                if ui.small_button("×").on_hover_text("remove").clicked() {
                    edit = Some(Edit::RemoveStep { view, index: k });
                }
            });
            repeat_warning(ui, s);
        }
        if let Some(e) = edit {
            self.push(e);
        }
        self.pipeline_text(ui, view, steps);
        ui.horizontal(|ui| {
            ui.label("Next:");
            if let Some(n) = scheme_editor(ui, "next", "scheme of the next step", &self.next) {
                self.next = n;
            }
        });
        repeat_warning(ui, &self.next);
        if self.next.shrinks_when_repeated() {
            ui.horizontal(|ui| {
                ui.label("repeated, divide by");
                ui.add(egui::DragValue::new(&mut self.shrink).range(1.0..=16.0).speed(0.05))
                    .on_hover_text("Step >> after a step of the same chamfer divides its l or d by this (seed 000: about 4, so the new faces are not cut from both sides)");
            });
        }
        ui.horizontal(|ui| {
            if ui.button("Step >> (S)").clicked() {
                self.step();
            }
            if ui.button("<< Back (B)").clicked() {
                self.back();
            }
        });
        let n = self.views[a].steps().len();
        if n == 0 {
            self.playing = None;
        }
        if n > 0 {
            self.play_tick(std::time::Instant::now());
            let mut lv = self.views[a].level.min(n);
            ui.horizontal(|ui| {
                let (icon, tip) = match self.playing {
                    Some(_) => ("Pause levels", "Stop at the level shown"),
                    None => (
                        "Play levels",
                        "Show the levels one after another, a second each, from the input to the last and round again",
                    ),
                };
                if ui.button(icon).on_hover_text(tip).clicked() {
                    self.playing = match self.playing {
                        Some(_) => None,
                        None => Some(std::time::Instant::now()),
                    };
                }
            });
            if let Some(last) = self.playing {
                ui.ctx()
                    .request_repaint_after(super::PLAY_STEP.saturating_sub(last.elapsed()));
            }
            if ui
                .add(egui::Slider::new(&mut lv, 0..=n).text("level shown"))
                .changed()
            {
                self.views[a].level = lv;
                if self.link_levels {
                    // Every view at that level (or its last, when it has fewer steps).
                    for w in &mut self.views {
                        w.level = lv.min(w.steps().len());
                    }
                }
            }
            if self.views.len() > 1 {
                ui.checkbox(&mut self.link_levels, "Same level in every view")
                    .on_hover_text("the slider moves every view of the compare split to one level");
            }
            if self.views[a].keep == prism_geom::pipeline::Keep::Needed {
                ui.label("the levels between the input and the last were freed (memory)");
            }
        }
        let v = &mut self.views[a];
        if let Some(job) = &v.job {
            let (k, of) = job.computing();
            let secs = job.started.elapsed().as_secs_f32();
            let fraction = job.done as f32 / job.total.max(1) as f32;
            ui.horizontal(|ui| {
                ui.add(
                    egui::ProgressBar::new(fraction)
                        .text(format!("level {k} of {of}, {secs:.1} s"))
                        .desired_width(170.0),
                );
                if ui.button("Cancel").clicked() {
                    self.pending.push(Command::Cancel { view: a });
                }
            });
        }
        let mut clamp = self.clamp;
        if ui
            .checkbox(&mut clamp, "Clamp overlapping radii and chamfers")
            .on_hover_text(
                "Lower the radius of edges whose rounds do not fit their faces to what fits \
                 (listed in the status bar), a chamfer's l or d on faces too small for it and \
                 the vector sum's α on faces its reflex corners would cross; \
                 off: such a rounding step is refused, naming the edges",
            )
            .changed()
        {
            self.set_clamp(clamp);
        }
        if !self.clamp {
            ui.label(
                egui::RichText::new(
                    "Clamp off: the papers' literal rules (a radius that does not fit is refused)",
                )
                .weak(),
            );
        }
        let mut mend = self.mend_crossings;
        if ui
            .checkbox(&mut mend, "Mend faces that pass through each other")
            .on_hover_text(
                "After each rounding, search the whole level for faces that pass through \
                 each other and give the round up for a small chamfer at their vertices \
                 (a rounding step takes about seven times as long); off: faster, and only \
                 crossings beside the fold guard's moves are looked for",
            )
            .changed()
        {
            self.set_mend_crossings(mend);
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

    /// The pipeline as text (`combination:r=0.2,doo-sabin`, the CLI's form): typed and
    /// applied with Enter, or copied out.
    fn pipeline_text(&mut self, ui: &mut egui::Ui, view: usize, steps: &[prism_geom::Scheme]) {
        ui.horizontal(|ui| {
            ui.label("as text:");
            let shown = prism_geom::scheme::format_pipeline(steps);
            let mut text = match &self.pipeline_edit {
                Some((v, t)) if *v == view => t.clone(),
                _ => shown.clone(),
            };
            let resp = ui.add(
                egui::TextEdit::singleline(&mut text)
                    .desired_width(ui.available_width())
                    .hint_text("e.g. combination:r=0.2,doo-sabin"),
            );
            if resp.changed() {
                self.pipeline_edit = Some((view, text.clone()));
            }
            if resp.lost_focus() {
                if ui.input(|i| i.key_pressed(egui::Key::Enter)) && text != shown {
                    let parsed = if text.trim().is_empty() {
                        Ok(Vec::new())
                    } else {
                        prism_geom::parse_pipeline(&text)
                    };
                    match parsed {
                        Ok(steps) => self.push(Edit::SetPipeline { view, steps }),
                        Err(e) => self.push(Command::Say(format!("pipeline: {e}"))),
                    }
                }
                self.pipeline_edit = None;
            }
        });
    }

    fn tool_section(&mut self, ui: &mut egui::Ui, doc: &DocState) {
        ui.heading("Tool");
        ui.horizontal(|ui| {
            ui.selectable_value(&mut self.tool, Tool::Orbit, "Orbit");
            ui.selectable_value(&mut self.tool, Tool::Vertices, "Vertices");
            ui.selectable_value(&mut self.tool, Tool::Edges, "Edges");
            ui.selectable_value(&mut self.tool, Tool::Measure, "Measure");
        });
        match self.tool {
            Tool::Orbit => {
                ui.label("Drag to turn, right-drag to pan, scroll to zoom.");
            }
            Tool::Vertices => self.vertex_section(ui, doc),
            Tool::Edges => self.edge_section(ui, doc),
            Tool::Measure => self.measure_section(ui),
        }
    }

    /// The Measure tool's read-out: the points clicked, the distances between them and, for
    /// three, the radius of the circle through them.
    fn measure_section(&mut self, ui: &mut egui::Ui) {
        ui.label(
            "Click points on the surface of the level shown: two give their distance, three \
             the radius of the circle through them (a fillet's, across its section); a fourth \
             starts again. Right-drag turns the view.",
        );
        for (k, p) in self.measure.iter().enumerate() {
            ui.label(format!(
                "point {}: ({:.5}, {:.5}, {:.5})",
                k + 1,
                p.x,
                p.y,
                p.z
            ));
        }
        for line in measure_lines(&self.measure) {
            ui.label(line);
        }
        if !self.measure.is_empty() && ui.button("Clear the points").clicked() {
            self.measure.clear();
        }
    }

    fn vertex_section(&mut self, ui: &mut egui::Ui, doc: &DocState) {
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
            .map(|&v| doc.mesh.positions[v as usize])
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

    fn edge_section(&mut self, ui: &mut egui::Ui, doc: &DocState) {
        ui.label("Click an edge on any level (shift-click adds, drag a box); marks go on the control edge it comes from. Right-drag turns the view.");
        ui.horizontal(|ui| {
            if ui.button("Select edges sharper than").clicked() {
                let add = ui.input(|i| i.modifiers.shift);
                self.select_sharper_than(doc, self.sharper_deg, add);
            }
            ui.add(
                egui::DragValue::new(&mut self.sharper_deg)
                    .range(0.0..=180.0)
                    .suffix("°"),
            );
        });
        let marked = doc.edge_attrs.len();
        ui.label(format!(
            "{} control edge(s) selected (yellow), {marked} marked",
            self.sel_edges.len()
        ))
        .on_hover_text("marked edges are drawn red (creased) or cyan (own radius)");
        // Sharpness is read by the primal steps only: say so rather than report a crease
        // that changes nothing.
        let primal = self.views[self.active]
            .steps()
            .iter()
            .any(|s| matches!(s, prism_geom::Scheme::Primal(_)));
        ui.horizontal(|ui| {
            let crease = ui
                .add_enabled(primal, egui::Button::new("Crease"))
                .on_disabled_hover_text(
                    "creases are read by Catmull–Clark and Loop steps; this pipeline has none (the biquadratic steps round or chamfer every edge)",
                );
            if crease.clicked() {
                self.mark(EdgeMark::Crease(self.crease_value));
            }
            ui.add(
                egui::Slider::new(&mut self.crease_value, 0.0..=10.0)
                    .text("sharpness (10 = sharp)"),
            );
        });
        ui.horizontal(|ui| {
            let own = ui.button("Own radius");
            if own.clicked() {
                self.mark(EdgeMark::Radius(Some(self.radius_value)));
            }
            ui.add(
                egui::DragValue::new(&mut self.radius_value)
                    .speed(0.005)
                    .range(1e-4..=1e6),
            )
            .labelled_by(own.id);
            if ui.button("Step's radius").clicked() {
                self.mark(EdgeMark::Radius(None));
            }
            if ui.button("Clear crease").clicked() {
                self.mark(EdgeMark::Crease(0.0));
            }
        });
        if self.sel_edges.len() == 1 {
            let e = *self.sel_edges.first().expect("one edge");
            let text = self.fillet_text(self.active, doc);
            ui.label(format!("fillet reached on {}-{}: {text}", e.0, e.1));
        }
    }

    fn display_section(&mut self, ui: &mut egui::Ui, doc: &DocState) {
        let d = &mut self.display;
        ui.checkbox(&mut d.smooth, "smooth shading (F)");
        ui.checkbox(&mut d.wireframe, "wireframe (W)");
        ui.horizontal(|ui| {
            ui.label("colour:");
            ui.radio_value(&mut d.color, Coloring::Uniform, "one");
            ui.radio_value(&mut d.color, Coloring::Kind, "face kind")
                .on_hover_text("the FACE-, EDGE- and VERTEX-faces of the last biquadratic step, in the three colours of the legend below");
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
        // The section's choice shares the last row with the framing button (the panel fits
        // 1280×800 with the Edges tool); its slider shows below once a plane is chosen.
        let mut frame = false;
        ui.horizontal(|ui| {
            frame = ui.button("Frame the model").clicked();
            section_choice(ui, &mut self.display.section);
        });
        if let Some(s) = &mut self.display.section {
            ui.horizontal_wrapped(|ui| {
                let mut at = f64::from(s.permille) / 1000.0;
                ui.add(egui::Slider::new(&mut at, 0.0..=1.0).text("along the box"));
                s.permille = (at * 1000.0).round() as u16;
                ui.checkbox(&mut s.above, "keep beyond");
            });
        }
        if frame {
            self.frame(doc);
        }
    }
}

/// The section plane's choice: off or an axis (a plane at the middle of the level's box,
/// the part before it kept, until the slider below says otherwise).
fn section_choice(ui: &mut egui::Ui, section: &mut Option<super::display::Section>) {
    let name = |s: &Option<super::display::Section>| match s {
        None => "off",
        Some(s) => ["x", "y", "z"][usize::from(s.axis.min(2))],
    };
    let mut axis = section.map(|s| s.axis);
    egui::ComboBox::from_label("section")
        .selected_text(name(section))
        .show_ui(ui, |ui| {
            ui.selectable_value(&mut axis, None, "off");
            for (k, n) in ["x", "y", "z"].iter().enumerate() {
                ui.selectable_value(&mut axis, Some(k as u8), *n)
                    .on_hover_text(format!(
                        "cut the model by a plane normal to {n}, the cut's outline in yellow"
                    ));
            }
        });
    *section = axis.map(|axis| super::display::Section {
        axis,
        ..section.unwrap_or(super::display::Section {
            axis,
            permille: 500,
            above: false,
        })
    });
}

/// What the Measure tool's points measure, one line each: the distances between consecutive
/// points and, for three, the radius of the circle through them.
pub fn measure_lines(points: &[glam::DVec3]) -> Vec<String> {
    let mut out: Vec<String> = points
        .windows(2)
        .enumerate()
        .map(|(k, w)| format!("distance {}–{}: {:.5}", k + 1, k + 2, w[0].distance(w[1])))
        .collect();
    if let [a, b, c] = points {
        out.push(format!("distance 1–3: {:.5}", a.distance(*c)));
        out.push(match prism_geom::geometry::circumradius(*a, *b, *c) {
            Some(r) => format!("radius of the circle through 1, 2, 3: {r:.5}"),
            None => "the three points lie on a line: no circle".to_string(),
        });
    }
    out
}
