//! The Skin tab's surface, rebuilt from the document's sections when they change (a skin of
//! a few sections builds in about a millisecond, so a drag rebuilds it every frame), its
//! crossings found on a thread (10× the build at K = 8, 140 ms at K = 32: more than a drag's
//! frame can spare), and the scene and the teaching overlays (section curves, chains,
//! trajectories, swept sections, twist angles) drawn from it.

use crate::gui::view3d::{Look, framing, overlay_for, sampled, view_bytes, within_budget};
use glam::DVec3;
use prism_geom::freeform::skin::SkinCrossings;
use prism_geom::freeform::spline;
use prism_geom::freeform::{Skin, SkinSpec};
use prism_geom::progress::Progress;
use prism_geom::{EdgeAttrs, PolyMesh, memory};
use prism_viewport::Scene;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, TryRecvError};
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
    /// The twist of each pair (fig. 2): from the next section's centre, a ray to each swept
    /// vertex and one to the vertex it is paired with.
    pub twists: bool,
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
            twists: false,
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
pub const PAIRED: [f32; 3] = [0.3, 1.0, 0.5];
pub const CROSSING: [f32; 3] = [1.0, 0.1, 0.1];

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
    /// The memory budget it was built within.
    pub budget: u64,
    pub result: Result<(Skin, PolyMesh), String>,
    pub millis: f64,
    /// Largest analytic normal jump across inner patch borders, degrees.
    pub jump: f64,
    /// Where the mesh passes through itself (marked in the view, named in the summary), found
    /// on a thread.
    pub crossings: CrossingCheck,
}

/// The crossing check of a build.
pub enum CrossingCheck {
    Checking(Receiver<SkinCrossings>),
    Done(SkinCrossings),
}

impl Built {
    /// Takes the crossing check's answer when it has come; true when it just did.
    pub fn poll_crossings(&mut self) -> bool {
        let CrossingCheck::Checking(rx) = &self.crossings else {
            return false;
        };
        let found = match rx.try_recv() {
            Ok(c) => c,
            Err(TryRecvError::Empty) => return false,
            Err(TryRecvError::Disconnected) => SkinCrossings::default(),
        };
        self.crossings = CrossingCheck::Done(found);
        true
    }

    /// The crossings, once checked.
    pub fn crossings(&self) -> Option<&SkinCrossings> {
        match &self.crossings {
            CrossingCheck::Done(c) => Some(c),
            CrossingCheck::Checking(_) => None,
        }
    }

    /// The skin of `spec` within `budget` bytes (on the tab's worker thread): the patches,
    /// then — when their mesh, its crossing check and the view's buffers fit the budget — the
    /// mesh, counting its rows in `progress` and stopping when it is cancelled.
    pub fn new((spec, budget): &(SkinSpec, u64), progress: &Progress) -> Built {
        let start = Instant::now();
        let result = spec.build().map_err(|e| e.to_string()).and_then(|s| {
            let counts =
                memory::tessellation_counts(s.patches.len() as u64, spec.resolution as u64);
            let need = memory::tessellation_bytes(&counts)
                + memory::crossing_bytes(&counts)
                + view_bytes(&counts);
            within_budget(need, *budget, "this skin", "a smaller resolution")?;
            let m = s
                .tessellate_with(spec.resolution, spec.caps, progress)
                .map_err(|e| e.to_string())?;
            Ok((s, m))
        });
        let millis = start.elapsed().as_secs_f64() * 1e3;
        let (jump, crossings) = match &result {
            Ok((s, m)) => {
                let (tx, rx) = std::sync::mpsc::channel();
                let (s2, m2, k) = (s.clone(), m.clone(), spec.resolution);
                std::thread::spawn(move || {
                    let _ = tx.send(s2.crossings(&m2, k));
                });
                (s.border_normal_jump(4), CrossingCheck::Checking(rx))
            }
            Err(_) => (0.0, CrossingCheck::Done(SkinCrossings::default())),
        };
        Built {
            spec: spec.clone(),
            budget: *budget,
            result,
            millis,
            jump,
            crossings,
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
    overlay.xray = o.look.xray;
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
            if o.twists {
                // Pair k: from section k + 1's centre, each swept vertex and its partner.
                let n = s.points_per_section();
                for (k, w) in s.swept.iter().enumerate() {
                    let next = &s.sections[k + 1];
                    let rays = |paired: bool| -> Vec<(DVec3, DVec3)> {
                        w.iter()
                            .enumerate()
                            .map(|(i, &v)| {
                                let to = if paired {
                                    next.points[(i + s.shifts[k]) % n]
                                } else {
                                    v
                                };
                                (next.centre, to)
                            })
                            .collect()
                    };
                    overlay.add_segments(&rays(false), SWEPT);
                    overlay.add_segments(&rays(true), PAIRED);
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
    // Faces through each other are always marked: a red cross at each pair.
    if let Some(c) = built.crossings() {
        overlay.add_points(&c.points, 0.01 * size, CROSSING);
    }
    (Arc::new(scene), Arc::new(overlay))
}
