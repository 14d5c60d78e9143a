//! Skinning a solid through planar cross-sections (seed 003, DESIGNBASE;
//! docs/algorithms/skin.md).
//!
//! A designer places a few closed planar sections in space; the skin is a G1 surface of
//! Gregory patches through them, found without a hand-drawn trajectory:
//!
//! 1. each section is checked and prepared ([`sections`]: centre, normal along the skinning
//!    direction, the closed C2 spline through its points or C2 pieces between corners);
//! 2. the previous section is swept into the next plane by the minimal rotation between their
//!    normals, and the correspondence is chosen over all n shifts ([`network`]): by shape (the
//!    least-squares match after the best turn about the normal, the default) or by the paper's
//!    least total twist;
//!    (sections with unequal counts first get vertices inserted by polar angle, [`polar`]);
//! 3. C2 cubic chains join corresponding vertices;
//! 4. every cell gets a Gregory patch, G1 across every inner border through the
//!    numbering-independent virtual basis ([`patches`]); chains through corners are creases;
//! 5. [`Skin::tessellate`] samples K×K quads a patch into one welded mesh, with planar caps.

pub mod crossings;
pub mod network;
pub mod patches;
mod polar;
pub mod sections;
mod tessellate;

use crate::freeform::RationalBezier;
use crate::freeform::gregory::Gregory;
use crate::freeform::spline::Cubic;
pub use crossings::{Cell, SkinCrossings};
use glam::DVec3;
pub use network::Pairing;
pub use patches::Basis;
pub use sections::Section;
use thiserror::Error;

/// One section as given: its points, the indices where its curve has a corner, and whether
/// every point is one.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct SectionInput {
    pub points: Vec<DVec3>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub corners: Vec<usize>,
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub polygon: bool,
}

/// A skin as a document keeps it (the `"skin"` block of a `.prism.json`, the Skin tab):
/// the sections and how to tessellate.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SkinSpec {
    pub sections: Vec<SectionInput>,
    /// Quads along each side of a patch.
    #[serde(default = "SkinSpec::default_resolution")]
    pub resolution: usize,
    /// Close the end sections with planar caps.
    #[serde(default = "SkinSpec::default_caps")]
    pub caps: bool,
    /// The G1 construction of inner borders (the numbering-independent virtual basis, or the
    /// paper's one-sided basis).
    #[serde(default, skip_serializing_if = "is_virtual")]
    pub basis: Basis,
    /// How neighbouring sections' vertices are paired (by shape, or the paper's least twist).
    #[serde(default, skip_serializing_if = "is_shape")]
    pub pairing: Pairing,
}

fn is_virtual(b: &Basis) -> bool {
    *b == Basis::Virtual
}

fn is_shape(p: &Pairing) -> bool {
    *p == Pairing::Shape
}

/// How a skin is built besides its sections.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct SkinOptions {
    pub basis: Basis,
    pub pairing: Pairing,
}

impl SkinSpec {
    fn default_resolution() -> usize {
        8
    }
    fn default_caps() -> bool {
        true
    }

    /// Sections with the default resolution and caps.
    pub fn new(sections: Vec<SectionInput>) -> SkinSpec {
        SkinSpec {
            sections,
            resolution: 8,
            caps: true,
            basis: Basis::Virtual,
            pairing: Pairing::Shape,
        }
    }

    /// The skin through the sections with the spec's options.
    pub fn build(&self) -> Result<Skin, SkinError> {
        skin_options(
            &self.sections,
            SkinOptions {
                basis: self.basis,
                pairing: self.pairing,
            },
        )
    }
}

/// Why a skin cannot be built. Sections and points are numbered from 0, as listed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SkinError {
    #[error("a skin needs at least 2 sections, {0} given")]
    TooFewSections(usize),
    #[error("section {section} has {points} point(s): a section needs at least 3")]
    TooFewPoints { section: usize, points: usize },
    #[error("section {section}, point {point}: a coordinate is not a finite number")]
    NonFinite { section: usize, point: usize },
    #[error("section {section}: points {a} and {b} are the same point")]
    RepeatedPoint { section: usize, a: usize, b: usize },
    #[error("section {section}: corner {corner} is not a point (the section has {points})")]
    CornerOutOfRange {
        section: usize,
        corner: usize,
        points: usize,
    },
    #[error("section {section} encloses no area (its points are collinear)")]
    NoArea { section: usize },
    #[error(
        "section {section} is not planar: point {point} is {distance:.3e} from its plane (tolerance {tolerance:.3e}, 1e-6 of the section's size)"
    )]
    NonPlanar {
        section: usize,
        point: usize,
        distance: f64,
        tolerance: f64,
    },
    #[error("section {section} intersects itself: its sides {a} and {b} cross")]
    SelfIntersecting { section: usize, a: usize, b: usize },
    #[error(
        "sections {a} and {b} are coincident (same centre): neighbouring sections must be apart"
    )]
    Coincident { a: usize, b: usize },
    #[error(
        "section {section} is not star-shaped about its centre (a ray from the centre meets its curve more than once, near point {point}): neighbouring sections are paired by their turn about their centres, and points are inserted by polar angle, which needs every ray from the centre to meet the curve once"
    )]
    NotStarShaped { section: usize, point: usize },
    #[error(
        "sections {a} and {b} cannot be matched by polar angle: vertices of one lie on the same ray from the centre of the other (within 1e-9 rad); give every section the same number of points instead"
    )]
    NotMatched { a: usize, b: usize },
    #[error(
        "the skin turns back at section {section}: chain {chain} meets it along or against the skinning direction (its neighbouring sections lie on one side of it, or it is tilted past them); move or reorder the sections"
    )]
    TurnsBack { section: usize, chain: usize },
    #[error("resolution {0} is out of range: 1 to 256 quads a patch side")]
    Resolution(usize),
    #[error("cancelled")]
    Cancelled,
}

