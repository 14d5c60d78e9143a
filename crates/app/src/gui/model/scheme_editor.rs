//! The scheme picker with its parameter, used for every step of a pipeline and for the
//! step that Step >> appends. The list, the defaults, the slider ranges and scales come
//! from the scheme catalogue.

use prism_geom::scheme::{CATALOGUE, Scale, SchemeKind};
use prism_geom::{CornerRule, ReflexMode, Scheme};

/// A scheme picker with its parameter; returns the new scheme when the user changed it.
/// `name` is what screen readers (and the UI tests) call the picker.
pub fn scheme_editor(
    ui: &mut egui::Ui,
    id: impl std::hash::Hash + std::fmt::Debug,
    name: &str,
    s: &Scheme,
) -> Option<Scheme> {
    let mut out = None;
    let kind = s.kind();
    ui.horizontal(|ui| {
        let combo = egui::ComboBox::from_id_salt(id)
            .selected_text(s.name())
            .show_ui(ui, |ui| {
                for e in &CATALOGUE {
                    let r = ui
                        .selectable_label(kind == e.kind, e.name)
                        .on_hover_text(format!("{}: {} {}", e.title, e.paper, e.equation));
                    if r.clicked() && kind != e.kind {
                        out = Some(e.kind.default_scheme());
                    }
                }
            });
        combo
            .response
            .widget_info(|| egui::WidgetInfo::labeled(egui::Role::ComboBox, true, name));
        if let (Some(p), Some(value)) = (kind.entry().param, s.param()) {
            let mut x = value;
            let slider = egui::Slider::new(&mut x, p.slider.0..=p.slider.1);
            // Lengths are in model units: a logarithmic slider, and a typed value may leave
            // its range.
            let slider = match p.scale {
                // The slider ends at the repeatable bound: typing may go past it, up to the
                // admissible range, with the warning below.
                Scale::Linear if p.repeatable.is_some() => {
                    slider.clamping(egui::SliderClamping::Never)
                }
                Scale::Linear => slider,
                Scale::Logarithmic => slider
                    .logarithmic(true)
                    .clamping(egui::SliderClamping::Never),
            };
            let resp = ui
                .add(slider.text(p.symbol).max_decimals(4))
                .on_hover_text(p.meaning);
            if resp.changed() && s.with_param(x).validate().is_ok() {
                out = Some(s.with_param(x));
            }
        }
        // Seed 000's reflex-corner remark: the displacement reversed at reflex corners.
        if let Scheme::Biquadratic(CornerRule::VectorSum { alpha, reflex }) = *s {
            let mut inward = reflex == ReflexMode::Inward;
            let r = ui.checkbox(&mut inward, "reflex inward").on_hover_text(
                "reverse the displacement at reflex corners (seed 000's remark on concave faces)",
            );
            if r.changed() {
                let reflex = if inward {
                    ReflexMode::Inward
                } else {
                    ReflexMode::AsPrinted
                };
                out = Some(Scheme::Biquadratic(CornerRule::VectorSum { alpha, reflex }));
            }
        }
    });
    out
}

/// Under a step's row, on a line of its own (so that it wraps rather than widening the
/// panel): a value that cannot be repeated (vector sum above α = ¼) is admitted and named.
pub fn repeat_warning(ui: &mut egui::Ui, s: &Scheme) {
    if let (Some(w), Some(p)) = (s.repeat_warning(), s.kind().entry().param)
        && let Some((bound, _)) = p.repeatable
    {
        ui.colored_label(
            egui::Color32::from_rgb(240, 170, 60),
            format!("{} above {bound}: folds when repeated", p.symbol),
        )
        .on_hover_text(w);
    }
}

/// The step Step >> appends when the settings name none: the combination rule.
pub fn default_next() -> Scheme {
    SchemeKind::Combination.default_scheme()
}
