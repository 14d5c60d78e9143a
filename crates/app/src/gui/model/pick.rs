//! Picking in a view: vertices and edges under the pointer or inside a dragged box, in
//! screen space. A point projects through the camera's view-projection (scene coordinates
//! are relative to the scene's origin, like the GPU's); a pointer click casts a ray against
//! the drawn triangles (Möller–Trumbore), so that a click picks what is in front, never an
//! edge behind the surface. Box selection takes everything inside the box, hidden or not,
//! as box selection does in most modellers.

use egui::{Pos2, Rect};
use glam::{DVec3, Mat4, Vec3, Vec4Swizzles};
use prism_geom::{EdgeKey, PolyMesh};
use prism_viewport::Scene;

/// Screen mapping of one view.
#[derive(Debug, Clone, Copy)]
pub struct Projector {
    pub view_proj: Mat4,
    pub rect: Rect,
    pub origin: DVec3,
}

impl Projector {
    /// Screen position and depth (0 near … 1 far) of an absolute point, if it is in front.
    pub fn project(&self, p: DVec3) -> Option<(Pos2, f32)> {
        let q = (p - self.origin).as_vec3();
        let c = self.view_proj * q.extend(1.0);
        if c.w <= 1e-9 {
            return None;
        }
        let n = c.xyz() / c.w;
        if !(0.0..=1.0).contains(&n.z) {
            return None;
        }
        Some((
            Pos2::new(
                self.rect.left() + (n.x + 1.0) * 0.5 * self.rect.width(),
                self.rect.top() + (1.0 - n.y) * 0.5 * self.rect.height(),
            ),
            n.z,
        ))
    }

    /// The ray through a screen point, in scene coordinates: origin on the near plane and
    /// unit direction.
    pub fn ray(&self, at: Pos2) -> (Vec3, Vec3) {
        let x = (at.x - self.rect.left()) / self.rect.width() * 2.0 - 1.0;
        let y = 1.0 - (at.y - self.rect.top()) / self.rect.height() * 2.0;
        let inv = self.view_proj.inverse();
        let near = inv.project_point3(Vec3::new(x, y, 0.0));
        let far = inv.project_point3(Vec3::new(x, y, 1.0));
        (near, (far - near).normalize_or_zero())
    }

    /// Whether an absolute point is not hidden behind the scene's triangles.
    pub fn visible(&self, scene: &Scene, p: DVec3) -> bool {
        let Some((s, _)) = self.project(p) else {
            return false;
        };
        let (o, d) = self.ray(s);
        let t = (p - self.origin).as_vec3().distance(o);
        match ray_hit(scene, o, d) {
            Some(hit) => t <= hit + 2e-3 * scene.radius(),
            None => true,
        }
    }
}

/// Distance along the ray to the nearest triangle of the scene.
pub fn ray_hit(scene: &Scene, o: Vec3, d: Vec3) -> Option<f32> {
    let mut best: Option<f32> = None;
    for t in scene.indices.chunks_exact(3) {
        let p = |i: u32| Vec3::from(scene.vertices[i as usize].position);
        let (a, b, c) = (p(t[0]), p(t[1]), p(t[2]));
        let (e1, e2) = (b - a, c - a);
        let h = d.cross(e2);
        let det = e1.dot(h);
        if det.abs() < 1e-12 {
            continue;
        }
        let f = 1.0 / det;
        let s = o - a;
        let u = f * s.dot(h);
        if !(0.0..=1.0).contains(&u) {
            continue;
        }
        let q = s.cross(e1);
        let v = f * d.dot(q);
        if v < 0.0 || u + v > 1.0 {
            continue;
        }
        let dist = f * e2.dot(q);
        if dist > 0.0 && best.is_none_or(|b| dist < b) {
            best = Some(dist);
        }
    }
    best
}

/// Every edge of a mesh once.
pub fn mesh_edges(mesh: &PolyMesh) -> Vec<EdgeKey> {
    let mut out = Vec::new();
    for l in 0..mesh.num_loops() {
        let vs = mesh.loop_verts(l);
        for i in 0..vs.len() {
            out.push(EdgeKey::new(vs[i], vs[(i + 1) % vs.len()]));
        }
    }
    out.sort_unstable();
    out.dedup();
    out
}

