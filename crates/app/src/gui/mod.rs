//! The desktop app (eframe/egui, wgpu). A menu bar (File: open, bundled samples, save,
//! export; Edit: undo/redo; tabs Model and Curves), on the left the panels — pipeline
//! (steps, each a scheme with its parameter, Step >> (S), << Back (B), reorder, level
//! slider, progress and Cancel), tools (orbit, select and move vertices, pick edges),
//! vertex coordinates, edge marks (crease, own radius, "sharper than X°"), display
//! options, compare split —, the 3D views in the middle (one, or two or four with linked
//! cameras and a table under them), counts, timings and warnings in the status bar.
//!
//! The document (control mesh, edge marks, tags, the pipeline of every view) changes only
//! through [`PrismApp::change`], which records the state before for undo; each view's levels
//! are then recomputed on a worker thread from the first step that changed
//! ([`view_pipe::ViewPipe::submit`]), so the window never waits for a step.
//!
//! `prism --screenshot OUT.png [FILE] [--pipeline P] ...` opens the window, waits for the
//! computation, saves a picture of the whole window (egui's screenshot command) and exits:
//! the test under Xvfb and the pictures in docs/ use it.

mod compare;
mod curves;
mod document;
mod panels;
mod pick;
mod scheme_editor;
mod view_pipe;
mod viewport;
mod views;
mod worker;

#[cfg(test)]
mod tests;

use document::{DocState, History, Origin};
use glam::Vec3;
use prism_geom::io;
use prism_geom::{EdgeKey, Pipeline, Scheme};
use prism_viewport::{Camera, ColorBy, SceneOptions, Shading, View};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use view_pipe::{Outcome, ViewPipe, Waker};

/// Window multisampling (and the renderer's, which must match).
const SAMPLES: u16 = 4;

/// Display toggles, also given on the command line (`--show smooth,wireframe`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Show {
    Smooth,
    Wireframe,
    Kinds,
    Curvature,
    Schemes,
    Cage,
    Corners,
    Limit,
}

/// The tool the primary mouse button uses in the views.
#[derive(
    Debug,
    Clone,
    Copy,
    PartialEq,
    Eq,
    Default,
    clap::ValueEnum,
    serde::Serialize,
    serde::Deserialize,
)]
pub enum Tool {
    /// Drag turns the model.
    #[default]
    Orbit,
    /// Click, shift-click or box-select control vertices; drag a selected one to move it.
    Vertices,
    /// Click, shift-click or box-select edges on any level.
    Edges,
}

/// The app's two tabs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Tab {
    #[default]
    Model,
    Curves,
}

/// How the app was started.
#[derive(Debug, Default)]
pub struct Launch {
    pub file: Option<PathBuf>,
    pub pipeline: Vec<Scheme>,
    /// Pipelines of further views: opens the compare split.
    pub compare: Vec<Vec<Scheme>>,
    pub show: Vec<Show>,
    pub tool: Option<Tool>,
    pub select_edges: Vec<EdgeKey>,
    pub tab: Option<Tab>,
    pub screenshot: Option<PathBuf>,
}

/// Where the screenshot callback leaves the picture for the next frame.
type ScreenshotSlot = Arc<Mutex<Option<Arc<egui::ColorImage>>>>;

/// The bundled samples: name, file name, contents.
pub const SAMPLES_FILES: [(&str, &str, &str); 6] = [
    (
        "Tripod",
        "tripod.obj",
        include_str!("../../../../assets/tripod.obj"),
    ),
    (
        "Cube",
        "cube.obj",
        include_str!("../../../../assets/cube.obj"),
    ),
    (
        "L-block",
        "l-block.obj",
        include_str!("../../../../assets/l-block.obj"),
    ),
    (
        "Holed block",
        "holed-block.prism.json",
        include_str!("../../../../assets/holed-block.prism.json"),
    ),
    (
        "Cube with a creased rim (circle weight)",
        "cube-rim.prism.json",
        include_str!("../../../../assets/cube-rim.prism.json"),
    ),
    (
        "Computer room",
        "computer-room.obj",
        include_str!("../../../../assets/computer-room.obj"),
    ),
];

