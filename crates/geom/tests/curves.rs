//! The three curve schemes against what seed 002 promises (docs/algorithms/curves.md).

use glam::DVec2;
use prism_geom::curve::{CurveScheme, Polyline, presets};
use std::f64::consts::PI;

#[test]
fn method_1_maps_regular_polygons_to_points_on_one_circle() {
    for n in 3..=12 {
        let mut cur = presets::regular_polygon(n, 1.0);
        let mut r_expected = 1.0;
        for level in 0..6 {
            r_expected *= (PI / (n as f64 * (1 << level) as f64)).cos();
            cur = cur.refine(CurveScheme::Circle).unwrap();
            let radii: Vec<f64> = cur.points.iter().map(|p| p.length()).collect();
            let (lo, hi) = radii
                .iter()
                .fold((f64::MAX, f64::MIN), |(a, b), &r| (a.min(r), b.max(r)));
            assert!(
                (hi - lo) / hi < 1e-12,
                "n={n} level {}: spread {}",
                level + 1,
                (hi - lo) / hi
            );
            // The circle of radius R·Π cos(π/(n 2^i)) (Viète's product).
            assert!(
                (hi - r_expected).abs() / r_expected < 1e-12,
                "n={n}: {hi} vs {r_expected}"
            );
        }
        assert_eq!(cur.points.len(), n << 6);
    }
    // Plain Catmull–Clark does not keep the square's points on a circle.
    let cc = presets::regular_polygon(4, 1.0)
        .refine_levels(CurveScheme::CatmullClark, 6)
        .unwrap();
    let radii: Vec<f64> = cc.points.iter().map(|p| p.length()).collect();
    let spread = radii.iter().cloned().fold(f64::MIN, f64::max)
        - radii.iter().cloned().fold(f64::MAX, f64::min);
    assert!(spread > 0.01, "{spread}");
}

#[test]
fn method_1_is_the_b_spline_rule_on_straight_lines() {
    // θ₀ = 0 everywhere: ω = ¼ and method 1 equals Catmull–Clark exactly.
    let line = Polyline::new(
        (0..7)
            .map(|i| DVec2::new(i as f64 * 0.7 + (i * i) as f64 * 0.05, 0.0))
            .collect(),
        false,
    );
    for levels in 1..5 {
        assert_eq!(
            line.refine_levels(CurveScheme::Circle, levels).unwrap(),
            line.refine_levels(CurveScheme::CatmullClark, levels)
                .unwrap()
        );
    }
}

#[test]
fn catmull_clark_is_the_uniform_cubic_b_spline() {
    // One level: the masks (1, 6, 1)/8 and (1, 1)/2; the limit of vertex i is
    // (P_(i−1) + 4P_i + P_(i+1))/6, and vertex i of the input is vertex i·2^k of level k.
    let poly = Polyline::new(
        vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(2.0, 0.5),
            DVec2::new(3.0, 2.0),
            DVec2::new(1.0, 3.5),
            DVec2::new(-1.0, 1.5),
        ],
        true,
    );
    let one = poly.refine(CurveScheme::CatmullClark).unwrap();
    let p = &poly.points;
    for i in 0..5 {
        let want = (p[(i + 4) % 5] + 6.0 * p[i] + p[(i + 1) % 5]) / 8.0;
        assert!((one.points[2 * i] - want).length() < 1e-15);
        assert!((one.points[2 * i + 1] - 0.5 * (p[i] + p[(i + 1) % 5])).length() < 1e-15);
    }
    let deep = poly.refine_levels(CurveScheme::CatmullClark, 12).unwrap();
    for i in 0..5 {
        let limit = (p[(i + 4) % 5] + 4.0 * p[i] + p[(i + 1) % 5]) / 6.0;
        // The error shrinks by ¼ per level: (¼)^12 ≈ 6e-8 of the polygon's size.
        assert!((deep.points[i << 12] - limit).length() < 1e-6, "vertex {i}");
    }
}

