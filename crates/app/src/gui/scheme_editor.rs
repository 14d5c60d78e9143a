//! The scheme picker with its parameter, used for every step of a pipeline and for the
//! step that Step >> appends.

use prism_geom::scheme::{BIQUADRATIC_NAMES, PRIMAL_NAMES};
use prism_geom::{ReflexMode, Scheme};

pub fn default_param(name: &str) -> Scheme {
    let v = |x| Some(x);
    Scheme::from_name(name, v(0.2), v(0.2), v(0.1), v(0.1), ReflexMode::AsPrinted)
        .expect("known scheme with its default parameter")
}

/// The parameter of a scheme, by name and value, if it has one.
pub fn param(s: &Scheme) -> Option<(&'static str, f64)> {
    use prism_geom::CornerRule::*;
    match s {
        Scheme::Biquadratic(r) => match *r {
            DooSabin => None,
            AngleBisector { l } => Some(("l", l)),
            CutWidth { d } => Some(("d", d)),
            VectorSum { alpha, .. } => Some(("α", alpha)),
            Cylindrical { r } | Minimum { r } | Combination { r } => Some(("r", r)),
        },
        Scheme::Primal(_) => None,
    }
}

pub fn with_param(s: &Scheme, x: f64) -> Scheme {
    use prism_geom::CornerRule::*;
    match *s {
        Scheme::Biquadratic(r) => Scheme::Biquadratic(match r {
            AngleBisector { .. } => AngleBisector { l: x },
            CutWidth { .. } => CutWidth { d: x },
            VectorSum { reflex, .. } => VectorSum { alpha: x, reflex },
            Cylindrical { .. } => Cylindrical { r: x },
            Minimum { .. } => Minimum { r: x },
            Combination { .. } => Combination { r: x },
            DooSabin => DooSabin,
        }),
        p => p,
    }
}

/// A scheme picker with its parameter; returns the new scheme when the user changed it.
/// `name` is what screen readers (and the UI tests) call the picker.
pub fn scheme_editor(
    ui: &mut egui::Ui,
    id: impl std::hash::Hash + std::fmt::Debug,
    name: &str,
    s: &Scheme,
) -> Option<Scheme> {
    let mut out = None;
    ui.horizontal(|ui| {
        let combo = egui::ComboBox::from_id_salt(id)
            .selected_text(s.name())
            .show_ui(ui, |ui| {
                for n in BIQUADRATIC_NAMES.iter().chain(PRIMAL_NAMES.iter()) {
                    if ui.selectable_label(s.name() == *n, *n).clicked() && s.name() != *n {
                        out = Some(default_param(n));
                    }
                }
            });
        combo
            .response
            .widget_info(|| egui::WidgetInfo::labeled(egui::Role::ComboBox, true, name));
        if let Some((label, value)) = param(s) {
            let mut x = value;
            // α lives in (0, 1/2); lengths are in model units, so their slider is
            // logarithmic and a typed value may leave its range.
            let slider = if label == "α" {
                egui::Slider::new(&mut x, 0.001..=0.499)
            } else {
                egui::Slider::new(&mut x, 0.001..=10.0)
                    .logarithmic(true)
                    .clamping(egui::SliderClamping::Never)
            };
            let resp = ui.add(slider.text(label).max_decimals(4));
            if resp.changed() && with_param(s, x).validate().is_ok() {
                out = Some(with_param(s, x));
            }
        }
    });
    out
}
