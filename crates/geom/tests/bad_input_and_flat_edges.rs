//! Flat edges (the dissolve policy) and bad input: every case gives a result without NaN or
//! a typed error naming the element, never a panic.

use prism_geom::rules::RuleError;
use prism_geom::scheme::parse_pipeline;
use prism_geom::{DVec3, EdgeAttrs, MeshError, Pipeline, PolyMesh, StepError, primitives};

fn run(mesh: &PolyMesh, pipeline: &str) -> Result<Pipeline, StepError> {
    let mut p = Pipeline::new(
        mesh.clone(),
        EdgeAttrs::new(),
        parse_pipeline(pipeline).unwrap(),
    );
    p.compute().map_err(|e| e.source)?;
    Ok(p)
}

/// The 3-cube with its top face split into two coplanar rectangles (a flat edge and two
/// T-junction vertices of valence 3).
fn cube_with_split_top() -> PolyMesh {
    let mut m = primitives::cube3();
    let a = m.positions.len() as u32;
    m.positions.push(DVec3::new(1.5, 0.0, 3.0));
    m.positions.push(DVec3::new(1.5, 3.0, 3.0));
    // Faces of cube3: 0 bottom, 1 top (4,5,6,7), then sides (0,1,5,4), (1,2,6,5), (2,3,7,6), (3,0,4,7).
    let faces: Vec<Vec<u32>> = vec![
        vec![3, 2, 1, 0],
        vec![4, a, a + 1, 7],
        vec![a, 5, 6, a + 1],
        vec![0, 1, 5, a, 4],
        vec![1, 2, 6, 5],
        vec![2, 3, 7, a + 1, 6],
        vec![3, 0, 4, 7],
    ];
    PolyMesh::from_polygons(m.positions, &faces)
}

/// Every face of the 3-cube split into two triangles.
fn triangulated_cube() -> PolyMesh {
    let m = primitives::cube3();
    let mut faces = Vec::new();
    for f in 0..m.num_faces() {
        let v = m.loop_verts(f);
        faces.push(vec![v[0], v[1], v[2]]);
        faces.push(vec![v[0], v[2], v[3]]);
    }
    PolyMesh::from_polygons(m.positions.clone(), &faces)
}

#[test]
fn flat_edges_are_dissolved_before_cylindrical_steps() {
    for rule in ["cylindrical:r=0.45", "minimum:r=0.45", "combination:r=0.45"] {
        let p = run(&cube_with_split_top(), &[rule; 3].join(",")).unwrap();
        let r1 = p.levels()[1].report.as_ref().unwrap();
        assert_eq!(r1.dissolved_edges, 1, "{rule}");
        for l in &p.levels()[1..] {
            let r = l.report.as_ref().unwrap();
            assert!(r.degenerate.is_empty(), "{rule}: {r:?}");
            assert!(r.flipped.is_empty(), "{rule}: {r:?}");
            assert!(l.mesh.all_finite());
        }
        // Same result as the plain cube: the split changed nothing about the solid.
        let plain = run(&primitives::cube3(), &[rule; 3].join(",")).unwrap();
        assert_eq!(
            p.levels()[3].mesh.num_faces(),
            plain.levels()[3].mesh.num_faces()
        );
        let vol = prism_geom::geometry::signed_volume(&p.levels()[3].mesh);
        let vol0 = prism_geom::geometry::signed_volume(&plain.levels()[3].mesh);
        assert!((vol - vol0).abs() < 1e-12, "{vol} vs {vol0}");
    }
}

#[test]
fn a_triangulated_cube_rounds_like_the_cube() {
    let p = run(
        &triangulated_cube(),
        "combination:r=0.45,combination:r=0.45",
    )
    .unwrap();
    assert_eq!(p.levels()[1].report.as_ref().unwrap().dissolved_edges, 6);
    let plain = run(
        &primitives::cube3(),
        "combination:r=0.45,combination:r=0.45",
    )
    .unwrap();
    let a = &p.levels()[2].mesh;
    let b = &plain.levels()[2].mesh;
    assert_eq!(a.num_faces(), b.num_faces());
    let mut pa: Vec<[i64; 3]> = a
        .positions
        .iter()
        .map(|p| (*p * 1e9).round().as_i64vec3().to_array())
        .collect();
    let mut pb: Vec<[i64; 3]> = b
        .positions
        .iter()
        .map(|p| (*p * 1e9).round().as_i64vec3().to_array())
        .collect();
    pa.sort();
    pb.sort();
    assert_eq!(pa, pb);
}

