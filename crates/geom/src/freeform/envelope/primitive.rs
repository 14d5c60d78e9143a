//! Primitives of an envelope (seed 004 §4; docs/algorithms/envelope.md): convex polyhedra whose
//! vertices lie on a sphere around their centre, checked and oriented, with a curvature
//! parameter t per vertex (ρ = t·r).
//!
//! The centre G is the circumcentre — the least-squares sphere through the vertices,
//! `2P·G + c = |P|²` solved for (G, c), `r² = c + |G|²` — which equals the vertex centroid for
//! the symmetric primitives the paper uses and is the only centre with every vertex at one
//! distance in general (docs/algorithms/envelope.md, "Primitives").

use super::EnvelopeError;
use crate::analysis::face_grid::FaceGrid;
use crate::freeform::envelope::tolerances::TOLERANCES;
use crate::primitives;
use glam::{DMat3, DVec3};
use serde::{Deserialize, Serialize};
use std::collections::HashMap;

/// [`TOLERANCES`]`.primitive`.
pub const TOLERANCE: f64 = TOLERANCES.primitive;

/// A primitive as a scene file lists it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PrimitiveInput {
    pub vertices: Vec<[f64; 3]>,
    pub faces: Vec<Vec<usize>>,
    /// The primitive's t (default: the scene's).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub t: Option<f64>,
    /// Per-vertex t (default: the primitive's).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vertex_t: Option<Vec<f64>>,
}

/// A checked primitive: faces counter-clockwise seen from outside.
#[derive(Debug, Clone, PartialEq)]
pub struct Primitive {
    pub centre: DVec3,
    pub radius: f64,
    pub vertices: Vec<DVec3>,
    pub faces: Vec<Vec<usize>>,
    /// Unit outward face normals.
    pub normals: Vec<DVec3>,
    /// t per vertex.
    pub t: Vec<f64>,
}

fn check_t(t: f64, what: impl Fn() -> String) -> Result<f64, EnvelopeError> {
    if t.is_finite() && t > 0.0 {
        Ok(t)
    } else {
        Err(EnvelopeError::BadT { what: what(), t })
    }
}

/// The least-squares sphere through `pts`: centre and radius. Solved about the points' mean
/// and in units of their spread, so that where the primitive sits and how large it is (1e8
/// away, 1e±100 across) change nothing but the answer's position and scale.
fn circumsphere(pts: &[DVec3]) -> Option<(DVec3, f64)> {
    // Normal equations of rows (2x, 2y, 2z, 1) · (G, c) = |P|², centred and scaled.
    let o = pts.iter().sum::<DVec3>() / pts.len() as f64;
    let s = pts.iter().map(|p| (*p - o).length()).fold(0.0, f64::max);
    if !(s > 0.0 && s.is_finite()) {
        return None;
    }
    let mut a = [[0.0; 4]; 4];
    let mut b = [0.0; 4];
    for p in pts {
        let q = (*p - o) / s;
        let row = [2.0 * q.x, 2.0 * q.y, 2.0 * q.z, 1.0];
        for i in 0..4 {
            for j in 0..4 {
                a[i][j] += row[i] * row[j];
            }
            b[i] += row[i] * q.length_squared();
        }
    }
    let m = glam::DMat4::from_cols_array_2d(&a);
    if m.determinant().abs() <= 1e-300 {
        return None;
    }
    let x = m.inverse() * glam::DVec4::from_array(b);
    let g = x.truncate();
    let r2 = x.w + g.length_squared();
    (r2 > 0.0).then(|| (g * s + o, r2.sqrt() * s))
}

