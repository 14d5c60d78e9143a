//! The Model tab: the pipeline panel (steps, each a scheme with its parameter, Step >> (S),
//! << Back (B), reorder, level slider, progress and Cancel), tools (orbit, select and move
//! vertices, pick edges), vertex coordinates, edge marks (crease, own radius, "sharper than
//! X°"), display options, the compare split, and the 3D views (one, or two or four with
//! linked cameras and a table under them).
//!
//! The tab owns its view state (cameras, selections, display options, each view's computed
//! levels) and reads the document; what would change the document it returns as
//! [`Command`]s from [`ModelTab::ui`] (or queues with [`ModelTab::push`] from its helpers).
//! Each view follows the document by its generation ([`ModelTab::sync`]): a changed pipeline
//! is recomputed on a worker thread from the first step that changed.

pub mod compare;
pub mod crossing_check;
pub(crate) mod display;
mod overlay;
pub(crate) mod panels;
pub mod pick;
mod run_options;
mod scheme_editor;
pub(crate) mod status;
pub mod view_pipe;
pub mod views;
pub mod worker;

pub use scheme_editor::default_next;

use super::command::{Command, EdgeMark, Edit};
use super::document::{DocState, Document};
use crate::gui::waker::Waker;
pub use display::{Coloring, Display, Tool};
use glam::Vec3;
use prism_geom::{EdgeKey, Pipeline, Scheme};
use prism_viewport::{Camera, View};
use std::collections::BTreeSet;
use view_pipe::{Outcome, ViewPipe};

/// A vertex drag in progress: its number (edits of one drag coalesce) and where the
/// dragged vertices started.
struct VertexDrag {
    id: u64,
    start: Vec<(u32, glam::DVec3)>,
}

/// The Model tab's state.
/// The side panels' width: resizable within this, never widened by their text (a long
/// message wraps).
pub const SIDE_PANEL: std::ops::RangeInclusive<f32> = 240.0..=440.0;

pub struct ModelTab {
    pub views: Vec<ViewPipe>,
    /// The view the pipeline panel edits.
    pub active: usize,
    /// One camera for every view (linked).
    pub camera: Camera,
    framed: bool,
    /// Width / height of the narrowest view, for framing.
    view_aspect: f32,
    pub display: Display,
    pub tool: Tool,
    pub sel_verts: BTreeSet<u32>,
    /// Selected control edges.
    pub sel_edges: BTreeSet<EdgeKey>,
    /// The points the Measure tool has clicked on the surface (at most three).
    pub measure: Vec<glam::DVec3>,
    /// Axis a vertex drag is held to (0 x, 1 y, 2 z).
    pub axis: Option<usize>,
    /// The scheme Step >> appends.
    pub next: Scheme,
    pub budget_mib: u64,
    /// Clamp radii whose rounds do not fit their faces (on by default; off: refuse them).
    pub clamp: bool,
    /// Search each rounding's whole level for faces that pass through each other and mend
    /// them with small chamfers (on by default, as clamping is: a rounding step then takes
    /// about seven times as long).
    pub mend_crossings: bool,
    /// Step >> after a step of the same absolute chamfer divides its l or d by this.
    pub shrink: f64,
    /// A step stopped at the budget: (view, estimate) waiting for the user's answer.
    pub question: Option<(usize, prism_geom::error::OverBudget)>,
    drag: Option<VertexDrag>,
    drags: u64,
    box_start: Option<egui::Pos2>,
    /// The pipeline being typed as text, and for which view.
    pipeline_edit: Option<(usize, String)>,
    /// Inputs of the edge panel.
    pub crease_value: f64,
    pub radius_value: f64,
    pub sharper_deg: f64,
    /// The level slider moves every view of the compare split.
    pub link_levels: bool,
    /// Playing the levels (one a [`PLAY_STEP`], round again after the last): when the shown
    /// level last moved.
    pub playing: Option<std::time::Instant>,
    /// The active view and where its camera's target is measured from in the world (its
    /// scene's origin plus its framing centre): when a new scene moves it, the camera moves
    /// back by as much, so the model does not jump during a drag or between levels.
    anchor: Option<(usize, glam::DVec3)>,
    /// The document generation the views were last brought in line with.
    synced: Option<u64>,
    /// How the document's file counts its vertices and faces, for step errors about them.
    numbering: std::sync::Arc<prism_geom::io::Numbering>,
    /// Commands decided outside `ui` (helpers the tests call too), taken by the next `ui`
    /// or [`ModelTab::take_commands`].
    pending: Vec<Command>,
    pub waker: Waker,
    pub has_gpu: bool,
}

