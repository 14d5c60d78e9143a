//! The whole-level search for faces that pass through each other (`analysis::crossings`:
//! `--check-crossings`, the app's crossing display and, by default in the app, the mending of
//! every rounding step) on the Computer room after five combination rounds r = 0.2, clamped
//! (129,066 faces), with the threads rayon finds and with one. The peer is CGAL's
//! `Polygon_mesh_processing::self_intersections` on the same level written as OBJ
//! (`benches/peers/cgal_self_intersections.cpp`, which says how to build and run it);
//! figures side by side in docs/performance.md, "The whole-level crossing search".

use prism_geom::pipeline::Pipeline;
use prism_geom::rules::Overlap;
use std::path::Path;

#[global_allocator]
static ALLOC: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    divan::main();
}

/// The Computer room after five rounds r = 0.2, clamped.
fn level() -> prism_geom::PolyMesh {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/computer-room.obj");
    let (doc, _) = prism_geom::io::load(&path).unwrap();
    let steps = prism_geom::parse_pipeline(&["combination:r=0.2"; 5].join(",")).unwrap();
    let mut p = Pipeline::with_tags(doc.mesh, doc.edge_attrs, doc.tags, steps);
    p.options.overlap = Overlap::Clamp;
    p.compute().unwrap().mesh.clone()
}

#[divan::bench(sample_count = 10)]
fn computer_room_level5(b: divan::Bencher) {
    let m = level();
    b.bench(|| prism_geom::analysis::crossings(&m));
}

#[divan::bench(sample_count = 10)]
fn computer_room_level5_one_thread(b: divan::Bencher) {
    let m = level();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    b.bench(|| pool.install(|| prism_geom::analysis::crossings(&m)));
}
