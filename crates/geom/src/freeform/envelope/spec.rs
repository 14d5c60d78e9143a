//! A scene as the user gives it ([`EnvelopeSpec`], the `.envelope.json` and `.prism.json`
//! form), the choices of construction it carries, and what can go wrong building it.

use super::primitive::PrimitiveInput;
use crate::freeform::skin::Basis;
use serde::{Deserialize, Serialize};
use thiserror::Error;

/// What stops an envelope, naming the primitive, the pair or the region.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum EnvelopeError {
    #[error("the scene has no primitive")]
    Empty,
    #[error("primitive {index}: {why}")]
    Primitive { index: usize, why: String },
    #[error("t of {what} is {t}: t must be finite and > 0 (ρ = t·r)")]
    BadT { what: String, t: f64 },
    #[error("fusing primitives {a} and {b}: {why}")]
    Fusion { a: usize, b: usize, why: String },
    #[error("primitives {a} and {b} have the same centre: there is no view vector between them")]
    SameCentre { a: usize, b: usize },
    #[error("resolution {0} is out of range: 1 to 256")]
    Resolution(usize),
    #[error("patch {patch} has a point that is not finite (a bug: please report the scene)")]
    NonFinite { patch: usize },
    #[error("region {region} has no chart: {why} (a bug: please report the scene)")]
    Chart { region: usize, why: String },
    #[error("cancelled")]
    Cancelled,
}

/// How the regions of the network are filled (docs/algorithms/envelope.md).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Surfacing {
    /// Scalar graphs over flat charts ([`super::chart`]): cannot fold, G1 by one tangent plane per
    /// curve, the faces enclosed.
    #[default]
    Charts,
    /// The paper's vector Coons patches with Gregory's twist (seed 004 §6), for comparison.
    Paper,
}

impl Surfacing {
    pub fn name(self) -> &'static str {
        match self {
            Surfacing::Charts => "charts",
            Surfacing::Paper => "paper",
        }
    }
}

fn is_charts(s: &Surfacing) -> bool {
    *s == Surfacing::Charts
}

/// A scene: the default t, the primitives and the tessellation's resolution.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EnvelopeSpec {
    #[serde(default = "one")]
    pub t: f64,
    pub primitives: Vec<PrimitiveInput>,
    /// Quads along each side of a patch.
    #[serde(default = "eight")]
    pub resolution: usize,
    /// The G1 construction of the borders: `virtual` (default: independent of the listing) or
    /// the paper's `one-sided` (the region listed first leads each border).
    #[serde(default, skip_serializing_if = "is_virtual")]
    pub basis: Basis,
    /// How the regions are filled: `charts` (default) or the paper's `paper` patches.
    #[serde(default, skip_serializing_if = "is_charts")]
    pub patches: Surfacing,
    /// Whether the charts' fusion strips are lifted over the primitives' removed corners
    /// (`lifted`, default) or keep the paper's central cut (`paper`).
    #[serde(default, skip_serializing_if = "is_lifted")]
    pub enclosure: Enclosure,
}

impl EnvelopeSpec {
    /// Bytes its construction holds, from the primitives' faces alone (before it is built;
    /// [`crate::memory::envelope_construction_bytes`]).
    pub fn construction_bytes(&self) -> u64 {
        let faces: usize = self.primitives.iter().map(|p| p.faces.len()).sum();
        crate::memory::envelope_construction_bytes(faces as u64)
    }
}

fn is_lifted(e: &Enclosure) -> bool {
    *e == Enclosure::Lifted
}

/// What holds the primitives' corners that the silhouette plane through each centre cuts off
/// (docs/algorithms/envelope.md, "Enclosure").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Enclosure {
    /// The fusion strips lifted over every removed corner and edge ([`super::chart::lift`]).
    #[default]
    Lifted,
    /// The paper's central cut as it lies: removed corners may poke out at small t.
    Paper,
}

impl Enclosure {
    pub fn name(self) -> &'static str {
        match self {
            Enclosure::Lifted => "lifted",
            Enclosure::Paper => "paper",
        }
    }
}

fn is_virtual(b: &Basis) -> bool {
    *b == Basis::Virtual
}

fn one() -> f64 {
    1.0
}

fn eight() -> usize {
    8
}
