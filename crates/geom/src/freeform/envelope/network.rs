//! The curve network of an envelope (seed 004 §4–§5; ALGORITHMS §11.1–11.5;
//! docs/algorithms/envelope.md): network vertices with their tangent planes, rational cubic
//! curves with their virtual bases (ALGORITHMS §8.2), and regions bounded by curves.
//!
//! For one primitive the network is the primitive itself with curved edges (§6.3): every
//! vertex's tangent plane is normal to `P − G`, which every edge curve touches there (§8.1),
//! and every curve's basis follows rule (b) at both ends, `g = n × unit(C′)` (three or more
//! curves meet at each vertex, none continuing another).

use super::EnvelopeError;
use super::edges::curved_edge;
use super::primitive::Primitive;
use crate::freeform::bezier::RationalBezier;
use glam::DVec3;
use std::collections::HashMap;

/// What a network curve is, for display.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CurveKind {
    /// A curved edge of a primitive.
    Edge,
    /// A curve inserted to split an n-sided region into quads (§6.3 of the paper).
    Insertion,
}

/// A network vertex and the unit normal of its tangent plane (outward).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NetVertex {
    pub position: DVec3,
    pub normal: DVec3,
}

/// A network curve from `ends[0]` (τ = 0) to `ends[1]` (τ = 1).
#[derive(Debug, Clone, PartialEq)]
pub struct NetCurve {
    pub bezier: RationalBezier,
    pub ends: [usize; 2],
    /// The virtual basis at τ = 0 and τ = 1 (linear between, §8.2); on its left seen from
    /// outside.
    pub basis: (DVec3, DVec3),
    pub kind: CurveKind,
    /// Network vertices on the curve, by parameter (its ends and the points where an
    /// n-sided region split it), ascending.
    pub pins: Vec<(f64, usize)>,
}

impl NetCurve {
    /// The basis at τ.
    pub fn basis_at(&self, t: f64) -> DVec3 {
        self.basis.0.lerp(self.basis.1, t)
    }
}

/// A face of the network: its sides counter-clockwise seen from outside, each a curve and
/// whether it runs forwards (τ 0 → 1).
#[derive(Debug, Clone, PartialEq)]
pub struct Region {
    pub sides: Vec<(usize, bool)>,
    /// The primitive and face it lies on.
    pub face: (usize, usize),
}

/// The network.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Network {
    pub vertices: Vec<NetVertex>,
    pub curves: Vec<NetCurve>,
    pub regions: Vec<Region>,
}

/// Rule (b) of §8.2: the direction in the tangent plane perpendicular to the curve.
pub(crate) fn perpendicular(n: DVec3, tangent: DVec3) -> DVec3 {
    n.cross(tangent.normalize_or_zero())
}

impl Network {
    /// Adds a curve between network vertices `a` and `b` with the basis from rule (b) at
    /// both ends (callers override it where rule (a) applies).
    pub(crate) fn add_curve(
        &mut self,
        bezier: RationalBezier,
        a: usize,
        b: usize,
        kind: CurveKind,
    ) -> usize {
        let d0 = bezier.derivatives(0.0).d1;
        let d1 = bezier.derivatives(1.0).d1;
        let basis = (
            perpendicular(self.vertices[a].normal, d0),
            perpendicular(self.vertices[b].normal, d1),
        );
        self.curves.push(NetCurve {
            bezier,
            ends: [a, b],
            basis,
            kind,
            pins: vec![(0.0, a), (1.0, b)],
        });
        self.curves.len() - 1
    }

    /// The network of one primitive (index `index` in the scene): its vertices, curved
    /// edges and faces.
    pub fn of_primitive(p: &Primitive, index: usize) -> Result<Network, EnvelopeError> {
        let mut net = Network {
            vertices: p
                .vertices
                .iter()
                .map(|&v| NetVertex {
                    position: v,
                    normal: (v - p.centre).normalize(),
                })
                .collect(),
            ..Network::default()
        };
        let mut edge_curve: HashMap<(usize, usize), usize> = HashMap::new();
        for (f, face) in p.faces.iter().enumerate() {
            let mut sides = Vec::with_capacity(face.len());
            for k in 0..face.len() {
                let (a, b) = (face[k], face[(k + 1) % face.len()]);
                let side = if let Some(&c) = edge_curve.get(&(b, a)) {
                    (c, false)
                } else {
                    let bez = curved_edge(p.centre, p.vertices[a], p.vertices[b], p.t[a], p.t[b])
                        .ok_or_else(|| EnvelopeError::Primitive {
                        index,
                        why: format!(
                            "edge {a}-{b} cannot be curved (through or opposite the centre)"
                        ),
                    })?;
                    let c = net.add_curve(bez, a, b, CurveKind::Edge);
                    edge_curve.insert((a, b), c);
                    (c, true)
                };
                sides.push(side);
            }
            net.regions.push(Region {
                sides,
                face: (index, f),
            });
        }
        Ok(net)
    }
}
