//! How a new document comes in: a solid made from the New solid dialog, a file opened (on a
//! thread when it is big, `opening.rs`), the autosave restored, the window's own state
//! restored, and the tabs following the switch.

use super::*;

impl PrismApp {
    /// Makes `solid` the document (undoable), keeping the pipelines and the curve sketch, and
    /// shows it on the Model tab.
    pub fn make_solid(&mut self, solid: &prism_geom::solid::Solid) {
        match solid.build() {
            Ok(mesh) => {
                let old = self.doc.state();
                let state = DocState {
                    mesh,
                    edge_attrs: Default::default(),
                    tags: Default::default(),
                    ..old.clone()
                };
                let name = match solid {
                    prism_geom::solid::Solid::Box { .. } => "a new box",
                    prism_geom::solid::Solid::Prism { .. } => "a new prism",
                    prism_geom::solid::Solid::Pyramid { .. } => "a new pyramid",
                    prism_geom::solid::Solid::Tripod { .. } => "a new tripod",
                    prism_geom::solid::Solid::Extrusion { .. } => "the extruded sketch",
                };
                let origin = document::Origin {
                    path: None,
                    name: name.into(),
                    ..Default::default()
                };
                self.replace_document(state, origin);
                self.tab = Tab::Model;
            }
            Err(e) => self.say(format!("no solid made: {e}")),
        }
    }

    /// Opens a file as the document (undoable: the previous document is one Ctrl+Z away); a
    /// big one on a thread behind a progress bar with Cancel (opening.rs).
    pub fn open_path(&mut self, path: &std::path::Path) {
        if let Some(o) = self.opening.take() {
            o.cancel();
        }
        let size = std::fs::metadata(path).map_or(0, |m| m.len());
        if size >= self.open_in_background_from {
            self.opening = Some(opening::Opening::start(path, self.model.waker.clone()));
            return;
        }
        self.opened(document::open(path));
    }

    pub(super) fn opened(
        &mut self,
        loaded: Result<(document::DocState, document::Origin), String>,
    ) {
        match loaded {
            Ok((state, origin)) => {
                if let Some(tab) = tab_for(&state) {
                    self.tab = tab;
                    self.envelope.reframe();
                    self.skin.reframe();
                }
                self.replace_document(state, origin);
                self.autosave.opened(self.doc.generation());
            }
            Err(e) => self.say(format!("could not open: {e}")),
        }
    }

    /// Takes the document the opening thread read, once it is done.
    pub(super) fn poll_opening(&mut self) {
        if let Some(loaded) = self.opening.as_ref().and_then(|o| o.poll()) {
            self.opening = None;
            self.opened(loaded);
        }
    }

    /// Stops opening a file: the document stays as it is.
    pub(super) fn cancel_opening(&mut self) {
        if let Some(o) = self.opening.take() {
            o.cancel();
            self.say(format!("stopped opening {}", o.path.display()));
        }
    }

    /// The copy of unsaved work an earlier run left, as the document (undoable); it is then
    /// the work in progress, unsaved, until saved.
    pub(super) fn restore_autosave(&mut self) {
        let Some(path) = self.autosave.offered_path() else {
            return;
        };
        let (name, target) = self.autosave.offered_origin();
        match document::open(&path) {
            Ok((state, _)) => {
                self.autosave.restored();
                // The work keeps its name and save target (Ctrl+S writes it back there).
                let origin = Origin {
                    path: target,
                    name,
                    ..Default::default()
                };
                self.replace_document(state, origin);
                self.say("restored the unsaved work of the last run (save it to keep it)");
            }
            Err(e) => {
                self.autosave.discard();
                self.say(format!("the unsaved work could not be restored: {e}"));
            }
        }
    }

    /// Offers the copy of unsaved work an earlier run left (none once answered).
    pub(super) fn restore_window(&mut self, ctx: &egui::Context) -> Option<Command> {
        let when = self.autosave.offer()?;
        let ago = when.elapsed().map_or(0, |d| d.as_secs() / 60);
        let mut out = None;
        egui::Window::new("Unsaved work")
            .collapsible(false)
            .resizable(false)
            .anchor(egui::Align2::CENTER_CENTER, egui::vec2(0.0, 0.0))
            .show(ctx, |ui| {
                ui.label(format!(
                    "The last run left work that was not saved ({ago} min ago)."
                ));
                ui.horizontal(|ui| {
                    if ui.button("Restore it").clicked() {
                        out = Some(Command::RestoreAutosave);
                    }
                    if ui.button("Discard it").clicked() {
                        out = Some(Command::DiscardAutosave);
                    }
                });
            });
        out
    }

    /// After undo or redo: when that brought back another document (an Open, a sample, a new
    /// solid undone), the views frame it and drop the other one's selection, as opening it did.
    pub(super) fn follow_document_switch(&mut self, before: &Origin) {
        if self.doc.origin() != before {
            self.model.reset_for_new_document();
        }
    }

    pub(super) fn replace_document(&mut self, state: DocState, origin: Origin) {
        self.model.reset_for_new_document();
        if let Some(p) = &origin.path {
            self.last_file = Some(p.clone());
        }
        let name = origin.name.clone();
        // A file (not a sample, a new solid or recovered work) goes to File ▸ Recent.
        if std::path::Path::new(&name).is_file() {
            self.remember(std::path::Path::new(&name));
        }
        let state = Box::new(state);
        self.run(command::Edit::Replace { state, origin });
        self.say(format!("opened {name}"));
    }
}