/// How faces are coloured.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Coloring {
    Uniform,
    /// FACE / EDGE / VERTEX faces of the last biquadratic step.
    Kind,
    /// Mean curvature colour map.
    Curvature,
    /// One colour per scheme (the step that made the level).
    Scheme,
}

/// What is drawn besides the faces.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Display {
    pub smooth: bool,
    pub wireframe: bool,
    /// Face colours.
    pub color: Coloring,
    pub cage: bool,
    pub corners: bool,
    pub limit: bool,
}

impl Default for Display {
    fn default() -> Self {
        Display {
            smooth: false,
            wireframe: true,
            color: Coloring::Uniform,
            cage: false,
            corners: false,
            limit: false,
        }
    }
}

impl Display {
    pub fn scene_options(&self) -> SceneOptions {
        SceneOptions {
            shading: if self.smooth {
                Shading::Smooth
            } else {
                Shading::Flat
            },
            color_by: match self.color {
                Coloring::Uniform => ColorBy::Uniform,
                Coloring::Kind => ColorBy::Kind,
                Coloring::Curvature => ColorBy::Curvature,
                // Resolved per level by `view_pipe::level_scene`.
                Coloring::Scheme => ColorBy::Solid(prism_viewport::scene::BASE_COLOR),
            },
            wireframe: self.wireframe,
            ..SceneOptions::default()
        }
    }
}

/// What eframe remembers between runs.
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct Settings {
    display: Display,
    tool: Tool,
    budget_mib: u64,
    next: String,
    last_file: Option<PathBuf>,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            display: Display::default(),
            tool: Tool::Orbit,
            budget_mib: 4096,
            next: "combination:r=0.2".into(),
            last_file: None,
        }
    }
}

const SETTINGS_KEY: &str = "prism-settings";

/// A vertex drag in progress.
struct MoveDrag {
    start: Vec<(u32, glam::DVec3)>,
}

pub struct PrismApp {
    pub doc: DocState,
    pub origin: Origin,
    pub history: History,
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
    /// Axis a vertex drag is held to (0 x, 1 y, 2 z).
    pub axis: Option<usize>,
    /// The scheme Step >> appends.
    pub next: Scheme,
    pub budget_mib: u64,
    /// A step stopped at the budget: (view, estimate) waiting for the user's answer.
    pub question: Option<(usize, prism_geom::error::OverBudget)>,
    /// A message for the status bar (what the last action did, or why it did nothing).
    pub note: Option<String>,
    pub tab: Tab,
    pub curves: curves::CurvesTab,
    moving: Option<MoveDrag>,
    box_start: Option<egui::Pos2>,
    /// Inputs of the edge panel.
    pub crease_value: f64,
    pub radius_value: f64,
    pub sharper_deg: f64,
    waker: Waker,
    has_gpu: bool,
    screenshot: Option<(PathBuf, u32, ScreenshotSlot)>,
    last_file: Option<PathBuf>,
}

