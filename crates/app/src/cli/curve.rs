//! `prism curve [IN.json | --preset fig6:θ1,θ2,l1,l2] -o OUT.json --scheme
//! catmull-clark|circle|log-spiral --levels N [--plot OUT.png]` and `prism curve --sweep -o
//! TABLE.csv [--plot OUT.png] [--angles …] [--lengths …]`.
//!
//! IN is `{"closed": bool, "points": [[x, y], ...]}`; OUT is the refined polyline in the
//! same form plus, per point, `"curvature"` (signed, 0 at the ends of an open polyline),
//! `"arc_length"` (cumulative) and `"evolute"` (the centre of curvature, `null` where there
//! is none), so OUT can be read back as IN. `--preset fig6:…` is seed 002's fig. 6 polyline
//! (angles in degrees, l₃ = 1). `--plot` draws the curve with its comb beside its curvature
//! against arc length. `--sweep` runs the paper's §4 study over every combination of the
//! angles (θ₁, θ₂) and lengths (l₁, l₂) given, writes one CSV row per combination and draws
//! the dimensional-stacking picture ([`prism_geom::curve_study`]).

use super::CliError;
use super::curve_plot::{curve_plot, study_plot};
use clap::Args;
use prism_geom::curve::{CurveScheme, Polyline, presets};
use prism_geom::curve_study::{SCHEMES, StudyRow, fig6_study};
use prism_geom::io::write_atomically;
use serde::Serialize;
use std::path::{Path, PathBuf};

#[derive(Debug, Args)]
pub struct CurveArgs {
    /// Input polyline (.json); not with --preset or --sweep.
    pub input: Option<PathBuf>,
    /// Output: the refined polyline (.json), or the study's table (.csv) with --sweep.
    #[arg(short, long)]
    pub output: PathBuf,
    /// catmull-clark, circle (method 1) or log-spiral (method 2).
    #[arg(long, required_unless_present = "sweep")]
    pub scheme: Option<String>,
    /// Levels of refinement.
    #[arg(long, default_value_t = 4)]
    pub levels: usize,
    /// Seed 002's fig. 6 polyline instead of a file: fig6:θ1,θ2,l1,l2 (degrees; l3 = 1).
    #[arg(long, conflicts_with = "input")]
    pub preset: Option<String>,
    /// Also draw a picture: the curve with its curvature comb, and its curvature against arc
    /// length (with --sweep: the study's dimensional stacking).
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// With --plot: draw the evolute too (the centres of curvature).
    #[arg(long, requires = "plot", conflicts_with = "sweep")]
    pub evolute: bool,
    /// Run seed 002's §4 study on fig. 6's polyline: every θ1, θ2 of --angles and l1, l2 of
    /// --lengths, refined by the three schemes.
    #[arg(long, conflicts_with_all = ["input", "preset", "scheme"])]
    pub sweep: bool,
    /// With --sweep: also draw seed 002 fig. 7, the curves of every θ1 (rows) and θ2 (columns)
    /// of --angles as small multiples (l1 = l2 = 1).
    #[arg(long, requires = "sweep")]
    pub family: Option<PathBuf>,
    /// The study's angles θ1 and θ2, degrees.
    #[arg(long, default_value = "15,30,45,60,75,90")]
    pub angles: String,
    /// The study's lengths l1 and l2 (l3 = 1).
    #[arg(long, default_value = "0.25,0.5,1,2,4")]
    pub lengths: String,
}

#[derive(Serialize)]
struct CurveOut {
    closed: bool,
    points: Vec<[f64; 2]>,
    curvature: Vec<f64>,
    arc_length: Vec<f64>,
    evolute: Vec<Option<[f64; 2]>>,
}

/// Comma-separated finite numbers, named by the flag that gave them.
fn numbers(flag: &str, s: &str) -> Result<Vec<f64>, CliError> {
    let v = super::comma_numbers(flag, s, "a list of numbers")?;
    if v.is_empty() || v.iter().any(|x| !x.is_finite()) {
        return Err(CliError::usage(format!(
            "{flag} '{s}' is not a list of finite numbers"
        )));
    }
    Ok(v)
}

/// `fig6:θ1,θ2,l1,l2` (degrees).
fn preset(s: &str) -> Result<Polyline, CliError> {
    let bad = || {
        CliError::usage(format!(
            "--preset '{s}' is not fig6:θ1,θ2,l1,l2 (degrees; l3 = 1)"
        ))
    };
    let rest = s.strip_prefix("fig6:").ok_or_else(bad)?;
    let v = numbers("--preset", rest)?;
    let [t1, t2, l1, l2] = v[..] else {
        return Err(bad());
    };
    if l1 <= 0.0 || l2 <= 0.0 {
        return Err(CliError::usage(format!(
            "--preset '{s}': l1 and l2 must be > 0"
        )));
    }
    Ok(presets::fig6(t1.to_radians(), t2.to_radians(), l1, l2))
}

