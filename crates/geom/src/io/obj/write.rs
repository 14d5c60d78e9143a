//! OBJ out: polygons as they are, a face with holes (which OBJ cannot hold) triangulated with
//! `earcutr` in the face's plane and reported as a warning; creases as `t crease` lines,
//! corners, holes and options as their `t` lines. Numbers are the shortest decimals that read
//! back to the same doubles, formatted on every core.

use super::super::{IoError, Normals, write_atomically_with};
use crate::edge_attrs::EdgeAttrs;
use crate::mesh::PolyMesh;
use crate::tags::SubdivTags;
use crate::triangulate::face_vertex_triangles;
use glam::DVec3;
use std::io::Write as IoWrite;
use std::path::Path;

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

/// `x` as the shortest decimal that reads back to the same double, without a trailing `.0`
/// (`1`, `0.25`, `-1.3760693973186022e-15`).
fn number(buf: &mut zmij::Buffer, x: f64) -> &str {
    let s = buf.format(x);
    s.strip_suffix(".0").unwrap_or(s)
}

/// `TAG x y z` lines for `points` (`v`, `vn`), each number the shortest decimal that reads
/// back to the same double, formatted on every core (also `prism limit`'s output).
pub fn write_point_lines(w: &mut dyn IoWrite, tag: &str, points: &[DVec3]) -> std::io::Result<()> {
    write_parallel(w, points.len(), |line, buf, i| {
        line.push_str(tag);
        for x in points[i].to_array() {
            line.push(' ');
            line.push_str(number(buf, x));
        }
        line.push('\n');
    })
}

/// A face corner ` v` or ` v//n` (1-based), the numbers written by `itoa`.
fn corner(line: &mut String, v: usize, normal: Option<usize>) {
    let mut b = itoa::Buffer::new();
    line.push(' ');
    line.push_str(b.format(v));
    if let Some(n) = normal {
        line.push_str("//");
        line.push_str(b.format(n));
    }
}

/// Writes the mesh as OBJ into `w`, streamed; returns the warnings.
fn write_obj_to(
    w: &mut dyn IoWrite,
    m: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    normals: Option<Normals>,
) -> std::io::Result<Vec<String>> {
    let mut warnings = Vec::new();
    w.write_all(b"# written by Prism\n")?;
    write_point_lines(w, "v", &m.positions)?;
    // On request, a `vn` per corner, and faces as `v//n`.
    let corner_normals = normals.map(|n| n.corner_normals(m));
    if let Some(cn) = &corner_normals {
        write_point_lines(w, "vn", cn)?;
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
                    corner(line, v as usize + 1, with_normals.then(|| normal(v)));
                }
                line.push('\n');
            }
        } else {
            line.push('f');
            let l = m.face_loops(f).start;
            for (v, c) in m.loop_verts(l).iter().zip(m.loop_corners(l)) {
                corner(line, *v as usize + 1, with_normals.then_some(c + 1));
            }
            line.push('\n');
        }
    })?;
    let mut tail = String::new();
    super::super::obj_tags::write_tags(&mut tail, attrs, tags);
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
    if attrs
        .values()
        .any(|a| a.radius.is_some() || a.fits.is_some())
    {
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
    super::super::check_finite_points(path, m)?;
    let mut warnings = Vec::new();
    write_atomically_with(path, |w| {
        warnings = write_obj_to(w, m, attrs, tags, normals)?;
        Ok(())
    })?;
    Ok(warnings)
}
