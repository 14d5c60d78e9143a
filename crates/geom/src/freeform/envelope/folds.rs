//! Folds of an envelope, found patch by patch (docs/algorithms/envelope.md, "Folds, reported").
//!
//! Every patch is sampled on a k × k grid of cells; a cell whose normal `(∂S/∂u) × (∂S/∂v)`
//! (from the cell's four corners) makes more than 90° with the outward normals of the
//! patch's four corners blended bilinearly to the cell's centre is **folded**: the surface
//! there has turned past the tangent planes it spans between. The corners are network
//! vertices, whose normals are the tangent planes every curve through them touches (outward),
//! so the test needs no other part of the surface and costs one grid per patch. The report
//! (and [`folds`]) excuses a cell that still faces within 90° of the tangent plane the network
//! prescribes along the patch's nearest side (its G1 plane, shared with the patch across),
//! blended towards the corners' normal as the cell lies further in: a step along a border that
//! climbs steeply between corners whose normals agree stands on edge but has not turned over
//! (envelope.md, "Folds, reported", *Steps along a border*). The build repairs every cell turned
//! past its corners' normals, steps included ([`grid_folds`], [`folds_past_corners`]). It sees
//! folds that a winding-number test at a step off the face misses (a cell tilted by 95° in a
//! pleat is outside-facing enough to pass that one); it does not see two distant parts of
//! the surface passing through each other, nor a patch folding over within its corners'
//! tangent planes — [`crossings`] of the tessellation does, and [`self_crossings`] of one
//! patch's own grid, which the build runs on every patch (most are cleared at once by
//! `projects_one_to_one`: one to one along their mean normal). The build checks every
//! patch as it makes it (and rescales those that fold or cross, `patches.rs`), so
//! [`super::Envelope::folds`] returns what it found, less the steps ([`reported`]).

use super::network::Network;
use super::patches::EnvelopePatch;
use crate::geometry::outline_meets_itself;
use crate::mesh::PolyMesh;
use glam::{DVec2, DVec3};

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
/// prescribed along their nearest side (the report's test; a step along a border is not a
/// fold, [`follows_its_border`]).
pub fn folds(net: &Network, patches: &[EnvelopePatch], k: usize) -> Vec<Fold> {
    sampled(net, patches, k, Test::Report, |_| true)
}

/// The cells of `patches` sampled `k` × `k` turned past the normals of their patch's corners
/// blended to them, steps along a border included (the build's test, [`grid_folds`]).
pub fn folds_past_corners(net: &Network, patches: &[EnvelopePatch], k: usize) -> Vec<Fold> {
    sampled(net, patches, k, Test::Build, |_| true)
}

/// Of the cells `folded` that the build left turned past their corners' normals
/// ([`grid_folds`], [`FOLD_CELLS`] a side), those the report calls folded ([`folds`]): each
/// patch with such a cell is sampled again.
pub(crate) fn reported(net: &Network, patches: &[EnvelopePatch], folded: &[Fold]) -> Vec<Fold> {
    sampled(net, patches, FOLD_CELLS, Test::Report, |pi| {
        folded.iter().any(|f| f.patch == pi)
    })
}

/// The cells that `test` calls folded of the patches numbered as `wanted` says, each sampled
/// `k` × `k`, patch by patch, in order.
fn sampled(
    net: &Network,
    patches: &[EnvelopePatch],
    k: usize,
    test: Test,
    wanted: impl Fn(usize) -> bool,
) -> Vec<Fold> {
    let k = k.max(1);
    let mut out = Vec::new();
    for (pi, p) in patches.iter().enumerate().filter(|&(pi, _)| wanted(pi)) {
        out.extend(turned_cells(net, p, pi, &p.coons.grid(k), k, test));
    }
    out
}

/// The cells of patch `p` (number `pi`) from its grid `g`, `k` cells a side
/// ([`super::coons::Coons::grid`]), turned past the normals of its corners blended to them:
/// the build's test. It repairs what it can of every such cell, a step along a border
/// included (which it can seldom move: the plane along a border is the network's).
pub(crate) fn grid_folds(
    net: &Network,
    p: &EnvelopePatch,
    pi: usize,
    g: &[DVec3],
    k: usize,
) -> Vec<Fold> {
    turned_cells(net, p, pi, g, k, Test::Build)
}

