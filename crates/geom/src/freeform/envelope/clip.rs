//! A primitive's curved network, trimmed by the silhouette planes towards its hull neighbours
//! (seed 004 §5.1; docs/algorithms/envelope.md, "The network for two primitives").
//!
//! Every cut k is a plane Π_k through the primitive's centre G with unit normal `d_k` (towards
//! the partner), and the primitive keeps `(x − G)·d_k ≤ 0` for all k. All of the primitive's
//! curves lie in planes through G (a curved edge in the plane of G and its two ends, a
//! silhouette edge in its Π_k), so which part of the curved primitive is kept is decided in
//! **directions** from G, and those are the directions of the flat polyhedron: each flat face is
//! clipped by the half-spaces as a convex polygon (Sutherland–Hodgman, points within 10⁻⁹ r of
//! a plane taken as on it), and every corner and side of a kept polygon is then mapped onto the
//! curved primitive:
//! - an original vertex stays;
//! - a point where Π_k crosses an edge is the **silhouette point** S on the curved edge in that
//!   direction (bisection to 10⁻¹⁵), its t interpolated between the edge's ends by central
//!   angle;
//! - a point inside a face where Π_k and Π_l cross (a section **cut again**, §5.1.3: the corner
//!   of a pie-slice section) lies on the ray along Π_k ∩ Π_l; its distance from G is the mean of
//!   where the two whole silhouette edges of that face (each built across the face as if the
//!   other cut were not there) cross the ray, and its t the mean of theirs (on the sphere at
//!   t = 1, on the flat face as t → 0), each weighted by 1/d² with d the distance there from
//!   that silhouette edge's nearer end — a corner near a primitive's edge lies at the distance
//!   of the silhouette point beside it, as its normal along the radius needs; and corners of
//!   one face a few hundredths of r apart are drawn to one distance (a face crossed by three
//!   cuts nearly at one point);
//! - a side along an edge is the curved edge (whole), or the kept piece **rebuilt** with §6.3
//!   between its ends so that its tangent at S is normal to S − G too; where the rebuilt piece
//!   would hook — leave its end or arrive backwards, when no convex arc is normal to both radii
//!   (`|A − G| cos γ > |S − G|`: small t, a plane cutting near a corner) — or nearly does (a
//!   leg under 5 % of the chord), the polynomial cubic normal to both radii, legs a third of
//!   the chord for t ≥ ½ and 2t thirds below (an inflection where it hooks; tending to the
//!   chord as t → 0 like the edges beside it), so that S keeps its tangent plane normal to
//!   S − G, which holds d;
//! - a side along Π_k is a **silhouette edge**, built in Π_k with §6.3 between its ends
//!   (ρ = t·|P − G| at each), or, where that hooks or nearly does (a leg under 15 % of the
//!   chord: a straight-looking curve whose parameter crowds at one end), the polynomial cubic
//!   along the section's tangents with legs of a third of the chord; a kept side along an
//!   edge that lies in Π_k is one as it is.
//!
//! The silhouette edges on Π_k, in the direction the kept faces run along them, are the
//! **section** facing partner k: a closed loop when nothing else cuts Π_k, otherwise a chain
//! between the two rays where the neighbouring cuts cross it (the straight edges of §5.1.3,
//! which end inside the solid and are not curves of the network).

use super::EnvelopeError;
use super::edges::{curved_edge, legs_for};
use super::network::{CurveKind, Network, PatchSide, Region, RegionKind};
use super::primitive::Primitive;
use crate::freeform::bezier::RationalBezier;
use crate::freeform::envelope::tolerances::TOLERANCES;
use glam::DVec3;
use std::collections::HashMap;

mod curves;
mod face;

use curves::{angle, at_direction, hooks, third_cubic};
use face::{Along, At, Corner, clip_face};

/// [`TOLERANCES`]`.on_plane`.
const ON_PLANE: f64 = TOLERANCES.on_plane;

/// [`TOLERANCES`]`.near_inside`.
const NEAR_INSIDE: f64 = TOLERANCES.near_inside;

