//! The Envelope tab's t sweep (docs/algorithms/envelope.md, "Figures"): the scene built at
//! three t side by side under one camera.

use super::*;

impl EnvelopeTab {
    /// The sweep's views: t and the number of patches (none when the envelope failed).
    pub fn sweep_summary(&self) -> Vec<(f64, Option<usize>)> {
        self.sweep_views
            .iter()
            .map(|v| {
                (
                    v.t,
                    v.built.result.as_ref().ok().map(|(e, _)| e.patch_count()),
                )
            })
            .collect()
    }

    /// The t sweep: three views side by side, one camera, each labelled with its t and its
    /// patches (or why it has none).
    pub(super) fn paint_sweep(&self, ui: &egui::Ui, rect: egui::Rect) {
        let w = rect.width() / self.sweep_views.len() as f32;
        // A cell is narrower than the view the camera was framed for: move back so that the
        // same width shows (the model's width fills a cell as its height filled the view).
        let mut camera = self.base.view.camera;
        let cell_aspect = w / rect.height().max(1.0);
        let aspect = rect.width() / rect.height().max(1.0);
        camera.zoom((0.8 * aspect.min(1.0) / cell_aspect).max(1.0));
        let summary = self.sweep_summary();
        for (i, v) in self.sweep_views.iter().enumerate() {
            let cell = egui::Rect::from_min_size(
                rect.left_top() + egui::vec2(i as f32 * w, 0.0),
                egui::vec2(w, rect.height()),
            );
            self.base
                .view
                .paint_scene(ui, cell, 1 + i, (&v.scene, &v.overlay), camera);
            if i > 0 {
                ui.painter().vline(
                    cell.left(),
                    cell.y_range(),
                    egui::Stroke::new(1.0, egui::Color32::from_gray(90)),
                );
            }
            let text = match (summary[i].1, &v.built.result) {
                (Some(n), Ok((e, _))) if e.surfacing == Surfacing::Charts => {
                    format!("t = {}: {n} charts", v.t)
                }
                (Some(n), _) => format!("t = {}: {n} patches", v.t),
                (None, Err(e)) => format!("t = {}: {e}", v.t),
                (None, Ok(_)) => format!("t = {}", v.t),
            };
            let at = cell.left_top() + egui::vec2(8.0, 8.0);
            viewport::caption(ui, (at, egui::Align2::LEFT_TOP), text, 14.0, 220);
        }
    }
}
