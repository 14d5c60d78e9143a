//! Property tests: random perturbations of closed solids through random rules never panic,
//! never produce NaN, and keep the counts and closedness.

mod common;

use prism_geom::analysis::counts;
use prism_geom::rules::CornerRule;
use prism_geom::{EdgeAttrs, Pipeline, ReflexMode, Scheme, Topology, primitives};
use proptest::prelude::*;

fn rule(k: u8, p: f64) -> CornerRule {
    match k % 7 {
        0 => CornerRule::DooSabin,
        1 => CornerRule::AngleBisector { l: 0.02 + 0.1 * p },
        2 => CornerRule::CutWidth { d: 0.02 + 0.1 * p },
        3 => CornerRule::VectorSum {
            alpha: 0.01 + 0.4 * p,
            reflex: ReflexMode::AsPrinted,
        },
        4 => CornerRule::Cylindrical { r: 0.02 + 0.2 * p },
        5 => CornerRule::Minimum { r: 0.02 + 0.2 * p },
        _ => CornerRule::Combination { r: 0.02 + 0.2 * p },
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn random_solids_and_rules(
        shape in 0u8..4,
        jitter in proptest::collection::vec(-0.05f64..0.05, 17 * 3),
        rules in proptest::collection::vec((0u8..7, 0.0f64..1.0), 1..4),
    ) {
        let mut m = match shape {
            0 => primitives::cube3(),
            1 => primitives::l_block(),
            2 => primitives::tripod(),
            _ => primitives::torus(6, 5, 3.0, 1.0),
        };
        common::jitter(&mut m, &jitter);
        let steps = rules.iter().map(|&(k, p)| Scheme::Biquadratic(rule(k, p))).collect();
        let mut pl = Pipeline::new(m, EdgeAttrs::new(), steps);
        // A step may refuse (an error is a value, not a panic); what it computes is sound.
        let _ = pl.compute();
        for w in pl.levels().windows(2) {
            let (a, b) = (&w[0].mesh, &w[1].mesh);
            prop_assert!(b.all_finite());
            let t = Topology::build(b).unwrap();
            t.require_closed(b).unwrap();
            prop_assert_eq!(counts(b).euler(), counts(a).euler());
        }
    }
}
