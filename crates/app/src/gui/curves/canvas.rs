//! Painting the Curves tab: the canvas (control polygon, the refined curves, the curvature
//! comb and evolute of the chosen scheme, the control points) and the curvature plot.

use super::{CurvesTab, Refined, SCHEME_COLORS, bounds, polyline, scheme_label};
use egui::{Color32, Pos2, Stroke, Vec2};
use glam::DVec2;
use prism_geom::curve::{CurveScheme, CurveSketch};

impl CurvesTab {
    pub(super) fn paint_canvas(
        &self,
        ui: &egui::Ui,
        rect: egui::Rect,
        sketch: &CurveSketch,
        results: &[(CurveScheme, Result<Refined, String>)],
    ) {
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, Color32::from_gray(22));
        let pts = self.screen(rect, &sketch.control.points);
        painter.add(polyline(
            pts.clone(),
            sketch.control.closed,
            Stroke::new(1.0, Color32::from_gray(110)),
        ));
        for (k, (s, r)) in results.iter().enumerate() {
            let Ok(r) = r else { continue };
            let main = *s == sketch.scheme;
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
            let c = if Some(i) == self.dragging.map(|d| d.0) {
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

    /// The tips of the comb's teeth (sketch coordinates): along the outward normal, at
    /// `scale·|k|` relative to the curve's size. Empty below three points.
    pub(super) fn comb_tips(&self, r: &Refined) -> Vec<DVec2> {
        let p = &r.curve.points;
        let n = p.len();
        if n < 3 {
            return Vec::new();
        }
        let size = {
            let (lo, hi) = bounds(p);
            (hi - lo).length()
        };
        (0..n)
            .map(|i| {
                let (a, b) = if r.curve.closed {
                    (p[(i + n - 1) % n], p[(i + 1) % n])
                } else {
                    (p[i.saturating_sub(1)], p[(i + 1).min(n - 1)])
                };
                let t = (b - a).normalize_or_zero();
                let left = DVec2::new(-t.y, t.x);
                p[i] - self.comb_scale * size * r.curvature[i] * left
            })
            .collect()
    }

    /// The comb: a tooth from each curve point to its tip, and the line through the tips.
    fn paint_comb(&self, painter: &egui::Painter, rect: egui::Rect, r: &Refined, color: Color32) {
        let tips: Vec<Pos2> = self
            .comb_tips(r)
            .iter()
            .zip(&r.curve.points)
            .map(|(tip, p)| {
                let (s0, s1) = (self.to_screen(rect, *p), self.to_screen(rect, *tip));
                painter.line_segment([s0, s1], Stroke::new(1.0, color));
                s1
            })
            .collect();
        painter.add(polyline(tips, r.curve.closed, Stroke::new(1.0, color)));
    }

    pub(super) fn plot(
        &self,
        ui: &mut egui::Ui,
        height: f32,
        chosen: CurveScheme,
        results: &[(CurveScheme, Result<Refined, String>)],
    ) {
        // Headroom above the highest curvature: the legend (top right, one line a scheme)
        // sits there instead of over the curve's end.
        let (lo, hi) = results
            .iter()
            .filter_map(|(_, r)| r.as_ref().ok())
            .flat_map(|r| r.curvature.iter().copied())
            .filter(|c| c.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| {
                (lo.min(c), hi.max(c))
            });
        let mut plot = egui_plot::Plot::new("curvature-plot");
        if lo <= hi {
            let rows = results.len() as f64;
            plot = plot
                .include_y(lo.min(0.0))
                .include_y(hi + (hi - lo.min(0.0)).max(1e-9) * 0.15 * rows);
        }
        plot.height(height)
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
                    let width = if *s == chosen { 2.0 } else { 1.2 };
                    p.line(
                        egui_plot::Line::new(scheme_label(*s), pts)
                            .color(SCHEME_COLORS[k])
                            .width(width),
                    );
                }
            });
    }
}
