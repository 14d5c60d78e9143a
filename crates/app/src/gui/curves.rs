//! The Curves tab (seed 002): control points on a 2D canvas — click to place, click near a
//! control segment to insert, drag to move, right-click to delete —, the refined curve of
//! the chosen scheme with its curvature comb and evolute, the other two schemes' curves
//! faintly for comparison, and curvature against arc length for all three (egui_plot).
//! Presets: square, regular hexagon, samples of a logarithmic spiral, and the paper's
//! fig. 6 polyline (θ₁, θ₂, l₁, l₂, l₃ = 1).

use egui::{Color32, Pos2, Stroke, Vec2};
use glam::DVec2;
use prism_geom::curve::{CurveScheme, Polyline, presets};

const SCHEME_COLORS: [Color32; 3] = [
    Color32::from_rgb(120, 170, 255),
    Color32::from_rgb(255, 170, 80),
    Color32::from_rgb(120, 220, 120),
];

fn scheme_label(s: CurveScheme) -> &'static str {
    match s {
        CurveScheme::CatmullClark => "Catmull–Clark (cubic B-spline)",
        CurveScheme::Circle => "method 1: keeps circles",
        CurveScheme::LogSpiral => "method 2: keeps log spirals",
    }
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
    pub control: Polyline,
    pub scheme: CurveScheme,
    pub levels: usize,
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
    dragging: Option<usize>,
    pub error: Option<String>,
}

impl Default for CurvesTab {
    fn default() -> Self {
        let mut t = CurvesTab {
            control: Polyline::default(),
            scheme: CurveScheme::Circle,
            levels: 4,
            comb: true,
            comb_scale: 0.3,
            evolute: false,
            others: true,
            fig6: [60.0, 30.0, 1.0, 1.0],
            center: DVec2::ZERO,
            zoom: 100.0,
            fit_next: true,
            dragging: None,
            error: None,
        };
        t.preset(Preset::Fig6);
        t
    }
}

/// The refined curve of one scheme with its curvature and arc length.
pub struct Refined {
    pub curve: Polyline,
    pub curvature: Vec<f64>,
    pub arc: Vec<f64>,
}

impl CurvesTab {
    pub fn preset(&mut self, p: Preset) {
        self.control = match p {
            Preset::Square => presets::regular_polygon(4, 1.0),
            Preset::Hexagon => presets::regular_polygon(6, 1.0),
            Preset::LogSpiral => presets::log_spiral(8, 0.15, std::f64::consts::FRAC_PI_3),
            Preset::Fig6 => {
                let [t1, t2, l1, l2] = self.fig6;
                presets::fig6(t1.to_radians(), t2.to_radians(), l1, l2)
            }
        };
        self.fit_next = true;
    }

