//! The pictures of `prism curve`, drawn with `plotters` into a buffer and written as PNG:
//! a refined curve (its control polygon, the curve, its curvature comb) beside its curvature
//! against arc length; the §4 study as dimensional stacking (θ₁, θ₂ outer, l₁, l₂ inner); and
//! fig. 7, the study's curves as small multiples.
//! Text and axes as [`super::plot_style`] draws them.

use super::CliError;
use super::plot_style::{FONT, axes, draw_error, legend, picture};
use plotters::prelude::*;
use prism_geom::curve::Polyline;
use prism_geom::curve_study::StudyRow;
use std::path::Path;

/// Pixels along the top of the curve's plot kept free for its legend (three rows).
const LEGEND_BAND: f64 = 80.0;

/// The x and y ranges of a plot `pw` × `ph` pixels with one scale on both axes, holding the box
/// `lo`–`hi` (and 4 % round it) centred below the top [`LEGEND_BAND`] pixels.
fn equal_scales(
    pw: f64,
    ph: f64,
    lo: glam::DVec2,
    hi: glam::DVec2,
) -> (std::ops::Range<f64>, std::ops::Range<f64>) {
    let below_legend = (ph - LEGEND_BAND).max(0.5 * ph);
    let c = 0.5 * (lo + hi);
    let half = 0.5 * (hi - lo).max_element().max(1e-9) * 1.08;
    let px = pw.min(below_legend) / (2.0 * half);
    let y0 = c.y - below_legend / (2.0 * px);
    (
        (c.x - pw / (2.0 * px))..(c.x + pw / (2.0 * px)),
        y0..(y0 + ph / px),
    )
}

/// The range of `v` with a margin, never empty.
fn padded(lo: f64, hi: f64) -> std::ops::Range<f64> {
    let span = (hi - lo).abs().max(1e-9);
    (lo - 0.05 * span)..(hi + 0.05 * span)
}

