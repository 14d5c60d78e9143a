//! The scaffold the 3D tabs (Skin, Envelope) share besides their view (`view3d.rs`): the
//! `Tab3d` trait (layout of panel and view, samples, edits), the placement rows (centre, turns,
//! scale), the drags in the view and what they do to points, the resolution and radio rows —
//! and the undo steps of continuous input: a number field dragged, a slider moved or a drag in the view is
//! one gesture, and every edit it makes carries the gesture's number so that the document
//! coalesces them into one undo step.

use super::command::{Command, Edit};
use super::doc_state::DocState;
use super::view3d::View3d;

/// A number field that turns a selection: its value (at rest 0), its prefix and the axis it
/// turns about.
pub type TurnField<'a> = (&'a mut f64, &'a str, glam::DVec3);

/// The tab's gesture counter and the field whose drag is under way.
#[derive(Debug, Clone, Copy)]
pub struct Gestures {
    count: u64,
    /// The gesture a field drag belongs to, while it lasts.
    active: Option<(egui::Id, u64)>,
    /// The "scale %" field's value: 100 at rest, the factor so far while it is dragged.
    scale: f64,
}

impl Default for Gestures {
    fn default() -> Self {
        Gestures {
            count: 0,
            active: None,
            scale: 100.0,
        }
    }
}

impl Gestures {
    /// A new gesture (a drag in the view starts one).
    pub fn start(&mut self) -> u64 {
        self.count += 1;
        self.count
    }

    /// The gesture id of a number field being dragged (a new one when the drag starts).
    /// Keyed by the field, so that the fields drawn after the dragged one in the same frame do
    /// not end its gesture.
    pub fn of(&mut self, r: &egui::Response) -> Option<u64> {
        let mine = self.active.filter(|(id, _)| *id == r.id).map(|(_, g)| g);
        let gesture = if r.drag_started() || (r.changed() && mine.is_none()) {
            let g = self.start();
            self.active = Some((r.id, g));
            Some(g)
        } else {
            mine
        };
        if gesture.is_some() && (r.drag_stopped() || (!r.dragged() && !r.has_focus())) {
            self.active = None;
        }
        gesture
    }

    /// A number field that acts by difference (turn, tilt, scale): returns its value before
    /// and after this frame's change and the change's gesture; when let go it falls back to
    /// `rest`.
    fn delta_field(
        &mut self,
        ui: &mut egui::Ui,
        value: &mut f64,
        rest: f64,
        prefix: &str,
        range: Option<std::ops::RangeInclusive<f64>>,
    ) -> Option<(f64, f64, Option<u64>)> {
        let before = *value;
        let mut field = egui::DragValue::new(value).speed(0.5).prefix(prefix);
        if let Some(range) = range {
            field = field.range(range);
        }
        let r = ui.add(field);
        let g = self.of(&r);
        let out = r.changed().then_some((before, *value, g));
        if !r.dragged() && !r.has_focus() {
            *value = rest;
        }
        out
    }

    /// A number field in degrees that turns about `axis` by difference ([`Gestures::delta_field`]
    /// at rest 0): this frame's turn and its gesture.
    fn turn_field(
        &mut self,
        ui: &mut egui::Ui,
        degrees: &mut f64,
        prefix: &str,
        axis: glam::DVec3,
    ) -> Option<(glam::DQuat, Option<u64>)> {
        let (before, after, g) = self.delta_field(ui, degrees, 0.0, prefix, None)?;
        Some((
            glam::DQuat::from_axis_angle(axis, (after - before).to_radians()),
            g,
        ))
    }

    /// The "centre" row of the 3D tabs: three number fields for `centre`; the moved centre and
    /// its gesture when one changed this frame.
    fn centre_field(
        &mut self,
        ui: &mut egui::Ui,
        centre: glam::DVec3,
    ) -> Option<(glam::DVec3, Option<u64>)> {
        let mut moved = centre;
        let mut changed = None;
        ui.horizontal(|ui| {
            ui.label("centre");
            for a in 0..3 {
                let r = ui.add(
                    egui::DragValue::new(&mut moved[a])
                        .speed(0.01)
                        .max_decimals(4),
                );
                let g = self.of(&r);
                if r.changed() {
                    changed = Some(g);
                }
            }
        });
        changed.map(|g| (moved, g))
    }

