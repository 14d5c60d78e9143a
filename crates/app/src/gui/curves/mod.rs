//! The Curves tab (seed 002): control points on a 2D canvas — click to place, click near a
//! control segment to insert, drag to move, right-click to delete —, the refined curve of
//! the chosen scheme with its curvature comb and evolute, the other two schemes' curves
//! faintly for comparison, and curvature against arc length for all three (egui_plot).
//! Presets: square, regular hexagon, samples of a logarithmic spiral, and the paper's
//! fig. 6 polyline (θ₁, θ₂, l₁, l₂, l₃ = 1).
//!
//! The sketch (control points, closed, scheme, levels) is part of the document: undoable
//! with the rest and saved in `.prism.json`. The tab keeps only how it looks at it (pan,
//! zoom, comb, evolute) and returns every change of the sketch as a [`CurveEdit`].

mod canvas;

use crate::gui::command::{Command, CurveEdit};
use egui::{Color32, Pos2, Stroke, Vec2};
use glam::DVec2;
use prism_geom::curve::{CurveScheme, CurveSketch, Polyline, presets};

const SCHEME_COLORS: [Color32; 3] = [
    Color32::from_rgb(120, 170, 255),
    Color32::from_rgb(255, 170, 80),
    Color32::from_rgb(120, 220, 120),
];

/// The scheme as the menu and the legend show it: the name `prism curve --scheme` takes, then
/// what it is (one name across the app and the command line).
fn scheme_label(s: CurveScheme) -> String {
    let what = match s {
        CurveScheme::CatmullClark => "cubic B-spline",
        CurveScheme::Circle => "method 1, keeps circles",
        CurveScheme::LogSpiral => "method 2, keeps log spirals",
    };
    format!("{}: {what}", s.name())
}

/// The smallest box around some points.
fn bounds(p: &[DVec2]) -> (DVec2, DVec2) {
    let lo = p.iter().copied().reduce(DVec2::min).unwrap_or_default();
    let hi = p.iter().copied().reduce(DVec2::max).unwrap_or_default();
    (lo, hi)
}

/// An open or closed line through screen points (nothing for fewer than two).
fn polyline(p: Vec<Pos2>, closed: bool, stroke: Stroke) -> egui::Shape {
    match (p.len() < 2, closed) {
        (true, _) => egui::Shape::Noop,
        (false, true) => egui::Shape::closed_line(p, stroke),
        (false, false) => egui::Shape::line(p, stroke),
    }
}

/// Which preset the preset row builds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Preset {
    Square,
    Hexagon,
    LogSpiral,
    Fig6,
}

pub struct CurvesTab {
    pub comb: bool,
    pub comb_scale: f64,
    pub evolute: bool,
    pub others: bool,
    /// Fig. 6 parameters (degrees for the angles).
    pub fig6: [f64; 4],
    /// World point at the canvas centre and pixels per unit.
    center: DVec2,
    zoom: f64,
    fit_next: bool,
    /// The point being dragged and the drag's number (its moves are one undo step).
    dragging: Option<(usize, u64)>,
    drags: u64,
    pub error: Option<String>,
    /// Edits decided this frame.
    out: Vec<Command>,
}

impl Default for CurvesTab {
    fn default() -> Self {
        CurvesTab {
            comb: true,
            comb_scale: 0.3,
            evolute: false,
            others: true,
            fig6: [60.0, 30.0, 1.0, 1.0],
            center: DVec2::ZERO,
            zoom: 100.0,
            fit_next: true,
            dragging: None,
            drags: 0,
            error: None,
            out: Vec::new(),
        }
    }
}

/// The refined curve of one scheme with its curvature and arc length.
pub struct Refined {
    pub curve: Polyline,
    pub curvature: Vec<f64>,
    pub arc: Vec<f64>,
}

