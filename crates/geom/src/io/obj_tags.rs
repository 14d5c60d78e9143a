//! OpenSubdiv's OBJ tag lines (`regression/common/shape_utils.cpp`):
//! `t NAME COUNTS ints… floats… strings…` with `COUNTS` = `i/f/s` (also accepted spelled as
//! separate numbers, `2 1` or `2 1 0`).
//!
//! | tag | meaning |
//! | --- | --- |
//! | `t crease 2/1/0 a b s` | edge a–b has sharpness s (more vertices: a chain of edges) |
//! | `t corner 1/1/0 v s` | vertex v has sharpness s |
//! | `t interpolateboundary 1/0/0 k` | 0 none, 1 edge and corner, 2 edge only |
//! | `t creasemethod 0/0/1 chaikin` | `normal` or `chaikin` |
//! | `t smoothtriangles 0/0/1 smooth` | `catmark` or `smooth` |
//! | `t hole n/0/0 f…` | faces that are holes |
//!
//! Other tags (face-varying options) do not change vertex positions and are skipped.

use crate::edge_attrs::{EdgeAttrs, EdgeKey};
use crate::tags::{BoundaryInterpolation, CreaseMethod, SubdivTags, TriangleSubdivision};
use std::fmt::Write as _;

/// A parsed tag line.
struct Tag<'a> {
    name: &'a str,
    ints: Vec<i64>,
    floats: Vec<f64>,
    strings: Vec<&'a str>,
}

fn parse_tag(words: &[String]) -> Result<Tag<'_>, String> {
    let name = words.first().ok_or("a tag line needs a name")?.as_str();
    let rest = &words[1..];
    let first = rest.first().ok_or("a tag line needs its counts 'i/f/s'")?;
    let (counts, args): (Vec<usize>, &[String]) = if first.contains('/') {
        let c: Result<Vec<usize>, _> = first.split('/').map(str::parse).collect();
        (
            c.map_err(|_| format!("'{first}' are not counts i/f/s"))?,
            &rest[1..],
        )
    } else {
        // Counts spelled as numbers: two (ints, floats) or three (…, strings); pick the one
        // that accounts for every word.
        let num = |k: usize| rest.get(k).and_then(|w| w.parse::<usize>().ok());
        let (i, f) = (
            num(0).ok_or("a tag line needs its counts")?,
            num(1).ok_or("a tag line needs its counts")?,
        );
        match num(2) {
            Some(s)
                if [3, i, f, s]
                    .iter()
                    .try_fold(0usize, |a, &b| a.checked_add(b))
                    == Some(rest.len()) =>
            {
                (vec![i, f, s], &rest[3..])
            }
            _ => (vec![i, f], &rest[2..]),
        }
    };
    let (ni, nf) = (
        counts.first().copied().unwrap_or(0),
        counts.get(1).copied().unwrap_or(0),
    );
    let ns = counts.get(2).copied().unwrap_or(0);
    // Counts come from the file: added with overflow checks (u64::MAX/1/0 must be an error,
    // not a panic).
    let total = ni.checked_add(nf).and_then(|x| x.checked_add(ns));
    if total.is_none_or(|t| args.len() < t) {
        return Err(format!(
            "tag '{name}' announces {ni} integers, {nf} floats, {ns} strings but has {} values",
            args.len()
        ));
    }
    let ints = args[..ni]
        .iter()
        .map(|w| {
            w.parse::<i64>()
                .map_err(|_| format!("'{w}' is not an integer"))
        })
        .collect::<Result<_, _>>()?;
    let floats = args[ni..ni + nf]
        .iter()
        .map(|w| match w.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(format!("'{w}' is not a finite number")),
        })
        .collect::<Result<_, _>>()?;
    let strings = args[ni + nf..ni + nf + ns]
        .iter()
        .map(String::as_str)
        .collect();
    Ok(Tag {
        name,
        ints,
        floats,
        strings,
    })
}

