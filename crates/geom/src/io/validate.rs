//! One check of a loaded model, after either reader (OBJ or `.prism.json`): what the file
//! says about vertices, faces, edges, corners and holes must name elements that exist and
//! carry values in range. The OBJ reader checks its tags line by line first (so its messages
//! name the line); this catches what reaches the model any other way, with messages naming
//! the element.

use crate::edge_attrs::EdgeAttrs;
use crate::mesh::PolyMesh;
use crate::numbering::Numbering;
use crate::tags::SubdivTags;
use std::collections::HashSet;

/// The first problem of the model, in words; vertices and faces named as `numbering` says
/// the file counts them (edges, corners and holes come from tags, which count from 0 in
/// both formats; the OBJ reader has checked its tags with their lines already).
pub fn validate_model(
    mesh: &PolyMesh,
    attrs: &EdgeAttrs,
    tags: &SubdivTags,
    numbering: &Numbering,
) -> Result<(), String> {
    let n = mesh.num_vertices();
    if let Some(v) = mesh.positions.iter().position(|p| !p.is_finite()) {
        return Err(format!(
            "{} has a coordinate that is not a finite number",
            numbering.vertex(v as u32)
        ));
    }
    // Only the edges the marks name are looked for (a set of every edge of a 5M-face model
    // took seconds and a gigabyte).
    let mut edges: HashSet<(u32, u32)> = HashSet::new();
    let wanted: HashSet<(u32, u32)> = attrs.keys().map(|k| (k.0.min(k.1), k.0.max(k.1))).collect();
    for f in 0..mesh.num_faces() {
        for (k, l) in mesh.face_loops(f).enumerate() {
            let vs = mesh.loop_verts(l);
            if let Some(&v) = vs.iter().find(|&&v| v as usize >= n) {
                return Err(format!(
                    "{}, loop {k}: vertex index {} is out of range (the model has {n} vertices)",
                    numbering.face(f as u32),
                    v as u64 + numbering.base as u64
                ));
            }
            if wanted.is_empty() {
                continue;
            }
            for i in 0..vs.len() {
                let (a, b) = (vs[i], vs[(i + 1) % vs.len()]);
                let e = (a.min(b), a.max(b));
                if wanted.contains(&e) {
                    edges.insert(e);
                }
            }
        }
    }
    for (key, attr) in attrs.iter() {
        let (a, b) = (key.0, key.1);
        if a as usize >= n || b as usize >= n {
            return Err(format!(
                "edge {a}-{b} names a vertex that does not exist (the model has {n} vertices)"
            ));
        }
        if !edges.contains(&(a.min(b), a.max(b))) {
            return Err(format!("edge {a}-{b} is not an edge of any face"));
        }
        if !(attr.crease.is_finite() && attr.crease >= 0.0) {
            return Err(format!(
                "edge {a}-{b}: crease sharpness {} must be a number of at least 0",
                attr.crease
            ));
        }
        if let Some(r) = attr.radius
            && !(r.is_finite() && r > 0.0)
        {
            return Err(format!("edge {a}-{b}: radius {r} must be a number above 0"));
        }
        if let Some(r) = attr.fits
            && !(r.is_finite() && r >= 0.0)
        {
            return Err(format!(
                "edge {a}-{b}: fitting radius {r} must be a number of at least 0"
            ));
        }
    }
    for (&v, &s) in &tags.corners {
        if v as usize >= n {
            return Err(format!(
                "corner at vertex {v}: no such vertex (the model has {n})"
            ));
        }
        if !(s.is_finite() && s >= 0.0) {
            return Err(format!(
                "corner at vertex {v}: sharpness {s} must be a number of at least 0"
            ));
        }
    }
    if let Some(&f) = tags.holes.iter().find(|&&f| f as usize >= mesh.num_faces()) {
        return Err(format!(
            "hole {f}: no such face (the model has {} faces)",
            mesh.num_faces()
        ));
    }
    Ok(())
}