impl CurvesTab {
    /// The control polyline of a preset (fig. 6 with the tab's θ₁, θ₂, l₁, l₂).
    pub fn preset(&self, p: Preset) -> Polyline {
        match p {
            Preset::Square => presets::regular_polygon(4, 1.0),
            Preset::Hexagon => presets::regular_polygon(6, 1.0),
            Preset::LogSpiral => presets::log_spiral(8, 0.15, std::f64::consts::FRAC_PI_3),
            Preset::Fig6 => {
                let [t1, t2, l1, l2] = self.fig6;
                presets::fig6(t1.to_radians(), t2.to_radians(), l1, l2)
            }
        }
    }

    /// Replaces the sketch's polyline by a preset and fits the canvas to it.
    fn use_preset(&mut self, p: Preset) {
        self.out.push(CurveEdit::SetControl(self.preset(p)).into());
        self.fit_next = true;
    }

    /// The curve of `scheme` after the sketch's number of levels.
    pub fn refined(sketch: &CurveSketch, scheme: CurveScheme) -> Result<Refined, String> {
        let curve = sketch
            .control
            .refine_levels(scheme, sketch.levels)
            .map_err(|e| e.to_string())?;
        Ok(Refined {
            curvature: curve.curvature(),
            arc: curve.arc_length(),
            curve,
        })
    }

    fn to_screen(&self, rect: egui::Rect, p: DVec2) -> Pos2 {
        let d = (p - self.center) * self.zoom;
        rect.center() + Vec2::new(d.x as f32, -d.y as f32)
    }

    fn screen(&self, rect: egui::Rect, p: &[DVec2]) -> Vec<Pos2> {
        p.iter().map(|q| self.to_screen(rect, *q)).collect()
    }

    fn to_world(&self, rect: egui::Rect, s: Pos2) -> DVec2 {
        let d = s - rect.center();
        self.center + DVec2::new(d.x as f64, -d.y as f64) / self.zoom
    }

    fn fit(&mut self, rect: egui::Rect, pts: &[DVec2]) {
        if pts.is_empty() {
            return;
        }
        let (lo, hi) = bounds(pts);
        self.center = 0.5 * (lo + hi);
        let size = (hi - lo).max(DVec2::splat(1e-6));
        self.zoom = 0.8 * (rect.width() as f64 / size.x).min(rect.height() as f64 / size.y);
    }

