//! The envelope's welded tessellation (docs/algorithms/envelope.md,
//! "The paper's patches"): K × K quads a patch, conforming where an unsplit region
//! meets split halves.
//!
//! The mesh vertices along a network curve are the union of the K + 1 uniform samples of
//! every patch side on it (parameters equal to 1e-12 merged), evaluated once on the curve
//! itself; network vertices are shared by every curve through them. Each patch keeps its own
//! K + 1 samples as its grid's border row and puts the other side's extra samples into its
//! border cells, which become fans of triangles from the cell's corners inside the patch
//! (`push_border_cell`): every mesh edge is in exactly two faces, so the mesh is closed with
//! no T-junction crack, and no triangle is made of border points alone. A needle's collapsed
//! tip (a curve of one point) gives all its samples the tip's vertex, and the cells there drop
//! the repeated corner (triangles).

use super::network::Network;
use super::patches::EnvelopePatch;
use crate::freeform::envelope::tolerances::TOLERANCES;
use crate::mesh::PolyMesh;
use glam::DVec3;

/// [`TOLERANCES`]`.same_parameter`.
const SAME: f64 = TOLERANCES.same_parameter;

/// Per curve, its mesh vertices by parameter, ascending.
struct CurveSamples {
    params: Vec<Vec<(f64, u32)>>,
}

impl CurveSamples {
    fn id(&self, curve: usize, tau: f64) -> u32 {
        let p = &self.params[curve];
        let i = p.partition_point(|&(t, _)| t < tau - SAME);
        debug_assert!(i < p.len() && (p[i].0 - tau).abs() <= SAME);
        p[i.min(p.len() - 1)].1
    }

    /// Appends the vertices strictly between τ = a and τ = b to `out`, in order from a to b.
    fn push_between(&self, out: &mut Vec<u32>, curve: usize, a: f64, b: f64) {
        let (lo, hi) = (a.min(b), a.max(b));
        let p = &self.params[curve];
        let from = p.partition_point(|&(t, _)| t <= lo + SAME);
        let to = p.partition_point(|&(t, _)| t < hi - SAME).max(from);
        let inside = p[from..to].iter().map(|&(_, id)| id);
        if a > b {
            out.extend(inside.rev());
        } else {
            out.extend(inside);
        }
    }
}

/// The tessellation of `patches` over `net` with `k` quads along each side of a patch.
pub fn tessellate(net: &Network, patches: &[EnvelopePatch], k: usize) -> PolyMesh {
    let kf = k as f64;
    let mut positions: Vec<DVec3> = net.vertices.iter().map(|v| v.position).collect();
    let mut wanted: Vec<Vec<f64>> = vec![Vec::new(); net.curves.len()];
    for p in patches {
        for (side, s) in p.sides.iter().enumerate() {
            wanted[s.curve].extend((0..=k).map(|j| p.tau(side, j as f64 / kf)));
        }
    }
    let mut params = Vec::with_capacity(net.curves.len());
    for (c, mut w) in wanted.into_iter().enumerate() {
        let curve = &net.curves[c];
        w.extend(curve.pins.iter().map(|&(t, _)| t));
        w.sort_by(f64::total_cmp);
        w.dedup_by(|a, b| (*a - *b).abs() <= SAME);
        let list: Vec<(f64, u32)> = w
            .into_iter()
            .map(|t| {
                let id = match net.vertex_at(c, t) {
                    Some(v) => v as u32,
                    // A needle's collapsed tip: every sample is its vertex.
                    None if curve.is_point() => curve.ends[0] as u32,
                    None => {
                        positions.push(curve.bezier.eval(t));
                        (positions.len() - 1) as u32
                    }
                };
                (t, id)
            })
            .collect();
        params.push(list);
    }
    let samples = CurveSamples { params };
    // The patches' grids (half the work) on every core; the welding after them runs in patch
    // order, so the mesh is the one a single thread makes.
    let grids: Vec<Vec<DVec3>> = {
        use rayon::prelude::*;
        patches.par_iter().map(|p| p.coons.grid(k)).collect()
    };
    let mut mesh = PolyMesh::new();
    let mut poly = Vec::with_capacity(4 * k);
    let mut tris = Vec::with_capacity(4 * k);
    for (p, inner) in patches.iter().zip(grids) {
        let n = k + 1;
        let mut grid = vec![0u32; n * n];
        let at = |i: usize, j: usize| i + n * j;
        for i in 0..n {
            for j in 0..n {
                let side_s = if j == 0 {
                    Some((0, i as f64 / kf))
                } else if i == k {
                    Some((1, j as f64 / kf))
                } else if j == k {
                    Some((2, (k - i) as f64 / kf))
                } else if i == 0 {
                    Some((3, (k - j) as f64 / kf))
                } else {
                    None
                };
                grid[at(i, j)] = match side_s {
                    Some((side, s)) => samples.id(p.sides[side].curve, p.tau(side, s)),
                    None => {
                        positions.push(inner[at(i, j)]);
                        (positions.len() - 1) as u32
                    }
                };
            }
        }
        for j in 0..k {
            for i in 0..k {
                let corners = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
                // The border each cell edge lies on, with its side parameters from → to.
                let on_border = |e: usize| -> Option<(usize, f64, f64)> {
                    match e {
                        0 if j == 0 => Some((0, i as f64 / kf, (i + 1) as f64 / kf)),
                        1 if i + 1 == k => Some((1, j as f64 / kf, (j + 1) as f64 / kf)),
                        2 if j + 1 == k => Some((2, (k - i - 1) as f64 / kf, (k - i) as f64 / kf)),
                        3 if i == 0 => Some((3, (k - j - 1) as f64 / kf, (k - j) as f64 / kf)),
                        _ => None,
                    }
                };
                poly.clear();
                let mut inner = [None; 2];
                for (e, &(ci, cj)) in corners.iter().enumerate() {
                    if ci > 0 && ci < k && cj > 0 && cj < k {
                        inner[usize::from(inner[0].is_some())] = Some(grid[at(ci, cj)]);
                    }
                    poly.push(grid[at(ci, cj)]);
                    if let Some((side, a, b)) = on_border(e) {
                        let (ta, tb) = (p.tau(side, a), p.tau(side, b));
                        samples.push_between(&mut poly, p.sides[side].curve, ta, tb);
                    }
                }
                // Cells at a collapsed side lose their repeated corner (triangles).
                poly.dedup();
                if poly.len() > 1 && poly[0] == poly[poly.len() - 1] {
                    poly.pop();
                }
                if poly.len() > 4 && inner[0].is_some() {
                    push_border_cell(&mut mesh, &positions, &poly, inner, &mut tris);
                } else if poly.len() >= 3 {
                    mesh.push_polygon(&poly);
                }
            }
        }
    }
    mesh.positions = positions;
    mesh
}

