//! The Skin tab (seed 003; docs/algorithms/skin.md, docs/user-guide.md "The Skin tab"): the
//! sections listed, added, deleted, reordered, moved, turned, tilted and scaled by typed or
//! dragged numbers, their points edited in their own plane; the G1 skin through them rebuilt
//! live on a worker thread, the last skin shown until the next is ready ([`super::latest`]),
//! with the paper's teaching pictures on request (trajectories, swept sections, the chosen
//! chains). A skin whose mesh would not fit the memory budget is refused before it is
//! tessellated. Every change is one [`Edit::SetSkin`]; a drag of one number is one undo step.

mod build;
mod section;

use super::command::Edit;
use super::doc_state::DocState;
pub use super::gestures::Mouse;
use super::gestures::{self, Base, Tab3d, dragged_points};
use super::latest::{BUILD_WAIT, Latest};
use super::view3d::View3d;
use build::{Built, Overlays};
use glam::DVec3;
use prism_geom::freeform::{Pairing, SectionInput, SkinSpec};

/// The bundled section sets: name, file name, contents.
pub const SKIN_SAMPLES: [(&str, &str, &str); 3] = [
    (
        "Spout (6 sections)",
        "spout.skin.json",
        include_str!("../../../../../assets/spout.skin.json"),
    ),
    (
        "Wing (4 sections)",
        "wing.skin.json",
        include_str!("../../../../../assets/wing.skin.json"),
    ),
    (
        "Wing moved and pitched",
        "wing-pitched.skin.json",
        include_str!("../../../../../assets/wing-pitched.skin.json"),
    ),
];

/// The view slot of the Skin tab's 3D view (the Model tab's views use 0–3).
const VIEW_SLOT: usize = 16;

/// Transient values of the number fields that act by difference (turn, tilt; the scale's is in `Gestures`).
#[derive(Debug, Default, Clone, Copy)]
struct Gesture {
    turn: f64,
    tilt_x: f64,
    tilt_y: f64,
}

pub struct SkinTab {
    pub selected: usize,
    pub mouse: Mouse,
    /// The drag under way: its gesture, the section and its points when it began.
    drag: Option<(u64, (usize, Vec<DVec3>))>,
    pub overlays: Overlays,
    /// The view, the gesture counter and this frame's commands.
    pub base: Base,
    /// The memory the skin may take (the Model tab's budget), bytes.
    pub budget: u64,
    built: Option<Built>,
    builds: Latest<(SkinSpec, u64), Built>,
    shown: Option<(usize, Overlays)>,
    gesture: Gesture,
}

impl Default for SkinTab {
    fn default() -> Self {
        SkinTab {
            selected: 0,
            mouse: Mouse::Orbit,
            drag: None,
            overlays: Overlays::default(),
            base: Base::new(VIEW_SLOT),
            budget: super::launch::DEFAULT_BUDGET_MIB << 20,
            built: None,
            builds: Latest::new(Built::new),
            shown: None,
            gesture: Gesture::default(),
        }
    }
}

/// The unit normal and in-plane frame of a section's points (Newell), and their mean.
fn frame(points: &[DVec3]) -> (DVec3, DVec3, DVec3, DVec3) {
    let n = points.len().max(1);
    let mean = points.iter().sum::<DVec3>() / n as f64;
    let mut newell = DVec3::ZERO;
    for i in 0..points.len() {
        newell += (points[i] - mean).cross(points[(i + 1) % points.len()] - mean);
    }
    let normal = newell.normalize_or(DVec3::Z);
    let x = (points.first().copied().unwrap_or(DVec3::X) - mean)
        .reject_from(normal)
        .normalize_or(normal.any_orthonormal_vector());
    (mean, normal, x, normal.cross(x))
}

impl SkinTab {
    /// Whether a build or the crossing check of the last one is under way.
    pub fn checking(&self) -> bool {
        self.builds.busy() || self.built.as_ref().is_some_and(|b| b.crossings().is_none())
    }