    /// The tab over the document's sketch; returns the edits the user made.
    pub fn ui(&mut self, ui: &mut egui::Ui, sketch: &CurveSketch) -> Vec<Command> {
        ui.horizontal_wrapped(|ui| {
            let mut scheme = sketch.scheme;
            ui.label("Scheme");
            // A fixed width: choosing another scheme does not move the controls after it.
            egui::ComboBox::from_id_salt("curve_scheme")
                .width(250.0)
                .selected_text(scheme_label(scheme))
                .show_ui(ui, |ui| {
                    for s in CurveScheme::ALL {
                        ui.selectable_value(&mut scheme, s, scheme_label(s));
                    }
                });
            if scheme != sketch.scheme {
                self.out.push(CurveEdit::SetScheme(scheme).into());
            }
            let mut levels = sketch.levels;
            ui.add(
                egui::Slider::new(&mut levels, 0..=prism_geom::curve::MAX_SKETCH_LEVELS)
                    .text("levels"),
            );
            if levels != sketch.levels {
                self.out.push(CurveEdit::SetLevels(levels).into());
            }
            let mut closed = sketch.control.closed;
            ui.checkbox(&mut closed, "closed");
            if closed != sketch.control.closed {
                self.out.push(CurveEdit::SetClosed(closed).into());
            }
            ui.checkbox(&mut self.comb, "curvature comb");
            ui.add(
                egui::DragValue::new(&mut self.comb_scale)
                    .speed(0.01)
                    .range(0.0..=100.0)
                    .prefix("scale "),
            );
            ui.checkbox(&mut self.evolute, "evolute");
            ui.checkbox(&mut self.others, "other schemes");
            if ui.button("Fit").clicked() {
                self.fit_next = true;
            }
            if ui
                .button("Extrude into a solid…")
                .on_hover_text("a new model: this closed polygon (or its refined curve) extruded, with an optional hole")
                .clicked()
            {
                self.out.push(Command::ShowNewSolid { extrude: true });
            }
        });
        ui.horizontal_wrapped(|ui| {
            ui.label("Presets:");
            if ui.button("square").clicked() {
                self.use_preset(Preset::Square);
            }
            if ui.button("hexagon").clicked() {
                self.use_preset(Preset::Hexagon);
            }
            if ui.button("log spiral").clicked() {
                self.use_preset(Preset::LogSpiral);
            }
            let mut changed = false;
            for (k, name) in ["θ₁°", "θ₂°", "l₁", "l₂"].iter().enumerate() {
                changed |= ui
                    .add(
                        egui::DragValue::new(&mut self.fig6[k])
                            .speed(if k < 2 { 1.0 } else { 0.02 })
                            .range(if k < 2 { -179.0..=179.0 } else { 0.01..=100.0 })
                            .prefix(format!("{name} ")),
                    )
                    .changed();
            }
            if ui.button("fig. 6").clicked() || changed {
                self.use_preset(Preset::Fig6);
            }
        });
        ui.label("Click to add a point, click near a segment to insert one, drag to move, right-click to delete.");
        let results: Vec<(CurveScheme, Result<Refined, String>)> = CurveScheme::ALL
            .into_iter()
            .map(|s| (s, CurvesTab::refined(sketch, s)))
            .collect();
        self.error = results
            .iter()
            .find(|(s, _)| *s == sketch.scheme)
            .and_then(|(_, r)| r.as_ref().err().cloned());
        let plot_h = (ui.available_height() * 0.32).max(120.0);
        let canvas_h = (ui.available_height() - plot_h - 8.0).max(100.0);
        let (rect, resp) = ui.allocate_exact_size(
            Vec2::new(ui.available_width(), canvas_h),
            egui::Sense::click_and_drag(),
        );
        if self.fit_next {
            // The control points, the chosen curve and, when shown, its comb all in view.
            let mut pts = sketch.control.points.clone();
            if let Some((_, Ok(r))) = results.iter().find(|(s, _)| *s == sketch.scheme) {
                pts.extend_from_slice(&r.curve.points);
                if self.comb {
                    pts.extend(self.comb_tips(r));
                }
            }
            self.fit(rect, &pts);
            self.fit_next = false;
        }
        self.canvas_input(rect, &resp, ui, &sketch.control);
        self.paint_canvas(ui, rect, sketch, &results);
        self.plot(ui, plot_h, sketch.scheme, &results);
        std::mem::take(&mut self.out)
    }

