//! The paper's patches over the envelope's network (seed 004 §6;
//! docs/algorithms/envelope.md, "The paper's patches"), built as printed, one
//! build, no repair: the option `--patches paper` beside the charts, for teaching and
//! comparison. Their folds are found and named, not mended ([`super::folds`]).
//!
//! **G1.** Every border takes the virtual basis of its curve, `g(τ) = (1 − τ)g₀ + τg₁`, on
//! both sides; each side's cross derivative is `X(s) = k(s)g(s) + h(s)C′(s)`, k and h linear
//! and fitted at the corners to the neighbouring sides' legs ([`super::coons`]). Both sides'
//! X lie in span(g, C′): one tangent plane along the whole border, whatever the numbering.
//! A side that is part of a curve takes the restriction of the curve's g.
//!
//! **Four-sided regions** are one Coons patch with variable twist (§9). **Other regions** are
//! split into n quads around an inserted point P_i (§11.7):
//! 1. `P_d(k)` = boundary k at τ = ½, `b_k = X_k(½)/3`;
//! 2. `P_i` = mean of `P_d(k) + (3/2)b_k`;
//! 3. on a primitive, moved along G → P_i to the distance `max(ρ̄, d_face)` from its centre
//!    G, ρ̄ the mean curvature radius at the region's corners (the paper's rule) and d_face
//!    the face plane's distance along the ray (envelope.md, "The paper's patches": never inside the
//!    primitive);
//! 4. tangent plane at P_i normal to `P_i − G`, or the face normal where d_face won (§12
//!    #41); between primitives, the mean of the boundary tangents × b_k;
//! 5. insertion curve k, with `λ_k = ((P_i − P_d)·n)/(b_k·n)`, `λ̂ = max(λ_k, ¼)` and Π the
//!    projection onto that plane: `P_i, P_i + ⅔Π(P_d + λ̂b_k − P_i), P_d + ⅔λ̂b_k, P_d` — the
//!    paper's elevated quadratic whenever λ_k ≥ ¼ (§12 #41);
//! 6. sub-quad k = insertion k, the second half of boundary k, the first half of boundary
//!    k + 1, insertion k + 1 backwards. The insertion curve's basis is rule (a) at P_d (the
//!    boundary runs on through P_d) and rule (b) at P_i.

use super::coons::{Coons, Side};
use super::network::{CurveKind, Network, PatchSide, Region, RegionKind};
use super::primitive::Primitive;
use crate::freeform::bezier::RationalBezier;
use crate::freeform::envelope::tolerances::TOLERANCES;
use glam::DVec3;

/// [`TOLERANCES`]`.lambda_min`.
const LAMBDA_MIN: f64 = TOLERANCES.lambda_min;

/// One four-sided patch: its sides in the network and its Coons patch.
#[derive(Debug, Clone, PartialEq)]
pub struct EnvelopePatch {
    pub sides: [PatchSide; 4],
    pub coons: Coons,
    /// The region it lies in.
    pub region: usize,
}

impl EnvelopePatch {
    /// The network curve's parameter at side `k`'s parameter s.
    pub fn tau(&self, k: usize, s: f64) -> f64 {
        self.sides[k].tau(s)
    }

    /// The side parameter at which side `k` reaches the network curve's parameter `tau`, if
    /// its piece holds it.
    pub fn side_parameter(&self, k: usize, tau: f64) -> Option<f64> {
        let s = self.sides[k];
        let (lo, hi) = (s.t0.min(s.t1), s.t0.max(s.t1));
        if tau < lo - 1e-12 || tau > hi + 1e-12 {
            return None;
        }
        Some((tau - s.t0) / (s.t1 - s.t0))
    }
}

/// The part of `c` from t0 to t1 (backwards when t0 > t1), parametrised on [0, 1].
pub fn piece(c: &RationalBezier, t0: f64, t1: f64) -> RationalBezier {
    let (lo, hi) = (t0.min(t1), t0.max(t1));
    let right = if lo > 0.0 { c.split(lo).1 } else { c.clone() };
    let mut p = if hi < 1.0 {
        right.split((hi - lo) / (1.0 - lo)).0
    } else {
        right
    };
    if t0 > t1 {
        p.points.reverse();
        p.weights.reverse();
    }
    p
}