/// Which cells are called folded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Test {
    /// Turned past the corners' normals blended.
    Build,
    /// Turned past those and past the plane along the nearest side ([`follows_its_border`]).
    Report,
}

/// The cells of patch `p` (number `pi`) from its grid `g`, `k` cells a side, that `test`
/// calls folded.
fn turned_cells(
    net: &Network,
    p: &EnvelopePatch,
    pi: usize,
    g: &[DVec3],
    k: usize,
    test: Test,
) -> Vec<Fold> {
    let mut out = Vec::new();
    cells(net, p, g, k, |c| {
        // A cell with a non-finite point counts as folded (never chosen, always reported).
        let turned = c.turn.is_nan()
            || (c.turn < 0.0 && (test == Test::Build || !follows_its_border(p, &c)));
        if turned {
            out.push(Fold {
                patch: pi,
                region: p.region,
                u: c.u,
                v: c.v,
            });
        }
    });
    out
}

/// The least, over the cells of patch `p`'s grid `g` (`k` cells a side), of
/// `(∂S/∂u × ∂S/∂v) · n / (|∂S/∂u| |∂S/∂v| |n|)` with `n` the outward normal expected there
/// (as [`grid_folds`] takes it): the sine of the cell's corner angle, tilted away from `n`.
/// A patch sound at its samples but with a cell nearly flattened (near 0) can fold over in a
/// strip between them (envelope.md, "Patches through themselves", *Nearly flat cells*); 1 for
/// a grid of square cells facing `n`, and a cell measured as 0/0 (a collapsed side) counts 1.
pub(crate) fn least_sine(net: &Network, p: &EnvelopePatch, g: &[DVec3], k: usize) -> f64 {
    let mut least = 1.0f64;
    cells(net, p, g, k, |c| {
        if c.size > 0.0 && c.turn.is_finite() {
            least = least.min(c.turn / c.size);
        }
    });
    least
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
    /// `|∂S/∂u| |∂S/∂v| |n|`.
    size: f64,
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
                size: du.length() * dv.length() * expected.length(),
            });
        }
    }
}

/// Whether a cell turned past its corners' normals blended there still faces the way the
/// network prescribes beside its nearest side (envelope.md, "Folds, reported", *Steps along a
/// border*): within 90° of that side's unit normal `C′ × X` (its G1 tangent plane, shared with
/// the patch across) at the foot (u or v along it), blended with the corners' unit normal as
/// the cell lies further in, `(1 − 2d)·b + 2d·n` for a cell `d` from the side in the patch's
/// parameters. A cell equally near two sides must follow both; a collapsed side prescribes no
/// plane. Such a cell follows a border that climbs steeply between corners whose normals agree
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
            !side.collapsed
                && b != DVec3::ZERO
                && c.normal
                    .dot(b * (1.0 - 2.0 * d) + c.expected.normalize_or_zero() * (2.0 * d))
                    > 0.0
        })
}

/// Pairs of triangles of patch `p`'s own `k` × `k` grid (each cell cut along its diagonal from
/// (u, v) to (u + 1/k, v + 1/k)) that pass through each other
/// ([`crate::analysis::triangles_cross`]): a patch folded over itself within its corners'
/// tangent planes, which the cell check of [`folds`] does not see ([`grid_crossings`]).
pub fn self_crossings(p: &EnvelopePatch, k: usize) -> usize {
    let k = k.max(1);
    grid_crossings(&p.coons.grid(k), k)
}

/// [`self_crossings`] of a patch's grid `g`, `k` cells a side ([`super::coons::Coons::grid`]):
/// none where the grid is one to one seen along its mean normal ([`projects_one_to_one`], most
/// patches), otherwise [`pairwise_crossings`].
pub(crate) fn grid_crossings(g: &[DVec3], k: usize) -> usize {
    if projects_one_to_one(g, k) {
        0
    } else {
        pairwise_crossings(g, k)
    }
}