/// How long each level is shown while the levels play.
pub const PLAY_STEP: std::time::Duration = std::time::Duration::from_secs(1);

impl ModelTab {
    /// Shows the active view's next level (the input after the last; every view with the
    /// levels linked) once [`PLAY_STEP`] has passed since the last move; true when it moved.
    pub fn play_tick(&mut self, now: std::time::Instant) -> bool {
        let Some(last) = self.playing else {
            return false;
        };
        if now.duration_since(last) < PLAY_STEP || self.views.is_empty() {
            return false;
        }
        let a = self.active.min(self.views.len() - 1);
        let n = self.views[a].steps().len();
        let next = if self.views[a].level >= n {
            0
        } else {
            self.views[a].level + 1
        };
        self.views[a].level = next;
        if self.link_levels {
            for w in &mut self.views {
                w.level = next.min(w.steps().len());
            }
        }
        self.playing = Some(now);
        true
    }

    pub fn new(display: Display, tool: Tool, next: Scheme, budget_mib: u64) -> ModelTab {
        ModelTab {
            views: Vec::new(),
            active: 0,
            camera: Camera::default(),
            framed: false,
            view_aspect: 1.5,
            display,
            tool,
            sel_verts: BTreeSet::new(),
            sel_edges: BTreeSet::new(),
            measure: Vec::new(),
            axis: None,
            next,
            budget_mib: budget_mib.max(64),
            clamp: true,
            mend_crossings: prism_geom::rules::MendOptions::default().crossings,
            shrink: 4.0,
            question: None,
            drag: None,
            drags: 0,
            box_start: None,
            pipeline_edit: None,
            crease_value: 10.0,
            radius_value: 0.1,
            sharper_deg: 60.0,
            playing: None,
            link_levels: false,
            anchor: None,
            synced: None,
            numbering: Default::default(),
            pending: Vec::new(),
            waker: std::sync::Arc::new(|| {}),
            has_gpu: false,
        }
    }

    /// Queues a command for the frame loop.
    pub fn push(&mut self, c: impl Into<Command>) {
        self.pending.push(c.into());
    }

    /// The commands queued so far.
    pub fn take_commands(&mut self) -> Vec<Command> {
        std::mem::take(&mut self.pending)
    }

