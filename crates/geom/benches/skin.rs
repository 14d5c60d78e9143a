//! The skin the Skin tab rebuilds while a section is dragged (docs/performance.md): 6 sections
//! × 16 points, K = 16 (96 patches, 24,576 quads): sections checked and prepared, sweep and
//! least twist, chains, patches, tessellation with caps. Also the same at K = 8.

use glam::{DQuat, DVec3};
use prism_geom::freeform::{SectionInput, skin};

fn main() {
    divan::main();
}

fn sections() -> Vec<SectionInput> {
    (0..6)
        .map(|k| {
            let a = k as f64 * 0.25;
            let centre = DVec3::new(3.0 * (1.0 - a.cos()), 0.0, 3.0 * a.sin());
            let rot = DQuat::from_rotation_arc(DVec3::Z, DVec3::new(a.sin(), 0.0, a.cos()));
            let (ra, rb) = (1.0 - 0.1 * k as f64, 0.8 - 0.05 * k as f64);
            SectionInput {
                points: (0..16)
                    .map(|i| {
                        let t = i as f64 * std::f64::consts::TAU / 16.0 + 0.05 * k as f64;
                        centre + rot * DVec3::new(ra * t.cos(), rb * t.sin(), 0.0)
                    })
                    .collect(),
                ..SectionInput::default()
            }
        })
        .collect()
}

#[divan::bench(args = [8, 16])]
fn skin_6x16(b: divan::Bencher, k: usize) {
    let s = sections();
    b.bench(|| skin(&s).unwrap().tessellate(k, true).unwrap());
}

/// The crossing check the Skin tab runs on every rebuild (the mesh of `skin_6x16`, caps on).
#[divan::bench(args = [8, 16, 32])]
fn crossings_6x16(b: divan::Bencher, k: usize) {
    let s = skin(&sections()).unwrap();
    let m = s.tessellate(k, true).unwrap();
    b.bench(|| s.crossings(&m, k));
}
