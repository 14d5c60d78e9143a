//! The desktop app (eframe/egui, wgpu): a menu bar (File: open, bundled samples, save,
//! export; Edit: undo/redo; the tabs), one tab at a time, a status bar.
//!
//! - [`document`]: the document (control mesh, marks, tags, the pipeline of every view, the
//!   curve sketch) and its one writer, `Document::apply`, with the global history;
//! - [`command`]: what tabs, keys and menus ask for;
//! - [`model`], [`curves`]: the tabs, each a folder with a state struct whose `ui` reads the
//!   document and returns commands;
//! - this file: [`PrismApp`], the frame loop — draw the menu (`menu.rs`) and the tab, carry out the
//!   commands they returned, let the tabs follow the document's generation.
//!
//! `prism --screenshot OUT.png [FILE] [--pipeline P] ...` opens the window, waits for the
//! computation, saves a picture of the whole window (egui's screenshot command) and exits:
//! the test under Xvfb and the pictures in docs/ use it.

mod autosave;
mod closing;
pub mod command;
mod curves;
pub mod doc_state;
pub mod document;
mod edits;
pub(crate) mod envelope;
mod files;
mod gestures;
mod latest;
mod launch;
mod menu;
pub mod model;
mod new_document;
mod new_solid;
mod opening;
mod paper_figures;
mod show;
pub(crate) mod skin;
mod view3d;
mod viewport;
pub mod waker;

impl PrismApp {
    /// Opens bundled sample `k` of a 3D tab and shows that tab (named `what` in the status).
    fn open_tab_sample<T: Tab3d>(
        &mut self,
        (tab, what): (Tab, &str),
        k: usize,
        of: impl Fn(&mut Self) -> &mut T,
    ) {
        let t = of(self);
        let opened = t.open_sample(k);
        let commands = std::mem::take(t.out());
        self.tab = tab;
        for c in commands {
            self.run(c);
        }
        match opened {
            Ok(name) => self.say(format!("{what} sample: {name}")),
            Err(e) => self.say(e),
        }
    }
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_autosave;
#[cfg(test)]
mod tests_envelope;
#[cfg(test)]
mod tests_files;
#[cfg(test)]
mod tests_new_solid;
#[cfg(test)]
mod tests_opening;
#[cfg(test)]
mod tests_rounding;
#[cfg(test)]
mod tests_skin;

use command::Command;
use doc_state::Part;
use document::{DocState, Document, Origin};
use gestures::Tab3d;
use launch::SETTINGS_KEY;
pub use launch::{Launch, SAMPLES_FILES, Settings, Show, Tab};
use model::ModelTab;
pub use model::Tool;
#[cfg(test)]
use prism_geom::EdgeKey;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

/// Window multisampling (and the renderer's, which must match).
const SAMPLES: u16 = 4;

/// Where the screenshot callback leaves the picture for the next frame.
type ScreenshotSlot = Arc<Mutex<Option<Arc<egui::ColorImage>>>>;

pub struct PrismApp {
    pub doc: Document,
    pub tab: Tab,
    pub model: ModelTab,
    pub curves: curves::CurvesTab,
    pub skin: skin::SkinTab,
    pub envelope: envelope::EnvelopeTab,
    /// A message for the status bar (what the last action did, or why it did nothing);
    /// cleared by the next change of the document.
    pub note: Option<String>,
    /// The document generation the note was written at.
    note_at: u64,
    screenshot: Option<(PathBuf, u32, ScreenshotSlot)>,
    /// When the last file dialog returned, and the frames drawn since ([`PrismApp::drop_keys_typed_in_dialog`]).
    after_dialog: Option<(std::time::Instant, u32)>,
    /// The camera before the last edit, and the document generation that edit made.
    camera_before_edit: Option<(u64, prism_viewport::Camera)>,
    last_file: Option<PathBuf>,
    /// Files opened or saved, the latest first (File ▸ Recent; remembered between runs).
    pub recent: Vec<PathBuf>,
    pub new_solid: new_solid::NewSolid,
    pub autosave: autosave::Autosave,
    /// A big file being opened on a thread (opening.rs).
    opening: Option<opening::Opening>,
    /// The title shown and the question on closing (closing.rs).
    pub closing: closing::Closing,
    /// The generation at which Ctrl+Z said the next undo reaches into another tab.
    undo_warned: Option<u64>,
    /// Files at least this large open on a thread ([`opening::IN_BACKGROUND_FROM`]).
    open_in_background_from: u64,
    /// The in-app file dialog, where the desktop has none (files.rs).
    pub file_dialog: Option<files::InAppDialog>,
}

/// How many files File ▸ Recent lists.
pub const RECENT: usize = 8;

impl PrismApp {
    /// The app without a window (tests drive it this way; `new` adds the GPU).
    pub fn headless(launch: Launch, settings: Option<Settings>) -> Result<PrismApp, String> {
        let settings = settings.unwrap_or_default();
        let remembered = settings.last_file.clone().filter(|p| p.exists());
        // A file that cannot be opened (given, or remembered from the last run) leaves the
        // window on the bundled tripod, its error in the status bar.
        let mut note = None;
        // A big file given alone opens on a thread behind a progress bar, over the tripod; a
        // screenshot or a pipeline for it waits for it.
        let file = launch.file.as_ref().or(remembered.as_ref());
        let in_background = file
            .filter(|p| {
                launch.screenshot.is_none()
                    && launch.pipeline.is_empty()
                    && launch.compare.is_empty()
                    && std::fs::metadata(p).is_ok_and(|m| m.len() >= opening::IN_BACKGROUND_FROM)
            })
            .cloned();
        let (mut state, origin) = match file.filter(|_| in_background.is_none()) {
            Some(p) => document::open(p).or_else(|e| {
                note = Some(format!("could not open {}: {e}", p.display()));
                files::sample(0)
            })?,
            None => files::sample(0)?,
        };
        if !launch.pipeline.is_empty() {
            state.pipelines[0] = launch.pipeline;
        }
        state.pipelines.extend(launch.compare.into_iter().take(3));
        if state.pipelines.len() == 3 {
            state.pipelines.push(state.pipelines[0].clone());
        }
        let mut display = settings.display.clone();
        let mut envelope = envelope::EnvelopeTab::default();
        let mut skin = skin::SkinTab::default();
        let mut curves = curves::CurvesTab::default();
        for &s in &launch.show {
            show::apply_show(s, &mut display, &mut envelope, &mut skin, &mut curves);
        }
        let next = prism_geom::parse_pipeline(&settings.next)
            .ok()
            .and_then(|v| v.first().copied())
            .unwrap_or_else(model::default_next);
        let mut model = ModelTab::new(
            display,
            launch.tool.unwrap_or(settings.tool),
            next,
            settings.budget_mib,
        );
        model.sel_edges = launch.select_edges.into_iter().collect();
        if launch.no_clamp {
            model.set_clamp(false);
        }
        let last_file = origin.path.clone().or(settings.last_file);
        let recent = settings.recent.clone();
        let first_tab = tab_for(&state);
        let doc = Document::new(state, origin);
        model.sync(&doc);
        let autosave = autosave::Autosave::new(launch.autosave.clone(), doc.generation());
        Ok(PrismApp {
            autosave,
            doc,
            tab: launch.tab.or(first_tab).unwrap_or_default(),
            model,
            curves,
            skin,
            envelope,
            new_solid: Default::default(),
            note,
            note_at: 0,
            screenshot: launch
                .screenshot
                .map(|p| (p, 0, Arc::new(Mutex::new(None)))),
            after_dialog: None,
            file_dialog: None,
            camera_before_edit: None,
            last_file,
            recent,
            opening: in_background.map(|p| opening::Opening::start(&p, Arc::new(|| {}))),
            open_in_background_from: opening::IN_BACKGROUND_FROM,
            closing: Default::default(),
            undo_warned: None,
        })
    }

