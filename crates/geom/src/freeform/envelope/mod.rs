//! Free-form surfaces that envelope primitives (seed 004, Ogasawara & Kobori;
//! docs/algorithms/envelope.md).
//!
//! A primitive's straight edges become rational cubics with end curvature 1/(t·r)
//! ([`edges`]). By default ([`Surfacing::Charts`]) every region of the network ([`network`])
//! is a scalar graph over a flat chart ([`chart`]): a primitive's region a radial graph about
//! its centre over its clipped flat face, a fusion strip a graph about the axis of its two
//! centres, a lid a graph over its hull facet; G1 along every curve by one tangent plane
//! shared by both sides; the fusion strips lifted over the corners the silhouette planes cut
//! off ([`Enclosure::Lifted`]). The paper's own construction stays as
//! [`Surfacing::Paper`]: vector Coons patches with variable twist ([`coons`]), n-sided regions
//! split about an inserted point ([`patches`]), their folds counted ([`folds`]).
//! [`tessellate`] welds either into a closed outward mesh.
//!
//! Any number of primitives: the hull of their centres ([`hull`]) says which primitive is cut
//! towards which (its hull neighbours) and which are swallowed ([`nested`] leaves out, too, a
//! primitive inside a larger one's sphere and the others' envelope); each kept primitive is clipped
//! by its silhouette planes ([`clip`]); the facing sections of every hull edge are joined by
//! fusion edges and quads ([`fusion`]), and every hull facet is a lid bounded by the fusion
//! edges at its ray.

pub mod chart;
pub mod clip;
pub mod coons;
pub mod edges;
mod facet;
pub mod folds;
pub mod fusion;
pub mod hull;
pub mod local;
pub mod nested;
pub mod network;
pub mod patches;
pub mod primitive;
pub mod study;
pub mod tessellate;
pub mod tolerances;
mod wrap;

mod report;
mod spec;

pub use local::LocalFrame;
pub use network::{CurveKind, Network};
pub use patches::EnvelopePatch;
pub use primitive::{Placement, Primitive, PrimitiveInput, Shape};
pub use spec::{Enclosure, EnvelopeError, EnvelopeSpec, Surfacing};
pub use tolerances::{TOLERANCES, Tolerances};

use crate::mesh::PolyMesh;
use crate::progress::Progress;
use glam::DVec3;
use network::{PatchSide, Region, RegionKind};
use rayon::prelude::*;
use std::collections::HashMap;

/// The envelope: checked primitives, the curve network (with the insertion curves of the
/// n-sided split) and the patches, all in the local coordinates of [`Envelope::frame`]; its
/// meshes ([`Envelope::mesh`], [`Envelope::tessellate`], [`Envelope::chart_mesh`]) are in the
/// scene's.
#[derive(Debug, Clone, PartialEq)]
pub struct Envelope {
    /// Where the local coordinates lie in the scene's ([`local`]).
    pub frame: LocalFrame,
    pub primitives: Vec<Primitive>,
    pub network: Network,
    /// Faces of the network before the n-sided split.
    pub regions: usize,
    pub patches: Vec<EnvelopePatch>,
    /// The folded cells of `patches` as built, [`folds::FOLD_CELLS`] a side (found while
    /// building them, less steps along a border: [`Envelope::folds`]).
    pub folded: Vec<folds::Fold>,
    /// Primitives swallowed by the others (indices in the scene): centre not a corner of the
    /// hull of the centres, or within a tenth of its radius of the others' hull ([`hull`]), or
    /// nested in a larger one and inside the others' envelope ([`nested`]).
    pub removed: Vec<usize>,
    /// The straight edges of the sections (§5.1.3), from a kept primitive's centre to where two
    /// of its silhouette planes cross its surface: inside the solid, for display only.
    pub straight: Vec<[DVec3; 2]>,
    /// How the regions are filled; with [`Surfacing::Charts`], one chart a region (and no
    /// `patches`).
    pub surfacing: Surfacing,
    pub charts: Vec<chart::Chart>,
    /// The fusion strips' lifts over the removed corners ([`Enclosure::Lifted`], charts only).
    pub lifts: Vec<chart::lift::Lift>,
    /// The primitives' and lids' regions raised over the points no lift holds (likewise).
    pub raises: Vec<chart::lift::Raise>,
    /// The mesh spacing for resolution 1: the mean length of the primitives' edges (local).
    pub edge_length: f64,
}

