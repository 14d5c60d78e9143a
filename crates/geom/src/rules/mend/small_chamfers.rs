//! [`super::Mend::SmallChamfers`] (docs/algorithms/cylindrical.md, "Small chamfers"): where new
//! faces are still flipped after the fold guard ([`super::fold_guard`]) and the untangling
//! ([`super::untangle`]) — or, with none flipped, a crossing search of the stage found faces
//! through each other ([`super::crossings`]) — the points around the parent vertices of those
//! faces give up the rule's points there for a small chamfer. Every corner c at
//! such a vertex v takes the point
//!
//! ```text
//! p_c = v + l_v · b_c,   b_c = unit bisector of the corner's angle, into its face, in its plane,
//! l_v = min(⅒ of the shortest edge at v, the shortest offset |p − v| the rule gave there) / 2ʰ
//! ```
//!
//! — the angle-bisector rule of seed 000 §2.3 with one short l for the whole vertex (where
//! sixteen rounds of it do not mend the step, they are tried once more with ⅒ of the
//! narrowest width `4·area/perimeter` of the faces at v in the minimum too: a sliver narrower
//! than its edges turns over under any chamfer wider than itself). Where the
//! parent is flat enough at v for its corners' sectors to lie in order round the vertex normal,
//! the VERTEX-face's points lie in that order (it cannot turn over), the EDGE-faces are thin
//! strips on their edges' own sides and the FACE-faces keep their faces' orientation, whatever
//! the rounding wanted there. The vertices of faces still flipped join, and so do those of
//! faces with a moved point that pass through another ([`crate::analysis::crossings_of`],
//! which the step's check cannot see); h counts how often a vertex has been among them;
//! sixteen rounds at most, judged on the whole step's check. Kept only when no new face is left
//! flipped, no more are degenerate than before and no face with a moved point passes through
//! another (else nothing moves, and the rounding's flipped faces are the report); the step
//! reports how many vertices took it. It cannot mend a parent that is already pleated at v (a
//! face turned more than 90° from the sum of the normals round it), where no small chamfer is
//! sound; a Catmull–Clark level that pleats says so itself (`step::primal_flipped`).
use crate::mesh::PolyMesh;
use crate::topology::Topology;
use glam::DVec3;

/// The unit bisector of corner `c` into its face, in the face's plane (`vsum`, the normal sum
/// at its vertex, for a face of no area). The face's interior lies to the left of its loop's
/// outgoing edge seen along the normal, holes included, so the bisector of a reflex corner is
/// turned round and that of a straight one is that left direction.
fn bisector(mesh: &PolyMesh, topo: &Topology, normals: &[DVec3], vsum: DVec3, c: usize) -> DVec3 {
    let f = topo.corner_face(c) as usize;
    let n = if normals[f] == DVec3::ZERO {
        vsum
    } else {
        normals[f]
    }
    .normalize_or_zero();
    let at = |c: u32| mesh.positions[mesh.corner_verts[c as usize] as usize];
    let v = at(c as u32);
    // The edges' directions in the face's plane: at a nearly straight corner of a face that is
    // not flat their sum would otherwise point along the normal, off the face.
    let in_plane = |w: DVec3| (w - n * w.dot(n)).normalize_or_zero();
    let (e1, e2) = (
        in_plane(at(topo.prev(c)) - v),
        in_plane(at(topo.next(c)) - v),
    );
    let left = n.cross(e2).normalize_or_zero();
    let sum = e1 + e2;
    if sum.length() < 1e-9 {
        return left;
    }
    let b = sum.normalize();
    if b.dot(left) < 0.0 { -b } else { b }
}

/// How wide face `f` is: four times its area over its perimeter (a strip's or a sliver's
/// width, a square's side). A sliver whose edges are long gets an l to suit its width, else
/// its small chamfer, wider than the face, turns it over.
fn width(mesh: &PolyMesh, f: usize) -> f64 {
    let perimeter = crate::geometry::face_perimeter(mesh, f);
    if perimeter > 0.0 {
        4.0 * crate::geometry::face_normal_raw(mesh, f).length() / perimeter
    } else {
        // A face collapsed to a point bounds nothing.
        f64::INFINITY
    }
}

