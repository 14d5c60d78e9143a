//! A primitive's curved network, trimmed by its silhouette plane (seed 004 §5.1;
//! ALGORITHMS §11.2–11.3; docs/algorithms/envelope.md).
//!
//! With the view vector d towards the partner, the silhouette plane Π passes through the
//! primitive's centre G normal to d and the primitive keeps `(x − G)·k ≤ 0` (k = d for the
//! first of a pair, −d for the second). A curved edge that crosses Π meets it once (it lies in a
//! plane through G and is an arc of central angle < π): the **silhouette point** S is the root
//! of `(C(τ) − G)·k` (bisection to 1e-15), and the kept piece from the kept vertex to S is
//! **rebuilt** with §6.3 so that at S too its tangent is normal to S − G, with t at S
//! interpolated between the edge's ends by central angle (for t = 1 the pieces are arcs of the
//! same great circle and nothing changes). Where no such arc exists — the rebuilt piece would
//! leave A or reach S backwards (a hook), as when S is much nearer G than A at a small central
//! angle (small t) — the edge's own piece up to S is kept, and S's tangent plane is the one
//! through that piece's tangent and the silhouette loop's. A face cut by Π keeps its part on the kept side,
//! closed by a **silhouette edge** from where its boundary leaves the kept side to where it
//! comes back, built in Π with §6.3 (centre G, ρ = t·|S − G| at each end). A kept face's edge
//! that lies in Π beside a removed face is a silhouette edge as it is. The silhouette edges
//! form the **silhouette loop**, which the fusion quads join to the partner's.

use super::EnvelopeError;
use super::edges::curved_edge;
use super::network::{CurveKind, Network, PatchSide, Region, RegionKind};
use super::primitive::Primitive;
use glam::DVec3;
use std::collections::HashMap;

/// Relative tolerance (of r) for "on the silhouette plane".
const ON_PLANE: f64 = 1e-9;

/// The silhouette loop of a trimmed primitive: its edges in the order and direction the kept
/// faces run along them (each a whole network curve).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SilhouetteLoop {
    pub edges: Vec<PatchSide>,
}