impl PrismApp {
    /// The app without a window (tests drive it this way; `new` adds the GPU).
    pub fn headless(launch: Launch, settings: Option<Settings>) -> Result<PrismApp, String> {
        let settings = settings.unwrap_or_default();
        let remembered = settings.last_file.clone().filter(|p| p.exists());
        let (mut doc, origin) = match launch.file.as_ref().or(remembered.as_ref()) {
            Some(p) => document::open(p)?,
            None => sample(0)?,
        };
        if !launch.pipeline.is_empty() {
            doc.pipelines[0] = launch.pipeline;
        }
        doc.pipelines.extend(launch.compare.into_iter().take(3));
        if doc.pipelines.len() == 3 {
            doc.pipelines.push(doc.pipelines[0].clone());
        }
        let mut display = settings.display.clone();
        for s in &launch.show {
            match s {
                Show::Smooth => display.smooth = true,
                Show::Wireframe => display.wireframe = true,
                Show::Kinds => display.color = Coloring::Kind,
                Show::Curvature => display.color = Coloring::Curvature,
                Show::Schemes => display.color = Coloring::Scheme,
                Show::Cage => display.cage = true,
                Show::Corners => display.corners = true,
                Show::Limit => display.limit = true,
            }
        }
        let next = prism_geom::parse_pipeline(&settings.next)
            .ok()
            .and_then(|v| v.first().copied())
            .unwrap_or_else(|| scheme_editor::default_param("combination"));
        let mut app = PrismApp {
            doc,
            origin,
            history: History::default(),
            views: Vec::new(),
            active: 0,
            camera: Camera::default(),
            framed: false,
            view_aspect: 1.5,
            display,
            tool: launch.tool.unwrap_or(settings.tool),
            sel_verts: BTreeSet::new(),
            sel_edges: launch.select_edges.into_iter().collect(),
            axis: None,
            next,
            budget_mib: settings.budget_mib.max(64),
            question: None,
            note: None,
            tab: launch.tab.unwrap_or_default(),
            curves: curves::CurvesTab::default(),
            moving: None,
            box_start: None,
            crease_value: 10.0,
            radius_value: 0.1,
            sharper_deg: 60.0,
            waker: Arc::new(|| {}),
            has_gpu: false,
            screenshot: launch
                .screenshot
                .map(|p| (p, 0, Arc::new(Mutex::new(None)))),
            last_file: settings.last_file,
        };
        if let Some(p) = &app.origin.path {
            app.last_file = Some(p.clone());
        }
        app.sync(false);
        Ok(app)
    }

    fn new(cc: &eframe::CreationContext<'_>, launch: Launch) -> Result<PrismApp, String> {
        let rs = cc
            .wgpu_render_state
            .as_ref()
            .ok_or("the wgpu renderer is not available")?;
        viewport::install(rs, SAMPLES as u32);
        // A screenshot run shows what its arguments say, not what the last session left.
        let settings = if launch.screenshot.is_some() {
            None
        } else {
            cc.storage
                .and_then(|s| eframe::get_value::<Settings>(s, SETTINGS_KEY))
        };
        let mut app = PrismApp::headless(launch, settings)?;
        app.has_gpu = true;
        let ctx = cc.egui_ctx.clone();
        app.waker = Arc::new(move || ctx.request_repaint());
        Ok(app)
    }

    fn settings(&self) -> Settings {
        Settings {
            display: self.display.clone(),
            tool: self.tool,
            budget_mib: self.budget_mib,
            next: self.next.to_string(),
            last_file: self.last_file.clone(),
        }
    }

    // ---- the document ----

    /// Applies a document change, recorded for undo, and recomputes what it affects.
    pub fn change(&mut self, f: impl FnOnce(&mut DocState)) {
        let before = self.doc.clone();
        f(&mut self.doc);
        if self.doc != before {
            self.history.record(before);
            self.sync(false);
        }
    }