/// [`TOLERANCES`]`.same_direction`.
const SAME_DIRECTION: f64 = TOLERANCES.same_direction;

/// [`TOLERANCES`]`.direction_cell`.
const DIRECTION_CELL: f64 = TOLERANCES.direction_cell;

fn direction_cell(u: DVec3) -> [i64; 3] {
    (u / DIRECTION_CELL).floor().as_i64vec3().to_array()
}

/// [`TOLERANCES`]`.near_hook`.
const NEAR_HOOK: f64 = TOLERANCES.near_hook;

/// [`TOLERANCES`]`.near_hook_edge`.
const NEAR_HOOK_EDGE: f64 = TOLERANCES.near_hook_edge;

/// A point located on the curved primitive.
#[derive(Debug, Clone, Copy)]
struct Located {
    position: DVec3,
    t: f64,
}

struct Clipper<'a> {
    p: &'a Primitive,
    index: usize,
    cuts: &'a [DVec3],
    tol: f64,
    /// (unit direction, network vertex, where) of every vertex added.
    points: Vec<(DVec3, usize, At)>,
    /// The points by cell of their direction ([`DIRECTION_CELL`]) and by network vertex, so
    /// that a primitive of many faces finds them without a scan.
    by_cell: HashMap<[i64; 3], Vec<usize>>,
    by_vertex: HashMap<usize, usize>,
    /// Whole curved edges, (a, b) with a < b, from a to b.
    full: HashMap<(usize, usize), RationalBezier>,
    /// Curves by their (unordered) end vertices.
    curves: HashMap<(usize, usize), usize>,
    /// Legs of a replacing cubic bounded so that it turns one way about G (the charts).
    monotone: bool,
}

