//! Files from the app: the bundled samples, the Open / Save / Export dialogs (the desktop's
//! through rfd, or the in-app one of `egui_file` where the desktop has none), saving and
//! exporting to a path, and `--screenshot` (the window's own picture, written once the levels
//! are computed).

use super::document::{DocState, Origin};
use super::gestures::Tab3d;
use super::{PrismApp, SAMPLES_FILES};
use prism_geom::io;
use std::path::{Path, PathBuf};

/// Whether something can show a native file dialog: zenity on the PATH, or a desktop
/// portal on the session bus (its service file installed).
fn dialog_helper_present() -> bool {
    let on_path = |name: &str| {
        std::env::var_os("PATH")
            .is_some_and(|p| std::env::split_paths(&p).any(|d| d.join(name).is_file()))
    };
    let portal = ["/usr/share/dbus-1/services/org.freedesktop.portal.Desktop.service"]
        .iter()
        .any(|f| Path::new(f).is_file());
    on_path("zenity") || portal
}

/// Whether the desktop's file dialogs can be shown: not on Linux without zenity or a portal,
/// nor when `PRISM_FILE_DIALOG=in-app` asks for the app's own.
fn native_dialogs() -> bool {
    if std::env::var_os("PRISM_FILE_DIALOG").is_some_and(|v| v == "in-app") {
        return false;
    }
    !cfg!(target_os = "linux") || dialog_helper_present()
}

/// What the in-app file dialog was opened for.
#[derive(Debug, Clone, PartialEq)]
pub enum Purpose {
    Open,
    /// Save as; `then_close` when the close question's Save asked for it.
    Save {
        then_close: bool,
    },
    /// Export the shown level or surface: `obj`, `stl`, `glb` or `obj+vn`.
    Export(&'static str),
}

/// The in-app file dialog (`egui_file`) and what it is for.
pub struct InAppDialog {
    pub dialog: egui_file::FileDialog,
    pub purpose: Purpose,
}

/// The extensions the Open dialog lists.
const OPENED: [&str; 4] = ["json", "obj", "stl", "ply"];

/// A bundled sample as a document.
pub fn sample(k: usize) -> Result<(DocState, Origin), String> {
    let (name, file, text) = *SAMPLES_FILES
        .get(k)
        .ok_or(format!("there is no sample {k}"))?;
    let (doc, numbering) = io::load_str(Path::new(file), text).map_err(|e| e.to_string())?;
    Ok((
        DocState::from_document(doc),
        Origin {
            path: None,
            name: format!("{} (bundled sample)", name.to_lowercase()),
            numbering: std::sync::Arc::new(numbering),
        },
    ))
}

impl PrismApp {
    /// Saves the document (`.prism.json` keeps the pipeline and the curve sketch, OBJ the
    /// mesh and its tags).
    pub fn save_to(&mut self, path: &Path) -> Result<(), String> {
        let warnings =
            io::save(path, &self.doc.state().to_document()).map_err(|e| e.to_string())?;
        let native = io::FileKind::of(path).ok() == Some(io::FileKind::Document);
        if native {
            self.last_file = Some(path.to_path_buf());
            self.remember(path);
        }
        self.doc.saved_as(path, native);
        if native {
            self.autosave.saved(self.doc.generation());
        }
        self.say(if warnings.is_empty() {
            format!("saved {}", path.display())
        } else {
            format!("saved {} ({})", path.display(), warnings.join("; "))
        });
        Ok(())
    }

    /// Exports the level shown in the active view (OBJ with its creases, STL, glTF) with
    /// normals as the view shades it (smooth or flat; in OBJ only when `obj_normals`).
    pub fn export_to(&mut self, path: &Path, obj_normals: bool) -> Result<(), String> {
        let shading = if self.tab != super::Tab::Model || self.model.display.smooth {
            io::Normals::Smooth
        } else {
            io::Normals::Flat
        };
        let vn = obj_normals.then_some(shading);
        if matches!(self.tab, super::Tab::Skin | super::Tab::Envelope) {
            let (what, surface) = if self.tab == super::Tab::Skin {
                ("skin", self.skin.surface())
            } else {
                ("envelope", self.envelope.surface())
            };
            let mesh = surface.map_err(|why| format!("there is no {what} to export: {why}"))?;
            if io::ExportFormat::of(path).is_some() {
                io::export(path, mesh, &|_| false, shading).map_err(|e| e.to_string())?;
            } else {
                io::write_obj_with_normals(
                    path,
                    mesh,
                    &Default::default(),
                    &Default::default(),
                    vn,
                )
                .map_err(|e| e.to_string())?;
            }
            self.say(format!("exported the {what} to {}", path.display()));
            return Ok(());
        }
        let (k, lv) = self.model.shown_level();
        let holes = &lv.tags.holes;
        if io::ExportFormat::of(path).is_some() {
            io::export(path, &lv.mesh, &|f| holes.contains(&(f as u32)), shading)
                .map_err(|e| e.to_string())?;
        } else {
            io::write_obj_with_normals(path, &lv.mesh, &lv.edge_attrs, &lv.tags, vn)
                .map_err(|e| e.to_string())?;
        }
        self.say(format!("exported level {k} to {}", path.display()));
        Ok(())
    }

