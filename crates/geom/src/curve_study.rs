//! Seed 002 §4: the parameter study of fig. 6–8. The four-point polyline of fig. 6 (turning
//! angles θ₁ at P₁ and θ₂ at P₂, edge lengths l₁, l₂ and l₃ = 1) is refined by each curve
//! scheme, and the curvature of the refined curve between the images of P₁ and P₂ is judged
//! by how monotone it is — the paper's "beautiful" curve has a curvature that changes
//! monotonically. The paper shows the result by dimensional stacking (LeBlanc, Ward and
//! Wittels 1990): θ₁, θ₂ on the outer axes, l₁, l₂ on the inner ones, coloured where the
//! log-spiral rule (method 2) improves on the circle rule (method 1).
//!
//! The measure, for curvatures κ_a … κ_b along the stretch: with Δ_i = κ_(i+1) − κ_i,
//! `defect = (Σ|Δ_i| − |Σ Δ_i|) / Σ|Δ_i|` — 0 for a monotone curvature, towards 1 when it
//! goes up and down as much as it changes — and the number of interior extrema (sign
//! changes of Δ, steps below 1e-9 of the total variation ignored).

use crate::curve::{CurveError, CurveScheme, presets};

/// The schemes compared, in the order of [`StudyRow::defect`].
pub const SCHEMES: [CurveScheme; 3] = [
    CurveScheme::CatmullClark,
    CurveScheme::Circle,
    CurveScheme::LogSpiral,
];

/// How monotone a sequence of curvatures is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Monotonicity {
    pub defect: f64,
    pub extrema: usize,
}

/// The monotonicity of `k` (see the module doc).
pub fn monotonicity(k: &[f64]) -> Monotonicity {
    let d: Vec<f64> = k.windows(2).map(|w| w[1] - w[0]).collect();
    let total: f64 = d.iter().map(|x| x.abs()).sum();
    if total == 0.0 || !total.is_finite() {
        return Monotonicity {
            defect: 0.0,
            extrema: 0,
        };
    }
    let net: f64 = d.iter().sum();
    let tiny = 1e-9 * total;
    let mut extrema = 0;
    let mut last = 0.0f64;
    for &x in &d {
        if x.abs() <= tiny {
            continue;
        }
        if last != 0.0 && x.signum() != last.signum() {
            extrema += 1;
        }
        last = x;
    }
    Monotonicity {
        defect: (total - net.abs()) / total,
        extrema,
    }
}

/// One cell of the study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StudyRow {
    /// Degrees.
    pub theta1: f64,
    pub theta2: f64,
    pub l1: f64,
    pub l2: f64,
    /// Per scheme of [`SCHEMES`].
    pub result: [Monotonicity; 3],
}

impl StudyRow {
    /// Method 2 against method 1: `Some(true)` when its defect is smaller (by more than
    /// 1e-6), `Some(false)` when larger, `None` when they tie.
    pub fn log_spiral_better(&self) -> Option<bool> {
        let (m1, m2) = (self.result[1].defect, self.result[2].defect);
        if (m1 - m2).abs() <= 1e-6 {
            None
        } else {
            Some(m2 < m1)
        }
    }
}

/// The curvature of fig. 6's polyline refined `levels` times by every scheme, judged between
/// the images of P₁ and P₂ (angles in degrees).
pub fn fig6_row(
    theta1: f64,
    theta2: f64,
    l1: f64,
    l2: f64,
    levels: usize,
) -> Result<StudyRow, CurveError> {
    let poly = presets::fig6(theta1.to_radians(), theta2.to_radians(), l1, l2);
    let mut result = [Monotonicity {
        defect: 0.0,
        extrema: 0,
    }; 3];
    for (r, s) in result.iter_mut().zip(SCHEMES) {
        let refined = poly.refine_levels(s, levels)?;
        let k = refined.curvature();
        // An open polyline of 4 points keeps its ends; P_j is at index j·2^levels.
        let step = 1usize << levels;
        *r = monotonicity(&k[step..=2 * step]);
    }
    Ok(StudyRow {
        theta1,
        theta2,
        l1,
        l2,
        result,
    })
}

/// Every combination of the given angles (degrees) and lengths, θ₁ slowest.
pub fn fig6_study(
    theta1: &[f64],
    theta2: &[f64],
    l1: &[f64],
    l2: &[f64],
    levels: usize,
) -> Result<Vec<StudyRow>, CurveError> {
    let mut out = Vec::with_capacity(theta1.len() * theta2.len() * l1.len() * l2.len());
    for &t1 in theta1 {
        for &t2 in theta2 {
            for &a in l1 {
                for &b in l2 {
                    out.push(fig6_row(t1, t2, a, b, levels)?);
                }
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn monotone_and_wavy_sequences() {
        assert_eq!(monotonicity(&[1.0, 2.0, 2.0, 3.0]).defect, 0.0);
        let m = monotonicity(&[0.0, 1.0, 0.0, 1.0]);
        assert!((m.defect - 2.0 / 3.0).abs() < 1e-15);
        assert_eq!(m.extrema, 2);
        assert_eq!(monotonicity(&[1.0; 5]).extrema, 0);
    }

    /// The paper's finding (fig. 8): method 2 improves on method 1 mostly where the lengths
    /// shrink along the polyline (l₁ > l₂, the lower right of each cell), "because a
    /// logarithmic spiral's vertex distances change by a constant factor". Measured over
    /// θ₁, θ₂ ∈ {15°, …, 90°}, l₁, l₂ ∈ {0.25, …, 4}, 5 levels: 292 of 360 cells with l₁ > l₂,
    /// 96 of 360 with l₁ < l₂.
    #[test]
    fn method_2_improves_where_the_lengths_shrink() {
        let angles = [15.0, 30.0, 45.0, 60.0, 75.0, 90.0];
        let lengths = [0.25, 0.5, 1.0, 2.0, 4.0];
        let rows = fig6_study(&angles, &angles, &lengths, &lengths, 5).unwrap();
        assert_eq!(rows.len(), 900);
        let share = |f: &dyn Fn(&StudyRow) -> bool| {
            let cells: Vec<_> = rows.iter().filter(|r| f(r)).collect();
            let b = cells.iter().filter(|r| r.log_spiral_better() == Some(true));
            b.count() as f64 / cells.len() as f64
        };
        let (down, up) = (share(&|r| r.l1 > r.l2), share(&|r| r.l1 < r.l2));
        assert!(down > 0.75 && up < 0.35, "{down} {up}");
    }

    /// Lengths in geometric progression (l₁ : l₂ : l₃ = 4 : 2 : 1) and equal turns are a
    /// logarithmic spiral's samples: method 2 keeps its curvature monotone, as the paper says
    /// ("the distances between vertices preferably change by a constant factor").
    #[test]
    fn a_spiral_configuration_favours_the_log_spiral_rule() {
        let r = fig6_row(40.0, 40.0, 4.0, 2.0, 5).unwrap();
        assert!(r.result[2].defect < 1e-9, "{r:?}");
        assert_eq!(r.result[2].extrema, 0);
        assert!(r.result[2].defect <= r.result[1].defect);
    }
}