/// [`TOLERANCES`]`.swallow`.
const SWALLOW: f64 = TOLERANCES.swallow;

/// The signed angle (0 to 2π) from `from` to `to` about unit `d`, counter-clockwise.
fn ccw(d: DVec3, from: DVec3, to: DVec3) -> f64 {
    d.dot(from.cross(to))
        .atan2(from.dot(to))
        .rem_euclid(std::f64::consts::TAU)
}

/// Builds the envelope of a scene, in the local coordinates of [`LocalFrame::of`] its
/// primitives.
pub fn envelope(spec: &EnvelopeSpec) -> Result<Envelope, EnvelopeError> {
    let frame = LocalFrame::of(&spec.primitives);
    // Every field but the primitives is a number or a choice: copied, the vertices mapped.
    let local = EnvelopeSpec {
        primitives: spec
            .primitives
            .iter()
            .map(|p| frame.input_to_local(p))
            .collect(),
        t: spec.t,
        resolution: spec.resolution,
        basis: spec.basis,
        patches: spec.patches,
        enclosure: spec.enclosure,
    };
    let mut e = envelope_here(&local)?;
    e.frame = frame;
    Ok(e)
}

/// The envelope of a scene in its own coordinates (the identity frame).
fn envelope_here(spec: &EnvelopeSpec) -> Result<Envelope, EnvelopeError> {
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
    if primitives.is_empty() {
        return Err(EnvelopeError::Empty);
    }
    for (a, pa) in primitives.iter().enumerate() {
        for (b, pb) in primitives.iter().enumerate().skip(a + 1) {
            if pa.centre.distance(pb.centre) <= 1e-9 * pa.radius.max(pb.radius) {
                return Err(EnvelopeError::SameCentre { a, b });
            }
        }
    }
    let without = |left_out: &[usize]| -> Vec<usize> {
        (0..primitives.len())
            .filter(|i| left_out.binary_search(i).is_err())
            .collect()
    };
    let candidates = nested::candidates(&primitives);
    if candidates.is_empty() {
        let all = without(&[]);
        return assemble(spec, primitives, all);
    }
    // The envelope without every candidate is the answer when all of them lie inside it.
    // Should that scene fail to build, the scene as given decides, candidates kept.
    let Ok(rest) = assemble(spec, primitives.clone(), without(&candidates)) else {
        let all = without(&[]);
        return assemble(spec, primitives, all);
    };
    let inside = nested::inside(spec, &primitives, &rest, &candidates);
    if inside.len() == candidates.len() {
        return Ok(rest);
    }
    let active = without(&inside);
    assemble(spec, primitives, active)
}

