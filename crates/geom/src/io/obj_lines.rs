//! The polylines of an OBJ: its `v` positions and `l` statements (what `prism envelope
//! --curves` and the curve exports write), for drawing them. Indices are 1-based or negative
//! (relative to the vertices read so far), `v/vt` forms keep their first number; every other
//! statement is skipped. Errors name the line.

use super::IoError;
use glam::DVec3;
use std::path::Path;

/// The polylines of OBJ text `text` (read from `path`, for messages), in file order.
pub fn polylines_from_str(path: &Path, text: &str) -> Result<Vec<Vec<DVec3>>, IoError> {
    let fail = |line: usize, message: String| IoError::Obj {
        path: path.to_path_buf(),
        line: Some(line),
        message,
    };
    let mut positions: Vec<DVec3> = Vec::new();
    let mut lines = Vec::new();
    for (k, raw) in text.lines().enumerate() {
        let n = k + 1;
        let body = raw.split('#').next().unwrap_or("");
        let mut words = body.split_whitespace();
        match words.next() {
            Some("v") => {
                let mut c = [0.0; 3];
                for x in &mut c {
                    *x = match words.next().map(str::parse::<f64>) {
                        Some(Ok(v)) if v.is_finite() => v,
                        _ => return Err(fail(n, "a vertex needs three finite numbers".into())),
                    };
                }
                positions.push(DVec3::from_array(c));
            }
            Some("l") => {
                let mut line = Vec::new();
                for w in words {
                    let first = w.split('/').next().unwrap_or("");
                    let i: i64 = first
                        .parse()
                        .map_err(|_| fail(n, format!("'{w}' is not a vertex index")))?;
                    let count = positions.len() as i64;
                    let at = if i < 0 { count + i } else { i - 1 };
                    if i == 0 || !(0..count).contains(&at) {
                        return Err(fail(
                            n,
                            format!("vertex {i} does not exist ({count} read so far)"),
                        ));
                    }
                    line.push(positions[at as usize]);
                }
                if line.len() < 2 {
                    return Err(fail(n, "a line needs at least two vertices".into()));
                }
                lines.push(line);
            }
            _ => {}
        }
    }
    Ok(lines)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polylines_are_read_with_relative_indices_and_bad_ones_named() {
        let p = Path::new("c.obj");
        let text = "# two\nv 0 0 0\nv 1 0 0\nv 1 1 0 # a comment\nl 1 2 3\nf 1 2 3\nl -1/1 -3\n";
        let l = polylines_from_str(p, text).unwrap();
        assert_eq!(l.len(), 2);
        assert_eq!(l[0], vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0)]);
        assert_eq!(l[1], vec![DVec3::new(1.0, 1.0, 0.0), DVec3::ZERO]);
        for (bad, line, says) in [
            ("v 0 0 0\nl 1 2\n", 2, "vertex 2 does not exist"),
            ("v 0 0\n", 1, "three finite numbers"),
            ("v 0 0 0\nv 1 1 1\nl 1 x\n", 3, "'x' is not"),
            ("v 0 0 0\nl 1\n", 2, "at least two"),
        ] {
            let e = polylines_from_str(p, bad).unwrap_err().to_string();
            assert!(
                e.contains(&format!("line {line}")) && e.contains(says),
                "{e}"
            );
        }
    }
}