impl Clipper<'_> {
    fn bad_edge(&self, a: usize, b: usize) -> EnvelopeError {
        EnvelopeError::Primitive {
            index: self.index,
            why: format!("edge {a}-{b} cannot be curved (through or opposite the centre)"),
        }
    }

    fn full_edge(&mut self, a: usize, b: usize) -> Result<RationalBezier, EnvelopeError> {
        if let Some(c) = self.full.get(&(a, b)) {
            return Ok(c.clone());
        }
        let p = self.p;
        let c = curved_edge(p.centre, p.vertices[a], p.vertices[b], p.t[a], p.t[b])
            .ok_or_else(|| self.bad_edge(a, b))?;
        self.full.insert((a, b), c.clone());
        Ok(c)
    }

    /// The curved point on edge (a, b) in direction u.
    fn on_edge(&mut self, a: usize, b: usize, u: DVec3) -> Result<Located, EnvelopeError> {
        let c = self.full_edge(a, b)?;
        let g = self.p.centre;
        let tau = at_direction(&c, g, u);
        let position = c.eval(tau);
        let (va, vb) = (self.p.vertices[a] - g, self.p.vertices[b] - g);
        let share = angle(va, position - g) / angle(va, vb).max(f64::MIN_POSITIVE);
        Ok(Located {
            position,
            t: self.p.t[a] + (self.p.t[b] - self.p.t[a]) * share,
        })
    }

    /// Where cut `k`'s line crosses the boundary of face `f` (unclipped): its two ends.
    fn face_line(&mut self, f: usize, k: usize) -> Result<Vec<Located>, EnvelopeError> {
        let p = self.p;
        let face = &p.faces[f];
        let m = face.len();
        let s: Vec<f64> = face
            .iter()
            .map(|&v| {
                let x = (p.vertices[v] - p.centre).dot(self.cuts[k]);
                if x.abs() <= self.tol { 0.0 } else { x }
            })
            .collect();
        let mut ends = Vec::new();
        for i in 0..m {
            let (a, b) = (face[i], face[(i + 1) % m]);
            let (sa, sb) = (s[i], s[(i + 1) % m]);
            if sa == 0.0 {
                ends.push(Located {
                    position: p.vertices[a],
                    t: p.t[a],
                });
            } else if sa * sb < 0.0 {
                let flat = p.vertices[a] + (p.vertices[b] - p.vertices[a]) * (sa / (sa - sb));
                let u = (flat - p.centre).normalize();
                ends.push(self.on_edge(a.min(b), a.max(b), u)?);
            }
        }
        Ok(ends)
    }

    /// The curved point inside face `f` in direction u, where cuts k and l cross: the mean of
    /// where the two whole silhouette edges across the face cross the ray, each weighted by
    /// 1/d², d its distance there from the silhouette edge's nearer end.
    fn inside(
        &mut self,
        f: usize,
        cuts: [usize; 2],
        flat: DVec3,
    ) -> Result<Located, EnvelopeError> {
        let g = self.p.centre;
        let u = (flat - g).normalize();
        let (mut dist, mut t, mut weight) = (0.0, 0.0, 0.0);
        for k in cuts {
            if let [e1, e2] = self.face_line(f, k)?.as_slice()
                && let Some(c) = curved_edge(g, e1.position, e2.position, e1.t, e2.t)
            {
                let q = c.eval(at_direction(&c, g, u));
                let (v1, v2) = (e1.position - g, e2.position - g);
                let share = angle(v1, q - g) / angle(v1, v2).max(f64::MIN_POSITIVE);
                // Weighted by 1/d², d from the nearer end: near a primitive's edge the corner
                // takes the distance of the silhouette point there, where that silhouette edge
                // leaves normal to its radius (envelope.md, "Corners inside a face").
                let near = q.distance(e1.position).min(q.distance(e2.position));
                let w = 1.0 / near.max(1e-12 * self.p.radius).powi(2);
                dist += w * q.distance(g);
                t += w * (e1.t + (e2.t - e1.t) * share);
                weight += w;
            }
        }
        if weight == 0.0 {
            return Err(EnvelopeError::Primitive {
                index: self.index,
                why: format!(
                    "face {f}: the corner where two silhouette planes cross it cannot be curved"
                ),
            });
        }
        Ok(Located {
            position: g + u * (dist / weight),
            t: t / weight,
        })
    }

    /// The corners of a clipped face inside it, located, and drawn to one distance from G
    /// where they lie close together: corner i's distance becomes `(rᵢ + Σ sᵢⱼ rⱼ) / (1 + Σ
    /// sᵢⱼ)` over the face's other inside corners, `sᵢⱼ = (a² / (a² + dᵢⱼ²))²` with `a =`
    /// [`NEAR_INSIDE`]` · r`: two corners a short silhouette side apart (three cuts crossing
    /// the face nearly at one point) end at nearly one distance — they differ by
    /// `(r₁ − r₂)(1 − s)/(1 + s)`, about `(r₁ − r₂) d²/a²` — as the normals along their radii
    /// need; corners far apart keep theirs, pulled as `(a/d)⁴` (envelope.md, "Corners inside
    /// a face").
    fn inside_corners(&mut self, poly: &[Corner]) -> Result<Vec<Option<Located>>, EnvelopeError> {
        let mut out = Vec::with_capacity(poly.len());
        for c in poly {
            out.push(match c.at {
                At::Inside { .. } => Some(self.locate(c)?),
                _ => None,
            });
        }
        let g = self.p.centre;
        let reach = NEAR_INSIDE * self.p.radius;
        let found: Vec<(usize, Located)> = out
            .iter()
            .enumerate()
            .filter_map(|(i, l)| l.map(|l| (i, l)))
            .collect();
        for &(i, li) in &found {
            let (mut sum, mut weight) = (li.position.distance(g), 1.0);
            for &(j, lj) in &found {
                if j != i {
                    // How far apart they lie across the face: the flat corners' distance, not
                    // the located ones', which holds the very difference in distance from G
                    // that drawing them together removes.
                    let d2 = poly[i].flat.distance_squared(poly[j].flat);
                    // Squared, so that a corner far across the face pulls as (a/d)⁴, not
                    // (a/d)²: a corner 1.2 away on a cube face pulled one beside the edge
                    // 0.0006 in (envelope.md, "How far the pull reaches").
                    let w = (reach * reach / (reach * reach + d2)).powi(2);
                    sum += w * lj.position.distance(g);
                    weight += w;
                }
            }
            let u = (li.position - g).normalize();
            out[i] = Some(Located {
                position: g + u * (sum / weight),
                t: li.t,
            });
        }
        Ok(out)
    }

    fn locate(&mut self, c: &Corner) -> Result<Located, EnvelopeError> {
        let g = self.p.centre;
        match c.at {
            At::Vertex(i) => Ok(Located {
                position: self.p.vertices[i],
                t: self.p.t[i],
            }),
            At::Edge { a, b, .. } => self.on_edge(a, b, (c.flat - g).normalize()),
            At::Inside { face, cuts } => self.inside(face, cuts, c.flat),
        }
    }

    /// The network vertex of a corner (one per direction).
    fn vertex(
        &mut self,
        net: &mut Network,
        c: &Corner,
        known: Option<Located>,
    ) -> Result<usize, EnvelopeError> {
        let u = (c.flat - self.p.centre).normalize();
        if let Some(v) = self.known(u) {
            return Ok(v);
        }
        let l = match known {
            Some(l) => l,
            None => self.locate(c)?,
        };
        let g = self.p.centre;
        let v = net.add_vertex(
            l.position,
            (l.position - g).normalize(),
            l.t * l.position.distance(g),
        );
        self.by_cell
            .entry(direction_cell(u))
            .or_default()
            .push(self.points.len());
        self.by_vertex.insert(v, self.points.len());
        self.points.push((u, v, c.at));
        Ok(v)
    }

    /// The network vertex already added in direction u (unit, from G), if any.
    fn known(&self, u: DVec3) -> Option<usize> {
        let (lo, hi) = (
            direction_cell(u - DVec3::splat(SAME_DIRECTION)),
            direction_cell(u + DVec3::splat(SAME_DIRECTION)),
        );
        // The first added among those within the tolerance, as a scan in order would find.
        let mut first: Option<usize> = None;
        for x in lo[0]..=hi[0] {
            for y in lo[1]..=hi[1] {
                for z in lo[2]..=hi[2] {
                    for &i in self.by_cell.get(&[x, y, z]).into_iter().flatten() {
                        if self.points[i].0.distance(u) <= SAME_DIRECTION {
                            first = Some(first.map_or(i, |f| f.min(i)));
                        }
                    }
                }
            }
        }
        first.map(|i| self.points[i].1)
    }

    fn at_of(&self, v: usize) -> At {
        self.points[self.by_vertex[&v]].2
    }

    /// The curve of a side from vertex x to vertex y along `along`, as a side of the region.
    fn side(
        &mut self,
        net: &mut Network,
        x: usize,
        y: usize,
        along: Along,
    ) -> Result<PatchSide, EnvelopeError> {
        let key = (x.min(y), x.max(y));
        if let Some(&c) = self.curves.get(&key) {
            return Ok(PatchSide::whole(c, net.curves[c].ends[0] == x));
        }
        let g = self.p.centre;
        let t_of = |net: &Network, v: usize| net.vertices[v].t_about(g);
        let (px, py) = (net.vertices[x].position, net.vertices[y].position);
        let c = match along {
            Along::Cut(k) => {
                let bez = curved_edge(g, px, py, t_of(net, x), t_of(net, y)).ok_or_else(|| {
                    EnvelopeError::Primitive {
                        index: self.index,
                        why: format!("a silhouette edge towards partner {k} cannot be curved"),
                    }
                })?;
                let bez = if hooks(&bez, py - px, NEAR_HOOK) {
                    // A short piece between points at different distances from G (a corner
                    // where two cuts cross, next to where one crosses an edge): no convex arc
                    // is normal to both radii, or only one with a leg too short to give its
                    // parameter room. The cubic that leaves and reaches them along the
                    // section's tangents, a third of the chord long, instead (an inflection,
                    // not a hook; envelope.md).
                    third_cubic(g, self.cuts[k], px, py, 1.0, self.monotone)
                } else {
                    bez
                };
                net.add_curve(bez, x, y, CurveKind::Silhouette)
            }
            Along::Edge(a, b) => {
                let (ax, ay) = (self.at_of(x), self.at_of(y));
                let whole = matches!((ax, ay), (At::Vertex(_), At::Vertex(_)));
                // A whole edge, or the kept piece rebuilt with §6.3 between its ends.
                let bez = curved_edge(g, px, py, t_of(net, x), t_of(net, y))
                    .ok_or_else(|| self.bad_edge(a, b))?;
                let bez = if !whole && hooks(&bez, py - px, NEAR_HOOK_EDGE) {
                    // The piece hooks (no convex arc joins them normal to both radii) or nearly
                    // does (a leg under NEAR_HOOK_EDGE of the chord, the parameter crowded at
                    // that end): the cubic normal to both radii instead, an inflection where it
                    // hooks; S keeps its tangent plane (envelope.md, "Where the rebuilt piece
                    // would hook", "Nearly hooked pieces").
                    let t = 0.5 * (t_of(net, x) + t_of(net, y));
                    third_cubic(
                        g,
                        (px - g).cross(py - g),
                        px,
                        py,
                        legs_for(t),
                        self.monotone,
                    )
                } else {
                    bez
                };
                net.add_curve(bez, x, y, CurveKind::Edge)
            }
        };
        self.curves.insert(key, c);
        Ok(PatchSide::whole(c, true))
    }
}