#[test]
fn merging_coplanar_faces_can_make_a_hole() {
    // A 3×3×1 block whose top is eight unit-ish quads around a square hole (as separate
    // faces): the dissolve merges them into one face with a hole.
    let hb = primitives::holed_block();
    // Top face of the holed block is face 1 with outer (8..12) and hole (12..16) loops;
    // rebuild it as 4 trapezoids between the outer and inner squares.
    let o: Vec<u32> = hb.loop_verts(2).to_vec();
    let i: Vec<u32> = hb.loop_verts(3).to_vec();
    // Outer runs CCW (0,0),(3,0),(3,3),(0,3); the hole (1,1),(1,2),(2,2),(2,1) runs CW.
    let inner_ccw = [i[0], i[3], i[2], i[1]];
    let mut faces: Vec<Vec<Vec<u32>>> = Vec::new();
    for f in 0..hb.num_faces() {
        if f == 1 {
            for k in 0..4 {
                let k1 = (k + 1) % 4;
                faces.push(vec![vec![o[k], o[k1], inner_ccw[k1], inner_ccw[k]]]);
            }
        } else {
            faces.push(
                hb.face_loops(f)
                    .map(|l| hb.loop_verts(l).to_vec())
                    .collect(),
            );
        }
    }
    let mut m = PolyMesh::new();
    m.positions = hb.positions.clone();
    for f in &faces {
        let loops: Vec<&[u32]> = f.iter().map(|l| l.as_slice()).collect();
        m.push_face(&loops);
    }
    let p = run(&m, "combination:r=0.15,combination:r=0.15").unwrap();
    assert_eq!(p.levels()[1].report.as_ref().unwrap().dissolved_edges, 4);
    let plain = run(&hb, "combination:r=0.15,combination:r=0.15").unwrap();
    assert_eq!(
        p.levels()[2].mesh.num_faces(),
        plain.levels()[2].mesh.num_faces()
    );
    assert_eq!(p.levels()[2].mesh.num_holed_faces(), 2);
}

#[test]
fn coplanar_triangles_merge_and_their_centre_vertex_goes() {
    // A pyramid whose square base is split into 4 coplanar triangles around its centre 4.
    let p = [
        (0., 0., 0.),
        (2., 0., 0.),
        (2., 2., 0.),
        (0., 2., 0.),
        (1., 1., 0.),
        (1., 1., 1.),
    ]
    .map(DVec3::from)
    .to_vec();
    let faces = vec![
        vec![0, 4, 1],
        vec![1, 4, 2],
        vec![2, 4, 3],
        vec![3, 4, 0],
        vec![0, 1, 5],
        vec![1, 2, 5],
        vec![2, 3, 5],
        vec![3, 0, 5],
    ];
    let m = PolyMesh::from_polygons(p, &faces);
    let out = run(&m, "cylindrical:r=0.1").unwrap();
    let rep = out.levels()[1].report.as_ref().unwrap();
    assert_eq!(rep.dissolved_edges, 4);
    // 5 faces, 5 vertices, 8 edges after the merge → 5 + 8 + 5 faces.
    assert_eq!(out.levels()[1].mesh.num_faces(), 18);
}

#[test]
fn bad_input_gives_typed_errors() {
    // Open mesh.
    let mut open = primitives::cube3();
    open.corner_verts.truncate(20);
    open.loop_starts.truncate(6);
    open.face_starts.truncate(6);
    assert!(matches!(
        run(&open, "doo-sabin"),
        Err(StepError::Mesh(MeshError::BoundaryEdge { .. }))
    ));
    // NaN coordinate.
    let mut nan = primitives::cube3();
    nan.positions[2].x = f64::NAN;
    assert!(matches!(
        run(&nan, "combination:r=0.1"),
        Err(StepError::Mesh(MeshError::NonFinite { vertex: 2, .. }))
    ));
    // Doo–Sabin on a holed face.
    let e = run(&primitives::holed_block(), "doo-sabin").unwrap_err();
    assert!(matches!(
        e,
        StepError::Rule(RuleError::HoledFace { face: 0 })
    ));
    assert!(e.to_string().contains("face 0"));
    // Memory budget.
    let mut p = Pipeline::new(
        primitives::torus(100, 100, 3.0, 1.0),
        EdgeAttrs::new(),
        parse_pipeline("doo-sabin").unwrap(),
    );
    p.options.memory_budget = 1 << 20;
    let e = p.compute().unwrap_err();
    assert!(matches!(e.source, StepError::TooLarge(_)), "{e}");
    // A knife edge: two triangles back to back (a closed, flat "pillow").
    let m = PolyMesh::from_polygons(
        vec![DVec3::ZERO, DVec3::X, DVec3::Y],
        &[vec![0, 1, 2], vec![0, 2, 1]],
    );
    let e = run(&m, "cylindrical:r=0.1").unwrap_err();
    assert!(
        matches!(e, StepError::Rule(RuleError::KnifeEdge { .. })),
        "{e}"
    );
}

