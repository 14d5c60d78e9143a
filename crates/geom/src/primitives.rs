//! Simple solids built in code: boxes, prisms with holes, the paper's tripod, tori.
//!
//! The bundled assets (`assets/*.obj`, `*.prism.json`) are written from these builders, and
//! the benchmarks use the torus. Every solid is closed and oriented outwards
//! (docs/algorithms/conventions.md).

use crate::mesh::PolyMesh;
use glam::{DVec2, DVec3};

/// An axis-aligned box from `lo` to `hi` (8 vertices, 6 quads).
pub fn cuboid(lo: DVec3, hi: DVec3) -> PolyMesh {
    extrude(
        &[
            DVec2::new(lo.x, lo.y),
            DVec2::new(hi.x, lo.y),
            DVec2::new(hi.x, hi.y),
            DVec2::new(lo.x, hi.y),
        ],
        &[],
        lo.z,
        hi.z,
    )
}

/// Extrudes a planar region along z from `z0` to `z1`. `outer` runs counter-clockwise,
/// each hole clockwise (seen from +z); the top and bottom faces keep the holes.
pub fn extrude(outer: &[DVec2], holes: &[Vec<DVec2>], z0: f64, z1: f64) -> PolyMesh {
    let mut rings: Vec<&[DVec2]> = vec![outer];
    rings.extend(holes.iter().map(|h| h.as_slice()));
    let total: usize = rings.iter().map(|r| r.len()).sum();
    let mut m = PolyMesh::new();
    let mut starts = Vec::new();
    for r in &rings {
        starts.push(m.positions.len() as u32);
        m.positions
            .extend(r.iter().map(|p| DVec3::new(p.x, p.y, z0)));
    }
    for r in &rings {
        m.positions
            .extend(r.iter().map(|p| DVec3::new(p.x, p.y, z1)));
    }
    let top = total as u32;
    // Bottom: every loop reversed (normal -z).
    let bottom: Vec<Vec<u32>> = rings
        .iter()
        .zip(&starts)
        .map(|(r, &s)| (0..r.len() as u32).rev().map(|i| s + i).collect())
        .collect();
    let refs: Vec<&[u32]> = bottom.iter().map(|l| l.as_slice()).collect();
    m.push_face(&refs);
    let upper: Vec<Vec<u32>> = rings
        .iter()
        .zip(&starts)
        .map(|(r, &s)| (0..r.len() as u32).map(|i| top + s + i).collect())
        .collect();
    let refs: Vec<&[u32]> = upper.iter().map(|l| l.as_slice()).collect();
    m.push_face(&refs);
    for (r, &s) in rings.iter().zip(&starts) {
        let n = r.len() as u32;
        for i in 0..n {
            let j = (i + 1) % n;
            m.push_polygon(&[s + i, s + j, top + s + j, top + s + i]);
        }
    }
    m
}

/// The regular `n`-gon of circumradius `radius` around the origin, counter-clockwise, its
/// first vertex on +x.
pub fn regular_polygon(n: u32, radius: f64) -> Vec<DVec2> {
    (0..n)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / n as f64;
            radius * DVec2::new(t.cos(), t.sin())
        })
        .collect()
}

/// A star of `points` tips at `outer` and notches at `inner` around the origin,
/// counter-clockwise, its first tip on +y.
pub fn star_polygon(points: u32, outer: f64, inner: f64) -> Vec<DVec2> {
    (0..2 * points)
        .map(|k| {
            let t = std::f64::consts::FRAC_PI_2 + std::f64::consts::PI * k as f64 / points as f64;
            let r = if k % 2 == 0 { outer } else { inner };
            r * DVec2::new(t.cos(), t.sin())
        })
        .collect()
}

/// A right prism over the regular `n`-gon of circumradius `radius`, from z = 0 to `height`.
pub fn ngon_prism(n: u32, radius: f64, height: f64) -> PolyMesh {
    extrude(&regular_polygon(n, radius), &[], 0.0, height)
}