    /// The last build (for the tests).
    #[cfg(test)]
    pub fn built(&self) -> Option<&Built> {
        self.built.as_ref()
    }

    fn summary(&mut self, ui: &mut egui::Ui) {
        super::latest::progress_row(ui, &mut self.builds, self.built.is_some());
        let Some(b) = &self.built else { return };
        match &b.result {
            Ok((s, m)) => {
                ui.label(format!(
                    "{} sections × {} points, {} patches, {} quads; {} inserted, {} crease chain(s)",
                    s.sections.len(),
                    s.points_per_section(),
                    s.patches.len(),
                    m.num_faces(),
                    s.inserted.iter().sum::<usize>(),
                    s.creases()
                ));
                let paired = s.paired_by();
                let pairs: Vec<String> = s
                    .pairs()
                    .map(|(k, sh, t)| format!("{k}–{}: shift {sh}, twist {t:.1}°", k + 1))
                    .collect();
                ui.label(format!("Paired {paired}: {}", pairs.join("; ")));
                ui.label(format!(
                    "G1: largest normal jump across patch borders {:.1e}°; built in {:.1} ms",
                    b.jump, b.millis
                ));
                let warn = egui::Color32::from_rgb(255, 170, 90);
                match b.crossings().map(|c| c.warning()) {
                    Some(Some(w)) => {
                        ui.colored_label(warn, format!("Crossings (red crosses): {w}"));
                    }
                    Some(None) => {
                        ui.label("Crossings: none");
                    }
                    None => {
                        ui.label(egui::RichText::new("Crossings: checking…").weak());
                        ui.ctx()
                            .request_repaint_after(std::time::Duration::from_millis(30));
                    }
                }
                for note in s.notes() {
                    ui.colored_label(warn, note);
                }
            }
            Err(e) => {
                ui.colored_label(
                    egui::Color32::from_rgb(255, 120, 100),
                    format!("No skin: {e}"),
                );
            }
        }
    }

    /// A primary drag that moves, turns or scales the selected section (one undo step).
    fn section_drag(
        &mut self,
        ui: &egui::Ui,
        resp: &egui::Response,
        rect: egui::Rect,
        spec: &SkinSpec,
    ) {
        let k = self.selected;
        let begin = || Some((k, spec.sections.get(k)?.points.clone()));
        let Some((g, (section, start), total)) =
            gestures::view_drag(&mut self.drag, &mut self.base.gestures, ui, resp, begin)
        else {
            return;
        };
        if section >= spec.sections.len() {
            return;
        }
        let (_, normal, _, _) = frame(&start);
        let Some(how) = self.mouse.points_drag(normal) else {
            return;
        };
        let mut s = spec.clone();
        let camera = &self.base.view.camera;
        s.sections[section].points = dragged_points(how, camera, (total, rect.height()), &start);
        self.set(Some(s), Some(g));
    }
}

