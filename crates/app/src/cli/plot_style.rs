//! What the command line's pictures share (plots, labels): the font egui ships (Ubuntu Light,
//! registered with `plotters` once, so that nothing depends on the system's fonts), the error
//! of a drawing, and the axes and legends of a plot.

use super::CliError;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

/// The family name the pictures ask `plotters` for.
pub const FONT: &str = "sans-serif";

/// A plot of `f64` against `f64` drawn into a bitmap.
pub type Plot<'a, 'b> =
    ChartContext<'a, BitMapBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Registers [`FONT`] (once; later calls do nothing).
pub fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        // The bytes are a valid TrueType font (egui draws its whole UI with them).
        let _ = plotters::style::register_font(
            FONT,
            FontStyle::Normal,
            epaint_default_fonts::UBUNTU_LIGHT,
        );
    });
}

pub fn draw_error(e: impl std::fmt::Display) -> CliError {
    CliError::input(format!("drawing the plot: {e}"))
}

/// The axes of `chart`, their numbers and their names `x` and `y`.
pub fn axes(chart: &mut Plot<'_, '_>, x: &str, y: &str) -> Result<(), CliError> {
    chart
        .configure_mesh()
        .x_desc(x)
        .y_desc(y)
        .label_style((FONT, 13))
        .axis_desc_style((FONT, 15))
        .draw()
        .map_err(draw_error)
}

/// The legend of the series drawn with labels, in a box at the upper left.
pub fn legend<'a, 'b: 'a>(chart: &mut Plot<'a, 'b>) -> Result<(), CliError> {
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .label_font((FONT, 13))
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(draw_error)
}

/// A white picture of `w` × `h` pixels drawn by `draw` and written to `path` as PNG.
pub fn picture(
    (w, h): (u32, u32),
    path: &std::path::Path,
    draw: impl FnOnce(&DrawingArea<BitMapBackend<'_>, plotters::coord::Shift>) -> Result<(), CliError>,
) -> Result<(), CliError> {
    register_font();
    let mut buf = vec![0u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(draw_error)?;
        draw(&root)?;
        root.present().map_err(draw_error)?;
    }
    let img = image::RgbImage::from_raw(w, h, buf).ok_or_else(|| draw_error("buffer size"))?;
    super::write_png(img.into(), path)
}