/// A right pyramid over the regular `n`-gon of circumradius `radius` at z = 0, apex at
/// (0, 0, `height`).
pub fn pyramid(n: u32, radius: f64, height: f64) -> PolyMesh {
    let mut positions: Vec<DVec3> = regular_polygon(n, radius)
        .iter()
        .map(|p| DVec3::new(p.x, p.y, 0.0))
        .collect();
    positions.push(DVec3::new(0.0, 0.0, height));
    let apex = n;
    let mut faces = vec![(0..n).rev().collect::<Vec<u32>>()];
    faces.extend((0..n).map(|i| vec![i, (i + 1) % n, apex]));
    PolyMesh::from_polygons(positions, &faces)
}

/// The regular tetrahedron with vertices at alternate corners of the cube [−1, 1]³.
pub fn tetrahedron() -> PolyMesh {
    let p = vec![
        DVec3::new(1.0, 1.0, 1.0),
        DVec3::new(1.0, -1.0, -1.0),
        DVec3::new(-1.0, 1.0, -1.0),
        DVec3::new(-1.0, -1.0, 1.0),
    ];
    PolyMesh::from_polygons(
        p,
        &[vec![0, 1, 2], vec![0, 3, 1], vec![0, 2, 3], vec![1, 3, 2]],
    )
}