impl Tab3d for SkinTab {
    type Spec = SkinSpec;
    const SAMPLES: &'static [(&'static str, &'static str, &'static str)] = &SKIN_SAMPLES;
    const PANEL: &'static str = "skin_panel";

    /// Rebuilds the skin and the scenes when the sections or the overlays changed.
    fn sync(&mut self, spec: Option<&SkinSpec>) {
        let Some(spec) = spec else {
            self.built = None;
            self.builds.clear();
            self.base.view.clear();
            self.shown = None;
            return;
        };
        let fresh = if self
            .built
            .as_ref()
            .is_some_and(|b| &b.spec == spec && b.budget == self.budget)
        {
            self.builds.clear();
            false
        } else if let Some(b) = self.builds.want(&(spec.clone(), self.budget), BUILD_WAIT) {
            self.built = Some(b);
            true
        } else {
            false
        };
        if self.built.is_none() {
            return;
        }
        // The crossings' marks join the overlay when the check's answer comes.
        let checked = self.built.as_mut().is_some_and(|b| b.poll_crossings());
        self.selected = self.selected.min(spec.sections.len().saturating_sub(1));
        if fresh || checked || self.shown != Some((self.selected, self.overlays)) {
            let b = self.built.as_ref().expect("built above");
            self.base
                .view
                .show(build::scenes(b, self.selected, &self.overlays));
            self.shown = Some((self.selected, self.overlays));
        }
    }

    fn base(&mut self) -> &mut Base {
        &mut self.base
    }

    fn panel(&mut self, ui: &mut egui::Ui, spec: Option<&SkinSpec>) {
        ui.heading("Skin through sections");
        let Some(spec) = spec else {
            ui.label("No sections yet. Start from a sample (also in File > Samples):");
            self.sample_buttons(ui);
            if ui.button("Two circles").clicked() {
                let circle = |z: f64, r: f64| SectionInput {
                    points: (0..8)
                        .map(|i| {
                            let t = i as f64 * std::f64::consts::TAU / 8.0;
                            DVec3::new(r * t.cos(), r * t.sin(), z)
                        })
                        .collect(),
                    ..SectionInput::default()
                };
                self.base.view.reframe();
                self.set(
                    Some(SkinSpec::new(vec![circle(0.0, 1.0), circle(2.0, 0.6)])),
                    None,
                );
            }
            return;
        };
        self.summary(ui);
        ui.separator();
        ui.label("Sections (in skinning order)");
        for (k, s) in spec.sections.iter().enumerate() {
            let mut text = format!("{k}: {} points", s.points.len());
            if s.polygon {
                text.push_str(", polygon");
            } else if !s.corners.is_empty() {
                text.push_str(&format!(", {} corner(s)", s.corners.len()));
            }
            if ui.selectable_label(k == self.selected, text).clicked() {
                self.selected = k;
            }
        }
        let k = self.selected;
        let n = spec.sections.len();
        ui.horizontal_wrapped(|ui| {
            if ui
                .button("Add after")
                .on_hover_text("A copy of the selected section, moved along its normal")
                .clicked()
            {
                let mut s = spec.clone();
                let mut copy = s.sections[k].clone();
                let (_, normal, _, _) = frame(&copy.points);
                let size = copy
                    .points
                    .iter()
                    .map(|p| (*p - copy.points[0]).length())
                    .fold(0.0, f64::max);
                let step = if k + 1 < n {
                    let (a, _, _, _) = frame(&s.sections[k].points);
                    let (b, _, _, _) = frame(&s.sections[k + 1].points);
                    0.5 * (b - a)
                } else {
                    normal * size.max(1e-3)
                };
                for p in &mut copy.points {
                    *p += step;
                }
                s.sections.insert(k + 1, copy);
                self.selected = k + 1;
                self.set(Some(s), None);
            }
            let delete = ui.add_enabled(n > 2, egui::Button::new("Delete"));
            if delete
                .on_disabled_hover_text("A skin needs at least 2 sections")
                .clicked()
            {
                let mut s = spec.clone();
                s.sections.remove(k);
                self.set(Some(s), None);
            }
            if ui
                .add_enabled(k > 0, egui::Button::new("Up"))
                .on_disabled_hover_text("The first section cannot move up")
                .clicked()
            {
                let mut s = spec.clone();
                s.sections.swap(k, k - 1);
                self.selected = k - 1;
                self.set(Some(s), None);
            }
            if ui
                .add_enabled(k + 1 < n, egui::Button::new("Down"))
                .on_disabled_hover_text("The last section cannot move down")
                .clicked()
            {
                let mut s = spec.clone();
                s.sections.swap(k, k + 1);
                self.selected = k + 1;
                self.set(Some(s), None);
            }
            if ui.button("Clear all").clicked() {
                self.set(None, None);
            }
        });
        ui.separator();
        self.section_editor(ui, spec);
        ui.separator();
        self.mouse.row(
            ui,
            &[Mouse::Orbit, Mouse::Move, Mouse::Turn, Mouse::Scale],
            "Move, turn and scale act on the selected section; right drag orbits then",
        );
        ui.separator();
        ui.label("Surface");
        let mut res = spec.resolution;
        let r = gestures::resolution_slider(ui, &mut res, "quads a patch side");
        let g = self.base.gestures.of(&r);
        self.set_changed(spec, res != spec.resolution, |s| s.resolution = res, g);
        let mut basis = spec.basis;
        gestures::basis_row(
            ui,
            &mut basis,
            [
                "Both sides of a border from the crossing curves' tangents: the surface does not depend on how sections are listed (the default)",
                "The cell listed first is the basis and the other follows it: G1 too, but the shape depends on the numbering",
            ],
        );
        self.set_changed(spec, basis != spec.basis, |s| s.basis = basis, None);
        let mut pairing = spec.pairing;
        gestures::radio_row(
            ui,
            "Pairing",
            &mut pairing,
            &[
                (
                    Pairing::Shape,
                    "by shape",
                    "Each section paired with the next where its shape, turned about the normal by up to a quarter turn, matches best (least squares); near-ties by the least twist (the default: a steadily turning section never crumples)",
                ),
                (
                    Pairing::Paper,
                    "least twist (paper)",
                    "Seed 003's criterion: the pairing of least total twist; it pairs corners with sides once a section turns more than 180°/n from the last",
                ),
            ],
        );
        self.set_changed(spec, pairing != spec.pairing, |s| s.pairing = pairing, None);
        let mut caps = spec.caps;
        if ui.checkbox(&mut caps, "Planar caps at the ends").changed() {
            let mut s = spec.clone();
            s.caps = caps;
            self.set(Some(s), None);
        }
        ui.separator();
        ui.label("Show");
        let o = &mut self.overlays;
        let shows = [
            (
                &mut o.sections,
                "Section curves: patch borders across (yellow; selected red)",
            ),
            (
                &mut o.chains,
                "Chains: patch borders along (blue; creases violet)",
            ),
            (&mut o.trajectories, "Trajectories between centres (fig. 1)"),
            (&mut o.swept, "Swept sections (fig. 2)"),
            (
                &mut o.twists,
                "Twist of each pair (fig. 2): rays to the swept vertices (orange) and their partners (green)",
            ),
            (&mut o.contours, "Contour lines (z = const, fig. 4b)"),
        ];
        for (on, label) in shows {
            ui.checkbox(on, label);
        }
        o.look.ui(ui);
        if ui.button("Frame the skin").clicked() {
            self.base.view.frame();
        }
    }

    fn view(&mut self, ui: &mut egui::Ui, spec: Option<&SkinSpec>) {
        let rect = ui.available_rect_before_wrap();
        if spec.is_none() {
            ui.centered_and_justified(|ui| {
                ui.label("Place sections from a sample on the left; the skin appears here.");
            });
            return;
        }
        let resp = self
            .base
            .view
            .interact(ui, rect, "skin_view", self.mouse == Mouse::Orbit);
        if self.mouse != Mouse::Orbit
            && let Some(spec) = spec
        {
            self.section_drag(ui, &resp, rect, spec);
        }
        self.base.view.paint(ui, rect);
        let orbit = "drag: orbit · right drag: pan · wheel: zoom";
        View3d::hint(ui, rect, &self.mouse.hint("section", orbit));
    }

    fn part(doc: &DocState) -> Option<&Self::Spec> {
        doc.skin.as_ref()
    }

    fn surface(&self) -> Result<&prism_geom::PolyMesh, &str> {
        let built = self.built.as_ref().ok_or("no sections")?;
        built.result.as_ref().map(|r| &r.1).map_err(String::as_str)
    }

    fn edit(spec: Option<SkinSpec>, gesture: Option<u64>) -> Edit {
        Edit::SetSkin { spec, gesture }
    }
}