    fn new(cc: &eframe::CreationContext<'_>, launch: Launch) -> Result<PrismApp, String> {
        let rs = cc
            .wgpu_render_state
            .as_ref()
            .ok_or("the wgpu renderer is not available")?;
        viewport::install(rs, SAMPLES as u32, &cc.egui_ctx);
        // A screenshot run shows what its arguments say, not what the last run left.
        let settings = if launch.screenshot.is_some() {
            None
        } else {
            cc.storage
                .and_then(|s| eframe::get_value::<Settings>(s, SETTINGS_KEY))
        };
        let mut app = PrismApp::headless(launch, settings)?;
        app.model.has_gpu = true;
        app.skin.base.view.has_gpu = true;
        app.envelope.base.view.has_gpu = true;
        let ctx = cc.egui_ctx.clone();
        app.model.waker = Arc::new(move || ctx.request_repaint());
        Ok(app)
    }

    fn settings(&self) -> Settings {
        Settings {
            display: self.model.display.clone(),
            tool: self.model.tool,
            budget_mib: self.model.budget_mib,
            next: self.model.next.to_string(),
            last_file: self.last_file.clone(),
            recent: self.recent.clone(),
        }
    }

    /// Puts `path` first in File ▸ Recent (at most [`RECENT`] files, each once).
    pub(super) fn remember(&mut self, path: &std::path::Path) {
        let path = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
        self.recent.retain(|p| *p != path);
        self.recent.insert(0, path);
        self.recent.truncate(RECENT);
    }