/// Reads the tag lines into edge creases and subdivision tags; an error names the line.
pub(super) fn read_tags(
    lines: &[(usize, Vec<String>)],
    vertices: usize,
    faces: usize,
) -> Result<(EdgeAttrs, SubdivTags), (usize, String)> {
    let mut attrs = EdgeAttrs::new();
    let mut tags = SubdivTags::default();
    let vertex = |k: i64, line: usize| -> Result<u32, (usize, String)> {
        if k >= 0 && (k as usize) < vertices {
            Ok(k as u32)
        } else {
            Err((
                line,
                format!("vertex {k} is out of range (the file has {vertices} vertices)"),
            ))
        }
    };
    let sharpness = |x: f64, line: usize| -> Result<f64, (usize, String)> {
        if x >= 0.0 {
            Ok(x)
        } else {
            Err((line, format!("sharpness {x} is negative")))
        }
    };
    for (line, words) in lines {
        let line = *line;
        let tag = parse_tag(words).map_err(|m| (line, m))?;
        match tag.name {
            "crease" => {
                if tag.ints.len() < 2 || tag.floats.is_empty() {
                    return Err((line, "expected 't crease 2/1/0 a b sharpness'".into()));
                }
                for (k, w) in tag.ints.windows(2).enumerate() {
                    let (a, b) = (vertex(w[0], line)?, vertex(w[1], line)?);
                    let s = sharpness(*tag.floats.get(k).unwrap_or(&tag.floats[0]), line)?;
                    attrs.entry(EdgeKey::new(a, b)).or_default().crease = s;
                }
            }
            "corner" => {
                if tag.ints.is_empty() || tag.floats.is_empty() {
                    return Err((line, "expected 't corner 1/1/0 v sharpness'".into()));
                }
                for (k, &v) in tag.ints.iter().enumerate() {
                    let s = sharpness(*tag.floats.get(k).unwrap_or(&tag.floats[0]), line)?;
                    tags.corners.insert(vertex(v, line)?, s);
                }
            }
            "hole" => {
                for &f in &tag.ints {
                    if f < 0 || f as usize >= faces {
                        return Err((
                            line,
                            format!("face {f} is out of range (the file has {faces} faces)"),
                        ));
                    }
                    tags.holes.insert(f as u32);
                }
            }
            "interpolateboundary" => {
                let k = tag.ints.first().copied().unwrap_or(-1);
                tags.boundary = BoundaryInterpolation::from_obj(k).ok_or((
                    line,
                    format!("interpolateboundary {k}: expected 0 (none), 1 (edge and corner) or 2 (edge only)"),
                ))?;
            }
            "creasemethod" => {
                tags.crease_method = match tag.strings.first().copied() {
                    Some("chaikin") => CreaseMethod::Chaikin,
                    Some("normal" | "uniform") => CreaseMethod::Uniform,
                    other => {
                        return Err((
                            line,
                            format!("creasemethod {other:?}: expected normal or chaikin"),
                        ));
                    }
                }
            }
            "smoothtriangles" => {
                tags.triangles = match tag.strings.first().copied() {
                    Some("smooth") => TriangleSubdivision::Smooth,
                    Some("catmark") => TriangleSubdivision::Catmark,
                    other => {
                        return Err((
                            line,
                            format!("smoothtriangles {other:?}: expected catmark or smooth"),
                        ));
                    }
                }
            }
            _ => {}
        }
    }
    Ok((attrs, tags))
}

/// Appends the tag lines for `attrs` and `tags` to OBJ text.
pub(super) fn write_tags(s: &mut String, attrs: &EdgeAttrs, tags: &SubdivTags) {
    if tags.boundary != BoundaryInterpolation::EdgeOnly {
        let _ = writeln!(s, "t interpolateboundary 1/0/0 {}", tags.boundary.to_obj());
    }
    if tags.crease_method == CreaseMethod::Chaikin {
        s.push_str("t creasemethod 0/0/1 chaikin\n");
    }
    if tags.triangles == TriangleSubdivision::Smooth {
        s.push_str("t smoothtriangles 0/0/1 smooth\n");
    }
    for (k, a) in attrs {
        if a.crease > 0.0 {
            let _ = writeln!(s, "t crease 2/1/0 {} {} {}", k.0, k.1, a.crease);
        }
    }
    for (v, sharp) in &tags.corners {
        if *sharp > 0.0 {
            let _ = writeln!(s, "t corner 1/1/0 {v} {sharp}");
        }
    }
    if !tags.holes.is_empty() {
        let _ = write!(s, "t hole {}/0/0", tags.holes.len());
        for f in &tags.holes {
            let _ = write!(s, " {f}");
        }
        s.push('\n');
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(text: &str) -> Vec<(usize, Vec<String>)> {
        text.lines()
            .enumerate()
            .map(|(i, l)| {
                (
                    i + 1,
                    l.split_whitespace().skip(1).map(String::from).collect(),
                )
            })
            .collect()
    }

    #[test]
    fn reads_every_tag_and_both_spellings() {
        let text = "t crease 2/1/0 0 1 2.5\nt crease 2 1 1 2 10\nt corner 1/1/0 3 4\n\
                    t interpolateboundary 1/0/0 1\nt creasemethod 0/0/1 chaikin\n\
                    t smoothtriangles 0/0/1 smooth\nt hole 2/0/0 0 1\nt facevaryinginterpolateboundary 1/0/0 1";
        let (a, t) = read_tags(&lines(text), 4, 2).unwrap();
        assert_eq!(a[&EdgeKey::new(0, 1)].crease, 2.5);
        assert_eq!(a[&EdgeKey::new(1, 2)].crease, 10.0);
        assert_eq!(t.corners[&3], 4.0);
        assert_eq!(t.boundary, BoundaryInterpolation::EdgeAndCorner);
        assert_eq!(t.crease_method, CreaseMethod::Chaikin);
        assert_eq!(t.triangles, TriangleSubdivision::Smooth);
        assert_eq!(t.holes.len(), 2);
        let mut s = String::new();
        write_tags(&mut s, &a, &t);
        let (a2, t2) = read_tags(&lines(&s), 4, 2).unwrap();
        assert_eq!((a2, t2), (a, t));
    }

    #[test]
    fn bad_tags_name_the_line() {
        let e = read_tags(&lines("t crease 2/1/0 0 1 2\nt crease 2/1/0 0 9 1"), 4, 1).unwrap_err();
        assert_eq!(e.0, 2);
        assert!(e.1.contains("vertex 9"), "{}", e.1);
        let e = read_tags(&lines("t hole 1/0/0 5"), 4, 1).unwrap_err();
        assert!(e.1.contains("face 5"));
        let e = read_tags(&lines("t interpolateboundary 1/0/0 7"), 4, 1).unwrap_err();
        assert!(e.1.contains("interpolateboundary 7"));
    }
}
