//! Tests of the topology builder and its checks.

use super::build::{ring_starts, serial_twins, uniform_layout};
use super::outgoing::Outgoing;
use super::*;
use glam::DVec3;

fn cube() -> PolyMesh {
    crate::primitives::cuboid(DVec3::ZERO, DVec3::ONE)
}

#[test]
fn cube_topology() {
    let m = cube();
    let t = Topology::build(&m).unwrap();
    assert_eq!(t.num_edges(), 12);
    t.require_closed(&m).unwrap();
    for c in 0..m.num_corners() {
        assert_eq!(t.twin[t.twin[c] as usize] as usize, c);
    }
}

#[test]
fn errors_name_the_element() {
    let mut m = cube();
    m.positions[3].y = f64::NAN;
    assert!(matches!(
        Topology::build(&m),
        Err(MeshError::NonFinite { vertex: 3, .. })
    ));

    let mut m = cube();
    m.corner_verts[5] = 99;
    assert!(matches!(
        Topology::build(&m),
        Err(MeshError::IndexOutOfRange { index: 99, .. })
    ));

    // Flip one face: inconsistent orientation.
    let mut m = cube();
    m.corner_verts[0..4].reverse();
    assert!(matches!(
        Topology::build(&m),
        Err(MeshError::InconsistentOrientation { .. })
    ));

    // Remove one face: open.
    let mut m = cube();
    m.corner_verts.truncate(20);
    m.loop_starts.truncate(6);
    m.face_starts.truncate(6);
    let t = Topology::build(&m).unwrap();
    assert!(matches!(
        t.require_closed(&m),
        Err(MeshError::BoundaryEdge { .. })
    ));

    // Repeated vertex, degenerate loop.
    let m = PolyMesh::from_polygons(
        vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z],
        &[vec![0, 1, 2, 1]],
    );
    assert!(matches!(
        Topology::build(&m),
        Err(MeshError::RepeatedVertex { face: 0, vertex: 1 })
    ));
    let m = PolyMesh::from_polygons(vec![DVec3::ZERO, DVec3::X], &[vec![0, 1]]);
    assert!(matches!(
        Topology::build(&m),
        Err(MeshError::DegenerateLoop { face: 0, .. })
    ));
}

#[test]
fn non_manifold_edge_and_unused_vertex() {
    // Three triangles on one edge 0-1.
    let p = vec![
        DVec3::ZERO,
        DVec3::X,
        DVec3::Y,
        DVec3::Z,
        -DVec3::Y,
        DVec3::ONE,
    ];
    let m = PolyMesh::from_polygons(p, &[vec![0, 1, 2], vec![1, 0, 3], vec![1, 0, 4]]);
    match Topology::build(&m) {
        Err(MeshError::NonManifoldEdge { a: 0, b: 1, faces }) => assert_eq!(faces.len(), 3),
        other => panic!("{other:?}"),
    }
    let mut m = cube();
    m.positions.push(DVec3::splat(5.0));
    let t = Topology::build(&m).unwrap();
    assert_eq!(
        t.warnings,
        vec![MeshWarning::UnusedVertices { count: 1, first: 8 }]
    );
}

#[test]
fn pinched_vertex_is_refused() {
    // Two tetrahedra sharing one vertex (0).
    let mut p = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    p.extend([-DVec3::X, -DVec3::Y, -DVec3::Z]);
    let tet = |a: u32, b: u32, c: u32, d: u32| {
        vec![vec![a, c, b], vec![a, b, d], vec![a, d, c], vec![b, c, d]]
    };
    let mut faces = tet(0, 1, 2, 3);
    faces.extend(tet(0, 4, 6, 5));
    let m = PolyMesh::from_polygons(p, &faces);
    let t = Topology::build(&m).unwrap();
    assert!(matches!(
        t.require_closed(&m),
        Err(MeshError::NonManifoldVertex { vertex: 0, .. })
    ));
}

