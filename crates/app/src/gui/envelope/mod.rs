//! The Envelope tab (seed 004; docs/algorithms/envelope.md, docs/user-guide.md "The Envelope
//! tab"): a primitive from the library, moved, turned and scaled by typed or dragged numbers or
//! by dragging in the view; the global t and a picked vertex's own t; the envelope rebuilt
//! live with its curve network — on a worker thread, the last surface shown until the next is
//! ready (a build that answers within [`BUILD_WAIT`] is shown in the same frame). Every change
//! is one [`Edit::SetEnvelope`]; a drag is one undo step.
//! Any number of primitives: those the others swallow (their centre is not a corner of the
//! hull of the centres) are named in the summary.

pub(crate) mod build;

use super::command::{Command, Edit};
use super::gestures::{self, Gestures};
use super::model::pick::{Projector, pick_vertex};
use super::view3d::View3d;
use super::viewport;
use build::{Built, Overlays};
use glam::{DQuat, DVec3};
use prism_geom::freeform::Basis;
use prism_geom::freeform::envelope::{
    Enclosure, EnvelopeSpec, Placement, PrimitiveInput, Shape, Surfacing,
};
use prism_viewport::Scene;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, RecvTimeoutError};
use std::time::Duration;

/// How long a frame waits for the worker's build before it shows the last one instead.
pub const BUILD_WAIT: Duration = Duration::from_millis(40);

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

/// The scene of bundled sample `k`.
pub fn sample(k: usize) -> Result<EnvelopeSpec, String> {
    let (name, _, text) = ENVELOPE_SAMPLES.get(k).ok_or("no such sample")?;
    serde_json::from_str(text).map_err(|e| format!("{name}: {e}"))
}

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

/// What a primary drag in the view does.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mouse {
    #[default]
    Orbit,
    /// Moves the primitive in the view plane.
    Move,
    /// Scales the primitive about its centre.
    Scale,
}

/// Transient values of the number fields that act by difference (rotation, scale).
#[derive(Debug, Default, Clone, Copy)]
struct Gesture {
    rotate: [f64; 3],
    scale: f64,
}

pub struct EnvelopeTab {
    /// The primitive the placement fields and view drags act on.
    pub selected: usize,
    /// The vertex (primitive, vertex) whose t the panel edits: clicked in the view.
    pub picked: Option<(usize, usize)>,
    pub mouse: Mouse,
    drag: Option<(u64, Vec<[f64; 3]>)>,
    pub overlays: Overlays,
    /// Shows t = 1, 0.5, 0.1 side by side instead of the one view (Table 1).
    pub sweep: bool,
    sweep_views: Vec<SweepView>,
    pub view: View3d,
    built: Option<Built>,
    /// The build under way on the worker thread: its scene and where it will answer.
    pending: Option<(EnvelopeSpec, Receiver<Built>)>,
    shown: Option<(Option<(usize, usize)>, Overlays)>,
    gestures: Gestures,
    gesture: Gesture,
    out: Vec<Command>,
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
            view: View3d::new(VIEW_SLOT),
            built: None,
            pending: None,
            shown: None,
            gestures: Gestures::default(),
            gesture: Gesture {
                scale: 100.0,
                ..Gesture::default()
            },
            out: Vec::new(),
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
    /// The last build (for the tests and the export).
    pub fn built(&self) -> Option<&Built> {
        self.built.as_ref()
    }

    /// Whether a build is under way on the worker thread (the view shows the last one).
    pub fn building(&self) -> bool {
        self.pending.is_some()
    }

