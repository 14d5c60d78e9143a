//! The quality report of an envelope's mesh as written (docs/algorithms/envelope.md,
//! "Quality report"): what a designer would see, measured on the triangles themselves.
//!
//! - the smallest and largest triangle angles (needles and caps);
//! - the largest normal turn between two triangles sharing an edge, inside a region and
//!   across the network's curves (a slit or ridge shows as a turn that does not fall with the
//!   resolution; a smooth surface's falls like 1/K);
//! - open edges (the mesh is closed when there are none), inward triangles (facing against the
//!   chart's direction: never for a graph);
//! - per primitive, the enclosure margin: the least signed distance (inside positive, as a
//!   share of its radius) of points on its faces, edges and vertices from the mesh, inside
//!   decided by the parity of a ray's crossings ([`crate::analysis::Inside`]), the
//!   distance by the triangles near the point on a grid, the search widened until the nearest
//!   found lies within it: about a point's neighbourhood rather than every triangle.

use super::Chart;
use crate::freeform::envelope::primitive::Primitive;
use crate::geometry::point_triangle_distance;
use crate::mesh::PolyMesh;
use glam::DVec3;
use std::collections::HashMap;

/// Enclosure margins are measured up to this share of a primitive's radius: a primitive
/// further inside the surface reads this (one swallowed deep inside a heap of thousands would
/// otherwise search most of the mesh for each of its points).
pub const MARGIN_CAP: f64 = 1.0;

/// The enclosure margins are measured up to this many triangles.
pub const ENCLOSURE_CHECK_FACES: usize = 1_000_000;

/// The report.
#[derive(Debug, Clone, PartialEq)]
pub struct Quality {
    pub triangles: usize,
    /// Degrees.
    pub smallest_angle: f64,
    /// Degrees.
    pub largest_angle: f64,
    /// Largest normal turn (degrees) between neighbouring triangles of one region, and that
    /// region.
    pub largest_turn: (f64, usize),
    /// Largest normal turn (degrees) between neighbouring triangles across a region border.
    pub border_turn: f64,
    /// Largest angle (degrees) at a border vertex between the vertex normals the two regions'
    /// own triangles give it (area-weighted): the mesh's G1 measure, which falls like 1/K on a
    /// G1 surface and stays where there is a crease.
    pub border_gap: f64,
    pub open_edges: usize,
    pub inward: usize,
    /// Per primitive of the scene: the enclosure margin (share of r; negative: a point of the
    /// primitive lies outside by that much). Empty when not measured (over
    /// [`ENCLOSURE_CHECK_FACES`] triangles).
    pub enclosure: Vec<f64>,
}

fn tri(mesh: &PolyMesh, f: usize) -> [u32; 3] {
    let c = mesh.face_corners(f);
    [
        mesh.corner_verts[c.start],
        mesh.corner_verts[c.start + 1],
        mesh.corner_verts[c.start + 2],
    ]
}

fn angle(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b)).to_degrees()
}

/// The report of triangle mesh `mesh` whose triangle f lies on region `regions[f]` of
/// `charts` (indexed by region), enclosing `prims`.
pub fn quality(mesh: &PolyMesh, regions: &[u32], charts: &[Chart], prims: &[Primitive]) -> Quality {
    quality_with(mesh, regions, prims, |r, x| {
        let ch = charts.get(r as usize)?;
        ch.frame.chart(x).map(|(c, _)| ch.frame.direction(c))
    })
}

