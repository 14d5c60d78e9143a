//! `prism envelope-study [--max 6] [--scenes 20] [--spread 4] [--seed 4] [--resolution 8]
//! [--plot OUT.png]`: seed 004's figs. 11 and 12 (`envelope::study`): equal axis-aligned cubes
//! at random centres, 2 to MAX of them; a table by count (the cubes kept, regions per kept
//! face, the median time of each stage) and, with `--plot`, every scene as a point: the time of
//! each stage against the regions (fig. 11) and the regions against the faces (fig. 12, with
//! the paper's 1.6 regions a face).

use super::CliError;
use super::plot_style::{FONT, Plot, axes, draw_error, legend, picture};
use clap::Args;
use plotters::prelude::*;
use prism_geom::freeform::envelope::study::{StudyScene, cube_study};
use std::path::PathBuf;

#[derive(Debug, Args)]
pub struct EnvelopeStudyArgs {
    /// Largest number of cubes (from 2).
    #[arg(long, default_value_t = 6)]
    pub max: usize,
    /// Scenes of each count.
    #[arg(long, default_value_t = 20)]
    pub scenes: usize,
    /// Side of the box the centres lie in (the cubes' half-size is 1).
    #[arg(long, default_value_t = 4.0)]
    pub spread: f64,
    /// Seed of the random centres (the same seed gives the same scenes).
    #[arg(long, default_value_t = 4)]
    pub seed: u64,
    /// Mesh resolution of the meshing stage (1 to 256).
    #[arg(long, default_value_t = 8)]
    pub resolution: usize,
    /// The scenes as points: time against regions (fig. 11) beside regions against faces
    /// (fig. 12).
    #[arg(long)]
    pub plot: Option<PathBuf>,
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(0.0)
}

pub fn run(a: EnvelopeStudyArgs) -> Result<(), CliError> {
    if !(2..=64).contains(&a.max) || !(1..=1000).contains(&a.scenes) {
        return Err(CliError::usage(format!(
            "--max {} --scenes {}: from 2 to 64 cubes, 1 to 1000 scenes of each",
            a.max, a.scenes
        )));
    }
    if !(a.spread.is_finite() && a.spread > 0.0 && (1..=256).contains(&a.resolution)) {
        return Err(CliError::usage(format!(
            "--spread {} --resolution {}: a spread > 0 and a resolution from 1 to 256",
            a.spread, a.resolution
        )));
    }
    if let Some(p) = &a.plot {
        super::check_output(p, None)?;
    }
    let scenes = cube_study(a.max, a.scenes, a.spread, a.seed, a.resolution)
        .map_err(|e| CliError::input(e.to_string()))?;
    println!(
        "cubes  scenes  kept  regions/face (mean, max)  network ms  mesh ms (K = {})  triangles",
        a.resolution
    );
    for count in 2..=a.max {
        let of: Vec<&StudyScene> = scenes.iter().filter(|s| s.cubes == count).collect();
        let n = of.len() as f64;
        let ratio: Vec<f64> = of
            .iter()
            .map(|s| s.regions as f64 / s.faces.max(1) as f64)
            .collect();
        println!(
            "{count:5}  {:6}  {:4.2}  {:6.3}, {:5.3}             {:10.3}  {:15.3}  {:9.0}",
            of.len(),
            of.iter().map(|s| s.kept as f64).sum::<f64>() / n,
            ratio.iter().sum::<f64>() / n,
            ratio.iter().copied().fold(0.0, f64::max),
            median(of.iter().map(|s| s.build_ms).collect()),
            median(of.iter().map(|s| s.mesh_ms).collect()),
            of.iter().map(|s| s.triangles as f64).sum::<f64>() / n,
        );
    }
    if let Some(p) = &a.plot {
        plot(&scenes, p)?;
        println!("wrote {}", p.display());
    }
    Ok(())
}

/// A stage's colour, name and time.
type Stage = (RGBColor, &'static str, fn(&StudyScene) -> f64);

/// A plot of `caption` on `area` over `x` × `y`, its axes named.
fn chart_on<'a, 'b>(
    area: &'a DrawingArea<BitMapBackend<'b>, plotters::coord::Shift>,
    caption: &str,
    (x, y): (std::ops::Range<f64>, std::ops::Range<f64>),
    (x_name, y_name): (&str, &str),
) -> Result<Plot<'a, 'b>, CliError> {
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FONT, 20))
        .margin(16)
        .x_label_area_size(40)
        .y_label_area_size(56)
        .build_cartesian_2d(x, y)
        .map_err(draw_error)?;
    axes(&mut chart, x_name, y_name)?;
    Ok(chart)
}

/// Fig. 11 (the stages' times against the regions) beside fig. 12 (the regions against the
/// faces, with the paper's 1.6 a face).
fn plot(scenes: &[StudyScene], path: &std::path::Path) -> Result<(), CliError> {
    let (w, h) = (1200u32, 520u32);
    picture((w, h), path, |root| {
        let (left, right) = root.split_horizontally(w / 2);
        let top = |f: fn(&StudyScene) -> f64| scenes.iter().map(f).fold(0.0, f64::max) * 1.08;
        let regions = top(|s| s.regions as f64).max(1.0);
        let ms = top(|s| s.build_ms.max(s.mesh_ms)).max(1e-3);
        let faces = top(|s| s.faces as f64).max(1.0);
        let network = RGBColor(40, 90, 200);
        let mesh = RGBColor(220, 110, 30);
        let mut chart = chart_on(
            &left,
            "seed 004 fig. 11: time per stage",
            (0.0..regions, 0.0..ms),
            ("regions (faces of the network)", "milliseconds"),
        )?;
        let stages: [Stage; 2] = [
            (network, "network, charts and lifts", |s| s.build_ms),
            (mesh, "mesh", |s| s.mesh_ms),
        ];
        for (color, name, f) in stages {
            chart
                .draw_series(
                    scenes
                        .iter()
                        .map(|s| Circle::new((s.regions as f64, f(s)), 3, color.filled())),
                )
                .map_err(draw_error)?
                .label(name)
                .legend(move |(x, y)| Circle::new((x + 8, y), 4, color.filled()));
        }
        legend(&mut chart)?;
        let mut chart = chart_on(
            &right,
            "seed 004 fig. 12: regions against faces",
            (0.0..faces, 0.0..regions.max(1.6 * faces)),
            ("faces of the cubes kept", "regions"),
        )?;
        chart
            .draw_series(
                scenes
                    .iter()
                    .map(|s| Circle::new((s.faces as f64, s.regions as f64), 3, network.filled())),
            )
            .map_err(draw_error)?
            .label("a scene")
            .legend(move |(x, y)| Circle::new((x + 8, y), 4, network.filled()));
        chart
            .draw_series(LineSeries::new([(0.0, 0.0), (faces, 1.6 * faces)], BLACK))
            .map_err(draw_error)?
            .label("the paper: 1.6 regions a face")
            .legend(|(x, y)| PathElement::new([(x, y), (x + 16, y)], BLACK));
        legend(&mut chart)?;
        Ok(())
    })
}
