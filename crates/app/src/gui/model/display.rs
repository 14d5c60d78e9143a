//! How the Model tab's views look and what the mouse does in them: [`Tool`], [`Coloring`],
//! [`Display`] (remembered between runs).

use prism_viewport::{ColorBy, SceneOptions, Shading};

/// The tool the primary mouse button uses in the views.
#[derive(
    Debug,
    Clone,
    Copy,
    PartialEq,
    Eq,
    Hash,
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
    /// Click points on the surface of the level shown: two give their distance, three the
    /// radius of the circle through them.
    Measure,
}

/// How faces are coloured.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
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
#[derive(Debug, Clone, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct Display {
    pub smooth: bool,
    pub wireframe: bool,
    /// Face colours.
    pub color: Coloring,
    pub cage: bool,
    pub corners: bool,
    pub limit: bool,
    /// A section plane through the shown level ([`Section`]); none draws it whole.
    #[serde(default)]
    pub section: Option<Section>,
}

/// A section plane normal to an axis, where along the level's box it lies in thousandths
/// (whole numbers, so that the display options stay hashable), and which side is kept.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct Section {
    /// 0 x, 1 y, 2 z.
    pub axis: u8,
    /// 0 to 1000.
    pub permille: u16,
    /// Keep the part beyond the plane rather than before it.
    pub above: bool,
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
            section: None,
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
            section: self.section.map(|s| prism_viewport::SectionPlane {
                axis: usize::from(s.axis),
                at: f64::from(s.permille.min(1000)) / 1000.0,
                flip: s.above,
            }),
            ..SceneOptions::default()
        }
    }
}
