use super::*;

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

#[test]
fn collinear_centres_keep_the_ends() {
    let l = layout(&[v(0., 0., 0.), v(6., 0., 0.), v(3., 0., 0.)], 1e-9);
    assert_eq!(l.kept, vec![0, 1]);
    assert_eq!(l.removed, vec![2]);
    assert_eq!(l.edges.len(), 1);
    assert!(l.facets.is_empty());
}

#[test]
fn coplanar_centres_give_a_polygon_and_two_lids() {
    // A square with a centre in the middle and one on a side.
    let c = [
        [0., 0.],
        [3., 0.],
        [3., 3.],
        [0., 3.],
        [1.5, 1.5],
        [1.5, 0.],
    ]
    .map(|[x, y]| v(x, y, 0.));
    let l = layout(&c, 1e-9);
    assert_eq!(l.kept, vec![0, 1, 2, 3]);
    assert_eq!(l.removed, vec![4, 5]);
    assert_eq!(l.edges.len(), 4);
    assert_eq!(l.facets.len(), 2);
    assert_eq!(l.neighbours(0), vec![1, 3]);
    for e in &l.edges {
        let mid = 0.5 * (c[e.a] + c[e.b]);
        assert!((mid - v(1.5, 1.5, 0.)).dot(e.outward) > 0.0);
    }
}

#[test]
fn a_tetrahedron_of_centres_with_one_inside() {
    // The corners of a right tetrahedron, and a point inside it.
    let c = [
        DVec3::ZERO,
        4.0 * DVec3::X,
        4.0 * DVec3::Y,
        4.0 * DVec3::Z,
        DVec3::splat(0.8),
    ];
    let l = layout(&c, 1e-9);
    assert_eq!(l.kept, vec![0, 1, 2, 3]);
    assert_eq!(l.removed, vec![4]);
    assert_eq!(l.edges.len(), 6);
    assert_eq!(l.facets.len(), 4);
    for f in &l.facets {
        assert_eq!(f.corners.len(), 3);
        // Counter-clockwise about the outward normal.
        let [a, b, cc] = [c[f.corners[0]], c[f.corners[1]], c[f.corners[2]]];
        assert!((b - a).cross(cc - a).dot(f.normal) > 0.0);
        assert!((c[4] - a).dot(f.normal) < 0.0);
    }
}

#[test]
fn a_cube_of_centres_has_square_facets() {
    let mut c = Vec::new();
    for i in 0..8 {
        c.push(v(
            3.0 * (i & 1) as f64,
            3.0 * ((i >> 1) & 1) as f64,
            3.0 * ((i >> 2) & 1) as f64,
        ));
    }
    let l = layout(&c, 1e-9);
    assert_eq!(l.kept.len(), 8);
    assert_eq!(l.facets.len(), 6);
    assert!(l.facets.iter().all(|f| f.corners.len() == 4));
    assert_eq!(l.edges.len(), 12);
    assert!(l.edges.iter().all(|e| {
        let [p, q] = e.facets.unwrap();
        p != q
    }));
}

#[test]
fn a_centre_a_hair_off_its_neighbours_line_is_swallowed() {
    let c = [v(0., 0., 0.), v(3., 0.05, 0.), v(6., 0., 0.)];
    let r = [1.7; 3];
    let l = layout_swallowing(&c, &r, (0..c.len()).collect(), 1e-9, 0.1);
    assert_eq!(l.kept, vec![0, 2]);
    assert_eq!(l.removed, vec![1]);
    // Well off the line it stays.
    let c = [v(0., 0., 0.), v(3., 0.5, 0.), v(6., 0., 0.)];
    assert_eq!(
        layout_swallowing(&c, &r, (0..c.len()).collect(), 1e-9, 0.1).kept,
        vec![0, 1, 2]
    );
    // Two close centres do not take each other out.
    let c = [
        v(0., 0., 0.),
        v(4., 0., 0.),
        v(4.05, 0.05, 0.),
        v(2., 3., 0.),
    ];
    let l = layout_swallowing(&c, &[1.7; 4], (0..c.len()).collect(), 1e-9, 0.1);
    assert_eq!(l.kept.len(), 3, "{l:?}");
    // A centre just above the middle of a facet goes; one at a corner stays.
    let c = [
        v(0., 0., 0.),
        v(4., 0., 0.),
        v(0., 4., 0.),
        v(0., 0., 4.),
        v(1.4, 1.4, 1.4),
    ];
    let l = layout_swallowing(&c, &[1.7; 5], (0..c.len()).collect(), 1e-9, 0.1);
    assert_eq!(l.kept, vec![0, 1, 2, 3]);
}

/// Centres for the comparisons below: random in a ball, or drawn from a 3 × 3 × 3 lattice
/// (many on one facet, on facet edges and inside).
fn centres(seed: u64, n: usize, lattice: bool) -> Vec<DVec3> {
    let mut s = seed;
    let mut next = move || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut c: Vec<DVec3> = Vec::new();
    while c.len() < n {
        let p = if lattice {
            let k = |x: f64| 2.0 * (3.0 * x).floor();
            v(k(next()), k(next()), k(next()))
        } else {
            5.0 * v(2.0 * next() - 1.0, 2.0 * next() - 1.0, 2.0 * next() - 1.0)
        };
        if c.iter().all(|q| q.distance(p) > 1e-6) {
            c.push(p);
        }
    }
    c
}

/// Gift wrapping finds the facets the search over every triple finds, bit for bit and in
/// the same order, on random centres and on lattice centres with many per facet.
#[test]
fn the_wrap_finds_the_facets_of_the_search() {
    let mut wrapped = 0;
    for seed in 0..60u64 {
        for lattice in [false, true] {
            let n = if lattice {
                6 + (seed as usize % 20)
            } else {
                4 + (seed as usize % 37)
            };
            let c = centres(seed, n, lattice);
            let extent = c.iter().map(|p| p.distance(c[0])).fold(0.0, f64::max);
            let tol = 1e-9 * extent;
            let l = layout(&c, tol);
            if l.facets.len() <= 2 {
                continue; // collinear or coplanar: no wrap
            }
            let search = exhaustive(&c, tol, extent);
            let wrap = super::super::wrap::facets(&c, tol, extent);
            assert_eq!(
                wrap.as_ref(),
                Some(&search),
                "seed {seed} lattice {lattice}"
            );
            assert_eq!(l.facets, search);
            wrapped += 1;
        }
    }
    assert!(wrapped > 100, "{wrapped}");
}

/// A centre's distance to the hull of the others is its distance to the hull of the
/// centres around it ([`Layout::around`]).
#[test]
fn the_distance_to_the_rest_needs_only_the_centres_around() {
    for seed in 0..40u64 {
        for lattice in [false, true] {
            let n = if lattice {
                5 + seed as usize % 20
            } else {
                5 + seed as usize % 30
            };
            let c = centres(seed + 100, n, lattice);
            let tol = 1e-9 * 10.0;
            let l = layout(&c, tol);
            for &i in &l.kept {
                let rest: Vec<usize> = l.kept.iter().copied().filter(|&j| j != i).collect();
                let all = hull_distance(c[i], &c, &layout_of(&c, &rest, tol));
                let near = hull_distance(c[i], &c, &layout_of(&c, &l.around(i), tol));
                assert!(
                    (all - near).abs() <= 1e-12 * (1.0 + all),
                    "seed {seed} lattice {lattice} centre {i}: {all} against {near}"
                );
            }
        }
    }
}