/// The regular octahedron with vertices ±x, ±y, ±z.
pub fn octahedron() -> PolyMesh {
    let p = vec![
        DVec3::X,
        -DVec3::X,
        DVec3::Y,
        -DVec3::Y,
        DVec3::Z,
        -DVec3::Z,
    ];
    let f = [
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    PolyMesh::from_polygons(p, &f.map(|t| t.to_vec()))
}

/// The cube of side 3 used throughout the measurements of docs/algorithms/cylindrical.md.
pub fn cube3() -> PolyMesh {
    cuboid(DVec3::ZERO, DVec3::splat(3.0))
}

/// The L-block of docs/algorithms/cylindrical.md: the L (0,0),(2,0),(2,1),(1,1),(1,2),(0,2) extruded by 4
/// (one concave edge, two concave end faces).
pub fn l_block() -> PolyMesh {
    let l = [(0., 0.), (2., 0.), (2., 1.), (1., 1.), (1., 2.), (0., 2.)].map(DVec2::from);
    extrude(&l, &[], 0.0, 4.0)
}

/// A 3×3×1 block with a 1×1 square hole through it (two faces with holes).
pub fn holed_block() -> PolyMesh {
    let outer = [(0., 0.), (3., 0.), (3., 3.), (0., 3.)].map(DVec2::from);
    let hole = [(1., 1.), (1., 2.), (2., 2.), (2., 1.)]
        .map(DVec2::from)
        .to_vec();
    extrude(&outer, &[hole], 0.0, 1.0)
}

/// The tripod: three orthogonal 1×1 arms of length 3 joined at a corner (17 vertices,
/// 27 edges, 12 faces: three concave L-shaped hexagons and nine rectangles; three convex and
/// three concave edges meet at the saddle vertex (1,1,1)). docs/algorithms/cylindrical.md.
pub fn tripod() -> PolyMesh {
    let p = [
        (0., 0., 0.),
        (3., 0., 0.),
        (3., 1., 0.),
        (3., 0., 1.),
        (3., 1., 1.),
        (0., 3., 0.),
        (1., 3., 0.),
        (0., 3., 1.),
        (1., 3., 1.),
        (0., 0., 3.),
        (1., 0., 3.),
        (0., 1., 3.),
        (1., 1., 3.),
        (1., 1., 0.),
        (1., 0., 1.),
        (0., 1., 1.),
        (1., 1., 1.),
    ]
    .map(DVec3::from)
    .to_vec();
    let faces = [
        vec![0, 5, 6, 13, 2, 1],
        vec![0, 1, 3, 14, 10, 9],
        vec![0, 9, 11, 15, 7, 5],
        vec![1, 2, 4, 3],
        vec![14, 3, 4, 16],
        vec![13, 16, 4, 2],
        vec![5, 7, 8, 6],
        vec![15, 16, 8, 7],
        vec![13, 6, 8, 16],
        vec![9, 10, 12, 11],
        vec![14, 16, 12, 10],
        vec![15, 11, 12, 16],
    ];
    PolyMesh::from_polygons(p, &faces)
}

/// A torus of `rings × segments` quads (major radius `big_r`, minor radius `small_r`).
pub fn torus(rings: u32, segments: u32, big_r: f64, small_r: f64) -> PolyMesh {
    let mut m = PolyMesh::with_capacity(
        (rings * segments) as usize,
        (rings * segments) as usize,
        (rings * segments) as usize,
        (4 * rings * segments) as usize,
    );
    for i in 0..rings {
        let u = std::f64::consts::TAU * i as f64 / rings as f64;
        for j in 0..segments {
            let v = std::f64::consts::TAU * j as f64 / segments as f64;
            let rr = big_r + small_r * v.cos();
            m.positions
                .push(DVec3::new(rr * u.cos(), rr * u.sin(), small_r * v.sin()));
        }
    }
    let id = |i: u32, j: u32| (i % rings) * segments + (j % segments);
    for i in 0..rings {
        for j in 0..segments {
            m.push_polygon(&[id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    m
}

/// Every hole-free face split into a fan of triangles from its first corner (for Loop
/// tests and benchmarks on the quad primitives; a fan is right for convex faces only).
pub fn fan_triangulated(m: &PolyMesh) -> PolyMesh {
    let mut t = PolyMesh::new();
    t.positions = m.positions.clone();
    for f in 0..m.num_faces() {
        let v: Vec<u32> = m.face_corners(f).map(|c| m.corner_verts[c]).collect();
        for k in 1..v.len() - 1 {
            t.push_polygon(&[v[0], v[k], v[k + 1]]);
        }
    }
    t
}

/// Several disjoint closed solids joined into one mesh.
pub fn union_disjoint(parts: &[PolyMesh]) -> PolyMesh {
    let mut m = PolyMesh::new();
    for p in parts {
        let base = m.positions.len() as u32;
        m.positions.extend_from_slice(&p.positions);
        for f in 0..p.num_faces() {
            let loops: Vec<Vec<u32>> = p
                .face_loops(f)
                .map(|l| p.loop_verts(l).iter().map(|v| v + base).collect())
                .collect();
            let refs: Vec<&[u32]> = loops.iter().map(|l| l.as_slice()).collect();
            m.push_face(&refs);
        }
    }
    m
}

/// A "computer room" like the paper's fig. 15: a desk (top and four legs), a monitor on
/// it, a keyboard, and two chairs (seat, back, legs). Every part is a closed box; parts touch
/// but share no vertices.
pub fn computer_room() -> PolyMesh {
    let b = |lo: (f64, f64, f64), hi: (f64, f64, f64)| cuboid(lo.into(), hi.into());
    let mut parts = vec![
        // Desk: top and legs.
        b((0.0, 0.0, 7.0), (12.0, 6.0, 7.6)),
        b((0.3, 0.3, 0.0), (1.0, 1.0, 7.0)),
        b((11.0, 0.3, 0.0), (11.7, 1.0, 7.0)),
        b((0.3, 5.0, 0.0), (1.0, 5.7, 7.0)),
        b((11.0, 5.0, 0.0), (11.7, 5.7, 7.0)),
        // Monitor: screen, neck, foot.
        b((3.5, 3.8, 9.0), (8.5, 4.4, 12.5)),
        b((5.7, 4.0, 7.9), (6.3, 4.4, 9.0)),
        b((4.8, 3.6, 7.6), (7.2, 4.8, 7.9)),
        // Keyboard.
        b((4.0, 1.0, 7.6), (8.0, 2.6, 7.9)),
    ];
    for (x0, y0) in [(2.0, -5.0), (7.5, -5.0)] {
        parts.push(b((x0, y0, 4.0), (x0 + 3.5, y0 + 3.5, 4.6)));
        parts.push(b((x0, y0 - 0.5, 4.0), (x0 + 3.5, y0, 9.0)));
        for (dx, dy) in [(0.2, 0.2), (2.8, 0.2), (0.2, 2.8), (2.8, 2.8)] {
            parts.push(b(
                (x0 + dx, y0 + dy, 0.0),
                (x0 + dx + 0.5, y0 + dy + 0.5, 4.0),
            ));
        }
    }
    union_disjoint(&parts)
}