    fn say(&mut self, text: impl Into<String>) {
        self.note = Some(text.into());
        self.note_at = self.doc.generation();
    }

    /// Carries out one command; the tabs follow the document's new generation.
    pub fn run(&mut self, c: impl Into<Command>) {
        match c.into() {
            Command::Edit(e) => {
                let camera = self.model.camera;
                match self.doc.apply(e) {
                    Ok(true) => self.camera_before_edit = Some((self.doc.generation(), camera)),
                    Ok(false) => {}
                    Err(msg) => self.say(msg),
                }
            }
            Command::Undo => {
                // From a tab whose own changes are all undone, the first Ctrl+Z says what
                // the next would take back in another tab; the second does it.
                let part = self.doc.next_undo();
                let elsewhere = part
                    .and_then(Part::tab_name)
                    .filter(|t| *t != self.tab.name());
                let generation = self.doc.generation();
                if let (Some(p), Some(t)) = (part, elsewhere)
                    && self.undo_warned != Some(generation)
                {
                    self.undo_warned = Some(generation);
                    self.say(format!(
                        "nothing left to undo in the {} tab; Ctrl+Z again undoes {} in the {t} tab",
                        self.tab.name(),
                        p.describe()
                    ));
                    return;
                }
                let before = self.doc.origin().clone();
                // Undoing the edit that blew a level up (vertices thrown far out) brings back
                // the camera from before it, not the one framed on the wreck.
                let blown_up = self.model.views.iter().any(|v| v.frame_sphere().2 > 0);
                let camera = self
                    .camera_before_edit
                    .filter(|(g, _)| blown_up && *g == self.doc.generation());
                if self.doc.undo() {
                    if let Some((_, c)) = camera {
                        self.model.camera = c;
                    }
                    self.follow_document_switch(&before);
                    let what = part.map_or("the last change", Part::describe);
                    let tab = part.and_then(Part::tab_name).map(|t| format!(" ({t} tab)"));
                    self.say(format!("undid {what}{}", tab.unwrap_or_default()));
                }
            }
            Command::Redo => {
                let before = self.doc.origin().clone();
                if self.doc.redo() {
                    self.follow_document_switch(&before);
                    self.say("redone");
                }
            }
            Command::Open(p) => self.open_path(&p),
            Command::OpenSample(k) => match files::sample(k) {
                Ok((state, origin)) => self.replace_document(state, origin),
                Err(e) => self.say(e),
            },
            Command::OpenSkinSample(k) => {
                self.open_tab_sample((Tab::Skin, "skin"), k, |a| &mut a.skin)
            }
            Command::OpenEnvelopeSample(k) => {
                self.open_tab_sample((Tab::Envelope, "envelope"), k, |a| &mut a.envelope)
            }
            Command::OpenFigure(k) => self.open_figure(k),
            Command::RestoreAutosave => self.restore_autosave(),
            Command::DiscardAutosave => {
                self.autosave.discard();
                self.say("discarded the unsaved work of the last run");
            }
            Command::OpenDialog => self.open_dialog(),
            Command::CancelOpening => self.cancel_opening(),
            Command::SaveDialog { as_new } => self.save_dialog(as_new, false),
            Command::ExportDialog(ext) => self.export_dialog(ext),
            Command::Cancel { view } => {
                if let Some(v) = self.model.views.get_mut(view) {
                    v.cancel();
                }
            }
            Command::ComputeAnyway => self.model.compute_anyway(self.doc.state()),
            Command::DropKeptLevels => self.model.drop_kept_levels(self.doc.state()),
            Command::RemoveOverBudgetStep => {
                if let Some(e) = self.model.remove_over_budget_step() {
                    self.run(e);
                }
            }
            Command::Say(text) => self.say(text),
            Command::ShowNewSolid { extrude } => {
                self.new_solid.open = true;
                if extrude {
                    self.new_solid.kind = new_solid::Kind::Extrusion;
                }
            }
            Command::NewSolid(solid) => self.make_solid(&solid),
        }
        self.model.sync(&self.doc);
        if self.note.is_some() && self.note_at != self.doc.generation() {
            self.note = None;
        }
    }

    /// Carries out the commands the Model tab's helpers queued (tests call those helpers
    /// directly, then this).
    #[cfg(test)]
    pub fn flush(&mut self) {
        for c in self.model.take_commands() {
            self.run(c);
        }
    }