/// A polygon turn (degrees) above which an unmarked section point is named by
/// [`Skin::notes`]: a regular triangle turns by 120°, a sharp trailing edge by 160° and more.
pub const SHARP_TURN: f64 = 150.0;

/// A skin: the prepared sections, the curve network and one Gregory patch per cell.
#[derive(Debug, Clone)]
pub struct Skin {
    pub sections: Vec<Section>,
    /// σ between sections k and k + 1 (in the prepared, counter-clockwise numbering).
    pub shifts: Vec<usize>,
    /// Total twist of each chosen shift, radians.
    pub twists: Vec<f64>,
    /// How the shifts were chosen: the requested pairing, or the polar pairing (twist 0) when
    /// points were inserted.
    pub pairing: Pairing,
    /// Per section, its vertex on chain 0.
    pub offset: Vec<usize>,
    /// Per chain, its cubic pieces between consecutive sections.
    pub chains: Vec<Vec<Cubic>>,
    /// Per chain, whether it is a crease (through a corner).
    pub crease: Vec<bool>,
    /// The virtual trajectories between neighbouring centres (for display).
    pub trajectories: Vec<RationalBezier>,
    /// The swept sections: section k moved into section k + 1's plane.
    pub swept: Vec<Vec<DVec3>>,
    /// Patch of cell (k, i) at `k * n + i`.
    pub patches: Vec<Gregory>,
    /// Vertices inserted into each section to equalise the counts (polar method, §10.9).
    pub inserted: Vec<usize>,
}

/// Builds the skin through `input` (at least 2 sections). Sections with unequal point counts
/// get vertices inserted by polar angle (beyond the paper, [`polar`]).
pub fn skin(input: &[SectionInput]) -> Result<Skin, SkinError> {
    skin_with(input, Basis::Virtual)
}

/// [`skin`] with the G1 construction of the inner borders chosen.
pub fn skin_with(input: &[SectionInput], basis: Basis) -> Result<Skin, SkinError> {
    skin_options(
        input,
        SkinOptions {
            basis,
            ..SkinOptions::default()
        },
    )
}

/// [`skin`] with every option chosen.
pub fn skin_options(input: &[SectionInput], options: SkinOptions) -> Result<Skin, SkinError> {
    let basis = options.basis;
    if input.len() < 2 {
        return Err(SkinError::TooFewSections(input.len()));
    }
    let checked = input
        .iter()
        .enumerate()
        .map(|(k, s)| sections::check(k, s))
        .collect::<Result<Vec<_>, _>>()?;
    for k in 1..checked.len() {
        let size = checked[k]
            .0
            .iter()
            .map(|p| (*p - checked[k].1).length())
            .fold(0.0, f64::max);
        if (checked[k].1 - checked[k - 1].1).length() <= 1e-9 * size {
            return Err(SkinError::Coincident { a: k - 1, b: k });
        }
    }
    let mut sections = sections::prepare(input, checked);
    for (k, s) in sections.iter().enumerate() {
        sections::check_star(k, s)?;
    }
    let n0 = sections[0].points.len();
    let (inserted, pairing) = if sections.iter().all(|s| s.points.len() == n0) {
        (vec![0; sections.len()], options.pairing)
    } else {
        // The polar insertion leaves a vertex on every transported ray: the least twist (0)
        // pairs them, whatever the shapes.
        (polar::equalise(&mut sections)?, Pairing::Paper)
    };
    let n = sections[0].points.len();
    let m = sections.len();
    let mut shifts = Vec::with_capacity(m - 1);
    let mut twists = Vec::with_capacity(m - 1);
    let mut swept = Vec::with_capacity(m - 1);
    let mut trajectories = Vec::with_capacity(m - 1);
    for k in 0..m - 1 {
        let s = network::sweep(&sections[k], &sections[k + 1]);
        let (sigma, twist) = network::pair(&s, &sections[k + 1], pairing);
        shifts.push(sigma);
        twists.push(twist);
        swept.push(s);
        trajectories.push(network::trajectory(&sections[k], &sections[k + 1]));
    }
    let (chains, offset) = network::chains(&sections, &shifts);
    network::check_forward(&sections, &chains)?;
    let crease: Vec<bool> = (0..n)
        .map(|i| {
            sections
                .iter()
                .zip(&offset)
                .any(|(s, &o)| s.corner[(i + o) % n])
        })
        .collect();
    let net = patches::Network {
        sections: &sections,
        chains: &chains,
        offset: &offset,
        crease: &crease,
        basis,
    };
    let patches = (0..m - 1)
        .flat_map(|k| (0..n).map(move |i| (k, i)))
        .map(|(k, i)| net.patch(k, i))
        .collect();
    Ok(Skin {
        sections,
        shifts,
        twists,
        pairing,
        offset,
        chains,
        crease,
        trajectories,
        swept,
        patches,
        inserted,
    })
}

