//! The Envelope tab's surface, rebuilt from the document's scene when it changes (one
//! primitive builds in well under a millisecond, so a drag or the t slider rebuilds it every
//! frame), with the scene and the overlays drawn from it: the primitives, the curve network
//! (primitive edges, silhouette edges, fusion edges, insertion curves and the sections'
//! straight edges in their own colours), the picked vertex.

use crate::gui::view3d::{Look, framing, overlay_for, sampled, view_bytes, within_budget};
use glam::DVec3;
use prism_geom::freeform::envelope::chart::quality::Quality;
use prism_geom::freeform::envelope::{CurveKind, Envelope, EnvelopeSpec, envelope};
use prism_geom::progress::Progress;
use prism_geom::{EdgeAttrs, PolyMesh, memory};
use prism_viewport::Scene;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, TryRecvError};
use std::time::Instant;

/// What the view shows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Overlays {
    pub primitives: bool,
    pub edges: bool,
    pub silhouettes: bool,
    pub fusion: bool,
    pub insertions: bool,
    /// The sections' straight edges (inside the solid).
    pub straight: bool,
    pub surface: bool,
    pub look: Look,
}

impl Default for Overlays {
    fn default() -> Self {
        Overlays {
            primitives: true,
            edges: true,
            silhouettes: true,
            fusion: true,
            insertions: true,
            straight: true,
            surface: true,
            look: Look::default(),
        }
    }
}

pub const PRIMITIVE: [f32; 3] = [0.75, 0.75, 0.8];
pub const EDGE: [f32; 3] = [1.0, 0.85, 0.2];
pub const SILHOUETTE: [f32; 3] = [1.0, 0.5, 0.15];
pub const FUSION: [f32; 3] = [0.35, 0.9, 0.4];
pub const INSERTION: [f32; 3] = [0.3, 0.8, 1.0];
pub const STRAIGHT: [f32; 3] = [0.85, 0.35, 0.85];
pub const PICKED: [f32; 3] = [1.0, 0.35, 0.2];
pub const FOLDED: [f32; 3] = [1.0, 0.1, 0.1];

/// One build of the envelope.
pub struct Built {
    pub spec: EnvelopeSpec,
    /// The memory budget it was built within.
    pub budget: u64,
    pub result: Result<(Envelope, PolyMesh), String>,
    /// Network and patches, milliseconds (no tessellation).
    pub millis: f64,
    /// Largest analytic normal jump across patch borders, degrees.
    pub jump: f64,
    /// The fold warning, when some sampled cell folds ([`Envelope::folds`]), and the count.
    pub folds: Option<(usize, String)>,
    /// The folded cells' centres on the surface, marked in the view.
    pub fold_points: Vec<DVec3>,
    /// The quality report of the mesh ([`Envelope::quality`]: angles, normal turns, inward
    /// faces, enclosure), computed on the crossing check's thread.
    pub quality: Option<Quality>,
    /// Where the surface passes through itself: checked on a thread
    /// ([`prism_geom::freeform::envelope::folds::crossings`]; 18 ms for the seven-primitive
    /// scene's 8,640 faces, more than a drag's frame can spare).
    pub crossings: Crossings,
}

/// The crossing check of a build, with the quality report of its mesh (both on a thread).
pub enum Crossings {
    Checking(Receiver<(Vec<DVec3>, Quality)>),
    /// The midpoints of the pairs of faces that pass through each other, and the warning.
    Done(Vec<DVec3>, Option<String>),
    /// No surface, or not checked (the t sweep's views).
    None,
}

impl Built {
    /// The tab's build (on its worker thread): [`Built::new`] with the crossing check.
    pub fn checked((spec, budget): &(EnvelopeSpec, u64), progress: &Progress) -> Built {
        Built::new(spec, *budget, true, progress)
    }

    /// The envelope of `spec`, its folds, and — when `check_crossings` (the view the summary
    /// describes; the t sweep's views show no summary) — a crossing check started on a
    /// thread. A mesh that with its checks and the view's copy would take more than `budget`
    /// bytes is refused before it is built. The mesh counts its charts in `progress` and stops
    /// when it is cancelled.
    pub fn new(
        spec: &EnvelopeSpec,
        budget: u64,
        check_crossings: bool,
        progress: &Progress,
    ) -> Built {
        let construction = spec.construction_bytes();
        let (what, knob) = ("this envelope", "a smaller resolution or fewer primitives");
        let start = Instant::now();
        let e = within_budget(construction + memory::BASELINE, budget, what, knob)
            .and_then(|()| envelope(spec).map_err(|e| e.to_string()));
        let millis = start.elapsed().as_secs_f64() * 1e3;
        // The region of each face, for the quality report on the check's thread.
        let mut regions = Vec::new();
        let result = e.map_err(|e| e.to_string()).and_then(|e| {
            let counts = e.mesh_counts(spec.resolution);
            let need = memory::surface_bytes(&counts) + view_bytes(&counts);
            within_budget(
                need,
                budget,
                "this envelope",
                "a smaller resolution or fewer primitives",
            )?;
            let (m, r) = e
                .mesh_with(spec.resolution, progress)
                .map_err(|e| e.to_string())?;
            regions = r;
            Ok((e, m))
        });
        let jump = match &result {
            Ok((e, _)) => e.largest_border_jump(),
            Err(_) => 0.0,
        };
        let (folds, fold_points) = match &result {
            Ok((e, _)) => {
                let f = e.folds();
                let points = f
                    .iter()
                    .filter_map(|c| e.patches.get(c.patch).map(|p| p.coons.eval(c.u, c.v)))
                    .map(|x| e.frame.to_world(x))
                    .collect();
                (e.fold_warning(&f).map(|w| (f.len(), w)), points)
            }
            Err(_) => (None, Vec::new()),
        };
        let crossings = match &result {
            Ok((e, m)) if check_crossings => {
                let (tx, rx) = std::sync::mpsc::channel();
                let (e, m) = (e.clone(), m.clone());
                std::thread::spawn(move || {
                    let crossings = prism_geom::freeform::envelope::folds::crossings(&m);
                    let quality = e.quality_of(&m, &regions);
                    let _ = tx.send((crossings, quality));
                });
                Crossings::Checking(rx)
            }
            _ => Crossings::None,
        };
        Built {
            spec: spec.clone(),
            budget,
            result,
            millis,
            jump,
            folds,
            fold_points,
            quality: None,
            crossings,
        }
    }

