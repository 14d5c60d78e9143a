//! What is drawn over each view's level: the previous level as a cage, the control mesh
//! and its selected vertices (Vertices tool), marked, clamped (orange; red where the fillet
//! misses the clamped radius) and selected control
//! edges where they are on this level, corner points with their displacement vectors, limit points with
//! normals. An overlay is rebuilt when the hash of what it is made from changes (the level,
//! the document, the selection, the display options, the tool); limit points come from a
//! thread ([`super::view_pipe::ViewPipe::limit_points`]).

use super::{ModelTab, Tool};
use crate::gui::command::Command;
use crate::gui::document::DocState;
use glam::DVec3;
use prism_geom::{EdgeKey, Scheme};
use prism_viewport::Scene;
use std::collections::BTreeSet;
use std::hash::{Hash, Hasher};
use std::sync::Arc;

const CONTROL: [f32; 3] = [0.55, 0.62, 0.80];
const SELECTED: [f32; 3] = [1.0, 0.86, 0.20];
const CREASE: [f32; 3] = [0.95, 0.30, 0.25];
const RADIUS: [f32; 3] = [0.25, 0.85, 0.90];
/// Edges whose radius was clamped to fit their faces.
const CLAMPED: [f32; 3] = [1.0, 0.55, 0.10];
/// Clamped edges whose fillet misses the radius they were clamped to.
const MISSED: [f32; 3] = [0.90, 0.10, 0.10];
const CAGE: [f32; 3] = [0.95, 0.75, 0.25];
const CORNER: [f32; 3] = [0.45, 0.95, 0.45];
const LIMIT: [f32; 3] = [0.95, 0.45, 0.95];
/// The Measure tool's points and the lines between them.
const MEASURE: [f32; 3] = [0.30, 0.95, 1.0];

impl ModelTab {
    /// Brings every view's scene and overlay up to date (`doc_generation`: the document's).
    pub fn rebuild_scenes(&mut self, doc: &DocState, doc_generation: u64) {
        let opts = self.display.scene_options();
        for i in 0..self.views.len() {
            self.views[i].refresh_scene(&opts, &self.waker);
            let w = self.waker.clone();
            self.views[i].check_crossings(&w);
            let limit = self.limit_scheme(i).and_then(|s| {
                let w = self.waker.clone();
                self.views[i].limit_points(s, &w)
            });
            let key = {
                let v = &self.views[i];
                let mut h = std::collections::hash_map::DefaultHasher::new();
                (v.generation, v.shown(), v.scene_serial(), doc_generation).hash(&mut h);
                (&self.display, self.tool, i == self.active).hash(&mut h);
                (&self.sel_verts, &self.sel_edges, limit.is_some()).hash(&mut h);
                for p in &self.measure {
                    p.to_array().map(f64::to_bits).hash(&mut h);
                }
                h.finish()
            };
            if self.views[i].overlay_key == Some(key) {
                continue;
            }
            let overlay = self.build_overlay(i, doc, limit.as_deref());
            let v = &mut self.views[i];
            v.overlay = Arc::new(overlay);
            v.overlay_key = Some(key);
            v.version += 1;
        }
    }

    /// The primal scheme whose limit points view `i` shows, if the display asks for them.
    fn limit_scheme(&self, i: usize) -> Option<prism_geom::PrimalScheme> {
        if !self.display.limit {
            return None;
        }
        let v = &self.views[i];
        let k = v.shown();
        let scheme = if k > 0 {
            Some(v.steps()[k - 1])
        } else {
            v.steps().first().copied()
        };
        match scheme {
            Some(Scheme::Primal(s)) => Some(s),
            _ => None,
        }
    }