impl Skin {
    /// Points per section.
    pub fn points_per_section(&self) -> usize {
        self.sections[0].points.len()
    }

    /// The patch of cell (k, i).
    pub fn patch(&self, k: usize, i: usize) -> &Gregory {
        &self.patches[k * self.points_per_section() + i]
    }

    /// The largest angle, in degrees, between the two patches' normals along any inner border
    /// that is not a crease, sampled at `samples` points a border (analytic normals).
    pub fn border_normal_jump(&self, samples: usize) -> f64 {
        let n = self.points_per_section();
        let m = self.sections.len();
        let mut worst = 0.0f64;
        let angle = |a: DVec3, b: DVec3| a.cross(b).length().atan2(a.dot(b)).to_degrees();
        for k in 0..m - 1 {
            for i in 0..n {
                for s in 0..=samples {
                    let t = s as f64 / samples as f64;
                    // Chain i + 1 between cells (k, i) and (k, i + 1).
                    if !self.crease[(i + 1) % n] {
                        let a = self.patch(k, i).eval(1.0, t).normal;
                        let b = self.patch(k, (i + 1) % n).eval(0.0, t).normal;
                        worst = worst.max(angle(a, b));
                    }
                    // Section k + 1 between cells (k, i) and (k + 1, i).
                    if k + 2 < m {
                        let a = self.patch(k, i).eval(t, 1.0).normal;
                        let b = self.patch(k + 1, i).eval(t, 0.0).normal;
                        worst = worst.max(angle(a, b));
                    }
                }
            }
        }
        worst
    }

    /// What the user should know about the sections: each point, not marked a corner, where
    /// its section's polygon turns by more than [`SHARP_TURN`] — the smooth curve must turn
    /// there within a small fraction of the point spacing, so the surface is a near-crease that
    /// only a fine mesh resolves.
    pub fn notes(&self) -> Vec<String> {
        let mut out = Vec::new();
        for (k, s) in self.sections.iter().enumerate() {
            let n = s.points.len();
            for i in 0..n {
                if s.corner[i] || s.original[i] == usize::MAX {
                    continue;
                }
                // The neighbouring given points (inserted ones lie on the curve).
                let given = |step: isize| {
                    (1..n)
                        .map(|d| (i as isize + step * d as isize).rem_euclid(n as isize) as usize)
                        .find(|&j| s.original[j] != usize::MAX)
                        .map_or(s.points[i], |j| s.points[j])
                };
                let (a, b) = (s.points[i] - given(-1), given(1) - s.points[i]);
                let turn = a.angle_between(b).to_degrees();
                if turn > SHARP_TURN {
                    out.push(format!(
                        "section {k}: point {} turns by {turn:.0}° and is not a corner: the smooth curve rounds it within a fraction of the point spacing (mark it a corner, \"corners\": [{}], for a sharp edge)",
                        s.original[i], s.original[i]
                    ));
                }
            }
        }
        out
    }

    /// Each pair of neighbouring sections k, k + 1: k, the shift chosen and its total twist in
    /// degrees.
    pub fn pairs(&self) -> impl Iterator<Item = (usize, usize, f64)> + '_ {
        (self.shifts.iter().zip(&self.twists))
            .enumerate()
            .map(|(k, (&shift, t))| (k, shift, t.to_degrees()))
    }

    /// How the shifts were chosen, for a summary: "by polar angle" when points were inserted,
    /// else "by shape" or "by least twist (paper)".
    pub fn paired_by(&self) -> &'static str {
        match (self.pairing, self.inserted.iter().any(|&i| i > 0)) {
            (_, true) => "by polar angle",
            (Pairing::Shape, false) => "by shape",
            (Pairing::Paper, false) => "by least twist (paper)",
        }
    }

    /// Number of chains that are creases.
    pub fn creases(&self) -> usize {
        self.crease.iter().filter(|&&c| c).count()
    }
}
