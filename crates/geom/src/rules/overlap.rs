//! Rounds that do not fit their faces (docs/algorithms/cylindrical.md, "Overlap"), and the
//! largest widths that do.
//!
//! Every face of a cylindrical-family step is cut by lines parallel to its edges, edge `E`'s
//! line at its width `w_E` inside the face. The new corner point at vertex V (eq. 4 in
//! Prism's split form, in `rules/cylindrical.rs`) lies along the edge `E₁ = V→V₊` at
//!
//! `a₁ = (m₂·u₁)(w₂ − c·w₁)/(1 − c²)`
//!
//! from V, and along `E₂ = V→V₋` at `a₂ = (m₁·u₂)(w₁ − c·w₂)/(1 − c²)` (notation of
//! [`super`]; `m₂·u₁ = m₁·u₂ = sin φ` on a planar face, so `a₁ = (w₂ + w₁cos φ)/sin φ`).
//! An edge of length L keeps its direction in the new face only while the two points on it
//! stay in order: `a₁(V) + a₂(V₊) ≤ L`. When that fails the rounds of the neighbouring
//! edges overlap across the face (the straight skeleton's *edge event*): the new face folds.
//!
//! Both sides are linear in the widths, so the largest factor by which the widths of one
//! constraint's edges may be scaled is exact: with P the sum of the positive terms and N
//! of the negative ones, scaling the positive ones by `(L − N)/P` makes the sum L. Each
//! edge takes the least factor of its constraints; one pass can break a constraint in which
//! an edge counts negatively (an obtuse or reflex corner), so the passes repeat until none
//! is broken.
//!
//! The pipeline uses this twice (docs/algorithms/cylindrical.md): before the first step of
//! a cylindrical-family run with the *limit* widths — the tangent lengths `r·tan(|ψ|/2)` at
//! which the finished fillet meets its faces — to refuse or clamp radii that do not fit the
//! solid; and at every combination step with that step's cut widths, which keeps the deep
//! levels from folding where fillets of different radii meet.

use super::{RuleInput, corner_frame_on_edges};

/// What a step does with radii whose rounds do not fit their faces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Overlap {
    /// Refuse the step, naming the edges and the largest radius that fits each.
    #[default]
    Refuse,
    /// Lower the radius of exactly those edges to what fits (as an own radius, so the
    /// steps after keep it) and list them in the report.
    Clamp,
    /// Do not check: the radii were checked when the run of cylindrical-family steps began
    /// (the pipeline sets this on the steps that continue a run), clamping or not.
    Unchecked { clamped: bool },
}

/// How far a clamp makes sure the combination rule reaches the radii it lowers to
/// (docs/algorithms/cylindrical.md, "Reach"; `Pipeline::compute_with`).
///
/// Lowering an edge until its round fits its faces is not enough for the combination rule:
/// where fillets of very different radii meet at a vertex (the tripod's arm edge 0-9 at 0.88
/// beside 0.12), its fold guard moves the faces into the vertex blend and the fillet comes out
/// a third smaller. The first step of a clamped run therefore measures every clamped edge's
/// fillet a few steps on; where one misses, the clamped radii are capped at c and the step is taken again,
/// c found by halving between the smallest and the largest clamped radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReachOptions {
    /// Whether a clamped run searches the cap at all (default on).
    pub search: bool,
    /// A clamped edge reaches its radius when its fitted radius `depth` steps into the run
    /// is within this share of what the rule's polygon gives there, `r/cos(ψ/2^(depth+1))`
    /// (default 0.05).
    pub tolerance: f64,
    /// The search asks this much closer (default 0.5: within 2.5 % `depth` steps on), since
    /// the fold guard can still take a little off at the levels after.
    pub search_share: f64,
    /// Steps of the rule taken to measure a trial, at most as many as the run has (default
    /// 4: the fold guard also acts at the second to fourth levels).
    pub depth: usize,
    /// Halvings of the cap's interval (default 8: a 256th of it).
    pub halvings: usize,
}

