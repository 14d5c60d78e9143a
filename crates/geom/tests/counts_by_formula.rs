//! Property tests over random closed solids — a split cube, the concave L-block and star
//! prism, the holed block, a torus, convex hulls of a heptagonal prism, a pentagonal pyramid
//! and an octahedron, each jittered — through three levels of every scheme:
//! the counts are what the formulas of `memory::Counts::after` say (the memory guard's
//! prediction is exact), a closed solid stays closed, the Euler characteristic is kept, no
//! coordinate is NaN. A step may refuse (a hole under Doo–Sabin, a radius too large): an
//! error is a value; what is computed is checked. 256 cases here; the `--ignored` run takes
//! 10,000 per scheme (`cargo test --release -p prism-geom --test counts_by_formula -- --ignored`).
//!
//! And on the same solids, Catmull–Clark and Loop converge to their limit positions: the
//! limit of every vertex of the first level all quads (Catmull–Clark: level 1; Loop: the
//! triangulated input) computed there is the one computed two levels later (the limit masks
//! are invariant under refinement), and the vertex's own position approaches it
//! geometrically (the gap at least halves a level; about 1/4 at a regular vertex, up to 0.38
//! seen at the concave solids' extraordinary ones).

mod common;

use prism_geom::analysis::counts;
use prism_geom::memory::Counts;
use prism_geom::primal::limit_points;
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
    match k % 8 {
        5 => primitives::ngon_prism(7, 1.0, 1.2),
        6 => primitives::pyramid(5, 1.0, 1.5),
        7 => primitives::octahedron(),
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
        s in 0u8..8,
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
                    0u8..8,
                    0.0f64..1.0,
                    proptest::collection::vec(-0.03f64..0.03, 24 * 3),
                ),
                |(s, p, jitter)| check(s, k, p, &jitter),
            )
            .unwrap_or_else(|e| panic!("{}: {e}", scheme(k, 0.5)));
    }
}

/// The largest distance of level `base`'s vertices at level `level` from their limit
/// positions, and the largest change of those limits computed on `level` instead of `base`.
fn limit_gaps(pl: &Pipeline, scheme: PrimalScheme, base: usize, level: usize) -> (f64, f64) {
    let b = &pl.levels()[base];
    let l0 = limit_points(&b.mesh, &b.edge_attrs, &b.tags, scheme)
        .unwrap()
        .positions;
    let at = &pl.levels()[level];
    let lk = limit_points(&at.mesh, &at.edge_attrs, &at.tags, scheme)
        .unwrap()
        .positions;
    let mut gap: f64 = 0.0;
    let mut moved: f64 = 0.0;
    for (i, l) in l0.iter().enumerate() {
        gap = gap.max((at.mesh.positions[i] - *l).length());
        moved = moved.max((lk[i] - *l).length());
    }
    (gap, moved)
}

fn check_limit(s: u8, loop_scheme: bool, jitter: &[f64]) -> Result<(), TestCaseError> {
    let mut m = shape(s);
    common::jitter(&mut m, jitter);
    let scheme = if loop_scheme {
        if m.num_loops() != m.num_faces() {
            return Ok(());
        }
        m = primitives::fan_triangulated(&m);
        PrimalScheme::Loop
    } else {
        if m.num_loops() != m.num_faces() {
            return Ok(()); // A face with a hole has no Catmull–Clark face point.
        }
        PrimalScheme::CatmullClark
    };
    let mut pl = Pipeline::new(m, EdgeAttrs::new(), vec![Scheme::Primal(scheme); 3]);
    if pl.compute().is_err() {
        return Ok(()); // A level turned inside out by the jitter: not this test's subject.
    }
    let size = pl.levels()[0].mesh.bbox_diagonal();
    let base = usize::from(scheme == PrimalScheme::CatmullClark);
    if scheme == PrimalScheme::CatmullClark {
        let l = &pl.levels()[0];
        let all_quads = (0..l.mesh.num_faces()).all(|f| l.mesh.face_corners(f).len() == 4);
        let r = limit_points(&l.mesh, &l.edge_attrs, &l.tags, scheme);
        prop_assert_eq!(
            r.is_ok(),
            all_quads,
            "n-gons have no Catmull–Clark limit mask"
        );
    }
    let gaps: Vec<(f64, f64)> = (base..4)
        .map(|k| limit_gaps(&pl, scheme, base, k))
        .collect();
    for (k, &(_, moved)) in gaps.iter().enumerate() {
        prop_assert!(
            moved <= 1e-12 * size,
            "{scheme:?} level {}: limit moved {moved:e}",
            base + k
        );
    }
    let (d_first, d_last) = (gaps[1].0, gaps[gaps.len() - 1].0);
    prop_assert!(
        d_last <= 0.5 * d_first + 1e-12 * size,
        "{scheme:?}: gaps {:?}",
        gaps.iter().map(|g| g.0).collect::<Vec<_>>()
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn catmull_clark_and_loop_converge_to_their_limits(
        s in 0u8..8,
        loop_scheme in proptest::bool::ANY,
        jitter in proptest::collection::vec(-0.03f64..0.03, 24 * 3),
    ) {
        check_limit(s, loop_scheme, &jitter)?;
    }
}

/// 10,000 cases of each (run with `--ignored`).
#[test]
#[ignore]
fn catmull_clark_and_loop_converge_ten_thousand_times() {
    for loop_scheme in [false, true] {
        let mut runner = TestRunner::new(Config::with_cases(10_000));
        runner
            .run(
                &(0u8..8, proptest::collection::vec(-0.03f64..0.03, 24 * 3)),
                |(s, jitter)| check_limit(s, loop_scheme, &jitter),
            )
            .unwrap();
    }
}