    /// The curve of `scheme` after the chosen number of levels.
    pub fn refined(&self, scheme: CurveScheme) -> Result<Refined, String> {
        let curve = self
            .control
            .refine_levels(scheme, self.levels)
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

    fn fit(&mut self, rect: egui::Rect) {
        let pts = &self.control.points;
        if pts.is_empty() {
            return;
        }
        let (lo, hi) = bounds(pts);
        self.center = 0.5 * (lo + hi);
        let size = (hi - lo).max(DVec2::splat(1e-6));
        self.zoom = 0.8 * (rect.width() as f64 / size.x).min(rect.height() as f64 / size.y);
    }

    pub fn ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            egui::ComboBox::from_label("scheme")
                .selected_text(scheme_label(self.scheme))
                .show_ui(ui, |ui| {
                    for s in CurveScheme::ALL {
                        ui.selectable_value(&mut self.scheme, s, scheme_label(s));
                    }
                });
            ui.add(egui::Slider::new(&mut self.levels, 0..=8).text("levels"));
            ui.checkbox(&mut self.control.closed, "closed");
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
        });
        ui.horizontal_wrapped(|ui| {
            ui.label("Presets:");
            if ui.button("square").clicked() {
                self.preset(Preset::Square);
            }
            if ui.button("hexagon").clicked() {
                self.preset(Preset::Hexagon);
            }
            if ui.button("log spiral").clicked() {
                self.preset(Preset::LogSpiral);
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
                self.preset(Preset::Fig6);
            }
        });
        ui.label("Click to add a point, click near a segment to insert one, drag to move, right-click to delete.");
        let results: Vec<(CurveScheme, Result<Refined, String>)> = CurveScheme::ALL
            .into_iter()
            .map(|s| (s, self.refined(s)))
            .collect();
        self.error = results
            .iter()
            .find(|(s, _)| *s == self.scheme)
            .and_then(|(_, r)| r.as_ref().err().cloned());
        let plot_h = (ui.available_height() * 0.32).max(120.0);
        let canvas_h = (ui.available_height() - plot_h - 8.0).max(100.0);
        let (rect, resp) = ui.allocate_exact_size(
            Vec2::new(ui.available_width(), canvas_h),
            egui::Sense::click_and_drag(),
        );
        if self.fit_next {
            self.fit(rect);
            self.fit_next = false;
        }
        self.canvas_input(rect, &resp, ui);
        self.paint_canvas(ui, rect, &results);
        self.plot(ui, plot_h, &results);
    }

    fn nearest_point(&self, rect: egui::Rect, at: Pos2, radius: f32) -> Option<usize> {
        self.control
            .points
            .iter()
            .enumerate()
            .map(|(i, p)| (i, self.to_screen(rect, *p).distance(at)))
            .filter(|(_, d)| *d <= radius)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(i, _)| i)
    }

    /// Where a click inserts: after point i of the segment near `at`, or at the end.
    fn insert_index(&self, rect: egui::Rect, at: Pos2) -> usize {
        let pts = &self.control.points;
        let n = pts.len();
        let segs = if self.control.closed {
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

    fn canvas_input(&mut self, rect: egui::Rect, resp: &egui::Response, ui: &egui::Ui) {
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
            self.dragging = self.nearest_point(rect, press, 10.0);
        }
        if resp.dragged_by(egui::PointerButton::Primary) {
            match self.dragging {
                Some(i) => self.control.points[i] = self.to_world(rect, pos),
                None => {
                    let d = resp.drag_delta();
                    self.center -= DVec2::new(d.x as f64, -d.y as f64) / self.zoom;
                }
            }
        }
        if resp.drag_stopped() {
            self.dragging = None;
        }
        if resp.clicked() && self.nearest_point(rect, pos, 10.0).is_none() {
            let i = self.insert_index(rect, pos);
            self.control.points.insert(i, self.to_world(rect, pos));
        }
        if resp.secondary_clicked()
            && let Some(i) = self.nearest_point(rect, pos, 10.0)
        {
            self.control.points.remove(i);
        }
    }

    fn paint_canvas(
        &self,
        ui: &egui::Ui,
        rect: egui::Rect,
        results: &[(CurveScheme, Result<Refined, String>)],
    ) {
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, Color32::from_gray(22));
        let pts = self.screen(rect, &self.control.points);
        painter.add(polyline(
            pts.clone(),
            self.control.closed,
            Stroke::new(1.0, Color32::from_gray(110)),
        ));
        for (k, (s, r)) in results.iter().enumerate() {
            let Ok(r) = r else { continue };
            let main = *s == self.scheme;
            if !main && !self.others {
                continue;
            }
            let sp = self.screen(rect, &r.curve.points);
            let c = SCHEME_COLORS[k];
            if main {
                if self.comb {
                    self.paint_comb(&painter, rect, r, c.gamma_multiply(0.6));
                }
                if self.evolute {
                    for e in r.curve.evolute().into_iter().flatten() {
                        let q = self.to_screen(rect, e);
                        if rect.contains(q) {
                            painter.circle_filled(q, 1.5, Color32::from_rgb(255, 120, 90));
                        }
                    }
                }
                painter.add(polyline(sp, r.curve.closed, Stroke::new(2.0, c)));
            } else {
                painter.add(polyline(
                    sp,
                    r.curve.closed,
                    Stroke::new(1.0, c.gamma_multiply(0.5)),
                ));
            }
        }
        for (i, p) in pts.iter().enumerate() {
            let c = if Some(i) == self.dragging {
                Color32::YELLOW
            } else {
                Color32::WHITE
            };
            painter.circle_stroke(*p, 5.0, Stroke::new(1.5, c));
        }
        if let Some(e) = &self.error {
            painter.text(
                rect.left_top() + Vec2::new(8.0, 8.0),
                egui::Align2::LEFT_TOP,
                e,
                egui::FontId::proportional(14.0),
                Color32::from_rgb(240, 110, 90),
            );
        }
    }

    /// Teeth along the outward normal, of length `scale·|k|` relative to the control size.
    fn paint_comb(&self, painter: &egui::Painter, rect: egui::Rect, r: &Refined, color: Color32) {
        let p = &r.curve.points;
        let n = p.len();
        if n < 3 {
            return;
        }
        let size = {
            let (lo, hi) = bounds(p);
            (hi - lo).length()
        };
        let mut tips = Vec::with_capacity(n);
        for i in 0..n {
            let (a, b) = if r.curve.closed {
                (p[(i + n - 1) % n], p[(i + 1) % n])
            } else {
                (p[i.saturating_sub(1)], p[(i + 1).min(n - 1)])
            };
            let t = (b - a).normalize_or_zero();
            let left = DVec2::new(-t.y, t.x);
            let tip = p[i] - self.comb_scale * size * r.curvature[i] * left;
            let (s0, s1) = (self.to_screen(rect, p[i]), self.to_screen(rect, tip));
            painter.line_segment([s0, s1], Stroke::new(1.0, color));
            tips.push(s1);
        }
        painter.add(polyline(tips, r.curve.closed, Stroke::new(1.0, color)));
    }

    fn plot(
        &self,
        ui: &mut egui::Ui,
        height: f32,
        results: &[(CurveScheme, Result<Refined, String>)],
    ) {
        egui_plot::Plot::new("curvature-plot")
            .height(height)
            .legend(egui_plot::Legend::default())
            .x_axis_label("arc length")
            .y_axis_label("curvature")
            .show(ui, |p| {
                for (k, (s, r)) in results.iter().enumerate() {
                    let Ok(r) = r else { continue };
                    let pts: Vec<[f64; 2]> = r
                        .arc
                        .iter()
                        .zip(&r.curvature)
                        .enumerate()
                        .filter(|(i, _)| r.curve.closed || (*i > 0 && *i + 1 < r.arc.len()))
                        .map(|(_, (a, c))| [*a, *c])
                        .collect();
                    let width = if *s == self.scheme { 2.0 } else { 1.2 };
                    p.line(
                        egui_plot::Line::new(scheme_label(*s), pts)
                            .color(SCHEME_COLORS[k])
                            .width(width),
                    );
                }
            });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_refine_with_every_scheme() {
        let mut t = CurvesTab::default();
        for p in [
            Preset::Square,
            Preset::Hexagon,
            Preset::LogSpiral,
            Preset::Fig6,
        ] {
            t.preset(p);
            for s in CurveScheme::ALL {
                let r = t.refined(s).unwrap();
                assert_eq!(r.curvature.len(), r.curve.points.len());
                assert!(r.arc.windows(2).all(|w| w[1] >= w[0]));
            }
        }
    }

    #[test]
    fn the_hexagon_under_method_1_has_constant_curvature() {
        let mut t = CurvesTab::default();
        t.preset(Preset::Hexagon);
        let r = t.refined(CurveScheme::Circle).unwrap();
        let k0 = r.curvature[0];
        assert!(r.curvature.iter().all(|k| (k - k0).abs() < 1e-9 * k0.abs()));
    }

    #[test]
    fn clicks_insert_near_a_segment_and_append_elsewhere() {
        let mut t = CurvesTab::default();
        t.preset(Preset::Square);
        let rect = egui::Rect::from_min_size(Pos2::ZERO, Vec2::new(400.0, 400.0));
        t.fit(rect);
        // Midpoint of the segment from point 0 to point 1.
        let mid = 0.5 * (t.control.points[0] + t.control.points[1]);
        assert_eq!(t.insert_index(rect, t.to_screen(rect, mid)), 1);
        assert_eq!(t.insert_index(rect, rect.center()), 4);
        let back = t.to_world(rect, t.to_screen(rect, mid));
        assert!((back - mid).length() < 1e-5);
    }

    #[test]
    fn too_few_points_is_an_error_not_a_panic() {
        let mut t = CurvesTab::default();
        t.control.points.truncate(2);
        assert!(t.refined(CurveScheme::Circle).is_err());
    }
}