    /// Blocks until every view's levels and the 3D tabs' surfaces are computed.
    #[cfg(test)]
    pub fn wait_idle(&mut self) {
        self.flush();
        self.model.wait_idle();
        // The 3D tabs brought up to the document, the envelope's build (off this thread)
        // waited for.
        let state = self.doc.state().clone();
        self.skin.sync(state.skin.as_ref());
        while self.skin.checking() {
            std::thread::sleep(std::time::Duration::from_millis(1));
            self.skin.sync(state.skin.as_ref());
        }
        self.envelope.sync(state.envelope.as_ref());
        while self.envelope.building() {
            self.envelope.sync(state.envelope.as_ref());
        }
    }

    pub fn busy(&self) -> bool {
        self.model.busy() || self.envelope.building() || self.skin.checking()
    }
}

impl eframe::App for PrismApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.frame_ui(ui);
    }

    fn on_exit(&mut self) {
        // Unsaved changes are copied for the next start (autosave.rs).
        if let Err(e) = self.autosave.tick(&self.doc, true) {
            eprintln!("{e}");
        }
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        if self.screenshot.is_none() {
            eframe::set_value(storage, SETTINGS_KEY, &self.settings());
        }
    }
}

/// The tab a document with no solid opens on: an envelope scene's or a skin's (a bare
/// `.envelope.json` or `.skin.json` opened).
fn tab_for(state: &document::DocState) -> Option<Tab> {
    if state.mesh.num_faces() > 0 {
        None
    } else if state.envelope.is_some() {
        Some(Tab::Envelope)
    } else if state.skin.is_some() {
        Some(Tab::Skin)
    } else {
        None
    }
}

impl PrismApp {
    /// One frame of the whole window (eframe calls it; the UI tests drive it directly):
    /// draw, then carry out what the menu, the keys and the tab asked for.
    pub fn frame_ui(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        // An option that changes the result (the clamp, mending) asks for a sync without a
        // command: every frame brings the views in line (nothing to do when they are).
        self.model.sync(&self.doc);
        if self.model.poll_jobs() {
            ctx.request_repaint();
        }
        if self.busy() {
            ctx.request_repaint_after(std::time::Duration::from_millis(50));
        }
        self.drop_keys_typed_in_dialog(&ctx);
        self.closing(&ctx);
        let mut commands = self.keys(&ctx);
        if let Some(f) = ctx.input(|i| i.raw.dropped_files.first().map(|f| f.path().to_path_buf()))
        {
            commands.push(Command::Open(f));
        }
        egui::Panel::top("menu").show(ui, |ui| commands.extend(self.menu_bar(ui)));
        let budget = self.model.budget_mib << 20;
        (self.skin.budget, self.envelope.budget) = (budget, budget);
        match self.tab {
            Tab::Model => {
                let note = self.note.clone();
                commands.extend(self.model.ui(ui, &self.doc, note.as_deref()));
            }
            Tab::Skin => commands.extend(self.skin.ui(ui, self.doc.state())),
            Tab::Envelope => commands.extend(self.envelope.ui(ui, self.doc.state())),
            Tab::Curves => {
                let sketch = &self.doc.state().curve;
                let out = egui::CentralPanel::default()
                    .show(ui, |ui| self.curves.ui(ui, sketch))
                    .inner;
                commands.extend(out);
            }
        }
        if self.new_solid.open
            && let Some(c) = self.new_solid.window(&ctx, &self.doc.state().curve)
        {
            commands.push(c);
        }
        if let Some(c) = self.restore_window(&ctx) {
            commands.push(c);
        }
        if self.opening.as_ref().is_some_and(|o| o.window(&ctx)) {
            commands.push(Command::CancelOpening);
        }
        self.show_in_app_dialog(&ctx);
        for c in commands {
            self.run(c);
        }
        // After the window was drawn: a file opened between frames shows its bar once.
        self.poll_opening();
        match self.autosave.tick(&self.doc, false) {
            Ok(_) => {}
            Err(e) => self.say(e),
        }
        // An idle window draws no frame: ask to be woken when the next copy is due.
        if let Some(due) = self.autosave.due_in(&self.doc) {
            ctx.request_repaint_after(due);
        }
        self.screenshot(&ctx);
    }
}

/// Where the window copies unsaved work (autosave.rs).
pub fn autosave_dir() -> Option<PathBuf> {
    autosave::Autosave::default_dir()
}

/// Opens the window; returns when it is closed.
pub fn run(launch: Launch) -> Result<(), String> {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("Prism")
            .with_inner_size([1280.0, 800.0])
            .with_drag_and_drop(true),
        renderer: eframe::Renderer::Wgpu,
        wgpu_options: egui_wgpu::WgpuConfiguration {
            wgpu_setup: egui_wgpu::WgpuSetup::CreateNew(egui_wgpu::WgpuSetupCreateNew {
                device_descriptor: Arc::new(viewport::device_descriptor),
                ..egui_wgpu::WgpuSetupCreateNew::without_display_handle()
            }),
            ..Default::default()
        },
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