/// The curves of `sides` as pieces, and each side's fitted cross derivative.
fn fitted_sides(net: &Network, sides: &[PatchSide]) -> Vec<Side> {
    let curves: Vec<RationalBezier> = sides
        .iter()
        .map(|s| piece(&net.curves[s.curve].bezier, s.t0, s.t1))
        .collect();
    let n = sides.len();
    (0..n)
        .map(|k| {
            let prev = &curves[(k + n - 1) % n];
            let next = &curves[(k + 1) % n];
            let a0 = -prev.derivatives(1.0).d1;
            let a1 = next.derivatives(0.0).d1;
            let c = &net.curves[sides[k].curve];
            let g = (c.basis_at(sides[k].t0), c.basis_at(sides[k].t1));
            Side::fitted(curves[k].clone(), g, a0, a1)
        })
        .collect()
}

fn patch(net: &Network, sides: [PatchSide; 4], region: usize) -> EnvelopePatch {
    let fitted = fitted_sides(net, &sides);
    EnvelopePatch {
        sides,
        coons: Coons {
            sides: fitted.try_into().expect("four sides"),
        },
        region,
    }
}

/// The inserted point of a region for the estimate `mean` (§11.7 steps 3–4) and its tangent
/// plane's normal.
fn place(
    net: &Network,
    region: &Region,
    prims: &[Primitive],
    b: &[DVec3],
    tangent_d: &[DVec3],
    mean: DVec3,
) -> (DVec3, DVec3) {
    match region.kind {
        RegionKind::Primitive { primitive, face } => {
            let p = &prims[primitive];
            let g = p.centre;
            let u = (mean - g).normalize();
            let corners: Vec<f64> = region
                .sides
                .iter()
                .filter_map(|s| net.vertex_at(s.curve, s.t0))
                .map(|v| net.vertices[v].rho)
                .collect();
            let rho = corners.iter().sum::<f64>() / corners.len().max(1) as f64;
            let nf = p.normals[face];
            let d_face = nf.dot(p.vertices[p.faces[face][0]] - g) / nf.dot(u);
            if rho < d_face {
                (g + d_face * u, nf)
            } else {
                (g + rho * u, u)
            }
        }
        RegionKind::Fusion { .. } | RegionKind::Lid { .. } => {
            let m = (0..b.len())
                .map(|k| tangent_d[k].cross(b[k]))
                .sum::<DVec3>();
            (mean, m.normalize())
        }
    }
}

/// Splits region `r` (not four-sided) into quads around an inserted point (§11.7), adding the
/// new vertices and insertion curves to `net`.
fn split(net: &mut Network, region: Region, r: usize, prims: &[Primitive]) -> Vec<EnvelopePatch> {
    let sides = region.sides.clone();
    let fitted = fitted_sides(net, &sides);
    let n = sides.len();
    let mut pd = Vec::with_capacity(n);
    let mut b = Vec::with_capacity(n);
    let mut tangent_d = Vec::with_capacity(n);
    for s in &fitted {
        let d = s.curve.derivatives(0.5);
        pd.push(d.point);
        b.push(s.cross(0.5).0 / 3.0);
        tangent_d.push(d.d1);
    }
    let mean = (0..n).map(|k| pd[k] + 1.5 * b[k]).sum::<DVec3>() / n as f64;
    let (pi_, normal) = place(net, &region, prims, &b, &tangent_d, mean);
    let rho_i = match region.kind {
        RegionKind::Primitive { primitive, .. } => pi_.distance(prims[primitive].centre),
        RegionKind::Fusion { .. } | RegionKind::Lid { .. } => 0.0,
    };
    let vi = net.add_vertex(pi_, normal, rho_i);
    let proj = |x: DVec3| x - x.dot(normal) * normal;
    let mut ins = Vec::with_capacity(n);
    for k in 0..n {
        let bn = b[k].dot(normal);
        let lambda = if bn.abs() < 1e-12 * b[k].length() {
            LAMBDA_MIN
        } else {
            ((pi_ - pd[k]).dot(normal) / bn).max(LAMBDA_MIN)
        };
        let nd = tangent_d[k].cross(b[k]).normalize();
        // The region across may have split this curve already: share its P_d.
        let tau = sides[k].tau(0.5);
        let vd = match net.vertex_at(sides[k].curve, tau) {
            Some(v) => v,
            None => {
                let v = net.add_vertex(pd[k], nd, 0.0);
                net.pin(sides[k].curve, tau, v);
                v
            }
        };
        let bez = RationalBezier::polynomial(vec![
            pi_,
            pi_ + 2.0 / 3.0 * proj(pd[k] + lambda * b[k] - pi_),
            pd[k] + 2.0 / 3.0 * lambda * b[k],
            pd[k],
        ])
        .expect("finite points");
        let end = bez.derivatives(1.0).d1;
        let c = net.add_curve(bez, vi, vd, CurveKind::Insertion);
        // Rule (a) at P_d: the boundary runs on through it.
        let along = tangent_d[k].normalize();
        net.curves[c].basis.1 = if along.dot(nd.cross(end)) >= 0.0 {
            along
        } else {
            -along
        };
        ins.push(c);
    }
    (0..n)
        .map(|k| {
            let j = (k + 1) % n;
            let quad = [
                PatchSide {
                    curve: ins[k],
                    t0: 0.0,
                    t1: 1.0,
                },
                PatchSide {
                    t0: sides[k].tau(0.5),
                    ..sides[k]
                },
                PatchSide {
                    t1: sides[j].tau(0.5),
                    ..sides[j]
                },
                PatchSide {
                    curve: ins[j],
                    t0: 1.0,
                    t1: 0.0,
                },
            ];
            patch(net, quad, r)
        })
        .collect()
}

