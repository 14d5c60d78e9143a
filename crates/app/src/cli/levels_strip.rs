//! `prism render … --levels-strip`: every level of the pipeline, level 0 (the input) included,
//! seen through one camera (framed on the input, or as the camera flags ask), as tiles of
//! `--size` side by side in `OUT.png` — at most [`COLUMNS`] a row, each labelled with its level
//! and step — and each level alone in `OUT-L0.png`, `OUT-L1.png`, … (seed 000 figs. 2, 6–7,
//! 12–15; seed 001 figs. 3–6; seed 002 figs. 1–2 are such sequences).

use super::CliError;
use super::plot_style::{FONT, register_font};
use plotters::prelude::*;
use prism_geom::{Level, Scheme};
use prism_viewport::{Camera, Offscreen, Scene};
use std::path::{Path, PathBuf};

/// Tiles a row at most.
pub const COLUMNS: usize = 4;

/// `OUT-L3.png` for level 3 of a strip written to `OUT.png`.
pub fn level_path(out: &Path, k: usize) -> PathBuf {
    suffixed(out, &format!("L{k}"), "level")
}

/// `OUT-SUFFIX.png` beside `OUT.png` (`stem`, `.png` where it has none): the frames of a strip
/// or a turntable.
pub fn suffixed(out: &Path, suffix: &str, stem: &str) -> PathBuf {
    let own = out.file_stem().map(|s| s.to_string_lossy().into_owned());
    let ext = out.extension().map(|e| e.to_string_lossy().into_owned());
    out.with_file_name(format!(
        "{}-{suffix}.{}",
        own.unwrap_or_else(|| stem.into()),
        ext.unwrap_or_else(|| "png".into())
    ))
}

/// The tiles' layout for `n` levels: (columns, rows).
pub fn layout(n: usize) -> (usize, usize) {
    let cols = n.clamp(1, COLUMNS);
    (cols, n.div_ceil(cols))
}

/// Renders `levels` (scenes made by `scene_of`) through `camera`, which is in the coordinates of
/// level 0's scene `first`, at `w` × `h` a tile, and writes the strip and the frames.
pub fn render(
    out: &Path,
    (w, h): (u32, u32),
    levels: &[Level],
    steps: &[Scheme],
    first: &Scene,
    camera: &Camera,
    scene_of: impl Fn(&Level) -> Scene,
) -> Result<(), CliError> {
    let (cols, rows) = layout(levels.len());
    let (sw, sh) = (cols as u32 * w, rows as u32 * h);
    let gpu = Offscreen::new().map_err(CliError::input)?;
    let mut strip = image::RgbImage::new(sw, sh);
    for (k, level) in levels.iter().enumerate() {
        let scene = scene_of(level);
        // One camera for every level: each scene is relative to its own origin.
        let mut cam = *camera;
        cam.target += (first.origin - scene.origin).as_vec3();
        let uploaded = gpu.upload(&scene).map_err(CliError::input)?;
        let img = gpu
            .render_uploaded(&uploaded, &cam, w, h)
            .map_err(CliError::input)?;
        let (x, y) = ((k % cols) as u32 * w, (k / cols) as u32 * h);
        for (px, py, p) in img.enumerate_pixels() {
            strip.put_pixel(x + px, y + py, image::Rgb([p[0], p[1], p[2]]));
        }
        super::write_png(img.into(), &level_path(out, k))?;
    }
    label(&mut strip, (w, h), cols, steps)?;
    super::write_png(strip.into(), out)
}

/// Writes each tile's level and the step that made it in its upper left corner.
fn label(
    strip: &mut image::RgbImage,
    (w, h): (u32, u32),
    cols: usize,
    steps: &[Scheme],
) -> Result<(), CliError> {
    register_font();
    let (sw, sh) = strip.dimensions();
    let draw_error =
        |e: &dyn std::fmt::Display| CliError::input(format!("labelling the strip: {e}"));
    let root = BitMapBackend::with_buffer(strip.as_mut(), (sw, sh)).into_drawing_area();
    let style = (FONT, 18).into_font().color(&WHITE);
    for k in 0..=steps.len() {
        let text = match k {
            0 => "level 0: the input".to_string(),
            _ => format!("level {k}: {}", steps[k - 1]),
        };
        let (x, y) = ((k % cols) as u32 * w + 10, (k / cols) as u32 * h + 8);
        root.draw(&Text::new(text, (x as i32, y as i32), style.clone()))
            .map_err(|e| draw_error(&e))?;
    }
    root.present().map_err(|e| draw_error(&e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tiles_run_four_a_row_and_each_level_has_its_file() {
        assert_eq!(layout(1), (1, 1));
        assert_eq!(layout(3), (3, 1));
        assert_eq!(layout(4), (4, 1));
        assert_eq!(layout(5), (4, 2));
        assert_eq!(layout(9), (4, 3));
        assert_eq!(
            level_path(Path::new("out/fig.png"), 2),
            Path::new("out/fig-L2.png")
        );
    }
}
