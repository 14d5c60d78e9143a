//! Opening a big file without freezing the window: the file is read and parsed on a thread
//! (`io::load_with`, which parses OBJ on every core) while the window shows a progress bar
//! with Cancel. Cancel stops the reader at its next block or chunk and drops whatever it
//! would have given: the document stays as it was. Files under [`IN_BACKGROUND_FROM`] open at
//! once, as they always did.

use super::document::{self, DocState, Origin};
use super::waker::Waker;
use prism_geom::progress::Progress;
use std::path::{Path, PathBuf};
use std::sync::{Arc, mpsc};

/// Files at least this large are opened on a thread behind a progress bar (about a tenth of
/// a second of reading and parsing on this kind of machine).
pub const IN_BACKGROUND_FROM: u64 = 16 << 20;

type Loaded = Result<(DocState, Origin), String>;

/// A file being opened on a thread.
pub struct Opening {
    pub path: PathBuf,
    progress: Arc<Progress>,
    result: mpsc::Receiver<Loaded>,
}

impl Opening {
    /// Starts opening `path`; `wake` asks for a frame when it is done.
    pub fn start(path: &Path, wake: Waker) -> Opening {
        let progress = Arc::new(Progress::default());
        let (tx, result) = mpsc::channel();
        let (p, file) = (progress.clone(), path.to_path_buf());
        std::thread::spawn(move || {
            let loaded = document::open_with(&file, &p);
            // The receiver is gone when the opening was cancelled.
            let _ = tx.send(loaded);
            wake();
        });
        Opening {
            path: path.to_path_buf(),
            progress,
            result,
        }
    }

    /// The part read and parsed, in [0, 1].
    pub fn fraction(&self) -> f32 {
        self.progress.fraction() as f32
    }

    /// Asks the reader to stop; what it gives after this is dropped with the `Opening`.
    pub fn cancel(&self) {
        self.progress.cancel();
    }

    /// The document, or why there is none, once the reader is done.
    pub fn poll(&self) -> Option<Loaded> {
        match self.result.try_recv() {
            Ok(r) => Some(r),
            Err(mpsc::TryRecvError::Empty) => None,
            Err(mpsc::TryRecvError::Disconnected) => {
                Some(Err("the reading stopped without a result".into()))
            }
        }
    }

    /// The progress window: the file, a bar, and Cancel (true when pressed).
    pub fn window(&self, ctx: &egui::Context) -> bool {
        let mut cancel = false;
        let name = self.path.file_name().map_or_else(
            || self.path.display().to_string(),
            |n| n.to_string_lossy().into(),
        );
        egui::Window::new("Opening")
            .collapsible(false)
            .resizable(false)
            .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
            .show(ctx, |ui| {
                ui.label(format!("Reading {name}…"));
                ui.add(
                    egui::ProgressBar::new(self.fraction())
                        .show_percentage()
                        .desired_width(280.0),
                );
                cancel = ui
                    .button("Cancel")
                    .on_hover_text("Stop reading: the document stays as it is")
                    .clicked();
            });
        ctx.request_repaint_after(std::time::Duration::from_millis(50));
        cancel
    }
}