    /// The placement rows of a 3D tab for a selection about `centre`: the centre row, the
    /// turn rows (each a label and its fields: the field's value, at rest 0, its prefix and
    /// the axis it turns about) and the "scale %" row. The map this frame's change makes and
    /// its gesture; a turn or a scale acts about `centre`.
    pub fn placement(
        &mut self,
        ui: &mut egui::Ui,
        centre: glam::DVec3,
        turns: Vec<(&str, Vec<TurnField<'_>>)>,
    ) -> Option<(glam::DAffine3, Option<u64>)> {
        use glam::{DAffine3, DQuat, DVec3};
        let about = |q: DQuat, f: f64| {
            DAffine3::from_translation(centre)
                * DAffine3::from_scale_rotation_translation(DVec3::splat(f), q, DVec3::ZERO)
                * DAffine3::from_translation(-centre)
        };
        let mut out = self
            .centre_field(ui, centre)
            .map(|(moved, g)| (DAffine3::from_translation(moved - centre), g));
        for (label, fields) in turns {
            ui.horizontal(|ui| {
                ui.label(label);
                for (degrees, prefix, axis) in fields {
                    if let Some((q, g)) = self.turn_field(ui, degrees, prefix, axis) {
                        out = Some((about(q, 1.0), g));
                    }
                }
            });
        }
        if let Some((f, g)) = self.scale_field(ui) {
            out = Some((about(DQuat::IDENTITY, f), g));
        }
        out
    }

    /// The "scale %" row of the 3D tabs, acting by difference ([`Gestures::delta_field`] at
    /// rest 100 %): this frame's factor and its gesture.
    fn scale_field(&mut self, ui: &mut egui::Ui) -> Option<(f64, Option<u64>)> {
        let mut out = None;
        let mut percent = self.scale;
        ui.horizontal(|ui| {
            ui.label("scale %");
            if let Some((b, a, g)) =
                self.delta_field(ui, &mut percent, 100.0, "", Some(1.0..=1000.0))
                && b > 0.0
                && a > 0.0
            {
                out = Some((a / b, g));
            }
        });
        self.scale = percent;
        out
    }
}

/// A primary drag in a 3D view that edits the tab's part. On the press it begins with what
/// `begin` says it starts from (`None`: nothing to drag) and a new gesture; on each frame of
/// the drag it answers the gesture, the start and how far the pointer has gone; released, it
/// ends.
pub fn view_drag<T: Clone>(
    state: &mut Option<(u64, T)>,
    gestures: &mut Gestures,
    ui: &egui::Ui,
    resp: &egui::Response,
    begin: impl FnOnce() -> Option<T>,
) -> Option<(u64, T, egui::Vec2)> {
    if resp.drag_started_by(egui::PointerButton::Primary) {
        *state = begin().map(|t| (gestures.start(), t));
    }
    let out = resp
        .dragged_by(egui::PointerButton::Primary)
        .then(|| state.clone().map(|(g, t)| (g, t, drag_total(ui))))
        .flatten();
    if resp.drag_stopped() {
        *state = None;
    }
    out
}

/// What a primary drag in a 3D view does: orbit the camera, or move, turn (the Skin tab's
/// sections, in their plane) or scale what is selected; the secondary button orbits then.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mouse {
    #[default]
    Orbit,
    Move,
    Turn,
    Scale,
}

impl Mouse {
    /// The "Drag in the view" row: `choices` (orbit first), with `hover` on the row.
    pub fn row(&mut self, ui: &mut egui::Ui, choices: &[Mouse], hover: &str) {
        ui.horizontal_wrapped(|ui| {
            ui.label("Drag in the view:");
            for &m in choices {
                ui.radio_value(self, m, m.name());
            }
        })
        .response
        .on_hover_text(hover);
    }

