//! The table under the compare split: per view, its pipeline, counts of the level shown,
//! flipped faces, pairs of faces through each other, the fillet radius reached and the time of
//! every level.
//!
//! The fillet radius is measured on one control edge ([`prism_geom::analysis::measure_fillet`]:
//! a circle fitted to the section through the edge's midpoint): the selected edge when
//! exactly one is selected, otherwise the first control edge that has a fillet. The target
//! is the radius the edge was rounded to ([`prism_geom::RoundingRun::radius`]: clamped, its
//! own, or the step's). The Edges tool shows the same for the selected edge.

use super::ModelTab;
use super::crossing_check::Crossings;
use crate::gui::document::DocState;
use prism_geom::EdgeKey;
use prism_geom::analysis::measure_fillet;

/// A pipeline for reading at a glance: runs of the same step written once with their count
/// (`5 × combination:r=0.2, 2 × doo-sabin`); "no steps" for none.
pub fn short_pipeline(steps: &[prism_geom::Scheme]) -> String {
    let mut runs: Vec<(usize, String)> = Vec::new();
    for s in steps {
        let text = s.to_string();
        match runs.last_mut() {
            Some((n, t)) if *t == text => *n += 1,
            _ => runs.push((1, text)),
        }
    }
    if runs.is_empty() {
        return "no steps".into();
    }
    runs.iter()
        .map(|(n, t)| {
            if *n > 1 {
                format!("{n} × {t}")
            } else {
                t.clone()
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

impl ModelTab {
    /// The clamped edges of view `i`'s rounding run whose fillet on the shown level misses the
    /// radius the panel says (measured once a level; empty where nothing was clamped): drawn
    /// red in the view and named in the status bar.
    pub fn missed_radii(&mut self, i: usize) -> std::sync::Arc<super::view_pipe::Missed> {
        let v = &self.views[i];
        let key = (v.generation, v.shown());
        if let Some((k, m)) = &v.missed
            && *k == key
        {
            return m.clone();
        }
        let m = std::sync::Arc::new(v.pipeline.missed_radii(v.shown()));
        self.views[i].missed = Some((key, m.clone()));
        m
    }

    /// The fillet measure of view `i`'s shown level, as table text.
    pub fn fillet_text(&mut self, i: usize, doc: &DocState) -> String {
        let edge = (self.sel_edges.len() == 1)
            .then(|| self.sel_edges.iter().next().copied())
            .flatten();
        let key = (self.views[i].generation, self.views[i].shown(), edge);
        if let Some((k, t)) = &self.views[i].fillet
            && *k == key
        {
            return t.clone();
        }
        let v = &self.views[i];
        let k = v.shown();
        let text = match v.pipeline.rounding_run(k) {
            None => "—".to_string(),
            // Edges are picked on the control mesh: measured when the rounding starts there.
            Some(run) if run.start > 0 => format!("(rounding starts at level {})", run.start),
            Some(run) => {
                let control = &doc.mesh;
                let refined = &v.pipeline.levels()[k].mesh;
                let candidates: Vec<EdgeKey> = match edge {
                    Some(e) => vec![e],
                    None => super::pick::mesh_edges(control),
                };
                let attrs = &v.pipeline.levels()[0].edge_attrs;
                // Each try slices the refined mesh: a few edges, not all of a big model.
                let found = candidates.iter().take(16).find_map(|e| {
                    let r = run.radius(attrs, *e)?;
                    measure_fillet(control, e.0, e.1, refined, r)
                        .ok()
                        .map(|m| (*e, r, m))
                });
                match found {
                    Some((e, r, m)) => format!(
                        "{:.4} (r {:.4}, {:+.2} %, edge {}-{})",
                        m.fitted_radius,
                        r,
                        100.0 * m.max_radial_error,
                        e.0,
                        e.1,
                    ),
                    None => "no fillet yet".to_string(),
                }
            }
        };
        self.views[i].fillet = Some((key, text.clone()));
        text
    }

    pub(super) fn compare_table(&mut self, ui: &mut egui::Ui, doc: &DocState) {
        let rows: Vec<[String; 8]> = (0..self.views.len())
            .map(|i| {
                let fillet = self.fillet_text(i, doc);
                let v = &self.views[i];
                let k = v.shown();
                let lv = &v.pipeline.levels()[k];
                let flipped = lv.report.as_ref().map_or(0, |r| r.flipped.len());
                // Pairs of faces through each other (checked on a thread; "…" meanwhile).
                let crossing = match v.crossings() {
                    Crossings::Done(p) => p.len().to_string(),
                    Crossings::Ask { .. } => "not checked".to_string(),
                    Crossings::Waiting | Crossings::Checking => "…".to_string(),
                };
                let times: Vec<String> = v.pipeline.levels()[1..]
                    .iter()
                    .map(|l| {
                        let ms = l.report.as_ref().map_or(0.0, |r| r.millis);
                        if ms >= 10.0 {
                            format!("{ms:.0}")
                        } else {
                            format!("{ms:.1}")
                        }
                    })
                    .collect();
                [
                    format!("{}", i + 1),
                    short_pipeline(v.steps()),
                    lv.mesh.num_vertices().to_string(),
                    lv.mesh.num_faces().to_string(),
                    flipped.to_string(),
                    crossing,
                    fillet,
                    times.join(" / "),
                ]
            })
            .collect();
        egui::ScrollArea::both().show(ui, |ui| {
            egui::Grid::new("compare-table")
                .striped(true)
                .num_columns(8)
                .show(ui, |ui| {
                    for h in [
                        "view",
                        "pipeline",
                        "vertices",
                        "faces",
                        "flipped",
                        "crossing",
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
                            } else if c == 1 {
                                // A long pipeline wraps, so the table fits 1280 px.
                                ui.scope(|ui| {
                                    ui.set_max_width(250.0);
                                    ui.add(egui::Label::new(cell).wrap());
                                });
                            } else if (c == 4 || c == 5) && cell.parse().is_ok_and(|n: usize| n > 0)
                            {
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
