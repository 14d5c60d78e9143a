//! The curve pieces the clipping builds: the point of a curve in a direction from the centre,
//! whether a §6.3 piece hooks, and the polynomial cubic that stands in for one that does.

use crate::freeform::bezier::RationalBezier;
use glam::DVec3;

/// The root of `(C(τ) − G)·w` on a curve through direction u from G (w normal to u in the
/// curve's plane): the curve point in direction u.
pub(super) fn at_direction(c: &RationalBezier, g: DVec3, u: DVec3) -> f64 {
    let n = (c.eval(0.0) - g).cross(c.eval(1.0) - g);
    let w = n.cross(u);
    let f = |tau: f64| (c.eval(tau) - g).dot(w);
    let (mut lo, mut hi) = (0.0, 1.0);
    let flo = f(lo) > 0.0;
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if (f(mid) > 0.0) == flo {
            lo = mid
        } else {
            hi = mid
        }
    }
    0.5 * (lo + hi)
}

/// Whether `c` (from the first to the last point of `chord`) hooks — leaves its start or
/// reaches its end backwards — or, for `near` > 0, nearly does: a leg shorter than `near` of
/// the chord.
pub(super) fn hooks(c: &RationalBezier, chord: DVec3, near: f64) -> bool {
    let p = &c.points;
    let least = near * chord.length();
    c.derivatives(0.0).d1.dot(chord) <= 0.0
        || c.derivatives(1.0).d1.dot(chord) <= 0.0
        || p[0].distance(p[1]) < least
        || p[3].distance(p[2]) < least
}

/// The polynomial cubic from `px` to `py` in the plane through `g` normal to `plane`, leaving
/// and reaching each end normal to its radius (towards the other end), legs `scale` × a third
/// of the chord: where a §6.3 piece hooks or nearly does. With `monotone` (the charts) each leg
/// is at most `|p − g|·tan(γ/3)`
/// (γ the angle the piece spans at g), so that its inner control points lie within the first
/// and last third of that angle: the control polygon, and so the curve (variation
/// diminishing), turns one way about g and meets every ray between its ends once — the radial
/// chart's side (`chart`) is a graph. Equal radii never meet the bound (a third of the chord is
/// at most r·tan(γ/3)).
pub(super) fn third_cubic(
    g: DVec3,
    plane: DVec3,
    px: DVec3,
    py: DVec3,
    scale: f64,
    monotone: bool,
) -> RationalBezier {
    let chord = py - px;
    let along = |p: DVec3| {
        let t = plane.cross(p - g).normalize();
        if t.dot(chord) < 0.0 { -t } else { t }
    };
    let l = scale * chord.length() / 3.0;
    let third = if monotone {
        ((px - g).angle_between(py - g) / 3.0).tan()
    } else {
        f64::INFINITY
    };
    let (lx, ly) = (
        l.min((px - g).length() * third),
        l.min((py - g).length() * third),
    );
    RationalBezier::polynomial(vec![px, px + lx * along(px), py - ly * along(py), py])
        .expect("finite points")
}

/// The angle between `x` and `y`, in [0, π], well conditioned near 0 and π.
pub(super) fn angle(x: DVec3, y: DVec3) -> f64 {
    x.cross(y).length().atan2(x.dot(y))
}
