//! Property tests over random closed solids — a split cube, the concave L-block and star
//! prism, the holed block, a torus, each jittered — through three levels of every scheme:
//! the counts are what the formulas of `memory::Counts::after` say (the memory guard's
//! prediction is exact), a closed solid stays closed, the Euler characteristic is kept, no
//! coordinate is NaN. A step may refuse (a hole under Doo–Sabin, a radius too large): an
//! error is a value; what is computed is checked. 256 cases here; the `--ignored` run takes
//! 10,000 per scheme (`cargo test --release -p prism-geom --test counts_by_formula -- --ignored`).

mod common;

use prism_geom::analysis::counts;
use prism_geom::memory::Counts;
use prism_geom::rules::CornerRule;
use prism_geom::{EdgeAttrs, Pipeline, PrimalScheme, ReflexMode, Scheme, Topology, primitives};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};

/// Scheme `k` of the ten, with its parameter from `p` in [0, 1).
fn scheme(k: u8, p: f64) -> Scheme {
    let b = Scheme::Biquadratic;
    match k % 10 {
        0 => b(CornerRule::DooSabin),
        1 => b(CornerRule::AngleBisector { l: 0.02 + 0.05 * p }),
        2 => b(CornerRule::CutWidth { d: 0.02 + 0.05 * p }),
        3 => b(CornerRule::VectorSum {
            alpha: 0.01 + 0.24 * p,
            reflex: ReflexMode::AsPrinted,
        }),
        4 => b(CornerRule::Cylindrical { r: 0.02 + 0.1 * p }),
        5 => b(CornerRule::Minimum { r: 0.02 + 0.1 * p }),
        6 => b(CornerRule::Combination { r: 0.02 + 0.1 * p }),
        7 => Scheme::Primal(PrimalScheme::CatmullClark),
        8 => Scheme::Primal(PrimalScheme::CatmullClarkCircle),
        _ => Scheme::Primal(PrimalScheme::Loop),
    }
}

fn shape(k: u8) -> prism_geom::PolyMesh {
    match k % 5 {
        0 => primitives::cube3(),
        1 => primitives::l_block(),
        2 => {
            let star = primitives::star_polygon(5, 1.5, 0.7);
            primitives::extrude(&star, &[], 0.0, 1.0)
        }
        3 => primitives::holed_block(),
        _ => primitives::torus(6, 5, 3.0, 1.0),
    }
}

/// Three levels of scheme `k` on jittered shape `s`; the checks of the module's doc.
fn check(s: u8, k: u8, p: f64, jitter: &[f64]) -> Result<(), TestCaseError> {
    let mut m = shape(s);
    common::jitter(&mut m, jitter);
    let step = scheme(k, p);
    if matches!(step, Scheme::Primal(PrimalScheme::Loop)) {
        if m.num_loops() != m.num_faces() {
            return Ok(()); // Loop needs triangles: a face with a hole has none.
        }
        m = primitives::fan_triangulated(&m);
    }
    let mut pl = Pipeline::new(m, EdgeAttrs::new(), vec![step; 3]);
    let _ = pl.compute();
    for w in pl.levels().windows(2) {
        let (a, b) = (&w[0].mesh, &w[1].mesh);
        prop_assert!(b.all_finite());
        let (ta, tb) = (Topology::build(a).unwrap(), Topology::build(b).unwrap());
        tb.require_closed(b).unwrap();
        prop_assert_eq!(counts(b).euler(), counts(a).euler());
        let dissolved = w[1].report.as_ref().is_some_and(|r| r.dissolved_edges > 0);
        if !dissolved {
            prop_assert_eq!(
                Counts::of(a, Some(ta.num_edges())).after(&step),
                Counts::of(b, Some(tb.num_edges())),
                "{}",
                step
            );
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]
    #[test]
    fn every_scheme_keeps_the_formulas(
        s in 0u8..5,
        k in 0u8..10,
        p in 0.0f64..1.0,
        jitter in proptest::collection::vec(-0.03f64..0.03, 24 * 3),
    ) {
        check(s, k, p, &jitter)?;
    }
}

/// 10,000 cases per scheme (run with `--ignored`).
#[test]
#[ignore]
fn every_scheme_keeps_the_formulas_ten_thousand_times() {
    for k in 0u8..10 {
        let mut runner = TestRunner::new(Config::with_cases(10_000));
        runner
            .run(
                &(
                    0u8..5,
                    0.0f64..1.0,
                    proptest::collection::vec(-0.03f64..0.03, 24 * 3),
                ),
                |(s, p, jitter)| check(s, k, p, &jitter),
            )
            .unwrap_or_else(|e| panic!("{}: {e}", scheme(k, 0.5)));
    }
}
