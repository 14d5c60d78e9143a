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

mod write;

pub use write::{obj_to_string, write_obj, write_obj_with_normals, write_point_lines};

use super::IoError;
use crate::edge_attrs::EdgeAttrs;
use crate::mesh::PolyMesh;
use crate::progress::Progress;
use crate::tags::SubdivTags;
use glam::DVec3;
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
    read_obj_with(path, &Progress::default())
}

/// Reads an OBJ file, adding to `progress` as it goes (reading the bytes counts half, parsing
/// them the other half) and stopping with [`IoError::Cancelled`] when it is cancelled.
pub fn read_obj_with(path: &Path, progress: &Progress) -> Result<ObjModel, IoError> {
    let bytes = super::read_bytes(path, progress, 2)?;
    parse(path, &bytes, progress)
}

/// Reads OBJ text (`path` is only used in messages).
pub fn read_obj_str(path: &Path, text: &str) -> Result<ObjModel, IoError> {
    parse(path, text.as_bytes(), &Progress::default())
}

/// Bytes of text a parsing chunk takes (cut after a line's end).
const CHUNK: usize = 1 << 22;

/// The counts of a chunk's records, by the first word of each line.
#[derive(Debug, Default, Clone, Copy)]
struct Counts {
    lines: usize,
    v: usize,
    vt: usize,
    vn: usize,
    f: usize,
}

/// The words of a line without its comment, split at whitespace exactly as
/// `str::split_whitespace` splits them (Unicode's White_Space): an ASCII line is split on its
/// bytes, any other by the standard library.
enum Words<'a> {
    Ascii(&'a str, usize),
    Unicode(std::str::SplitWhitespace<'a>),
}

impl<'a> Iterator for Words<'a> {
    type Item = &'a str;
    fn next(&mut self) -> Option<&'a str> {
        // The ASCII characters of White_Space: tab, LF, VT, FF, CR, space.
        let space = |b: u8| matches!(b, b' ' | b'\t'..=b'\r');
        match self {
            Words::Ascii(s, at) => {
                let b = s.as_bytes();
                let mut i = *at;
                while i < b.len() && space(b[i]) {
                    i += 1;
                }
                if i == b.len() {
                    *at = i;
                    return None;
                }
                let start = i;
                while i < b.len() && !space(b[i]) {
                    i += 1;
                }
                *at = i;
                Some(&s[start..i])
            }
            Words::Unicode(w) => w.next(),
        }
    }
}

/// The lines of `text` as `str::lines` cuts them (at `\n`, a `\r` before it dropped), each
/// without its comment (`#` to the end of the line): one `memchr2` a line finds whichever
/// comes first.
fn lines(text: &str) -> impl Iterator<Item = &str> {
    let b = text.as_bytes();
    let mut at = 0;
    std::iter::from_fn(move || {
        if at >= b.len() {
            return None;
        }
        let start = at;
        let line = match memchr::memchr2(b'\n', b'#', &b[start..]) {
            Some(k) if b[start + k] == b'\n' => {
                at = start + k + 1;
                let line = &text[start..start + k];
                line.strip_suffix('\r').unwrap_or(line)
            }
            Some(k) => {
                at = memchr::memchr(b'\n', &b[start + k..]).map_or(b.len(), |e| start + k + e + 1);
                &text[start..start + k]
            }
            None => {
                at = b.len();
                &text[start..]
            }
        };
        Some(line)
    })
}

/// The words of a line without its comment.
fn words(line: &str) -> Words<'_> {
    if line.is_ascii() {
        Words::Ascii(line, 0)
    } else {
        Words::Unicode(line.split_whitespace())
    }
}

/// The statement of a line (its first word) and the words after it. A line that starts
/// with `v`, `vt`, `vn` or `f` and a blank is known by its first bytes; any other is split.
fn statement(raw: &str) -> (Option<&str>, Words<'_>) {
    let keyword = match raw.as_bytes() {
        [b'v', b' ' | b'\t', ..] => Some("v"),
        [b'f', b' ' | b'\t', ..] => Some("f"),
        [b'v', b't', b' ' | b'\t', ..] => Some("vt"),
        [b'v', b'n', b' ' | b'\t', ..] => Some("vn"),
        _ => None,
    };
    match keyword {
        Some(k) => (Some(k), words(&raw[k.len()..])),
        None => {
            let mut w = words(raw);
            (w.next(), w)
        }
    }
}

fn count(text: &str) -> Counts {
    let mut c = Counts::default();
    for raw in lines(text) {
        c.lines += 1;
        match statement(raw).0 {
            Some("v") => c.v += 1,
            Some("vt") => c.vt += 1,
            Some("vn") => c.vn += 1,
            Some("f") => c.f += 1,
            _ => {}
        }
    }
    c
}

