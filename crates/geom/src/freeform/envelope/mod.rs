//! Free-form surfaces that envelope primitives (seed 004, Ogasawara & Kobori; ALGORITHMS §6.3,
//! §8, §9, §11; docs/algorithms/envelope.md).
//!
//! A primitive's straight edges become rational cubics with end curvature 1/(t·r)
//! ([`edges`]); the network of curves ([`network`]) is filled with Coons patches with
//! variable twist ([`coons`]), G1 across every border through the numbering-independent
//! virtual basis, n-sided regions split into quads around an inserted point ([`patches`]);
//! [`tessellate`] welds them into a closed outward mesh.
//!
//! This version envelopes one or two primitives: each of a pair is trimmed by its silhouette
//! plane ([`trim`]) and the two silhouette loops are joined by fusion edges and quads
//! ([`fusion`]). Three or more (sections cut again, straight edges, swallowed primitives) are
//! the next increment, and such a scene is refused with that said.

pub mod coons;
pub mod edges;
pub mod fusion;
pub mod network;
pub mod patches;
pub mod primitive;
pub mod tessellate;
pub mod trim;

pub use network::{CurveKind, Network};
pub use patches::EnvelopePatch;
pub use primitive::{Placement, Primitive, PrimitiveInput, Shape};

use crate::freeform::skin::Basis;
use crate::mesh::PolyMesh;
use serde::{Deserialize, Serialize};
use thiserror::Error;

#[derive(Debug, Clone, PartialEq, Error)]
pub enum EnvelopeError {
    #[error("the scene has no primitive")]
    Empty,
    #[error("primitive {index}: {why}")]
    Primitive { index: usize, why: String },
    #[error("t of {what} is {t}: t must be finite and > 0 (ρ = t·r)")]
    BadT { what: String, t: f64 },
    #[error(
        "{count} primitives: this version envelopes one or two primitives; the network of three or more (sections cut again, straight edges, swallowed primitives, seed 004 §5.1.3 and §5.2 b) is not built yet"
    )]
    Several { count: usize },
    #[error("primitives {a} and {b} have the same centre: there is no view vector between them")]
    SameCentre { a: usize, b: usize },
    #[error("resolution {0} is out of range: 1 to 256")]
    Resolution(usize),
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

/// The envelope: checked primitives, the curve network (with the insertion curves of the
/// n-sided split) and the patches.
#[derive(Debug, Clone, PartialEq)]
pub struct Envelope {
    pub primitives: Vec<Primitive>,
    pub network: Network,
    /// Faces of the network before the n-sided split.
    pub regions: usize,
    pub patches: Vec<EnvelopePatch>,
    /// Primitives swallowed by the others (indices in the scene).
    pub removed: Vec<usize>,
}

/// Builds the envelope of a scene.
pub fn envelope(spec: &EnvelopeSpec) -> Result<Envelope, EnvelopeError> {
    if !(spec.t.is_finite() && spec.t > 0.0) {
        return Err(EnvelopeError::BadT {
            what: "the scene".into(),
            t: spec.t,
        });
    }
    let primitives = spec
        .primitives
        .iter()
        .enumerate()
        .map(|(i, p)| Primitive::new(i, p, spec.t))
        .collect::<Result<Vec<_>, _>>()?;
    let mut network = Network::default();
    match primitives.as_slice() {
        [] => return Err(EnvelopeError::Empty),
        [p] => {
            trim::add_primitive(&mut network, p, 0, None)?;
        }
        [a, b] => {
            let between = b.centre - a.centre;
            if between.length() <= 1e-9 * a.radius.max(b.radius) {
                return Err(EnvelopeError::SameCentre { a: 0, b: 1 });
            }
            let d = between.normalize();
            let la = trim::add_primitive(&mut network, a, 0, Some(d))?;
            let lb = trim::add_primitive(&mut network, b, 1, Some(-d))?;
            fusion::fuse(&mut network, (a.centre, &la), (b.centre, &lb), d);
        }
        more => return Err(EnvelopeError::Several { count: more.len() }),
    }
    network.assign_bases(spec.basis);
    let regions = network.regions.len();
    let patches = patches::build(&mut network, &primitives);
    Ok(Envelope {
        primitives,
        network,
        regions,
        patches,
        removed: Vec::new(),
    })
}

impl Envelope {
    /// The welded tessellation, `k` × `k` quads a patch.
    pub fn tessellate(&self, k: usize) -> Result<PolyMesh, EnvelopeError> {
        if k == 0 || k > 256 {
            return Err(EnvelopeError::Resolution(k));
        }
        Ok(tessellate::tessellate(&self.network, &self.patches, k))
    }

    /// The largest angle in degrees between the two sides' normals along the patch borders
    /// (analytic, 16 samples a side).
    pub fn largest_border_jump(&self) -> f64 {
        patches::largest_border_jump(&self.network, &self.patches, 16)
    }
}
