//! The curve network of a skin (seed 003 §2 steps 1–4;
//! docs/algorithms/skin.md, "The network"): the virtual trajectory between neighbouring section
//! centres (a rational quadratic, for display), the sweep of each section into the next plane
//! by the minimal rotation `R(N_k → N_(k+1))`, the correspondence over all n shifts — by shape
//! (the default, [`Pairing::Shape`]) or by the paper's least total twist ([`Pairing::Paper`]) —
//! and the C2 chains through corresponding vertices.

use super::SkinError;
use super::sections::Section;
use crate::freeform::RationalBezier;
use crate::freeform::spline::{self, Cubic};
use glam::{DQuat, DVec2, DVec3};

/// The minimal rotation taking unit `a` to unit `b` (a U-turn turns about a perpendicular).
pub fn rotation(a: DVec3, b: DVec3, d: DVec3) -> DQuat {
    let axis = a.cross(b);
    let s = axis.length();
    let c = a.dot(b);
    if s > 1e-15 {
        return DQuat::from_axis_angle(axis / s, s.atan2(c));
    }
    if c > 0.0 {
        return DQuat::IDENTITY;
    }
    let mut p = a.cross(d);
    if p.length_squared() < 1e-30 {
        p = a.any_orthonormal_vector();
    }
    DQuat::from_axis_angle(p.normalize(), std::f64::consts::PI)
}

/// Section `a` swept into section `b`'s plane: `C_b + R (V − C_a)`.
pub fn sweep(a: &Section, b: &Section) -> Vec<DVec3> {
    let r = rotation(a.normal, b.normal, b.centre - a.centre);
    a.points
        .iter()
        .map(|&v| b.centre + r * (v - a.centre))
        .collect()
}

/// How the vertices of neighbouring sections are paired (docs/algorithms/skin.md,
/// "Correspondence").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Pairing {
    /// By shape: the shift whose swept section, turned about the normal by its best angle
    /// (within a quarter turn), lies closest to the next in the least-squares sense (a
    /// Procrustes match); near-ties by the least total twist. A steadily turning section keeps
    /// its natural pairing at any turn a section up to a quarter turn.
    #[default]
    Shape,
    /// The paper's criterion: the least total twist `Σ ∠(V′_i − C, V_(i+σ) − C)`. Past a
    /// steady turn of 180°/n a section it pairs corners with sides (the skin crumples).
    Paper,
}

/// The shift σ pairing swept vertex i with vertex (i + σ) mod n of the next section by
/// `pairing`, and its total twist (radians).
pub fn pair(swept: &[DVec3], next: &Section, pairing: Pairing) -> (usize, f64) {
    match pairing {
        Pairing::Paper => least_twist(swept, next),
        Pairing::Shape => best_match(swept, next),
    }
}

/// The total twist `Σ ∠(V′_i − C, V_(i+σ) − C)` of shift σ and its sum of squared distances;
/// none once the partial sum is past `bound` (every term is ≥ 0, so the whole would be too).
fn twist_of(swept: &[DVec3], next: &Section, s: usize, bound: f64) -> Option<(f64, f64)> {
    let n = swept.len();
    let c = next.centre;
    let (mut twist, mut dist) = (0.0, 0.0);
    for (i, &v) in swept.iter().enumerate() {
        let (a, b) = (v - c, next.points[(i + s) % n] - c);
        twist += a.cross(b).length().atan2(a.dot(b));
        if twist > bound {
            return None;
        }
        dist += (v - next.points[(i + s) % n]).length_squared();
    }
    Some((twist, dist))
}

/// The shift of least Procrustes residual: with the points as complex numbers about the
/// centre in the next section's plane (z the swept section's, w the next's),
/// `residual(σ) = Σ|z_i|² + Σ|w_j|² − 2|Σ conj(z_i) w_(i+σ)|`, the squared distance left after
/// the best rotation `arg Σ conj(z_i) w_(i+σ)` about the normal. Only shifts whose best
/// rotation is within a quarter turn compete (a section turned further from its neighbour
/// cannot be told from its own symmetric images: an ellipse matches itself turned by a half
/// turn); residuals within [`NEAR_TIE`] of the sections' scale are ties, broken by the least
/// total twist, then the sum of squared distances, then the smaller σ.
fn best_match(swept: &[DVec3], next: &Section) -> (usize, f64) {
    let (z, w) = planar(swept, next);
    let scale: f64 = z.iter().chain(&w).map(|p| p.length_squared()).sum();
    let sums = correlation(&z, &w);
    let candidates: Vec<(usize, f64)> = sums
        .iter()
        .enumerate()
        .filter(|(_, sum)| sum.x >= 0.0)
        .map(|(s, sum)| (s, scale - 2.0 * sum.length()))
        .collect();
    let least = candidates.iter().map(|c| c.1).fold(f64::INFINITY, f64::min);
    if !least.is_finite() {
        return least_twist(swept, next);
    }
    let ties: Vec<usize> = candidates
        .iter()
        .filter(|c| c.1 <= least + NEAR_TIE * scale)
        .map(|c| c.0)
        .collect();
    let seed = ties
        .iter()
        .copied()
        .max_by(|&a, &b| sums[a].x.total_cmp(&sums[b].x));
    least_twist_among(swept, next, ties.into_iter(), seed)
}

