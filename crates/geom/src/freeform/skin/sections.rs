//! Checking and preparing the sections of a skin (docs/algorithms/skin.md,
//! "Sections"): each is a closed planar polygon; its centre is the area centroid
//! in its plane, its normal the Newell normal oriented along the skinning direction (the point
//! list reversed when that flips it, so every section runs counter-clockwise about its normal),
//! and its curve the closed C2 spline through its points, or open C2 pieces between the
//! vertices marked as corners.

use super::{SectionInput, SkinError};
use crate::analysis::face_grid::FaceGrid;
use crate::freeform::spline::{self, Cubic};
use glam::{DVec2, DVec3};
use std::collections::HashMap;
use std::f64::consts::TAU;

/// Largest distance of a point from its section's plane, as a fraction of the section's
/// size (bounding-box diagonal).
pub const PLANARITY_TOLERANCE: f64 = 1e-6;

/// A section ready for skinning.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    /// The points, counter-clockwise about `normal`.
    pub points: Vec<DVec3>,
    /// The input index of each point.
    pub original: Vec<usize>,
    /// Whether the curve has a corner at each point.
    pub corner: Vec<bool>,
    pub centre: DVec3,
    pub normal: DVec3,
    /// `points.len()` cubic pieces, piece j from point j to point j + 1.
    pub curve: Vec<Cubic>,
}

/// A frame of the plane with normal `n`.
fn plane_frame(n: DVec3) -> (DVec3, DVec3) {
    let x = n.any_orthonormal_vector();
    (x, n.cross(x))
}

/// Whether segments ab and cd cross properly (each one's ends strictly on both sides of the
/// other). Orientations within `eps` (an area) count as on the line: points along one straight
/// side of a section, turned in space, are collinear up to rounding and must not cross.
fn segments_cross(a: DVec2, b: DVec2, c: DVec2, d: DVec2, eps: f64) -> bool {
    let orient = |p: DVec2, q: DVec2, r: DVec2| {
        let o = (q - p).perp_dot(r - p);
        if o.abs() <= eps { 0.0 } else { o }
    };
    let (o1, o2) = (orient(a, b, c), orient(a, b, d));
    let (o3, o4) = (orient(c, d, a), orient(c, d, b));
    o1 * o2 < 0.0 && o3 * o4 < 0.0
}