    /// Lines and points over view `i`'s level.
    fn build_overlay(
        &mut self,
        i: usize,
        doc: &DocState,
        limit: Option<&super::view_pipe::Limits>,
    ) -> Scene {
        let (origin, bbox, radius) = {
            let s = &self.views[i].scene;
            (s.origin, s.bbox, s.radius() as f64)
        };
        let mut o = Scene {
            origin,
            bbox,
            ..Scene::default()
        };
        let k = self.views[i].shown();
        let size = 0.008 * radius;
        if self.display.cage && k > 0 {
            o.add_cage(&self.views[i].pipeline.levels()[k - 1].mesh, CAGE);
        }
        if !self.measure.is_empty() {
            o.add_points(&self.measure, 1.5 * size, MEASURE);
            let mut segs: Vec<(DVec3, DVec3)> =
                self.measure.windows(2).map(|w| (w[0], w[1])).collect();
            if self.measure.len() == 3 {
                segs.push((self.measure[2], self.measure[0]));
            }
            o.add_segments(&segs, MEASURE);
        }
        if self.tool == Tool::Vertices && i == self.active {
            o.add_cage(&doc.mesh, CONTROL);
            o.add_points(&doc.mesh.positions, size, CONTROL);
            let sel: Vec<DVec3> = self
                .sel_verts
                .iter()
                .filter_map(|&v| doc.mesh.positions.get(v as usize).copied())
                .collect();
            o.add_points(&sel, 2.0 * size, SELECTED);
        }
        // Marked and selected control edges, drawn where they are on this level.
        let marked = |f: &dyn Fn(&prism_geom::EdgeAttr) -> bool| -> BTreeSet<EdgeKey> {
            doc.edge_attrs
                .iter()
                .filter(|(_, a)| f(a))
                .map(|(e, _)| *e)
                .collect()
        };
        let creased = marked(&|a| a.crease > 0.0);
        let radiused = marked(&|a| a.radius.is_some());
        // Edges whose radius was clamped to fit (when the rounding starts on the control
        // mesh, their names are control edges).
        let clamped: BTreeSet<EdgeKey> = {
            let p = &self.views[i].pipeline;
            match p.rounding_run(k) {
                Some(run) if run.start == 0 => run.clamped.keys().copied().collect(),
                _ => BTreeSet::new(),
            }
        };
        let missed: BTreeSet<EdgeKey> = if clamped.is_empty() {
            BTreeSet::new()
        } else {
            self.missed_radii(i).iter().map(|m| m.0).collect()
        };
        if !creased.is_empty()
            || !radiused.is_empty()
            || !clamped.is_empty()
            || !self.sel_edges.is_empty()
        {
            let origins = self.views[i].origins();
            if let Ok(map) = origins.as_ref() {
                let mesh = &self.views[i].pipeline.levels()[k].mesh;
                let segs = |set: &BTreeSet<EdgeKey>| -> Vec<(DVec3, DVec3)> {
                    map.iter()
                        .filter(|(_, c)| set.contains(c))
                        .map(|(e, _)| (mesh.positions[e.0 as usize], mesh.positions[e.1 as usize]))
                        .collect()
                };
                o.add_segments(&segs(&creased), CREASE);
                o.add_segments(&segs(&radiused), RADIUS);
                o.add_segments(&segs(&clamped), CLAMPED);
                o.add_segments(&segs(&missed), MISSED);
                o.add_segments(&segs(&self.sel_edges), SELECTED);
            }
        }
        let v = &self.views[i];
        let levels = v.pipeline.levels();
        if self.display.corners && k > 0 && matches!(v.steps()[k - 1], Scheme::Biquadratic(_)) {
            let lv = &levels[k];
            let parent = &levels[k - 1].mesh;
            let undissolved = lv.report.as_ref().is_some_and(|r| r.dissolved_edges == 0);
            if let (true, Some(prov)) = (undissolved, lv.provenance.as_ref()) {
                // Each new corner point, from the parent vertex it was cut from.
                let n = prov.numbering;
                let vecs: Vec<(DVec3, DVec3)> = (0..lv.mesh.num_vertices() as u32)
                    .filter_map(|i| {
                        let pv = n.parent_vertex(parent, i)?;
                        Some((parent.positions[pv as usize], lv.mesh.positions[i as usize]))
                    })
                    .collect();
                o.add_segments(&vecs, [0.30, 0.65, 0.30]);
                o.add_points(&lv.mesh.positions, size, CORNER);
            }
        }
        match limit {
            Some(Ok(lp)) => {
                o.add_points(&lp.positions, size, LIMIT);
                let len = 0.05 * radius;
                let normals: Vec<(DVec3, DVec3)> = lp
                    .positions
                    .iter()
                    .zip(&lp.normals)
                    .map(|(p, n)| (*p, *p + len * *n))
                    .collect();
                o.add_segments(&normals, LIMIT);
            }
            Some(Err(e)) => self.push(Command::Say(format!("limit points: {e}"))),
            None => {}
        }
        o
    }
}