impl Default for ReachOptions {
    fn default() -> Self {
        ReachOptions {
            search: true,
            tolerance: 0.05,
            search_share: 0.5,
            depth: 4,
            halvings: 8,
        }
    }
}

/// What a clamped run's reach search did ([`ReachOptions`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reached {
    /// The cap on the clamped radii whose fillets the rule reaches, or `None` where even the
    /// smallest clamped radius missed (the clamp's radii then stand, with a warning).
    pub cap: Option<f64>,
    /// Edges the cap lowered below what fits their faces.
    pub capped: usize,
    /// Trials taken, the plain step included (each a few levels of the run).
    pub steps: usize,
}

/// `x` rounded down to four significant digits (a radius said in a message is one that fits).
pub fn round_down(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return x;
    }
    let scale = 10f64.powi(3 - x.log10().floor() as i32);
    (x * scale).floor() / scale
}

/// An edge whose round does not fit: its radius and the largest that fits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EdgeFit {
    pub a: u32,
    pub b: u32,
    pub radius: f64,
    pub fits: f64,
}

impl Overlap {
    /// Whether the step is asked for a sound solid: clamping, or continuing a clamped run
    /// (the minimum type and the chamfers then mend too: `CornerRule::mends`).
    pub fn clamps(self) -> bool {
        matches!(self, Overlap::Clamp | Overlap::Unchecked { clamped: true })
    }

    /// `Clamp` when `clamp`, else `Refuse` (the CLI's `--clamp`, the app's checkbox).
    pub fn clamping(clamp: bool) -> Overlap {
        if clamp {
            Overlap::Clamp
        } else {
            Overlap::Refuse
        }
    }
}

impl std::fmt::Display for EdgeFit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "edge {}-{} (r = {} fits up to {:.4})",
            self.a,
            self.b,
            short(self.radius),
            self.fits
        )
    }
}

