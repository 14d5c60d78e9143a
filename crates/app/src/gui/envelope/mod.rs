//! The Envelope tab (seed 004; docs/algorithms/envelope.md, docs/user-guide.md "The Envelope
//! tab"): a primitive from the library, moved, turned and scaled by typed or dragged numbers or
//! by dragging in the view; the global t and a picked vertex's own t; the envelope rebuilt
//! live with its curve network — on a worker thread, the last surface shown until the next is
//! ready ([`super::latest`]; the t sweep's three builds too); a surface whose mesh would not
//! fit the memory budget is refused before it is tessellated. Every change
//! is one [`Edit::SetEnvelope`]; a drag is one undo step.
//! Any number of primitives: those the others swallow (their centre is not a corner of the
//! hull of the centres) are named in the summary.

pub(crate) mod build;
mod panel;
mod sweep;

use super::command::Edit;
use super::doc_state::DocState;
pub use super::gestures::Mouse;
use super::gestures::{self, Base, Tab3d, dragged_points};
use super::latest::{BUILD_WAIT, Latest};
use super::model::pick::{Projector, pick_vertex};
use super::view3d::View3d;
use super::viewport;
use build::{Built, Overlays};
use glam::DVec3;
use prism_geom::freeform::envelope::{
    Enclosure, EnvelopeSpec, Placement, PrimitiveInput, Shape, Surfacing,
};
use prism_viewport::Scene;
use std::sync::Arc;

/// The bundled scenes: name, file name, contents.
pub const ENVELOPE_SAMPLES: [(&str, &str, &str); 6] = [
    (
        "One cube (t = 1, Table 1)",
        "cube.envelope.json",
        include_str!("../../../../../assets/cube.envelope.json"),
    ),
    (
        "Hexagonal prism (t = 0.5)",
        "hexagonal-prism.envelope.json",
        include_str!("../../../../../assets/hexagonal-prism.envelope.json"),
    ),
    (
        "Two cubes side by side (t = 1)",
        "two-cubes.envelope.json",
        include_str!("../../../../../assets/two-cubes.envelope.json"),
    ),
    (
        "Two cubes on a diagonal (t = 0.7)",
        "diagonal-cubes.envelope.json",
        include_str!("../../../../../assets/diagonal-cubes.envelope.json"),
    ),
    (
        "Seven primitives (t = 1, like Table 2 a)",
        "table2-seven.envelope.json",
        include_str!("../../../../../assets/table2-seven.envelope.json"),
    ),
    (
        "Five primitives (t = 1, like Table 2 b)",
        "table2-five.envelope.json",
        include_str!("../../../../../assets/table2-five.envelope.json"),
    ),
];

/// The primitive library.
pub const LIBRARY: [(&str, Shape); 6] = [
    ("Cube", Shape::Cube),
    (
        "Box",
        Shape::Box {
            a: 1.0,
            b: 0.6,
            c: 0.4,
        },
    ),
    ("Tetrahedron", Shape::Tetrahedron),
    ("Octahedron", Shape::Octahedron),
    ("Triangular prism", Shape::TriangularPrism { height: 1.0 }),
    ("Hexagonal prism", Shape::HexagonalPrism { height: 1.0 }),
];

/// A scene of one library shape of radius 1 at the origin.
pub fn of_shape(shape: Shape) -> EnvelopeSpec {
    EnvelopeSpec {
        t: 1.0,
        primitives: vec![shape.placed(&Placement::default())],
        resolution: 8,
        basis: Default::default(),
        patches: Default::default(),
        enclosure: Default::default(),
    }
}

/// The view slot of the Envelope tab's 3D view (the Model tab uses 0–3, the Skin tab 16); the
/// t sweep's three views use the next three.
const VIEW_SLOT: usize = 17;

/// The t of the sweep's views (the paper's Table 1).
pub const SWEEP: [f64; 3] = [1.0, 0.5, 0.1];

/// One view of the t sweep: its t, build and scenes.
struct SweepView {
    t: f64,
    built: Built,
    scene: Arc<Scene>,
    overlay: Arc<Scene>,
}

/// The sweep's builds of `spec` at each t of [`SWEEP`] (on the worker thread).
fn sweep_builds(
    (spec, budget): &(EnvelopeSpec, u64),
    progress: &prism_geom::progress::Progress,
) -> (EnvelopeSpec, Vec<Built>) {
    let builds = SWEEP
        .iter()
        .map(|&t| Built::new(&with_uniform_t(spec, t), *budget, false, progress))
        .collect();
    (spec.clone(), builds)
}

/// The scene with one uniform t (own values of primitives and vertices dropped).
pub fn with_uniform_t(spec: &EnvelopeSpec, t: f64) -> EnvelopeSpec {
    let mut s = spec.clone();
    s.t = t;
    for p in &mut s.primitives {
        p.t = None;
        p.vertex_t = None;
    }
    s
}

/// Transient values of the number fields that act by difference (rotation; the scale's is in `Gestures`).
#[derive(Debug, Default, Clone, Copy)]
struct Gesture {
    rotate: [f64; 3],
}

