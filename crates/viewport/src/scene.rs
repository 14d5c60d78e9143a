//! What is drawn, prepared on the CPU: triangles with normals and colours, and the lines of
//! the polygon edges (not of the triangulation).
//!
//! Faces are triangulated with `earcutr` in their own plane (concave faces and holes
//! included); triangles and convex quads take a fan. **Flat** shading gives every corner its
//! face's normal; **smooth** shading averages the area-weighted normals of the faces around
//! a vertex within each fan between *sharp* edges — crease edges and edges whose faces meet
//! at more than the crease angle — so that creases stay crisp
//! ([`prism_geom::normals`], which the glTF export shares).

use glam::{DVec3, Vec3};
use prism_geom::geometry::{face_normals_raw, unit_or_zero};
use prism_geom::normals::{flat_corner_normals, smooth_corner_normals};
use prism_geom::refine::FaceKind;
use prism_geom::triangulate::push_face_triangles;
use prism_geom::{EdgeAttrs, PolyMesh};
use rayon::prelude::*;

/// How faces are shaded.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Shading {
    #[default]
    Flat,
    Smooth,
}

/// How faces are coloured.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum ColorBy {
    /// One material colour.
    #[default]
    Uniform,
    /// FACE-, EDGE- and VERTEX-faces of the last biquadratic step in three colours.
    Kind,
    /// Mean curvature per vertex (`geom::analysis::mean_curvature`), mapped from the 2nd to
    /// the 98th percentile of the vertices off crease edges onto a viridis-like scale
    /// (dark blue low, yellow high).
    Curvature,
    /// One colour chosen by the caller: [`scheme_color`] of the step that made the level,
    /// so that schemes side by side are told apart at a glance.
    Solid([f32; 3]),
}

/// The colour of the faces a scheme made (the Tableau 10 palette), by the scheme's place in
/// the catalogue; the input level (no scheme) gets the material colour.
pub fn scheme_color(s: Option<&prism_geom::Scheme>) -> [f32; 3] {
    // Tableau 10, its grey lightened to stand apart from the material colour.
    const PALETTE: [u32; 10] = [
        0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd, 0x8c564b, 0xe377c2, 0x17becf, 0xbcbd22,
        0x999999,
    ];
    let Some(s) = s else { return BASE_COLOR };
    rgb(PALETTE[s.kind().index() % PALETTE.len()])
}

/// `0xRRGGBB` as the 0..1 floats the other material colours are given in (published
/// palettes are written in hex).
fn rgb(hex: u32) -> [f32; 3] {
    [16, 8, 0].map(|shift| ((hex >> shift) & 0xff) as f32 / 255.0)
}

/// The curvature colour scale: viridis at five stops, interpolated.
pub fn curvature_color(t: f64) -> [f32; 3] {
    // viridis at 0, ¼, ½, ¾ and 1.
    const STOPS: [u32; 5] = [0x440154, 0x3b528b, 0x21918c, 0x5ec962, 0xfde725];
    let x = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    } * 4.0;
    let i = (x.floor() as usize).min(3);
    let f = x - i as f64;
    let (a, b) = (rgb(STOPS[i]), rgb(STOPS[i + 1]));
    std::array::from_fn(|k| (a[k] as f64 * (1.0 - f) + b[k] as f64 * f) as f32)
}

/// The colours of the FACE-, EDGE- and VERTEX-faces (also the legend's).
pub const KIND_COLORS: [[f32; 3]; 3] = [[0.85, 0.62, 0.35], [0.35, 0.62, 0.85], [0.55, 0.80, 0.45]];
/// The material colour.
pub const BASE_COLOR: [f32; 3] = [0.72, 0.74, 0.80];
/// Faces that point the wrong way (a step's flipped faces, seed 000 fig. 10).
pub const FLIPPED_COLOR: [f32; 3] = [0.90, 0.12, 0.10];

/// One vertex of the triangle buffer.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Vertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
    pub color: [f32; 3],
}

/// One end of a line.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LineVertex {
    pub position: [f32; 3],
    pub color: [f32; 3],
}