/// Vertices of more than 16 half-edges look their neighbours up in a sorted list: two cones
/// of 20 sides closed by their bases pair and walk like any vertex, and the same cones
/// touching at their tips (40 half-edges at one vertex, two fans) are refused there.
#[test]
fn busy_vertices_pair_and_walk_their_fans() {
    let n = 20u32;
    let cone = |tip: DVec3, base: f64, flip: bool, offset: u32| {
        let mut p = vec![tip];
        for k in 0..n {
            let a = std::f64::consts::TAU * k as f64 / n as f64;
            p.push(DVec3::new(a.cos(), a.sin(), base));
        }
        let mut faces: Vec<Vec<u32>> = (0..n)
            .map(|k| vec![offset, offset + 1 + k, offset + 1 + (k + 1) % n])
            .collect();
        faces.push((0..n).rev().map(|k| offset + 1 + k).collect());
        if flip {
            faces.iter_mut().for_each(|f| f.reverse());
        }
        (p, faces)
    };
    let (p, faces) = cone(DVec3::Z, 0.0, false, 0);
    let m = PolyMesh::from_polygons(p.clone(), &faces);
    let t = Topology::build(&m).unwrap();
    assert!(t.fans_checked);
    t.require_closed(&m).unwrap();
    let outgoing = Outgoing::new(m.num_vertices(), &m.corner_verts, t.loops());
    let serial = serial_twins(&m.corner_verts, t.loops(), &outgoing, m.num_corners());
    assert_eq!(serial.unwrap(), t.twin);
    // The second cone below, sharing the tip (vertex 0).
    let (q, lower) = cone(DVec3::ZERO, -1.0, true, 0);
    let mut pts = p;
    pts.extend_from_slice(&q[1..]);
    let mut all = faces;
    all.extend(lower.into_iter().map(|f| {
        f.into_iter()
            .map(|v| if v == 0 { 0 } else { v + n })
            .collect::<Vec<u32>>()
    }));
    let m = PolyMesh::from_polygons(pts, &all);
    let t = Topology::build(&m).unwrap();
    assert!(!t.fans_checked);
    assert!(matches!(
        t.require_closed(&m),
        Err(MeshError::NonManifoldVertex { vertex: 0, .. })
    ));
}

/// The twins found on every core are the serial pass's, on a mesh big enough to be cut
/// into many pieces (a 200 × 150 torus with a hole cut in it: boundary half-edges too); a
/// mesh the parallel pass cannot pair falls back to the serial pass and its error.
#[test]
fn twins_found_in_parallel_are_the_serial_ones() {
    let mut m = crate::primitives::torus(200, 150, 3.0, 1.0);
    let mut cut = PolyMesh::new();
    cut.positions = m.positions.clone();
    for f in 0..m.num_faces() {
        if f % 97 != 5 {
            cut.push_polygon(
                &m.face_corners(f)
                    .map(|c| m.corner_verts[c])
                    .collect::<Vec<_>>(),
            );
        }
    }
    for mesh in [&m, &cut] {
        let t = Topology::build(mesh).unwrap();
        let cv = &mesh.corner_verts;
        let (nv, nc) = (mesh.num_vertices(), mesh.num_corners());
        let mut out: Vec<Vec<(u32, u32)>> = vec![Vec::new(); nv];
        for c in 0..nc {
            out[cv[c] as usize].push((c as u32, cv[t.next(c) as usize]));
        }
        // The counting sort gives these lists however the corners are cut into runs.
        // The counting while looking at each face (every face a quad: the torus) gives the
        // same lists.
        if mesh.num_corners() == 4 * mesh.num_faces() {
            let outgoing = Outgoing::of_uniform::<4>(nv, cv, t.loops()).unwrap();
            for (v, list) in out.iter().enumerate() {
                assert!(outgoing.of(v as u32).eq(list.iter().copied()), "vertex {v}");
            }
        }
        for runs in [1, 2, 3, 7] {
            let outgoing = Outgoing::in_runs(nv, cv, t.loops(), runs);
            for (v, list) in out.iter().enumerate() {
                assert!(outgoing.of(v as u32).eq(list.iter().copied()), "vertex {v}");
            }
            let serial = serial_twins(cv, t.loops(), &outgoing, nc);
            assert_eq!(serial.unwrap(), t.twin);
            // The ring starts picked while pairing are the ones a pass of their own picks.
            assert_eq!(ring_starts(&t.twin, &outgoing, nv), t.vert_corner);
        }
        assert!(t.fans_checked, "every vertex a single fan");
        // So does the edge numbering however the half-edges are cut into blocks.
        let one = edges::one_pass(&t.twin);
        assert_eq!(
            (&one.corner_edge, &one.edge_corner),
            (&t.corner_edge, &t.edge_corner)
        );
        let open = t.twin.iter().filter(|&&x| x == NONE).count();
        assert_eq!(one.open, open);
        assert_eq!(t.is_closed(), open == 0);
        // And the numbering from the leading half-edges counted while pairing.
        let outgoing = Outgoing::new(nv, cv, t.loops());
        let leads = by_vertex::twins(cv, t.loops(), &outgoing).unwrap().leads;
        assert!(leads.per_block.len() > 1);
        let counted = edges::from_counts(&t.twin, edges::BLOCK, &leads);
        assert_eq!(
            (counted.corner_edge, counted.edge_corner, counted.open),
            (one.corner_edge.clone(), one.edge_corner.clone(), one.open)
        );
        for block in [1, 7, 4096, 1 << 16] {
            let b = edges::in_blocks(&t.twin, block);
            assert_eq!(
                (b.corner_edge, b.edge_corner, b.open),
                (one.corner_edge.clone(), one.edge_corner.clone(), one.open),
                "blocks of {block}"
            );
        }
    }
    assert!(t_has_boundary(&cut));
    // A face repeated: every edge of it is used three times.
    m.push_polygon(&[0, 1, 151]);
    m.push_polygon(&[0, 1, 151]);
    assert!(matches!(
        Topology::build(&m),
        Err(MeshError::NonManifoldEdge { .. } | MeshError::InconsistentOrientation { .. })
    ));
}

