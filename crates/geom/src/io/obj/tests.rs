use super::*;
use crate::edge_attrs::EdgeKey;
use crate::primitives;

/// Parsing in chunks of a few bytes gives the model (and the first error, with its line)
/// that one chunk gives: relative indices, texture and normal counts, tags and line
/// numbers all carry across chunk ends.
#[test]
fn chunks_parse_as_one_text_does() {
    let text = "# a cube with everything\nv 0 0 0\nv 1 0 0\nvt 0 0\nv 1 1 0\nv 0 1 0\n\
                v 0 0 1\nvn 0 0 1\nv 1 0 1\r\nv 1 1 1\nv 0 1 1\nf 1 4 3 2\nf -8/1 -7 -3 -4\n\
                f 2/1/1 3 7 6\ng side\nf 3 4 8 7\nf 4 1 5 8\nf 5 6 7 8 # top\n\
                t crease 2/1/0 0 1 5.0\nt corner 1/1/0 2 3.0\n";
    let p = Path::new("c.obj");
    let one = parse_in(p, text.as_bytes(), &Progress::default(), 1 << 20).unwrap();
    assert_eq!(one.mesh.num_faces(), 6);
    for chunk in [1, 7, 16, 40] {
        let m = parse_in(p, text.as_bytes(), &Progress::default(), chunk).unwrap();
        assert_eq!(m.mesh, one.mesh, "chunks of {chunk}");
        assert_eq!(m.vertex_lines, one.vertex_lines);
        assert_eq!(m.face_lines, one.face_lines);
        assert_eq!(m.edge_attrs, one.edge_attrs);
        assert_eq!(m.tags, one.tags);
    }
    assert_eq!(one.face_lines[1], 13);
    let f1: Vec<u32> = one
        .mesh
        .face_corners(1)
        .map(|c| one.mesh.corner_verts[c])
        .collect();
    assert_eq!(f1, vec![0, 1, 5, 4]);
    let bad = format!("{text}f 1 2 9\n");
    for chunk in [1, 7, 1 << 20] {
        let e = parse_in(p, bad.as_bytes(), &Progress::default(), chunk)
            .unwrap_err()
            .to_string();
        assert!(e.contains("line 21") && e.contains("vertex index 9"), "{e}");
    }
    let e = parse_in(
        p,
        b"v 0 0 0\nv 1 0 0\nv 0 \xff 1\n",
        &Progress::default(),
        4,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("line 3") && e.contains("not UTF-8"), "{e}");
}

/// The line cutter is `str::lines` with each line's comment cut off.
#[test]
fn lines_are_the_standard_lines_without_comments() {
    for text in [
        "",
        "\n",
        "v 1 2 3\nf 1 2 3",
        "v 1 2 3 # a\r\n# only\n\nf 1 2 3\r\n",
        "a\rb\r\n#\n##\nlast\r",
        "x # y # z\n  # \n\t\n",
    ] {
        let want: Vec<&str> = text.lines().map(|l| l.split('#').next().unwrap()).collect();
        assert_eq!(lines(text).collect::<Vec<_>>(), want, "{text:?}");
    }
}

/// A cancelled read stops with `Cancelled`; progress runs to 1 on a whole read.
#[test]
fn reading_reports_progress_and_stops_when_cancelled() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cube.obj");
    write_obj(
        &path,
        &primitives::cuboid(DVec3::ZERO, DVec3::ONE),
        &EdgeAttrs::default(),
        &SubdivTags::default(),
    )
    .unwrap();
    let progress = Progress::default();
    read_obj_with(&path, &progress).unwrap();
    assert!(
        (progress.fraction() - 1.0).abs() < 1e-12,
        "{}",
        progress.fraction()
    );
    let progress = Progress::default();
    progress.cancel();
    let e = read_obj_with(&path, &progress).unwrap_err();
    assert!(matches!(e, IoError::Cancelled { .. }), "{e}");
    // Cancelled between parsing chunks: the bytes are read, the parse stops.
    let bytes = std::fs::read(&path).unwrap();
    let e = parse_in(&path, &bytes, &progress, 8).unwrap_err();
    assert!(matches!(e, IoError::Cancelled { .. }), "{e}");
}

