//! Seed 004's figs. 11 and 12 as a study anyone can run (`prism envelope-study`; docs/algorithms/
//! envelope.md, "Figures"): equal axis-aligned cubes of half-size 1 at random centres, uniform
//! in a box of side `spread`, from 2 to `max` cubes, `scenes` scenes of each count; per scene
//! the cubes kept, the regions of the network against the kept cubes' faces (fig. 12: the
//! paper reports about 1.6 regions a face) and the time of each stage (fig. 11: the network
//! with its charts and lifts, then the mesh at resolution `k`).

use super::primitive::{Placement, PrimitiveInput, Shape};
use super::{EnvelopeError, EnvelopeSpec, envelope};
use std::time::Instant;

/// One scene of the study.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyScene {
    pub cubes: usize,
    /// Cubes not swallowed by the others.
    pub kept: usize,
    /// Faces of the network (regions) ...
    pub regions: usize,
    /// ... against the kept cubes' faces.
    pub faces: usize,
    /// The network, its charts and the lifts, milliseconds.
    pub build_ms: f64,
    /// The mesh at the study's resolution, milliseconds.
    pub mesh_ms: f64,
    pub triangles: usize,
}

/// A reproducible sequence in [0, 1) (a linear congruential generator, Knuth's constants).
pub struct Lcg(pub u64);

impl Lcg {
    pub fn uniform(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `count` equal axis-aligned cubes of half-size 1, centres uniform in [0, spread]³.
pub fn random_cubes(rng: &mut Lcg, count: usize, spread: f64) -> Vec<PrimitiveInput> {
    (0..count)
        .map(|_| {
            let centre = [0; 3].map(|_| spread * rng.uniform());
            Shape::Cube.placed(&Placement {
                centre,
                scale: 3f64.sqrt(),
                rotation: [0.0; 3],
            })
        })
        .collect()
}

/// The study: every scene of 2 to `max` cubes, `scenes` of each, at t = 1 and resolution `k`.
/// Two cubes at one centre (a chance of about 10⁻¹⁵) are named as the envelope names them.
pub fn cube_study(
    max: usize,
    scenes: usize,
    spread: f64,
    seed: u64,
    k: usize,
) -> Result<Vec<StudyScene>, EnvelopeError> {
    let mut rng = Lcg(seed);
    let mut out = Vec::with_capacity(max.saturating_sub(1) * scenes);
    for cubes in 2..=max {
        for _ in 0..scenes {
            let spec = EnvelopeSpec {
                t: 1.0,
                primitives: random_cubes(&mut rng, cubes, spread),
                resolution: k,
                basis: Default::default(),
                patches: Default::default(),
                enclosure: Default::default(),
            };
            let start = Instant::now();
            let e = envelope(&spec)?;
            let built = Instant::now();
            let (mesh, _) = e.mesh(k)?;
            let meshed = Instant::now();
            let kept = cubes - e.removed.len();
            out.push(StudyScene {
                cubes,
                kept,
                regions: e.regions,
                faces: 6 * kept,
                build_ms: (built - start).as_secs_f64() * 1e3,
                mesh_ms: (meshed - built).as_secs_f64() * 1e3,
                triangles: mesh.num_faces(),
            });
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_study_is_reproducible_and_counts_what_it_builds() {
        let a = cube_study(3, 4, 4.0, 4, 2).unwrap();
        let b = cube_study(3, 4, 4.0, 4, 2).unwrap();
        assert_eq!(a.len(), 8);
        for (x, y) in a.iter().zip(&b) {
            assert_eq!(
                (x.cubes, x.kept, x.regions, x.triangles),
                (y.cubes, y.kept, y.regions, y.triangles)
            );
            assert_eq!(x.faces, 6 * x.kept);
            // Every kept cube keeps at least one region, and fusion adds some.
            assert!(x.regions > x.kept && x.triangles > 0, "{x:?}");
        }
    }
}