    /// Brings every view's pipeline in line with the document when its generation moved:
    /// views added or removed, changed steps recomputed from the first that changed, a
    /// changed input from scratch. A drag (`doc.live()`) lets a running job finish first.
    pub fn sync(&mut self, doc: &Document) {
        if self.synced == Some(doc.generation()) {
            return;
        }
        let first = self.synced.is_none();
        self.synced = Some(doc.generation());
        self.numbering = doc.origin().numbering.clone();
        let d = doc.state();
        let live = doc.live();
        let n = d.pipelines.len();
        let nv = d.mesh.num_vertices() as u32;
        self.sel_verts.retain(|&v| v < nv);
        if self.views.len() != n && !first {
            self.framed = false;
        }
        self.views.truncate(n);
        self.active = self.active.min(n - 1);
        let budget = self.budget_mib << 20;
        for (i, steps) in d.pipelines.iter().enumerate() {
            let fresh = || {
                Pipeline::with_tags(
                    d.mesh.clone(),
                    d.edge_attrs.clone(),
                    d.tags.clone(),
                    steps.clone(),
                )
            };
            if i >= self.views.len() {
                // The input alone on screen until the job brings the levels.
                let next = fresh();
                let mut v = ViewPipe::new(next.rebased(Vec::new()));
                v.overlap = self.overlap();
                v.mend_crossings = self.mend_crossings;
                v.level = steps.len();
                v.scene_opts = self.display.scene_options();
                v.submit(next, budget, live, &self.waker);
                self.views.push(v);
                continue;
            }
            let v = &mut self.views[i];
            let input = v.pipeline.input();
            let same_input =
                input.mesh == d.mesh && input.edge_attrs == d.edge_attrs && input.tags == d.tags;
            let same_options = v.pipeline.options.overlap == v.overlap
                && v.pipeline.options.mend.crossings == v.mend_crossings;
            if same_input && same_options && v.pipeline.steps() == steps.as_slice() && !v.busy() {
                continue;
            }
            // Only vertices moved (a drag): the primal steps keep their faces and topology
            // and evaluate the points again (Pipeline::moved).
            let moved = !same_input
                && same_options
                && v.pipeline.steps() == steps.as_slice()
                && input.edge_attrs == d.edge_attrs
                && input.tags == d.tags
                && input.mesh.positions.len() == d.mesh.positions.len()
                && input.mesh.corner_verts == d.mesh.corner_verts
                && input.mesh.loop_starts == d.mesh.loop_starts
                && input.mesh.face_starts == d.mesh.face_starts;
            let next = if same_input && same_options {
                v.pipeline.rebased(steps.clone())
            } else if moved {
                v.pipeline.moved(d.mesh.positions.clone())
            } else {
                fresh()
            };
            let grew = steps.len() > v.pipeline.steps().len();
            if grew || v.level > steps.len() {
                v.level = steps.len();
            }
            v.submit(next, budget, live, &self.waker);
        }
    }

    /// Takes finished jobs; returns whether anything changed.
    pub fn poll_jobs(&mut self) -> bool {
        let mut any = false;
        for (i, v) in self.views.iter_mut().enumerate() {
            match v.poll(&self.waker, &self.numbering) {
                Outcome::Nothing => {}
                Outcome::Updated => any = true,
                Outcome::AskBudget(o) => {
                    any = true;
                    self.question = Some((i, o));
                }
            }
        }
        any
    }

    /// Blocks until every view's levels are computed.
    #[cfg(test)]
    pub fn wait_idle(&mut self) {
        while self.views.iter().any(|v| v.busy()) {
            self.poll_jobs();
            std::thread::sleep(std::time::Duration::from_millis(2));
        }
    }

    pub fn busy(&self) -> bool {
        self.views
            .iter()
            .any(|v| v.busy() || v.preparing() || v.checking())
    }

    /// Step >>: appends the next step to the active view's pipeline.
    /// Step >>: appends the next scheme to the active view's pipeline; an absolute chamfer
    /// after a step of the same kind continues its schedule (l or d divided by
    /// [`ModelTab::shrink`]).
    pub fn step(&mut self) {
        self.push(Edit::PushStep {
            view: self.active,
            scheme: self.next,
            shrink: self.shrink,
        });
    }

    /// << Back: removes the last step of the active view's pipeline.
    pub fn back(&mut self) {
        let view = self.active;
        self.push(Edit::PopStep { view });
    }

    /// Marks the selected control edges (one undo step); says what to do when none is
    /// selected.
    pub fn mark(&mut self, mark: EdgeMark) {
        if self.sel_edges.is_empty() {
            self.push(Command::Say(
                "select edges first (Edges tool: click, shift-click or drag a box)".into(),
            ));
            return;
        }
        let edges: Vec<EdgeKey> = self.sel_edges.iter().copied().collect();
        let n = edges.len();
        self.push(Edit::MarkEdges { edges, mark });
        if let EdgeMark::Crease(s) = mark {
            self.push(Command::Say(format!(
                "{n} edge(s) creased with sharpness {s}"
            )));
        }
    }