/// A polyline file `{"closed": bool, "points": [[x, y], ...]}`, or the error naming the
/// line and column.
pub fn read_polyline(path: &Path) -> Result<Polyline, CliError> {
    let text = super::read_text(path)?;
    prism_geom::io::polyline_from_str(path, &text).map_err(|e| CliError::input(e.to_string()))
}

pub fn run(a: CurveArgs) -> Result<(), CliError> {
    super::check_output(&a.output, None)?;
    if a.sweep {
        return sweep(&a);
    }
    let name = a.scheme.as_deref().unwrap_or_default();
    let scheme = CurveScheme::from_name(name).ok_or_else(|| {
        CliError::usage(format!(
            "unknown curve scheme '{name}' (known: catmull-clark, circle, log-spiral)"
        ))
    })?;
    let (poly, source) = match (&a.input, &a.preset) {
        (Some(path), None) => (read_polyline(path)?, path.display().to_string()),
        (None, Some(p)) => (preset(p)?, p.clone()),
        _ => {
            return Err(CliError::usage(
                "give an input polyline (.json) or --preset fig6:θ1,θ2,l1,l2",
            ));
        }
    };
    let out = poly
        .refine_levels(scheme, a.levels)
        .map_err(|e| CliError::input(format!("{source}: {e}")))?;
    let doc = CurveOut {
        closed: out.closed,
        curvature: out.curvature(),
        arc_length: out.arc_length(),
        evolute: out
            .evolute()
            .iter()
            .map(|e| e.map(|p| p.to_array()))
            .collect(),
        points: out.points.iter().map(|p| p.to_array()).collect(),
    };
    let json = serde_json::to_string(&doc).expect("numbers serialise");
    write_atomically(&a.output, json.as_bytes()).map_err(CliError::input)?;
    println!(
        "{} points after {} level(s) of {}, arc length {:.6}; wrote {}",
        doc.points.len(),
        a.levels,
        scheme.name(),
        doc.arc_length.last().copied().unwrap_or(0.0),
        a.output.display()
    );
    if let Some(plot) = &a.plot {
        let title = format!("{} × {} levels: {source}", scheme.name(), a.levels);
        curve_plot(&poly, &out, &title, a.evolute, plot)?;
        println!("plotted {}", plot.display());
    }
    Ok(())
}

/// Seed 002 §4: the study's table and picture.
fn sweep(a: &CurveArgs) -> Result<(), CliError> {
    let angles = numbers("--angles", &a.angles)?;
    let lengths = numbers("--lengths", &a.lengths)?;
    if lengths.iter().any(|&l| l <= 0.0) {
        return Err(CliError::usage(format!(
            "--lengths '{}' must be > 0",
            a.lengths
        )));
    }
    let rows =
        fig6_study(&angles, &angles, &lengths, &lengths, a.levels).map_err(CliError::input)?;
    let mut csv = String::from("theta1,theta2,l1,l2");
    for s in SCHEMES {
        csv += &format!(",{0}_defect,{0}_extrema", s.name());
    }
    csv += ",log_spiral_vs_circle\n";
    let (mut better, mut worse) = (0, 0);
    for r in &rows {
        csv += &format!("{},{},{},{}", r.theta1, r.theta2, r.l1, r.l2);
        for m in &r.result {
            csv += &format!(",{:.6e},{}", m.defect, m.extrema);
        }
        let verdict = match r.log_spiral_better() {
            Some(true) => {
                better += 1;
                "better"
            }
            Some(false) => {
                worse += 1;
                "worse"
            }
            None => "tie",
        };
        csv += &format!(",{verdict}\n");
    }
    write_atomically(&a.output, csv.as_bytes()).map_err(CliError::input)?;
    // Where the improvements gather (the paper: the lower right of each cell, l1 > l2).
    let share = |f: &dyn Fn(&StudyRow) -> bool| {
        let cells: Vec<&StudyRow> = rows.iter().filter(|r| f(r)).collect();
        let b = cells
            .iter()
            .filter(|r| r.log_spiral_better() == Some(true))
            .count();
        (b, cells.len())
    };
    let (down_b, down_n) = share(&|r| r.l1 > r.l2);
    let (up_b, up_n) = share(&|r| r.l1 < r.l2);
    println!(
        "{} configurations × {} levels: method 2 (log-spiral) more monotone than method 1 (circle) in {better}, less in {worse}, tied in {}; where l1 > l2 better in {down_b} of {down_n}, where l1 < l2 in {up_b} of {up_n}; wrote {}",
        rows.len(),
        a.levels,
        rows.len() - better - worse,
        a.output.display()
    );
    if let Some(plot) = &a.plot {
        study_plot(&rows, (&angles, &angles, &lengths, &lengths), plot)?;
        println!("plotted {}", plot.display());
    }
    if let Some(family) = &a.family {
        super::curve_plot::family_plot(&angles, 1.0, a.levels, family)?;
        println!("plotted {}", family.display());
    }
    Ok(())
}