/// The report of triangle mesh `mesh` whose triangle f lies on region `regions[f]`; a triangle
/// at point x of region r faces inwards where its normal is against `direction(r, x)` (`None`:
/// not judged).
pub fn quality_with(
    mesh: &PolyMesh,
    regions: &[u32],
    prims: &[Primitive],
    direction: impl Fn(u32, DVec3) -> Option<DVec3>,
) -> Quality {
    let nf = mesh.num_faces();
    let p = &mesh.positions;
    let mut normals = Vec::with_capacity(nf);
    let (mut smallest, mut largest) = (180.0f64, 0.0f64);
    let mut inward = 0;
    for (f, &region) in regions.iter().enumerate().take(nf) {
        let [a, b, c] = tri(mesh, f).map(|i| p[i as usize]);
        for (x, y, z) in [(a, b, c), (b, c, a), (c, a, b)] {
            let t = angle(y - x, z - x);
            smallest = smallest.min(t);
            largest = largest.max(t);
        }
        let n = (b - a).cross(c - a);
        if let Some(dir) = direction(region, (a + b + c) / 3.0)
            && n.dot(dir) <= 0.0
        {
            inward += 1;
        }
        normals.push(n.normalize_or_zero());
    }
    let mut edges: HashMap<(u32, u32), Vec<usize>> = HashMap::with_capacity(3 * nf);
    for f in 0..nf {
        let t = tri(mesh, f);
        for k in 0..3 {
            let (u, v) = (t[k], t[(k + 1) % 3]);
            edges.entry((u.min(v), u.max(v))).or_default().push(f);
        }
    }
    let mut open = 0;
    let mut turn = (0.0f64, 0usize);
    let mut border = 0.0f64;
    for fs in edges.values() {
        if fs.len() != 2 {
            open += 1;
            continue;
        }
        let t = angle(normals[fs[0]], normals[fs[1]]);
        if regions[fs[0]] == regions[fs[1]] {
            if t > turn.0 {
                turn = (t, regions[fs[0]] as usize);
            }
        } else {
            border = border.max(t);
        }
    }
    // Vertex normals per (vertex, region), area-weighted.
    let mut vn: HashMap<(u32, u32), DVec3> = HashMap::new();
    for (f, &region) in regions.iter().enumerate().take(nf) {
        let t = tri(mesh, f);
        let [a, b, c] = t.map(|i| p[i as usize]);
        let n = (b - a).cross(c - a);
        for v in t {
            *vn.entry((v, region)).or_default() += n;
        }
    }
    let mut per_vertex: HashMap<u32, Vec<DVec3>> = HashMap::new();
    for (&(v, _), n) in &vn {
        per_vertex.entry(v).or_default().push(*n);
    }
    let gap = per_vertex
        .values()
        .filter(|ns| ns.len() > 1)
        .flat_map(|ns| {
            ns.iter()
                .enumerate()
                .flat_map(move |(i, a)| ns[i + 1..].iter().map(move |b| angle(*a, *b)))
        })
        .fold(0.0f64, f64::max);
    let enclosure = if nf <= ENCLOSURE_CHECK_FACES {
        margins(mesh, prims)
    } else {
        Vec::new()
    };
    Quality {
        triangles: nf,
        smallest_angle: smallest,
        largest_angle: largest,
        largest_turn: turn,
        border_turn: border,
        border_gap: gap,
        open_edges: open,
        inward,
        enclosure,
    }
}

/// Points on a primitive: vertices, edge midpoints, face centres and the points halfway from
/// each face centre to its corners, drawn a hair (10⁻⁹ r) towards the centre.
fn primitive_points(pr: &Primitive) -> Vec<DVec3> {
    let mut out: Vec<DVec3> = pr.vertices.clone();
    for f in &pr.faces {
        let c = f.iter().map(|&i| pr.vertices[i]).sum::<DVec3>() / f.len() as f64;
        out.push(c);
        for k in 0..f.len() {
            let (a, b) = (pr.vertices[f[k]], pr.vertices[f[(k + 1) % f.len()]]);
            if f[k] < f[(k + 1) % f.len()] {
                out.push(0.5 * (a + b));
            }
            out.push(0.5 * (a + c));
        }
    }
    out.into_iter()
        .map(|x| pr.centre + (1.0 - 1e-9) * (x - pr.centre))
        .collect()
}

/// The enclosure margin of every primitive (share of its r; negative when a point lies
/// outside), on all cores.
fn margins(mesh: &PolyMesh, prims: &[Primitive]) -> Vec<f64> {
    use rayon::prelude::*;
    let inside = crate::analysis::Inside::new(mesh);
    let grid = crate::analysis::face_grid::FaceGrid::new(mesh);
    let ((lo, hi), whole) = (mesh.bbox(), mesh.bbox_diagonal());
    debug_assert!(whole.is_finite());
    // The distance from q to the mesh when it is under `most` (else at least `most`): the
    // triangles whose boxes come within a reach of q, the reach widened until the nearest lies
    // within it. A face not visited has its box, so itself, further than the reach.
    let distance = |q: DVec3, start: f64, most: f64| {
        let mut reach = start.min(most);
        loop {
            let mut d = f64::INFINITY;
            let r = DVec3::splat(reach);
            grid.for_each_overlapping((q - r, q + r), |f| {
                let [a, b, c] = tri(mesh, f).map(|i| mesh.positions[i as usize]);
                d = d.min(point_triangle_distance(q, a, b, c));
            });
            if d <= reach || reach >= most {
                return d.min(most);
            }
            reach = (4.0 * reach).min(most);
        }
    };
    prims
        .par_iter()
        .map(|pr| {
            let r = pr.radius;
            let mut worst = f64::INFINITY;
            for q in primitive_points(pr) {
                // A point inside matters only when it is nearer the surface than the worst so
                // far and than one radius (margins are measured up to 1); one outside always
                // does.
                let m = if inside.contains(q) {
                    distance(q, 0.05 * r, worst.min(MARGIN_CAP) * r) / r
                } else {
                    // No point of the mesh is further than this.
                    let far = whole + q.distance(q.clamp(lo, hi));
                    -distance(q, 0.05 * r, far) / r
                };
                worst = worst.min(m);
            }
            worst
        })
        .collect()
}