/// A border cell with the other side's samples on its border (`poly`, counter-clockwise, at
/// least five points), as triangles that each hold a grid point inside the patch (`inner`: one
/// or two of the cell's corners): a fan from the inner corner, or with two, a fan from each
/// over its half of the border run and the triangle joining them at the run's point nearest
/// its middle. Left as one polygon, the cell's triangles were whatever the renderer's ear
/// clipping found in the cell's mean plane, and it took ears of three neighbouring border
/// points: a sliver in the border curve's osculating plane, which can stand across the
/// surface (a fusion strip's first row "through" the face beside it, heap 300332 at t = 3), or
/// of two samples a ten-millionth apart, whose normal is noise (heaps 300013 and 600210 at
/// t = 0.16, where a T-point's piece of a curve samples it almost where the whole curve does).
fn push_border_cell(
    mesh: &mut PolyMesh,
    positions: &[DVec3],
    poly: &[u32],
    inner: [Option<u32>; 2],
    tris: &mut Vec<[u32; 3]>,
) {
    let n = poly.len();
    let is_inner = |v: u32| inner.contains(&Some(v));
    // Start at the inner corner the border run follows: poly = a, p₀, …, p_m [, b].
    let Some(start) = (0..n).find(|&i| is_inner(poly[i]) && !is_inner(poly[(i + 1) % n])) else {
        mesh.push_polygon(poly);
        return;
    };
    let at = |i: usize| poly[(start + i) % n];
    let a = at(0);
    let b = is_inner(at(n - 1)).then(|| at(n - 1));
    let run: Vec<u32> = (1..n).map(at).take_while(|&v| !is_inner(v)).collect();
    tris.clear();
    match b {
        None => tris.extend(run.windows(2).map(|w| [a, w[0], w[1]])),
        Some(b) => {
            let pos = |v: u32| positions[v as usize];
            let middle = (pos(run[0]) + pos(run[run.len() - 1])) * 0.5;
            let mid = (1..run.len() - 1)
                .min_by(|&i, &j| {
                    pos(run[i])
                        .distance_squared(middle)
                        .total_cmp(&pos(run[j]).distance_squared(middle))
                })
                .unwrap_or(0);
            tris.extend(run[..=mid].windows(2).map(|w| [a, w[0], w[1]]));
            tris.push([a, run[mid], b]);
            tris.extend(run[mid..].windows(2).map(|w| [w[0], w[1], b]));
        }
    }
    for t in tris.iter() {
        mesh.push_polygon(t);
    }
}