/// The swept and the next section's points as plane vectors about the next centre.
fn planar(swept: &[DVec3], next: &Section) -> (Vec<DVec2>, Vec<DVec2>) {
    let c = next.centre;
    let x = next.normal.any_orthonormal_vector();
    let y = next.normal.cross(x);
    let flat = |p: DVec3| DVec2::new((p - c).dot(x), (p - c).dot(y));
    (
        swept.iter().map(|&p| flat(p)).collect(),
        next.points.iter().map(|&p| flat(p)).collect(),
    )
}

/// Sections of at least this many points are correlated by FFT.
const FFT_FROM: usize = 256;

/// `Σ_i conj(z_i) w_(i+s)` (as re, im) for every shift s: directly, O(n²), for sections of
/// fewer than [`FFT_FROM`] points; else as the inverse FFT of `conj(Z)·W` (the circular
/// cross-correlation, O(n log n); `rustfft`), which agrees to rounding (about 1e-16 of the
/// sections' scale a term).
fn correlation(z: &[DVec2], w: &[DVec2]) -> Vec<DVec2> {
    use rustfft::{FftPlanner, num_complex::Complex64};
    let n = z.len();
    if n < FFT_FROM {
        return (0..n)
            .map(|s| {
                let mut sum = DVec2::ZERO;
                for (i, a) in z.iter().enumerate() {
                    let b = w[(i + s) % n];
                    sum += DVec2::new(a.dot(b), a.perp_dot(b));
                }
                sum
            })
            .collect();
    }
    let mut planner = FftPlanner::<f64>::new();
    let (forward, inverse) = (planner.plan_fft_forward(n), planner.plan_fft_inverse(n));
    let complex =
        |p: &[DVec2]| -> Vec<Complex64> { p.iter().map(|q| Complex64::new(q.x, q.y)).collect() };
    let (mut zf, mut wf) = (complex(z), complex(w));
    forward.process(&mut zf);
    forward.process(&mut wf);
    // Σ_i conj(z_i) w_(i+s) = IFFT(conj(Z)·W)_s / n.
    let mut c: Vec<Complex64> = zf.iter().zip(&wf).map(|(a, b)| a.conj() * b).collect();
    inverse.process(&mut c);
    c.iter()
        .map(|x| DVec2::new(x.re, x.im) / n as f64)
        .collect()
}

/// Procrustes residuals closer than this share of the sections' scale (`Σ|z|² + Σ|w|²`) are
/// ties. A shape match is decided only when it is clear; sections that match about equally
/// under several shifts (a regular polygon, an ellipse against a slightly different one) are
/// paired by the least twist among them.
pub const NEAR_TIE: f64 = 1e-3;

/// The shift σ pairing swept vertex i with vertex (i + σ) mod n of the next section: the
/// least total twist `Σ ∠(V'_i − C, V_(i+σ) − C)` over all n shifts; ties by the smaller sum of
/// squared distances, then the smaller σ.
pub fn least_twist(swept: &[DVec3], next: &Section) -> (usize, f64) {
    // Long sections: the shift that aligns them best (the largest Σ a_i·b_(i+σ), by FFT)
    // first, so that the others' sums stop early.
    let seed = (swept.len() >= FFT_FROM).then(|| {
        let (z, w) = planar(swept, next);
        let sums = correlation(&z, &w);
        (0..sums.len())
            .max_by(|&a, &b| sums[a].x.total_cmp(&sums[b].x))
            .unwrap_or(0)
    });
    least_twist_among(swept, next, 0..swept.len(), seed)
}

/// The shift of least total twist among `shifts` (ascending) and its twist; ties by the smaller
/// sum of squared distances, then the earlier shift. `seed`, one of the shifts, is summed
/// first, to bound the others from the start.
fn least_twist_among(
    swept: &[DVec3],
    next: &Section,
    shifts: impl Iterator<Item = usize>,
    seed: Option<usize>,
) -> (usize, f64) {
    let seeded = seed
        .and_then(|s| twist_of(swept, next, s, f64::INFINITY))
        .map_or(f64::INFINITY, |t| t.0);
    let mut best = (0usize, f64::INFINITY, f64::INFINITY);
    for s in shifts {
        // A shift whose twist passes the best (or the seed's) by more than the tie tolerance
        // can neither win nor tie: its sum stops there (x − 1e-12(1 + x) grows with x, so a
        // partial sum past it means the whole is). Most shifts stop after a few terms.
        let bound = (best.1.min(seeded) + 1e-12) / (1.0 - 1e-12);
        let Some((twist, dist)) = twist_of(swept, next, s, bound) else {
            continue;
        };
        let tol = 1e-12 * (1.0 + twist);
        if twist < best.1 - tol || ((twist - best.1).abs() <= tol && dist < best.2) {
            best = (s, twist, dist);
        }
    }
    (best.0, best.1)
}