impl Primitive {
    /// Checks primitive `index` of a scene whose default t is `scene_t`: at least four
    /// vertices, finite, distinct, on one sphere; a closed surface of planar convex faces
    /// with the centre strictly inside; every t finite and > 0. Faces are turned to face
    /// outwards.
    pub fn new(index: usize, p: &PrimitiveInput, scene_t: f64) -> Result<Primitive, EnvelopeError> {
        let bad = |why: String| EnvelopeError::Primitive { index, why };
        let n = p.vertices.len();
        if n < 4 || p.faces.len() < 4 {
            return Err(bad(format!(
                "{n} vertices and {} faces: a solid needs at least 4 of each",
                p.faces.len()
            )));
        }
        let vertices: Vec<DVec3> = p.vertices.iter().map(|v| DVec3::from_array(*v)).collect();
        if let Some(i) = vertices.iter().position(|v| !v.is_finite()) {
            return Err(bad(format!("vertex {i} is not a finite point")));
        }
        let t0 = check_t(p.t.unwrap_or(scene_t), || format!("primitive {index}"))?;
        let t = match &p.vertex_t {
            None => vec![t0; n],
            Some(vt) if vt.len() != n => {
                return Err(bad(format!(
                    "{} vertex_t values for {n} vertices",
                    vt.len()
                )));
            }
            Some(vt) => vt
                .iter()
                .enumerate()
                .map(|(i, &t)| check_t(t, || format!("vertex {i} of primitive {index}")))
                .collect::<Result<_, _>>()?,
        };
        let (centre, radius) =
            circumsphere(&vertices).ok_or_else(|| bad("its vertices span no sphere".into()))?;
        let tol = TOLERANCE * radius;
        // Vertices by cell of side 4 tol: a vertex meets the few before it in its cell and
        // the cells beside it, not all of them.
        let mut cells: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
        let cell_of = |v: DVec3| ((v - centre) / (4.0 * tol)).floor().as_i64vec3().to_array();
        for (i, v) in vertices.iter().enumerate() {
            let off = (v.distance(centre) - radius).abs();
            if off > tol {
                return Err(bad(format!(
                    "vertex {i} is {off:.3e} off the sphere through the vertices (centre {centre:.4}, r = {radius:.4}; tolerance {TOLERANCE:e} r)"
                )));
            }
            let c = cell_of(*v);
            let same = (0..27)
                .flat_map(|k| {
                    let near = [c[0] + k % 3 - 1, c[1] + (k / 3) % 3 - 1, c[2] + k / 9 - 1];
                    cells.get(&near).into_iter().flatten()
                })
                .copied()
                .filter(|&j| vertices[j].distance(*v) <= tol)
                .min();
            if let Some(j) = same {
                return Err(bad(format!("vertices {j} and {i} coincide")));
            }
            cells.entry(c).or_default().push(i);
        }
        // Closed and consistently oriented: every directed edge once, its reverse once.
        let mut directed = HashMap::new();
        for (f, face) in p.faces.iter().enumerate() {
            if face.len() < 3 {
                return Err(bad(format!("face {f} has {} vertices", face.len())));
            }
            if let Some(&v) = face.iter().find(|&&v| v >= n) {
                return Err(bad(format!("face {f} names vertex {v}; there are {n}")));
            }
            for k in 0..face.len() {
                let e = (face[k], face[(k + 1) % face.len()]);
                if directed.insert(e, f).is_some() {
                    return Err(bad(format!(
                        "edge {}-{} is used twice in one direction (faces not consistently oriented, or more than two faces at the edge)",
                        e.0, e.1
                    )));
                }
            }
        }
        if let Some((&(a, b), &f)) = directed
            .iter()
            .find(|(e, _)| !directed.contains_key(&(e.1, e.0)))
        {
            return Err(bad(format!(
                "edge {a}-{b} of face {f} has no second face: not closed"
            )));
        }
        // Faces, planes and sides about the centre in units of the radius: where the
        // primitive sits and how large it is change nothing.
        let local: Vec<DVec3> = vertices.iter().map(|v| (*v - centre) / radius).collect();
        let newell = |face: &[usize]| {
            (0..face.len())
                .map(|k| local[face[k]].cross(local[face[(k + 1) % face.len()]]))
                .sum::<DVec3>()
        };
        let outward = p.faces.iter().map(|f| {
            let c = f.iter().map(|&v| local[v]).sum::<DVec3>() / f.len() as f64;
            newell(f).dot(c)
        });
        let sum: f64 = outward.sum();
        let faces: Vec<Vec<usize>> = if sum >= 0.0 {
            p.faces.clone()
        } else {
            p.faces
                .iter()
                .map(|f| f.iter().rev().copied().collect())
                .collect()
        };
        // The vertices on a grid, so that a face meets those near its cap of the sphere (the
        // only ones that can lie beyond its plane) rather than all of them.
        let grid = FaceGrid::of_boxes(local.iter().map(|&u| (u, u)).collect(), local.len() as f64);
        let mut normals = Vec::with_capacity(faces.len());
        for (f, face) in faces.iter().enumerate() {
            let nf = newell(face).normalize_or_zero();
            if nf == DVec3::ZERO {
                return Err(bad(format!("face {f} has no area")));
            }
            let d = nf.dot(local[face[0]]);
            let off = |v: usize| nf.dot(local[v]) - d;
            if let Some(&v) = face.iter().find(|&&v| off(v).abs() > TOLERANCE) {
                return Err(bad(format!(
                    "face {f} is not planar: vertex {v} is {:.3e} off its plane (tolerance {TOLERANCE:e} r)",
                    off(v).abs() * radius
                )));
            }
            // A vertex beyond the plane (n·u > d + TOLERANCE, |u| ≤ 1 + TOLERANCE) lies within
            // this distance of the cap's pole n.
            let reach = DVec3::splat((2.0 - 2.0 * d).max(0.0).sqrt() + 1e-5);
            let mut beyond: Option<usize> = None;
            grid.for_each_overlapping((nf - reach, nf + reach), |v| {
                if off(v) > TOLERANCE {
                    beyond = Some(beyond.map_or(v, |b| b.min(v)));
                }
            });
            if let Some(v) = beyond {
                return Err(bad(format!(
                    "not convex: vertex {v} lies {:.3e} outside the plane of face {f}",
                    off(v) * radius
                )));
            }
            if d <= TOLERANCE {
                return Err(bad(format!(
                    "its centre {centre:.4} is not inside it (on or beyond the plane of face {f})"
                )));
            }
            normals.push(nf);
        }
        Ok(Primitive {
            centre,
            radius,
            vertices,
            faces,
            normals,
            t,
        })
    }
}

