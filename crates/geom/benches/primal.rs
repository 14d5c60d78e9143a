//! Catmull–Clark and Loop, single thread, the jobs OpenSubdiv 3.5 was timed on
//! (docs/performance.md): the timed region starts from the face lists (the half-edge
//! topology is built inside, as `Far::TopologyRefinerFactory::Create` does) and ends with
//! the refined face lists and positions.
//!
//! - `catmull_clark_l1_1m`: one level on a 1000 × 1000 quad torus (1M quads);
//! - `catmull_clark_l2_100k`: two levels on a 316 × 316 quad torus (99 856 quads);
//! - `loop_l1_1m`: one level on a 708 × 708 torus split into 1 002 528 triangles.

use prism_geom::{EdgeAttrs, PolyMesh, PrimalScheme, SubdivTags, primitives, refine_primal_levels};

#[global_allocator]
static ALLOC: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    divan::main();
}

fn levels(m: &PolyMesh, scheme: PrimalScheme, n: usize) -> PolyMesh {
    let (attrs, tags) = (EdgeAttrs::new(), SubdivTags::default());
    refine_primal_levels(m, &attrs, &tags, scheme, n, u64::MAX)
        .unwrap()
        .mesh
}

#[divan::bench(sample_count = 5)]
fn catmull_clark_l1_1m(b: divan::Bencher) {
    let m = primitives::torus(1000, 1000, 3.0, 1.0);
    b.bench(|| levels(&m, PrimalScheme::CatmullClark, 1));
}

#[divan::bench(sample_count = 10)]
fn catmull_clark_l2_100k(b: divan::Bencher) {
    let m = primitives::torus(316, 316, 3.0, 1.0);
    b.bench(|| levels(&m, PrimalScheme::CatmullClark, 2));
}

#[divan::bench(sample_count = 5)]
fn loop_l1_1m(b: divan::Bencher) {
    let m = primitives::fan_triangulated(&primitives::torus(708, 708, 3.0, 1.0));
    b.bench(|| levels(&m, PrimalScheme::Loop, 1));
}
