//! OBJ in and out.
//!
//! Reading is one pass over the lines: `v` positions in file order (OpenSubdiv-style `t` tag
//! lines index the file's own vertex order, which a general OBJ loader such as tobj does not
//! keep: groups and materials split the mesh into re-indexed models, positions come back in
//! first-use order — Prism used tobj on a rewritten copy of the text, read twice and held
//! three times, 3.2 GB to load a 363 MB file), `f` polygons as they are (any number of
//! corners, `v/vt/vn` forms, relative indices), every index checked against the lines read so
//! far so that errors name the line; `o`, `g`, `usemtl`, `mtllib`, `l`, `p` and unknown
//! statements are skipped. Numbers are parsed by the standard library (correctly rounded, the
//! exact double the writer's shortest decimal stands for). OpenSubdiv's `t` tag lines are
//! read by `obj_tags` (creases into edge attributes, corners, holes and options into
//! [`SubdivTags`]).
//!
//! Writing keeps polygons; a face with holes, which OBJ cannot hold, is triangulated with
//! `earcutr` in the face's plane and reported as a warning. Creases are written as `t crease`
//! lines, corners, holes and options as their `t` lines.

use super::{IoError, Normals, write_atomically_with};
use crate::edge_attrs::EdgeAttrs;
use crate::mesh::PolyMesh;
use crate::tags::SubdivTags;
use crate::triangulate::face_vertex_triangles;
use glam::DVec3;
use std::fmt::Write as _;
use std::io::Write as IoWrite;
use std::path::Path;

/// A mesh read from OBJ, with the line of every face and vertex for error messages.
#[derive(Debug, Clone)]
pub struct ObjModel {
    pub mesh: PolyMesh,
    pub edge_attrs: EdgeAttrs,
    /// Corners, holes and subdivision options from the `t` lines.
    pub tags: SubdivTags,
    /// 1-based line number of each face.
    pub face_lines: Vec<usize>,
    /// 1-based line number of each vertex.
    pub vertex_lines: Vec<usize>,
}

/// Reads an OBJ file.
pub fn read_obj(path: &Path) -> Result<ObjModel, IoError> {
    let text = std::fs::read_to_string(path).map_err(|source| IoError::Read {
        path: path.into(),
        source,
    })?;
    read_obj_str(path, &text)
}