/// The text cut into chunks of about [`CHUNK`] bytes, each ending after a line's end (a
/// `\n` is never inside a UTF-8 sequence, so every chunk is checked as UTF-8 on its own).
fn chunks(bytes: &[u8], chunk: usize) -> Vec<&[u8]> {
    let mut out = Vec::with_capacity(bytes.len() / chunk + 1);
    let mut rest = bytes;
    while rest.len() > chunk {
        let cut = match memchr::memchr(b'\n', &rest[chunk..]) {
            Some(k) => chunk + k + 1,
            None => rest.len(),
        };
        let (a, b) = rest.split_at(cut);
        out.push(a);
        rest = b;
    }
    if !rest.is_empty() {
        out.push(rest);
    }
    out
}

/// What one chunk parses into: its faces (global vertex indices) and tag lines; its vertices
/// and the lines of its vertices and faces go straight into the mesh's own arrays.
#[derive(Default)]
struct Parsed {
    corners: Vec<u32>,
    sizes: Vec<u32>,
    tags: Vec<(usize, Vec<String>)>,
}

/// The slots of `v` for the chunks, `counts[i]` each.
fn split_slots<T>(mut v: &mut [T], counts: impl Iterator<Item = usize>) -> Vec<&mut [T]> {
    let mut out = Vec::new();
    for n in counts {
        let (a, b) = v.split_at_mut(n);
        out.push(a);
        v = b;
    }
    out
}

/// Parses OBJ bytes on every core: a first parallel pass counts each chunk's lines and
/// records (by the same first-word test the parse uses, so the counts are exact), which gives
/// every chunk the line, vertex, texture-coordinate and normal numbers it starts from; the
/// chunks are then parsed in parallel into their own slots of the mesh's arrays, and their
/// faces appended in order. Every message is the one a line-by-line reading gives: the
/// first error in file order, with its line.
fn parse(path: &Path, bytes: &[u8], progress: &Progress) -> Result<ObjModel, IoError> {
    parse_in(path, bytes, progress, CHUNK)
}

/// [`parse`] with chunks of about `chunk` bytes.
fn parse_in(
    path: &Path,
    bytes: &[u8],
    progress: &Progress,
    chunk: usize,
) -> Result<ObjModel, IoError> {
    use rayon::prelude::*;
    let err = |line: Option<usize>, message: String| IoError::Obj {
        path: path.into(),
        line,
        message,
    };
    // A UTF-8 byte-order mark is not part of the first line; old Mac files end lines with a
    // bare CR (one not before a LF), which would otherwise make the whole file one line.
    let bytes = bytes.strip_prefix("\u{feff}".as_bytes()).unwrap_or(bytes);
    let bare_cr = memchr::memchr_iter(b'\r', bytes).any(|i| bytes.get(i + 1) != Some(&b'\n'));
    let converted;
    let bytes = if bare_cr {
        converted = String::from_utf8_lossy(bytes)
            .replace("\r\n", "\n")
            .replace('\r', "\n")
            .into_bytes();
        &converted[..]
    } else {
        bytes
    };
    let pieces = chunks(bytes, chunk);
    let texts: Vec<&str> = pieces
        .par_iter()
        .map(|c| std::str::from_utf8(c).map_err(|e| &c[..e.valid_up_to()]))
        .collect::<Vec<_>>()
        .into_iter()
        .enumerate()
        .map(|(k, r)| {
            r.map_err(|valid| {
                let before: usize = pieces[..k]
                    .iter()
                    .map(|c| c.iter().filter(|&&b| b == b'\n').count())
                    .sum();
                let line = before + valid.iter().filter(|&&b| b == b'\n').count() + 1;
                err(Some(line), "the line is not UTF-8 text".into())
            })
        })
        .collect::<Result<_, _>>()?;
    let counts: Vec<Counts> = texts.par_iter().map(|t| count(t)).collect();
    let mut starts = Vec::with_capacity(counts.len());
    let mut at = Counts::default();
    for c in &counts {
        starts.push(at);
        at.lines += c.lines;
        at.v += c.v;
        at.vt += c.vt;
        at.vn += c.vn;
        at.f += c.f;
    }
    let total = at;
    if total.v > u32::MAX as usize {
        return Err(err(
            None,
            format!("{} vertices are more than Prism indexes (2^32)", total.v),
        ));
    }
    let mut positions = vec![DVec3::ZERO; total.v];
    let mut vertex_lines = vec![0usize; total.v];
    let mut face_lines = vec![0usize; total.f];
    let slots = split_slots(&mut positions, counts.iter().map(|c| c.v))
        .into_iter()
        .zip(split_slots(&mut vertex_lines, counts.iter().map(|c| c.v)))
        .zip(split_slots(&mut face_lines, counts.iter().map(|c| c.f)));
    let jobs: Vec<_> = texts.iter().zip(&starts).zip(slots).collect();
    let parsed: Vec<Result<Parsed, IoError>> = jobs
        .into_par_iter()
        .map(|((text, start), ((pos, vlines), flines))| {
            progress
                .check()
                .map_err(|_| IoError::Cancelled { path: path.into() })?;
            let p = parse_chunk(text, start, pos, vlines, flines).map_err(|(l, m)| err(Some(l), m));
            progress.add(text.len() as u64);
            p
        })
        .collect();
    let parsed = parsed.into_iter().collect::<Result<Vec<_>, _>>()?;
    let corners: usize = parsed.iter().map(|p| p.corners.len()).sum();
    if corners > u32::MAX as usize {
        return Err(err(
            None,
            format!("{corners} face corners are more than Prism indexes (2^32)"),
        ));
    }
    let mut mesh = PolyMesh::with_capacity(0, total.f, total.f, corners);
    mesh.positions = positions;
    let mut tags = Vec::new();
    for p in parsed {
        mesh.corner_verts.extend_from_slice(&p.corners);
        let mut end = *mesh
            .loop_starts
            .last()
            .expect("a mesh has its first loop start");
        for s in p.sizes {
            end += s;
            mesh.loop_starts.push(end);
            mesh.face_starts.push((mesh.loop_starts.len() - 1) as u32);
        }
        tags.extend(p.tags);
    }
    let (edge_attrs, subdiv_tags) = super::obj_tags::read_tags(&tags, total.v, total.f)
        .map_err(|(line, m)| err(Some(line), m))?;
    Ok(ObjModel {
        mesh,
        edge_attrs,
        tags: subdiv_tags,
        face_lines,
        vertex_lines,
    })
}