    pub fn name(self) -> &'static str {
        match self {
            Mouse::Orbit => "orbit",
            Mouse::Move => "move",
            Mouse::Turn => "turn",
            Mouse::Scale => "scale",
        }
    }

    /// What the drag does to the selection's points (`axis`: what a turn turns about); `None`
    /// when it orbits.
    pub fn points_drag(self, axis: glam::DVec3) -> Option<PointsDrag> {
        match self {
            Mouse::Orbit => None,
            Mouse::Move => Some(PointsDrag::Slide),
            Mouse::Turn => Some(PointsDrag::Turn(axis)),
            Mouse::Scale => Some(PointsDrag::Scale),
        }
    }

    /// The line of help at the view's foot: `orbit` when it orbits, else what the drag does
    /// to the selected `what`.
    pub fn hint(self, what: &str, orbit: &str) -> String {
        match self {
            Mouse::Orbit => orbit.to_string(),
            Mouse::Move => {
                format!("drag: move the selected {what} in the view plane · right drag: orbit")
            }
            Mouse::Turn => {
                format!("drag sideways: turn the selected {what} in its plane · right drag: orbit")
            }
            Mouse::Scale => {
                format!("drag up or down: scale the selected {what} · right drag: orbit")
            }
        }
    }
}

/// What a drag in a 3D view does to the points it holds.
#[derive(Debug, Clone, Copy)]
pub enum PointsDrag {
    /// Slides them in the view plane with the pointer.
    Slide,
    /// Turns them about the axis through their centre, 0.01 radian a point sideways.
    Turn(glam::DVec3),
    /// Scales them about their centre ([`drag_scale`]).
    Scale,
}

/// The points `start` (about their mean) after a drag of `total` points in a view `height`
/// points high seen by `camera`.
pub fn dragged_points(
    how: PointsDrag,
    camera: &prism_viewport::Camera,
    (total, height): (egui::Vec2, f32),
    start: &[glam::DVec3],
) -> Vec<glam::DVec3> {
    let centre = start.iter().sum::<glam::DVec3>() / start.len().max(1) as f64;
    match how {
        PointsDrag::Slide => {
            let by = camera
                .drag_in_view_plane(total.x, total.y, height)
                .as_dvec3();
            start.iter().map(|p| *p + by).collect()
        }
        PointsDrag::Turn(axis) => {
            let q = glam::DQuat::from_axis_angle(axis, (total.x as f64 * 0.01).clamp(-10.0, 10.0));
            start.iter().map(|p| centre + q * (*p - centre)).collect()
        }
        PointsDrag::Scale => {
            let f = drag_scale(total);
            start.iter().map(|p| centre + (*p - centre) * f).collect()
        }
    }
}

/// How far the pointer has been dragged since the press, in points.
pub fn drag_total(ui: &egui::Ui) -> egui::Vec2 {
    ui.input(|i| i.pointer.press_origin().zip(i.pointer.latest_pos()))
        .map_or(egui::Vec2::ZERO, |(a, b)| b - a)
}

/// The factor a scaling drag of `total` gives: up grows, down shrinks, by e per 200 points.
pub fn drag_scale(total: egui::Vec2) -> f64 {
    (-total.y as f64 * 0.005).exp()
}

/// What every 3D tab holds besides its own state.
pub struct Base {
    pub view: View3d,
    pub gestures: Gestures,
    /// The commands gathered this frame.
    pub out: Vec<Command>,
}

impl Base {
    /// With its view in view slot `slot` (the Model tab's views use 0–3).
    pub fn new(slot: usize) -> Base {
        Base {
            view: View3d::new(slot),
            gestures: Gestures::default(),
            out: Vec::new(),
        }
    }
}

