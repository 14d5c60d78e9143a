//! Help ▸ Paper figures: the papers' figures that are a state of the app, each opened as it
//! is shown in docs/figures.md — the tab, the bundled input, the steps, the overlays — so that
//! a teacher can project it and then play with it. The seed 000 figures turn the clamp off
//! (the paper's literal rules, marked so in the panel).

use super::PrismApp;
use super::command::{Command, Edit};
use super::launch::{Show, Tab};

/// What a figure opens.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Opens {
    /// Bundled solid `sample` (File ▸ Samples) through `pipeline`, level `level` shown (the
    /// last when `None`), with `show`'s display options; `literal` turns the clamp off.
    Model {
        sample: usize,
        pipeline: &'static str,
        level: Option<usize>,
        show: &'static [Show],
        literal: bool,
    },
    /// Bundled skin `sample` on the Skin tab with `show`'s overlays.
    Skin {
        sample: usize,
        show: &'static [Show],
    },
    /// Bundled envelope scene `sample` on the Envelope tab with `show`'s overlays.
    Envelope {
        sample: usize,
        show: &'static [Show],
    },
}

/// One entry of the menu: the paper and figure, its caption, what it opens.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PaperFigure {
    pub id: &'static str,
    pub caption: &'static str,
    pub opens: Opens,
}

const fn model(
    id: &'static str,
    caption: &'static str,
    sample: usize,
    pipeline: &'static str,
    show: &'static [Show],
) -> PaperFigure {
    PaperFigure {
        id,
        caption,
        opens: Opens::Model {
            sample,
            pipeline,
            level: None,
            show,
            literal: true,
        },
    }
}

/// The samples' places in File ▸ Samples ([`super::SAMPLES_FILES`]).
const TRIPOD: usize = 0;
const CUBE: usize = 1;
const RIM: usize = 4;
const ROOM: usize = 5;