/// Checks section `k` and computes its plane, centre and orientation-free data.
pub(super) fn check(k: usize, s: &SectionInput) -> Result<(Vec<DVec3>, DVec3, DVec3), SkinError> {
    let p = &s.points;
    if p.len() < 3 {
        return Err(SkinError::TooFewPoints {
            section: k,
            points: p.len(),
        });
    }
    if let Some(i) = p.iter().position(|q| !q.is_finite()) {
        return Err(SkinError::NonFinite {
            section: k,
            point: i,
        });
    }
    let (lo, hi) = p
        .iter()
        .fold((p[0], p[0]), |(lo, hi), &q| (lo.min(q), hi.max(q)));
    let size = (hi - lo).length();
    // Repeated points by cells of side 4e-12 size: each point meets the few before it in its
    // cell and the cells beside it, not all of them.
    let tol = 1e-12 * size;
    let mut cells: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
    for (j, &q) in p.iter().enumerate() {
        let c = ((q - lo) / (4.0 * tol).max(f64::MIN_POSITIVE))
            .floor()
            .as_i64vec3()
            .to_array();
        let earlier = (0..27)
            .flat_map(|k| {
                let near = [c[0] + k % 3 - 1, c[1] + (k / 3) % 3 - 1, c[2] + k / 9 - 1];
                cells.get(&near).into_iter().flatten()
            })
            .copied()
            .filter(|&i| (p[i] - q).length() <= tol)
            .min();
        if let Some(i) = earlier {
            return Err(SkinError::RepeatedPoint {
                section: k,
                a: i,
                b: j,
            });
        }
        cells.entry(c).or_default().push(j);
    }
    if let Some(&c) = s.corners.iter().find(|&&c| c >= p.len()) {
        return Err(SkinError::CornerOutOfRange {
            section: k,
            corner: c,
            points: p.len(),
        });
    }
    let o = p[0];
    let mut newell = DVec3::ZERO;
    for i in 0..p.len() {
        newell += (p[i] - o).cross(p[(i + 1) % p.len()] - o);
    }
    let normal = newell.normalize_or_zero();
    if normal == DVec3::ZERO {
        return Err(SkinError::NoArea { section: k });
    }
    let mean = p.iter().sum::<DVec3>() / p.len() as f64;
    let (worst, dist) = p
        .iter()
        .map(|q| (q - mean).dot(normal).abs())
        .enumerate()
        .fold((0, 0.0), |a, (i, d)| if d > a.1 { (i, d) } else { a });
    if dist > PLANARITY_TOLERANCE * size {
        return Err(SkinError::NonPlanar {
            section: k,
            point: worst,
            distance: dist,
            tolerance: PLANARITY_TOLERANCE * size,
        });
    }
    let (x, y) = plane_frame(normal);
    let flat: Vec<DVec2> = p
        .iter()
        .map(|q| DVec2::new((q - mean).dot(x), (q - mean).dot(y)))
        .collect();
    let n = flat.len();
    // Sides that cross: each side against those whose boxes meet its own on a grid.
    let eps = 1e-12 * size * size;
    // Padded by the tolerance, so that sides the test finds touching are tried.
    let side_box = |i: usize| {
        let (a, b) = (flat[i], flat[(i + 1) % n]);
        let pad = DVec2::splat(tol);
        ((a.min(b) - pad).extend(0.0), (a.max(b) + pad).extend(0.0))
    };
    let grid = FaceGrid::of_boxes((0..n).map(side_box).collect(), n as f64);
    for i in 0..n {
        let mut first: Option<usize> = None;
        grid.for_each_overlapping(side_box(i), |j| {
            let apart = j >= i + 2 && !(i == 0 && j == n - 1);
            if apart
                && first.is_none_or(|f| j < f)
                && segments_cross(flat[i], flat[(i + 1) % n], flat[j], flat[(j + 1) % n], eps)
            {
                first = Some(j);
            }
        });
        if let Some(j) = first {
            return Err(SkinError::SelfIntersecting {
                section: k,
                a: i,
                b: j,
            });
        }
    }
    // Area centroid in the plane.
    let (mut area, mut c) = (0.0, DVec2::ZERO);
    for i in 0..n {
        let (a, b) = (flat[i], flat[(i + 1) % n]);
        let w = a.perp_dot(b);
        area += w;
        c += w * (a + b);
    }
    let c = c / (3.0 * area);
    let centre = mean + c.x * x + c.y * y;
    Ok((p.clone(), centre, normal))
}

/// The section curve: the closed C2 spline through the points, or open C2 pieces between
/// corners (a polygon when every point is one).
pub(super) fn curve(points: &[DVec3], corner: &[bool]) -> Vec<Cubic> {
    let n = points.len();
    let Some(first) = corner.iter().position(|&c| c) else {
        return spline::closed(points);
    };
    let mut out = vec![[DVec3::ZERO; 4]; n];
    let mut start = first;
    loop {
        let mut end = (start + 1) % n;
        while !corner[end] {
            end = (end + 1) % n;
        }
        let len = (end + n - start - 1) % n + 2;
        let chain: Vec<DVec3> = (0..len).map(|i| points[(start + i) % n]).collect();
        for (i, seg) in spline::open(&chain).into_iter().enumerate() {
            out[(start + i) % n] = seg;
        }
        start = end;
        if start == first {
            break;
        }
    }
    out
}

/// Orients the checked sections along the skinning direction and builds their curves.
pub(super) fn prepare(
    input: &[SectionInput],
    checked: Vec<(Vec<DVec3>, DVec3, DVec3)>,
) -> Vec<Section> {
    let m = checked.len();
    let centres: Vec<DVec3> = checked.iter().map(|c| c.1).collect();
    checked
        .into_iter()
        .enumerate()
        .map(|(k, (points, centre, mut normal))| {
            let dir = centres[(k + 1).min(m - 1)] - centres[k.saturating_sub(1)];
            let n = points.len();
            let s = &input[k];
            let mut corner = vec![s.polygon; n];
            for &c in &s.corners {
                corner[c] = true;
            }
            let mut original: Vec<usize> = (0..n).collect();
            let mut points = points;
            if normal.dot(dir) < 0.0 {
                normal = -normal;
                points.reverse();
                corner.reverse();
                original.reverse();
            }
            let curve = curve(&points, &corner);
            Section {
                points,
                original,
                corner,
                centre,
                normal,
                curve,
            }
        })
        .collect()
}

