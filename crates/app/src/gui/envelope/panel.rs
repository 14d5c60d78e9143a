//! The Envelope tab's side panel ([`EnvelopeTab::panel`]): the summary and quality report,
//! the primitives and the selected one's placement, the curvature t, the surface and display
//! options.

use super::*;
use crate::gui::latest;

impl EnvelopeTab {
    /// The tab's side panel: the library or a bundled scene when there is none; else the
    /// summary, the primitives, the selected one's placement, t, the surface and display
    /// options.
    pub(super) fn side_panel(&mut self, ui: &mut egui::Ui, spec: Option<&EnvelopeSpec>) {
        ui.heading("Envelope of primitives");
        let Some(spec) = spec else {
            ui.label("No primitive yet. Start from one of the library:");
            ui.horizontal_wrapped(|ui| {
                for (name, shape) in LIBRARY {
                    if ui.button(name).clicked() {
                        self.base.view.reframe();
                        self.set(Some(of_shape(shape)), None);
                    }
                }
            });
            ui.label("or a bundled scene (also in File > Samples):");
            self.sample_buttons(ui);
            return;
        };
        self.summary(ui);
        ui.separator();
        ui.label("Primitives");
        for (k, p) in spec.primitives.iter().enumerate() {
            let c = centre_of(p);
            let text = format!(
                "{k}: {} vertices, {} faces at ({:.2}, {:.2}, {:.2})",
                p.vertices.len(),
                p.faces.len(),
                c.x,
                c.y,
                c.z
            );
            if ui.selectable_label(k == self.selected, text).clicked() {
                self.selected = k;
            }
        }
        let k = self.selected;
        ui.horizontal_wrapped(|ui| {
            ui.label("Replace with");
            for (name, shape) in LIBRARY {
                if ui.small_button(name).clicked() {
                    let mut s = spec.clone();
                    let at = spec.primitives.get(k).map(centre_of).unwrap_or_default();
                    s.primitives[k] = mapped(&shape.placed(&Placement::default()), |v| v + at);
                    self.picked = None;
                    self.set(Some(s), None);
                }
            }
        });
        ui.horizontal_wrapped(|ui| {
            ui.menu_button("Add", |ui| {
                for (name, shape) in LIBRARY {
                    if ui.button(name).clicked() {
                        let mut s = spec.clone();
                        let at = spec.primitives.get(k).map(centre_of).unwrap_or_default();
                        // Beside the selected one, clear of every centre in the scene.
                        let step = DVec3::new(2.5, 0.8, 0.4);
                        let mut c = at + step;
                        while spec
                            .primitives
                            .iter()
                            .any(|p| centre_of(p).distance(c) < 1.0)
                        {
                            c += step;
                        }
                        s.primitives
                            .push(mapped(&shape.placed(&Placement::default()), |v| v + c));
                        self.selected = s.primitives.len() - 1;
                        self.set(Some(s), None);
                    }
                }
            });
            let delete = ui.add_enabled(spec.primitives.len() > 1, egui::Button::new("Delete"));
            if delete
                .on_disabled_hover_text("The scene needs a primitive; Clear removes the scene")
                .clicked()
            {
                let mut s = spec.clone();
                s.primitives.remove(k);
                self.picked = None;
                self.set(Some(s), None);
            }
        });
        if let Some(p) = spec.primitives.get(k) {
            self.placement(ui, spec, k, p);
        }
        ui.separator();
        self.curvature(ui, spec);
        ui.separator();
        ui.label("Surface");
        let mut surfacing = spec.patches;
        gestures::radio_row(
            ui,
            "",
            &mut surfacing,
            &[
                (
                    Surfacing::Charts,
                    "charts",
                    "Each region a graph over its flat chart: it cannot fold, the faces are enclosed, G1 along every curve by one shared tangent plane (the default)",
                ),
                (
                    Surfacing::Paper,
                    "paper",
                    "Seed 004 §6 as printed: vector Coons patches with Gregory's twist, n-sided regions split about an inserted point; may fold (counted below)",
                ),
            ],
        );
        let mut enclosure = spec.enclosure;
        ui.add_enabled_ui(spec.patches == Surfacing::Charts, |ui| {
            gestures::radio_row(ui, "Cut corners", &mut enclosure, &[
                (Enclosure::Lifted, "held", "The fusion strips are raised over the corners the silhouette plane through each centre cuts off: every primitive lies inside (the default)"),
                (Enclosure::Paper, "paper's cut", "The paper's central cut as it lies: at small t a cut-off corner can poke out (named in the Enclosure row)"),
            ]);
        })
        .response
        .on_disabled_hover_text("The charts only: the paper's patches keep the paper's cut");
        let chosen = (surfacing, enclosure);
        let changed = chosen != (spec.patches, spec.enclosure);
        self.set_changed(spec, changed, |s| (s.patches, s.enclosure) = chosen, None);
        let mut res = spec.resolution;
        let text = match spec.patches {
            Surfacing::Charts => "mesh density",
            Surfacing::Paper => "quads a patch side",
        };
        let r = gestures::resolution_slider(ui, &mut res, text).on_hover_text(match spec.patches {
            Surfacing::Charts => "About this many mesh edges along a primitive's edge",
            Surfacing::Paper => "Quads along each side of a patch",
        });
        let g = self.base.gestures.of(&r);
        self.set_changed(spec, res != spec.resolution, |s| s.resolution = res, g);
        let mut basis = spec.basis;
        ui.add_enabled_ui(spec.patches == Surfacing::Paper, |ui| gestures::basis_row(ui, &mut basis, [
            "Both sides of a border from the crossing curves: the surface does not depend on how faces and primitives are listed (the default)",
            "The region listed first leads each border and the other follows: G1 too, but a cube's tangent planes tilt 18° into the sphere at mid-edge and the shape depends on the listing",
        ]))
        .response
        .on_disabled_hover_text("The paper's patches only: the charts share one tangent plane per curve");
        self.set_changed(spec, basis != spec.basis, |s| s.basis = basis, None);
        self.mouse.row(
            ui,
            &[Mouse::Orbit, Mouse::Move, Mouse::Scale],
            "Move and scale act on the primitive; right drag orbits then. A click picks a vertex for its own t",
        );
        ui.separator();
        ui.label("Show");
        let o = &mut self.overlays;
        ui.checkbox(&mut o.primitives, "Primitive (grey)");
        ui.checkbox(&mut o.edges, "Curved edges (yellow)");
        ui.checkbox(&mut o.silhouettes, "Silhouette edges (orange)");
        ui.checkbox(&mut o.fusion, "Fusion edges between primitives (green)");
        ui.checkbox(&mut o.insertions, "Insertion curves of split faces (blue)");
        ui.checkbox(
            &mut o.straight,
            "Straight edges of the sections, inside (violet)",
        );
        ui.checkbox(&mut o.surface, "Surface");
        o.look.ui(ui);
        ui.checkbox(&mut self.sweep, "t sweep: t = 1, 0.5, 0.1 side by side")
            .on_hover_text("The paper's Table 1: the same scene with one t everywhere, three views sharing the camera");
        ui.horizontal(|ui| {
            if ui.button("Frame the envelope").clicked() {
                self.base.view.frame();
            }
            if ui.button("Clear").clicked() {
                self.set(None, None);
            }
        });
    }

