//! Helpers shared by the integration tests.

use prism_geom::{DVec3, PolyMesh};

/// Moves every vertex of `m` by one of the `offsets.len() / 3` random offsets, vertex `i`
/// by offset `i mod n`: the property tests draw a fixed number of offsets whatever the
/// mesh's size.
pub fn jitter(m: &mut PolyMesh, offsets: &[f64]) {
    let n = offsets.len() / 3;
    for (i, p) in m.positions.iter_mut().enumerate() {
        let j = 3 * (i % n);
        *p += DVec3::new(offsets[j], offsets[j + 1], offsets[j + 2]);
    }
}
