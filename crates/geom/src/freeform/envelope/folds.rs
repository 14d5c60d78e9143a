//! Folds of the paper's patches, found patch by patch and named, never mended
//! (docs/algorithms/envelope.md, "The paper's patches").
//!
//! Every patch is sampled on a k × k grid of cells; a cell whose normal `(∂S/∂u) × (∂S/∂v)`
//! (from the cell's four corners) makes more than 90° with the outward normals of the
//! patch's four corners blended bilinearly to the cell's centre is **folded**: the surface
//! there has turned past the tangent planes it spans between. The corners are network
//! vertices, whose normals are the tangent planes every curve through them touches (outward),
//! so the test needs no other part of the surface and costs one grid per patch. A cell that
//! still faces within 90° of the tangent plane the network prescribes along the patch's
//! nearest side (its G1 plane, shared with the patch across), blended towards the corners'
//! normal as the cell lies further in, is excused: a step along a border that climbs steeply
//! between corners whose normals agree stands on edge but has not turned over. The test does
//! not see two distant parts of the surface passing through each other; [`crossings`] of the
//! tessellation does.

use super::network::Network;
use super::patches::EnvelopePatch;
use crate::mesh::PolyMesh;
use glam::DVec3;

/// Cells along each side of a patch that the check samples.
pub const FOLD_CELLS: usize = 8;

/// A folded cell: its patch, the patch's region and the cell's centre (u, v).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fold {
    pub patch: usize,
    pub region: usize,
    pub u: f64,
    pub v: f64,
}

/// The folded cells of `patches` sampled `k` × `k`, patch by patch, in order: those turned
/// past the normals of their patch's corners blended to them **and** past the tangent plane
/// prescribed along their nearest side ([`follows_its_border`]). A cell with a point that is
/// not finite counts as folded.
pub fn folds(net: &Network, patches: &[EnvelopePatch], k: usize) -> Vec<Fold> {
    let k = k.max(1);
    let mut out = Vec::new();
    for (pi, p) in patches.iter().enumerate() {
        cells(net, p, &p.coons.grid(k), k, |c| {
            if c.turn.is_nan() || (c.turn < 0.0 && !follows_its_border(p, &c)) {
                out.push(Fold {
                    patch: pi,
                    region: p.region,
                    u: c.u,
                    v: c.v,
                });
            }
        });
    }
    out
}

/// A cell of a patch's grid, as [`cells`] gives it.
struct GridCell {
    /// Its centre.
    u: f64,
    v: f64,
    /// `∂S/∂u × ∂S/∂v` from the cell's four corners.
    normal: DVec3,
    /// `n`: the patch's corner normals (outward, those of the network's vertices) blended
    /// bilinearly to the centre.
    expected: DVec3,
    /// `(∂S/∂u × ∂S/∂v) · n`.
    turn: f64,
}

/// Every cell of patch `p`'s grid `g` (`k` cells a side), in order.
fn cells(net: &Network, p: &EnvelopePatch, g: &[DVec3], k: usize, mut each: impl FnMut(GridCell)) {
    let kf = k as f64;
    // Corners (0, 0), (1, 0), (1, 1), (0, 1): the starts of sides 0 to 3.
    let n: Vec<DVec3> = p
        .sides
        .iter()
        .map(|s| {
            net.vertex_at(s.curve, s.t0)
                .map_or(DVec3::ZERO, |v| net.vertices[v].normal)
        })
        .collect();
    let at = |i: usize, j: usize| g[i + (k + 1) * j];
    for j in 0..k {
        for i in 0..k {
            let du = at(i + 1, j) - at(i, j) + at(i + 1, j + 1) - at(i, j + 1);
            let dv = at(i, j + 1) - at(i, j) + at(i + 1, j + 1) - at(i + 1, j);
            let (u, v) = ((i as f64 + 0.5) / kf, (j as f64 + 0.5) / kf);
            let expected = n[0] * ((1.0 - u) * (1.0 - v))
                + n[1] * (u * (1.0 - v))
                + n[2] * (u * v)
                + n[3] * ((1.0 - u) * v);
            let normal = du.cross(dv);
            each(GridCell {
                u,
                v,
                normal,
                expected,
                turn: normal.dot(expected),
            });
        }
    }
}

/// Whether a cell turned past its corners' normals blended there still faces the way the
/// network prescribes beside its nearest side (envelope.md, "The paper's
/// patches"): within 90° of that side's unit normal `C′ × X` (its G1 tangent plane, shared with
/// the patch across) at the foot (u or v along it), blended with the corners' unit normal as
/// the cell lies further in, `(1 − 2d)·b + 2d·n` for a cell `d` from the side in the patch's
/// parameters. A cell equally near two sides must follow both. Such a cell follows a border that climbs steeply between corners whose normals agree
/// (a fusion edge of a cone between primitives of unequal sizes at small t): the surface
/// stands on edge there, as its neighbour across does, but has not turned over.
fn follows_its_border(p: &EnvelopePatch, c: &GridCell) -> bool {
    let (u, v) = (c.u, c.v);
    // (distance from the side, the side, the foot's parameter along it)
    let near = [
        (v, 0, u),
        (1.0 - u, 1, v),
        (1.0 - v, 2, 1.0 - u),
        (u, 3, 1.0 - v),
    ];
    let d = near.iter().map(|n| n.0).fold(f64::INFINITY, f64::min);
    d < 0.5
        && near.iter().filter(|n| n.0 == d).all(|&(_, k, s)| {
            let side = &p.coons.sides[k];
            let b = side.d1(s).cross(side.cross(s).0).normalize_or_zero();
            b != DVec3::ZERO
                && c.normal
                    .dot(b * (1.0 - 2.0 * d) + c.expected.normalize_or_zero() * (2.0 * d))
                    > 0.0
        })
}

/// Where a tessellation passes through itself: its pairs of faces that cross
/// ([`crate::analysis::crossings`]), each as the midpoint of the two faces' centroids. It sees
/// what the fold check cannot: a patch folded over within its corners' tangent planes and
/// parts of the surface through each other (docs/algorithms/envelope.md, "Quality report").
pub fn crossings(mesh: &PolyMesh) -> Vec<DVec3> {
    crate::analysis::crossing_points(mesh, &crate::analysis::crossings(mesh))
}
