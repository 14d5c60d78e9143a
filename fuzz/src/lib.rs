//! The bodies of Prism's fuzz targets: every reader of user files, and what Prism does next
//! with what a reader accepts. A body may see an error (that is the answer to bad input);
//! it must never panic, hang or run out of memory. Inputs a reader accepts are processed
//! only up to a size (faces, points, primitives) that keeps an execution in milliseconds,
//! so that a run of ten minutes tries hundreds of thousands of them.
//!
//! `crates/geom/tests/fuzz_regressions.rs` includes this file and replays every input under
//! `fuzz/regressions/<target>/` with the same bodies.

use prism_geom::freeform::envelope::envelope;
use prism_geom::freeform::{Basis, SectionInput, skin_with};
use prism_geom::io::{self, Document};
use prism_geom::scheme::CATALOGUE;
use prism_geom::{Pipeline, analysis, curve::CurveScheme, memory};
use std::path::Path;

/// The most faces a mesh may have for the step target to refine it.
const MAX_FACES: usize = 300;
/// Memory budget of one step in the step target.
const STEP_BUDGET: u64 = 256 << 20;

fn text(data: &[u8]) -> std::borrow::Cow<'_, str> {
    String::from_utf8_lossy(data)
}

/// The OBJ reader with its validation (what `prism` and the app's Open run on a file).
pub fn obj(data: &[u8]) {
    let _ = io::load_str(Path::new("fuzz.obj"), &text(data));
}

/// The STL reader (ASCII or binary, its facets welded) with the model checks, then one
/// Catmull–Clark step of what it accepts, as `prism subdivide FILE.stl` runs.
pub fn stl(data: &[u8]) {
    solid(data, "fuzz.stl");
}

/// The PLY reader (ASCII or binary) with the model checks, then one Catmull–Clark step of what
/// it accepts, as `prism subdivide FILE.ply` runs.
pub fn ply(data: &[u8]) {
    solid(data, "fuzz.ply");
}

/// The reader of `name`'s kind on `data`, then one Catmull–Clark step of what it accepts.
fn solid(data: &[u8], name: &str) {
    let Ok((doc, _)) = io::load_bytes(Path::new(name), data) else {
        return;
    };
    if doc.mesh.num_faces() <= MAX_FACES {
        let steps = vec![prism_geom::scheme::SchemeKind::CatmullClark.default_scheme()];
        let mut p = Pipeline::with_tags(doc.mesh, doc.edge_attrs, doc.tags, steps);
        p.options.memory_budget = STEP_BUDGET;
        if p.compute().is_ok() {
            assert_finite(&p.levels()[1].mesh, name);
        }
    }
}

/// The `.prism.json` reader with its validation, then what the app computes on opening it:
/// the document's pipeline (its first three steps), skin and envelope.
pub fn document(data: &[u8]) {
    let Ok((doc, _)) = io::load_str(Path::new("fuzz.prism.json"), &text(data)) else {
        return;
    };
    if let Some(steps) = &doc.pipeline
        && doc.mesh.num_faces() <= MAX_FACES
    {
        let mut p = Pipeline::with_tags(
            doc.mesh.clone(),
            doc.edge_attrs.clone(),
            doc.tags.clone(),
            steps.iter().copied().take(3).collect(),
        );
        p.options.memory_budget = STEP_BUDGET;
        let _ = p.compute();
    }
    freeform_of(&doc);
}

fn freeform_of(doc: &Document) {
    if let Some(s) = &doc.skin {
        skin_sections(&s.sections);
    }
    if let Some(e) = &doc.envelope {
        let mut e = e.clone();
        e.resolution = e.resolution.clamp(1, 3);
        scene_of(&e);
    }
}

/// The curve reader, then three levels of every curve scheme and the curvature plot's data.
pub fn polyline(data: &[u8]) {
    let Ok(p) = io::polyline_from_str(Path::new("fuzz.json"), &text(data)) else {
        return;
    };
    if p.points.len() > 64 {
        return;
    }
    for scheme in CurveScheme::ALL {
        if let Ok(out) = p.refine_levels(scheme, 3) {
            let _ = out.curvature();
            let _ = out.evolute();
            let _ = out.arc_length();
        }
    }
}

