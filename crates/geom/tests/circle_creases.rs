//! Seed 002's circle-preserving weight on Catmull–Clark surfaces along crease curves
//! (`catmull-clark-circle`): a creased square rim becomes a circle, straight creases and
//! smooth regions stay as plain Catmull–Clark.

use prism_geom::scheme::parse_pipeline;
use prism_geom::{DVec3, EdgeAttr, EdgeAttrs, EdgeKey, Pipeline, PolyMesh, primitives};

/// The cube of side 3 with the four edges around its top face creased (sharpness 10).
fn cube_with_creased_rim() -> (PolyMesh, EdgeAttrs) {
    let m = primitives::cube3();
    let mut attrs = EdgeAttrs::new();
    for (a, b) in [(4, 5), (5, 6), (6, 7), (7, 4)] {
        assert_eq!(m.positions[a].z, 3.0);
        attrs.insert(EdgeKey::new(a as u32, b as u32), EdgeAttr::creased(10.0));
    }
    (m, attrs)
}

fn run(m: &PolyMesh, attrs: &EdgeAttrs, p: &str) -> Pipeline {
    let mut pl = Pipeline::new(m.clone(), attrs.clone(), parse_pipeline(p).unwrap());
    pl.compute().unwrap();
    pl
}

/// Distances from the rim's axis of the vertices on creased edges of the last level.
fn rim_radii(p: &Pipeline) -> Vec<f64> {
    let lv = p.levels().last().unwrap();
    let mut vs: Vec<u32> = lv
        .edge_attrs
        .iter()
        .filter(|(_, a)| a.crease > 0.0)
        .flat_map(|(e, _)| [e.0, e.1])
        .collect();
    vs.sort_unstable();
    vs.dedup();
    let centre = DVec3::new(1.5, 1.5, 3.0);
    vs.iter()
        .map(|&v| {
            let q = lv.mesh.positions[v as usize];
            assert!((q.z - 3.0).abs() < 1e-12, "the rim stays in its plane");
            (q - centre).length()
        })
        .collect()
}

#[test]
fn a_creased_square_rim_becomes_a_circle() {
    let (m, attrs) = cube_with_creased_rim();
    let levels = 6;
    let circle = run(&m, &attrs, &vec!["catmull-clark-circle"; levels].join(","));
    let r = rim_radii(&circle);
    assert_eq!(r.len(), 4 << levels);
    // The square of circumradius R = 1.5√2 becomes the 2ⁿ·4-gon of radius R·Π cos(π/n_j).
    let mut want = 1.5 * 2f64.sqrt();
    for j in 0..levels {
        want *= (std::f64::consts::PI / (4 << j) as f64).cos();
    }
    for x in &r {
        assert!((x - want).abs() < 1e-12 * want, "{x} vs {want}");
    }
    // Plain Catmull–Clark makes the rim a cubic B-spline of the square: not a circle.
    let plain = run(&m, &attrs, &vec!["catmull-clark"; levels].join(","));
    let rp = rim_radii(&plain);
    let (lo, hi) = rp
        .iter()
        .fold((f64::MAX, f64::MIN), |(l, h), &x| (l.min(x), h.max(x)));
    // (1.375…1.414 measured: 2.8 % apart.)
    assert!(hi - lo > 0.02 * hi, "B-spline rim radii {lo}..{hi}");
}

#[test]
fn straight_creases_and_smooth_surfaces_are_plain_catmull_clark() {
    // Every edge creased: all creases are straight, every vertex a corner.
    let m = primitives::cube3();
    let all: EdgeAttrs = prism_geom::Topology::build(&m)
        .map(|t| {
            (0..t.num_edges())
                .map(|e| {
                    let (a, b) = t.edge_verts(&m, e);
                    (EdgeKey::new(a, b), EdgeAttr::creased(10.0))
                })
                .collect()
        })
        .unwrap();
    for attrs in [all, EdgeAttrs::new()] {
        let a = run(
            &m,
            &attrs,
            "catmull-clark-circle,catmull-clark-circle,catmull-clark-circle",
        );
        let b = run(&m, &attrs, "catmull-clark,catmull-clark,catmull-clark");
        assert!(a.levels()[3].mesh == b.levels()[3].mesh);
    }
    // A smooth surface without creases: nothing for the weight to act on.
    let t = primitives::torus(8, 6, 3.0, 1.0);
    let b = run(
        &t,
        &EdgeAttrs::new(),
        "catmull-clark-circle,catmull-clark-circle",
    );
    let c = run(&t, &EdgeAttrs::new(), "catmull-clark,catmull-clark");
    assert!(b.levels()[2].mesh == c.levels()[2].mesh);
}

#[test]
fn limit_masks_are_refused_for_the_circle_variant() {
    let (m, attrs) = cube_with_creased_rim();
    let e = prism_geom::limit_points(
        &m,
        &attrs,
        &Default::default(),
        prism_geom::PrimalScheme::CatmullClarkCircle,
    )
    .unwrap_err();
    assert!(e.to_string().contains("no limit masks"));
}