fn segment_distance(p: Pos2, a: Pos2, b: Pos2) -> (f32, f32) {
    let ab = b - a;
    let len2 = ab.length_sq();
    let t = if len2 > 0.0 {
        ((p - a).dot(ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    ((a + t * ab).distance(p), t)
}

/// The visible vertex nearest to `at` within `radius` pixels.
pub fn pick_vertex(
    proj: &Projector,
    scene: Option<&Scene>,
    positions: &[DVec3],
    at: Pos2,
    radius: f32,
) -> Option<u32> {
    let mut near: Vec<(f32, u32)> = positions
        .iter()
        .enumerate()
        .filter_map(|(i, &p)| {
            let (s, _) = proj.project(p)?;
            let d = s.distance(at);
            (d <= radius).then_some((d, i as u32))
        })
        .collect();
    near.sort_by(|a, b| a.0.total_cmp(&b.0));
    near.into_iter()
        .take(16)
        .find(|&(_, i)| scene.is_none_or(|s| proj.visible(s, positions[i as usize])))
        .map(|(_, i)| i)
}

/// The visible edge nearest to `at` within `radius` pixels.
pub fn pick_edge(
    proj: &Projector,
    scene: Option<&Scene>,
    mesh: &PolyMesh,
    edges: &[EdgeKey],
    at: Pos2,
    radius: f32,
) -> Option<EdgeKey> {
    let mut near: Vec<(f32, f32, EdgeKey)> = edges
        .iter()
        .filter_map(|&e| {
            let (pa, pb) = (mesh.positions[e.0 as usize], mesh.positions[e.1 as usize]);
            let (a, _) = proj.project(pa)?;
            let (b, _) = proj.project(pb)?;
            let (d, t) = segment_distance(at, a, b);
            (d <= radius).then_some((d, t, e))
        })
        .collect();
    near.sort_by(|a, b| a.0.total_cmp(&b.0));
    near.into_iter()
        .take(16)
        .find(|&(_, t, e)| {
            let p = mesh.positions[e.0 as usize].lerp(mesh.positions[e.1 as usize], t as f64);
            scene.is_none_or(|s| proj.visible(s, p))
        })
        .map(|(_, _, e)| e)
}

/// Vertices whose projection lies in `rect`.
pub fn box_vertices(proj: &Projector, positions: &[DVec3], rect: Rect) -> Vec<u32> {
    positions
        .iter()
        .enumerate()
        .filter(|(_, p)| proj.project(**p).is_some_and(|(s, _)| rect.contains(s)))
        .map(|(i, _)| i as u32)
        .collect()
}

/// Edges with both ends' projections in `rect`.
pub fn box_edges(proj: &Projector, mesh: &PolyMesh, edges: &[EdgeKey], rect: Rect) -> Vec<EdgeKey> {
    let inside = |v: u32| {
        proj.project(mesh.positions[v as usize])
            .is_some_and(|(s, _)| rect.contains(s))
    };
    edges
        .iter()
        .copied()
        .filter(|e| inside(e.0) && inside(e.1))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use prism_geom::primitives;
    use prism_viewport::{Camera, View};

    fn setup() -> (PolyMesh, Scene, Projector) {
        let m = primitives::cube3();
        let scene = Scene::plain(&m);
        let cam = Camera::looking(View::Iso, Vec3::ZERO, scene.radius());
        let rect = Rect::from_min_size(Pos2::new(10.0, 20.0), egui::vec2(400.0, 300.0));
        let proj = Projector {
            view_proj: cam.view_proj(rect.width() / rect.height()),
            rect,
            origin: scene.origin,
        };
        (m, scene, proj)
    }

    #[test]
    fn a_click_on_a_projected_vertex_picks_it_unless_it_is_hidden() {
        let (m, scene, proj) = setup();
        let mut seen = 0;
        for (i, &p) in m.positions.iter().enumerate() {
            let (s, _) = proj.project(p).unwrap();
            let picked = pick_vertex(
                &proj,
                Some(&scene),
                &m.positions,
                s + egui::vec2(2.0, 1.0),
                8.0,
            );
            // From the iso view 7 corners of a cube are visible, the far one is not.
            if picked == Some(i as u32) {
                seen += 1;
            }
        }
        assert_eq!(seen, 7);
    }

    #[test]
    fn a_click_near_an_edge_midpoint_picks_that_edge() {
        let (m, scene, proj) = setup();
        let edges = mesh_edges(&m);
        assert_eq!(edges.len(), 12);
        let mut hits = 0;
        for &e in &edges {
            let mid = 0.5 * (m.positions[e.0 as usize] + m.positions[e.1 as usize]);
            let (s, _) = proj.project(mid).unwrap();
            if pick_edge(&proj, Some(&scene), &m, &edges, s, 6.0) == Some(e) {
                hits += 1;
            }
        }
        // Nine edges are visible from the iso view; the three at the far corner are hidden.
        assert_eq!(hits, 9);
        // A box around the whole view takes every edge, hidden ones too.
        assert_eq!(box_edges(&proj, &m, &edges, proj.rect).len(), 12);
        assert_eq!(box_vertices(&proj, &m.positions, proj.rect).len(), 8);
    }

    #[test]
    fn the_ray_through_a_projected_point_passes_through_it() {
        let (_, _, proj) = setup();
        let p = DVec3::new(0.3, -0.2, 0.7);
        let (s, _) = proj.project(p).unwrap();
        let (o, d) = proj.ray(s);
        let q = (p - proj.origin).as_vec3();
        let off = (q - o) - (q - o).dot(d) * d;
        assert!(off.length() < 1e-4, "{off}");
    }
}