impl Quality {
    /// The least enclosure margin over the primitives and the primitive it belongs to.
    pub fn worst_enclosure(&self) -> Option<(usize, f64)> {
        self.enclosure
            .iter()
            .copied()
            .enumerate()
            .min_by(|a, b| a.1.total_cmp(&b.1))
    }

    /// The report in one line of `key=value` words.
    pub fn summary(&self) -> String {
        let enclosure = self
            .worst_enclosure()
            .map_or("unchecked".to_string(), |(_, m)| format!("{m:.3e}"));
        format!(
            "triangles={} smallest_angle={:.2}° largest_angle={:.2}° largest_turn={:.2}° (region {}) border_turn={:.2}° border_gap={:.2}° inward={} open_edges={} enclosure={}",
            self.triangles,
            self.smallest_angle,
            self.largest_angle,
            self.largest_turn.0,
            self.largest_turn.1,
            self.border_turn,
            self.border_gap,
            self.inward,
            self.open_edges,
            enclosure
        )
    }

    /// The warning for primitives not enclosed (a point more than 10⁻⁶ r outside): each by
    /// number (the first eight), those in `swallowed` (left out of the network) marked so,
    /// and the worst.
    pub fn enclosure_warning(&self, swallowed: &[usize]) -> Option<String> {
        let out: Vec<usize> = (0..self.enclosure.len())
            .filter(|&i| self.enclosure[i] < -1e-6)
            .collect();
        let (worst, m) = self.worst_enclosure().filter(|w| w.1 < -1e-6)?;
        let mut names: Vec<String> = out
            .iter()
            .take(8)
            .map(|&i| match swallowed.contains(&i) {
                true => format!("{i} (swallowed)"),
                false => i.to_string(),
            })
            .collect();
        if out.len() > 8 {
            names.push(format!("and {} more", out.len() - 8));
        }
        Some(format!(
            "{} primitive(s) not wholly inside the surface: {}; primitive {worst} reaches {:.3} r outside (a corner cut off by the silhouette plane through a centre, seed 004 §5.1, that no strip's lift or raise reaches: past the partner's centre plane, near a lid's corner, or with the paper's cut: envelope.md, \"Enclosure\"); primitives further apart or a t nearer 1 usually clear it",
            out.len(),
            names.join(", "),
            -m
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every primitive left outside is named (eight, then a count), the swallowed ones marked,
    /// the worst given with its distance; none when all are inside.
    #[test]
    fn the_enclosure_warning_names_each_primitive_out() {
        let mut q = Quality {
            triangles: 1,
            smallest_angle: 60.0,
            largest_angle: 60.0,
            largest_turn: (0.0, 0),
            border_turn: 0.0,
            border_gap: 0.0,
            open_edges: 0,
            inward: 0,
            enclosure: vec![0.2, -0.01, 0.3, -0.05, 1.0],
        };
        let w = q.enclosure_warning(&[3]).expect("two out");
        assert!(w.starts_with("2 primitive(s)"), "{w}");
        assert!(w.contains(": 1, 3 (swallowed);"), "{w}");
        assert!(w.contains("primitive 3 reaches 0.050 r outside"), "{w}");
        q.enclosure = (0..11).map(|i| -0.001 * (i + 1) as f64).collect();
        let w = q.enclosure_warning(&[]).expect("all out");
        assert!(w.contains("0, 1, 2, 3, 4, 5, 6, 7, and 3 more"), "{w}");
        q.enclosure = vec![0.0, 0.5];
        assert_eq!(q.enclosure_warning(&[0]), None);
    }
}