/// `x` to four decimals without trailing zeros: 0.2 stays "0.2", an own radius the clamp
/// capped reads "0.1359" rather than seventeen digits.
fn short(x: f64) -> String {
    let s = format!("{x:.4}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// `fits` as a short list for an error or a warning: the first five, then how many more.
pub fn list(fits: &[EdgeFit]) -> String {
    // The tightest first: the edges that decide the radius that fits.
    let mut sorted: Vec<&EdgeFit> = fits.iter().collect();
    sorted.sort_by(|a, b| a.fits.total_cmp(&b.fits));
    let mut s: Vec<String> = sorted.iter().take(5).map(|e| e.to_string()).collect();
    if fits.len() > 5 {
        s.push(format!("and {} more", fits.len() - 5));
    }
    s.join(", ")
}

/// The largest radius that fits every edge of `fits` (each edge's bound with its neighbours
/// at their asked radii; lower neighbours leave it more room, so this one number fits all),
/// rounded down to four significant digits, so that the number said is one that fits.
pub fn largest_fit(fits: &[EdgeFit]) -> f64 {
    round_down(fits.iter().map(|e| e.fits).fold(f64::INFINITY, f64::min))
}

/// The sentence a step's report gives for the radii `fits` lowered ([`crate::step::StepReport::notes`]).
pub fn note(fits: &[EdgeFit]) -> String {
    format!(
        "{} edge radius(es) clamped to fit their faces: {}",
        fits.len(),
        list(fits)
    )
}

/// Straight-corner threshold on 1 − c, as the simple type's (there the along-edge term is
/// capped by the rule, and only the mean width counts here).
const STRAIGHT_CORNER: f64 = 1e-12;

/// A constraint is broken when its sum exceeds L by more than this fraction of L.
const SLACK: f64 = 1e-9;

/// Along-edge extents of the new point at a corner as coefficients of the widths:
/// `[[a₁ per w₁, a₁ per w₂], [a₂ per w₁, a₂ per w₂]]`, or `None` where the corner has no
/// frame (a zero-length edge or a face without area: the rule reports those).
fn extents(input: &RuleInput, c: usize) -> Option<[[f64; 2]; 2]> {
    let fr = corner_frame_on_edges(input, c).ok()?;
    let (s1, s2) = (fr.m2.dot(fr.u1), fr.m1.dot(fr.u2));
    if 1.0 - fr.c < STRAIGHT_CORNER {
        let h1 = 0.5 * s1 / (1.0 + fr.c);
        let h2 = 0.5 * s2 / (1.0 + fr.c);
        return Some([[h1, h1], [h2, h2]]);
    }
    let d = (1.0 - fr.c * fr.c).max(f64::MIN_POSITIVE);
    Some([[-fr.c * s1 / d, s1 / d], [s2 / d, -fr.c * s2 / d]])
}

/// The largest factor `s_E ∈ [0, 1]` per edge such that the widths `s_E·widths[E]` fit
/// every face not marked in `skip` (faces the rule does not cut, such as the combination
/// rule's Doo–Sabin faces), each edge of length L keeping at least `(1 − room)·L`.
/// `input.cut_widths` is not read.
pub fn fitting_scales(input: &RuleInput, widths: &[f64], skip: &[bool], room: f64) -> Vec<f64> {
    use rayon::prelude::*;
    use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
    const MIN: usize = 1 << 12;
    let (m, t) = (input.mesh, input.topo);
    let mut scale = vec![1.0f64; widths.len()];
    let cut = |c: usize| {
        !skip
            .get(t.corner_face(c) as usize)
            .copied()
            .unwrap_or(false)
    };
    // Each corner's frame once: a constraint reads its own corner and the next.
    let ext: Vec<Option<[[f64; 2]; 2]>> = (0..m.num_corners())
        .into_par_iter()
        .with_min_len(MIN)
        .map(|c| if cut(c) { extents(input, c) } else { None })
        .collect();
    // One constraint per face corner: its edge E₁ = c→next(c), with the coefficients of
    // the widths of E₂(c), E₁ and E₁(next(c)); formed again in each pass (usually there is
    // one) rather than stored.
    let constraint = |c: usize| {
        let n = t.next(c) as usize;
        let (Some(kc), Some(kn)) = (ext[c], ext[n]) else {
            return None;
        };
        let len = (m.positions[m.corner_verts[n] as usize]
            - m.positions[m.corner_verts[c] as usize])
            .length();
        let edges = [
            t.corner_edge[t.prev(c) as usize] as usize,
            t.corner_edge[c] as usize,
            t.corner_edge[n] as usize,
        ];
        // a₁(c) = kc[0][0]·w(E₁) + kc[0][1]·w(E₂(c)); a₂(n) = kn[1][0]·w(E₁(n)) + kn[1][1]·w(E₁).
        let coef = [kc[0][1], kc[0][0] + kn[1][1], kn[1][0]];
        Some((edges, coef, room * len))
    };
    // Each pass reads the factors of the pass before and lowers every edge to the least
    // factor its broken constraints ask for, all at once: no edge is favoured for coming
    // first, so the result does not depend on how the input is numbered — nor on the
    // threads. The factors lie in [0, 1], where the order of an f64's bits is its order
    // as a number, so the least is kept by an atomic minimum of the bits.
    let lowered: Vec<AtomicU64> = (0..widths.len())
        .into_par_iter()
        .with_min_len(MIN)
        .map(|_| AtomicU64::new(1.0f64.to_bits()))
        .collect();
    for _ in 0..input.options.overlap_passes {
        lowered
            .par_iter()
            .with_min_len(MIN)
            .for_each(|l| l.store(1.0f64.to_bits(), Relaxed));
        let changed = (0..m.num_corners())
            .into_par_iter()
            .with_min_len(MIN)
            .map(|c| {
                let Some((edges, coef, len)) = constraint(c) else {
                    return false;
                };
                let terms = [0, 1, 2].map(|i| coef[i] * widths[edges[i]] * scale[edges[i]]);
                let sum: f64 = terms.iter().sum();
                if sum <= len * (1.0 + SLACK) {
                    return false;
                }
                let pos: f64 = terms.iter().filter(|&&x| x > 0.0).sum();
                let neg: f64 = terms.iter().filter(|&&x| x < 0.0).sum();
                // + 0.0 turns a −0.0 into 0.0, whose bits are the least.
                let k = ((len - neg) / pos).clamp(0.0, 1.0) + 0.0;
                let mut changed = false;
                for i in 0..3 {
                    if terms[i] > 0.0 {
                        let before = lowered[edges[i]].fetch_min(k.to_bits(), Relaxed);
                        changed |= k.to_bits() < before;
                    }
                }
                changed
            })
            .reduce(|| false, |a, b| a | b);
        if !changed {
            break;
        }
        scale
            .par_iter_mut()
            .with_min_len(MIN)
            .zip(&lowered)
            .for_each(|(s, l)| *s *= f64::from_bits(l.load(Relaxed)));
    }
    scale
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;
    use crate::topology::Topology;
    use glam::DVec3;

    /// The message names radii in four decimals at most.
    #[test]
    fn radii_read_short() {
        let fit = |radius| EdgeFit {
            a: 180,
            b: 181,
            radius,
            fits: 0.1315,
        };
        assert_eq!(
            fit(0.13593386622447848).to_string(),
            "edge 180-181 (r = 0.1359 fits up to 0.1315)"
        );
        assert_eq!(
            fit(0.2).to_string(),
            "edge 180-181 (r = 0.2 fits up to 0.1315)"
        );
        assert_eq!(
            fit(2.0).to_string(),
            "edge 180-181 (r = 2 fits up to 0.1315)"
        );
    }

    fn scales_on(m: &crate::PolyMesh, widths: impl Fn(f64) -> f64) -> (Topology, Vec<f64>) {
        let topo = Topology::build(m).unwrap();
        let normals = crate::geometry::face_normals_raw(m)
            .into_iter()
            .map(crate::geometry::unit_or_zero)
            .collect::<Vec<_>>();
        let w: Vec<f64> = (0..topo.num_edges())
            .map(|e| {
                let (a, b) = topo.edge_verts(m, e);
                widths((m.positions[a as usize] - m.positions[b as usize]).length())
            })
            .collect();
        let input = RuleInput {
            mesh: m,
            topo: &topo,
            normals: &normals,
            cut_widths: &[],
            face_params: &[],
            vertex_neighbourhood: &[],
            options: &crate::rules::RoundingOptions::default(),
        };
        let s = fitting_scales(&input, &w, &[], 1.0);
        (topo, s)
    }

    /// A 4 × 2 × 0.3 slab with width 0.2 on every edge: the side faces are 0.3 high, so the
    /// eight edges along the top and bottom must go to 0.15 (the rounds meet), and the four
    /// short vertical edges, whose neighbours fit in 4 and 2, keep theirs.
    #[test]
    fn a_thin_slab_halves_its_long_edges_and_nothing_else() {
        let m = primitives::cuboid(DVec3::ZERO, DVec3::new(4.0, 2.0, 0.3));
        let (topo, s) = scales_on(&m, |_| 0.2);
        for (e, &k) in s.iter().enumerate() {
            let (a, b) = topo.edge_verts(&m, e);
            let d = m.positions[a as usize] - m.positions[b as usize];
            let want = if d.z.abs() > 0.0 { 1.0 } else { 0.75 };
            assert!((k - want).abs() < 1e-12, "edge {a}-{b}: {k}, want {want}");
        }
    }

    /// Widths that fit leave every factor at 1.
    #[test]
    fn fitting_widths_are_left_alone() {
        let (_, s) = scales_on(&primitives::l_block(), |_| 0.1);
        assert!(s.iter().all(|&k| k == 1.0));
    }
}