/// Options of [`Scene::build`].
#[derive(Debug, Clone, PartialEq)]
pub struct SceneOptions {
    pub shading: Shading,
    pub color_by: ColorBy,
    /// Draw the polygon edges.
    pub wireframe: bool,
    /// Edges whose faces meet at more than this (degrees) stay sharp in smooth shading.
    pub crease_angle_deg: f64,
    /// A section plane through the level: only the part on one side is drawn, with the
    /// outline where the plane cuts the surface.
    pub section: Option<SectionPlane>,
}

/// A plane normal to a coordinate axis through a model: the part where the coordinate is at
/// most (`flip`: at least) the share `at` of the way along the level's bounding box is kept.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SectionPlane {
    /// 0 x, 1 y, 2 z.
    pub axis: usize,
    /// 0 the box's low side, 1 its high side.
    pub at: f64,
    pub flip: bool,
}

/// The colour of a section's outline.
pub const SECTION_COLOR: [f32; 3] = [1.0, 0.85, 0.25];

impl SectionPlane {
    /// The half-space it keeps of a mesh whose box is `(lo, hi)`.
    pub fn half_space(&self, (lo, hi): (DVec3, DVec3)) -> prism_geom::analysis::HalfSpace {
        let axis = DVec3::AXES[self.axis.min(2)];
        let at = lo.dot(axis) + self.at.clamp(0.0, 1.0) * (hi - lo).dot(axis);
        if self.flip {
            prism_geom::analysis::HalfSpace {
                normal: -axis,
                offset: -at,
            }
        } else {
            prism_geom::analysis::HalfSpace {
                normal: axis,
                offset: at,
            }
        }
    }
}

impl Default for SceneOptions {
    fn default() -> Self {
        SceneOptions {
            shading: Shading::Flat,
            color_by: ColorBy::Uniform,
            wireframe: false,
            crease_angle_deg: 40.0,
            section: None,
        }
    }
}

/// Triangles and lines ready for the GPU, positions relative to `origin` (kept in `f64`
/// on the CPU so that large coordinates keep their digits on the GPU's `f32`).
#[derive(Debug, Clone, Default)]
pub struct Scene {
    pub vertices: Vec<Vertex>,
    pub indices: Vec<u32>,
    pub lines: Vec<LineVertex>,
    pub origin: DVec3,
    /// Bounding box of the mesh (absolute coordinates).
    pub bbox: (DVec3, DVec3),
    /// The values at the two ends of the colour scale, when colouring by curvature.
    pub color_range: Option<(f64, f64)>,
    /// Its lines are drawn through every surface in front of them (x-ray: a trajectory or a
    /// section inside the solid shows).
    pub xray: bool,
}

impl Scene {
    /// Prepares `mesh` for drawing. `kinds` colours faces by kind when given; `attrs`
    /// marks crease edges, which stay sharp in smooth shading; `hidden` faces (holes) are
    /// not drawn.
    /// A mesh as it is: no marked edges, one colour, nothing hidden, default options.
    pub fn plain(mesh: &PolyMesh) -> Scene {
        Scene::build(
            mesh,
            &EdgeAttrs::new(),
            None,
            &|_| false,
            &SceneOptions::default(),
        )
    }

    /// The scene of a pipeline level: its faces, holes left out, with their kinds when a
    /// biquadratic step made it (for [`ColorBy::Kind`]).
    pub fn of_level(lv: &prism_geom::Level, opts: &SceneOptions) -> Scene {
        let kinds: Option<&[FaceKind]> = lv.provenance.as_ref().and_then(|p| p.face_kinds());
        let holes = &lv.tags.holes;
        if let Some(plane) = opts.section {
            // The kept part of every face, with its kind, hole and flip carried over.
            let cut = prism_geom::analysis::section(&lv.mesh, plane.half_space(lv.mesh.bbox()));
            let from = &cut.from_face;
            let kinds: Option<Vec<FaceKind>> =
                kinds.map(|k| from.iter().map(|&f| k[f as usize]).collect());
            let mut scene = Scene::build(
                &cut.mesh,
                &EdgeAttrs::new(),
                kinds.as_deref(),
                &|f| holes.contains(&from[f]),
                opts,
            );
            if let Some(r) = &lv.report {
                let was: std::collections::HashSet<u32> = r.flipped.iter().copied().collect();
                let flipped: Vec<u32> = (0..from.len() as u32)
                    .filter(|&f| was.contains(&from[f as usize]))
                    .collect();
                scene.paint_faces(&cut.mesh, &flipped, FLIPPED_COLOR);
            }
            scene.add_segments(&cut.outline, SECTION_COLOR);
            return scene;
        }
        Scene::build(
            &lv.mesh,
            &lv.edge_attrs,
            kinds,
            &|f| holes.contains(&(f as u32)),
            opts,
        )
    }

