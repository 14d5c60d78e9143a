//! The table under the compare split: per view, its pipeline, counts of the level shown,
//! flipped faces, the fillet radius reached and the time of every level.
//!
//! The fillet radius is measured on one control edge ([`prism_geom::analysis::measure_fillet`]:
//! a circle fitted to the section through the edge's midpoint): the selected edge when
//! exactly one is selected, otherwise the first control edge that has a fillet. The target
//! is the radius of the view's last cylindrical-family step (or the edge's own radius).

use super::ModelTab;
use crate::gui::document::DocState;
use prism_geom::analysis::measure_fillet;
use prism_geom::{CornerRule, EdgeKey, Scheme};

/// The rule of a pipeline's last step with a radius: it says which radius an edge gets.
fn rounding_rule(steps: &[Scheme]) -> Option<CornerRule> {
    steps.iter().rev().find_map(|s| match s {
        Scheme::Biquadratic(rule) => rule.radius().map(|_| *rule),
        Scheme::Primal(_) => None,
    })
}

impl ModelTab {
    /// The fillet measure of view `i`'s shown level, as table text.
    pub fn fillet_text(&mut self, i: usize, doc: &DocState) -> String {
        let edge = (self.sel_edges.len() == 1)
            .then(|| self.sel_edges.iter().next().copied())
            .flatten();
        let key = (self.views[i].generation, edge);
        if let Some((k, t)) = &self.views[i].fillet
            && *k == key
        {
            return t.clone();
        }
        let v = &self.views[i];
        let text = match rounding_rule(v.steps()) {
            None => "—".to_string(),
            Some(rule) => {
                let control = &doc.mesh;
                let refined = &v.pipeline.levels()[v.shown()].mesh;
                let candidates: Vec<EdgeKey> = match edge {
                    Some(e) => vec![e],
                    None => super::pick::mesh_edges(control),
                };
                // Each try slices the refined mesh: a few edges, not all of a big model.
                let found = candidates.iter().take(16).find_map(|e| {
                    let r = rule.edge_radius(doc.edge_attrs.get(e))?;
                    measure_fillet(control, e.0, e.1, refined, r)
                        .ok()
                        .map(|m| (*e, r, m))
                });
                match found {
                    Some((e, r, m)) => format!(
                        "{:.4} (r = {r}, edge {}-{}, error {:+.2} %)",
                        m.fitted_radius,
                        e.0,
                        e.1,
                        100.0 * m.max_radial_error
                    ),
                    None => "no fillet yet".to_string(),
                }
            }
        };
        self.views[i].fillet = Some((key, text.clone()));
        text
    }

    pub(super) fn compare_table(&mut self, ui: &mut egui::Ui, doc: &DocState) {
        let rows: Vec<[String; 7]> = (0..self.views.len())
            .map(|i| {
                let fillet = self.fillet_text(i, doc);
                let v = &self.views[i];
                let k = v.shown();
                let lv = &v.pipeline.levels()[k];
                let flipped = lv.report.as_ref().map_or(0, |r| r.flipped.len());
                let times: Vec<String> = v.pipeline.levels()[1..]
                    .iter()
                    .map(|l| format!("{:.1}", l.report.as_ref().map_or(0.0, |r| r.millis)))
                    .collect();
                [
                    format!("{}", i + 1),
                    prism_geom::scheme::format_pipeline(v.steps()),
                    lv.mesh.num_vertices().to_string(),
                    lv.mesh.num_faces().to_string(),
                    flipped.to_string(),
                    fillet,
                    times.join(" / "),
                ]
            })
            .collect();
        egui::ScrollArea::both().show(ui, |ui| {
            egui::Grid::new("compare-table")
                .striped(true)
                .num_columns(7)
                .show(ui, |ui| {
                    for h in [
                        "view",
                        "pipeline",
                        "vertices",
                        "faces",
                        "flipped",
                        "fillet radius reached",
                        "ms per level",
                    ] {
                        ui.strong(h);
                    }
                    ui.end_row();
                    for (i, row) in rows.iter().enumerate() {
                        for (c, cell) in row.iter().enumerate() {
                            if c == 0 {
                                if ui.selectable_label(i == self.active, cell).clicked() {
                                    self.active = i;
                                }
                            } else if c == 4 && cell != "0" {
                                ui.colored_label(egui::Color32::from_rgb(240, 110, 90), cell);
                            } else {
                                ui.label(cell);
                            }
                        }
                        ui.end_row();
                    }
                });
        });
    }
}
