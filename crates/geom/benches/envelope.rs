//! The envelope the Envelope tab rebuilds while t or a primitive is dragged
//! (docs/performance.md): network and patches (`envelope`, what `time_ms=` reports) and, apart,
//! the K = 8 tessellation, for one cube (6 patches), one hexagonal prism (18), two cubes side by
//! side (14), two cubes on a body diagonal (54) and the bundled scenes like the paper's Table 2
//! (five primitives: 81 patches; seven: 135), and 20, 50 and 100 cubes on a sphere (all kept:
//! 376, 842 and 1,697 patches). Time per patch is the figure to compare as scenes grow.

use prism_geom::freeform::envelope::{EnvelopeSpec, Placement, PrimitiveInput, Shape, envelope};

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

#[divan::bench(args = SCENES)]
fn network_and_patches(b: divan::Bencher, name: &str) {
    let s = scene(name);
    b.bench(|| envelope(&s).unwrap());
}

#[divan::bench(args = SCENES)]
fn tessellation_k8(b: divan::Bencher, name: &str) {
    let e = envelope(&scene(name)).unwrap();
    b.bench(|| e.tessellate(8).unwrap());
}
