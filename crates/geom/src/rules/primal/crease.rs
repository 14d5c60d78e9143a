//! Crease sharpness: rules, decay, the crease mask and transitional weights (seed 001 §2,
//! eq. 3–4; DeRose, Kass & Truong 1998), in the arithmetic OpenSubdiv uses (`Sdc::Crease`)
//! so that results agree to the last digits.
//!
//! Sharpness is `f32`, as in OpenSubdiv: 0 is smooth, ≥ 10 infinitely sharp, in between
//! semi-sharp. Per level a semi-sharp value decays to `s − 1` (uniform) or, with Chaikin, to
//! `¾ s + ¼ s̄ − 1` where `s̄` is the mean of the *other* semi-sharp edges at the vertex the
//! child edge touches. A vertex's rule comes from its own sharpness and the number of sharp
//! edges at it: 0 smooth, 1 dart, 2 crease, more (or a sharp vertex) corner. Where a rule
//! changes between a parent and its child (a semi-sharp feature running out), the masks of
//! both are blended with the fraction of this module's `fractional_weight`.

use crate::tags::CreaseMethod;
use glam::DVec3;

/// Sharpness of an infinitely sharp edge or vertex.
pub const INFINITE: f32 = 10.0;

#[inline]
pub fn is_sharp(s: f32) -> bool {
    s > 0.0
}
#[inline]
pub fn is_infinite(s: f32) -> bool {
    s >= INFINITE
}
#[inline]
pub fn is_semi_sharp(s: f32) -> bool {
    s > 0.0 && s < INFINITE
}

/// The subdivision rule of a vertex.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rule {
    Smooth,
    Dart,
    Crease,
    Corner,
}

/// Rule of a vertex with sharpness `vertex` and `sharp_edges` sharp incident edges.
#[inline]
pub fn vertex_rule(vertex: f32, sharp_edges: usize) -> Rule {
    if is_sharp(vertex) {
        return Rule::Corner;
    }
    match sharp_edges {
        0 => Rule::Smooth,
        1 => Rule::Dart,
        2 => Rule::Crease,
        _ => Rule::Corner,
    }
}

/// One level of decay with the uniform rule (also of every vertex sharpness).
#[inline]
pub fn decrement(s: f32) -> f32 {
    if s <= 0.0 {
        0.0
    } else if is_infinite(s) {
        INFINITE
    } else if s > 1.0 {
        s - 1.0
    } else {
        0.0
    }
}

/// Sum and count of the semi-sharp values among `sharpness` (in ring order, as OpenSubdiv
/// adds them).
#[inline]
pub fn semi_sharp_sum(sharpness: impl Iterator<Item = f32>) -> (f32, u32) {
    let mut sum = 0.0f32;
    let mut count = 0;
    for s in sharpness {
        if is_semi_sharp(s) {
            sum += s;
            count += 1;
        }
    }
    (sum, count)
}

/// Sharpness of the child of an edge of sharpness `s` at a vertex with `edges` incident
/// edges whose semi-sharp values sum to `semi_sum` over `semi_count` edges (`s` included).
#[inline]
pub fn child_edge_sharpness(
    method: CreaseMethod,
    s: f32,
    edges: usize,
    semi_sum: f32,
    semi_count: u32,
) -> f32 {
    if method == CreaseMethod::Uniform || edges < 2 {
        return decrement(s);
    }
    if s <= 0.0 {
        return 0.0;
    }
    if is_infinite(s) {
        return INFINITE;
    }
    let mut s = s;
    if semi_count > 1 {
        let others = (semi_sum - s) / (semi_count - 1) as f32;
        s = 0.75 * s + 0.25 * others;
    }
    s -= 1.0;
    if is_sharp(s) { s } else { 0.0 }
}

/// The weight of the parent's mask where a vertex's rule changes from parent to child
/// (the child's mask gets `1 − w`).
pub fn fractional_weight(
    method: CreaseMethod,
    parent_vertex: f32,
    child_vertex: f32,
    parent_edges: &[f32],
    child_edges: &[f32],
) -> f32 {
    let mut count = 0u32;
    let mut sum = 0.0f32;
    if is_sharp(parent_vertex) && !is_sharp(child_vertex) {
        count = 1;
        sum = parent_vertex;
    }
    for (&p, &c) in parent_edges.iter().zip(child_edges) {
        let transition = match method {
            CreaseMethod::Uniform => is_sharp(p) && p <= 1.0,
            CreaseMethod::Chaikin => is_sharp(p) && !is_sharp(c),
        };
        if transition {
            sum += p;
            count += 1;
        }
    }
    if count == 0 {
        return 0.0;
    }
    (sum / count as f32).min(1.0)
}

/// The first two sharp edges in ring order (the ends of a crease).
#[inline]
pub fn crease_ends(sharpness: &[f32]) -> [usize; 2] {
    let mut ends = [0; 2];
    let mut k = 0;
    for (i, &s) in sharpness.iter().enumerate() {
        if is_sharp(s) {
            ends[k] = i;
            k += 1;
            if k == 2 {
                break;
            }
        }
    }
    ends
}

/// The crease mask at v between its crease neighbours a and b: `(1 − ω) v + ω/2 (a + b)`,
/// with the cubic B-spline's `ω = ¼` or, for `circle`, seed 002's circle-preserving weight
/// of the crease's turning angle at v ([`crate::curve::circle_weight_of_cos`]; ¼ on a
/// straight crease and where an edge has no length).
#[inline]
pub fn crease_point(v: DVec3, a: DVec3, b: DVec3, circle: bool) -> DVec3 {
    let w = if circle {
        let (d1, d2) = (v - a, b - v);
        let den = d1.length() * d2.length();
        if den == 0.0 {
            0.25
        } else {
            crate::curve::circle_weight_of_cos(d1.dot(d2) / den)
        }
    } else {
        0.25
    };
    (1.0 - w) * v + 0.5 * w * (a + b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rules_and_decay() {
        assert_eq!(vertex_rule(0.0, 0), Rule::Smooth);
        assert_eq!(vertex_rule(0.0, 1), Rule::Dart);
        assert_eq!(vertex_rule(0.0, 2), Rule::Crease);
        assert_eq!(vertex_rule(0.0, 3), Rule::Corner);
        assert_eq!(vertex_rule(0.5, 0), Rule::Corner);
        assert_eq!(decrement(2.5), 1.5);
        assert_eq!(decrement(0.7), 0.0);
        assert_eq!(decrement(10.0), 10.0);
        // Chaikin: 3/4·2 + 1/4·1 − 1 = 0.75 for an edge of 2 beside an edge of 1.
        let c = child_edge_sharpness(CreaseMethod::Chaikin, 2.0, 4, 3.0, 2);
        assert_eq!(c, 0.75);
        assert_eq!(
            child_edge_sharpness(CreaseMethod::Uniform, 2.0, 4, 3.0, 2),
            1.0
        );
        // A crease of 0.5 running out at a dart: half crease, half smooth.
        let w = fractional_weight(CreaseMethod::Uniform, 0.0, 0.0, &[0.5, 0.0], &[0.0, 0.0]);
        assert_eq!(w, 0.5);
        assert_eq!(crease_ends(&[0.0, 1.0, 0.0, 2.0, 3.0]), [1, 3]);
    }
}