    /// Starts the build of `spec` on the worker thread unless it is under way, and takes its
    /// answer when it comes within [`BUILD_WAIT`]; true when a new build was taken.
    fn rebuild(&mut self, spec: &EnvelopeSpec) -> bool {
        if self.built.as_ref().is_some_and(|b| &b.spec == spec) {
            self.pending = None;
            return false;
        }
        if self.pending.as_ref().is_none_or(|(s, _)| s != spec) {
            let (tx, rx) = std::sync::mpsc::channel();
            let s = spec.clone();
            // A build that is no longer wanted finishes and its answer is dropped.
            std::thread::spawn(move || {
                let _ = tx.send(Built::new(&s, true));
            });
            self.pending = Some((spec.clone(), rx));
        }
        let Some((_, rx)) = &self.pending else {
            return false;
        };
        match rx.recv_timeout(BUILD_WAIT) {
            Ok(b) => {
                self.built = Some(b);
                self.pending = None;
                true
            }
            Err(RecvTimeoutError::Timeout) => false,
            Err(RecvTimeoutError::Disconnected) => {
                self.pending = None;
                false
            }
        }
    }

    /// Rebuilds the envelope and the scenes when the scene or the overlays changed.
    pub fn sync(&mut self, spec: Option<&EnvelopeSpec>) {
        let Some(spec) = spec else {
            self.built = None;
            self.pending = None;
            self.view.clear();
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
            self.view
                .show(build::scenes(b, self.picked, &self.overlays));
        }
        if let Some((p, v)) = self.picked
            && spec.primitives.get(p).is_none_or(|x| v >= x.vertices.len())
        {
            self.picked = None;
        }
        self.selected = self.selected.min(spec.primitives.len().saturating_sub(1));
        if fresh || self.shown != Some((self.picked, self.overlays)) {
            let b = self.built.as_ref().expect("built above");
            self.view
                .show(build::scenes(b, self.picked, &self.overlays));
            self.shown = Some((self.picked, self.overlays));
            self.sweep_views.clear();
        }
        if self.sweep && self.sweep_views.is_empty() {
            self.sweep_views = SWEEP
                .iter()
                .map(|&t| {
                    let built = Built::new(&with_uniform_t(spec, t), false);
                    let (scene, overlay) = build::scenes(&built, None, &self.overlays);
                    SweepView {
                        t,
                        built,
                        scene,
                        overlay,
                    }
                })
                .collect();
        }
    }

    /// The screen mapping of the view in `rect` (clicks pick vertices with it).
    pub fn projector(&self, rect: egui::Rect) -> Projector {
        Projector {
            view_proj: self
                .view
                .camera
                .view_proj(rect.width() / rect.height().max(1.0)),
            rect,
            origin: self.view.scene.origin,
        }
    }

    /// Frames the envelope again on the next frame (a new sample).
    pub fn reframe(&mut self) {
        self.view.reframe();
    }

    fn set(&mut self, spec: Option<EnvelopeSpec>, gesture: Option<u64>) {
        self.out
            .push(Command::Edit(Edit::SetEnvelope { spec, gesture }));
    }

    pub fn ui(&mut self, ui: &mut egui::Ui, spec: Option<&EnvelopeSpec>) -> Vec<Command> {
        self.sync(spec);
        gestures::layout(
            ui,
            "envelope_panel",
            self,
            |t, ui| t.panel(ui, spec),
            |t, ui| t.view(ui, spec),
        );
        std::mem::take(&mut self.out)
    }