/// Reads OBJ text (`path` is only used in messages).
pub fn read_obj_str(path: &Path, text: &str) -> Result<ObjModel, IoError> {
    let err = |line: Option<usize>, message: String| IoError::Obj {
        path: path.into(),
        line,
        message,
    };
    let mut vertex_lines = Vec::new();
    let mut face_lines = Vec::new();
    // Sized by a first look at the lines (a memchr scan): no vector grows by copying.
    let (nv, nf) = count_records(text);
    let mut mesh = PolyMesh::with_capacity(nv, nf, nf, 4 * nf);
    vertex_lines.reserve(nv);
    face_lines.reserve(nf);
    let mut face: Vec<u32> = Vec::new();
    let mut tags: Vec<(usize, Vec<String>)> = Vec::new();
    // A UTF-8 byte-order mark is not part of the first line; old Mac files end lines with a
    // bare CR, which would otherwise make the whole file one line.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let text: std::borrow::Cow<'_, str> = if text.contains('\r') {
        text.replace("\r\n", "\n").replace('\r', "\n").into()
    } else {
        text.into()
    };
    let (mut textures, mut normals) = (0i64, 0i64);
    for (i, raw) in text.lines().enumerate() {
        let lineno = i + 1;
        let line = match raw.find('#') {
            Some(k) => &raw[..k],
            None => raw,
        };
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                let mut xyz = [0.0f64; 3];
                for x in &mut xyz {
                    *x = match words.next().map(str::parse::<f64>) {
                        Some(Ok(v)) => v,
                        _ => {
                            return Err(err(
                                Some(lineno),
                                format!("'{}' is not a vertex 'v x y z'", line.trim()),
                            ));
                        }
                    };
                }
                vertex_lines.push(lineno);
                mesh.positions.push(DVec3::from_array(xyz));
            }
            Some("f") => {
                face.clear();
                for w in words {
                    // v, v/vt, v//vn or v/vt/vn: the texture and normal indices must name
                    // lines that exist (they are not used, but a wrong one means a broken file).
                    let mut parts = w.split('/');
                    let v = parts.next().unwrap_or("");
                    for (slot, (what, count)) in
                        parts.zip([("texture coordinate", textures), ("normal", normals)])
                    {
                        if slot.is_empty() {
                            continue;
                        }
                        let k: i64 = slot.parse().map_err(|_| {
                            err(Some(lineno), format!("'{w}' is not a vertex index"))
                        })?;
                        if k == 0 || k > count || k < -count {
                            return Err(err(
                                Some(lineno),
                                format!(
                                    "'{w}' names {what} {k}, but the file has {count} {what}(s) so far"
                                ),
                            ));
                        }
                    }
                    let k: i64 = v
                        .parse()
                        .map_err(|_| err(Some(lineno), format!("'{w}' is not a vertex index")))?;
                    let n = vertex_lines.len() as i64;
                    if k == 0 || k > n || k < -n {
                        return Err(err(
                            Some(lineno),
                            format!(
                                "vertex index {k} is out of range (the file has {n} vertices so far)"
                            ),
                        ));
                    }
                    // A relative index counts back from the vertices read so far.
                    face.push(if k < 0 { n + k } else { k - 1 } as u32);
                }
                if face.len() < 3 {
                    return Err(err(
                        Some(lineno),
                        format!(
                            "a face needs at least 3 vertices, '{}' has {}",
                            line.trim(),
                            face.len()
                        ),
                    ));
                }
                face_lines.push(lineno);
                mesh.push_polygon(&face);
            }
            Some("t") => tags.push((lineno, words.map(str::to_string).collect())),
            Some("vt") => textures += 1,
            Some("vn") => normals += 1,
            _ => {}
        }
    }
    let n = vertex_lines.len();
    let nf = mesh.num_faces();
    let (edge_attrs, subdiv_tags) =
        super::obj_tags::read_tags(&tags, n, nf).map_err(|(line, m)| err(Some(line), m))?;
    Ok(ObjModel {
        mesh,
        edge_attrs,
        tags: subdiv_tags,
        face_lines,
        vertex_lines,
    })
}

/// Writes the lines `fmt` makes for items `0..n` in order, formatting them on every core:
/// batches of 2^17 items are cut into 2^13-item chunks formatted in parallel, then written in
/// order, so the output is the serial one byte for byte and at most one batch of text is held.
fn write_parallel(
    w: &mut dyn IoWrite,
    n: usize,
    fmt: impl Fn(&mut String, &mut zmij::Buffer, usize) + Sync,
) -> std::io::Result<()> {
    use rayon::prelude::*;
    const BATCH: usize = 1 << 17;
    const CHUNK: usize = 1 << 13;
    for start in (0..n).step_by(BATCH) {
        let end = (start + BATCH).min(n);
        let texts: Vec<String> = (start..end)
            .step_by(CHUNK)
            .collect::<Vec<_>>()
            .into_par_iter()
            .map(|a| {
                let mut text = String::with_capacity(48 * CHUNK);
                let mut buf = zmij::Buffer::new();
                for i in a..(a + CHUNK).min(end) {
                    fmt(&mut text, &mut buf, i);
                }
                text
            })
            .collect();
        for t in texts {
            w.write_all(t.as_bytes())?;
        }
    }
    Ok(())
}

/// The number of `v` and `f` lines (an upper bound: a line is counted by its first word).
fn count_records(text: &str) -> (usize, usize) {
    let (mut v, mut f) = (0, 0);
    for line in text.as_bytes().split(|&b| b == b'\n') {
        let t = line.trim_ascii_start();
        match t {
            [b'v', b' ' | b'\t', ..] => v += 1,
            [b'f', b' ' | b'\t', ..] => f += 1,
            _ => {}
        }
    }
    (v, f)
}

/// `x` as the shortest decimal that reads back to the same double, without a trailing `.0`
/// (`1`, `0.25`, `-1.3760693973186022e-15`).
fn number(buf: &mut zmij::Buffer, x: f64) -> &str {
    let s = buf.format(x);
    s.strip_suffix(".0").unwrap_or(s)
}