    pub fn build(
        mesh: &PolyMesh,
        attrs: &EdgeAttrs,
        kinds: Option<&[FaceKind]>,
        hidden: &(dyn Fn(usize) -> bool + Sync),
        opts: &SceneOptions,
    ) -> Scene {
        let (lo, hi) = mesh.bbox();
        let origin = if mesh.positions.is_empty() {
            DVec3::ZERO
        } else {
            0.5 * (lo + hi)
        };
        let raw = face_normals_raw(mesh);
        let rel = |c: usize| -> [f32; 3] {
            (mesh.positions[mesh.corner_verts[c] as usize] - origin)
                .as_vec3()
                .to_array()
        };
        let corner_normals: Vec<DVec3> = match opts.shading {
            Shading::Smooth => smooth_corner_normals(mesh, &raw, attrs, opts.crease_angle_deg),
            Shading::Flat => flat_corner_normals(mesh, &raw),
        };
        let mut scene = Scene {
            origin,
            bbox: (lo, hi),
            ..Scene::default()
        };
        scene.vertices = (0..mesh.num_corners())
            .into_par_iter()
            .with_min_len(4096)
            .map(|c| Vertex {
                position: rel(c),
                normal: corner_normals[c].as_vec3().to_array(),
                color: match opts.color_by {
                    ColorBy::Solid(c) => c,
                    _ => BASE_COLOR,
                },
            })
            .collect();
        if opts.color_by == ColorBy::Curvature
            && let Ok(h) = prism_geom::analysis::mean_curvature(mesh)
        {
            // The scale is set by the surface, not by the spikes on crease edges.
            let mut on_crease = vec![false; h.len()];
            for (e, a) in attrs {
                if a.crease > 0.0 {
                    for v in [e.0, e.1] {
                        if let Some(x) = on_crease.get_mut(v as usize) {
                            *x = true;
                        }
                    }
                }
            }
            let mut sorted: Vec<f64> = h
                .iter()
                .zip(&on_crease)
                .filter(|(x, c)| x.is_finite() && !**c)
                .map(|(x, _)| *x)
                .collect();
            sorted.sort_by(f64::total_cmp);
            if let (Some(_), n) = (sorted.first(), sorted.len()) {
                let lo = sorted[n * 2 / 100];
                let hi = sorted[(n * 98 / 100).min(n - 1)];
                let span = (hi - lo).max(1e-12);
                for (c, v) in scene.vertices.iter_mut().enumerate() {
                    let x = h[mesh.corner_verts[c] as usize];
                    v.color = curvature_color((x - lo) / span);
                }
                scene.color_range = Some((lo, hi));
            }
        }
        if let (ColorBy::Kind, Some(k)) = (opts.color_by, kinds) {
            for f in (0..mesh.num_faces()).filter(|&f| !hidden(f)) {
                let col = KIND_COLORS[match k.get(f) {
                    Some(FaceKind::Face) | None => 0,
                    Some(FaceKind::Edge) => 1,
                    Some(FaceKind::Vertex) => 2,
                }];
                for c in mesh.face_corners(f) {
                    scene.vertices[c].color = col;
                }
            }
        }
        // Triangles in chunks of faces on every core, joined in face order (the serial
        // result); a chunk fills one buffer.
        const CHUNK: usize = 8192;
        let nf = mesh.num_faces();
        let chunks: Vec<Vec<[u32; 3]>> = (0..nf.div_ceil(CHUNK))
            .into_par_iter()
            .map(|k| {
                let faces = k * CHUNK..((k + 1) * CHUNK).min(nf);
                let mut out = Vec::with_capacity(2 * faces.len());
                for f in faces.filter(|&f| !hidden(f)) {
                    push_face_triangles(mesh, f, unit_or_zero(raw[f]), &mut out);
                }
                out
            })
            .collect();
        scene.indices = Vec::with_capacity(3 * chunks.iter().map(Vec::len).sum::<usize>());
        for c in &chunks {
            scene.indices.extend(c.iter().flatten());
        }
        if opts.wireframe {
            for f in (0..mesh.num_faces()).filter(|&f| !hidden(f)) {
                for l in mesh.face_loops(f) {
                    let r = mesh.loop_corners(l);
                    for c in r.clone() {
                        let n = if c + 1 == r.end { r.start } else { c + 1 };
                        for e in [c, n] {
                            scene.lines.push(LineVertex {
                                position: rel(e),
                                color: [0.08, 0.09, 0.12],
                            });
                        }
                    }
                }
            }
        }
        scene
    }

