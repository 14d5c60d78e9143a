//! The window's title — the document's name, marked `*` while it has changes no save holds —
//! and the question on closing with such changes: *Save*, *Don't save* or *Cancel*.
//! (Whatever is not saved is also copied for the next start: autosave.rs.)

use super::PrismApp;

/// What the window last showed and whether it is asking.
#[derive(Debug, Default)]
pub struct Closing {
    /// The title last sent to the window.
    title: String,
    /// The question is open.
    pub asking: bool,
    /// The user chose to close: the next close request goes through.
    pub leave: bool,
}

impl PrismApp {
    /// Whether the document has changes that no save (or open) holds.
    pub fn unsaved(&self) -> bool {
        self.autosave.unsaved(&self.doc)
    }

    /// The window's title: `*` first while unsaved, the document's file name, the program.
    pub fn title(&self) -> String {
        let name = &self.doc.origin().name;
        let short = std::path::Path::new(name)
            .file_name()
            .map_or(name.clone(), |n| n.to_string_lossy().into_owned());
        let mark = if self.unsaved() { "*" } else { "" };
        format!("{mark}{short} — Prism")
    }

    /// Keeps the title current and asks before a close would drop unsaved changes.
    pub(super) fn closing(&mut self, ctx: &egui::Context) {
        let title = self.title();
        if title != self.closing.title {
            ctx.send_viewport_cmd(egui::ViewportCommand::Title(title.clone()));
            self.closing.title = title;
        }
        let requested = ctx.input(|i| i.viewport().close_requested());
        if requested && self.unsaved() && !self.closing.leave && self.screenshot.is_none() {
            ctx.send_viewport_cmd(egui::ViewportCommand::CancelClose);
            self.closing.asking = true;
        }
        if !self.closing.asking {
            return;
        }
        let mut answer = None;
        egui::Modal::new(egui::Id::unique("prism-close-question")).show(ctx, |ui| {
            ui.heading("Save the changes before closing?");
            ui.label(format!(
                "{} has changes that are not saved. Not saved, they are kept only as the copy \
                 offered at the next start.",
                self.doc.origin().name
            ));
            ui.horizontal(|ui| {
                for choice in ["Save", "Don't save", "Cancel"] {
                    if ui.button(choice).clicked() {
                        answer = Some(choice);
                    }
                }
            });
        });
        match answer {
            Some("Save") => {
                self.save_dialog(false, true);
                self.closing.asking = false;
                // Closed only when the save went through (a dialog cancelled, or an error in
                // the status bar, leaves the window open).
                if !self.unsaved() {
                    self.close(ctx);
                }
            }
            Some("Don't save") => {
                self.closing.asking = false;
                self.close(ctx);
            }
            Some(_) => self.closing.asking = false,
            None => {}
        }
    }

    pub(super) fn close(&mut self, ctx: &egui::Context) {
        self.closing.leave = true;
        ctx.send_viewport_cmd(egui::ViewportCommand::Close);
    }
}
