//! How the app starts: the command line's launch options ([`Launch`], [`Show`], [`Tab`]), the
//! bundled samples, and the settings eframe remembers between runs.

use super::model::{self, Display, Tool};
use prism_geom::{EdgeKey, Scheme};
use std::path::PathBuf;

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
    /// The Envelope tab's t sweep (t = 1, 0.5, 0.1 side by side).
    TSweep,
    /// The Envelope tab: the curve network alone (the surface hidden).
    NetworkOnly,
    /// The Skin tab: the trajectories (seed 003 fig. 1).
    Trajectories,
    /// The Skin tab: the sections swept along the trajectories.
    Swept,
    /// The Skin tab: contour lines, sections of the surface by planes z = const (fig. 4b).
    Contours,
    /// The Skin tab: the twist of each pair of sections (fig. 2).
    Twists,
    /// The Curves tab: the evolute (the centres of curvature).
    Evolute,
    /// The Curves tab: no curvature comb.
    NoComb,
    /// The Skin and Envelope tabs: their curves drawn through the surface.
    Xray,
}

/// The app's tabs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Tab {
    #[default]
    Model,
    Curves,
    Skin,
    Envelope,
}

impl Tab {
    /// The tab's name as its button says it.
    pub fn name(self) -> &'static str {
        match self {
            Tab::Model => "Model",
            Tab::Curves => "Curves",
            Tab::Skin => "Skin",
            Tab::Envelope => "Envelope",
        }
    }
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
    /// Where unsaved work is copied (none: no autosave).
    pub autosave: Option<PathBuf>,
    /// Start with the clamp off (the papers' literal rules).
    pub no_clamp: bool,
}

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

/// The memory budget of a first run, MiB (the Model tab's field changes it).
pub(super) const DEFAULT_BUDGET_MIB: u64 = 4096;

/// What eframe remembers between runs.
#[derive(Debug, Clone, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct Settings {
    pub(super) display: Display,
    pub(super) tool: Tool,
    pub(super) budget_mib: u64,
    pub(super) next: String,
    pub(super) last_file: Option<PathBuf>,
    /// Files opened or saved, the latest first (File ▸ Recent).
    pub(super) recent: Vec<PathBuf>,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            display: Display::default(),
            tool: Tool::Orbit,
            budget_mib: DEFAULT_BUDGET_MIB,
            next: model::default_next().to_string(),
            last_file: None,
            recent: Vec::new(),
        }
    }
}

pub(super) const SETTINGS_KEY: &str = "prism-settings";
