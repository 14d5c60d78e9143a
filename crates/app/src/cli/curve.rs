//! `prism curve IN.json -o OUT.json --scheme catmull-clark|circle|log-spiral --levels N`.
//!
//! IN is `{"closed": bool, "points": [[x, y], ...]}`; OUT is the refined polyline in the
//! same form plus `"curvature": [k, ...]`, one signed value per point (0 at the ends of an
//! open polyline), so OUT can be read back as IN.

use super::CliError;
use clap::Args;
use prism_geom::curve::{CurveScheme, Polyline};
use prism_geom::io::write_atomically;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

#[derive(Debug, Args)]
pub struct CurveArgs {
    /// Input polyline (.json).
    pub input: PathBuf,
    /// Output polyline (.json).
    #[arg(short, long)]
    pub output: PathBuf,
    /// catmull-clark, circle (method 1) or log-spiral (method 2).
    #[arg(long)]
    pub scheme: String,
    /// Levels of refinement.
    #[arg(long, default_value_t = 4)]
    pub levels: usize,
}

#[derive(Deserialize)]
struct CurveIn {
    closed: bool,
    points: Vec<[f64; 2]>,
}

#[derive(Serialize)]
struct CurveOut {
    closed: bool,
    points: Vec<[f64; 2]>,
    curvature: Vec<f64>,
}

/// A polyline file `{"closed": bool, "points": [[x, y], ...]}`, or the error naming the
/// line and column.
pub fn read_polyline(path: &Path) -> Result<Polyline, CliError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::input(format!("cannot read {}: {e}", path.display())))?;
    let c: CurveIn = serde_json::from_str(&text).map_err(|e| {
        CliError::input(format!(
            "{}, line {}, column {}: {e} (expected {{\"closed\": bool, \"points\": [[x, y], ...]}})",
            path.display(),
            e.line(),
            e.column()
        ))
    })?;
    Ok(Polyline::new(
        c.points.iter().map(|&p| p.into()).collect(),
        c.closed,
    ))
}

pub fn run(a: CurveArgs) -> Result<(), CliError> {
    let scheme = CurveScheme::from_name(&a.scheme).ok_or_else(|| {
        CliError::usage(format!(
            "unknown curve scheme '{}' (known: catmull-clark, circle, log-spiral)",
            a.scheme
        ))
    })?;
    let poly = read_polyline(&a.input)?;
    let out = poly
        .refine_levels(scheme, a.levels)
        .map_err(|e| CliError::input(format!("{}: {e}", a.input.display())))?;
    let doc = CurveOut {
        closed: out.closed,
        curvature: out.curvature(),
        points: out.points.iter().map(|p| p.to_array()).collect(),
    };
    let json = serde_json::to_string(&doc).expect("numbers serialise");
    write_atomically(&a.output, json.as_bytes()).map_err(CliError::input)?;
    println!(
        "{} points after {} level(s) of {}; wrote {}",
        doc.points.len(),
        a.levels,
        scheme.name(),
        a.output.display()
    );
    Ok(())
}