    /// Moves control vertices by `d` (typed coordinates; one undo step).
    pub fn move_vertices(&mut self, verts: &[u32], by: glam::DVec3) {
        self.push(Edit::MoveVertices {
            verts: verts.to_vec(),
            by,
        });
    }

    /// Selects every control edge whose faces meet at more than `deg` degrees.
    pub fn select_sharper_than(&mut self, doc: &DocState, deg: f64, add: bool) {
        let m = &doc.mesh;
        let Ok(topo) = prism_geom::Topology::build(m) else {
            self.push(Command::Say(
                "the control mesh is not a manifold: no bend angles".into(),
            ));
            return;
        };
        let normals: Vec<_> = prism_geom::geometry::face_normals_raw(m)
            .into_iter()
            .map(prism_geom::geometry::unit_or_zero)
            .collect();
        let bends = prism_geom::geometry::signed_bend_angles(m, &topo, &normals);
        if !add {
            self.sel_edges.clear();
        }
        let mut n = 0;
        for (e, b) in bends.iter().enumerate() {
            if b.abs().to_degrees() > deg {
                let (a, c) = topo.edge_verts(m, e);
                self.sel_edges.insert(EdgeKey::new(a, c));
                n += 1;
            }
        }
        self.push(Command::Say(format!("{n} edge(s) sharper than {deg}°")));
    }

    /// Stops every view's computation (before a new document replaces the old).
    pub fn cancel_all(&mut self) {
        for v in &mut self.views {
            v.cancel();
        }
    }

    /// A new document: selections and the split start afresh, the camera frames it.
    pub fn reset_for_new_document(&mut self) {
        self.cancel_all();
        for v in &mut self.views {
            v.keep = prism_geom::pipeline::Keep::All;
            v.clear_scene();
        }
        self.sel_verts.clear();
        self.sel_edges.clear();
        self.active = 0;
        self.framed = false;
    }

    /// The camera view `i` is drawn with: the linked camera, whose target is relative to
    /// each view's framing centre, so every view of the split keeps its own model in the
    /// middle (a view whose level threw vertices far away has its framing centre, and with
    /// it the scene's origin, elsewhere than the others).
    pub fn view_camera(&self, i: usize) -> Camera {
        let mut c = self.camera;
        c.target += self.views[i].frame_sphere().0;
        c
    }

    /// Frames the models: the linked camera looks at each view's framing centre from a
    /// distance that fits the largest of their framing spheres.
    pub fn frame(&mut self, doc: &DocState) {
        let r = if self.views.iter().all(|v| v.scene.vertices.is_empty()) {
            let (lo, hi) = doc.mesh.bbox();
            (0.5 * (hi - lo).length()).max(1e-9) as f32
        } else {
            // Most of each model, not the few vertices a broken step threw far away.
            self.views
                .iter()
                .filter(|v| !v.scene.vertices.is_empty())
                .map(|v| v.frame_sphere().1)
                .fold(0.0, f32::max)
        };
        // A narrow view (the compare split) has the smaller horizontal field: fit that too.
        let half_y = 0.5 * Camera::default().fov_y;
        let half_x = (half_y.tan() * self.view_aspect.clamp(0.1, 10.0)).atan();
        let r = r * half_y.sin() / half_x.min(half_y).sin();
        self.camera = Camera::looking(View::Iso, Vec3::ZERO, r);
        self.framed = true;
        self.anchor = None;
    }

    /// Keeps the camera where it is in the world when the active view's scene moves its
    /// origin or framing centre ([`ModelTab::anchor`]).
    pub(super) fn hold_camera(&mut self) {
        let a = self.active;
        let v = &self.views[a];
        if v.scene.vertices.is_empty() {
            return;
        }
        let anchor = v.scene.origin + v.frame_sphere().0.as_dvec3();
        if let Some((i, old)) = self.anchor
            && i == a
            && self.framed
        {
            self.camera.target -= (anchor - old).as_vec3();
        }
        self.anchor = Some((a, anchor));
    }

