//! The envelope the Envelope tab rebuilds while t or a primitive is dragged
//! (docs/performance.md): the build (`envelope`, what `time_ms=` reports) and, apart, the K = 8
//! tessellation, side by side for the charts (the default) and the paper's patches, for one
//! cube, one hexagonal prism, two cubes side by side, two cubes on a body diagonal, the bundled
//! scenes like the paper's Table 2 (five and seven primitives), and 20, 50 and 100 cubes on a
//! sphere (all kept). Time per region is the figure to compare as scenes grow.

use prism_geom::freeform::envelope::{
    EnvelopeSpec, Placement, PrimitiveInput, Shape, Surfacing, envelope,
};

#[path = "../tests/common/mod.rs"]
mod common;

fn main() {
    divan::main();
}

fn cube(centre: [f64; 3]) -> PrimitiveInput {
    Shape::Cube.placed(&Placement {
        centre,
        scale: 3f64.sqrt(),
        rotation: [0.0; 3],
    })
}

fn scene(name: &str) -> EnvelopeSpec {
    let primitives = match name {
        "cube" => vec![cube([0.0; 3])],
        "hexagonal-prism" => {
            vec![Shape::HexagonalPrism { height: 1.0 }.placed(&Placement::default())]
        }
        "two-cubes" => vec![cube([0.0; 3]), cube([3.0, 0.0, 0.0])],
        "table2-five" => return bundled(include_str!("../../../assets/table2-five.envelope.json")),
        "table2-seven" => {
            return bundled(include_str!("../../../assets/table2-seven.envelope.json"));
        }
        "sphere-20" => common::cubes_on_a_sphere(20, 0.0),
        "sphere-50" => common::cubes_on_a_sphere(50, 0.0),
        "sphere-100" => common::cubes_on_a_sphere(100, 0.0),
        _ => vec![cube([0.0; 3]), cube([3.0, 3.0, 3.0])],
    };
    EnvelopeSpec {
        t: 0.7,
        primitives,
        resolution: 8,
        basis: Default::default(),
        patches: Default::default(),
        enclosure: Default::default(),
    }
}

/// A bundled scene at t = 0.7, like the others.
fn bundled(text: &str) -> EnvelopeSpec {
    let mut s: EnvelopeSpec = serde_json::from_str(text).expect("a bundled scene");
    s.t = 0.7;
    s
}

const SCENES: [&str; 9] = [
    "cube",
    "hexagonal-prism",
    "two-cubes",
    "diagonal-cubes",
    "table2-five",
    "table2-seven",
    "sphere-20",
    "sphere-50",
    "sphere-100",
];

fn with(name: &str, surfacing: Surfacing) -> EnvelopeSpec {
    EnvelopeSpec {
        patches: surfacing,
        enclosure: Default::default(),
        ..scene(name)
    }
}

/// Times one build of `s`: the network and the patches or charts, no tessellation.
fn time_build(b: divan::Bencher, s: EnvelopeSpec) {
    b.bench(|| envelope(&s).unwrap());
}

#[divan::bench(args = SCENES)]
fn build_charts(b: divan::Bencher, name: &str) {
    time_build(b, with(name, Surfacing::Charts));
}

/// The charts with the paper's central cut: no strip lifted, no region raised (the cost of
/// the enclosure is `build_charts` less this).
#[divan::bench(args = SCENES)]
fn build_charts_central_cut(b: divan::Bencher, name: &str) {
    let s = EnvelopeSpec {
        enclosure: prism_geom::freeform::envelope::Enclosure::Paper,
        ..with(name, Surfacing::Charts)
    };
    time_build(b, s);
}

#[divan::bench(args = SCENES)]
fn build_paper(b: divan::Bencher, name: &str) {
    time_build(b, with(name, Surfacing::Paper));
}

#[divan::bench(args = SCENES)]
fn tessellation_k8_charts(b: divan::Bencher, name: &str) {
    let e = envelope(&with(name, Surfacing::Charts)).unwrap();
    b.bench(|| e.tessellate(8).unwrap());
}

#[divan::bench(args = SCENES)]
fn tessellation_k8_paper(b: divan::Bencher, name: &str) {
    let e = envelope(&with(name, Surfacing::Paper)).unwrap();
    b.bench(|| e.tessellate(8).unwrap());
}