/// Samples a piece to check that the polar angle runs monotonically along it.
const STAR_SAMPLES: usize = 16;

/// Checks that section k's curve turns monotonically about its centre (star-shaped: every ray
/// from the centre meets it once, so it cannot cross itself either), sampled
/// [`STAR_SAMPLES`] times a piece.
pub(super) fn check_star(k: usize, s: &Section) -> Result<(), SkinError> {
    let x = s.normal.any_orthonormal_vector();
    let angle = |p: DVec3| {
        let d = p - s.centre;
        d.dot(s.normal.cross(x)).atan2(d.dot(x))
    };
    let mut total = 0.0;
    let mut prev = angle(s.curve[0][0]);
    for (i, piece) in s.curve.iter().enumerate() {
        for j in 1..=STAR_SAMPLES {
            let a = angle(spline::eval(piece, j as f64 / STAR_SAMPLES as f64));
            let step = (a - prev + TAU / 2.0).rem_euclid(TAU) - TAU / 2.0;
            if step <= 0.0 {
                return Err(SkinError::NotStarShaped {
                    section: k,
                    point: s.original[i],
                });
            }
            total += step;
            prev = a;
        }
    }
    if (total - TAU).abs() > 1e-6 {
        return Err(SkinError::NotStarShaped {
            section: k,
            point: s.original[0],
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first pair of crossing sides as a scan of every pair finds it.
    fn crossing_by_scan(flat: &[DVec2], eps: f64) -> Option<(usize, usize)> {
        let n = flat.len();
        (0..n).find_map(|i| {
            (i + 2..n)
                .filter(|&j| !(i == 0 && j == n - 1))
                .find(|&j| {
                    segments_cross(flat[i], flat[(i + 1) % n], flat[j], flat[(j + 1) % n], eps)
                })
                .map(|j| (i, j))
        })
    }

    /// Wavy star-shaped sections with two points swapped or one repeated, at several
    /// places: the grid's checks name what a scan of every pair names.
    #[test]
    fn the_grid_checks_name_what_a_scan_names() {
        for n in [7usize, 40, 301] {
            let ring: Vec<DVec3> = (0..n)
                .map(|i| {
                    let a = TAU * i as f64 / n as f64;
                    let r = 1.0 + 0.3 * (5.0 * a).sin();
                    DVec3::new(r * a.cos(), r * a.sin(), 0.4)
                })
                .collect();
            for k in [0, n / 3, n - 2] {
                let mut swapped = ring.clone();
                swapped.swap(k, k + 1);
                let size = 4.0;
                let flat: Vec<DVec2> = swapped.iter().map(|p| p.truncate()).collect();
                let expected = crossing_by_scan(&flat, 1e-12 * size * size);
                let input = SectionInput {
                    points: swapped,
                    ..SectionInput::default()
                };
                match check(2, &input) {
                    Err(SkinError::SelfIntersecting { section: 2, a, b }) => {
                        let (i, j) = expected.expect("the scan finds a crossing");
                        // The frame's own origin differs from the test's; the pair is the same.
                        assert_eq!((a, b), (i, j), "n = {n}, swapped at {k}");
                    }
                    other => assert!(expected.is_none(), "n = {n}, k = {k}: {other:?}"),
                }
                let mut twice = ring.clone();
                twice[(k + n / 2) % n] = twice[k];
                let (a, b) = (k.min((k + n / 2) % n), k.max((k + n / 2) % n));
                let input = SectionInput {
                    points: twice,
                    ..SectionInput::default()
                };
                assert!(
                    matches!(check(2, &input), Err(SkinError::RepeatedPoint { section: 2, a: x, b: y }) if (x, y) == (a, b)),
                    "n = {n}, k = {k}"
                );
            }
        }
    }
}