    fn panel(&mut self, ui: &mut egui::Ui, spec: Option<&EnvelopeSpec>) {
        ui.heading("Envelope of primitives");
        let Some(spec) = spec else {
            ui.label("No primitive yet. Start from one of the library:");
            ui.horizontal_wrapped(|ui| {
                for (name, shape) in LIBRARY {
                    if ui.button(name).clicked() {
                        self.view.reframe();
                        self.set(Some(of_shape(shape)), None);
                    }
                }
            });
            ui.label("or a bundled scene (also in File > Samples):");
            for (k, (name, _, _)) in ENVELOPE_SAMPLES.iter().enumerate() {
                if ui.button(*name).clicked() {
                    match sample(k) {
                        Ok(s) => {
                            self.view.reframe();
                            self.set(Some(s), None);
                        }
                        Err(e) => self.out.push(Command::Say(e)),
                    }
                }
            }
            return;
        };
        self.summary(ui);
        ui.separator();
        ui.label("Primitives");
        for (k, p) in spec.primitives.iter().enumerate() {
            let c = centre_of(p);
            let text = format!(
                "{k}: {} vertices, {} faces at ({:.2}, {:.2}, {:.2})",
                p.vertices.len(),
                p.faces.len(),
                c.x,
                c.y,
                c.z
            );
            if ui.selectable_label(k == self.selected, text).clicked() {
                self.selected = k;
            }
        }
        let k = self.selected;
        ui.horizontal_wrapped(|ui| {
            ui.label("Replace with");
            for (name, shape) in LIBRARY {
                if ui.small_button(name).clicked() {
                    let mut s = spec.clone();
                    let at = spec.primitives.get(k).map(centre_of).unwrap_or_default();
                    s.primitives[k] = mapped(&shape.placed(&Placement::default()), |v| v + at);
                    self.picked = None;
                    self.set(Some(s), None);
                }
            }
        });
        ui.horizontal_wrapped(|ui| {
            ui.menu_button("Add", |ui| {
                for (name, shape) in LIBRARY {
                    if ui.button(name).clicked() {
                        let mut s = spec.clone();
                        let at = spec.primitives.get(k).map(centre_of).unwrap_or_default();
                        // Beside the selected one, clear of every centre in the scene.
                        let step = DVec3::new(2.5, 0.8, 0.4);
                        let mut c = at + step;
                        while spec
                            .primitives
                            .iter()
                            .any(|p| centre_of(p).distance(c) < 1.0)
                        {
                            c += step;
                        }
                        s.primitives
                            .push(mapped(&shape.placed(&Placement::default()), |v| v + c));
                        self.selected = s.primitives.len() - 1;
                        self.set(Some(s), None);
                    }
                }
            });
            let delete = ui.add_enabled(spec.primitives.len() > 1, egui::Button::new("Delete"));
            if delete
                .on_disabled_hover_text("The scene needs a primitive; Clear removes the scene")
                .clicked()
            {
                let mut s = spec.clone();
                s.primitives.remove(k);
                self.picked = None;
                self.set(Some(s), None);
            }
        });
        if let Some(p) = spec.primitives.get(k) {
            self.placement(ui, spec, k, p);
        }
        ui.separator();
        self.curvature(ui, spec);
        ui.separator();
        ui.label("Surface");
        let mut surfacing = spec.patches;
        ui.horizontal(|ui| {
            ui.radio_value(&mut surfacing, Surfacing::Charts, "charts")
                .on_hover_text("Each region a graph over its flat chart: it cannot fold, the faces are enclosed, G1 along every curve by one shared tangent plane (the default)");
            ui.radio_value(&mut surfacing, Surfacing::Paper, "paper")
                .on_hover_text("Seed 004 §6 as printed: vector Coons patches with Gregory's twist, n-sided regions split about an inserted point; may fold (counted below)");
        });
        if surfacing != spec.patches {
            let mut s = spec.clone();
            s.patches = surfacing;
            self.set(Some(s), None);
        }
        let mut enclosure = spec.enclosure;
        ui.add_enabled_ui(spec.patches == Surfacing::Charts, |ui| {
            ui.horizontal(|ui| {
                ui.label("Cut corners");
                ui.radio_value(&mut enclosure, Enclosure::Lifted, "held")
                    .on_hover_text("The fusion strips are raised over the corners the silhouette plane through each centre cuts off: every primitive lies inside (the default)");
                ui.radio_value(&mut enclosure, Enclosure::Paper, "paper's cut")
                    .on_hover_text("The paper's central cut as it lies: at small t a cut-off corner can poke out (named in the Enclosure row)");
            });
        })
        .response
        .on_disabled_hover_text("The charts only: the paper's patches keep the paper's cut");
        if enclosure != spec.enclosure {
            let mut s = spec.clone();
            s.enclosure = enclosure;
            self.set(Some(s), None);
        }
        let mut res = spec.resolution;
        // A scene's own resolution (the CLI takes up to 256) is kept until the slider moves.
        let r = ui
            .add(
                egui::Slider::new(&mut res, 1..=32)
                    .clamping(egui::SliderClamping::Edits)
                    .text(match spec.patches {
                        Surfacing::Charts => "mesh density",
                        Surfacing::Paper => "quads a patch side",
                    }),
            )
            .on_hover_text(match spec.patches {
                Surfacing::Charts => "About this many mesh edges along a primitive's edge",
                Surfacing::Paper => "Quads along each side of a patch",
            });
        let g = self.gestures.of(&r);
        if res != spec.resolution {
            let mut s = spec.clone();
            s.resolution = res;
            self.set(Some(s), g);
        }
        let mut basis = spec.basis;
        ui.add_enabled_ui(spec.patches == Surfacing::Paper, |ui| ui.horizontal(|ui| {
            ui.label("G1 basis");
            ui.radio_value(&mut basis, Basis::Virtual, "virtual")
                .on_hover_text("Both sides of a border from the crossing curves: the surface does not depend on how faces and primitives are listed (the default)");
            ui.radio_value(&mut basis, Basis::OneSided, "one-sided (paper)")
                .on_hover_text("The region listed first leads each border and the other follows: G1 too, but a cube's tangent planes tilt 18° into the sphere at mid-edge and the shape depends on the listing");
        }))
        .response
        .on_disabled_hover_text("The paper's patches only: the charts share one tangent plane per curve");
        if basis != spec.basis {
            let mut s = spec.clone();
            s.basis = basis;
            self.set(Some(s), None);
        }
        ui.horizontal_wrapped(|ui| {
            ui.label("Drag in the view:");
            ui.radio_value(&mut self.mouse, Mouse::Orbit, "orbit");
            ui.radio_value(&mut self.mouse, Mouse::Move, "move");
            ui.radio_value(&mut self.mouse, Mouse::Scale, "scale");
        })
        .response
        .on_hover_text("Move and scale act on the primitive; right drag orbits then. A click picks a vertex for its own t");
        ui.separator();
        ui.label("Show");
        let o = &mut self.overlays;
        ui.checkbox(&mut o.primitives, "Primitive (grey)");
        ui.checkbox(&mut o.edges, "Curved edges (yellow)");
        ui.checkbox(&mut o.silhouettes, "Silhouette edges (orange)");
        ui.checkbox(&mut o.fusion, "Fusion edges between primitives (green)");
        ui.checkbox(&mut o.insertions, "Insertion curves of split faces (blue)");
        ui.checkbox(
            &mut o.straight,
            "Straight edges of the sections, inside (violet)",
        );
        ui.checkbox(&mut o.surface, "Surface");
        ui.checkbox(&mut o.wireframe, "Iso-parameter lines");
        ui.checkbox(&mut o.curvature, "Mean-curvature colours");
        ui.checkbox(&mut o.smooth, "Smooth shading");
        ui.checkbox(&mut self.sweep, "t sweep: t = 1, 0.5, 0.1 side by side")
            .on_hover_text("The paper's Table 1: the same scene with one t everywhere, three views sharing the camera");
        ui.horizontal(|ui| {
            if ui.button("Frame the envelope").clicked() {
                self.view.frame();
            }
            if ui.button("Clear").clicked() {
                self.set(None, None);
            }
        });
    }

