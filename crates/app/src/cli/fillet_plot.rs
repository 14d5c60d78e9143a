//! `prism subdivide … --measure-edge A-B --plot OUT.png`: seed 000 fig. 8 as a picture — the
//! section of one rounded edge through its midpoint at every level of the rounding run, against
//! the target circle of radius r about the ideal axis (`analysis::FilletMeasure::section`),
//! one scale on both axes. Repeated cuts give polygons circumscribing the arc, their corners
//! `r/cos(ψ/2^(k+1))` from the axis after k steps, so the levels close in on the circle.

use super::CliError;
use super::plot_style::{FONT, axes, draw_error, legend, picture};
use glam::DVec2;
use plotters::prelude::*;
use std::path::Path;

/// One colour a level, the first levels warm and the last cool.
const LEVELS: [RGBColor; 8] = [
    RGBColor(215, 48, 39),
    RGBColor(244, 109, 67),
    RGBColor(230, 171, 2),
    RGBColor(102, 166, 30),
    RGBColor(27, 158, 119),
    RGBColor(49, 130, 189),
    RGBColor(84, 39, 143),
    RGBColor(0, 0, 0),
];

/// The sections `levels` (level, points about the ideal axis) of edge `edge` against the circle
/// of radius `r`, written to `path`.
pub fn fillet_plot(
    levels: &[(usize, Vec<DVec2>)],
    r: f64,
    edge: (u32, u32),
    path: &Path,
) -> Result<(), CliError> {
    // The box of every section (the arc's point on the bisector where there is none), square.
    let (lo, hi) = levels
        .iter()
        .flat_map(|(_, s)| s.iter())
        .fold((DVec2::new(r, 0.0), DVec2::new(r, 0.0)), |(lo, hi), p| {
            (lo.min(*p), hi.max(*p))
        });
    let c = 0.5 * (lo + hi);
    let half = (0.5 * (hi - lo).max_element()).max(0.05 * r) * 1.15;
    picture((760, 800), path, |root| {
        let mut chart = ChartBuilder::on(root)
            .caption(
                format!(
                    "seed 000 fig. 8: the section of edge {}-{} at each level against r = {r}",
                    edge.0, edge.1
                ),
                (FONT, 18),
            )
            .margin(16)
            .x_label_area_size(40)
            .y_label_area_size(56)
            .build_cartesian_2d((c.x - half)..(c.x + half), (c.y - half)..(c.y + half))
            .map_err(draw_error)?;
        axes(&mut chart, "along the faces' bisector", "across it")?;
        // The circle's pieces inside the box (plotters would draw the rest along its border).
        let inside = |(x, y): (f64, f64)| (x - c.x).abs() <= half && (y - c.y).abs() <= half;
        let circle: Vec<(f64, f64)> = (0..=720)
            .map(|i| {
                let t = std::f64::consts::TAU * f64::from(i) / 720.0;
                (r * t.cos(), r * t.sin())
            })
            .collect();
        chart
            .draw_series(
                circle
                    .windows(2)
                    .filter(|w| inside(w[0]) && inside(w[1]))
                    .map(|w| PathElement::new([w[0], w[1]], BLACK.mix(0.5))),
            )
            .map_err(draw_error)?
            .label(format!("target circle, r = {r}"))
            .legend(|(x, y)| PathElement::new([(x, y), (x + 18, y)], BLACK.mix(0.5)));
        for (i, (k, s)) in levels.iter().enumerate() {
            let color = LEVELS[i % LEVELS.len()];
            chart
                .draw_series(LineSeries::new(
                    s.iter().map(|p| (p.x, p.y)),
                    color.stroke_width(2),
                ))
                .map_err(draw_error)?
                .label(format!("level {k}"))
                .legend(move |(x, y)| {
                    PathElement::new([(x, y), (x + 18, y)], color.stroke_width(2))
                });
            chart
                .draw_series(s.iter().map(|p| Circle::new((p.x, p.y), 2, color.filled())))
                .map_err(draw_error)?;
        }
        legend(&mut chart)
    })
}