/// The pairs of cells of the grid `g` whose boxes in the patch's own frame overlap, then their
/// triangles that share no grid point and pass through each other (those that share one only
/// touch there, or fold, which the cell check sees). The cells are swept along the patch's
/// first side (sorted by where their boxes start), and each triangle's plane is found once; a
/// pair of triangles whose own boxes are apart is not tested further.
fn pairwise_crossings(g: &[DVec3], k: usize) -> usize {
    let idx = |i: usize, j: usize| i + (k + 1) * j;
    // Boxes in the patch's own frame (along its first side, across it, and off it), where a
    // sound patch's cells overlap only their neighbours.
    let (o, x, y) = (g[0], g[idx(k, 0)] - g[0], g[idx(0, k)] - g[0]);
    let n = x.cross(y).normalize_or_zero();
    let e1 = x.normalize_or_zero();
    let e2 = n.cross(e1);
    let local: Vec<DVec3> = g
        .iter()
        .map(|&p| {
            let d = p - o;
            DVec3::new(d.dot(e1), d.dot(e2), d.dot(n))
        })
        .collect();
    // Each cell's two triangles (grid indices), cut along its diagonal from (i, j), with their
    // points, unit normals and boxes in the patch's frame.
    struct Tri {
        v: [usize; 3],
        p: [DVec3; 3],
        n: Option<DVec3>,
        lo: DVec3,
        hi: DVec3,
    }
    let tri = |v: [usize; 3]| {
        let p = v.map(|v| g[v]);
        let q = v.map(|v| local[v]);
        Tri {
            v,
            p,
            n: crate::analysis::plane(&p),
            lo: q[0].min(q[1]).min(q[2]),
            hi: q[0].max(q[1]).max(q[2]),
        }
    };
    let cells: Vec<[Tri; 2]> = (0..k * k)
        .map(|c| {
            let (i, j) = (c % k, c / k);
            let (a, b, cc, d) = (idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1));
            [tri([a, b, cc]), tri([a, cc, d])]
        })
        .collect();
    let boxes: Vec<(DVec3, DVec3)> = cells
        .iter()
        .map(|[t, u]| (t.lo.min(u.lo), t.hi.max(u.hi)))
        .collect();
    let apart = |(la, ha): (DVec3, DVec3), (lb, hb): (DVec3, DVec3)| {
        lb.x > ha.x || la.x > hb.x || lb.y > ha.y || la.y > hb.y || lb.z > ha.z || la.z > hb.z
    };
    // The cells in the order their boxes start along the first side: a cell's box meets only
    // those after it that start before it ends.
    let mut order: Vec<usize> = (0..cells.len()).collect();
    order.sort_by(|&a, &b| boxes[a].0.x.total_cmp(&boxes[b].0.x));
    let mut pairs = 0;
    for (s, &a) in order.iter().enumerate() {
        let ha = boxes[a].1;
        for &b in order[s + 1..].iter().take_while(|&&b| boxes[b].0.x <= ha.x) {
            if apart(boxes[a], boxes[b]) {
                continue;
            }
            for ta in &cells[a] {
                for tb in &cells[b] {
                    if ta.v.iter().all(|v| !tb.v.contains(v))
                        && !apart((ta.lo, ta.hi), (tb.lo, tb.hi))
                    {
                        pairs += usize::from(crate::analysis::planes_cross(ta.p, ta.n, tb.p, tb.n));
                    }
                }
            }
        }
    }
    pairs
}

/// Pairs of triangles, one of grid `a` and one of grid `b` (two patches' grids, `k` cells a
/// side, each cell cut as [`grid_crossings`] cuts it), that pass through each other
/// ([`crate::analysis::triangles_cross`]): patches of one region bulging into each other
/// between the samples. Triangles with a point in common (to 10⁻⁹ of the grids' size: the
/// two sides of a curve they share sample it alike) only touch there, and are skipped.
pub(crate) fn grids_crossing(a: &[DVec3], b: &[DVec3], k: usize) -> usize {
    let (ca, cb) = (Cell::all(a, k), Cell::all(b, k));
    let (ja, jb) = (Cell::joint(&ca), Cell::joint(&cb));
    if !boxes_meet(ja, jb) {
        return 0;
    }
    let same = 1e-9 * (ja.1 - ja.0).max(jb.1 - jb.0).max_element();
    let touch =
        |x: &[DVec3; 3], y: &[DVec3; 3]| x.iter().any(|p| y.iter().any(|q| p.distance(*q) <= same));
    let near_b: Vec<&Cell> = cb.iter().filter(|y| boxes_meet(y.bounds, ja)).collect();
    let mut pairs = 0;
    for x in ca.iter().filter(|x| boxes_meet(x.bounds, jb)) {
        for y in near_b.iter().filter(|y| boxes_meet(x.bounds, y.bounds)) {
            for ta in &x.tris {
                for tb in &y.tris {
                    if !touch(ta, tb) {
                        pairs += usize::from(crate::analysis::triangles_cross(*ta, *tb));
                    }
                }
            }
        }
    }
    pairs
}

