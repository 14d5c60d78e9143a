//! What each [`Edit`] does to the document's state: validated first, so a refused edit
//! leaves the state as it was (`Document::apply` works on a copy and keeps it only when this
//! succeeds).

use super::command::{CurveEdit, EdgeMark, Edit};
use super::doc_state::{DocState, Origin};
use prism_geom::Scheme;
use prism_geom::curve::{CurveSketch, MAX_SKETCH_LEVELS};

/// The tessellation resolution of a free-form block (skin, envelope): 1 to 256 quads along a
/// patch side.
fn check_resolution(resolution: Option<usize>) -> Result<(), String> {
    match resolution {
        Some(k) if !(1..=256).contains(&k) => Err(format!(
            "resolution {k} is out of range: 1 to 256 quads a patch side"
        )),
        _ => Ok(()),
    }
}

/// The effect of one edit on a copy of the state.
pub(super) fn apply_to(d: &mut DocState, origin: &mut Origin, edit: Edit) -> Result<(), String> {
    let views = d.pipelines.len();
    let view_ok = |v: usize| {
        if v < views {
            Ok(())
        } else {
            Err(format!("there is no view {}", v + 1))
        }
    };
    let step_ok = |p: &Vec<Scheme>, k: usize| {
        if k < p.len() {
            Ok(())
        } else {
            Err(format!("the pipeline has no step {}", k + 1))
        }
    };
    match edit {
        Edit::PushStep {
            view,
            scheme,
            shrink,
        } => {
            view_ok(view)?;
            let p = &mut d.pipelines[view];
            let next = match p.last() {
                Some(last) if last.kind() == scheme.kind() && scheme.shrinks_when_repeated() => {
                    last.shrunk(shrink)
                }
                _ => scheme,
            };
            next.validate().map_err(|e| e.to_string())?;
            p.push(next);
        }
        Edit::PopStep { view } => {
            view_ok(view)?;
            d.pipelines[view].pop();
        }
        Edit::SetStep {
            view,
            index,
            scheme,
        } => {
            view_ok(view)?;
            step_ok(&d.pipelines[view], index)?;
            scheme.validate().map_err(|e| e.to_string())?;
            d.pipelines[view][index] = scheme;
        }
        Edit::SwapSteps { view, index } => {
            view_ok(view)?;
            step_ok(&d.pipelines[view], index + 1)?;
            d.pipelines[view].swap(index, index + 1);
        }
        Edit::RemoveStep { view, index } => {
            view_ok(view)?;
            step_ok(&d.pipelines[view], index)?;
            d.pipelines[view].remove(index);
        }
        Edit::TruncateSteps { view, len } => {
            view_ok(view)?;
            d.pipelines[view].truncate(len);
        }
        Edit::SetPipeline { view, steps } => {
            view_ok(view)?;
            if let Some(e) = steps.iter().find_map(|s| s.validate().err()) {
                return Err(e.to_string());
            }
            d.pipelines[view] = steps;
        }
        Edit::SetViews(n) => {
            if ![1, 2, 4].contains(&n) {
                return Err(format!("{n} views: the split has 1, 2 or 4"));
            }
            let main = d.pipelines[0].clone();
            d.pipelines.resize(n, main);
        }
        Edit::MarkEdges { edges, mark } => {
            if let EdgeMark::Radius(Some(r)) = mark
                && !(r.is_finite() && r > 0.0)
            {
                return Err(format!("a radius must be positive, not {r}"));
            }
            if let EdgeMark::Crease(s) = mark
                && !(s.is_finite() && s >= 0.0)
            {
                return Err(format!("a crease sharpness must be 0 or more, not {s}"));
            }
            for e in edges {
                let a = d.edge_attrs.entry(e).or_default();
                match mark {
                    EdgeMark::Crease(s) => a.crease = s,
                    EdgeMark::Radius(r) => a.radius = r,
                }
            }
            d.edge_attrs.retain(|_, a| !a.is_empty());
        }
        Edit::MoveVertices { verts, by } => {
            if !by.is_finite() {
                return Err("coordinates must be numbers".into());
            }
            for v in verts {
                *control_vertex(&mut d.mesh, v)? += by;
            }
        }
        Edit::DragVertices { to, .. } => {
            for (v, p) in to {
                if !p.is_finite() {
                    return Err("coordinates must be numbers".into());
                }
                *control_vertex(&mut d.mesh, v)? = p;
            }
        }
        Edit::Curve(c) => apply_curve(&mut d.curve, c)?,
        Edit::SetSkin { spec, .. } => {
            check_resolution(spec.as_ref().map(|s| s.resolution))?;
            d.skin = spec;
        }
        Edit::SetEnvelope { spec, .. } => {
            check_resolution(spec.as_ref().map(|s| s.resolution))?;
            d.envelope = spec;
        }
        Edit::Replace { state, origin: o } => {
            *d = *state;
            *origin = o;
        }
    }
    Ok(())
}

/// The position of control vertex `v`, or why there is none.
fn control_vertex(mesh: &mut prism_geom::PolyMesh, v: u32) -> Result<&mut glam::DVec3, String> {
    let n = mesh.num_vertices();
    mesh.positions
        .get_mut(v as usize)
        .ok_or(format!("there is no control vertex {v} (the mesh has {n})"))
}

fn apply_curve(c: &mut CurveSketch, edit: CurveEdit) -> Result<(), String> {
    let n = c.control.points.len();
    let finite = |p: glam::DVec2| {
        if p.is_finite() {
            Ok(())
        } else {
            Err("coordinates must be numbers".to_string())
        }
    };
    let index_ok = |i: usize| {
        if i < n {
            Ok(())
        } else {
            Err(format!("the curve has no point {i}"))
        }
    };
    match edit {
        CurveEdit::Insert { index, at } => {
            finite(at)?;
            c.control.points.insert(index.min(n), at);
        }
        CurveEdit::Move { index, to, .. } => {
            finite(to)?;
            index_ok(index)?;
            c.control.points[index] = to;
        }
        CurveEdit::Delete { index } => {
            index_ok(index)?;
            c.control.points.remove(index);
        }
        CurveEdit::SetClosed(b) => c.control.closed = b,
        CurveEdit::SetScheme(s) => c.scheme = s,
        CurveEdit::SetLevels(k) => {
            if k > MAX_SKETCH_LEVELS {
                return Err(format!("at most {MAX_SKETCH_LEVELS} levels"));
            }
            c.levels = k;
        }
        CurveEdit::SetControl(p) => {
            p.check_finite().map_err(|e| e.to_string())?;
            c.control = p;
        }
    }
    Ok(())
}
