//! The Model tab's status bar: the level's counts and time, the step's notes in the CLI's
//! words ([`step_notes`]), the flipped faces' and the crossings' menus.

use super::ModelTab;
use super::crossing_check::Crossings;

impl ModelTab {
    /// "N flipped faces": a menu listing them (the first hundred); opening it frames the
    /// first, clicking one frames that one.
    fn flipped_menu(&mut self, ui: &mut egui::Ui, flipped: &[u32]) {
        let red = egui::Color32::from_rgb(240, 90, 80);
        let title =
            egui::RichText::new(format!("{} flipped face(s): show", flipped.len())).color(red);
        let menu = ui.menu_button(title, |ui| {
            ui.label("Drawn in red. Click one to frame it:");
            egui::ScrollArea::vertical()
                .max_height(240.0)
                .show(ui, |ui| {
                    for &f in flipped.iter().take(100) {
                        if ui.button(format!("face {f}")).clicked() {
                            self.frame_face(f);
                        }
                    }
                    if flipped.len() > 100 {
                        ui.label(format!("… and {} more", flipped.len() - 100));
                    }
                });
        });
        if menu.response.clicked() {
            self.frame_face(flipped[0]);
        }
    }

    /// "N pairs of faces pass through each other": a menu like the flipped faces' one; or
    /// that the check is running, or a button to run it on a big level.
    fn crossings_status(&mut self, ui: &mut egui::Ui, crossings: Crossings) {
        match crossings {
            Crossings::Waiting => {}
            Crossings::Checking => {
                ui.weak("checking for faces that pass through each other…");
            }
            Crossings::Ask { faces } => {
                if ui
                    .button("Check for faces that pass through each other")
                    .on_hover_text(format!(
                        "{faces} faces: a few seconds on a thread (levels up to {} faces are checked by themselves)",
                        super::crossing_check::AUTO_FACES
                    ))
                    .clicked()
                {
                    self.views[self.active].ask_crossings();
                }
            }
            Crossings::Done(pairs) if pairs.is_empty() => {}
            Crossings::Done(pairs) => {
                let red = egui::Color32::from_rgb(240, 90, 80);
                let title = egui::RichText::new(format!(
                    "{} pair(s) of faces pass through each other: show",
                    pairs.len()
                ))
                .color(red);
                let menu = ui.menu_button(title, |ui| {
                    ui.label("The surface crosses itself there (drawn in red). Click a pair to frame it:");
                    egui::ScrollArea::vertical()
                        .max_height(240.0)
                        .show(ui, |ui| {
                            for &(f, g) in pairs.iter().take(100) {
                                if ui.button(format!("faces {f} and {g}")).clicked() {
                                    self.frame_face(f);
                                }
                            }
                            if pairs.len() > 100 {
                                ui.label(format!("… and {} more", pairs.len() - 100));
                            }
                        });
                });
                if menu.response.clicked() {
                    self.frame_face(pairs[0].0);
                }
            }
        }
    }

    pub(super) fn status(&mut self, ui: &mut egui::Ui, note: Option<&str>) {
        let (_, _, far) = self.views[self.active].frame_sphere();
        let missed = self.missed_radii(self.active);
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
            if let Some(t) = v.last_edit {
                text += &format!(" (last edit to picture {:.0} ms)", t.as_secs_f64() * 1e3);
            }
            // The radii the rounding run clamped, at every level of it (orange in the view).
            let clamped = v
                .pipeline
                .rounding_run(k)
                .and_then(|run| v.pipeline.levels()[run.start + 1].report.as_ref())
                .map(|first| &first.clamped[..])
                .unwrap_or(&r.clamped[..]);
            if !clamped.is_empty() {
                text += &format!(" — {} (orange)", prism_geom::rules::overlap::note(clamped));
            }
            if !missed.is_empty() {
                text += &format!(" — warning: {} (red)", missed_note(&missed));
            }
            text += &step_notes(r);
            if far > 0 {
                text += &format!(
                    " — warning: {far} corner(s) lie far outside the rest of the model (framing leaves them out)"
                );
            }
        }
        let flipped = lv
            .report
            .as_ref()
            .map(|r| r.flipped.clone())
            .unwrap_or_default();
        let error = v.error.clone();
        let crossings = v.crossings();
        // The alarms first; the text after them wraps where it is wider than the window, so
        // that the step's notes at its end stay in view.
        ui.horizontal_wrapped(|ui| {
            if !flipped.is_empty() {
                self.flipped_menu(ui, &flipped);
            }
            self.crossings_status(ui, crossings);
            if let Some(e) = &error {
                ui.colored_label(egui::Color32::from_rgb(240, 110, 90), e);
            }
            ui.label(text);
            if let Some(n) = note {
                ui.separator();
                ui.label(n);
            }
        });
    }
}

/// The clamped edges whose fillet misses their radius, in words: the first five with both
/// numbers, then how many more.
pub fn missed_note(missed: &[(prism_geom::EdgeKey, f64, Option<f64>)]) -> String {
    let mut parts: Vec<String> = missed
        .iter()
        .take(5)
        .map(|(e, r, m)| {
            let m = m.map_or("too few points to measure".to_string(), |m| {
                format!("{m:.4}")
            });
            format!("edge {}-{} clamped to {r:.4} reaches {m}", e.0, e.1)
        })
        .collect();
    if missed.len() > 5 {
        parts.push(format!("and {} more", missed.len() - 5));
    }
    format!(
        "the combination rule misses {} clamped radius(es): {}",
        missed.len(),
        parts.join(", ")
    )
}

/// The step's report in the status bar: every note and warning of [`StepReport::notes`], in
/// the CLI's words, but for the flipped faces (the bar's menu button names them) and the
/// clamped radii (the bar lists the whole rounding run's, in orange).
///
/// [`StepReport::notes`]: prism_geom::StepReport::notes
pub(crate) fn step_notes(r: &prism_geom::StepReport) -> String {
    use prism_geom::step::Topic;
    let mut text = String::new();
    for n in r.notes() {
        if matches!(n.topic, Topic::Flipped | Topic::ClampedRadii) {
            continue;
        }
        text += " — ";
        if n.warning {
            text += "warning: ";
        }
        text += &n.text;
    }
    text
}