/// The new faces with a point moved round `vertices` (the child's vertex c is the parent's
/// corner c).
fn moved_faces(mesh: &PolyMesh, child: &PolyMesh, vertices: &[usize]) -> Vec<u32> {
    let mut moved = vec![false; mesh.num_vertices()];
    for &v in vertices {
        moved[v] = true;
    }
    (0..child.num_faces() as u32)
        .filter(|&f| {
            child
                .face_corners(f as usize)
                .any(|c| moved[mesh.corner_verts[child.corner_verts[c] as usize] as usize])
        })
        .collect()
}

/// The vertices taking small chamfers and how often each has been among those of faces still
/// flipped.
struct Round {
    halvings: Vec<i32>,
    member: Vec<bool>,
    list: Vec<usize>,
}

impl Round {
    /// The parent vertices of the new `faces` join; those already in halve their l.
    fn join(&mut self, mesh: &PolyMesh, child: &PolyMesh, faces: &[u32]) {
        let mut seen: Vec<usize> = faces
            .iter()
            .flat_map(|&f| child.face_corners(f as usize))
            .map(|c| mesh.corner_verts[child.corner_verts[c] as usize] as usize)
            .collect();
        seen.sort_unstable();
        seen.dedup();
        for v in seen {
            if self.member[v] {
                self.halvings[v] += 1;
            } else {
                self.member[v] = true;
                self.list.push(v);
            }
        }
    }
}

/// Moves the points of `child` (its vertex c is the parent's corner c) round the parent
/// vertices of the `flipped` new faces to small chamfers until `check` (the new faces
/// flipped, and how many are degenerate) finds none flipped and no more degenerate than
/// `degenerate`; returns how many parent vertices took one, or 0 with `child` unchanged.
/// Where the rounds run out, they are tried once more with each vertex's first l also
/// bounded by a tenth of the faces' widths round it ([`width`]): a sliver with long edges
/// turns over under a chamfer wider than itself at every halving the rounds allow.
pub(super) fn retreat(
    mesh: &PolyMesh,
    topo: &Topology,
    normals: &[DVec3],
    child: &mut PolyMesh,
    (flipped, degenerate): (&[u32], usize),
    options: &super::MendOptions,
    mut check: impl FnMut(&PolyMesh) -> (Vec<u32>, usize),
) -> usize {
    let vsum = crate::geometry::vertex_normal_sums(mesh, topo, normals);
    let original = child.positions.clone();
    for by_width in [false, true] {
        let mut round = Round {
            halvings: vec![0; mesh.num_vertices()],
            member: vec![false; mesh.num_vertices()],
            list: Vec::new(),
        };
        round.join(mesh, child, flipped);
        for _ in 0..options.small_chamfer_rounds {
            for &v in &round.list {
                let p = mesh.positions[v];
                let l = topo
                    .corners_around(v)
                    .map(|c| {
                        let w = mesh.positions
                            [mesh.corner_verts[topo.next(c as usize) as usize] as usize];
                        let mut room = p.distance(w);
                        if by_width {
                            room = room.min(width(mesh, topo.corner_face(c as usize) as usize));
                        }
                        (options.small_chamfer_share * room).min(original[c as usize].distance(p))
                    })
                    .fold(f64::INFINITY, f64::min)
                    * 0.5f64.powi(round.halvings[v].min(60));
                for c in topo.corners_around(v).map(|c| c as usize) {
                    child.positions[c] = p + bisector(mesh, topo, normals, vsum[v], c) * l;
                }
            }
            let (mut left, tiny) = check(child);
            if left.is_empty() {
                if tiny > degenerate {
                    // Faces of no area (an l halved to nothing on a sliver): the rounding's
                    // flipped faces are the honest report, not these.
                    break;
                }
                // Faces facing outward that pass through others (the step's check cannot see
                // them) are treated as flipped ones: their vertices join, or halve their l.
                let crossing = crate::analysis::crossings_of(
                    child,
                    &moved_faces(mesh, child, &round.list),
                    None,
                );
                if crossing.is_empty() {
                    return round.list.len();
                }
                left = crate::analysis::crossing_faces(&crossing);
            }
            round.join(mesh, child, &left);
        }
        child.positions.copy_from_slice(&original);
    }
    0
}
