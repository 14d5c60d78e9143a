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

/// How far x lies from the charts' surface of `e` along its chart's direction (∞ where no chart
/// holds it): the surface itself, not a mesh of it.
#[allow(dead_code)] // not every test crate that includes this module uses it
pub fn off_surface(e: &prism_geom::freeform::envelope::Envelope, x: DVec3) -> f64 {
    let x = e.frame.to_local(x);
    e.frame.scale
        * e.charts
            .iter()
            .filter_map(|ch| {
                let (c, h) = ch.frame.chart(x)?;
                let inside = ch.sides.iter().all(|s| s.coords(c).1 >= -1e-9 * s.length);
                inside.then(|| (ch.value(c) - h).abs() * ch.frame.direction(c).length())
            })
            .fold(f64::INFINITY, f64::min)
}

/// Points of every kept primitive's faces — each face's centre moved the `shares` of the way
/// to its corners — on the kept side of the planes through the primitive's centre towards
/// every other kept primitive (a part of what the envelope's construction keeps), pulled the
/// share `pull` towards the centre; in the scene's coordinates.
#[allow(dead_code)] // not every test crate that includes this module uses it
pub fn kept_points(
    e: &prism_geom::freeform::envelope::Envelope,
    shares: &[f64],
    pull: f64,
) -> Vec<DVec3> {
    let kept: Vec<usize> = (0..e.primitives.len())
        .filter(|i| !e.removed.contains(i))
        .collect();
    let mut out = Vec::new();
    for &i in &kept {
        let p = &e.primitives[i];
        let cuts: Vec<DVec3> = kept
            .iter()
            .filter(|&&j| j != i)
            .map(|&j| (e.primitives[j].centre - p.centre).normalize())
            .collect();
        for face in &p.faces {
            let c = face.iter().map(|&v| p.vertices[v]).sum::<DVec3>() / face.len() as f64;
            for &v in face {
                for &s in shares {
                    let x = c.lerp(p.vertices[v], s);
                    if cuts
                        .iter()
                        .all(|d| (x - p.centre).dot(*d) <= -1e-9 * p.radius)
                    {
                        out.push(e.frame.to_world(p.centre + (x - p.centre) * (1.0 - pull)));
                    }
                }
            }
        }
    }
    out
}

/// The envelope scene of `primitives` at global `t` on the charts, K = 8.
#[allow(dead_code)] // not every test crate that includes this module uses it
pub fn spec(
    primitives: Vec<prism_geom::freeform::envelope::PrimitiveInput>,
    t: f64,
) -> prism_geom::freeform::envelope::EnvelopeSpec {
    prism_geom::freeform::envelope::EnvelopeSpec {
        t,
        primitives,
        resolution: 8,
        basis: Default::default(),
        patches: prism_geom::freeform::envelope::Surfacing::Charts,
        enclosure: Default::default(),
    }
}

/// The Hausdorff distance between two point sets (each point's nearest in the other, the
/// largest of those either way).
#[allow(dead_code)] // not every test crate that includes this module uses it
pub fn hausdorff(a: &[DVec3], b: &[DVec3]) -> f64 {
    let one = |a: &[DVec3], b: &[DVec3]| {
        a.iter()
            .map(|p| {
                b.iter()
                    .map(|q| p.distance(*q))
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(0.0, f64::max)
    };
    one(a, b).max(one(b, a))
}

/// The 48 rotations and reflections of a cube about its centre: the signed permutation
/// matrices.
#[allow(dead_code)] // not every test crate that includes this module uses it
pub fn cube_symmetries() -> Vec<glam::DMat3> {
    let perms = (0..27)
        .map(|i| [i / 9, i / 3 % 3, i % 3])
        .filter(|[a, b, c]| a != b && b != c && a != c);
    let mut out = Vec::new();
    for p in perms {
        for signs in 0..8 {
            let mut rows = [[0.0; 3]; 3];
            for (row, &col) in p.iter().enumerate() {
                rows[row][col] = if signs >> row & 1 == 1 { -1.0 } else { 1.0 };
            }
            out.push(glam::DMat3::from_cols_array_2d(&rows).transpose());
        }
    }
    assert_eq!(out.len(), 48);
    out
}