/// The shapes of the primitive library, each inscribed in its sphere of radius 1 about the
/// origin before placement.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", tag = "shape")]
pub enum Shape {
    Cube,
    /// Half-extents a, b, c (scaled to the unit sphere).
    Box {
        a: f64,
        b: f64,
        c: f64,
    },
    Tetrahedron,
    Octahedron,
    /// Regular triangular prism whose height is `height` × the base's circumradius.
    TriangularPrism {
        height: f64,
    },
    /// Regular hexagonal prism whose height is `height` × the base's circumradius.
    HexagonalPrism {
        height: f64,
    },
}

/// Where a library shape goes: centre, uniform scale (the sphere's radius) and rotation
/// (degrees about x, then y, then z).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Placement {
    pub centre: [f64; 3],
    pub scale: f64,
    #[serde(default)]
    pub rotation: [f64; 3],
}

impl Default for Placement {
    fn default() -> Self {
        Placement {
            centre: [0.0; 3],
            scale: 1.0,
            rotation: [0.0; 3],
        }
    }
}

impl Shape {
    /// Vertices (on the unit sphere) and outward counter-clockwise faces.
    pub fn unit(&self) -> (Vec<DVec3>, Vec<Vec<usize>>) {
        let prism = |n: u32, height: f64| {
            primitives::extrude(
                &primitives::regular_polygon(n, 1.0),
                &[],
                -0.5 * height,
                0.5 * height,
            )
        };
        let m = match *self {
            Shape::Cube => primitives::cuboid(-DVec3::ONE, DVec3::ONE),
            Shape::Box { a, b, c } => {
                let h = DVec3::new(a, b, c);
                primitives::cuboid(-h, h)
            }
            Shape::Tetrahedron => primitives::tetrahedron(),
            Shape::Octahedron => primitives::octahedron(),
            Shape::TriangularPrism { height } => prism(3, height),
            Shape::HexagonalPrism { height } => prism(6, height),
        };
        let v = m.positions.iter().map(|p| p.normalize()).collect();
        let f = (0..m.num_faces())
            .map(|f| {
                m.loop_verts(m.face_loops(f).start)
                    .iter()
                    .map(|&v| v as usize)
                    .collect()
            })
            .collect();
        (v, f)
    }

    /// The shape placed, as a scene lists a primitive.
    pub fn placed(&self, at: &Placement) -> PrimitiveInput {
        let (v, f) = self.unit();
        let [rx, ry, rz] = at.rotation.map(f64::to_radians);
        let rot =
            DMat3::from_rotation_z(rz) * DMat3::from_rotation_y(ry) * DMat3::from_rotation_x(rx);
        let c = DVec3::from_array(at.centre);
        PrimitiveInput {
            vertices: v
                .iter()
                .map(|p| (c + rot * (*p * at.scale)).to_array())
                .collect(),
            faces: f,
            t: None,
            vertex_t: None,
        }
    }
}