    fn summary(&self, ui: &mut egui::Ui) {
        let Some(b) = &self.built else {
            if self.building() {
                ui.label(egui::RichText::new("Building…").weak());
                ui.ctx().request_repaint_after(Duration::from_millis(30));
            }
            return;
        };
        if self.building() {
            ui.label(egui::RichText::new("Building… (the last surface is shown)").weak());
            ui.ctx().request_repaint_after(Duration::from_millis(30));
        }
        match &b.result {
            Ok((e, m)) => {
                ui.label(format!(
                    "{} primitive(s), {} regions, {} {}, {} faces",
                    e.primitives.len(),
                    e.regions,
                    e.patch_count(),
                    match e.surfacing {
                        Surfacing::Charts => "charts",
                        Surfacing::Paper => "patches",
                    },
                    m.num_faces()
                ));
                if let Some(note) = e.removed_note() {
                    ui.label(note)
                    .on_hover_text("The paper cuts every primitive by the plane through its centre normal to each partner; these keep nothing (seed 004 §5.1.3). A primitive inside a larger one's sphere whose shape lies inside the others' envelope is left out too: the strip between them would fold");
                }
                if let Some(p) = e.primitives.get(self.selected) {
                    ui.label(format!(
                        "primitive {}: centre ({:.3}, {:.3}, {:.3}), sphere radius r = {:.4}",
                        self.selected, p.centre.x, p.centre.y, p.centre.z, p.radius
                    ));
                }
                ui.label(format!(
                    "G1: largest normal jump across region borders {:.1e}°; network and {} in {:.2} ms",
                    b.jump,
                    match e.surfacing {
                        Surfacing::Charts => "charts",
                        Surfacing::Paper => "patches",
                    },
                    b.millis
                ));
                // One row each whatever the answer, with the long text on hover: the
                // crossing check answers a few frames later, and a line that wrapped then
                // would move every field below it under the pointer.
                let red = egui::Color32::from_rgb(255, 120, 100);
                let row = |ui: &mut egui::Ui, text: egui::RichText, hover: String| {
                    ui.add(egui::Label::new(text).truncate())
                        .on_hover_text(hover);
                };
                match &b.quality {
                    Some(q) => {
                        row(
                            ui,
                            format!(
                                "Mesh: angles {:.1}°–{:.1}°, largest turn {:.1}°",
                                q.smallest_angle, q.largest_angle, q.largest_turn.0
                            )
                            .into(),
                            format!(
                                "{}\nThe largest turn is between neighbouring triangles of {}; it falls with a finer mesh where the surface is smooth",
                                q.summary(),
                                e.describe_region(q.largest_turn.1)
                            ),
                        );
                        match q.enclosure_warning() {
                            Some(w) => row(
                                ui,
                                egui::RichText::new(format!(
                                    "Enclosure: a primitive reaches {:.3} r outside",
                                    -q.worst_enclosure().map_or(0.0, |x| x.1)
                                ))
                                .color(red),
                                w,
                            ),
                            None => row(
                                ui,
                                "Enclosure: every primitive inside".into(),
                                "Points on every primitive's faces, edges and vertices lie inside the surface".into(),
                            ),
                        }
                    }
                    None => row(
                        ui,
                        egui::RichText::new("Mesh: measuring…").weak(),
                        "Angles, normal turns and enclosure of the mesh as written".into(),
                    ),
                }
                match &b.folds {
                    Some((n, text)) => row(
                        ui,
                        egui::RichText::new(format!("Folds: {n} cell(s), marked with red crosses"))
                            .color(red),
                        text.clone(),
                    ),
                    None if e.surfacing == Surfacing::Charts => row(
                        ui,
                        "Folds: none (a graph cannot fold)".into(),
                        "Every region is a graph of one number over its flat chart".into(),
                    ),
                    None => row(
                        ui,
                        "Folds: none".into(),
                        "Every sampled cell faces like its patch's corners".into(),
                    ),
                }
                match &b.crossings {
                    build::Crossings::Checking(_) => {
                        row(
                            ui,
                            egui::RichText::new("Crossings: checking…").weak(),
                            "Looking for faces of the surface that pass through each other".into(),
                        );
                        ui.ctx()
                            .request_repaint_after(std::time::Duration::from_millis(30));
                    }
                    build::Crossings::Done(_, Some(text)) => row(
                        ui,
                        egui::RichText::new(format!(
                            "Crossings: {} pair(s), marked with red crosses",
                            b.crossing_points().len()
                        ))
                        .color(red),
                        format!("Faces of the surface pass through each other. {text}"),
                    ),
                    build::Crossings::Done(_, None) => row(
                        ui,
                        "Crossings: none".into(),
                        "No two faces of the surface pass through each other".into(),
                    ),
                    build::Crossings::None => {}
                }
            }
            Err(e) => {
                ui.colored_label(
                    egui::Color32::from_rgb(255, 120, 100),
                    format!("No envelope: {e}"),
                );
            }
        }
    }