    /// Paints the faces `faces` of `mesh` (the mesh the scene was built from) in `color`,
    /// whatever the colouring: flipped faces in red over any colour map. Face numbers
    /// outside the mesh are ignored.
    pub fn paint_faces(&mut self, mesh: &PolyMesh, faces: &[u32], color: [f32; 3]) {
        for &f in faces {
            if (f as usize) < mesh.num_faces() {
                for c in mesh.face_corners(f as usize) {
                    if let Some(v) = self.vertices.get_mut(c) {
                        v.color = color;
                    }
                }
            }
        }
    }

    /// Adds the polygon edges of another mesh (e.g. the previous level as a ghost cage).
    pub fn add_cage(&mut self, mesh: &PolyMesh, color: [f32; 3]) {
        let mut segs = Vec::new();
        for l in 0..mesh.num_loops() {
            let vs = mesh.loop_verts(l);
            for i in 0..vs.len() {
                let (a, b) = (vs[i], vs[(i + 1) % vs.len()]);
                segs.push((mesh.positions[a as usize], mesh.positions[b as usize]));
            }
        }
        self.add_segments(&segs, color);
    }

    /// Line segments (absolute coordinates): highlighted edges, displacement vectors,
    /// normals.
    pub fn add_segments(&mut self, segs: &[(DVec3, DVec3)], color: [f32; 3]) {
        for &(a, b) in segs {
            for p in [a, b] {
                self.lines.push(LineVertex {
                    position: self.to_local(p).to_array(),
                    color,
                });
            }
        }
    }

    /// Points drawn as small three-axis crosses of half-size `size`.
    pub fn add_points(&mut self, points: &[DVec3], size: f64, color: [f32; 3]) {
        let mut segs = Vec::with_capacity(3 * points.len());
        for &p in points {
            for axis in [DVec3::X, DVec3::Y, DVec3::Z] {
                segs.push((p - size * axis, p + size * axis));
            }
        }
        self.add_segments(&segs, color);
    }

    /// A sphere around most of the model, in the scene's coordinates, for framing: the
    /// per-axis median of the drawn corners as centre, and the 98th percentile of their
    /// distances to it (times 1.15) as radius, so that a few vertices thrown far away by a
    /// broken step do not shrink the model to a dot. Also how many corners lie more than ten
    /// radii away. The bounding sphere when nothing is drawn.
    pub fn robust_sphere(&self) -> (Vec3, f32, usize) {
        let p: Vec<Vec3> = self
            .vertices
            .iter()
            .map(|v| Vec3::from_array(v.position))
            .filter(|p| p.is_finite())
            .collect();
        if p.is_empty() {
            return (Vec3::ZERO, self.radius(), 0);
        }
        let median = |axis: usize| {
            let mut v: Vec<f32> = p.iter().map(|q| q[axis]).collect();
            v.sort_by(f32::total_cmp);
            v[v.len() / 2]
        };
        let c = Vec3::new(median(0), median(1), median(2));
        let mut d: Vec<f32> = p.iter().map(|q| q.distance(c)).collect();
        d.sort_by(f32::total_cmp);
        let r98 = d[(d.len() * 98 / 100).min(d.len() - 1)];
        let r = (1.15 * r98).max(1e-9).min(self.radius().max(1e-9) * 2.0);
        let far = d.iter().filter(|&&x| x > 10.0 * r).count();
        (c, r, far)
    }

    /// Radius of the bounding sphere around the origin.
    pub fn radius(&self) -> f32 {
        (0.5 * (self.bbox.1 - self.bbox.0).length()).max(1e-9) as f32
    }

