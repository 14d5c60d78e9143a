//! OBJ reading and writing in memory (no disk), on every core: a 1000 × 1000 quad torus
//! (1M quads, the file of the whole-process figures in docs/performance.md). Throughput is
//! the text's size over the time (divan prints bytes/s).
//!
//! - `read_1m`: the text parsed into a mesh (`io::read_obj_str`: chunks on every core);
//! - `write_1m`: the mesh formatted into a buffer (`io::obj_to_string`: the streamed writer's
//!   formatting, shortest round-trip numbers on every core).

use prism_geom::io::{obj_to_string, read_obj_str};
use prism_geom::{EdgeAttrs, SubdivTags, primitives};
use std::path::Path;

#[global_allocator]
static ALLOC: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    divan::main();
}

fn torus_text() -> String {
    let m = primitives::torus(1000, 1000, 3.0, 1.0);
    obj_to_string(&m, &EdgeAttrs::new(), &SubdivTags::default()).0
}

#[divan::bench(sample_count = 5)]
fn read_1m(b: divan::Bencher) {
    let text = torus_text();
    b.counter(divan::counter::BytesCount::new(text.len()))
        .bench(|| read_obj_str(Path::new("torus.obj"), &text).unwrap());
}

#[divan::bench(sample_count = 5)]
fn write_1m(b: divan::Bencher) {
    let m = primitives::torus(1000, 1000, 3.0, 1.0);
    let len = torus_text().len();
    b.counter(divan::counter::BytesCount::new(len))
        .bench(|| obj_to_string(&m, &EdgeAttrs::new(), &SubdivTags::default()));
}