/// Adds primitive `index` to `net`, trimmed to `(x − G)·d_k ≤ 0` for every unit `d_k` in
/// `cuts`: its kept vertices, silhouette points, curves and regions. Returns each cut's
/// section: the silhouette edges on it, in the direction the kept faces run along them.
pub fn add_primitive(
    net: &mut Network,
    p: &Primitive,
    index: usize,
    cuts: &[DVec3],
    monotone: bool,
) -> Result<Vec<Vec<PatchSide>>, EnvelopeError> {
    let tol = ON_PLANE * p.radius;
    let mut clip = Clipper {
        p,
        index,
        cuts,
        tol,
        points: Vec::new(),
        by_cell: HashMap::new(),
        by_vertex: HashMap::new(),
        full: HashMap::new(),
        curves: HashMap::new(),
        monotone,
    };
    let on_cut = |k: usize, x: DVec3| (x - p.centre).dot(cuts[k]).abs() <= tol;
    let mut sections = vec![Vec::new(); cuts.len()];
    let polys: Vec<(usize, Vec<Corner>)> = (0..p.faces.len())
        .map(|f| (f, clip_face(p, f, cuts, tol)))
        .filter(|(_, poly)| !poly.is_empty())
        .collect();
    // Every corner is located in its own face first (the listing of the faces cannot change
    // where it lies).
    for (_, poly) in &polys {
        let inside = clip.inside_corners(poly)?;
        for (c, l) in poly.iter().zip(inside) {
            clip.vertex(net, c, l)?;
        }
    }
    for (f, poly) in polys {
        let ids = poly
            .iter()
            .map(|c| clip.vertex(net, c, None))
            .collect::<Result<Vec<_>, _>>()?;
        let m = poly.len();
        let mut sides = Vec::with_capacity(m);
        for i in 0..m {
            let (x, y) = (ids[i], ids[(i + 1) % m]);
            if x == y {
                continue;
            }
            let side = clip.side(net, x, y, poly[i].along)?;
            let cut = match poly[i].along {
                Along::Cut(k) => Some(k),
                // A kept edge lying in a cut plane (the face across is removed).
                Along::Edge(..) => (0..cuts.len())
                    .find(|&k| on_cut(k, poly[i].flat) && on_cut(k, poly[(i + 1) % m].flat)),
            };
            // A side of two faces (a kept edge in a cut plane) is one piece of the section.
            if let Some(k) = cut
                && !sections[k]
                    .iter()
                    .any(|s: &PatchSide| s.curve == side.curve)
            {
                net.curves[side.curve].kind = CurveKind::Silhouette;
                sections[k].push(side);
            }
            sides.push(side);
        }
        if sides.len() < 3 {
            continue;
        }
        net.regions.push(Region {
            sides,
            kind: RegionKind::Primitive {
                primitive: index,
                face: f,
            },
        });
    }
    Ok(sections)
}