/// A 3D tab (Skin, Envelope) as the scaffold sees it: its part of the document, the edit that
/// sets it, its panel and its view. The scaffold lays them out and gathers the commands.
pub trait Tab3d {
    type Spec: Clone + serde::de::DeserializeOwned;
    /// The id of the tab's side panel.
    const PANEL: &'static str;
    /// Rebuilds what the tab shows when `spec` changed.
    fn sync(&mut self, spec: Option<&Self::Spec>);
    fn panel(&mut self, ui: &mut egui::Ui, spec: Option<&Self::Spec>);
    fn view(&mut self, ui: &mut egui::Ui, spec: Option<&Self::Spec>);
    /// What every 3D tab holds: its view, gestures and commands.
    fn base(&mut self) -> &mut Base;
    /// The bundled samples: name, file, what each shows.
    const SAMPLES: &'static [(&'static str, &'static str, &'static str)];

    /// The tab's part of the document.
    fn part(doc: &DocState) -> Option<&Self::Spec>;
    /// The last build's mesh, or why there is none (what the build refused, or no input).
    fn surface(&self) -> Result<&prism_geom::PolyMesh, &str>;
    /// The edit that makes `spec` the document's, coalesced with the others of `gesture`.
    fn edit(spec: Option<Self::Spec>, gesture: Option<u64>) -> Edit;

    /// The commands gathered this frame.
    fn out(&mut self) -> &mut Vec<Command> {
        &mut self.base().out
    }

    /// Frames the view again on the next frame (a new sample or document).
    fn reframe(&mut self) {
        self.base().view.reframe();
    }

    /// Makes `spec` the document's (one undo step per gesture).
    fn set(&mut self, spec: Option<Self::Spec>, gesture: Option<u64>) {
        let edit = Self::edit(spec, gesture);
        self.out().push(Command::Edit(edit));
    }

    /// Bundled sample `k`, read from its text.
    fn sample(k: usize) -> Result<Self::Spec, String> {
        let (name, _, text) = Self::SAMPLES.get(k).ok_or("no such sample")?;
        serde_json::from_str(text).map_err(|e| format!("{name}: {e}"))
    }

    /// Opens bundled sample `k` in the tab, framed: its name, or why it cannot be read.
    fn open_sample(&mut self, k: usize) -> Result<&'static str, String> {
        let spec = Self::sample(k)?;
        self.reframe();
        self.set(Some(spec), None);
        Ok(Self::SAMPLES[k].0)
    }

    /// A button for each bundled sample, opening it.
    fn sample_buttons(&mut self, ui: &mut egui::Ui) {
        for (k, (name, _, _)) in Self::SAMPLES.iter().enumerate() {
            if ui.button(*name).clicked()
                && let Err(e) = self.open_sample(k)
            {
                self.out().push(Command::Say(e));
            }
        }
    }

    /// Makes `spec` with `put` applied the document's, when `changed` (a control moved).
    fn set_changed(
        &mut self,
        spec: &Self::Spec,
        changed: bool,
        put: impl FnOnce(&mut Self::Spec),
        gesture: Option<u64>,
    ) {
        if changed {
            let mut s = spec.clone();
            put(&mut s);
            self.set(Some(s), gesture);
        }
    }

    /// The tab's panel on the left (resizable, scrolling) and its view in the rest, after a
    /// sync with its part of `doc`; the commands of this frame.
    fn ui(&mut self, ui: &mut egui::Ui, doc: &DocState) -> Vec<Command> {
        let spec = Self::part(doc);
        self.sync(spec);
        if let Some(v) = super::viewport::standard_view_key(ui.ctx()) {
            self.base().view.camera.turn_to(v);
        }
        if !super::viewport::full_view(ui.ctx()) {
            egui::Panel::left(Self::PANEL)
                .resizable(true)
                .default_size(300.0)
                .size_range(super::model::SIDE_PANEL)
                .show(ui, |ui| {
                    egui::ScrollArea::vertical().show(ui, |ui| self.panel(ui, spec));
                });
        }
        egui::CentralPanel::default().show(ui, |ui| self.view(ui, spec));
        std::mem::take(self.out())
    }
}

/// The 3D tabs' resolution slider, 1 to 32 (a document's own larger value, which the CLI
/// takes up to 256, is kept until the slider moves).
pub fn resolution_slider(ui: &mut egui::Ui, res: &mut usize, text: &str) -> egui::Response {
    ui.add(
        egui::Slider::new(res, 1..=32)
            .clamping(egui::SliderClamping::Edits)
            .text(text),
    )
}

/// A row of radio buttons after `label`: each choice a value, its name and what it means.
pub fn radio_row<T: PartialEq + Copy>(
    ui: &mut egui::Ui,
    label: &str,
    value: &mut T,
    choices: &[(T, &str, &str)],
) {
    ui.horizontal(|ui| {
        if !label.is_empty() {
            ui.label(label);
        }
        for &(v, name, hover) in choices {
            ui.radio_value(value, v, name).on_hover_text(hover);
        }
    });
}

/// The 3D tabs' "G1 basis" row: the virtual basis (the default) or the paper's one-sided one,
/// each with what it means in the tab.
pub fn basis_row(
    ui: &mut egui::Ui,
    basis: &mut prism_geom::freeform::Basis,
    [virtual_hover, one_sided_hover]: [&str; 2],
) {
    use prism_geom::freeform::Basis;
    let choices = [
        (Basis::Virtual, "virtual", virtual_hover),
        (Basis::OneSided, "one-sided (paper)", one_sided_hover),
    ];
    radio_row(ui, "G1 basis", basis, &choices);
}