    fn summary(&mut self, ui: &mut egui::Ui) {
        let shown = self.built.is_some();
        if self.sweep {
            latest::progress_row(ui, &mut self.sweeps, !self.sweep_views.is_empty());
        }
        latest::progress_row(ui, &mut self.builds, shown);
        let Some(b) = &self.built else {
            return;
        };
        match &b.result {
            Ok((e, m)) => {
                ui.label(format!(
                    "{} primitive(s), {} regions, {} {}, {} faces",
                    e.primitives.len(),
                    e.regions,
                    e.patch_count(),
                    match e.surfacing {
                        Surfacing::Charts => "charts",
                        Surfacing::Paper => "patches",
                    },
                    m.num_faces()
                ));
                if let Some(note) = e.removed_note() {
                    ui.label(note)
                    .on_hover_text("The paper cuts every primitive by the plane through its centre normal to each partner; these keep nothing (seed 004 §5.1.3). A primitive inside a larger one's sphere whose shape lies inside the others' envelope is left out too: the strip between them would fold");
                }
                if let Some(p) = e.primitives.get(self.selected) {
                    let c = e.frame.to_world(p.centre);
                    ui.label(format!(
                        "primitive {}: centre ({:.3}, {:.3}, {:.3}), sphere radius r = {:.4}",
                        self.selected,
                        c.x,
                        c.y,
                        c.z,
                        p.radius * e.frame.scale
                    ));
                }
                ui.label(format!(
                    "G1: largest normal jump across region borders {:.1e}°; network and {} in {:.2} ms",
                    b.jump,
                    match e.surfacing {
                        Surfacing::Charts => "charts",
                        Surfacing::Paper => "patches",
                    },
                    b.millis
                ));
                // One row each whatever the answer, with the long text on hover: the
                // crossing check answers a few frames later, and a line that wrapped then
                // would move every field below it under the pointer.
                let red = egui::Color32::from_rgb(255, 120, 100);
                let row = |ui: &mut egui::Ui, text: egui::RichText, hover: String| {
                    ui.add(egui::Label::new(text).truncate())
                        .on_hover_text(hover);
                };
                match &b.quality {
                    Some(q) => {
                        row(
                            ui,
                            format!(
                                "Mesh: angles {:.1}°–{:.1}°, largest turn {:.1}°",
                                q.smallest_angle, q.largest_angle, q.largest_turn.0
                            )
                            .into(),
                            format!(
                                "{}\nThe largest turn is between neighbouring triangles of {}; it falls with a finer mesh where the surface is smooth",
                                q.summary(),
                                e.describe_region(q.largest_turn.1)
                            ),
                        );
                        match q.enclosure_warning(&e.removed) {
                            Some(w) => row(
                                ui,
                                egui::RichText::new(format!(
                                    "Enclosure: a primitive reaches {:.3} r outside",
                                    -q.worst_enclosure().map_or(0.0, |x| x.1)
                                ))
                                .color(red),
                                w,
                            ),
                            None => row(
                                ui,
                                "Enclosure: every primitive inside".into(),
                                "Points on every primitive's faces, edges and vertices lie inside the surface".into(),
                            ),
                        }
                    }
                    None => row(
                        ui,
                        egui::RichText::new("Mesh: measuring…").weak(),
                        "Angles, normal turns and enclosure of the mesh as written".into(),
                    ),
                }
                match &b.folds {
                    Some((n, text)) => row(
                        ui,
                        egui::RichText::new(format!("Folds: {n} cell(s), marked with red crosses"))
                            .color(red),
                        text.clone(),
                    ),
                    None if e.surfacing == Surfacing::Charts => row(
                        ui,
                        "Folds: none (a graph cannot fold)".into(),
                        "Every region is a graph of one number over its flat chart".into(),
                    ),
                    None => row(
                        ui,
                        "Folds: none".into(),
                        "Every sampled cell faces like its patch's corners".into(),
                    ),
                }
                match &b.crossings {
                    build::Crossings::Checking(_) => {
                        row(
                            ui,
                            egui::RichText::new("Crossings: checking…").weak(),
                            "Looking for faces of the surface that pass through each other".into(),
                        );
                        ui.ctx()
                            .request_repaint_after(std::time::Duration::from_millis(30));
                    }
                    build::Crossings::Done(_, Some(text)) => row(
                        ui,
                        egui::RichText::new(format!(
                            "Crossings: {} pair(s), marked with red crosses",
                            b.crossing_points().len()
                        ))
                        .color(red),
                        format!("Faces of the surface pass through each other. {text}"),
                    ),
                    build::Crossings::Done(_, None) => row(
                        ui,
                        "Crossings: none".into(),
                        "No two faces of the surface pass through each other".into(),
                    ),
                    build::Crossings::None => {}
                }
            }
            Err(e) => {
                ui.colored_label(
                    egui::Color32::from_rgb(255, 120, 100),
                    format!("No envelope: {e}"),
                );
            }
        }
    }