/// Coordinates are written as the shortest decimal that reads back to the same double:
/// tiny values with an exponent (they were printed positionally, 33 characters for
/// -1.3760693973186022e-15), whole numbers without ".0"; read back bit for bit.
#[test]
fn numbers_are_shortest_and_exact() {
    let mut m = primitives::cube3();
    m.positions[0] = DVec3::new(-1.3760693973186022e-15, 1.0 / 3.0, 2.0);
    m.positions[1].x = 1e300;
    m.positions[2].y = -0.1 - 0.2;
    let (s, _) = obj_to_string(&m, &EdgeAttrs::new(), &SubdivTags::default());
    assert!(
        s.contains("v -1.3760693973186022e-15 0.3333333333333333 2\n"),
        "{s}"
    );
    let back = read_obj_str(Path::new("t.obj"), &s).unwrap();
    for (a, b) in back.mesh.positions.iter().zip(&m.positions) {
        assert_eq!(
            a.to_array().map(f64::to_bits),
            b.to_array().map(f64::to_bits)
        );
    }
}

#[test]
fn round_trip_keeps_vertex_order_and_polygons() {
    let m = primitives::tripod();
    let (s, w) = obj_to_string(&m, &EdgeAttrs::new(), &SubdivTags::default());
    assert!(w.is_empty());
    let back = read_obj_str(Path::new("t.obj"), &s).unwrap();
    assert_eq!(back.mesh, m);
}

#[test]
fn groups_do_not_split_or_reorder_vertices() {
    let text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 5 5 5\ng a\nusemtl x\nf 3 4 1\ng b\nf 1 2 3\nt crease 2/1/0 0 2 10\n";
    let m = read_obj_str(Path::new("t.obj"), text).unwrap();
    assert_eq!(m.mesh.num_vertices(), 5);
    assert_eq!(m.mesh.positions[4], DVec3::splat(5.0));
    assert_eq!(m.mesh.loop_verts(0), &[2, 3, 0]);
    assert_eq!(m.mesh.loop_verts(1), &[0, 1, 2]);
    assert_eq!(m.face_lines, vec![8, 10]);
    assert_eq!(m.edge_attrs[&EdgeKey::new(0, 2)].crease, 10.0);
}

#[test]
fn relative_indices_count_back_from_the_vertices_read_so_far() {
    // Two triangles, each after its own vertices, one with relative indices, the other
    // with v/vt/vn forms; comments and tabs.
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1 # first\nv 5 0 0\nvt 0 0\nvn 0 0 1\n\
                f\t2/1/1 4//1 3\n";
    let m = read_obj_str(Path::new("t.obj"), text).unwrap();
    assert_eq!(m.mesh.loop_verts(0), &[0, 1, 2]);
    assert_eq!(m.mesh.loop_verts(1), &[1, 3, 2]);
    assert_eq!(m.vertex_lines, vec![1, 2, 3, 5]);
    assert_eq!(m.face_lines, vec![4, 8]);
}

#[test]
fn errors_name_the_line() {
    let e = read_obj_str(Path::new("t.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n").unwrap_err();
    assert!(e.to_string().contains("line 4"), "{e}");
    let e = read_obj_str(Path::new("t.obj"), "v 0 0\n").unwrap_err();
    assert!(e.to_string().contains("line 1"), "{e}");
    let e = read_obj_str(Path::new("t.obj"), "v 0 0 0\nv 1 0 0\nf 1 2\n").unwrap_err();
    assert!(e.to_string().contains("line 3"), "{e}");
}

#[test]
fn holed_faces_are_triangulated_with_a_warning() {
    let m = primitives::holed_block();
    let (s, w) = obj_to_string(&m, &EdgeAttrs::new(), &SubdivTags::default());
    assert_eq!(w.len(), 1);
    let back = read_obj_str(Path::new("t.obj"), &s).unwrap();
    // Two holed faces (8 vertices each, 1 hole) → 8 triangles each; 8 side quads.
    assert_eq!(back.mesh.num_faces(), 8 + 2 * 8);
    let t = crate::topology::Topology::build(&back.mesh).unwrap();
    t.require_closed(&back.mesh).unwrap();
    assert!((crate::geometry::signed_volume(&back.mesh) - 8.0).abs() < 1e-12);
}