/// Curve, control polygon and comb (left); curvature against arc length (right).
/// With `evolute`, the centres of curvature too (green; runs broken where the curve is straight
/// or a centre lies more than three extents away, the box kept on the curve).
pub fn curve_plot(
    control: &Polyline,
    refined: &Polyline,
    title: &str,
    evolute: bool,
    path: &Path,
) -> Result<(), CliError> {
    let (w, h) = (1200u32, 520u32);
    picture((w, h), path, |root| {
        let (left, right) = root.split_horizontally(w / 2);
        let k = refined.curvature();
        let s = refined.arc_length();
        let pts = &refined.points;
        // The comb: 0.25 of the curve's extent at the largest |κ|, inwards for κ > 0.
        let (mut lo, mut hi) = (pts[0], pts[0]);
        for p in pts.iter().chain(&control.points) {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
        let extent = (hi - lo).max_element().max(1e-9);
        let kmax = k.iter().fold(0.0f64, |m, x| m.max(x.abs())).max(1e-12);
        let scale = 0.25 * extent / kmax;
        let n = pts.len();
        let normal = |i: usize| {
            let a = if i > 0 || refined.closed {
                pts[(i + n - 1) % n]
            } else {
                pts[i]
            };
            let b = if i + 1 < n || refined.closed {
                pts[(i + 1) % n]
            } else {
                pts[i]
            };
            (b - a).perp().normalize_or_zero()
        };
        let teeth: Vec<(f64, f64)> = (0..n)
            .map(|i| {
                let t = pts[i] - scale * k[i] * normal(i);
                (t.x, t.y)
            })
            .collect();
        let (mut clo, mut chi) = (lo, hi);
        for t in &teeth {
            clo = clo.min((*t).into());
            chi = chi.max((*t).into());
        }
        // Equal scales on both axes in pixels, the curve and its comb in a square box below
        // a band kept free for the legend.
        let area = left.titled(title, (FONT, 20)).map_err(draw_error)?;
        let (margin, x_labels, y_labels) = (12, 28, 40);
        let (aw, ah) = area.dim_in_pixel();
        let pw = f64::from(aw.saturating_sub(2 * margin + y_labels).max(1));
        let ph = f64::from(ah.saturating_sub(2 * margin + x_labels).max(1));
        let (xs, ys) = equal_scales(pw, ph, clo, chi);
        let mut chart = ChartBuilder::on(&area)
            .margin(margin)
            .x_label_area_size(x_labels)
            .y_label_area_size(y_labels)
            .build_cartesian_2d(xs, ys)
            .map_err(draw_error)?;
        chart
            .configure_mesh()
            .label_style((FONT, 13))
            .disable_mesh()
            .draw()
            .map_err(draw_error)?;
        let closed = |p: &Polyline| {
            let mut v: Vec<(f64, f64)> = p.points.iter().map(|q| (q.x, q.y)).collect();
            if p.closed && !v.is_empty() {
                v.push(v[0]);
            }
            v
        };
        let comb = RGBColor(230, 120, 60);
        for (i, t) in teeth.iter().enumerate() {
            chart
                .draw_series(LineSeries::new([(pts[i].x, pts[i].y), *t], comb.mix(0.6)))
                .map_err(draw_error)?;
        }
        let mut tips = teeth.clone();
        if refined.closed && !tips.is_empty() {
            tips.push(tips[0]);
        }
        chart
            .draw_series(LineSeries::new(tips, comb))
            .map_err(draw_error)?
            .label("curvature comb")
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 18, y)], comb));
        if evolute {
            let green = RGBColor(40, 160, 70);
            let middle = 0.5 * (lo + hi);
            let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
            for c in refined.evolute() {
                match c.filter(|c| c.distance(middle) <= 3.0 * extent) {
                    Some(c) => runs.last_mut().expect("one run").push((c.x, c.y)),
                    None if runs.last().is_some_and(|r| !r.is_empty()) => runs.push(Vec::new()),
                    None => {}
                }
            }
            for (k, run) in runs.into_iter().filter(|r| r.len() > 1).enumerate() {
                let drawn = chart
                    .draw_series(LineSeries::new(run, green))
                    .map_err(draw_error)?;
                if k == 0 {
                    drawn
                        .label("evolute (centres of curvature)")
                        .legend(move |(x, y)| PathElement::new([(x, y), (x + 18, y)], green));
                }
            }
        }
        chart
            .draw_series(LineSeries::new(closed(control), RGBColor(150, 150, 150)))
            .map_err(draw_error)?
            .label("control polygon")
            .legend(|(x, y)| PathElement::new([(x, y), (x + 18, y)], RGBColor(150, 150, 150)));
        chart
            .draw_series(LineSeries::new(
                closed(refined),
                ShapeStyle::from(&RGBColor(30, 90, 180)).stroke_width(2),
            ))
            .map_err(draw_error)?
            .label("refined curve")
            .legend(|(x, y)| PathElement::new([(x, y), (x + 18, y)], RGBColor(30, 90, 180)));
        legend(&mut chart)?;

        // Curvature against arc length (the ends of an open polyline have none).
        let range = if refined.closed {
            0..n
        } else {
            1..n.saturating_sub(1)
        };
        let series: Vec<(f64, f64)> = range.map(|i| (s[i], k[i])).collect();
        let (klo, khi) = series
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p.1), b.max(p.1))
            });
        let (klo, khi) = if klo.is_finite() {
            (klo, khi)
        } else {
            (0.0, 1.0)
        };
        let mut chart = ChartBuilder::on(&right)
            .caption("curvature against arc length", (FONT, 20))
            .margin(12)
            .x_label_area_size(36)
            .y_label_area_size(56)
            .build_cartesian_2d(
                padded(0.0, *s.last().unwrap_or(&1.0)),
                padded(klo.min(0.0), khi),
            )
            .map_err(draw_error)?;
        axes(&mut chart, "arc length s", "κ")?;
        chart
            .draw_series(LineSeries::new(
                series.clone(),
                ShapeStyle::from(&RGBColor(30, 90, 180)).stroke_width(2),
            ))
            .map_err(draw_error)?;
        chart
            .draw_series(
                series
                    .iter()
                    .map(|&p| Circle::new(p, 2, RGBColor(30, 90, 180).filled())),
            )
            .map_err(draw_error)?;
        Ok(())
    })
}

/// The colours of the study's cells: method 2 better, method 1 better, a tie.
pub const BETTER: RGBColor = RGBColor(60, 160, 90);
pub const WORSE: RGBColor = RGBColor(235, 140, 50);
pub const TIE: RGBColor = RGBColor(200, 200, 200);

