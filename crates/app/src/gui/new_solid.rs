//! File ▸ New solid…: a box, a prism or pyramid over a regular n-gon, a tripod, or the
//! Curves tab's polygon extruded (its control polygon or the refined curve, concave allowed,
//! with an optional hole: the outline scaled about its centroid). The window only gathers
//! the parameters; [`prism_geom::solid::Solid::build`] checks them and names what is wrong.

use super::command::Command;
use glam::DVec2;
use prism_geom::curve::CurveSketch;
use prism_geom::solid::{MAX_SIDES, Solid, SolidParams};

/// Which solid the window makes.
pub use prism_geom::solid::SolidKind as Kind;

/// The window's state: open or not, and the parameters of every kind (kept between uses).
pub struct NewSolid {
    pub open: bool,
    pub kind: Kind,
    pub params: SolidParams,
    /// Extrude the refined curve (else the control polygon).
    pub refined: bool,
    pub hole: bool,
    pub hole_scale: f64,
    /// Why the last "Create" made nothing.
    pub error: Option<String>,
}

impl Default for NewSolid {
    fn default() -> Self {
        NewSolid {
            open: false,
            kind: Kind::Box,
            params: SolidParams::default(),
            refined: false,
            hole: false,
            hole_scale: 0.5,
            error: None,
        }
    }
}

impl NewSolid {
    /// The solid the parameters describe (the sketch gives the extrusion's outline).
    pub fn solid(&self, sketch: &CurveSketch) -> Result<Solid, String> {
        self.params.solid(self.kind, || {
            if !sketch.control.closed {
                return Err(
                    "the sketch is open: close it on the Curves tab (\"closed\") to extrude it"
                        .to_string(),
                );
            }
            let outline: Vec<DVec2> = if self.refined {
                sketch
                    .control
                    .refine_levels(sketch.scheme, sketch.levels)
                    .map_err(|e| e.to_string())?
                    .points
            } else {
                sketch.control.points.clone()
            };
            Ok((outline, self.hole.then_some(self.hole_scale)))
        })
    }

    /// The window, when open; "Create" gives the command that makes the solid the
    /// document.
    pub fn window(&mut self, ctx: &egui::Context, sketch: &CurveSketch) -> Option<Command> {
        let mut out = None;
        let mut open = self.open;
        egui::Window::new("New solid")
            .open(&mut open)
            .resizable(false)
            .collapsible(false)
            .show(ctx, |ui| {
                ui.horizontal(|ui| {
                    for (k, name) in [
                        (Kind::Box, "box"),
                        (Kind::Prism, "prism"),
                        (Kind::Pyramid, "pyramid"),
                        (Kind::Tripod, "tripod"),
                        (Kind::Extrusion, "extrude the sketch"),
                    ] {
                        ui.selectable_value(&mut self.kind, k, name);
                    }
                });
                let len = |ui: &mut egui::Ui, x: &mut f64, name: &str| {
                    ui.horizontal(|ui| {
                        ui.label(name);
                        ui.add(egui::DragValue::new(x).speed(0.01).range(1e-3..=1e4));
                    });
                };
                match self.kind {
                    Kind::Box => {
                        for (i, name) in ["width", "depth", "height"].into_iter().enumerate() {
                            len(ui, &mut self.params.size[i], name);
                        }
                    }
                    Kind::Prism | Kind::Pyramid => {
                        ui.horizontal(|ui| {
                            ui.label("sides");
                            ui.add(
                                egui::DragValue::new(&mut self.params.sides).range(3..=MAX_SIDES),
                            );
                        });
                        len(ui, &mut self.params.radius, "circumradius");
                        len(ui, &mut self.params.height, "height");
                    }
                    Kind::Tripod => {
                        len(ui, &mut self.params.arm, "arm length");
                        len(ui, &mut self.params.width, "arm width");
                    }
                    Kind::Extrusion => {
                        ui.label(format!(
                            "The Curves tab's {} polygon of {} points, extruded along z.",
                            if sketch.control.closed {
                                "closed"
                            } else {
                                "open"
                            },
                            sketch.control.points.len()
                        ));
                        ui.checkbox(
                            &mut self.refined,
                            "the refined curve (else the control polygon)",
                        );
                        len(ui, &mut self.params.height, "height");
                        ui.horizontal(|ui| {
                            ui.checkbox(&mut self.hole, "hole: the outline scaled by");
                            ui.add_enabled(
                                self.hole,
                                egui::DragValue::new(&mut self.hole_scale)
                                    .speed(0.01)
                                    .range(0.01..=0.99),
                            )
                            .on_disabled_hover_text("Tick hole to cut one");
                        });
                    }
                }
                ui.label(
                    "It replaces the model (Ctrl+Z brings the old one back); the pipeline stays.",
                );
                if ui.button("Create").clicked() {
                    // Checked here so that a bad outline keeps the window open, named.
                    match self.solid(sketch).and_then(|s| {
                        s.build().map_err(|e| e.to_string())?;
                        Ok(s)
                    }) {
                        Ok(s) => {
                            self.error = None;
                            out = Some(Command::NewSolid(s));
                        }
                        Err(e) => self.error = Some(e),
                    }
                }
                if let Some(e) = &self.error {
                    ui.colored_label(egui::Color32::from_rgb(240, 110, 90), e);
                }
            });
        self.open = open && out.is_none();
        out
    }
}
