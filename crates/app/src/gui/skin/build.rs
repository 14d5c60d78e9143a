//! The Skin tab's surface, rebuilt from the document's sections when they change (a skin of
//! a few sections builds in milliseconds, so a drag rebuilds it every frame), with the scene
//! and the teaching overlays (section curves, chains, trajectories, swept sections) drawn from
//! it.

use crate::gui::view3d::{Look, framing, overlay_for, sampled};
use glam::DVec3;
use prism_geom::freeform::spline;
use prism_geom::freeform::{Skin, SkinSpec, skin_with};
use prism_geom::{EdgeAttrs, PolyMesh};
use prism_viewport::Scene;
use std::sync::Arc;
use std::time::Instant;

/// What the overlay shows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Overlays {
    pub sections: bool,
    pub chains: bool,
    pub trajectories: bool,
    pub swept: bool,
    /// Contour lines: sections of the surface by 24 planes z = const (fig. 4b).
    pub contours: bool,
    pub look: Look,
}

impl Default for Overlays {
    fn default() -> Self {
        Overlays {
            sections: true,
            chains: true,
            trajectories: false,
            swept: false,
            contours: false,
            look: Look::default(),
        }
    }
}

pub const SECTION: [f32; 3] = [1.0, 0.85, 0.2];
pub const SELECTED: [f32; 3] = [1.0, 0.35, 0.2];
pub const CHAIN: [f32; 3] = [0.3, 0.8, 1.0];
pub const CREASE: [f32; 3] = [0.9, 0.3, 0.9];
pub const TRAJECTORY: [f32; 3] = [0.9, 0.4, 1.0];
pub const SWEPT: [f32; 3] = [1.0, 0.6, 0.2];
pub const CONTOUR: [f32; 3] = [0.15, 0.15, 0.2];

/// The sections of `mesh` by `count` planes z = const spread over its height (the paper's
/// contour display, fig. 4b): per face, the crossings of its edges joined in pairs.
pub fn contours(mesh: &PolyMesh, count: usize) -> Vec<(DVec3, DVec3)> {
    let (lo, hi) = mesh.bbox();
    let h = hi.z - lo.z;
    if h <= 0.0 {
        return Vec::new();
    }
    let mut out = Vec::new();
    for j in 1..=count {
        let z = lo.z + h * j as f64 / (count + 1) as f64;
        for f in 0..mesh.num_faces() {
            let vs = mesh.loop_verts(mesh.face_loops(f).start);
            let mut hits = Vec::with_capacity(2);
            for i in 0..vs.len() {
                let (a, b) = (
                    mesh.positions[vs[i] as usize],
                    mesh.positions[vs[(i + 1) % vs.len()] as usize],
                );
                if (a.z < z) != (b.z < z) {
                    let t = (z - a.z) / (b.z - a.z);
                    hits.push(a.lerp(b, t));
                }
            }
            for pair in hits.chunks_exact(2) {
                out.push((pair[0], pair[1]));
            }
        }
    }
    out
}

/// One build of the skin.
pub struct Built {
    pub spec: SkinSpec,
    pub result: Result<(Skin, PolyMesh), String>,
    pub millis: f64,
    /// Largest analytic normal jump across inner patch borders, degrees.
    pub jump: f64,
}

impl Built {
    pub fn new(spec: &SkinSpec) -> Built {
        let start = Instant::now();
        let result = skin_with(&spec.sections, spec.basis)
            .map_err(|e| e.to_string())
            .and_then(|s| {
                let m = s
                    .tessellate(spec.resolution, spec.caps)
                    .map_err(|e| e.to_string())?;
                Ok((s, m))
            });
        let millis = start.elapsed().as_secs_f64() * 1e3;
        let jump = match &result {
            Ok((s, _)) => s.border_normal_jump(4),
            Err(_) => 0.0,
        };
        Built {
            spec: spec.clone(),
            result,
            millis,
            jump,
        }
    }
}

fn curve_segments(pieces: &[spline::Cubic], samples: usize) -> Vec<(DVec3, DVec3)> {
    let mut out = Vec::with_capacity(pieces.len() * samples);
    for c in pieces {
        let mut prev = c[0];
        for j in 1..=samples {
            let p = spline::eval(c, j as f64 / samples as f64);
            out.push((prev, p));
            prev = p;
        }
    }
    out
}

fn polygon(points: &[DVec3]) -> Vec<(DVec3, DVec3)> {
    (0..points.len())
        .map(|i| (points[i], points[(i + 1) % points.len()]))
        .collect()
}

/// The surface and its overlay for the view. The selected section is drawn in its own
/// colour; sections are drawn even when the skin cannot be built (so the user sees what is
/// wrong).
pub fn scenes(built: &Built, selected: usize, o: &Overlays) -> (Arc<Scene>, Arc<Scene>) {
    let scene = match &built.result {
        Ok((_, mesh)) => Scene::build(mesh, &EdgeAttrs::new(), None, &|_| false, &o.look.options()),
        // No surface: frame the sections' points.
        Err(_) => framing(
            built
                .spec
                .sections
                .iter()
                .flat_map(|s| s.points.iter().copied()),
        ),
    };
    let (mut overlay, size) = overlay_for(&scene);
    match &built.result {
        Ok((s, _)) => {
            if o.sections {
                for (k, sec) in s.sections.iter().enumerate() {
                    let color = if k == selected { SELECTED } else { SECTION };
                    overlay.add_segments(&curve_segments(&sec.curve, 12), color);
                }
                let pts: Vec<DVec3> = s.sections.iter().flat_map(|x| x.points.clone()).collect();
                overlay.add_points(&pts, 0.006 * size, SECTION);
            }
            if o.chains {
                for (i, chain) in s.chains.iter().enumerate() {
                    let color = if s.crease[i] { CREASE } else { CHAIN };
                    overlay.add_segments(&curve_segments(chain, 12), color);
                }
            }
            if o.trajectories {
                for t in &s.trajectories {
                    overlay.add_segments(&sampled(|u| t.eval(u), 24), TRAJECTORY);
                }
                let centres: Vec<DVec3> = s.sections.iter().map(|x| x.centre).collect();
                overlay.add_points(&centres, 0.01 * size, TRAJECTORY);
            }
            if o.contours
                && let Ok((_, mesh)) = &built.result
            {
                overlay.add_segments(&contours(mesh, 24), CONTOUR);
            }
            if o.swept {
                for w in &s.swept {
                    overlay.add_segments(&polygon(w), SWEPT);
                }
            }
        }
        Err(_) => {
            for (k, sec) in built.spec.sections.iter().enumerate() {
                let color = if k == selected { SELECTED } else { SECTION };
                let pts: Vec<DVec3> = sec
                    .points
                    .iter()
                    .copied()
                    .filter(|p| p.is_finite())
                    .collect();
                overlay.add_segments(&polygon(&pts), color);
            }
        }
    }
    (Arc::new(scene), Arc::new(overlay))
}