    /// The native file dialogs block the frame loop, and keys typed while one is open (where
    /// the window manager lets the main window keep the keyboard, or none decides) wait in
    /// the window's queue and reach it when the dialog closes. They were meant for the
    /// dialog: the two frames after it, and any frame within 300 ms of it, drop every key and
    /// text event, so S, B or W typed into a file name never change the model.
    pub fn drop_keys_typed_in_dialog(&mut self, ctx: &egui::Context) {
        let Some((at, frames)) = &mut self.after_dialog else {
            return;
        };
        *frames += 1;
        if *frames > 2 && at.elapsed() > std::time::Duration::from_millis(300) {
            self.after_dialog = None;
            return;
        }
        ctx.input_mut(|i| {
            i.events
                .retain(|e| !matches!(e, egui::Event::Key { .. } | egui::Event::Text(_)));
            i.keys_down.clear();
        });
    }

    /// Runs one native file dialog (`show`), then marks its return for
    /// [`PrismApp::drop_keys_typed_in_dialog`]; when it gave nothing, says why if it most
    /// likely never opened ([`PrismApp::no_dialog`]).
    fn dialog(
        &mut self,
        show: impl FnOnce() -> Option<std::path::PathBuf>,
    ) -> Option<std::path::PathBuf> {
        let asked = std::time::Instant::now();
        let picked = show();
        self.dialog_returned();
        if picked.is_none() {
            self.no_dialog(asked);
        }
        picked
    }

    /// Marks that a file dialog has just returned ([`PrismApp::drop_keys_typed_in_dialog`]).
    pub(super) fn dialog_returned(&mut self) {
        self.after_dialog = Some((std::time::Instant::now(), 0));
    }

    /// Opens the in-app file dialog for `purpose`, in the folder of the document's file (or
    /// the working folder), with the file name `name` for a save.
    pub fn in_app_dialog(&mut self, purpose: Purpose, name: Option<String>) {
        let folder = self
            .doc
            .origin()
            .path
            .as_ref()
            .and_then(|p| p.parent().map(Path::to_path_buf))
            .filter(|p| p.is_dir())
            .or_else(|| std::env::current_dir().ok())
            .unwrap_or_default();
        let mut dialog = match purpose {
            Purpose::Open => egui_file::FileDialog::open_file()
                .title("Open a Prism document, OBJ, STL or PLY")
                .show_files_filter(Box::new(|p: &Path| {
                    p.extension()
                        .and_then(|e| e.to_str())
                        .is_some_and(|e| OPENED.contains(&e.to_ascii_lowercase().as_str()))
                })),
            Purpose::Save { .. } => egui_file::FileDialog::save_file().title("Save as"),
            Purpose::Export(_) => egui_file::FileDialog::save_file().title("Export"),
        }
        .initial_path(folder)
        .show_new_folder(true)
        .show_rename(false)
        .default_size([640.0, 420.0]);
        if let Some(n) = name {
            dialog = dialog.default_filename(n);
        }
        dialog.open();
        self.file_dialog = Some(InAppDialog { dialog, purpose });
    }

    /// Draws the in-app file dialog, if one is open, and acts on its answer.
    pub(super) fn show_in_app_dialog(&mut self, ctx: &egui::Context) {
        let Some(d) = &mut self.file_dialog else {
            return;
        };
        d.dialog.show(ctx);
        match d.dialog.state() {
            egui_file::State::Open => {}
            egui_file::State::Selected => {
                let path = d.dialog.path().map(Path::to_path_buf);
                let purpose = d.purpose.clone();
                self.file_dialog = None;
                if let Some(p) = path {
                    self.dialog_chose(purpose, p, ctx);
                }
            }
            egui_file::State::Closed | egui_file::State::Cancelled => self.file_dialog = None,
        }
    }

