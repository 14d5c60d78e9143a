//! The Skin tab's editor of the selected section ([`SkinTab::section_editor`]).

use super::{SkinTab, frame};
use crate::gui::gestures::Tab3d;
use glam::DVec3;
use prism_geom::freeform::SkinSpec;

impl SkinTab {
    /// The selected section's numbers: its centre, turn and tilt, scale, whether it is a
    /// polygon, and its points in its plane; every change one edit, a field's drag one undo step.
    pub(super) fn section_editor(&mut self, ui: &mut egui::Ui, spec: &SkinSpec) {
        let k = self.selected;
        let Some(sec) = spec.sections.get(k) else {
            return;
        };
        let (centre, normal, x, y) = frame(&sec.points);
        ui.label(format!("Section {k}"));
        // Turn, tilt and scale act by difference: each frame's change of the field is applied
        // to the section as it is, and the field falls back to its rest value when let go.
        let mut gst = self.gesture;
        let turns = vec![
            ("turn in plane °", vec![(&mut gst.turn, "", normal)]),
            (
                "tilt °",
                vec![
                    (&mut gst.tilt_x, "about x: ", x),
                    (&mut gst.tilt_y, "about y: ", y),
                ],
            ),
        ];
        let placed = self.base.gestures.placement(ui, centre, turns);
        self.gesture = gst;
        if let Some((map, g)) = placed {
            let mut s = spec.clone();
            for p in &mut s.sections[k].points {
                *p = map.transform_point3(*p);
            }
            self.set(Some(s), g);
        }
        let mut polygon = sec.polygon;
        if ui
            .checkbox(
                &mut polygon,
                "Polygon (every point a corner: straight sides, creases)",
            )
            .changed()
        {
            let mut s = spec.clone();
            s.sections[k].polygon = polygon;
            self.set(Some(s), None);
        }
        egui::CollapsingHeader::new(format!("Points of section {k} (in its plane)"))
            .id_salt(("skin_points", k))
            .show(ui, |ui| {
                let mut edit: Option<(usize, DVec3, bool, Option<u64>)> = None;
                for (i, p) in sec.points.iter().enumerate() {
                    let d = *p - centre;
                    let (mut u, mut v) = (d.dot(x), d.dot(y));
                    let mut corner = sec.corners.contains(&i);
                    ui.horizontal(|ui| {
                        ui.label(format!("{i}"));
                        let r1 = ui.add(egui::DragValue::new(&mut u).speed(0.005).max_decimals(4));
                        let g1 = self.base.gestures.of(&r1);
                        let r2 = ui.add(egui::DragValue::new(&mut v).speed(0.005).max_decimals(4));
                        let g2 = self.base.gestures.of(&r2);
                        let c = ui.checkbox(&mut corner, "corner");
                        if r1.changed() || r2.changed() || c.changed() {
                            let g = if r1.changed() { g1 } else { g2 };
                            let off = d.dot(normal);
                            let g = if c.changed() { None } else { g };
                            edit = Some((i, centre + u * x + v * y + off * normal, corner, g));
                        }
                    });
                }
                if let Some((i, p, corner, g)) = edit {
                    let mut s = spec.clone();
                    let sec = &mut s.sections[k];
                    sec.points[i] = p;
                    sec.corners.retain(|&c| c != i);
                    if corner {
                        sec.corners.push(i);
                        sec.corners.sort_unstable();
                    }
                    self.set(Some(s), g);
                }
            });
    }
}
