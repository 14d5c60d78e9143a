//! One biquadratic level on a 100k-quad torus (316 × 316 = 99 856 quads), single thread.
//!
//! `doo_sabin_level1` is the kernel from face lists to the refined face lists and points:
//! topology build with every input check, closed-solid check, Doo–Sabin points, split.
//! `step_*` is the whole user-visible step (`biquadratic_step`: topology build and checks,
//! normals, corner points, split, flipped-face report); `split_only` is the topology of the
//! split alone from precomputed points. Figures: docs/performance.md.
//!
//! The benchmark uses mimalloc, as the `prism` binary does: with glibc's default
//! thresholds every level's fresh tens of megabytes are returned to the kernel and faulted
//! in again, which costs more than the subdivision itself.

use prism_geom::refine::dual_quad;
use prism_geom::rules::{CornerRule, RuleInput, corner_points};
use prism_geom::{EdgeAttrs, RoundingOptions, Topology, biquadratic_step, primitives};

#[global_allocator]
static ALLOC: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    divan::main();
}

fn torus() -> prism_geom::PolyMesh {
    primitives::torus(316, 316, 3.0, 1.0)
}

#[divan::bench(sample_count = 20)]
fn step_doo_sabin(b: divan::Bencher) {
    let m = torus();
    let attrs = EdgeAttrs::new();
    b.bench(|| {
        biquadratic_step(
            &m,
            &attrs,
            &CornerRule::DooSabin,
            None,
            &RoundingOptions::default(),
        )
        .unwrap()
    });
}

/// The whole user-visible step of `rule` on `m`, from the start of a run, without the
/// whole-level crossing search of the mending stage (the `crossings` bench times that apart).
fn bench_step(b: divan::Bencher, m: prism_geom::PolyMesh, rule: CornerRule) {
    let attrs = EdgeAttrs::new();
    let mut options = RoundingOptions::default();
    options.mend.crossings = false;
    b.bench(|| biquadratic_step(&m, &attrs, &rule, None, &options).unwrap());
}

#[divan::bench(sample_count = 20)]
fn step_cylindrical(b: divan::Bencher) {
    bench_step(b, torus(), CornerRule::Cylindrical { r: 0.01 });
}

/// The same torus with every vertex moved off it by up to 0.2 % of the tube radius (a
/// pattern, not noise): every quad is warped, so every corner takes the corner plane's full
/// path (docs/algorithms/conventions.md) where the planar torus takes its shortcut.
fn warped_torus() -> prism_geom::PolyMesh {
    let mut m = torus();
    for (i, p) in m.positions.iter_mut().enumerate() {
        let ring = glam::DVec3::new(p.x, p.y, 0.0).normalize() * 3.0;
        let out = (*p - ring).normalize();
        *p += out * (0.002 * (i as f64 * 0.7).sin());
    }
    m
}

#[divan::bench(sample_count = 20)]
fn step_cylindrical_warped(b: divan::Bencher) {
    bench_step(b, warped_torus(), CornerRule::Cylindrical { r: 0.01 });
}

/// A combination step on the warped torus: the cylindrical points plus the fold guard, which
/// tests every new face's outline (docs/algorithms/cylindrical.md, "Fold guard").
#[divan::bench(sample_count = 20)]
fn step_combination_warped(b: divan::Bencher) {
    bench_step(b, warped_torus(), CornerRule::Combination { r: 0.01 });
}

#[divan::bench(sample_count = 20)]
fn topology_build(b: divan::Bencher) {
    let m = torus();
    b.bench(|| Topology::build(&m).unwrap());
}

/// Doo–Sabin corner points and the split, given the topology.
fn points_and_split(m: &prism_geom::PolyMesh, t: &Topology) -> prism_geom::PolyMesh {
    let input = RuleInput {
        mesh: m,
        topo: t,
        normals: &[],
        cut_widths: &[],
        face_params: &[],
        vertex_neighbourhood: &[],
        options: &RoundingOptions::default(),
    };
    let (pts, _) = corner_points(&CornerRule::DooSabin, &input).unwrap();
    dual_quad::split(m, t, pts).0
}

#[divan::bench(sample_count = 20)]
fn doo_sabin_points_and_split(b: divan::Bencher) {
    let m = torus();
    let t = Topology::build(&m).unwrap();
    b.bench(|| points_and_split(&m, &t));
}

#[divan::bench(sample_count = 20)]
fn doo_sabin_level1(b: divan::Bencher) {
    let m = torus();
    b.bench(|| {
        let t = Topology::build(&m).unwrap();
        t.require_closed(&m).unwrap();
        points_and_split(&m, &t)
    });
}