/// An axis-aligned box, (least, greatest) corner.
type Bounds = (DVec3, DVec3);

fn boxes_meet(x: Bounds, y: Bounds) -> bool {
    x.0.cmple(y.1).all() && y.0.cmple(x.1).all()
}

/// One cell of a grid as [`grids_crossing`] tests it: its two triangles and its box.
struct Cell {
    tris: [[DVec3; 3]; 2],
    bounds: Bounds,
}

impl Cell {
    /// The cells of grid `g`, `k` a side, cut along the diagonal from (i, j).
    fn all(g: &[DVec3], k: usize) -> Vec<Cell> {
        let idx = |i: usize, j: usize| i + (k + 1) * j;
        (0..k * k)
            .map(|c| {
                let (i, j) = (c % k, c / k);
                let q = [idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)].map(|v| g[v]);
                Cell {
                    tris: [[q[0], q[1], q[2]], [q[0], q[2], q[3]]],
                    bounds: (
                        q[0].min(q[1]).min(q[2]).min(q[3]),
                        q[0].max(q[1]).max(q[2]).max(q[3]),
                    ),
                }
            })
            .collect()
    }

    /// The box of all of `cells`.
    fn joint(cells: &[Cell]) -> Bounds {
        cells.iter().fold((DVec3::MAX, DVec3::MIN), |(lo, hi), c| {
            (lo.min(c.bounds.0), hi.max(c.bounds.1))
        })
    }
}

/// The largest angle (radians) between consecutive segments of the lines of the grid `g` (`k`
/// cells a side), both ways: where it is large, the surface bends much between the samples, and
/// may pass through itself between them.
pub(crate) fn largest_turn(g: &[DVec3], k: usize) -> f64 {
    let idx = |i: usize, j: usize| i + (k + 1) * j;
    let mut worst = 0.0f64;
    for j in 0..=k {
        for i in 1..k {
            let (a, b) = (
                g[idx(i, j)] - g[idx(i - 1, j)],
                g[idx(i + 1, j)] - g[idx(i, j)],
            );
            worst = worst.max(a.angle_between(b));
            let (a, b) = (
                g[idx(j, i)] - g[idx(j, i - 1)],
                g[idx(j, i + 1)] - g[idx(j, i)],
            );
            worst = worst.max(a.angle_between(b));
        }
    }
    worst
}

/// Whether the grid `g` (`k` cells a side, each cut along its diagonal from (i, j) as
/// [`grid_crossings`] cuts it), seen along its mean normal, is one to one: every triangle turns
/// the same way as the mean normal and the outline crosses and touches itself nowhere. A
/// piecewise-linear map of a disk whose triangles all keep their orientation and whose outline
/// is a simple polygon is one to one (the degree of every point inside the outline is 1), so no
/// two of its triangles can pass through each other: the grid is then a graph over that plane.
/// A few µs against the pairwise test's 25; `false` only means "not shown" (a collapsed side, a
/// patch turning past 90°), and the pairwise test decides.
fn projects_one_to_one(g: &[DVec3], k: usize) -> bool {
    let idx = |i: usize, j: usize| i + (k + 1) * j;
    let mut n = DVec3::ZERO;
    for j in 0..k {
        for i in 0..k {
            n += (g[idx(i + 1, j + 1)] - g[idx(i, j)]).cross(g[idx(i, j + 1)] - g[idx(i + 1, j)]);
        }
    }
    let Some(n) = n.try_normalize() else {
        return false;
    };
    let e1 = n.any_orthonormal_vector();
    let e2 = n.cross(e1);
    let flat: Vec<DVec2> = g.iter().map(|p| DVec2::new(p.dot(e1), p.dot(e2))).collect();
    let (lo, hi) = flat.iter().fold((DVec2::MAX, DVec2::MIN), |(lo, hi), &p| {
        (lo.min(p), hi.max(p))
    });
    let size = (hi - lo).max_element();
    // Orientation of (a, b, c): twice the signed area.
    let turn = |a: DVec2, b: DVec2, c: DVec2| (b - a).perp_dot(c - a);
    let least = 1e-12 * size * size;
    for j in 0..k {
        for i in 0..k {
            let (a, b, c, d) = (
                flat[idx(i, j)],
                flat[idx(i + 1, j)],
                flat[idx(i + 1, j + 1)],
                flat[idx(i, j + 1)],
            );
            if !(turn(a, b, c) > least && turn(a, c, d) > least) {
                return false;
            }
        }
    }
    // The outline, counter-clockwise in (u, v): no two segments but neighbours may meet.
    // Turns within `least` of zero count as zero, so a touch or an overlap along one line
    // counts as meeting (only a clear miss is a miss).
    let outline: Vec<DVec2> = (0..k)
        .map(|i| flat[idx(i, 0)])
        .chain((0..k).map(|j| flat[idx(k, j)]))
        .chain((0..k).map(|i| flat[idx(k - i, k)]))
        .chain((0..k).map(|j| flat[idx(0, k - j)]))
        .collect();
    outline_meets_itself(&outline, least).is_none()
}

