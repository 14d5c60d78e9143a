//! The scaffold the 3D tabs (Skin, Envelope) share besides their view (`view3d.rs`): the
//! layout of panel and view, the centre and scale fields, the pointer's drag — and the undo
//! steps of continuous input: a number field dragged, a slider moved or a drag in the view is
//! one gesture, and every edit it makes carries the gesture's number so that the document
//! coalesces them into one undo step.

/// The tab's gesture counter and the field whose drag is under way.
#[derive(Debug, Default, Clone, Copy)]
pub struct Gestures {
    count: u64,
    /// The gesture a field drag belongs to, while it lasts.
    active: Option<(egui::Id, u64)>,
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
    pub fn delta_field(
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

    /// The "centre" row of the 3D tabs: three number fields for `centre`; the moved centre and
    /// its gesture when one changed this frame.
    pub fn centre_field(
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

    /// The "scale %" row of the 3D tabs, acting by difference ([`Gestures::delta_field`] at
    /// rest 100 %): this frame's factor and its gesture.
    pub fn scale_field(
        &mut self,
        ui: &mut egui::Ui,
        percent: &mut f64,
    ) -> Option<(f64, Option<u64>)> {
        let mut out = None;
        ui.horizontal(|ui| {
            ui.label("scale %");
            if let Some((b, a, g)) = self.delta_field(ui, percent, 100.0, "", Some(1.0..=1000.0))
                && b > 0.0
                && a > 0.0
            {
                out = Some((a / b, g));
            }
        });
        out
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

/// The 3D tabs' layout: the tab's panel on the left (resizable, scrolling) and its view in the
/// rest; `panel` and `view` draw them with the tab.
pub fn layout<T>(
    ui: &mut egui::Ui,
    id: &'static str,
    tab: &mut T,
    panel: impl FnOnce(&mut T, &mut egui::Ui),
    view: impl FnOnce(&mut T, &mut egui::Ui),
) {
    egui::Panel::left(id)
        .resizable(true)
        .default_size(300.0)
        .show(ui, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| panel(tab, ui));
        });
    egui::CentralPanel::default().show(ui, |ui| view(tab, ui));
}