/// `log|z| − b·φ` along the points, φ the unwrapped polar angle: constant on a logarithmic
/// spiral `r = A e^(bφ)` centred at the origin.
fn spiral_phase(points: &[DVec2], b: f64) -> Vec<f64> {
    let mut phi = points[0].y.atan2(points[0].x);
    let mut prev = points[0];
    points
        .iter()
        .map(|&z| {
            let mut d = z.y.atan2(z.x) - prev.y.atan2(prev.x);
            while d > PI {
                d -= 2.0 * PI;
            }
            while d < -PI {
                d += 2.0 * PI;
            }
            phi += d;
            prev = z;
            z.length().ln() - b * phi
        })
        .collect()
}

#[test]
fn method_2_keeps_log_spirals_with_their_centre_and_growth() {
    for (b, step) in [(0.15, 0.4), (-0.2, 0.3), (0.4, 1.0), (0.02, 0.05)] {
        let spiral = presets::log_spiral(40, b, step);
        let mut cur = spiral.clone();
        for level in 1..=4 {
            cur = cur.refine(CurveScheme::LogSpiral).unwrap();
            let n = cur.points.len();
            // The fixed ends are not on the refined spiral: look at the middle half.
            let mid = &cur.points[n / 4..3 * n / 4];
            let phase = spiral_phase(mid, b);
            let (lo, hi) = phase
                .iter()
                .fold((f64::MAX, f64::MIN), |(a, c), &x| (a.min(x), c.max(x)));
            assert!(
                hi - lo < 1e-9,
                "b={b} step={step} level {level}: spread {:.2e}",
                hi - lo
            );
            // Curvature along it is monotone (the spiral's κ ∝ e^(−bφ)).
            let k = Polyline::new(mid.to_vec(), false).curvature();
            let inner = &k[1..k.len() - 1];
            let rising = inner.windows(2).all(|w| w[1] > w[0]);
            let falling = inner.windows(2).all(|w| w[1] < w[0]);
            assert!(
                rising || falling,
                "b={b}: curvature not monotone at level {level}"
            );
        }
        // The other schemes leave the spiral.
        let cc = spiral.refine_levels(CurveScheme::CatmullClark, 3).unwrap();
        let n = cc.points.len();
        let phase = spiral_phase(&cc.points[n / 4..3 * n / 4], b);
        let spread = phase.iter().cloned().fold(f64::MIN, f64::max)
            - phase.iter().cloned().fold(f64::MAX, f64::min);
        if b.abs() > 0.1 {
            assert!(spread > 1e-6, "b={b}: {spread}");
        }
    }
}

#[test]
fn method_2_equals_method_1_on_isosceles_triples_and_keeps_circles() {
    for n in 3..=12 {
        let poly = presets::regular_polygon(n, 2.0);
        let a = poly.refine_levels(CurveScheme::LogSpiral, 4).unwrap();
        let b = poly.refine_levels(CurveScheme::Circle, 4).unwrap();
        for (p, q) in a.points.iter().zip(&b.points) {
            assert!((*p - *q).length() < 1e-13, "n={n}");
        }
    }
}

#[test]
fn curvature_and_evolute_of_a_circle() {
    let c = presets::regular_polygon(64, 3.0);
    let k = c.curvature();
    for (i, &x) in k.iter().enumerate() {
        // The circle through three vertices of the polygon is its circumcircle: κ = 1/3.
        assert!((x - 1.0 / 3.0).abs() < 1e-12, "{i}: {x}");
    }
    for e in c.evolute() {
        assert!(e.unwrap().length() < 1e-12);
    }
    // Clockwise: negative curvature.
    let mut cw = c.clone();
    cw.points.reverse();
    assert!(
        cw.curvature()
            .iter()
            .all(|&x| (x + 1.0 / 3.0).abs() < 1e-12)
    );
    let s = c.arc_length();
    assert!((s[63] - 63.0 * 2.0 * 3.0 * (PI / 64.0).sin()).abs() < 1e-12);
}