/// Every figure the app opens, in the papers' order (docs/figures.md has all 50).
pub const FIGURES: &[PaperFigure] = &[
    model(
        "000 fig. 1",
        "New vertices and the three kinds of faces",
        CUBE,
        "doo-sabin",
        &[Show::Kinds, Show::Cage],
    ),
    model(
        "000 fig. 2",
        "Doo–Sabin subdivision of the tripod",
        TRIPOD,
        "doo-sabin,doo-sabin,doo-sabin",
        &[],
    ),
    model(
        "000 fig. 3",
        "Angle-bisector chamfer (l = 0.2)",
        TRIPOD,
        "angle-bisector:l=0.2",
        &[Show::Cage],
    ),
    model(
        "000 fig. 4",
        "Cut-width chamfer (d = 0.2)",
        TRIPOD,
        "cut-width:d=0.2",
        &[Show::Cage],
    ),
    model(
        "000 fig. 5",
        "Vector-sum chamfer (α = 0.2)",
        TRIPOD,
        "vector-sum:alpha=0.2",
        &[Show::Cage],
    ),
    model(
        "000 fig. 6",
        "Vector-sum subdivision, α = 0.2",
        TRIPOD,
        "vector-sum:alpha=0.2,vector-sum:alpha=0.2,vector-sum:alpha=0.2",
        &[],
    ),
    model(
        "000 fig. 7",
        "A vector sum (α = 0.1), then Doo–Sabin",
        TRIPOD,
        "vector-sum:alpha=0.1,doo-sabin,doo-sabin,doo-sabin",
        &[],
    ),
    model(
        "000 fig. 9",
        "Simple cylindrical type's new vertices",
        TRIPOD,
        "cylindrical:r=0.2",
        &[Show::Kinds, Show::Cage],
    ),
    model(
        "000 fig. 10",
        "Faces turn over (simple cylindrical ×4)",
        CUBE,
        "cylindrical:r=0.45,cylindrical:r=0.45,cylindrical:r=0.45,cylindrical:r=0.45",
        &[Show::Wireframe],
    ),
    model(
        "000 fig. 11",
        "Minimum type's new vertices",
        TRIPOD,
        "minimum:r=0.2",
        &[Show::Cage],
    ),
    model(
        "000 fig. 12",
        "Minimum-type subdivision",
        TRIPOD,
        "minimum:r=0.2,minimum:r=0.2,minimum:r=0.2,minimum:r=0.2",
        &[],
    ),
    model(
        "000 fig. 13",
        "Combination (case-split) subdivision",
        TRIPOD,
        "combination:r=0.2,combination:r=0.2,combination:r=0.2,combination:r=0.2",
        &[Show::Kinds],
    ),
    model(
        "000 fig. 14",
        "Shaded tripod",
        TRIPOD,
        "combination:r=0.2,combination:r=0.2,combination:r=0.2,combination:r=0.2,combination:r=0.2",
        &[Show::Smooth],
    ),
    model(
        "000 fig. 15",
        "The computer room rounded",
        ROOM,
        "combination:r=0.15,combination:r=0.15,combination:r=0.15",
        &[Show::Smooth],
    ),
    PaperFigure {
        id: "001 fig. 3",
        caption: "Subdivision of smooth parts",
        opens: Opens::Model {
            sample: CUBE,
            pipeline: "catmull-clark,catmull-clark,catmull-clark",
            level: None,
            show: &[Show::Cage],
            literal: false,
        },
    },
    PaperFigure {
        id: "001 fig. 4",
        caption: "Subdivision of sharp parts (a creased rim)",
        opens: Opens::Model {
            sample: RIM,
            pipeline: "catmull-clark-circle,catmull-clark-circle,catmull-clark-circle",
            level: None,
            show: &[Show::Smooth],
            literal: false,
        },
    },
    PaperFigure {
        id: "003 fig. 1",
        caption: "Sweep along a virtual trajectory",
        opens: Opens::Skin {
            sample: 0,
            show: &[Show::Trajectories, Show::Xray],
        },
    },
    PaperFigure {
        id: "003 fig. 4",
        caption: "Spout from six sections, as contours",
        opens: Opens::Skin {
            sample: 0,
            show: &[Show::Contours],
        },
    },
    PaperFigure {
        id: "003 fig. 5",
        caption: "Wing from four sections",
        opens: Opens::Skin {
            sample: 1,
            show: &[],
        },
    },
    PaperFigure {
        id: "003 fig. 6",
        caption: "Wing with its sections pitched",
        opens: Opens::Skin {
            sample: 2,
            show: &[],
        },
    },
    PaperFigure {
        id: "004 fig. 4",
        caption: "The curve network of two cubes",
        opens: Opens::Envelope {
            sample: 2,
            show: &[Show::NetworkOnly],
        },
    },
    PaperFigure {
        id: "004 Table 1",
        caption: "One cube, the parameter t",
        opens: Opens::Envelope {
            sample: 0,
            show: &[Show::TSweep],
        },
    },
    PaperFigure {
        id: "004 Table 2",
        caption: "Seven primitives",
        opens: Opens::Envelope {
            sample: 4,
            show: &[],
        },
    },
];

impl PrismApp {
    /// Opens figure `k` of [`FIGURES`]: its input as a new document (undoable like any open),
    /// its steps, level, tab and display options.
    pub fn open_figure(&mut self, k: usize) {
        let Some(fig) = FIGURES.get(k).copied() else {
            return;
        };
        match fig.opens {
            Opens::Model {
                sample,
                pipeline,
                level,
                show,
                literal,
            } => {
                self.run(Command::OpenSample(sample));
                let steps = prism_geom::parse_pipeline(pipeline).expect("a figure's pipeline");
                let n = steps.len();
                self.model.set_clamp(!literal);
                self.model.display = super::model::Display {
                    wireframe: false,
                    ..Default::default()
                };
                self.model.tool = super::model::Tool::Orbit;
                self.show(show);
                self.run(Command::Edit(Edit::SetPipeline { view: 0, steps }));
                self.model.views[0].level = level.unwrap_or(n);
                self.tab = Tab::Model;
            }
            Opens::Skin { sample, show } => {
                self.run(Command::OpenSkinSample(sample));
                self.skin.overlays = Default::default();
                self.show(show);
            }
            Opens::Envelope { sample, show } => {
                self.run(Command::OpenEnvelopeSample(sample));
                self.envelope.overlays = Default::default();
                self.envelope.sweep = false;
                self.show(show);
            }
        }
        self.say(format!(
            "opened seed {}: {} (docs/figures.md)",
            fig.id, fig.caption
        ));
    }
}