    fn placement(&mut self, ui: &mut egui::Ui, spec: &EnvelopeSpec, k: usize, p: &PrimitiveInput) {
        let centre = centre_of(p);
        if let Some((moved, g)) = self.gestures.centre_field(ui, centre) {
            let mut s = spec.clone();
            s.primitives[k] = mapped(p, |v| v + moved - centre);
            self.set(Some(s), g);
        }
        let mut gst = self.gesture;
        let mut act: Option<(DQuat, f64, Option<u64>)> = None;
        ui.horizontal(|ui| {
            ui.label("turn °");
            for (a, (axis, name)) in [(DVec3::X, "x: "), (DVec3::Y, "y: "), (DVec3::Z, "z: ")]
                .into_iter()
                .enumerate()
            {
                if let Some((b, after, g)) =
                    self.gestures
                        .delta_field(ui, &mut gst.rotate[a], 0.0, name, None)
                {
                    act = Some((
                        DQuat::from_axis_angle(axis, (after - b).to_radians()),
                        1.0,
                        g,
                    ));
                }
            }
        });
        if let Some((f, g)) = self.gestures.scale_field(ui, &mut gst.scale) {
            act = Some((DQuat::IDENTITY, f, g));
        }
        self.gesture = gst;
        if let Some((q, f, g)) = act {
            let mut s = spec.clone();
            s.primitives[k] = mapped(p, |v| centre + q * ((v - centre) * f));
            self.set(Some(s), g);
        }
    }