    /// Does what the in-app dialog was opened for with the file chosen.
    pub fn dialog_chose(&mut self, purpose: Purpose, path: PathBuf, ctx: &egui::Context) {
        match purpose {
            Purpose::Open => self.open_path(&path),
            Purpose::Save { then_close } => {
                // A name without a kind Prism writes is saved as a document.
                let path = if io::FileKind::of(&path).is_ok() {
                    path
                } else {
                    with_suffix(&path, "prism.json")
                };
                match self.save_to(&path) {
                    Ok(()) if then_close && !self.unsaved() => self.close(ctx),
                    Ok(()) => {}
                    Err(e) => self.say(format!("could not save: {e}")),
                }
            }
            Purpose::Export(kind) => {
                let (ext, normals) = export_kind(kind);
                let path = if path
                    .extension()
                    .is_some_and(|e| e.eq_ignore_ascii_case(ext))
                {
                    path
                } else {
                    with_suffix(&path, ext)
                };
                if let Err(e) = self.export_to(&path, normals) {
                    self.say(format!("could not export: {e}"));
                }
            }
        }
    }

    pub(super) fn open_dialog(&mut self) {
        if !native_dialogs() {
            self.in_app_dialog(Purpose::Open, None);
            return;
        }
        let picked = self.dialog(|| {
            rfd::FileDialog::new()
                .add_filter("Prism documents, OBJ, STL and PLY", &OPENED)
                .pick_file()
        });
        if let Some(p) = picked {
            self.open_path(&p);
        }
    }

    /// A dialog that came back at once with nothing most likely never opened: on Linux the
    /// native dialogs need an xdg-desktop-portal or zenity. Says so, and what works anyway.
    fn no_dialog(&mut self, asked: std::time::Instant) {
        if cfg!(target_os = "linux")
            && asked.elapsed() < std::time::Duration::from_millis(300)
            && !dialog_helper_present()
        {
            self.say(
                "no file dialog could be shown: it needs zenity or an xdg-desktop-portal \
                 (apt-get install zenity); meanwhile drag a file onto the window, or start \
                 `prism FILE`",
            );
        }
    }

    /// Saves to the document's own file, or asks where (`as_new`: always asks); `then_close`
    /// closes the window once an in-app dialog's save went through.
    pub(super) fn save_dialog(&mut self, as_new: bool, then_close: bool) {
        let own = self.doc.origin().path.clone().filter(|_| !as_new);
        if own.is_none() && !native_dialogs() {
            self.in_app_dialog(
                Purpose::Save { then_close },
                Some("model.prism.json".to_string()),
            );
            return;
        }
        let path = own.or_else(|| {
            self.dialog(|| {
                rfd::FileDialog::new()
                    .add_filter("Prism document", &["prism.json"])
                    .add_filter("OBJ", &["obj"])
                    .set_file_name("model.prism.json")
                    .save_file()
            })
        });
        if let Some(p) = path
            && let Err(e) = self.save_to(&p)
        {
            self.say(format!("could not save: {e}"));
        }
    }

    /// Asks where to export; `kind` is `obj`, `stl`, `glb`, or `obj+vn` (OBJ with normals).
    pub(super) fn export_dialog(&mut self, kind: &'static str) {
        let (ext, normals) = export_kind(kind);
        let name = match self.tab {
            super::Tab::Skin => format!("skin.{ext}"),
            super::Tab::Envelope => format!("envelope.{ext}"),
            _ => format!("level.{ext}"),
        };
        if !native_dialogs() {
            self.in_app_dialog(Purpose::Export(kind), Some(name));
            return;
        }
        let picked = self.dialog(|| {
            rfd::FileDialog::new()
                .add_filter(ext, &[ext])
                .set_file_name(name)
                .save_file()
        });
        if let Some(p) = picked
            && let Err(e) = self.export_to(&p, normals)
        {
            self.say(format!("could not export: {e}"));
        }
    }

    /// `--screenshot`: once nothing is computing, waits a few frames, asks egui for the
    /// window's picture, writes it and closes the window.
    pub(super) fn screenshot(&mut self, ctx: &egui::Context) {
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

/// `path` with `.suffix` added to its name.
fn with_suffix(path: &Path, suffix: &str) -> PathBuf {
    let mut s = path.as_os_str().to_owned();
    s.push(".");
    s.push(suffix);
    PathBuf::from(s)
}

/// An export's kind, `obj`, `stl`, `glb` or `obj+vn`: its extension and whether OBJ carries
/// normals.
fn export_kind(kind: &str) -> (&str, bool) {
    match kind.strip_suffix("+vn") {
        Some(e) => (e, true),
        None => (kind, false),
    }
}
