//! Undo steps of continuous input in the 3D tabs (Skin, Envelope): a number field dragged, a
//! slider moved or a drag in the view is one gesture, and every edit it makes carries the
//! gesture's number so that the document coalesces them into one undo step.

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
}
