//! The envelope the Envelope tab rebuilds while t or a primitive is dragged
//! (docs/performance.md): network and patches (`envelope`, what `time_ms=` reports) and, apart,
//! the K = 8 tessellation, for one cube (6 patches), one hexagonal prism (18), two cubes side by
//! side (14) and two cubes on a body diagonal (54). Time per patch is the figure to compare as
//! scenes grow.

use prism_geom::freeform::envelope::{EnvelopeSpec, Placement, PrimitiveInput, Shape, envelope};

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
        _ => vec![cube([0.0; 3]), cube([3.0, 3.0, 3.0])],
    };
    EnvelopeSpec {
        t: 0.7,
        primitives,
        resolution: 8,
        basis: Default::default(),
    }
}

const SCENES: [&str; 4] = ["cube", "hexagonal-prism", "two-cubes", "diagonal-cubes"];

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