    /// Takes the crossing check's answer when it has come; true when it just did.
    pub fn poll_crossings(&mut self) -> bool {
        let Crossings::Checking(rx) = &self.crossings else {
            return false;
        };
        let points = match rx.try_recv() {
            Ok((p, q)) => {
                self.quality = Some(q);
                p
            }
            Err(TryRecvError::Empty) => return false,
            Err(TryRecvError::Disconnected) => Vec::new(),
        };
        let warning = match &self.result {
            Ok((e, _)) => e.crossing_warning(&points, self.spec.resolution),
            Err(_) => None,
        };
        self.crossings = Crossings::Done(points, warning);
        true
    }

    /// The crossing midpoints found so far (none while checking).
    pub fn crossing_points(&self) -> &[DVec3] {
        match &self.crossings {
            Crossings::Done(p, _) => p,
            _ => &[],
        }
    }
}

fn primitive_edges(spec: &EnvelopeSpec) -> Vec<(DVec3, DVec3)> {
    let mut out = Vec::new();
    for p in &spec.primitives {
        let v = |i: usize| p.vertices.get(i).map(|x| DVec3::from_array(*x));
        for f in &p.faces {
            for k in 0..f.len() {
                let (a, b) = (f[k], f[(k + 1) % f.len()]);
                if a < b
                    && let (Some(pa), Some(pb)) = (v(a), v(b))
                    && pa.is_finite()
                    && pb.is_finite()
                {
                    out.push((pa, pb));
                }
            }
        }
    }
    out
}

/// The surface and its overlay for the view; `picked` is the vertex (primitive, vertex)
/// whose t is being edited. The primitives are drawn even when the envelope cannot be built.
pub fn scenes(
    built: &Built,
    picked: Option<(usize, usize)>,
    o: &Overlays,
) -> (Arc<Scene>, Arc<Scene>) {
    let all: Vec<DVec3> = built
        .spec
        .primitives
        .iter()
        .flat_map(|p| p.vertices.iter().map(|x| DVec3::from_array(*x)))
        .filter(|p| p.is_finite())
        .collect();
    let scene = match &built.result {
        Ok((_, mesh)) if o.surface => {
            Scene::build(mesh, &EdgeAttrs::new(), None, &|_| false, &o.look.options())
        }
        Ok((_, mesh)) => framing(mesh.positions.iter().copied()),
        Err(_) => framing(all.iter().copied()),
    };
    let (mut overlay, size) = overlay_for(&scene);
    overlay.xray = o.look.xray;
    if o.primitives {
        overlay.add_segments(&primitive_edges(&built.spec), PRIMITIVE);
        overlay.add_points(&all, 0.006 * size, PRIMITIVE);
    }
    if let Ok((e, _)) = &built.result {
        for kind in [
            CurveKind::Edge,
            CurveKind::Silhouette,
            CurveKind::Fusion,
            CurveKind::Insertion,
        ] {
            let (show, color) = match kind {
                CurveKind::Edge => (o.edges, EDGE),
                CurveKind::Silhouette => (o.silhouettes, SILHOUETTE),
                CurveKind::Fusion => (o.fusion, FUSION),
                CurveKind::Insertion => (o.insertions, INSERTION),
            };
            if !show {
                continue;
            }
            let segs: Vec<(DVec3, DVec3)> = e
                .network
                .curves
                .iter()
                .filter(|c| c.kind == kind)
                .flat_map(|c| sampled(|u| e.frame.to_world(c.bezier.eval(u)), 24))
                .collect();
            overlay.add_segments(&segs, color);
        }
        if o.straight {
            let segs: Vec<(DVec3, DVec3)> = e
                .straight
                .iter()
                .map(|s| (e.frame.to_world(s[0]), e.frame.to_world(s[1])))
                .collect();
            overlay.add_segments(&segs, STRAIGHT);
        }
    }
    // Folded cells and faces through each other are always marked: a red cross at each.
    overlay.add_points(&built.fold_points, 0.01 * size, FOLDED);
    overlay.add_points(built.crossing_points(), 0.01 * size, FOLDED);
    if let Some((p, v)) = picked
        && let Some(x) = built.spec.primitives.get(p).and_then(|p| p.vertices.get(v))
    {
        overlay.add_points(&[DVec3::from_array(*x)], 0.015 * size, PICKED);
    }
    (Arc::new(scene), Arc::new(overlay))
}
