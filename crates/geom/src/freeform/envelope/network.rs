//! The curve network of an envelope (seed 004 §4–§5;
//! docs/algorithms/envelope.md): network vertices with their tangent planes, rational cubic
//! curves with their virtual bases (docs/algorithms/skin.md, "Patches and G1"), and regions bounded by curves or parts
//! of curves.
//!
//! Every curve of a primitive touches, at each of its ends, the plane normal to `P − G`
//! there (§6.3), so that plane is the vertex's tangent plane (§8.1). A curve's basis is chosen
//! per end once all regions exist ([`Network::assign_bases`]): rule (a), the crossing curves'
//! common direction, where the two regions beside the curve leave that end along one line in
//! opposite senses (the halves of a split border, a silhouette loop through a fusion edge's
//! end); rule (b), `g = n × unit(C′)`, elsewhere (primitive corners, where three or more
//! curves meet).

use crate::freeform::bezier::RationalBezier;
use crate::freeform::envelope::tolerances::TOLERANCES;
use crate::freeform::skin::Basis;
use glam::DVec3;

/// What a network curve is, for display.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CurveKind {
    /// A curved edge of a primitive, or the kept part of one.
    Edge,
    /// A silhouette edge: where a primitive is cut by its silhouette plane (§5.1).
    Silhouette,
    /// A fusion edge between two primitives' silhouette loops (§5.2).
    Fusion,
    /// A curve inserted to split an n-sided region into quads (§6.3 of the paper).
    Insertion,
}

/// A network vertex: its position, the unit normal of its tangent plane (outward) and its
/// curvature radius ρ = t·|P − G| (for the n-sided split's ρ̄).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NetVertex {
    pub position: DVec3,
    pub normal: DVec3,
    pub rho: f64,
}

impl NetVertex {
    /// Its curvature parameter t = ρ/|P − G| about its primitive's centre `g`.
    pub fn t_about(&self, g: DVec3) -> f64 {
        self.rho / self.position.distance(g)
    }
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
    /// Network vertices on the curve, by parameter (its ends, the T-points where a fusion
    /// quad's corner lies on it, the points where an n-sided region split it), ascending.
    pub pins: Vec<(f64, usize)>,
}

impl NetCurve {
    /// Whether it is a point: the collapsed side of a needle patched as one quad (its ends
    /// are one vertex).
    pub fn is_point(&self) -> bool {
        self.ends[0] == self.ends[1]
    }

    /// The basis at τ.
    pub fn basis_at(&self, t: f64) -> DVec3 {
        self.basis.0.lerp(self.basis.1, t)
    }
}

/// A side of a region or patch: curve `curve` from τ = t0 to τ = t1 (t0 > t1: backwards).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchSide {
    pub curve: usize,
    pub t0: f64,
    pub t1: f64,
}

impl PatchSide {
    /// The whole curve, forwards or backwards.
    pub fn whole(curve: usize, forward: bool) -> PatchSide {
        let (t0, t1) = if forward { (0.0, 1.0) } else { (1.0, 0.0) };
        PatchSide { curve, t0, t1 }
    }

    /// Its first or second half.
    pub fn half(&self, second: bool) -> PatchSide {
        let mid = 0.5 * (self.t0 + self.t1);
        if second {
            PatchSide { t0: mid, ..*self }
        } else {
            PatchSide { t1: mid, ..*self }
        }
    }

    /// The curve parameter at side parameter s.
    pub fn tau(&self, s: f64) -> f64 {
        self.t0 + (self.t1 - self.t0) * s
    }

    /// The same piece the other way.
    pub fn reversed(&self) -> PatchSide {
        PatchSide {
            curve: self.curve,
            t0: self.t1,
            t1: self.t0,
        }
    }
}

/// What a region lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RegionKind {
    /// (The kept part of) face `face` of primitive `primitive`.
    Primitive { primitive: usize, face: usize },
    /// A fusion quad between the silhouette sections of primitives `from` and `to` (its fusion
    /// edges run from `from`'s section to `to`'s, along d = unit(G_to − G_from)).
    Fusion { from: usize, to: usize },
    /// A lid over facet `facet` of the hull of the centres, bounded by fusion edges.
    Lid { facet: usize },
}

impl RegionKind {
    /// Whether it lies between primitives (a fusion quad or a lid).
    pub fn between(&self) -> bool {
        !matches!(self, RegionKind::Primitive { .. })
    }
}