/// The sections reader, then the skin in both bases, tessellated with and without caps.
pub fn sections(data: &[u8]) {
    if let Ok(s) = io::sections_from_str(Path::new("fuzz.json"), &text(data)) {
        skin_sections(&s);
    }
}

fn skin_sections(s: &[SectionInput]) {
    if s.len() > 8 || s.iter().any(|x| x.points.len() > 32) {
        return;
    }
    for basis in [Basis::Virtual, Basis::OneSided] {
        if let Ok(skin) = skin_with(s, basis) {
            for (k, caps) in [(2, true), (1, false)] {
                if let Ok(m) = skin.tessellate(k, caps) {
                    // What a writer would get: finite, and within the memory guard's counts.
                    assert_finite(&m, "skin");
                    let counts = memory::tessellation_counts(skin.patches.len() as u64, k as u64);
                    within_counts(&m, &counts, caps, "skin");
                    // The crossing check the CLI refuses on runs on whatever is accepted.
                    let _ = skin.crossings(&m, k);
                }
            }
        }
    }
}

/// Every point of `m` is finite: no writer ever gets NaN.
fn assert_finite(m: &prism_geom::PolyMesh, what: &str) {
    if let Some(i) = m.positions.iter().position(|p| !p.is_finite()) {
        panic!("{what}: vertex {i} is {}", m.positions[i]);
    }
}

/// The mesh is no larger than the memory guard's counts said (caps add their polygons).
fn within_counts(m: &prism_geom::PolyMesh, c: &memory::Counts, caps: bool, what: &str) {
    let extra = if caps { 2 } else { 0 };
    assert!(
        m.num_vertices() as u64 <= c.vertices && m.num_faces() as u64 <= c.faces + extra,
        "{what}: {} vertices, {} faces against an estimate of {} and {}",
        m.num_vertices(),
        m.num_faces(),
        c.vertices,
        c.faces
    );
}

/// The scene reader, then the envelope, its tessellation and its G1 measure.
pub fn scene(data: &[u8]) {
    if let Ok(mut spec) = io::scene_from_str(Path::new("fuzz.json"), &text(data)) {
        spec.resolution = spec.resolution.clamp(1, 3);
        scene_of(&spec);
    }
}

fn scene_of(spec: &prism_geom::freeform::envelope::EnvelopeSpec) {
    let small = spec.primitives.len() <= 3
        && spec
            .primitives
            .iter()
            .all(|p| p.vertices.len() <= 32 && p.faces.len() <= 32);
    if !small {
        return;
    }
    if let Ok(e) = envelope(spec) {
        if let Ok(m) = e.tessellate(spec.resolution) {
            assert_finite(&m, "envelope");
            within_counts(&m, &e.mesh_counts(spec.resolution), false, "envelope");
        }
        let _ = e.largest_border_jump();
    }
}

/// One step of every scheme of the catalogue on any mesh the OBJ reader accepts (its
/// parameter scaled from the default by the input's last byte), with the fillet report and
/// the level's counts, as `prism subdivide` does.
pub fn step(data: &[u8]) {
    let Ok((doc, _)) = io::load_str(Path::new("fuzz.obj"), &text(data)) else {
        return;
    };
    if doc.mesh.num_faces() > MAX_FACES {
        return;
    }
    let scale = 0.25 + 1.5 * f64::from(data.last().copied().unwrap_or(128)) / 255.0;
    for entry in CATALOGUE {
        let scheme = entry.kind.default_scheme();
        let scheme = match scheme.param() {
            Some(p) => scheme.with_param(p * scale),
            None => scheme,
        };
        if scheme.validate().is_err() {
            continue;
        }
        let mut p = Pipeline::with_tags(
            doc.mesh.clone(),
            doc.edge_attrs.clone(),
            doc.tags.clone(),
            vec![scheme],
        );
        p.options.memory_budget = STEP_BUDGET;
        if let Ok(level) = p.compute() {
            let _ = analysis::counts(&level.mesh);
        }
        let _ = p.measure_fillets(1);
    }
}
