//! A flat face of a primitive clipped by the cut half-spaces (Sutherland–Hodgman): the kept
//! convex polygon, each corner saying where it lies on the primitive (a vertex, an edge a cut
//! crosses, inside the face where two cuts cross) and what the side from it runs along.

use super::super::primitive::Primitive;
use glam::DVec3;

/// Where a corner of a clipped face lies on the primitive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum At {
    Vertex(usize),
    /// On edge (a, b), a < b, where cut `cut` crosses it.
    Edge {
        a: usize,
        b: usize,
        cut: usize,
    },
    /// Inside face `face`, where two cuts cross.
    Inside {
        face: usize,
        cuts: [usize; 2],
    },
}

/// What the side from a corner to the next runs along.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Along {
    /// The primitive's edge between these vertices.
    Edge(usize, usize),
    Cut(usize),
}

#[derive(Debug, Clone, Copy)]
pub(super) struct Corner {
    pub flat: DVec3,
    pub at: At,
    pub along: Along,
}

/// The face clipped by every cut, as a convex polygon of corners (empty when nothing is kept).
pub(super) fn clip_face(p: &Primitive, f: usize, cuts: &[DVec3], tol: f64) -> Vec<Corner> {
    let face = &p.faces[f];
    let m = face.len();
    let mut poly: Vec<Corner> = (0..m)
        .map(|i| Corner {
            flat: p.vertices[face[i]],
            at: At::Vertex(face[i]),
            along: Along::Edge(face[i], face[(i + 1) % m]),
        })
        .collect();
    for (k, &d) in cuts.iter().enumerate() {
        let s: Vec<f64> = poly
            .iter()
            .map(|c| {
                let x = (c.flat - p.centre).dot(d);
                if x.abs() <= tol { 0.0 } else { x }
            })
            .collect();
        if s.iter().all(|&x| x <= 0.0) {
            continue;
        }
        let crossing = |cur: Corner, nxt: Corner, sc: f64, sn: f64| Corner {
            flat: cur.flat + (nxt.flat - cur.flat) * (sc / (sc - sn)),
            at: match cur.along {
                Along::Edge(a, b) => At::Edge {
                    a: a.min(b),
                    b: a.max(b),
                    cut: k,
                },
                Along::Cut(l) => At::Inside {
                    face: f,
                    cuts: [l, k],
                },
            },
            along: cur.along,
        };
        let n = poly.len();
        let mut out = Vec::with_capacity(n + 1);
        for i in 0..n {
            let (cur, nxt) = (poly[i], poly[(i + 1) % n]);
            let (sc, sn) = (s[i], s[(i + 1) % n]);
            if sc <= 0.0 {
                if sn <= 0.0 {
                    out.push(cur);
                } else if sc < 0.0 {
                    out.push(cur);
                    out.push(Corner {
                        along: Along::Cut(k),
                        ..crossing(cur, nxt, sc, sn)
                    });
                } else {
                    out.push(Corner {
                        along: Along::Cut(k),
                        ..cur
                    });
                }
            } else if sn < 0.0 {
                out.push(crossing(cur, nxt, sc, sn));
            }
        }
        poly = out;
        if poly.len() < 3 {
            return Vec::new();
        }
    }
    poly
}