/// A face of the network: its sides counter-clockwise seen from outside.
#[derive(Debug, Clone, PartialEq)]
pub struct Region {
    pub sides: Vec<PatchSide>,
    pub kind: RegionKind,
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

/// [`TOLERANCES`]`.straight_legs`.
const STRAIGHT: f64 = TOLERANCES.straight_legs;

/// [`TOLERANCES`]`.grazing`.
const GRAZING: f64 = TOLERANCES.grazing;

impl Network {
    /// Adds a vertex.
    pub(crate) fn add_vertex(&mut self, position: DVec3, normal: DVec3, rho: f64) -> usize {
        self.vertices.push(NetVertex {
            position,
            normal,
            rho,
        });
        self.vertices.len() - 1
    }

    /// Adds a curve between network vertices `a` and `b` with the basis from rule (b) at
    /// both ends ([`Network::assign_bases`] revisits it once the regions exist).
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

    /// The network vertex at τ on `curve` (an end or a pin), if any.
    pub fn vertex_at(&self, curve: usize, tau: f64) -> Option<usize> {
        self.curves[curve]
            .pins
            .iter()
            .find(|&&(t, _)| (t - tau).abs() <= 1e-12)
            .map(|&(_, v)| v)
    }

    /// Adds network vertex `v` at τ on `curve` (a T-point or a split point).
    pub(crate) fn pin(&mut self, curve: usize, tau: f64, v: usize) {
        let pins = &mut self.curves[curve].pins;
        let at = pins.partition_point(|&(t, _)| t < tau);
        pins.insert(at, (tau, v));
    }

    /// The derivative of a side's curve piece at its start (`end = false`) or end, in the
    /// piece's own parameter.
    pub(crate) fn side_derivative(&self, s: &PatchSide, end: bool) -> DVec3 {
        let tau = if end { s.t1 } else { s.t0 };
        self.curves[s.curve].bezier.derivatives(tau).d1 * (s.t1 - s.t0)
    }

    /// Chooses every curve's basis per end from the regions beside it (§8.2): rule (a) where
    /// the two regions' legs at that end are antiparallel (the curves crossing there continue
    /// each other), rule (b) elsewhere; oriented so that `g·(n × C′) > 0` at both ends. With
    /// [`Basis::OneSided`] (the paper's reading, an option) the first region listed that runs
    /// along the whole curve is its basis: g is that region's own legs at the curve's ends, so
    /// its cross derivative is their linear blend (k = 1, h = 0) and the other side follows it.
    pub fn assign_bases(&mut self, basis: Basis) {
        // Per (curve, end): (region, whether it has the whole curve, the leg it leaves with).
        type Legs = Vec<(usize, bool, DVec3)>;
        let mut legs: Vec<[Legs; 2]> = vec![[Vec::new(), Vec::new()]; self.curves.len()];
        for (ri, r) in self.regions.iter().enumerate() {
            let n = r.sides.len();
            for k in 0..n {
                let s = r.sides[k];
                let whole = (s.t0 - s.t1).abs() == 1.0;
                let (prev, next) = (&r.sides[(k + n - 1) % n], &r.sides[(k + 1) % n]);
                for (tau, leg) in [
                    (s.t0, -self.side_derivative(prev, true)),
                    (s.t1, self.side_derivative(next, false)),
                ] {
                    if tau == 0.0 {
                        legs[s.curve][0].push((ri, whole, leg));
                    } else if tau == 1.0 {
                        legs[s.curve][1].push((ri, whole, leg));
                    }
                }
            }
        }
        for (c, legs) in legs.iter().enumerate() {
            let curve = &self.curves[c];
            if basis == Basis::OneSided {
                let first = legs[0]
                    .iter()
                    .filter(|l| l.1)
                    .map(|l| l.0)
                    .min()
                    .filter(|&r| legs[1].iter().any(|l| l.0 == r));
                let of = |end: usize, r: usize| legs[end].iter().find(|l| l.0 == r).map(|l| l.2);
                if let Some(r) = first
                    && legs[0].len() == 2
                    && let (Some(a0), Some(a1)) = (of(0, r), of(1, r))
                {
                    self.curves[c].basis = (a0, a1);
                    continue;
                }
            }
            let mut g = [DVec3::ZERO; 2];
            for end in 0..2 {
                let v = &self.vertices[curve.ends[end]];
                let d = curve.bezier.derivatives(end as f64).d1.normalize_or_zero();
                let side = v.normal.cross(d);
                g[end] = match legs[end].iter().map(|l| l.2).collect::<Vec<_>>().as_slice() {
                    [a, b]
                        if a.cross(*b).length().atan2(a.dot(*b))
                            > std::f64::consts::PI - STRAIGHT
                            && a.normalize_or_zero().cross(d).length() >= GRAZING =>
                    {
                        let u = a.normalize_or_zero();
                        if u.dot(side) >= 0.0 { u } else { -u }
                    }
                    _ => side,
                };
            }
            self.curves[c].basis = (g[0], g[1]);
        }
    }
}