pub struct EnvelopeTab {
    /// The primitive the placement fields and view drags act on.
    pub selected: usize,
    /// The vertex (primitive, vertex) whose t the panel edits: clicked in the view.
    pub picked: Option<(usize, usize)>,
    pub mouse: Mouse,
    /// The drag under way: its gesture and the primitive's vertices when it began.
    drag: Option<(u64, Vec<DVec3>)>,
    pub overlays: Overlays,
    /// Shows t = 1, 0.5, 0.1 side by side instead of the one view (Table 1).
    pub sweep: bool,
    sweep_views: Vec<SweepView>,
    /// The scene the sweep's views were built from.
    sweep_for: Option<EnvelopeSpec>,
    sweeps: Latest<(EnvelopeSpec, u64), (EnvelopeSpec, Vec<Built>)>,
    /// The view, the gesture counter and this frame's commands.
    pub base: Base,
    /// The memory the envelope may take (the Model tab's budget), bytes.
    pub budget: u64,
    built: Option<Built>,
    builds: Latest<(EnvelopeSpec, u64), Built>,
    shown: Option<(Option<(usize, usize)>, Overlays)>,
    gesture: Gesture,
}

impl Default for EnvelopeTab {
    fn default() -> Self {
        EnvelopeTab {
            selected: 0,
            picked: None,
            mouse: Mouse::Orbit,
            drag: None,
            overlays: Overlays::default(),
            sweep: false,
            sweep_views: Vec::new(),
            sweep_for: None,
            sweeps: Latest::new(sweep_builds),
            base: Base::new(VIEW_SLOT),
            budget: super::launch::DEFAULT_BUDGET_MIB << 20,
            built: None,
            builds: Latest::new(Built::checked),
            shown: None,
            gesture: Gesture::default(),
        }
    }
}

fn centre_of(p: &PrimitiveInput) -> DVec3 {
    let n = p.vertices.len().max(1) as f64;
    p.vertices
        .iter()
        .map(|v| DVec3::from_array(*v))
        .sum::<DVec3>()
        / n
}

/// `p`'s vertices mapped by `f`.
fn mapped(p: &PrimitiveInput, f: impl Fn(DVec3) -> DVec3) -> PrimitiveInput {
    PrimitiveInput {
        vertices: p
            .vertices
            .iter()
            .map(|v| f(DVec3::from_array(*v)).to_array())
            .collect(),
        ..p.clone()
    }
}

impl EnvelopeTab {
    /// The last build (for the tests).
    #[cfg(test)]
    pub fn built(&self) -> Option<&Built> {
        self.built.as_ref()
    }

    /// Whether a build is under way on the worker thread (the view shows the last one).
    pub fn building(&self) -> bool {
        self.builds.busy() || self.sweeps.busy()
    }

    /// Takes the worker's build of `spec` when it has come (within [`BUILD_WAIT`]), or an
    /// earlier one newer than the view's; true when a new build was taken.
    fn rebuild(&mut self, spec: &EnvelopeSpec) -> bool {
        if self
            .built
            .as_ref()
            .is_some_and(|b| &b.spec == spec && b.budget == self.budget)
        {
            self.builds.clear();
            return false;
        }
        match self.builds.want(&(spec.clone(), self.budget), BUILD_WAIT) {
            Some(b) => {
                self.built = Some(b);
                true
            }
            None => false,
        }
    }

    /// The screen mapping of the view in `rect` (clicks pick vertices with it).
    pub fn projector(&self, rect: egui::Rect) -> Projector {
        Projector {
            view_proj: self
                .base
                .view
                .camera
                .view_proj(rect.width() / rect.height().max(1.0)),
            rect,
            origin: self.base.view.scene.origin,
        }
    }

    /// A primary drag that moves or scales the primitive (one undo step).
    fn primitive_drag(
        &mut self,
        ui: &egui::Ui,
        resp: &egui::Response,
        rect: egui::Rect,
        spec: &EnvelopeSpec,
    ) {
        let k = self.selected;
        let begin = || {
            let p = spec.primitives.get(k)?;
            Some(p.vertices.iter().map(|v| DVec3::from_array(*v)).collect())
        };
        let Some((g, start, total)) =
            gestures::view_drag(&mut self.drag, &mut self.base.gestures, ui, resp, begin)
        else {
            return;
        };
        // The envelope offers no turn: a turn by a drag would need an axis.
        let Some(how) = self
            .mouse
            .points_drag(DVec3::Z)
            .filter(|_| self.mouse != Mouse::Turn)
        else {
            return;
        };
        if spec
            .primitives
            .get(k)
            .is_none_or(|p| p.vertices.len() != start.len())
        {
            return;
        }
        let camera = &self.base.view.camera;
        let moved = dragged_points(how, camera, (total, rect.height()), &start);
        let mut s = spec.clone();
        s.primitives[k].vertices = moved.iter().map(|v| v.to_array()).collect();
        self.set(Some(s), Some(g));
    }
}

