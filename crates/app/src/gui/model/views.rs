//! The 3D views: the grid of one, two or four views and the mouse in them (orbit, pan, zoom;
//! pick, box-select and move with the Vertices and Edges tools). A vertex drag queues one
//! [`Edit::DragVertices`] a frame, all with the drag's number, so the whole drag is one undo
//! step.

use super::pick::{self, Projector};
use super::{ModelTab, Tool, VertexDrag};
use crate::gui::command::{Command, Edit};
use crate::gui::document::DocState;
use crate::gui::viewport;
use glam::DVec3;
use std::collections::BTreeSet;

/// Rectangles of `n` views in `area` (side by side for two, 2×2 for four).
pub fn grid(area: egui::Rect, n: usize) -> Vec<egui::Rect> {
    let gap = 2.0;
    match n {
        0 | 1 => vec![area],
        2 => {
            let w = (area.width() - gap) / 2.0;
            (0..2)
                .map(|i| {
                    egui::Rect::from_min_size(
                        area.min + egui::vec2(i as f32 * (w + gap), 0.0),
                        egui::vec2(w, area.height()),
                    )
                })
                .collect()
        }
        _ => {
            let w = (area.width() - gap) / 2.0;
            let h = (area.height() - gap) / 2.0;
            (0..4)
                .map(|i| {
                    egui::Rect::from_min_size(
                        area.min
                            + egui::vec2((i % 2) as f32 * (w + gap), (i / 2) as f32 * (h + gap)),
                        egui::vec2(w, h),
                    )
                })
                .collect()
        }
    }
}

impl ModelTab {
    /// The projector of view rectangle `rect` for view `i`.
    pub fn projector(&self, i: usize, rect: egui::Rect) -> Projector {
        Projector {
            view_proj: self
                .view_camera(i)
                .view_proj(rect.width() / rect.height().max(1.0)),
            rect,
            origin: self.views[i].scene.origin,
        }
    }

    pub(super) fn views_ui(&mut self, ui: &mut egui::Ui, doc: &DocState) {
        let area = ui.available_rect_before_wrap();
        let n = self.views.len();
        let cells = grid(area, n);
        self.view_aspect = cells
            .iter()
            .map(|c| c.width() / (c.height() - if n > 1 { 20.0 } else { 0.0 }).max(1.0))
            .fold(f32::MAX, f32::min);
        if !self.framed && !self.views[0].scene.vertices.is_empty() {
            self.frame(doc);
        }
        self.hold_camera();
        for (i, cell) in cells.into_iter().enumerate() {
            let header = if n > 1 {
                egui::Rect::from_min_size(cell.min, egui::vec2(cell.width(), 20.0))
            } else {
                egui::Rect::from_min_size(cell.min, egui::vec2(0.0, 0.0))
            };
            let rect = egui::Rect::from_min_max(egui::pos2(cell.left(), header.bottom()), cell.max);
            if n > 1 {
                let active = i == self.active;
                ui.painter().rect_filled(
                    header,
                    0.0,
                    if active {
                        egui::Color32::from_rgb(60, 70, 95)
                    } else {
                        egui::Color32::from_gray(35)
                    },
                );
                let text = format!(
                    "View {}: {}",
                    i + 1,
                    super::compare::short_pipeline(&doc.pipelines[i])
                );
                let at = header.left_center() + egui::vec2(6.0, 0.0);
                viewport::caption(ui, (at, egui::Align2::LEFT_CENTER), text, 13.0, 220);
            }
            self.view_input(ui, i, rect, doc);
            viewport::paint_background(ui, rect);
            let v = &self.views[i];
            if self.has_gpu {
                ui.painter().add(egui_wgpu::Callback::new_paint_callback(
                    rect,
                    viewport::ViewCallback {
                        view: i,
                        scene: v.scene.clone(),
                        overlay: v.overlay.clone(),
                        version: v.version,
                        camera: self.view_camera(i),
                        aspect: rect.width() / rect.height().max(1.0),
                    },
                ));
                viewport::paint_refusal(ui, rect, i);
            }
            if let Some(start) = self.box_start
                && i == self.active
                && let Some(now) = ui.ctx().pointer_latest_pos()
            {
                ui.painter().rect_stroke(
                    egui::Rect::from_two_pos(start, now),
                    0.0,
                    egui::Stroke::new(1.0, egui::Color32::from_rgb(255, 220, 50)),
                    egui::StrokeKind::Inside,
                );
            }
            if let Some(job) = &v.job {
                let (k, n) = job.computing();
                let at = rect.right_top() + egui::vec2(-8.0, 8.0);
                let text = format!("computing level {k} of {n} …");
                viewport::caption(ui, (at, egui::Align2::RIGHT_TOP), text, 13.0, 230);
            }
        }
        ui.allocate_rect(area, egui::Sense::hover());
    }