    /// Frames face `f` of the active view's shown level (its neighbourhood: a sphere three
    /// times its size), looking at it from the side away from the model's centre.
    pub fn frame_face(&mut self, f: u32) {
        let v = &self.views[self.active];
        let mesh = &v.pipeline.levels()[v.shown()].mesh;
        if f as usize >= mesh.num_faces() {
            return;
        }
        let (mut lo, mut hi) = (
            glam::DVec3::splat(f64::INFINITY),
            glam::DVec3::splat(f64::NEG_INFINITY),
        );
        for c in mesh.face_corners(f as usize) {
            let p = mesh.positions[mesh.corner_verts[c] as usize];
            lo = lo.min(p);
            hi = hi.max(p);
        }
        let size = (0.5 * (hi - lo).length()).max(1e-4 * v.scene.radius() as f64);
        let centre = v.scene.to_local(0.5 * (lo + hi));
        // Seen from outside: from the model's centre through the face (the scene's origin).
        if let Some(c) = Camera::from_eye(2.0 * centre, centre, self.camera.fov_y) {
            self.camera = c;
        }
        self.camera.frame(centre, (3.0 * size) as f32);
        // The linked camera's target is relative to the view's framing centre.
        self.camera.target -= v.frame_sphere().0;
        self.framed = true;
        self.anchor = None;
    }

    /// The keys of the Model tab (S, B, F, W, X/Y/Z, Esc), when no text field has them.
    pub fn keys(&mut self, ctx: &egui::Context) {
        use egui::Key;
        let plain = |k: Key| ctx.input(|i| i.modifiers.is_none() && i.key_pressed(k));
        if plain(Key::S) {
            self.step();
        }
        if plain(Key::B) {
            self.back();
        }
        if plain(Key::F) {
            self.display.smooth = !self.display.smooth;
        }
        if plain(Key::W) {
            self.display.wireframe = !self.display.wireframe;
        }
        for (k, a) in [(Key::X, 0), (Key::Y, 1), (Key::Z, 2)] {
            if plain(k) {
                self.axis = if self.axis == Some(a) { None } else { Some(a) };
            }
        }
        if plain(Key::Escape) {
            self.sel_verts.clear();
            self.sel_edges.clear();
        }
        if let Some(v) = super::viewport::standard_view_key(ctx) {
            self.camera.turn_to(v);
        }
    }

    /// The tab: side panel, compare table, views and the memory question. Returns what the
    /// frame loop is to do.
    pub fn ui(&mut self, ui: &mut egui::Ui, doc: &Document, note: Option<&str>) -> Vec<Command> {
        let ctx = ui.ctx().clone();
        let d = doc.state();
        if !super::viewport::full_view(&ctx) {
            egui::Panel::left("panels")
                .resizable(true)
                .default_size(300.0)
                .size_range(SIDE_PANEL)
                .show(ui, |ui| {
                    // A solid scroll bar: at 1280×800 a long pipeline with the Edges tool is
                    // taller than the window, and the floating bar shows only on hover.
                    ui.spacing_mut().scroll = egui::style::ScrollStyle::solid();
                    egui::ScrollArea::vertical().show(ui, |ui| self.side_panel(ui, doc));
                });
        }
        egui::Panel::bottom("status").show(ui, |ui| self.status(ui, note));
        let n = d.pipelines.len();
        if n > 1 {
            egui::Panel::bottom(("compare", n))
                .resizable(true)
                .default_size(40.0 + 24.0 * n as f32)
                .show(ui, |ui| self.compare_table(ui, d));
        }
        self.rebuild_scenes(d, doc.generation());
        egui::CentralPanel::default()
            .frame(egui::Frame::NONE)
            .show(ui, |ui| self.views_ui(ui, d));
        self.budget_question(&ctx);
        self.take_commands()
    }
    /// The level shown in the active view.
    pub fn shown_level(&self) -> (usize, &prism_geom::Level) {
        let v = &self.views[self.active];
        (v.shown(), &v.pipeline.levels()[v.shown()])
    }
}