impl Tab3d for EnvelopeTab {
    type Spec = EnvelopeSpec;
    const SAMPLES: &'static [(&'static str, &'static str, &'static str)] = &ENVELOPE_SAMPLES;
    const PANEL: &'static str = "envelope_panel";

    /// Rebuilds the envelope and the scenes when the scene or the overlays changed.
    fn sync(&mut self, spec: Option<&EnvelopeSpec>) {
        let Some(spec) = spec else {
            self.built = None;
            self.builds.clear();
            self.sweeps.clear();
            self.base.view.clear();
            self.shown = None;
            self.picked = None;
            return;
        };
        let fresh = self.rebuild(spec);
        if self.built.is_none() {
            return;
        }
        // The crossings' marks join the overlay when the check's answer comes.
        if let Some(b) = self.built.as_mut()
            && b.poll_crossings()
            && !fresh
            && self.shown == Some((self.picked, self.overlays))
        {
            self.base
                .view
                .show(build::scenes(b, self.picked, &self.overlays));
        }
        if let Some((p, v)) = self.picked
            && spec.primitives.get(p).is_none_or(|x| v >= x.vertices.len())
        {
            self.picked = None;
        }
        self.selected = self.selected.min(spec.primitives.len().saturating_sub(1));
        let overlays_changed = self.shown.is_none_or(|(_, o)| o != self.overlays);
        if fresh || self.shown != Some((self.picked, self.overlays)) {
            let b = self.built.as_ref().expect("built above");
            self.base
                .view
                .show(build::scenes(b, self.picked, &self.overlays));
            self.shown = Some((self.picked, self.overlays));
        }
        // The sweep's three builds on the worker too; the last ones shown until they come.
        let mut swept = false;
        if self.sweep && self.sweep_for.as_ref() != Some(spec) {
            if let Some((s, builds)) = self.sweeps.want(&(spec.clone(), self.budget), BUILD_WAIT) {
                self.sweep_views = builds
                    .into_iter()
                    .zip(SWEEP)
                    .map(|(built, t)| SweepView {
                        t,
                        built,
                        scene: Arc::default(),
                        overlay: Arc::default(),
                    })
                    .collect();
                self.sweep_for = Some(s);
                swept = true;
            }
        } else if !self.sweep {
            self.sweeps.clear();
        }
        if swept || overlays_changed {
            for v in &mut self.sweep_views {
                (v.scene, v.overlay) = build::scenes(&v.built, None, &self.overlays);
            }
        }
    }

    fn base(&mut self) -> &mut Base {
        &mut self.base
    }

    fn panel(&mut self, ui: &mut egui::Ui, spec: Option<&EnvelopeSpec>) {
        self.side_panel(ui, spec);
    }

    fn view(&mut self, ui: &mut egui::Ui, spec: Option<&EnvelopeSpec>) {
        let rect = ui.available_rect_before_wrap();
        let Some(spec) = spec else {
            ui.centered_and_justified(|ui| {
                ui.label("Pick a primitive on the left; its envelope appears here.");
            });
            return;
        };
        let resp = self
            .base
            .view
            .interact(ui, rect, "envelope_view", self.mouse == Mouse::Orbit);
        if self.mouse != Mouse::Orbit {
            self.primitive_drag(ui, &resp, rect, spec);
        }
        if resp.clicked()
            && let Some(at) = resp.interact_pointer_pos()
        {
            let proj = self.projector(rect);
            let owner: Vec<(usize, usize)> = spec
                .primitives
                .iter()
                .enumerate()
                .flat_map(|(p, x)| (0..x.vertices.len()).map(move |v| (p, v)))
                .collect();
            let positions: Vec<DVec3> = spec
                .primitives
                .iter()
                .flat_map(|p| p.vertices.iter().map(|v| DVec3::from_array(*v)))
                .collect();
            self.picked = pick_vertex(&proj, None, &positions, at, 14.0).map(|i| owner[i as usize]);
            if let Some((p, _)) = self.picked {
                self.selected = p;
            }
        }
        if self.sweep && !self.sweep_views.is_empty() {
            viewport::paint_background(ui, rect);
            self.paint_sweep(ui, rect);
        } else {
            self.base.view.paint(ui, rect);
        }
        let orbit = "drag: orbit · right drag: pan · wheel: zoom · click: pick a vertex";
        View3d::hint(ui, rect, &self.mouse.hint("primitive", orbit));
    }

    fn part(doc: &DocState) -> Option<&Self::Spec> {
        doc.envelope.as_ref()
    }

    fn surface(&self) -> Result<&prism_geom::PolyMesh, &str> {
        let built = self.built.as_ref().ok_or("no scene")?;
        built.result.as_ref().map(|r| &r.1).map_err(String::as_str)
    }

    fn edit(spec: Option<EnvelopeSpec>, gesture: Option<u64>) -> Edit {
        Edit::SetEnvelope { spec, gesture }
    }
}