    fn view_input(&mut self, ui: &mut egui::Ui, i: usize, rect: egui::Rect, doc: &DocState) {
        let resp = ui.interact(
            rect,
            ui.scope_id().with(("view", i)),
            egui::Sense::click_and_drag(),
        );
        if resp.clicked() || resp.drag_started() || resp.secondary_clicked() {
            self.active = i;
        }
        let shift = ui.input(|inp| inp.modifiers.shift);
        let (orbit_button, pan_buttons) = match self.tool {
            Tool::Orbit => (
                egui::PointerButton::Primary,
                [egui::PointerButton::Secondary, egui::PointerButton::Middle],
            ),
            _ => (
                egui::PointerButton::Secondary,
                [egui::PointerButton::Middle, egui::PointerButton::Middle],
            ),
        };
        viewport::camera_input(
            &mut self.camera,
            ui,
            &resp,
            rect,
            orbit_button,
            &pan_buttons,
        );
        if self.tool == Tool::Orbit {
            return;
        }
        let Some(pos) = resp.interact_pointer_pos() else {
            return;
        };
        let proj = self.projector(i, rect);
        if resp.clicked() {
            self.click_pick(i, &proj, pos, shift, doc);
        }
        if resp.drag_started_by(egui::PointerButton::Primary) {
            let press = ui.input(|inp| inp.pointer.press_origin()).unwrap_or(pos);
            let on_selected = self.tool == Tool::Vertices
                && pick::pick_vertex(&proj, None, &doc.mesh.positions, press, 8.0).is_some_and(
                    |v| {
                        if !self.sel_verts.contains(&v) && !shift {
                            self.sel_verts = BTreeSet::from([v]);
                        }
                        self.sel_verts.contains(&v)
                    },
                );
            if on_selected {
                self.drags += 1;
                self.drag = Some(VertexDrag {
                    id: self.drags,
                    start: self
                        .sel_verts
                        .iter()
                        .map(|&v| (v, doc.mesh.positions[v as usize]))
                        .collect(),
                });
            } else {
                self.box_start = Some(press);
            }
        }
        if resp.dragged_by(egui::PointerButton::Primary)
            && let Some(mv) = &self.drag
        {
            let press = ui.input(|inp| inp.pointer.press_origin()).unwrap_or(pos);
            let d = self.drag_vector(pos - press, rect);
            let to = mv.start.iter().map(|&(v, p)| (v, p + d)).collect();
            let drag = mv.id;
            self.push(Edit::DragVertices { drag, to });
        }
        if resp.drag_stopped() {
            self.drag = None;
            if let Some(start) = self.box_start.take() {
                self.box_pick(i, &proj, egui::Rect::from_two_pos(start, pos), shift, doc);
            }
        }
    }