/// Both readers validate alike (issue 15): a `.prism.json` is refused for what the OBJ
/// reader refuses — negative sharpness, corners and holes that name nothing, edges naming
/// vertices that do not exist or that no face has — and for a radius that is not above 0;
/// each message names the element.
#[test]
fn documents_are_validated_like_obj_files() {
    use std::path::Path;
    let tet = r#""vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]],
                 "faces": [[[0,2,1]],[[0,1,3]],[[1,2,3]],[[0,3,2]]]"#;
    let load = |extra: &str| {
        let text = format!("{{\"version\": 1, {tet}{extra}}}");
        prism_geom::io::load_str(Path::new("t.prism.json"), &text).map(|_| ())
    };
    load("").unwrap();
    for (extra, says) in [
        (
            r#", "edges": [{"a": 0, "b": 1, "crease": -2}]"#,
            "edge 0-1: crease sharpness -2",
        ),
        (
            r#", "edges": [{"a": 0, "b": 9, "crease": 2}]"#,
            "edge 0-9 names a vertex",
        ),
        (
            r#", "edges": [{"a": 0, "b": 1, "radius": -0.3}]"#,
            "edge 0-1: radius -0.3",
        ),
        (
            r#", "edges": [{"a": 0, "b": 1, "radius": 0}]"#,
            "edge 0-1: radius 0",
        ),
        (
            r#", "subdivision": {"corners": {"7": 10}}"#,
            "corner at vertex 7",
        ),
        (
            r#", "subdivision": {"corners": {"1": -1}}"#,
            "corner at vertex 1: sharpness -1",
        ),
        (r#", "subdivision": {"holes": [4]}"#, "hole 4: no such face"),
    ] {
        let e = load(extra).unwrap_err().to_string();
        assert!(e.contains(says), "{extra}: {e}");
    }
    let bad_face = r#"{"version": 1, "vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[[0,1,5]]]}"#;
    let e = prism_geom::io::load_str(Path::new("t.prism.json"), bad_face).unwrap_err();
    assert!(
        e.to_string().contains("face 0, loop 0: vertex index 5"),
        "{e}"
    );
}

/// OBJ text as other tools write it: a UTF-8 byte-order mark and bare CR line ends read as
/// the plain file (they gave "vertex index 8 is out of range" and tobj's "color parse error");
/// a face naming a texture coordinate or normal that does not exist is refused by line.
#[test]
fn obj_byte_order_marks_and_cr_line_ends_read_and_missing_vt_is_named() {
    use std::path::Path;
    let plain = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
    let load = |t: &str| prism_geom::io::load_str(Path::new("t.obj"), t).map(|d| d.0.mesh);
    let base = load(plain).unwrap();
    assert_eq!(load(&format!("\u{feff}{plain}")).unwrap(), base);
    assert_eq!(load(&plain.replace('\n', "\r")).unwrap(), base);
    assert_eq!(load(&plain.replace('\n', "\r\n")).unwrap(), base);
    let e = load(&plain.replace("f 1 3 2", "f 1/7/3 3 2"))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("line 5") && e.contains("texture coordinate 7"),
        "{e}"
    );
    let with = plain.replace("f 1 3 2", "vt 0 0\nvn 0 0 1\nf 1/1/1 3 2");
    assert_eq!(load(&with).unwrap().num_faces(), 4);
    let e = load(&with.replace("f 1/1/1", "f 1/1/2"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("normal 2"), "{e}");
}