/// Where a tessellation passes through itself: its pairs of faces that cross
/// ([`crate::analysis::crossings`]), each as the midpoint of the two faces' centroids. It sees
/// what the fold check cannot: a patch folded over within its corners' tangent planes (per-vertex
/// t a thousand times apart on an octahedron did so at 12 quads a side, not at 8, before k was
/// eased into short legs) and parts of the surface through each other in a heap
/// (docs/algorithms/envelope.md, "Folds, reported").
pub fn crossings(mesh: &PolyMesh) -> Vec<DVec3> {
    let centroid = |f: u32| {
        let c = mesh.face_corners(f as usize);
        let n = c.len().max(1) as f64;
        c.map(|c| mesh.positions[mesh.corner_verts[c] as usize])
            .sum::<DVec3>()
            / n
    };
    crate::analysis::crossings(mesh)
        .into_iter()
        .map(|(f, g)| 0.5 * (centroid(f) + centroid(g)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A k × k grid of `f(u, v)`, i + (k + 1)j as `Coons::grid` lists it.
    fn grid(k: usize, f: impl Fn(f64, f64) -> DVec3) -> Vec<DVec3> {
        let kf = k as f64;
        (0..=k)
            .flat_map(|j| (0..=k).map(move |i| (i as f64 / kf, j as f64 / kf)))
            .map(|(u, v)| f(u, v))
            .collect()
    }

    /// The quick test vouches only for grids the pairwise test clears: a bump, a saddle and a
    /// cylinder a third round are one to one seen along their mean normal; a cylinder wrapped
    /// past a full turn (which passes through itself) and a grid with a pleat are not, and the
    /// pairwise test finds the first one's crossings.
    #[test]
    fn a_grid_one_to_one_along_its_mean_normal_has_no_crossing() {
        let k = 8;
        let tau = std::f64::consts::TAU;
        let bump = grid(k, |u, v| {
            DVec3::new(u, v, 0.3 * (u * (1.0 - u) * v * (1.0 - v)))
        });
        let saddle = grid(k, |u, v| DVec3::new(u, v, (u - 0.5) * (v - 0.5)));
        let arc = grid(k, |u, v| {
            let a = u * tau / 3.0;
            DVec3::new(a.sin(), v, -a.cos())
        });
        for (name, g) in [("bump", &bump), ("saddle", &saddle), ("arc", &arc)] {
            assert!(projects_one_to_one(g, k), "{name}");
            assert_eq!(pairwise_crossings(g, k), 0, "{name}");
        }
        // Round 1.2 turns, the radius growing 10 % a turn so that the overlap crosses.
        let wrapped = grid(k, |u, v| {
            let a = u * 1.2 * tau;
            let r = 1.0 + 0.1 * (u - 0.5) + 0.3 * (v - 0.5) * (u - 0.5);
            DVec3::new(r * a.cos(), r * a.sin(), v)
        });
        assert!(!projects_one_to_one(&wrapped, k));
        assert!(pairwise_crossings(&wrapped, k) > 0);
        let pleat = grid(k, |u, v| {
            // The middle column moved past its neighbour: a cell turned over.
            let x = if (u - 0.5).abs() < 1e-9 { 0.7 } else { u };
            DVec3::new(x, v, 0.0)
        });
        assert!(!projects_one_to_one(&pleat, k));
        assert_eq!(grid_crossings(&bump, k), 0);
    }
}