    /// A screen drag as a movement in the model: in the view plane, or along the held axis.
    pub fn drag_vector(&self, delta: egui::Vec2, rect: egui::Rect) -> DVec3 {
        let c = &self.camera;
        match self.axis {
            Some(a) => {
                let (right, up) = c.view_axes();
                let scale = c.visible_height() / rect.height().max(1.0);
                let mut axis = DVec3::ZERO;
                axis[a] = 1.0;
                // The screen motion along the axis' own screen direction.
                let s = (right.as_dvec3().dot(axis), up.as_dvec3().dot(axis));
                let len2 = s.0 * s.0 + s.1 * s.1;
                if len2 < 1e-6 {
                    return DVec3::ZERO;
                }
                let along = (delta.x as f64 * s.0 - delta.y as f64 * s.1) / len2;
                axis * along * scale as f64
            }
            None => c
                .drag_in_view_plane(delta.x, delta.y, rect.height())
                .as_dvec3(),
        }
    }

    /// A click with the Vertices or Edges tool.
    pub fn click_pick(
        &mut self,
        i: usize,
        proj: &Projector,
        pos: egui::Pos2,
        add: bool,
        doc: &DocState,
    ) {
        match self.tool {
            Tool::Vertices => {
                let hit = pick::pick_vertex(proj, None, &doc.mesh.positions, pos, 8.0);
                toggle(&mut self.sel_verts, hit, add);
            }
            Tool::Edges => {
                let v = &mut self.views[i];
                let edges = v.edges();
                let k = v.shown();
                let scene = v.scene.clone();
                let mesh = &v.pipeline.levels()[k].mesh;
                let hit = pick::pick_edge(proj, Some(&scene), mesh, &edges, pos, 6.0);
                let control = match hit {
                    None => None,
                    Some(e) => match self.views[i].origins().as_ref() {
                        Ok(map) => {
                            let o = map.get(&e).copied();
                            if o.is_none() {
                                self.pending.push(Command::Say(
                                    "that edge lies inside a face of the control mesh: it follows no control edge".into(),
                                ));
                            }
                            o
                        }
                        Err(msg) => {
                            self.pending.push(Command::Say(msg.clone()));
                            None
                        }
                    },
                };
                if hit.is_none() || control.is_some() {
                    toggle(&mut self.sel_edges, control, add);
                }
            }
            Tool::Measure => {
                let v = &self.views[i];
                let (o, d) = proj.ray(pos);
                if let Some(t) = pick::ray_hit(&v.scene, o, d) {
                    let p = v.scene.origin + (o + d * t).as_dvec3();
                    // A fourth point starts a new measure.
                    if self.measure.len() >= 3 {
                        self.measure.clear();
                    }
                    self.measure.push(p);
                }
            }
            Tool::Orbit => {}
        }
    }

    /// A dragged box with the Vertices or Edges tool.
    pub fn box_pick(
        &mut self,
        i: usize,
        proj: &Projector,
        rect: egui::Rect,
        add: bool,
        doc: &DocState,
    ) {
        match self.tool {
            Tool::Vertices => {
                if !add {
                    self.sel_verts.clear();
                }
                self.sel_verts
                    .extend(pick::box_vertices(proj, &doc.mesh.positions, rect));
            }
            Tool::Edges => {
                let v = &mut self.views[i];
                let edges = v.edges();
                let k = v.shown();
                let inside = pick::box_edges(proj, &v.pipeline.levels()[k].mesh, &edges, rect);
                let origins = v.origins();
                if !add {
                    self.sel_edges.clear();
                }
                match origins.as_ref() {
                    Ok(map) => self
                        .sel_edges
                        .extend(inside.iter().filter_map(|e| map.get(e).copied())),
                    Err(msg) => self.pending.push(Command::Say(msg.clone())),
                }
            }
            Tool::Orbit | Tool::Measure => {}
        }
    }
}

fn toggle<T: Ord + Copy>(set: &mut BTreeSet<T>, hit: Option<T>, add: bool) {
    match (hit, add) {
        (Some(x), true) => {
            if !set.remove(&x) {
                set.insert(x);
            }
        }
        (Some(x), false) => {
            set.clear();
            set.insert(x);
        }
        (None, false) => set.clear(),
        (None, true) => {}
    }
}
