//! `--show` values and the paper figures' overlays set on the tabs they concern: the one place
//! that knows every tab's options (launch.rs, which the tabs read, stays below them).

use super::launch::Show;

/// One `--show` value (or a paper figure's overlay) set on the tabs it concerns.
pub(super) fn apply_show(
    s: Show,
    display: &mut super::model::Display,
    envelope: &mut super::envelope::EnvelopeTab,
    skin: &mut super::skin::SkinTab,
    curves: &mut super::curves::CurvesTab,
) {
    use super::model::Coloring;
    match s {
        Show::Smooth => display.smooth = true,
        Show::Wireframe => display.wireframe = true,
        Show::Kinds => display.color = Coloring::Kind,
        Show::Curvature => display.color = Coloring::Curvature,
        Show::Schemes => display.color = Coloring::Scheme,
        Show::Cage => display.cage = true,
        Show::Corners => display.corners = true,
        Show::Limit => display.limit = true,
        Show::TSweep => envelope.sweep = true,
        Show::NetworkOnly => envelope.overlays.surface = false,
        Show::Trajectories => skin.overlays.trajectories = true,
        Show::Swept => skin.overlays.swept = true,
        Show::Contours => skin.overlays.contours = true,
        Show::Twists => skin.overlays.twists = true,
        Show::Evolute => curves.evolute = true,
        Show::NoComb => curves.comb = false,
        Show::Xray => {
            skin.overlays.look.xray = true;
            envelope.overlays.look.xray = true;
        }
    }
}

impl super::PrismApp {
    /// `show`'s values set on the tabs ([`apply_show`]).
    pub(super) fn show(&mut self, show: &[Show]) {
        for &s in show {
            apply_show(
                s,
                &mut self.model.display,
                &mut self.envelope,
                &mut self.skin,
                &mut self.curves,
            );
        }
    }
}