/// Writes the mesh as OBJ into `w`, streamed; returns the warnings.
pub fn write_obj_to(
    w: &mut dyn IoWrite,
    m: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    normals: Option<Normals>,
) -> std::io::Result<Vec<String>> {
    let mut warnings = Vec::new();
    w.write_all(b"# written by Prism\n")?;
    // `v x y z` or `vn x y z`, each number the shortest that reads back the same.
    let triple = |line: &mut String, buf: &mut zmij::Buffer, tag: &str, p: DVec3| {
        line.push_str(tag);
        for x in [p.x, p.y, p.z] {
            line.push(' ');
            line.push_str(number(buf, x));
        }
        line.push('\n');
    };
    write_parallel(w, m.num_vertices(), |line, buf, i| {
        triple(line, buf, "v", m.positions[i])
    })?;
    // On request, a `vn` per corner, and faces as `v//n`.
    let corner_normals = normals.map(|n| n.corner_normals(m));
    if let Some(cn) = &corner_normals {
        write_parallel(w, cn.len(), |line, buf, i| triple(line, buf, "vn", cn[i]))?;
    }
    let with_normals = corner_normals.is_some();
    let holed = (0..m.num_faces()).filter(|&f| m.face_has_holes(f)).count();
    write_parallel(w, m.num_faces(), |line, _, f| {
        if m.face_has_holes(f) {
            let corner_of: Vec<(u32, usize)> =
                m.face_corners(f).map(|c| (m.corner_verts[c], c)).collect();
            let normal = |v: u32| corner_of.iter().find(|x| x.0 == v).map_or(0, |x| x.1) + 1;
            for t in face_vertex_triangles(m, f) {
                line.push('f');
                for v in t {
                    if with_normals {
                        write!(line, " {}//{}", v + 1, normal(v))
                    } else {
                        write!(line, " {}", v + 1)
                    }
                    .expect("writing to a String");
                }
                line.push('\n');
            }
        } else {
            line.push('f');
            let l = m.face_loops(f).start;
            for (v, c) in m.loop_verts(l).iter().zip(m.loop_corners(l)) {
                if with_normals {
                    write!(line, " {}//{}", v + 1, c + 1)
                } else {
                    write!(line, " {}", v + 1)
                }
                .expect("writing to a String");
            }
            line.push('\n');
        }
    })?;
    let mut tail = String::new();
    super::obj_tags::write_tags(&mut tail, attrs, tags);
    w.write_all(tail.as_bytes())?;
    if holed > 0 && !tags.holes.is_empty() {
        warnings.push(
            "hole tags refer to faces before triangulation; faces with holes and hole tags do not mix in OBJ".into(),
        );
    }
    if holed > 0 {
        warnings.push(format!(
            "OBJ cannot hold faces with holes: {holed} face(s) were triangulated (save as .prism.json to keep them)"
        ));
    }
    if attrs.values().any(|a| a.radius.is_some()) {
        warnings.push("OBJ cannot hold per-edge radii: they were not written (save as .prism.json to keep them)".into());
    }
    Ok(warnings)
}

/// The mesh as OBJ text, plus warnings.
pub fn obj_to_string(m: &PolyMesh, attrs: &EdgeAttrs, tags: &SubdivTags) -> (String, Vec<String>) {
    let mut bytes = Vec::with_capacity(m.num_vertices() * 40 + m.num_corners() * 8);
    let warnings = write_obj_to(&mut bytes, m, attrs, tags, None).expect("writing to memory");
    (
        String::from_utf8(bytes).expect("OBJ text is UTF-8"),
        warnings,
    )
}

/// Writes OBJ atomically, streamed; returns warnings.
pub fn write_obj(
    path: &Path,
    m: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
) -> Result<Vec<String>, IoError> {
    write_obj_with_normals(path, m, attrs, tags, None)
}

/// [`write_obj`] with a `vn` normal per corner when `normals` asks for them (faces written
/// `v//n`).
pub fn write_obj_with_normals(
    path: &Path,
    m: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    normals: Option<Normals>,
) -> Result<Vec<String>, IoError> {
    let mut warnings = Vec::new();
    write_atomically_with(path, |w| {
        warnings = write_obj_to(w, m, attrs, tags, normals)?;
        Ok(())
    })?;
    Ok(warnings)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::edge_attrs::EdgeKey;
    use crate::primitives;

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
        let e =
            read_obj_str(Path::new("t.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n").unwrap_err();
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
}