/// The virtual trajectory from section `a`'s centre to `b`'s (§10.3): a rational quadratic
/// through the tangent lines' meeting point with weight cos(½∠(N_a, N_b)), a cubic Hermite
/// when they meet behind a section, a line when they are parallel.
pub fn trajectory(a: &Section, b: &Section) -> RationalBezier {
    let (c1, c2, n1, n2) = (a.centre, b.centre, a.normal, b.normal);
    let d = c2 - c1;
    let bb = n1.dot(n2);
    let (e, f) = (n1.dot(d), n2.dot(d));
    let den = 1.0 - bb * bb;
    let l = d.length();
    let hermite = || {
        RationalBezier::polynomial(vec![c1, c1 + l / 3.0 * n1, c2 - l / 3.0 * n2, c2])
            .expect("finite points")
    };
    if den <= 1e-12 {
        return if (n1 - d / l).length() < 1e-9 {
            RationalBezier::polynomial(vec![c1, c2]).expect("finite points")
        } else {
            hermite()
        };
    }
    let s = (e - bb * f) / den;
    let t = (bb * e - f) / den;
    if s <= 0.0 || t >= 0.0 {
        return hermite();
    }
    let q = 0.5 * ((c1 + s * n1) + (c2 + t * n2));
    let w = ((1.0 + bb) / 2.0).sqrt();
    RationalBezier::new(vec![c1, q, c2], vec![1.0, w, 1.0]).expect("positive weights")
}

/// The chains: `shifts[k]` is σ between sections k and k + 1; chain i runs through vertex
/// `(i + σ₀ + … + σ_(k−1)) mod n` of section k. Returns, per chain, its K − 1 cubic pieces,
/// and per section the offset of chain 0.
pub fn chains(sections: &[Section], shifts: &[usize]) -> (Vec<Vec<Cubic>>, Vec<usize>) {
    let n = sections[0].points.len();
    let mut offset = vec![0usize; sections.len()];
    for k in 1..sections.len() {
        offset[k] = (offset[k - 1] + shifts[k - 1]) % n;
    }
    let chains = (0..n)
        .map(|i| {
            let q: Vec<DVec3> = sections
                .iter()
                .zip(&offset)
                .map(|(s, &o)| s.points[(i + o) % n])
                .collect();
            spline::open(&q)
        })
        .collect();
    (chains, offset)
}

/// Checks that every chain leaves and reaches every section forwards: its tangent there (the
/// leg of its cubic) has a positive component along the section's normal, which points along
/// the skinning direction. A skin through sections A, B, A turns back at B (the chains stop
/// there: their tangent is zero), and a section tilted past its neighbours meets its chains
/// against the direction; either would fold the patches on both sides (and, at a zero
/// tangent, leave them with no normal).
pub fn check_forward(sections: &[Section], chains: &[Vec<Cubic>]) -> Result<(), SkinError> {
    let m = sections.len();
    for (i, chain) in chains.iter().enumerate() {
        for (k, s) in sections.iter().enumerate() {
            let leg = if k + 1 < m {
                chain[k][1] - chain[k][0]
            } else {
                chain[k - 1][3] - chain[k - 1][2]
            };
            let size = (s.points[0] - s.centre).length();
            // NaN (no leg) fails as a zero leg does.
            let forward = leg.dot(s.normal);
            if forward.is_nan() || forward <= 1e-9 * size {
                return Err(SkinError::TurnsBack {
                    section: k,
                    chain: i,
                });
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The FFT's correlation is the direct sum's, to rounding, for every shift.
    #[test]
    fn the_fft_correlation_is_the_direct_sum() {
        let n = FFT_FROM + 45;
        let point = |i: usize, k: f64| {
            let x = i as f64;
            DVec2::new((k * x).sin() + 0.3 * (2.0 * x).cos(), (1.7 * k * x).cos())
        };
        let z: Vec<DVec2> = (0..n).map(|i| point(i, 0.37)).collect();
        let w: Vec<DVec2> = (0..n).map(|i| point(i, 0.91)).collect();
        let fast = correlation(&z, &w);
        for (s, f) in fast.iter().enumerate() {
            let mut sum = DVec2::ZERO;
            for (i, a) in z.iter().enumerate() {
                let b = w[(i + s) % n];
                sum += DVec2::new(a.dot(b), a.perp_dot(b));
            }
            assert!(
                (*f - sum).length() < 1e-9 * n as f64,
                "shift {s}: {f} against {sum}"
            );
        }
    }
}