    fn curvature(&mut self, ui: &mut egui::Ui, spec: &EnvelopeSpec) {
        ui.label("Curvature parameter t (ρ = t·r at every vertex)");
        let mut t = spec.t;
        let r = ui
            .add(
                // A scene opened with t outside the slider's range (the CLI takes any t > 0)
                // keeps it until the slider is moved.
                egui::Slider::new(&mut t, 0.1..=3.0)
                    .logarithmic(true)
                    .clamping(egui::SliderClamping::Edits)
                    .text("t"),
            )
            .on_hover_text("1: edges are arcs on the primitive's sphere; towards 0 the surface tends to the flat faces; above 1 the edges bulge outside the sphere (polynomial cubics at 3/(1 + 2cos θ), 1.14 on a cube)");
        let g = self.gestures.of(&r);
        if t != spec.t {
            let mut s = spec.clone();
            s.t = t;
            for p in &mut s.primitives {
                p.t = None;
            }
            self.set(Some(s), g);
        }
        let Some((pi, v)) = self.picked else {
            ui.label("Click a vertex in the view to give it its own t.");
            return;
        };
        let Some(p) = spec.primitives.get(pi) else {
            return;
        };
        let base = p.t.unwrap_or(spec.t);
        let mut own = p
            .vertex_t
            .as_ref()
            .and_then(|vt| vt.get(v).copied())
            .unwrap_or(base);
        ui.horizontal(|ui| {
            ui.label(format!("vertex {v}"));
            let r = ui.add(
                egui::DragValue::new(&mut own)
                    .prefix("own t: ")
                    .speed(0.01)
                    .range(0.1..=3.0)
                    .clamp_existing_to_range(false)
                    .min_decimals(2)
                    .max_decimals(3),
            );
            let g = self.gestures.of(&r);
            if r.changed() {
                let mut s = spec.clone();
                let q = &mut s.primitives[pi];
                let mut vt = q
                    .vertex_t
                    .clone()
                    .unwrap_or_else(|| vec![base; q.vertices.len()]);
                vt[v] = own;
                q.vertex_t = Some(vt);
                self.set(Some(s), g);
            }
            if ui
                .add_enabled(p.vertex_t.is_some(), egui::Button::new("All vertices to t"))
                .on_disabled_hover_text("No vertex has its own t")
                .clicked()
            {
                let mut s = spec.clone();
                s.primitives[pi].vertex_t = None;
                self.set(Some(s), None);
            }
        });
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
        if resp.drag_started_by(egui::PointerButton::Primary)
            && let Some(p) = spec.primitives.get(k)
        {
            self.drag = Some((self.gestures.start(), p.vertices.clone()));
        }
        if resp.dragged_by(egui::PointerButton::Primary)
            && let Some((g, start)) = &self.drag
            && let Some(p) = spec.primitives.get(k)
            && p.vertices.len() == start.len()
        {
            let total = gestures::drag_total(ui);
            let from = PrimitiveInput {
                vertices: start.clone(),
                ..p.clone()
            };
            let centre = centre_of(&from);
            let q = match self.mouse {
                Mouse::Move => {
                    let by = self
                        .view
                        .camera
                        .drag_in_view_plane(total.x, total.y, rect.height())
                        .as_dvec3();
                    mapped(&from, |v| v + by)
                }
                Mouse::Scale => {
                    let f = gestures::drag_scale(total);
                    mapped(&from, |v| centre + (v - centre) * f)
                }
                Mouse::Orbit => return,
            };
            let mut s = spec.clone();
            s.primitives[k] = q;
            let g = *g;
            self.set(Some(s), Some(g));
        }
        if resp.drag_stopped() {
            self.drag = None;
        }
    }