/// Adds primitive `index` to `net`, trimmed to `(x − G)·k ≤ 0` when `keep` is `Some(k)`
/// (unit k): its kept vertices, silhouette points, curves and regions. Returns the silhouette
/// loop (empty when nothing was cut).
pub fn add_primitive(
    net: &mut Network,
    p: &Primitive,
    index: usize,
    keep: Option<DVec3>,
) -> Result<SilhouetteLoop, EnvelopeError> {
    let g = p.centre;
    let tol = ON_PLANE * p.radius;
    let side: Vec<f64> = p
        .vertices
        .iter()
        .map(|v| match keep {
            Some(k) => {
                let s = (*v - g).dot(k);
                if s.abs() <= tol { 0.0 } else { s }
            }
            None => -1.0,
        })
        .collect();
    let bad_edge = |a: usize, b: usize| EnvelopeError::Primitive {
        index,
        why: format!("edge {a}-{b} cannot be curved (through or opposite the centre)"),
    };
    // Network vertices of the kept original vertices.
    let mut vid: Vec<Option<usize>> = vec![None; p.vertices.len()];
    for (i, v) in p.vertices.iter().enumerate() {
        if side[i] <= 0.0 {
            vid[i] = Some(net.add_vertex(*v, (*v - g).normalize(), p.t[i] * v.distance(g)));
        }
    }
    // Whole kept edges and crossed edges (the kept piece, from the kept vertex to S), by the
    // directed edge of the first face that meets them.
    let mut whole: HashMap<(usize, usize), usize> = HashMap::new();
    let mut crossed: HashMap<(usize, usize), (usize, usize)> = HashMap::new(); // → (curve, S)
    let mut whole_edge =
        |net: &mut Network, a: usize, b: usize| -> Result<PatchSide, EnvelopeError> {
            if let Some(&c) = whole.get(&(b, a)) {
                return Ok(PatchSide::whole(c, false));
            }
            let bez = curved_edge(g, p.vertices[a], p.vertices[b], p.t[a], p.t[b])
                .ok_or_else(|| bad_edge(a, b))?;
            let (va, vb) = (vid[a].expect("kept"), vid[b].expect("kept"));
            let c = net.add_curve(bez, va, vb, CurveKind::Edge);
            whole.insert((a, b), c);
            Ok(PatchSide::whole(c, true))
        };
    // The kept piece of crossed edge (kept vertex a, removed vertex b): curve from a to S.
    let mut kept_piece =
        |net: &mut Network, a: usize, b: usize| -> Result<(usize, usize), EnvelopeError> {
            let key = (a.min(b), a.max(b));
            if let Some(&found) = crossed.get(&key) {
                return Ok(found);
            }
            let k = keep.expect("a crossed edge has a plane");
            let full = curved_edge(g, p.vertices[a], p.vertices[b], p.t[a], p.t[b])
                .ok_or_else(|| bad_edge(a, b))?;
            let f = |tau: f64| (full.eval(tau) - g).dot(k);
            let (mut lo, mut hi) = (0.0, 1.0);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if f(mid) <= 0.0 { lo = mid } else { hi = mid }
            }
            let s = full.eval(0.5 * (lo + hi));
            let (va, vb) = (p.vertices[a] - g, p.vertices[b] - g);
            let angle = |x: DVec3, y: DVec3| x.cross(y).length().atan2(x.dot(y));
            let share = angle(va, s - g) / angle(va, vb).max(f64::MIN_POSITIVE);
            let ts = p.t[a] + (p.t[b] - p.t[a]) * share;
            let tau = 0.5 * (lo + hi);
            let rebuilt =
                curved_edge(g, p.vertices[a], s, p.t[a], ts).ok_or_else(|| bad_edge(a, b))?;
            let chord = s - p.vertices[a];
            let hooks = |c: &crate::freeform::bezier::RationalBezier| {
                c.derivatives(0.0).d1.dot(chord) <= 0.0 || c.derivatives(1.0).d1.dot(chord) <= 0.0
            };
            let (bez, normal) = if hooks(&rebuilt) {
                // No convex arc leaves A and reaches S normal to both radii (|A − G|cos γ >
                // |S − G|): the edge's own piece up to S instead. Its tangent at S is not
                // normal to S − G, so S's tangent plane is the one through it and the loop's.
                let piece = full.split(tau).0;
                let along = piece.derivatives(1.0).d1;
                let loop_dir = k.cross(s - g);
                let mut n = loop_dir.cross(along).normalize();
                if n.dot(s - g) < 0.0 {
                    n = -n;
                }
                (piece, n)
            } else {
                (rebuilt, (s - g).normalize())
            };
            let vs = net.add_vertex(s, normal, ts * s.distance(g));
            let c = net.add_curve(bez, vid[a].expect("kept"), vs, CurveKind::Edge);
            crossed.insert(key, (c, vs));
            Ok((c, vs))
        };
    let mut silhouette = SilhouetteLoop::default();
    let t_of = |net: &Network, v: usize| net.vertices[v].rho / net.vertices[v].position.distance(g);
    for (f, face) in p.faces.iter().enumerate() {
        let m = face.len();
        let s: Vec<f64> = face.iter().map(|&v| side[v]).collect();
        if s.iter().all(|&x| x >= 0.0) && s.iter().any(|&x| x > 0.0) {
            // Removed; a kept neighbour's in-plane edge becomes a silhouette edge below.
            continue;
        }
        let mut sides: Vec<PatchSide> = Vec::with_capacity(m + 2);
        // Where the boundary leaves the kept side (index in `sides` to insert the
        // silhouette edge at, and the vertex) and where it comes back.
        let mut exit: Option<(usize, usize)> = None;
        let mut entry: Option<usize> = None;
        for i in 0..m {
            let (a, b) = (face[i], face[(i + 1) % m]);
            let (sa, sb) = (s[i], s[(i + 1) % m]);
            if sa <= 0.0 && sb <= 0.0 {
                sides.push(whole_edge(net, a, b)?);
            } else if sa < 0.0 && sb > 0.0 {
                let (c, vs) = kept_piece(net, a, b)?;
                sides.push(PatchSide::whole(c, true));
                exit = Some((sides.len(), vs));
            } else if sa > 0.0 && sb < 0.0 {
                let (c, vs) = kept_piece(net, b, a)?;
                entry = Some(vs);
                sides.push(PatchSide::whole(c, false));
            } else if sa == 0.0 && sb > 0.0 {
                exit = Some((sides.len(), vid[a].expect("on the plane: kept")));
            } else if sa > 0.0 && sb == 0.0 {
                entry = Some(vid[b].expect("on the plane: kept"));
            }
        }
        match (exit, entry) {
            (Some((at, x)), Some(y)) => {
                let (px, py) = (net.vertices[x].position, net.vertices[y].position);
                let bez = curved_edge(g, px, py, t_of(net, x), t_of(net, y)).ok_or_else(|| {
                    EnvelopeError::Primitive {
                        index,
                        why: format!("face {f}: its silhouette edge cannot be curved"),
                    }
                })?;
                let c = net.add_curve(bez, x, y, CurveKind::Silhouette);
                sides.insert(at, PatchSide::whole(c, true));
                silhouette.edges.push(PatchSide::whole(c, true));
            }
            (None, None) => {}
            _ => {
                return Err(EnvelopeError::Primitive {
                    index,
                    why: format!("face {f} is cut by the silhouette plane at one point only"),
                });
            }
        }
        net.regions.push(Region {
            sides,
            kind: RegionKind::Primitive {
                primitive: index,
                face: f,
            },
        });
    }
    // Kept faces' edges in the plane beside a removed face.
    if keep.is_some() {
        let removed = |f: usize| {
            let s: Vec<f64> = p.faces[f].iter().map(|&v| side[v]).collect();
            s.iter().all(|&x| x >= 0.0) && s.iter().any(|&x| x > 0.0)
        };
        let mut face_of: HashMap<(usize, usize), usize> = HashMap::new();
        for (f, face) in p.faces.iter().enumerate() {
            for i in 0..face.len() {
                face_of.insert((face[i], face[(i + 1) % face.len()]), f);
            }
        }
        for (&(a, b), &f) in &face_of {
            if !removed(f)
                && side[a] == 0.0
                && side[b] == 0.0
                && face_of.get(&(b, a)).is_some_and(|&o| removed(o))
            {
                let c = whole[&(a, b)];
                net.curves[c].kind = CurveKind::Silhouette;
                silhouette.edges.push(PatchSide::whole(c, true));
            }
        }
    }
    Ok(silhouette)
}