fn t_has_boundary(m: &PolyMesh) -> bool {
    Topology::build(m).unwrap().twin.contains(&NONE)
}

/// Everything the build writes on rayon's pool (loops, ring starts, the fan check) and the
/// primal splits are the same on one thread as on several, field for field and bit for bit,
/// on a mesh cut into many pieces with n-gons, holes and boundaries in it, big enough for
/// the points to be computed on the pool (`PARALLEL_FACES`); the first bad face is named
/// the same way.
#[test]
fn the_build_and_the_splits_are_the_same_on_any_number_of_threads() {
    use crate::primal::{PARALLEL_FACES, PrimalScheme, refine_primal};
    use crate::tags::SubdivTags;
    let torus = crate::primitives::torus(300, 200, 3.0, 1.0);
    assert!(torus.num_faces() > PARALLEL_FACES);
    let holed =
        crate::primitives::union_disjoint(&[torus.clone(), crate::primitives::holed_block()]);
    let mut open = crate::primitives::union_disjoint(&[
        crate::primitives::ngon_prism(7, 1.0, 1.0),
        torus.clone(),
    ]);
    open.truncate_faces(open.num_faces() - 3);
    let tri = crate::primitives::fan_triangulated(&torus);
    let on = |threads: usize, m: &PolyMesh, scheme: Option<PrimalScheme>| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let t = Topology::build(m).unwrap();
            let fans = t.require_single_fans(m);
            let refined = scheme.map(|s| {
                let attrs = crate::edge_attrs::EdgeAttrs::new();
                refine_primal(m, &attrs, &SubdivTags::default(), s, u64::MAX).unwrap()
            });
            (t, fans, refined)
        })
    };
    let cases = [
        (&holed, None),
        (&open, Some(PrimalScheme::CatmullClark)),
        (&torus, Some(PrimalScheme::CatmullClark)),
        (&tri, Some(PrimalScheme::Loop)),
    ];
    for (m, scheme) in cases {
        let (a, fa, ra) = on(1, m, scheme);
        let (b, fb, rb) = on(3, m, scheme);
        assert!(a.loops().same(b.loops(), a.num_corners()));
        assert_eq!(a.twin, b.twin);
        assert_eq!(a.corner_edge, b.corner_edge);
        assert_eq!(a.edge_corner, b.edge_corner);
        assert_eq!(a.vert_corner, b.vert_corner);
        assert_eq!(a.warnings, b.warnings);
        assert_eq!(fa, fb);
        // And what one pass over the loops gives.
        for f in 0..m.num_faces() {
            for l in m.face_loops(f) {
                let r = m.loop_corners(l);
                for c in r.clone() {
                    assert_eq!(a.corner_face(c), f as u32);
                    let n = if c + 1 == r.end { r.start } else { c + 1 };
                    assert_eq!(a.next(c), n as u32);
                    assert_eq!(a.prev(n), c as u32);
                }
            }
        }
        if let (Some(ra), Some(rb)) = (ra, rb) {
            assert_eq!(ra.mesh, rb.mesh);
            assert_eq!(ra.tags.holes, rb.tags.holes);
        }
    }
    // Two bad faces far apart: the first is named.
    let mut bad = torus.clone();
    let n = bad.num_faces();
    let (f1, f2) = (n / 3, 2 * n / 3);
    for f in [f2, f1] {
        let c = bad.face_corners(f).start;
        bad.corner_verts[c + 1] = bad.corner_verts[c];
    }
    for threads in [1, 3] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        match pool.install(|| Topology::build(&bad)) {
            Err(MeshError::RepeatedVertex { face, .. }) => assert_eq!(face, f1 as u32),
            other => panic!("{threads} threads: {:?}", other.map(|_| ())),
        }
    }
}