/// The patches of every region of `net`: one Coons patch a four-sided region, the split of
/// §11.7 for the others. The network's bases must be assigned.
pub fn build(net: &mut Network, prims: &[Primitive]) -> Vec<EnvelopePatch> {
    let mut out = Vec::new();
    for r in 0..net.regions.len() {
        let region = net.regions[r].clone();
        if region.sides.len() == 4 {
            let quad: [PatchSide; 4] = region.sides.clone().try_into().expect("four");
            out.push(patch(net, quad, r));
        } else {
            out.extend(split(net, region, r, prims));
        }
    }
    out
}

/// The largest angle (degrees) between the two sides' normals along every border, sampled at
/// `samples` + 1 points per patch side: `C′ × X` on each side (analytic, outward).
pub fn largest_border_jump(net: &Network, patches: &[EnvelopePatch], samples: usize) -> f64 {
    largest_border_jump_on(net, patches, samples, |_| true)
}

/// [`largest_border_jump`] along the curves that a side of a patch in region `r` with
/// `near(r)` lies on.
pub fn largest_border_jump_on(
    net: &Network,
    patches: &[EnvelopePatch],
    samples: usize,
    near: impl Fn(usize) -> bool,
) -> f64 {
    // Per curve, the (side range, normal function) of every patch side on it.
    let mut on: Vec<Vec<(usize, usize)>> = vec![Vec::new(); net.curves.len()];
    for (p, patch) in patches.iter().enumerate() {
        for (k, s) in patch.sides.iter().enumerate() {
            on[s.curve].push((p, k));
        }
    }
    for users in &mut on {
        if !users.iter().any(|&(p, _)| near(patches[p].region)) {
            users.clear();
        }
    }
    let normal = |p: usize, k: usize, tau: f64| -> Option<DVec3> {
        let sp = patches[p].side_parameter(k, tau)?;
        let side = &patches[p].coons.sides[k];
        Some(side.d1(sp).cross(side.cross(sp).0).normalize_or_zero())
    };
    let mut worst = 0.0f64;
    for users in &on {
        for &(p, k) in users {
            for j in 0..=samples {
                let tau = patches[p].tau(k, j as f64 / samples as f64);
                let n0 = normal(p, k, tau).unwrap_or(DVec3::ZERO);
                for &(q, l) in users {
                    if q == p {
                        continue;
                    }
                    if let Some(n1) = normal(q, l, tau)
                        && n0 != DVec3::ZERO
                        && n1 != DVec3::ZERO
                    {
                        let angle = n0.cross(n1).length().atan2(n0.dot(n1));
                        worst = worst.max(angle.to_degrees());
                    }
                }
            }
        }
    }
    worst
}
