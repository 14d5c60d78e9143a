//! The window's menu bar (File, Edit, the tabs) and its keyboard shortcuts: each returns the
//! commands the frame loop carries out.

use super::*;

impl PrismApp {
    pub(super) fn keys(&mut self, ctx: &egui::Context) -> Vec<Command> {
        use egui::{Key, KeyboardShortcut, Modifiers};
        let undo = KeyboardShortcut::new(Modifiers::COMMAND, Key::Z);
        let redo = KeyboardShortcut::new(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z);
        let redo_y = KeyboardShortcut::new(Modifiers::COMMAND, Key::Y);
        let save = KeyboardShortcut::new(Modifiers::COMMAND, Key::S);
        let open = KeyboardShortcut::new(Modifiers::COMMAND, Key::O);
        let mut out = Vec::new();
        // The in-app file dialog has the keyboard: its file name is no shortcut.
        if self.file_dialog.is_some() {
            return out;
        }
        // Longest shortcut first: Ctrl+Shift+Z must not be eaten as Ctrl+Z.
        if ctx.input_mut(|i| i.consume_shortcut(&redo) || i.consume_shortcut(&redo_y)) {
            out.push(Command::Redo);
        } else if ctx.input_mut(|i| i.consume_shortcut(&undo)) {
            out.push(Command::Undo);
        }
        if ctx.input_mut(|i| i.consume_key(Modifiers::NONE, Key::F11)) {
            super::viewport::toggle_full_view(ctx);
        }
        if ctx.input_mut(|i| i.consume_shortcut(&save)) {
            out.push(Command::SaveDialog { as_new: false });
        }
        if ctx.input_mut(|i| i.consume_shortcut(&open)) {
            out.push(Command::OpenDialog);
        }
        if !ctx.egui_wants_keyboard_input() && self.tab == Tab::Model {
            self.model.keys(ctx);
        }
        out
    }

    pub(super) fn menu_bar(&mut self, ui: &mut egui::Ui) -> Vec<Command> {
        let mut out = Vec::new();
        egui::MenuBar::new().ui(ui, |ui| {
            ui.menu_button("File", |ui| {
                if ui.button("New solid…").clicked() {
                    out.push(Command::ShowNewSolid { extrude: false });
                }
                if ui.button("Open… (Ctrl+O)").clicked() {
                    out.push(Command::OpenDialog);
                }
                let recent: Vec<PathBuf> =
                    self.recent.iter().filter(|p| p.exists()).cloned().collect();
                ui.add_enabled_ui(!recent.is_empty(), |ui| {
                    ui.menu_button("Recent", |ui| out.extend(recent_menu(ui, &recent)))
                        .response
                        .on_disabled_hover_text("No file opened or saved yet");
                });
                ui.menu_button("Samples", |ui| {
                    for (k, (name, _, _)) in SAMPLES_FILES.iter().enumerate() {
                        if ui.button(*name).clicked() {
                            out.push(Command::OpenSample(k));
                        }
                    }
                    ui.separator();
                    ui.label("Skins (the Skin tab)");
                    for (k, (name, _, _)) in skin::SKIN_SAMPLES.iter().enumerate() {
                        if ui.button(*name).clicked() {
                            out.push(Command::OpenSkinSample(k));
                        }
                    }
                    ui.separator();
                    ui.label("Envelopes (the Envelope tab)");
                    for (k, (name, _, _)) in envelope::ENVELOPE_SAMPLES.iter().enumerate() {
                        if ui.button(*name).clicked() {
                            out.push(Command::OpenEnvelopeSample(k));
                        }
                    }
                });
                ui.separator();
                if ui.button("Save (Ctrl+S)").clicked() {
                    out.push(Command::SaveDialog { as_new: false });
                }
                if ui.button("Save as…").clicked() {
                    out.push(Command::SaveDialog { as_new: true });
                }
                ui.menu_button("Export the shown level", |ui| {
                    for (ext, label) in [
                        ("obj", "OBJ…"),
                        ("obj+vn", "OBJ with normals…"),
                        ("stl", "STL…"),
                        ("glb", "glTF (.glb)…"),
                    ] {
                        if ui
                            .button(label)
                            .on_hover_text(
                                "normals as the view shades the level: smooth, or flat \
                                 with smooth shading off",
                            )
                            .clicked()
                        {
                            out.push(Command::ExportDialog(ext));
                        }
                    }
                });
            });
            ui.menu_button("Edit", |ui| {
                let undo = match self.doc.next_undo() {
                    Some(p) => match p.tab_name() {
                        Some(t) => format!("Undo {} ({t}) (Ctrl+Z)", p.describe()),
                        None => format!("Undo {} (Ctrl+Z)", p.describe()),
                    },
                    None => "Undo (Ctrl+Z)".to_string(),
                };
                let entries = [
                    (
                        undo.as_str(),
                        self.doc.can_undo(),
                        Command::Undo,
                        "Nothing to undo",
                    ),
                    (
                        "Redo (Ctrl+Shift+Z)",
                        self.doc.can_redo(),
                        Command::Redo,
                        "Nothing to redo",
                    ),
                ];
                for (label, can, command, why_not) in entries {
                    if ui
                        .add_enabled(can, egui::Button::new(label))
                        .on_disabled_hover_text(why_not)
                        .clicked()
                    {
                        out.push(command);
                    }
                }
            });
            ui.menu_button("Help", |ui| {
                ui.menu_button("Paper figures", |ui| {
                    ui.label(
                        "Opens the figure's input, steps and view (docs/figures.md lists all 50)",
                    );
                    let mut paper = "";
                    for (k, f) in super::paper_figures::FIGURES.iter().enumerate() {
                        let seed = &f.id[..3];
                        if seed != paper {
                            ui.separator();
                            paper = seed;
                        }
                        if ui.button(format!("{}: {}", f.id, f.caption)).clicked() {
                            out.push(Command::OpenFigure(k));
                        }
                    }
                });
            });
            ui.separator();
            ui.selectable_value(&mut self.tab, Tab::Model, "Model");
            ui.selectable_value(&mut self.tab, Tab::Curves, "Curves");
            ui.selectable_value(&mut self.tab, Tab::Skin, "Skin");
            ui.selectable_value(&mut self.tab, Tab::Envelope, "Envelope");
            if self.tab == Tab::Model {
                ui.separator();
                self.model
                    .views_picker(ui, self.doc.state().pipelines.len());
            }
        });
        out
    }
}

/// File ▸ Recent's entries: each file by name (the whole path on hover); the one chosen.
fn recent_menu(ui: &mut egui::Ui, recent: &[PathBuf]) -> Option<Command> {
    let mut chosen = None;
    for p in recent {
        let name = p.file_name().map_or(p.display().to_string(), |n| {
            n.to_string_lossy().into_owned()
        });
        if ui
            .button(name)
            .on_hover_text(p.display().to_string())
            .clicked()
        {
            chosen = Some(Command::Open(p.clone()));
        }
    }
    chosen
}