/// `find_edge` walks a vertex's ring without a list: it finds exactly the edges the ring
/// lists (the first, in ring order), on a closed solid and on an open 3 × 3 grid whose
/// boundary vertices end their rings at the closing boundary edge, and nothing for a pair
/// that shares no edge or a vertex out of range.
#[test]
fn find_edge_finds_what_the_ring_lists() {
    let mut grid_points = Vec::new();
    for j in 0..4 {
        for i in 0..4 {
            grid_points.push(DVec3::new(i as f64, j as f64, 0.0));
        }
    }
    let quads: Vec<Vec<u32>> = (0..3)
        .flat_map(|j| (0..3).map(move |i| (i, j)))
        .map(|(i, j)| {
            let v = |a: u32, b: u32| 4 * (j + b) + i + a;
            vec![v(0, 0), v(1, 0), v(1, 1), v(0, 1)]
        })
        .collect();
    let grid = PolyMesh::from_polygons(grid_points, &quads);
    for m in [crate::primitives::tripod(), grid] {
        let t = Topology::build(&m).unwrap();
        let n = m.num_vertices() as u32;
        let (mut ring, mut corners) = (Vec::new(), Vec::new());
        for a in 0..n {
            t.vertex_ring_from(&m, t.vert_corner[a as usize], &mut ring, &mut corners);
            for b in 0..n {
                let listed = ring.iter().find(|&&(_, o)| o == b).map(|&(e, _)| e);
                assert_eq!(t.find_edge(&m, a, b), listed, "{a}-{b}");
            }
            assert_eq!(t.find_edge(&m, a, n), None);
        }
        assert_eq!(t.find_edge(&m, n, 0), None);
        // Every edge from both of its ends.
        for e in 0..t.num_edges() {
            let (a, b) = t.edge_verts(&m, e);
            assert_eq!(t.find_edge(&m, a, b), Some(e as u32));
            assert_eq!(t.find_edge(&m, b, a), Some(e as u32));
        }
    }
}

/// A mesh of quads only, or of triangles only, is checked by its corners alone; the first
/// bad face is named as on any other mesh.
#[test]
fn uniform_meshes_name_their_first_bad_face() {
    let quads = crate::primitives::torus(20, 10, 3.0, 1.0);
    let tris = crate::primitives::fan_triangulated(&quads);
    for (m, k) in [(quads, 4), (tris, 3)] {
        assert_eq!(uniform_layout(&m), Some(k));
        let t = Topology::build(&m).unwrap();
        assert!(matches!(t.loops(), Loops::Quads | Loops::Triangles));
        assert!(t.loops().same(
            &Loops::of(&m, None, &[0, m.num_faces()], &[0, m.num_corners()]),
            m.num_corners()
        ));
        let mut bad = m.clone();
        bad.corner_verts[k * 150 + 1] = bad.corner_verts[k * 150];
        bad.corner_verts[k * 170] = 9999;
        assert!(matches!(
            Topology::build(&bad),
            Err(MeshError::RepeatedVertex { face: 150, .. }
                | MeshError::DegenerateLoop { face: 150, .. })
        ));
        let mut bad = m.clone();
        bad.corner_verts[k * 170 + 2] = 9999;
        assert!(matches!(
            Topology::build(&bad),
            Err(MeshError::IndexOutOfRange {
                face: 170,
                index: 9999,
                ..
            })
        ));
    }
}
