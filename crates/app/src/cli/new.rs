//! `prism new box|prism|pyramid|tripod|extrude -o OUT [--size W,D,H] [--sides N]
//! [--radius R] [--height H] [--arm L] [--width W] [--outline FILE.json] [--hole S]`: a new
//! solid without a file, as File ▸ New solid… makes it in the app
//! ([`prism_geom::solid::Solid`]); `extrude` takes a polyline file as `prism curve` reads it
//! (closed, concave allowed) and an optional hole, the outline scaled by S about its
//! centroid.

use super::CliError;
use clap::{Args, ValueEnum};
use glam::DVec3;
use prism_geom::io::{self, Document};
use prism_geom::solid::{SolidKind as Kind, SolidParams};
use std::path::PathBuf;

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum SolidKind {
    Box,
    Prism,
    Pyramid,
    Tripod,
    Extrude,
}

#[derive(Debug, Args)]
pub struct NewArgs {
    pub kind: SolidKind,
    /// Output: .obj or .prism.json.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Box: width, depth, height.
    #[arg(long, default_value = "3,2,1")]
    pub size: String,
    /// Prism, pyramid: sides of the regular base polygon (3 to 512).
    #[arg(long, default_value_t = 6)]
    pub sides: u32,
    /// Prism, pyramid: circumradius of the base.
    #[arg(long, default_value_t = 1.5)]
    pub radius: f64,
    /// Prism, pyramid, extrude: height.
    #[arg(long, default_value_t = 2.0)]
    pub height: f64,
    /// Tripod: arm length.
    #[arg(long, default_value_t = 3.0)]
    pub arm: f64,
    /// Tripod: arm width.
    #[arg(long, default_value_t = 1.0)]
    pub width: f64,
    /// Extrude: the outline, {"closed": true, "points": [[x, y], ...]}.
    #[arg(long)]
    pub outline: Option<PathBuf>,
    /// Extrude: cut a hole, the outline scaled by S (0 < S < 1) about its centroid.
    #[arg(long)]
    pub hole: Option<f64>,
}

pub fn run(a: NewArgs) -> Result<(), CliError> {
    super::check_output(&a.output, None)?;
    let size = super::comma_numbers("--size", &a.size, "W,D,H")?;
    let [w, d, h] = size[..] else {
        return Err(CliError::usage(format!("--size '{}' is not W,D,H", a.size)));
    };
    let params = SolidParams {
        size: DVec3::new(w, d, h),
        sides: a.sides,
        radius: a.radius,
        height: a.height,
        arm: a.arm,
        width: a.width,
    };
    let kind = match a.kind {
        SolidKind::Box => Kind::Box,
        SolidKind::Prism => Kind::Prism,
        SolidKind::Pyramid => Kind::Pyramid,
        SolidKind::Tripod => Kind::Tripod,
        SolidKind::Extrude => Kind::Extrusion,
    };
    let solid = params.solid(kind, || {
        let path = a
            .outline
            .as_ref()
            .ok_or_else(|| CliError::usage("extrude needs --outline FILE.json"))?;
        let poly = super::curve::read_polyline(path)?;
        if !poly.closed {
            return Err(CliError::input(format!(
                "{}: the outline is open (\"closed\": false); a solid needs a closed one",
                path.display()
            )));
        }
        Ok((poly.points, a.hole))
    })?;
    let mesh = solid.build().map_err(CliError::input)?;
    let doc = Document {
        mesh,
        edge_attrs: Default::default(),
        tags: Default::default(),
        ..Document::default()
    };
    let c = prism_geom::analysis::counts(&doc.mesh);
    io::save(&a.output, &doc).map_err(CliError::input)?;
    println!(
        "{} vertices, {} edges, {} faces, volume {:.6}; wrote {}",
        c.vertices,
        c.edges,
        c.faces,
        prism_geom::geometry::signed_volume(&doc.mesh),
        a.output.display()
    );
    Ok(())
}