    fn nearest_point(
        &self,
        rect: egui::Rect,
        control: &Polyline,
        at: Pos2,
        radius: f32,
    ) -> Option<usize> {
        control
            .points
            .iter()
            .enumerate()
            .map(|(i, p)| (i, self.to_screen(rect, *p).distance(at)))
            .filter(|(_, d)| *d <= radius)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(i, _)| i)
    }

    /// Where a click inserts: after point i of the segment near `at`, or at the end.
    fn insert_index(&self, rect: egui::Rect, control: &Polyline, at: Pos2) -> usize {
        let pts = &control.points;
        let n = pts.len();
        let segs = if control.closed {
            n
        } else {
            n.saturating_sub(1)
        };
        (0..segs)
            .map(|i| {
                let a = self.to_screen(rect, pts[i]);
                let b = self.to_screen(rect, pts[(i + 1) % n]);
                let ab = b - a;
                let t = ((at - a).dot(ab) / ab.length_sq().max(1e-9)).clamp(0.0, 1.0);
                (i, (a + t * ab).distance(at))
            })
            .filter(|(_, d)| *d <= 8.0)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map_or(n, |(i, _)| i + 1)
    }

    fn canvas_input(
        &mut self,
        rect: egui::Rect,
        resp: &egui::Response,
        ui: &egui::Ui,
        control: &Polyline,
    ) {
        if resp.hovered() {
            let scroll = ui.input(|i| i.smooth_scroll_delta.y);
            if scroll != 0.0 {
                self.zoom *= (scroll as f64 * 0.002).exp();
            }
        }
        let Some(pos) = resp.interact_pointer_pos() else {
            return;
        };
        if resp.drag_started_by(egui::PointerButton::Primary) {
            let press = ui.input(|i| i.pointer.press_origin()).unwrap_or(pos);
            self.drags += 1;
            self.dragging = self
                .nearest_point(rect, control, press, 10.0)
                .map(|i| (i, self.drags));
        }
        if resp.dragged_by(egui::PointerButton::Primary) {
            match self.dragging {
                Some((index, drag)) => {
                    let to = self.to_world(rect, pos);
                    self.out.push(CurveEdit::Move { index, to, drag }.into());
                }
                None => {
                    let d = resp.drag_delta();
                    self.center -= DVec2::new(d.x as f64, -d.y as f64) / self.zoom;
                }
            }
        }
        if resp.drag_stopped() {
            self.dragging = None;
        }
        if resp.clicked() && self.nearest_point(rect, control, pos, 10.0).is_none() {
            let index = self.insert_index(rect, control, pos);
            let at = self.to_world(rect, pos);
            self.out.push(CurveEdit::Insert { index, at }.into());
        }
        if resp.secondary_clicked()
            && let Some(index) = self.nearest_point(rect, control, pos, 10.0)
        {
            self.out.push(CurveEdit::Delete { index }.into());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Fit brings the whole comb into the canvas (it framed the control points only, and the
    /// teeth of fig. 6's sharp turn ran off the canvas).
    #[test]
    fn fit_keeps_the_comb_inside_the_canvas() {
        let mut tab = CurvesTab::default();
        let sketch = CurveSketch::default();
        let r = CurvesTab::refined(&sketch, sketch.scheme).unwrap();
        let rect = egui::Rect::from_min_size(egui::pos2(0.0, 100.0), egui::vec2(1264.0, 460.0));
        let mut pts = sketch.control.points.clone();
        pts.extend_from_slice(&r.curve.points);
        pts.extend(tab.comb_tips(&r));
        tab.fit(rect, &pts);
        for tip in tab.comb_tips(&r) {
            let s = tab.to_screen(rect, tip);
            assert!(rect.contains(s), "{tip} at {s:?} outside {rect:?}");
        }
    }

    fn sketch(control: Polyline) -> CurveSketch {
        CurveSketch {
            control,
            ..CurveSketch::default()
        }
    }

    #[test]
    fn presets_refine_with_every_scheme() {
        let t = CurvesTab::default();
        for p in [
            Preset::Square,
            Preset::Hexagon,
            Preset::LogSpiral,
            Preset::Fig6,
        ] {
            let k = sketch(t.preset(p));
            for s in CurveScheme::ALL {
                let r = CurvesTab::refined(&k, s).unwrap();
                assert_eq!(r.curvature.len(), r.curve.points.len());
                assert!(r.arc.windows(2).all(|w| w[1] >= w[0]));
            }
        }
    }

    #[test]
    fn the_hexagon_under_method_1_has_constant_curvature() {
        let t = CurvesTab::default();
        let r =
            CurvesTab::refined(&sketch(t.preset(Preset::Hexagon)), CurveScheme::Circle).unwrap();
        let k0 = r.curvature[0];
        assert!(r.curvature.iter().all(|k| (k - k0).abs() < 1e-9 * k0.abs()));
    }

    #[test]
    fn clicks_insert_near_a_segment_and_append_elsewhere() {
        let mut t = CurvesTab::default();
        let square = t.preset(Preset::Square);
        let rect = egui::Rect::from_min_size(Pos2::ZERO, Vec2::new(400.0, 400.0));
        t.fit(rect, &square.points);
        // Midpoint of the segment from point 0 to point 1.
        let mid = 0.5 * (square.points[0] + square.points[1]);
        assert_eq!(t.insert_index(rect, &square, t.to_screen(rect, mid)), 1);
        assert_eq!(t.insert_index(rect, &square, rect.center()), 4);
        let back = t.to_world(rect, t.to_screen(rect, mid));
        assert!((back - mid).length() < 1e-5);
    }

    #[test]
    fn too_few_points_is_an_error_not_a_panic() {
        let mut k = CurveSketch::default();
        k.control.points.truncate(2);
        assert!(CurvesTab::refined(&k, CurveScheme::Circle).is_err());
    }
}