    /// Brings every view's pipeline in line with the document: views added or removed,
    /// changed steps recomputed from the first that changed, a changed input from scratch.
    pub fn sync(&mut self, live: bool) {
        let n = self.doc.pipelines.len().max(1);
        if self.doc.pipelines.is_empty() {
            self.doc.pipelines.push(Vec::new());
        }
        self.views.truncate(n);
        self.active = self.active.min(n - 1);
        let budget = self.budget_mib << 20;
        for i in 0..n {
            let steps = self.doc.pipelines[i].clone();
            let fresh = || {
                Pipeline::with_tags(
                    self.doc.mesh.clone(),
                    self.doc.edge_attrs.clone(),
                    self.doc.tags.clone(),
                    steps.clone(),
                )
            };
            if i >= self.views.len() {
                // The input alone on screen until the job brings the levels.
                let next = fresh();
                let mut v = ViewPipe::new(next.rebased(Vec::new()));
                v.level = steps.len();
                v.scene_opts = self.display.scene_options();
                v.submit(next, budget, live, &self.waker);
                self.views.push(v);
                continue;
            }
            let v = &mut self.views[i];
            let input = v.pipeline.input();
            let same_input = input.mesh == self.doc.mesh
                && input.edge_attrs == self.doc.edge_attrs
                && input.tags == self.doc.tags;
            if same_input && v.pipeline.steps() == steps.as_slice() && !v.busy() {
                continue;
            }
            let next = if same_input {
                v.pipeline.rebased(steps.clone())
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
            match v.poll(&self.waker) {
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
        self.views.iter().any(|v| v.busy() || v.preparing())
    }

    pub fn undo(&mut self) {
        if let Some(s) = self.history.undo(self.doc.clone()) {
            self.doc = s;
            self.after_history();
            self.note = Some("undone".into());
        }
    }

    pub fn redo(&mut self) {
        if let Some(s) = self.history.redo(self.doc.clone()) {
            self.doc = s;
            self.after_history();
            self.note = Some("redone".into());
        }
    }

    fn after_history(&mut self) {
        let nv = self.doc.mesh.num_vertices() as u32;
        self.sel_verts.retain(|&v| v < nv);
        self.sync(false);
    }

    /// Appends the next step to the active view's pipeline.
    pub fn step(&mut self) {
        let (a, s) = (self.active, self.next);
        self.change(|d| d.pipelines[a].push(s));
    }

    /// Removes the last step of the active view's pipeline.
    pub fn back(&mut self) {
        let a = self.active;
        self.change(|d| {
            d.pipelines[a].pop();
        });
    }

    /// Splits the view into `n` (1, 2 or 4) views; new views start with the main pipeline.
    pub fn set_compare(&mut self, n: usize) {
        self.change(|d| {
            let main = d.pipelines[0].clone();
            d.pipelines.resize(n.max(1), main);
        });
        self.framed = false;
    }

    /// Gives the selected control edges a crease sharpness (0 removes it).
    pub fn mark_crease(&mut self, sharpness: f64) {
        if let Some(n) = self.mark_selected(|a| a.crease = sharpness) {
            self.note = Some(format!("{n} edge(s) creased with sharpness {sharpness}"));
        }
    }

    /// Gives the selected control edges their own fillet radius (None: the step's).
    pub fn mark_radius(&mut self, radius: Option<f64>) {
        if !self.sel_edges.is_empty()
            && let Some(r) = radius
            && !(r.is_finite() && r > 0.0)
        {
            self.note = Some(format!("a radius must be positive, not {r}"));
            return;
        }
        self.mark_selected(|a| a.radius = radius);
    }

    /// Applies `set` to the attributes of every selected control edge (one undo step) and
    /// drops attributes left empty; returns how many edges, or None (with a note) when none
    /// is selected.
    fn mark_selected(&mut self, set: impl Fn(&mut prism_geom::EdgeAttr)) -> Option<usize> {
        if self.sel_edges.is_empty() {
            self.note =
                Some("select edges first (Edges tool: click, shift-click or drag a box)".into());
            return None;
        }
        let sel = self.sel_edges.clone();
        self.change(|d| {
            for e in &sel {
                set(d.edge_attrs.entry(*e).or_default());
            }
            d.edge_attrs
                .retain(|_, a| a.crease != 0.0 || a.radius.is_some());
        });
        Some(sel.len())
    }

    /// Selects every control edge whose faces meet at more than `deg` degrees.
    pub fn select_sharper_than(&mut self, deg: f64, add: bool) {
        let m = &self.doc.mesh;
        let Ok(topo) = prism_geom::Topology::build(m) else {
            self.note = Some("the control mesh is not a manifold: no bend angles".into());
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
        self.note = Some(format!("{n} edge(s) sharper than {deg}°"));
        self.mark_overlays();
    }

    /// Moves control vertices by `d` (typed coordinates; one undo step).
    pub fn move_vertices(&mut self, verts: &[u32], d: glam::DVec3) {
        if !d.is_finite() {
            self.note = Some("coordinates must be numbers".into());
            return;
        }
        self.change(|doc| {
            for &v in verts {
                if let Some(q) = doc.mesh.positions.get_mut(v as usize) {
                    *q += d;
                }
            }
        });
        self.mark_overlays();
    }

    pub fn mark_overlays(&mut self) {
        for v in &mut self.views {
            v.overlay_dirty = true;
        }
    }

    // ---- files ----

    /// Opens a file as the document (undoable: the previous document is one Ctrl+Z away).
    pub fn open_path(&mut self, path: &Path) {
        match document::open(path) {
            Ok((doc, origin)) => self.replace_document(doc, origin),
            Err(e) => self.note = Some(format!("could not open: {e}")),
        }
    }

    pub fn open_sample(&mut self, k: usize) {
        match sample(k) {
            Ok((doc, origin)) => self.replace_document(doc, origin),
            Err(e) => self.note = Some(e),
        }
    }

    fn replace_document(&mut self, doc: DocState, origin: Origin) {
        self.cancel_all();
        let before = std::mem::replace(&mut self.doc, doc);
        self.history.record(before);
        if let Some(p) = &origin.path {
            self.last_file = Some(p.clone());
        }
        self.note = Some(format!("opened {}", origin.name));
        self.origin = origin;
        self.sel_verts.clear();
        self.sel_edges.clear();
        self.active = 0;
        self.framed = false;
        self.sync(false);
    }

    /// Saves the document (`.prism.json` keeps the pipeline, OBJ the mesh and its tags).
    pub fn save_to(&mut self, path: &Path) -> Result<(), String> {
        let warnings = io::save(path, &self.doc.to_document()).map_err(|e| e.to_string())?;
        if io::FileKind::of(path).ok() == Some(io::FileKind::Document) {
            self.origin.path = Some(path.to_path_buf());
            self.last_file = Some(path.to_path_buf());
        }
        self.origin.name = path.display().to_string();
        self.note = Some(if warnings.is_empty() {
            format!("saved {}", path.display())
        } else {
            format!("saved {} ({})", path.display(), warnings.join("; "))
        });
        Ok(())
    }

    /// Exports the level shown in the active view (OBJ with its creases, STL, glTF).
    pub fn export_to(&mut self, path: &Path) -> Result<(), String> {
        let v = &self.views[self.active];
        let lv = &v.pipeline.levels()[v.shown()];
        let holes = &lv.tags.holes;
        if io::ExportFormat::of(path).is_some() {
            io::export(path, &lv.mesh, &|f| holes.contains(&(f as u32)))
                .map_err(|e| e.to_string())?;
        } else {
            io::write_obj(path, &lv.mesh, &lv.edge_attrs, &lv.tags).map_err(|e| e.to_string())?;
        }
        self.note = Some(format!(
            "exported level {} to {}",
            v.shown(),
            path.display()
        ));
        Ok(())
    }

    pub fn cancel_all(&mut self) {
        for v in &mut self.views {
            v.cancel();
        }
    }

    /// Frames the model of the active view.
    pub fn frame(&mut self) {
        let v = &self.views[self.active];
        let r = if v.scene.vertices.is_empty() {
            let (lo, hi) = self.doc.mesh.bbox();
            (0.5 * (hi - lo).length()).max(1e-9) as f32
        } else {
            v.scene.radius()
        };
        // A narrow view (the compare split) has the smaller horizontal field: fit that too.
        let half_y = 0.5 * Camera::default().fov_y;
        let half_x = (half_y.tan() * self.view_aspect.clamp(0.1, 10.0)).atan();
        let r = r * half_y.sin() / half_x.min(half_y).sin();
        self.camera = Camera::looking(View::Iso, Vec3::ZERO, r);
        self.framed = true;
    }

    // ---- the frame ----

    fn keys(&mut self, ctx: &egui::Context) {
        use egui::{Key, KeyboardShortcut, Modifiers};
        let undo = KeyboardShortcut::new(Modifiers::COMMAND, Key::Z);
        let redo = KeyboardShortcut::new(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z);
        let redo_y = KeyboardShortcut::new(Modifiers::COMMAND, Key::Y);
        let save = KeyboardShortcut::new(Modifiers::COMMAND, Key::S);
        let open = KeyboardShortcut::new(Modifiers::COMMAND, Key::O);
        // Longest shortcut first: Ctrl+Shift+Z must not be eaten as Ctrl+Z.
        if ctx.input_mut(|i| i.consume_shortcut(&redo) || i.consume_shortcut(&redo_y)) {
            self.redo();
        } else if ctx.input_mut(|i| i.consume_shortcut(&undo)) {
            self.undo();
        }
        if ctx.input_mut(|i| i.consume_shortcut(&save)) {
            self.save_dialog(false);
        }
        if ctx.input_mut(|i| i.consume_shortcut(&open)) {
            self.open_dialog();
        }
        if ctx.egui_wants_keyboard_input() || self.tab != Tab::Model {
            return;
        }
        let plain = |k: Key| ctx.input(|i| i.modifiers.is_none() && i.key_pressed(k));
        if plain(Key::S) {
            self.step();
        }
        if plain(Key::B) {
            self.back();
        }
        if plain(Key::F) {
            self.display.smooth = !self.display.smooth;
            self.display_changed();
        }
        if plain(Key::W) {
            self.display.wireframe = !self.display.wireframe;
            self.display_changed();
        }
        for (k, a) in [(Key::X, 0), (Key::Y, 1), (Key::Z, 2)] {
            if plain(k) {
                self.axis = if self.axis == Some(a) { None } else { Some(a) };
            }
        }
        if plain(Key::Escape) {
            self.sel_verts.clear();
            self.sel_edges.clear();
            self.mark_overlays();
        }
    }

    pub fn display_changed(&mut self) {
        for v in &mut self.views {
            v.scene_opts = self.display.scene_options();
            v.scene_dirty = true;
            v.overlay_dirty = true;
        }
    }

    fn open_dialog(&mut self) {
        if let Some(p) = rfd::FileDialog::new()
            .add_filter("Prism documents and OBJ", &["json", "obj"])
            .pick_file()
        {
            self.open_path(&p);
        }
    }

    /// Saves to the document's own file, or asks where (`as_new`: always asks).
    fn save_dialog(&mut self, as_new: bool) {
        let path = match (&self.origin.path, as_new) {
            (Some(p), false) => Some(p.clone()),
            _ => rfd::FileDialog::new()
                .add_filter("Prism document", &["prism.json"])
                .add_filter("OBJ", &["obj"])
                .set_file_name("model.prism.json")
                .save_file(),
        };
        if let Some(p) = path
            && let Err(e) = self.save_to(&p)
        {
            self.note = Some(format!("could not save: {e}"));
        }
    }

    fn export_dialog(&mut self, ext: &str) {
        if let Some(p) = rfd::FileDialog::new()
            .add_filter(ext, &[ext])
            .set_file_name(format!("level.{ext}"))
            .save_file()
            && let Err(e) = self.export_to(&p)
        {
            self.note = Some(format!("could not export: {e}"));
        }
    }

    fn dropped_files(&mut self, ctx: &egui::Context) {
        let dropped = ctx.input(|i| i.raw.dropped_files.clone());
        if let Some(f) = dropped.first() {
            let p = f.path().to_path_buf();
            self.open_path(&p);
        }
    }

    fn budget_question(&mut self, ctx: &egui::Context) {
        let Some((view, o)) = self.question.clone() else {
            return;
        };
        let mut answer = None;
        egui::Modal::new(egui::Id::unique("prism-budget-question")).show(ctx, |ui| {
            ui.heading("This step needs a lot of memory");
            ui.label(format!(
                "View {}: the next level would have {} faces and need about {} MiB; the budget is {} MiB.",
                view + 1,
                o.faces,
                o.needed_mib,
                o.budget_mib
            ));
            ui.horizontal(|ui| {
                if ui.button("Compute anyway").clicked() {
                    answer = Some(true);
                }
                if ui.button("Remove the step").clicked() {
                    answer = Some(false);
                }
            });
        });
        match answer {
            Some(true) => self.compute_anyway(),
            Some(false) => {
                self.question = None;
                let v = view;
                let keep = self.views[v].pipeline.levels().len() - 1;
                self.change(|d| d.pipelines[v].truncate(keep));
            }
            None => {}
        }
    }

    /// The answer "compute anyway" to the budget question.
    pub fn compute_anyway(&mut self) {
        if let Some((view, o)) = self.question.take() {
            let v = &mut self.views[view];
            v.budget_override = Some((o.needed_mib + o.needed_mib / 4 + 16) << 20);
            let next = v.pipeline.rebased(self.doc.pipelines[view].clone());
            v.submit(next, self.budget_mib << 20, false, &self.waker);
        }
    }

    fn screenshot(&mut self, ctx: &egui::Context) {
        let busy = self.busy();
        let Some((path, frames, slot)) = &mut self.screenshot else {
            return;
        };
        ctx.request_repaint();
        if busy {
            return;
        }
        *frames += 1;
        if *frames == 8 {
            let slot = slot.clone();
            ctx.send_viewport_cmd(egui::ViewportCommand::Screenshot(
                egui::ScreenshotCallback::new(move |img| {
                    *slot.lock().expect("screenshot slot") = Some(img);
                }),
            ));
        }
        let taken = slot.lock().expect("screenshot slot").take();
        if let Some(img) = taken {
            let [w, h] = img.size;
            let rgba: Vec<u8> = img.pixels.iter().flat_map(|c| c.to_array()).collect();
            let mut png = Vec::new();
            let ok = image::RgbaImage::from_raw(w as u32, h as u32, rgba)
                .map(|i| i.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png));
            match ok {
                Some(Ok(())) => match io::write_atomically(path, &png) {
                    Ok(()) => println!("wrote {} ({w}x{h})", path.display()),
                    Err(e) => eprintln!("error: {e}"),
                },
                _ => eprintln!("error: encoding the screenshot failed"),
            }
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
    }
}

/// A bundled sample as a document.
fn sample(k: usize) -> Result<(DocState, Origin), String> {
    let (name, file, text) = SAMPLES_FILES[k];
    let (doc, _) = io::load_str(Path::new(file), text).map_err(|e| e.to_string())?;
    Ok((
        DocState::from_document(doc),
        Origin {
            path: None,
            name: format!("{} (bundled sample)", name.to_lowercase()),
        },
    ))
}

impl eframe::App for PrismApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.frame_ui(ui);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        if self.screenshot.is_none() {
            eframe::set_value(storage, SETTINGS_KEY, &self.settings());
        }
    }
}

impl PrismApp {
    /// One frame of the whole window (eframe calls it; the UI tests drive it directly).
    pub fn frame_ui(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        if self.poll_jobs() {
            ctx.request_repaint();
        }
        if self.busy() {
            ctx.request_repaint_after(std::time::Duration::from_millis(50));
        }
        self.keys(&ctx);
        self.dropped_files(&ctx);
        egui::Panel::top("menu").show(ui, |ui| self.menu_bar(ui));
        match self.tab {
            Tab::Model => {
                egui::Panel::left("panels")
                    .resizable(true)
                    .default_size(300.0)
                    .show(ui, |ui| {
                        egui::ScrollArea::vertical().show(ui, |ui| self.side_panel(ui));
                    });
                egui::Panel::bottom("status").show(ui, |ui| self.status(ui));
                let n = self.doc.pipelines.len();
                if n > 1 {
                    egui::Panel::bottom(("compare", n))
                        .resizable(true)
                        .default_size(34.0 + 22.0 * n as f32)
                        .show(ui, |ui| self.compare_table(ui));
                }
                self.rebuild_scenes();
                egui::CentralPanel::default()
                    .frame(egui::Frame::NONE)
                    .show(ui, |ui| self.views_ui(ui));
                self.budget_question(&ctx);
            }
            Tab::Curves => {
                egui::CentralPanel::default().show(ui, |ui| self.curves.ui(ui));
            }
        }
        self.screenshot(&ctx);
    }
}

/// Opens the window; returns when it is closed.
pub fn run(launch: Launch) -> Result<(), String> {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("Prism")
            .with_inner_size([1280.0, 800.0])
            .with_drag_and_drop(true),
        renderer: eframe::Renderer::Wgpu,
        multisampling: SAMPLES,
        depth_buffer: 32,
        ..Default::default()
    };
    eframe::run_native(
        "Prism",
        options,
        Box::new(move |cc| {
            PrismApp::new(cc, launch)
                .map(|a| Box::new(a) as Box<dyn eframe::App>)
                .map_err(|e| e.into())
        }),
    )
    .map_err(|e| format!("the window could not be opened: {e}"))
}