/// The envelope of the primitives `active` (ascending) of `primitives`, the others reported
/// as removed.
fn assemble(
    spec: &EnvelopeSpec,
    primitives: Vec<Primitive>,
    active: Vec<usize>,
) -> Result<Envelope, EnvelopeError> {
    let centres: Vec<DVec3> = primitives.iter().map(|p| p.centre).collect();
    let largest = primitives.iter().map(|p| p.radius).fold(0.0, f64::max);
    let extent = centres
        .iter()
        .map(|c| c.distance(centres[0]))
        .fold(largest, f64::max);
    let radii: Vec<f64> = primitives.iter().map(|p| p.radius).collect();
    let lay = hull::layout_swallowing(&centres, &radii, active, 1e-9 * extent, SWALLOW);
    let mut network = Network::default();
    let mut sections: HashMap<(usize, usize), Vec<PatchSide>> = HashMap::new();
    let near_angle = match spec.patches {
        Surfacing::Charts => 0.0,
        Surfacing::Paper => fusion::NEAR_ANGLE,
    };
    for &a in &lay.kept {
        // The cuts in an order of their directions, not of the listing, so that rounding in the
        // clipping cannot depend on the listing either.
        let mut partners = lay.neighbours(a);
        let dir = |b: usize| (centres[b] - centres[a]).normalize().to_array();
        partners.sort_by(|&p, &q| {
            let (u, v) = (dir(p), dir(q));
            u[0].total_cmp(&v[0])
                .then(u[1].total_cmp(&v[1]))
                .then(u[2].total_cmp(&v[2]))
        });
        let cuts: Vec<DVec3> = partners
            .iter()
            .map(|&b| (centres[b] - centres[a]).normalize())
            .collect();
        let found = clip::add_primitive(
            &mut network,
            &primitives[a],
            a,
            &cuts,
            spec.patches == Surfacing::Charts,
        )?;
        for (b, s) in partners.into_iter().zip(found) {
            sections.insert((a, b), s);
        }
    }
    // Fusion strips along the hull edges; the fusion edges at each end, by facet.
    let mut ends: HashMap<(usize, usize), usize> = HashMap::new(); // (edge, facet) → curve
    for (ei, e) in lay.edges.iter().enumerate() {
        let d = (centres[e.b] - centres[e.a]).normalize();
        let order = e.facets.map(|[f1, f2]| {
            let (r1, r2) = (lay.facets[f1].normal, lay.facets[f2].normal);
            if ccw(d, r1, e.outward) < ccw(d, r1, r2) {
                ((f1, r1), (f2, r2))
            } else {
                ((f2, r2), (f1, r1))
            }
        });
        let fused = fusion::fuse(
            &mut network,
            (centres[e.a], &sections[&(e.a, e.b)]),
            (centres[e.b], &sections[&(e.b, e.a)]),
            d,
            order.map(|(s, t)| (s.1, t.1)),
            (e.a, e.b, near_angle),
        )
        .map_err(|why| EnvelopeError::Fusion {
            a: e.a,
            b: e.b,
            why,
        })?;
        if let (Some((first, last)), Some((s, t))) = (fused, order) {
            ends.insert((ei, s.0), first);
            ends.insert((ei, t.0), last);
        }
    }
    // Lids: each facet, bounded by the fusion edges at its ray.
    let mut straight = Vec::new();
    for (fi, f) in lay.facets.iter().enumerate() {
        let m = f.corners.len();
        let mut sides = Vec::with_capacity(m);
        for i in 0..m {
            let (p, q) = (f.corners[i], f.corners[(i + 1) % m]);
            let ei = lay
                .edges
                .iter()
                .position(|e| (e.a, e.b) == (p.min(q), p.max(q)))
                .expect("a facet's side is a hull edge");
            let c = ends[&(ei, fi)];
            let side = PatchSide::whole(c, p < q);
            let corner = network.curves[c].ends[if p < q { 0 } else { 1 }];
            straight.push([centres[p], network.vertices[corner].position]);
            sides.push(side);
        }
        network.regions.push(Region {
            sides,
            kind: RegionKind::Lid { facet: fi },
        });
    }
    let regions = network.regions.len();
    let edge_length = {
        let lengths: Vec<f64> = primitives
            .iter()
            .flat_map(|p| {
                p.faces.iter().flat_map(move |f| {
                    (0..f.len())
                        .map(move |k| p.vertices[f[k]].distance(p.vertices[f[(k + 1) % f.len()]]))
                })
            })
            .collect();
        lengths.iter().sum::<f64>() / lengths.len().max(1) as f64
    };
    if spec.patches == Surfacing::Charts {
        let lids: Vec<chart::LidPlane> = lay
            .facets
            .iter()
            .map(|f| chart::LidPlane {
                point: centres[f.corners[0]],
                normal: f.normal,
            })
            .collect();
        let charts = chart::charts(&network, &primitives, &lids)?;
        let (lifts, raises) = match spec.enclosure {
            Enclosure::Lifted => chart::lift::enclosure(&network, &charts, &primitives),
            Enclosure::Paper => (Vec::new(), Vec::new()),
        };
        return Ok(Envelope {
            frame: LocalFrame::IDENTITY,
            primitives,
            network,
            regions,
            patches: Vec::new(),
            folded: Vec::new(),
            removed: lay.removed,
            straight,
            surfacing: Surfacing::Charts,
            charts,
            lifts,
            raises,
            edge_length,
        });
    }
    network.assign_bases(spec.basis);
    let patches = patches::build(&mut network, &primitives);
    let folded = folds::folds(&network, &patches, folds::FOLD_CELLS);
    Ok(Envelope {
        frame: LocalFrame::IDENTITY,
        primitives,
        network,
        regions,
        patches,
        folded,
        removed: lay.removed,
        straight,
        surfacing: Surfacing::Paper,
        charts: Vec::new(),
        lifts: Vec::new(),
        raises: Vec::new(),
        edge_length,
    })
}