/// Dimensional stacking of the §4 study: θ₁ across and θ₂ up in the outer grid, l₁ across
/// and l₂ up inside each cell; a cell is green where the log-spiral rule's curvature is more
/// monotone than the circle rule's, orange where less, grey where they tie.
pub fn study_plot(
    rows: &[StudyRow],
    axes: (&[f64], &[f64], &[f64], &[f64]),
    path: &Path,
) -> Result<(), CliError> {
    let (t1, t2, l1, l2) = axes;
    let (w, h) = (900u32, 860u32);
    picture((w, h), path, |root| {
        let (nx, ny) = (t1.len() * l1.len(), t2.len() * l2.len());
        let mut chart = ChartBuilder::on(root)
            .caption(
                "seed 002 §4: log-spiral (method 2) against circle (method 1)",
                (FONT, 20),
            )
            .margin(16)
            .x_label_area_size(80)
            .y_label_area_size(50)
            .build_cartesian_2d(0f64..nx as f64, 0f64..ny as f64)
            .map_err(draw_error)?;
        let (n1, n2) = (l1.len(), l2.len());
        chart
            .configure_mesh()
            .disable_mesh()
            .disable_x_axis()
            .disable_y_axis()
            .draw()
            .map_err(draw_error)?;
        let index = |v: &[f64], x: f64| v.iter().position(|&y| y == x).unwrap_or(0);
        chart
            .draw_series(rows.iter().map(|r| {
                let x = (index(t1, r.theta1) * n1 + index(l1, r.l1)) as f64;
                let y = (index(t2, r.theta2) * n2 + index(l2, r.l2)) as f64;
                let c = match r.log_spiral_better() {
                    Some(true) => BETTER,
                    Some(false) => WORSE,
                    None => TIE,
                };
                Rectangle::new([(x + 0.04, y + 0.04), (x + 0.96, y + 0.96)], c.filled())
            }))
            .map_err(draw_error)?;
        // The outer grid.
        for i in 0..=t1.len() {
            let x = (i * n1) as f64;
            chart
                .draw_series(LineSeries::new([(x, 0.0), (x, ny as f64)], BLACK))
                .map_err(draw_error)?;
        }
        for j in 0..=t2.len() {
            let y = (j * n2) as f64;
            chart
                .draw_series(LineSeries::new([(0.0, y), (nx as f64, y)], BLACK))
                .map_err(draw_error)?;
        }
        // Axis labels, placed in pixels from the chart's coordinates.
        let style = (FONT, 14).into_font().color(&BLACK);
        let label = |at: (f64, f64), dx: i32, dy: i32, text: String| -> Result<(), CliError> {
            let (x, y) = chart.backend_coord(&at);
            root.draw(&Text::new(text, (x + dx, y + dy), style.clone()))
                .map_err(draw_error)
        };
        for (i, t) in t1.iter().enumerate() {
            label(
                ((i * n1) as f64 + 0.5 * n1 as f64, 0.0),
                -14,
                8,
                format!("{t}°"),
            )?;
        }
        for (j, t) in t2.iter().enumerate() {
            label(
                (0.0, (j * n2) as f64 + 0.5 * n2 as f64),
                -44,
                -7,
                format!("{t}°"),
            )?;
        }
        let lengths = |v: &[f64]| {
            v.iter()
                .map(|x| x.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        };
        label(
            (0.0, 0.0),
            0,
            30,
            format!(
                "outer: θ₁ across, θ₂ up; inside each cell: l₁ across ({}), l₂ up ({}); l₃ = 1",
                lengths(l1),
                lengths(l2)
            ),
        )?;
        let (lx, ly) = chart.backend_coord(&(0.0, 0.0));
        for (k, (c, name)) in [
            (BETTER, "method 2 (log-spiral) more monotone"),
            (WORSE, "method 1 (circle) more monotone"),
            (TIE, "tie"),
        ]
        .into_iter()
        .enumerate()
        {
            let x = lx + 290 * k as i32;
            root.draw(&Rectangle::new(
                [(x, ly + 54), (x + 14, ly + 68)],
                c.filled(),
            ))
            .map_err(draw_error)?;
            root.draw(&Text::new(name, (x + 20, ly + 53), style.clone()))
                .map_err(draw_error)?;
        }
        Ok(())
    })
}

/// Seed 002 fig. 7 as small multiples: fig. 6's polyline for every θ₁ (rows) and θ₂ (columns)
/// of `angles` at l₁ = l₂ = `length`, each cell one scale on both axes, the polyline in grey and
/// the curves of method 1 (circle, blue) and method 2 (log spiral, orange) after `levels`.
pub fn family_plot(
    angles: &[f64],
    length: f64,
    levels: usize,
    path: &Path,
) -> Result<(), CliError> {
    use prism_geom::curve::CurveScheme;
    let n = angles.len().max(1);
    let cell = 150u32;
    let (w, h) = (cell * n as u32 + 40, cell * n as u32 + 70);
    picture((w, h), path, |root| {
        let title = format!(
            "seed 002 fig. 7: fig. 6's polyline (grey), circle (blue), log spiral (orange); {levels} levels, l1 = l2 = {length}"
        );
        root.draw(&Text::new(title, (12, 10), (FONT, 15).into_font()))
            .map_err(draw_error)?;
        let grid = root.margin(40, 0, 30, 10);
        let cells = grid.split_evenly((n, n));
        for (k, area) in cells.iter().enumerate() {
            let (t1, t2) = (angles[k / n], angles[k % n]);
            let poly =
                prism_geom::curve::presets::fig6(t1.to_radians(), t2.to_radians(), length, length);
            let curves = [CurveScheme::Circle, CurveScheme::LogSpiral]
                .map(|s| poly.refine_levels(s, levels).ok());
            let all = poly
                .points
                .iter()
                .chain(curves.iter().flatten().flat_map(|c| c.points.iter()));
            let (lo, hi) = all.fold(
                (
                    glam::DVec2::splat(f64::INFINITY),
                    glam::DVec2::splat(f64::NEG_INFINITY),
                ),
                |(lo, hi), p| (lo.min(*p), hi.max(*p)),
            );
            // One scale on both axes, the curves' box centred with 8 % round it.
            let (cw, ch) = area.dim_in_pixel();
            let (cw, ch) = (f64::from(cw), f64::from(ch) - 16.0);
            let c = 0.5 * (lo + hi);
            let half = 0.5 * (hi - lo).max_element().max(1e-9) * 1.08;
            let px = cw.min(ch) / (2.0 * half);
            let (xs, ys) = (
                (c.x - cw / (2.0 * px))..(c.x + cw / (2.0 * px)),
                (c.y - ch / (2.0 * px))..(c.y + ch / (2.0 * px)),
            );
            let mut chart = ChartBuilder::on(area)
                .caption(format!("θ1 {t1}°, θ2 {t2}°"), (FONT, 12))
                .margin(4)
                .build_cartesian_2d(xs, ys)
                .map_err(draw_error)?;
            let line = |pts: &[glam::DVec2], color: RGBColor| {
                LineSeries::new(pts.iter().map(|p| (p.x, p.y)), color.stroke_width(1))
            };
            chart
                .draw_series(line(&poly.points, RGBColor(170, 170, 170)))
                .map_err(draw_error)?;
            for (c, color) in curves
                .iter()
                .zip([RGBColor(40, 90, 200), RGBColor(235, 120, 20)])
            {
                if let Some(c) = c {
                    chart
                        .draw_series(line(&c.points, color))
                        .map_err(draw_error)?;
                }
            }
        }
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    /// One unit is as many pixels across as up, and the box lies inside, under the legend's
    /// band, for boxes wider and taller than the plot.
    #[test]
    fn a_circle_is_drawn_round_and_clear_of_the_legend() {
        let (pw, ph) = (536.0, 448.0);
        for (lo, hi) in [
            (DVec2::new(-1.0, -1.0), DVec2::new(1.0, 1.0)),
            (DVec2::new(0.0, 0.0), DVec2::new(10.0, 1.0)),
            (DVec2::new(2.0, -5.0), DVec2::new(3.0, 5.0)),
        ] {
            let (xs, ys) = equal_scales(pw, ph, lo, hi);
            let (sx, sy) = (pw / (xs.end - xs.start), ph / (ys.end - ys.start));
            assert!((sx / sy - 1.0).abs() < 1e-12, "{sx} {sy}");
            assert!(xs.start <= lo.x && hi.x <= xs.end && ys.start <= lo.y);
            assert!(hi.y <= ys.end - LEGEND_BAND / sy, "{lo} {hi}");
        }
    }
}