    /// The selected primitive's centre, turn about the axes and scale; a field's drag one
    /// undo step.
    fn placement(&mut self, ui: &mut egui::Ui, spec: &EnvelopeSpec, k: usize, p: &PrimitiveInput) {
        let mut gst = self.gesture;
        let [rx, ry, rz] = &mut gst.rotate;
        let turns = vec![(
            "turn °",
            vec![
                (rx, "x: ", DVec3::X),
                (ry, "y: ", DVec3::Y),
                (rz, "z: ", DVec3::Z),
            ],
        )];
        let placed = self.base.gestures.placement(ui, centre_of(p), turns);
        self.gesture = gst;
        if let Some((map, g)) = placed {
            let mut s = spec.clone();
            s.primitives[k] = mapped(p, |v| map.transform_point3(v));
            self.set(Some(s), g);
        }
    }

    fn curvature(&mut self, ui: &mut egui::Ui, spec: &EnvelopeSpec) {
        ui.label("Curvature parameter t (ρ = t·r at every vertex)");
        let mut t = spec.t;
        let r = ui
            .add(
                // A scene opened with t outside the slider's range (the CLI takes any t > 0)
                // keeps it until the slider is moved.
                egui::Slider::new(&mut t, 0.1..=3.0)
                    .logarithmic(true)
                    .clamping(egui::SliderClamping::Edits)
                    .text("t"),
            )
            .on_hover_text("1: edges are arcs on the primitive's sphere; towards 0 the surface tends to the flat faces; above 1 the edges bulge outside the sphere (polynomial cubics at 3/(1 + 2cos θ), 1.14 on a cube)");
        let g = self.base.gestures.of(&r);
        if t != spec.t {
            let mut s = spec.clone();
            s.t = t;
            for p in &mut s.primitives {
                p.t = None;
            }
            self.set(Some(s), g);
        }
        let Some((pi, v)) = self.picked else {
            ui.label("Click a vertex in the view to give it its own t.");
            return;
        };
        let Some(p) = spec.primitives.get(pi) else {
            return;
        };
        let base = p.t.unwrap_or(spec.t);
        let mut own = p
            .vertex_t
            .as_ref()
            .and_then(|vt| vt.get(v).copied())
            .unwrap_or(base);
        ui.horizontal(|ui| {
            ui.label(format!("vertex {v}"));
            let r = ui.add(
                egui::DragValue::new(&mut own)
                    .prefix("own t: ")
                    .speed(0.01)
                    .range(0.1..=3.0)
                    .clamp_existing_to_range(false)
                    .min_decimals(2)
                    .max_decimals(3),
            );
            let g = self.base.gestures.of(&r);
            if r.changed() {
                let mut s = spec.clone();
                let q = &mut s.primitives[pi];
                let mut vt = q
                    .vertex_t
                    .clone()
                    .unwrap_or_else(|| vec![base; q.vertices.len()]);
                vt[v] = own;
                q.vertex_t = Some(vt);
                self.set(Some(s), g);
            }
            if ui
                .add_enabled(p.vertex_t.is_some(), egui::Button::new("All vertices to t"))
                .on_disabled_hover_text("No vertex has its own t")
                .clicked()
            {
                let mut s = spec.clone();
                s.primitives[pi].vertex_t = None;
                self.set(Some(s), None);
            }
        });
    }
}