/// One chunk of lines, `start` giving the numbers of the lines and records before it;
/// vertices and the lines of vertices and faces are written into the chunk's slots.
fn parse_chunk(
    text: &str,
    start: &Counts,
    positions: &mut [DVec3],
    vertex_lines: &mut [usize],
    face_lines: &mut [usize],
) -> Result<Parsed, (usize, String)> {
    let mut out = Parsed {
        corners: Vec::with_capacity(4 * face_lines.len()),
        sizes: Vec::with_capacity(face_lines.len()),
        tags: Vec::new(),
    };
    let (mut v, mut f) = (0usize, 0usize);
    let (mut textures, mut normals) = (start.vt as i64, start.vn as i64);
    for (i, raw) in lines(text).enumerate() {
        let lineno = start.lines + i + 1;
        let (first, mut words) = statement(raw);
        match first {
            Some("v") => {
                let mut xyz = [0.0f64; 3];
                for x in &mut xyz {
                    *x = match words.next().map(str::parse::<f64>) {
                        Some(Ok(v)) => v,
                        _ => {
                            return Err((
                                lineno,
                                format!("'{}' is not a vertex 'v x y z'", raw.trim()),
                            ));
                        }
                    };
                }
                positions[v] = DVec3::from_array(xyz);
                vertex_lines[v] = lineno;
                v += 1;
            }
            Some("f") => {
                let n = (start.v + v) as i64;
                let before = out.corners.len();
                for w in words {
                    // v, v/vt, v//vn or v/vt/vn: the texture and normal indices must name
                    // lines that exist (they are not used, but a wrong one means a broken file).
                    let mut parts = w.split('/');
                    let vi = parts.next().unwrap_or("");
                    for (slot, (what, count)) in
                        parts.zip([("texture coordinate", textures), ("normal", normals)])
                    {
                        if slot.is_empty() {
                            continue;
                        }
                        face_index(w, slot, count, |k| {
                            format!(
                                "'{w}' names {what} {k}, but the file has {count} {what}(s) so far"
                            )
                        })
                        .map_err(|e| (lineno, e))?;
                    }
                    let k = face_index(w, vi, n, |k| {
                        format!(
                            "vertex index {k} is out of range (the file has {n} vertices so far)"
                        )
                    })
                    .map_err(|e| (lineno, e))?;
                    out.corners.push(k as u32);
                }
                let size = out.corners.len() - before;
                if size < 3 {
                    return Err((
                        lineno,
                        format!(
                            "a face needs at least 3 vertices, '{}' has {size}",
                            raw.trim(),
                        ),
                    ));
                }
                out.sizes.push(size as u32);
                face_lines[f] = lineno;
                f += 1;
            }
            Some("t") => out.tags.push((lineno, words.map(str::to_string).collect())),
            Some("vt") => textures += 1,
            Some("vn") => normals += 1,
            _ => {}
        }
    }
    Ok(out)
}

/// The 0-based index that `slot` of face word `w` names among the `count` items read so far:
/// 1-based, or negative counting back from the last; `out_of_range` words the error for an
/// index that names no item.
fn face_index(
    w: &str,
    slot: &str,
    count: i64,
    out_of_range: impl FnOnce(i64) -> String,
) -> Result<i64, String> {
    let k: i64 = slot
        .parse()
        .map_err(|_| format!("'{w}' is not a vertex index"))?;
    if k == 0 || k > count || k < -count {
        return Err(out_of_range(k));
    }
    Ok(if k < 0 { count + k } else { k - 1 })
}

#[cfg(test)]
mod tests;