/// The first face with a point that is not finite, if any (the face of the first such point).
fn non_finite_face(mesh: &PolyMesh) -> Option<usize> {
    let v = mesh.positions.iter().position(|p| !p.is_finite())?;
    Some(
        (0..mesh.num_faces())
            .find(|&f| {
                mesh.face_corners(f)
                    .any(|c| mesh.corner_verts[c] as usize == v)
            })
            .unwrap_or(0),
    )
}

impl Envelope {
    /// The welded tessellation, `k` × `k` quads a patch (the charts' mesh at resolution `k`),
    /// in the scene's coordinates.
    pub fn tessellate(&self, k: usize) -> Result<PolyMesh, EnvelopeError> {
        self.local_tessellation(k, &Progress::default())
            .map(|m| self.to_world(m))
    }

    /// A mesh in local coordinates moved to the scene's.
    fn to_world(&self, mut mesh: PolyMesh) -> PolyMesh {
        if self.frame != LocalFrame::IDENTITY {
            for p in &mut mesh.positions {
                *p = self.frame.to_world(*p);
            }
        }
        mesh
    }

    /// A mesh in the scene's coordinates moved to local ones.
    pub(crate) fn to_local<'a>(&self, mesh: &'a PolyMesh) -> std::borrow::Cow<'a, PolyMesh> {
        if self.frame == LocalFrame::IDENTITY {
            return std::borrow::Cow::Borrowed(mesh);
        }
        let mut m = mesh.clone();
        for p in &mut m.positions {
            *p = self.frame.to_local(*p);
        }
        std::borrow::Cow::Owned(m)
    }

    /// [`Envelope::tessellate`] in local coordinates.
    fn local_tessellation(&self, k: usize, progress: &Progress) -> Result<PolyMesh, EnvelopeError> {
        if k == 0 || k > 256 {
            return Err(EnvelopeError::Resolution(k));
        }
        if self.surfacing == Surfacing::Charts {
            return self.local_chart_mesh(k, progress).map(|(m, _)| m);
        }
        progress.check().map_err(|_| EnvelopeError::Cancelled)?;
        let mesh = tessellate::tessellate(&self.network, &self.patches, k);
        // Never a mesh with a point that is not finite: the patch it came from is named (each
        // patch writes k × k faces in order).
        if let Some(face) = non_finite_face(&mesh) {
            return Err(EnvelopeError::NonFinite {
                patch: face / (k * k),
            });
        }
        Ok(mesh)
    }

    /// The charts' mesh at resolution `k` (about k segments along a primitive's edge) and the
    /// region of each triangle, in the scene's coordinates.
    pub fn chart_mesh(&self, k: usize) -> Result<(PolyMesh, Vec<u32>), EnvelopeError> {
        self.local_chart_mesh(k, &Progress::default())
            .map(|(m, r)| (self.to_world(m), r))
    }

    /// [`Envelope::chart_mesh`] in local coordinates, a unit of `progress` a chart.
    fn local_chart_mesh(
        &self,
        k: usize,
        progress: &Progress,
    ) -> Result<(PolyMesh, Vec<u32>), EnvelopeError> {
        if k == 0 || k > 256 {
            return Err(EnvelopeError::Resolution(k));
        }
        let spacing = self.edge_length / k as f64;
        let (mut mesh, regions) =
            chart::mesh::tessellate(&self.network, &self.charts, spacing, 64 * k, progress)?;
        self.lift(&mut mesh, &regions);
        if let Some(face) = non_finite_face(&mesh) {
            return Err(EnvelopeError::NonFinite {
                patch: regions.get(face).copied().unwrap_or(0) as usize,
            });
        }
        Ok((mesh, regions))
    }

    /// Moves every vertex by the strips' lifts ([`chart::lift`]: each one smooth map of space
    /// about its strip's axis, identity to first order on the silhouette sections; where several
    /// reach a vertex, their displacements weighted by the fourth power of their lengths, so the
    /// largest leads and the order of the strips does not matter), then every vertex of
    /// a raised region by its raise (identity to first order on the region's borders, so
    /// vertices shared with other regions stay put).
    fn lift(&self, mesh: &mut PolyMesh, regions: &[u32]) {
        if self.lifts.is_empty() && self.raises.is_empty() {
            return;
        }
        let bounds: Vec<(DVec3, DVec3)> = self.lifts.iter().map(|l| l.bounds()).collect();
        let moved: Vec<DVec3> = mesh
            .positions
            .par_iter()
            .map(|&x| {
                // Where several lifts reach a point (near a lid's corner), their displacements
                // weighted by |d|⁴: the largest leads, smoothly, and they do not pile up.
                let (mut num, mut den) = (DVec3::ZERO, 0.0);
                for (l, &(lo, hi)) in self.lifts.iter().zip(&bounds) {
                    if x.cmpge(lo).all() && x.cmple(hi).all() {
                        let d = l.apply(x) - x;
                        let w = d.length_squared().powi(2);
                        num += w * d;
                        den += w;
                    }
                }
                if den > 0.0 { x + num / den } else { x }
            })
            .collect();
        mesh.positions = moved;
        let mut raise_of: Vec<Option<usize>> = vec![None; self.network.regions.len()];
        for (k, x) in self.raises.iter().enumerate() {
            raise_of[x.region] = Some(k);
        }
        let mut raised: Vec<Option<usize>> = vec![None; mesh.num_vertices()];
        for (f, &r) in regions.iter().enumerate() {
            if let Some(&Some(k)) = raise_of.get(r as usize) {
                for c in mesh.face_corners(f) {
                    raised[mesh.corner_verts[c] as usize] = Some(k);
                }
            }
        }
        for (p, k) in mesh.positions.iter_mut().zip(raised) {
            if let Some(k) = k {
                let x = &self.raises[k];
                *p = x.apply(&self.charts[x.region], *p);
            }
        }
    }

    /// The tessellation at resolution `k` and the region of each face: the charts' triangles,
    /// or the paper's patches (k × k faces a patch, in order); in the scene's coordinates.
    pub fn mesh(&self, k: usize) -> Result<(PolyMesh, Vec<u32>), EnvelopeError> {
        self.mesh_with(k, &Progress::default())
    }

    /// [`Envelope::mesh`], counting its charts done in `progress` and stopping with
    /// [`EnvelopeError::Cancelled`] at the next chart once it is cancelled (the Envelope tab's
    /// progress bar and Cancel).
    pub fn mesh_with(
        &self,
        k: usize,
        progress: &Progress,
    ) -> Result<(PolyMesh, Vec<u32>), EnvelopeError> {
        self.local_mesh(k, progress)
            .map(|(m, r)| (self.to_world(m), r))
    }

    /// [`Envelope::mesh_with`] in local coordinates.
    pub(crate) fn local_mesh(
        &self,
        k: usize,
        progress: &Progress,
    ) -> Result<(PolyMesh, Vec<u32>), EnvelopeError> {
        if self.surfacing == Surfacing::Charts {
            return self.local_chart_mesh(k, progress);
        }
        let mesh = self.local_tessellation(k, progress)?;
        let regions = (0..mesh.num_faces())
            .map(|f| self.patches.get(f / (k * k)).map_or(0, |p| p.region) as u32)
            .collect();
        Ok((mesh, regions))
    }

    /// The mesh counts of the tessellation at resolution `k`, estimated before it is built (for
    /// the memory guard): the paper's K × K quads a patch, or the charts' mesh at resolution
    /// min(K, 8) (a few milliseconds) scaled by (K/8)², with a quarter to spare.
    pub fn mesh_counts(&self, k: usize) -> crate::memory::Counts {
        let k = k.max(1) as u64;
        if self.surfacing == Surfacing::Paper {
            return crate::memory::tessellation_counts(self.patches.len() as u64, k);
        }
        let k0 = k.min(8);
        let (v0, t0) = self
            .local_chart_mesh(k0 as usize, &Progress::default())
            .map(|(m, _)| (m.num_vertices() as u64, m.num_faces() as u64))
            .unwrap_or((0, 0));
        let scale = |x: u64| (x * k * k / (k0 * k0)) * 5 / 4 + 64;
        let (vertices, triangles) = (scale(v0), scale(t0));
        crate::memory::Counts {
            vertices,
            corners: 3 * triangles,
            loops: triangles,
            faces: triangles,
            edges: 3 * triangles / 2,
        }
    }
}