    /// The sweep's views: t and the number of patches (none when the envelope failed).
    pub fn sweep_summary(&self) -> Vec<(f64, Option<usize>)> {
        self.sweep_views
            .iter()
            .map(|v| {
                (
                    v.t,
                    v.built.result.as_ref().ok().map(|(e, _)| e.patch_count()),
                )
            })
            .collect()
    }

    /// The t sweep: three views side by side, one camera, each labelled with its t and its
    /// patches (or why it has none).
    fn paint_sweep(&self, ui: &egui::Ui, rect: egui::Rect) {
        let w = rect.width() / self.sweep_views.len() as f32;
        // A cell is narrower than the view the camera was framed for: move back so that the
        // same width shows (the model's width fills a cell as its height filled the view).
        let mut camera = self.view.camera;
        let cell_aspect = w / rect.height().max(1.0);
        let aspect = rect.width() / rect.height().max(1.0);
        camera.zoom((0.8 * aspect.min(1.0) / cell_aspect).max(1.0));
        let summary = self.sweep_summary();
        for (i, v) in self.sweep_views.iter().enumerate() {
            let cell = egui::Rect::from_min_size(
                rect.left_top() + egui::vec2(i as f32 * w, 0.0),
                egui::vec2(w, rect.height()),
            );
            self.view
                .paint_scene(ui, cell, 1 + i, (&v.scene, &v.overlay), camera);
            if i > 0 {
                ui.painter().vline(
                    cell.left(),
                    cell.y_range(),
                    egui::Stroke::new(1.0, egui::Color32::from_gray(90)),
                );
            }
            let text = match (summary[i].1, &v.built.result) {
                (Some(n), Ok((e, _))) if e.surfacing == Surfacing::Charts => {
                    format!("t = {}: {n} charts", v.t)
                }
                (Some(n), _) => format!("t = {}: {n} patches", v.t),
                (None, Err(e)) => format!("t = {}: {e}", v.t),
                (None, Ok(_)) => format!("t = {}", v.t),
            };
            ui.painter().text(
                cell.left_top() + egui::vec2(8.0, 8.0),
                egui::Align2::LEFT_TOP,
                text,
                egui::FontId::proportional(14.0),
                egui::Color32::from_gray(220),
            );
        }
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
            self.view.paint(ui, rect);
        }
        View3d::hint(
            ui,
            rect,
            match self.mouse {
                Mouse::Orbit => {
                    "drag: orbit · right drag: pan · wheel: zoom · click: pick a vertex"
                }
                Mouse::Move => {
                    "drag: move the selected primitive in the view plane · right drag: orbit"
                }
                Mouse::Scale => "drag up or down: scale the selected primitive · right drag: orbit",
            },
        );
    }
}