    /// Number of triangles.
    pub fn triangles(&self) -> usize {
        self.indices.len() / 3
    }

    /// A point in the scene's coordinates (relative to its origin, `f32`).
    pub fn to_local(&self, p: DVec3) -> Vec3 {
        (p - self.origin).as_vec3()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use prism_geom::primitives;
    use prism_geom::triangulate::face_triangles;

    /// A vertex thrown far away (a broken step) does not shrink the frame to a dot: the
    /// robust sphere holds the torus, and the far corners are counted.
    #[test]
    fn framing_leaves_out_a_few_far_vertices() {
        let mut m = primitives::torus(48, 24, 3.0, 1.0);
        let clean = Scene::plain(&m);
        let (_, r, far) = clean.robust_sphere();
        assert_eq!(far, 0);
        assert!(r > 3.5 && r < 1.2 * clean.radius(), "{r}");
        m.positions[0] = DVec3::new(1e4, 0.0, 0.0);
        let broken = Scene::plain(&m);
        let (c, r, far) = broken.robust_sphere();
        assert_eq!(far, 4, "the four corners of vertex 0");
        assert!(r < 6.0, "{r}");
        // The centre is the torus's, not halfway to the far vertex.
        let torus_centre = broken.to_local(DVec3::ZERO);
        assert!(c.distance(torus_centre) < 0.5, "{c} {torus_centre}");
    }

    #[test]
    fn curvature_colours_run_from_the_inner_to_the_outer_equator_of_a_torus() {
        let m = primitives::torus(48, 24, 3.0, 1.0);
        let opts = SceneOptions {
            color_by: ColorBy::Curvature,
            ..SceneOptions::default()
        };
        let s = Scene::build(&m, &EdgeAttrs::new(), None, &|_| false, &opts);
        let (lo, hi) = s.color_range.expect("a range");
        assert!(lo < hi);
        let distinct: std::collections::BTreeSet<[u32; 3]> = s
            .vertices
            .iter()
            .map(|v| v.color.map(f32::to_bits))
            .collect();
        assert!(distinct.len() > 10);
        // The scale's ends are its first and last colours.
        assert_eq!(curvature_color(-1.0), curvature_color(0.0));
        assert_eq!(curvature_color(f64::NAN), curvature_color(0.0));
        assert!(curvature_color(1.0)[0] > curvature_color(0.0)[0]);
    }

    #[test]
    fn concave_and_holed_faces_triangulate_to_their_area() {
        for m in [primitives::tripod(), primitives::holed_block()] {
            let raw = face_normals_raw(&m);
            for (f, &r) in raw.iter().enumerate() {
                let n = unit_or_zero(r);
                let area: f64 = face_triangles(&m, f, n)
                    .iter()
                    .map(|t| {
                        let p = |c: u32| m.positions[m.corner_verts[c as usize] as usize];
                        0.5 * (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0])).dot(n)
                    })
                    .sum();
                assert!((area - r.length()).abs() < 1e-12, "face {f}: {area}");
            }
        }
    }

    #[test]
    fn smooth_normals_split_at_sharp_edges() {
        // A cube: every edge is 90°, so smooth shading with a 40° crease angle is flat.
        let m = primitives::cube3();
        let flat = Scene::plain(&m);
        let opts = SceneOptions {
            shading: Shading::Smooth,
            ..SceneOptions::default()
        };
        let smooth = Scene::build(&m, &EdgeAttrs::new(), None, &|_| false, &opts);
        assert_eq!(flat.vertices, smooth.vertices);
        // With a 100° crease angle the corners average three faces: (±1, ±1, ±1)/√3.
        let opts = SceneOptions {
            shading: Shading::Smooth,
            crease_angle_deg: 100.0,
            ..SceneOptions::default()
        };
        let round = Scene::build(&m, &EdgeAttrs::new(), None, &|_| false, &opts);
        for v in &round.vertices {
            let n = Vec3::from(v.normal);
            assert!(
                (n.abs() - Vec3::splat(1.0 / 3f32.sqrt())).length() < 1e-6,
                "{n}"
            );
        }
        assert_eq!(round.triangles(), 12);
    }
}
