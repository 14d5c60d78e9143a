//! Helpers shared by the integration tests.

use prism_geom::{DVec3, PolyMesh};

/// Moves every vertex of `m` by one of the `offsets.len() / 3` random offsets, vertex `i`
/// by offset `i mod n`: the property tests draw a fixed number of offsets whatever the
/// mesh's size.
#[allow(dead_code)] // not every test crate that includes this module uses it
pub fn jitter(m: &mut PolyMesh, offsets: &[f64]) {
    let n = offsets.len() / 3;
    for (i, p) in m.positions.iter_mut().enumerate() {
        let j = 3 * (i % n);
        *p += DVec3::new(offsets[j], offsets[j + 1], offsets[j + 2]);
    }
}

/// `n` cubes of side 2 (the library cube at scale 1) spread evenly over a sphere of radius
/// 1.2 √n (a Fibonacci lattice, about 4.3 apart), each a corner of the hull of the centres;
/// cube i turned by `turn_deg` · i about x. The envelope benchmark's scenes of many primitives
/// (`benches/envelope.rs` includes this module) and a test's.
#[allow(dead_code)] // not every test crate that includes this module uses it
pub fn cubes_on_a_sphere(
    n: usize,
    turn_deg: f64,
) -> Vec<prism_geom::freeform::envelope::PrimitiveInput> {
    use prism_geom::freeform::envelope::{Placement, Shape};
    let radius = 1.2 * (n as f64).sqrt();
    (0..n)
        .map(|i| {
            let y = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
            let r = (1.0 - y * y).sqrt();
            let phi = i as f64 * 2.399963229728653;
            Shape::Cube.placed(&Placement {
                centre: [radius * r * phi.cos(), radius * y, radius * r * phi.sin()],
                scale: 1.0,
                rotation: [turn_deg * i as f64, 0.0, 0.0],
            })
        })
        .collect()
}
