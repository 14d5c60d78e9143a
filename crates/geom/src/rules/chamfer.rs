//! The three chamfer rules of seed 000 §3.1 (docs/algorithms/chamfers.md).
//!
//! - angle bisector, distance l: `V' = V + l·unit(m₁ + m₂)` (|m₁ + m₂| = 2 sin(φ/2), so the
//!   bisector exists for every φ in (0, 2π), reflex corners included);
//! - cut width d (every edge moved inwards by d): `V' = V + d(m₁ + m₂)/(1 + c)`, a point at
//!   distance d/sin(φ/2) along the bisector;
//! - vector sum α (eq. 2): `V' = V + α(e₁ + e₂)`; with [`ReflexMode::Inward`] the
//!   displacement is reversed at reflex corners.
//!
//! l and d are absolute: repeated at a constant value the new faces (about d wide) are cut
//! from both sides and flip from level 2; a pipeline shrinks them about 4× per step (§2.3).

use super::{ReflexMode, RuleError, RuleInput, corner_frame};
use crate::mesh::PolyMesh;
use glam::DVec3;

/// Below this |m₁ + m₂| (= 2 sin(φ/2)) a corner is a needle and has no bisector.
const NEEDLE_BISECTOR: f64 = 1e-12;

fn needle(input: &RuleInput, c: usize) -> RuleError {
    RuleError::NeedleCorner {
        face: input.topo.corner_face(c),
        vertex: input.mesh.corner_verts[c],
    }
}

pub(super) fn angle_bisector(input: &RuleInput, c: usize, l: f64) -> Result<DVec3, RuleError> {
    let fr = corner_frame(input, c)?;
    let s = fr.m1 + fr.m2;
    let len = s.length();
    if len < NEEDLE_BISECTOR {
        return Err(needle(input, c));
    }
    Ok(fr.v + l * s / len)
}

pub(super) fn cut_width(input: &RuleInput, c: usize, d: f64) -> Result<DVec3, RuleError> {
    let fr = corner_frame(input, c)?;
    if 1.0 + fr.c < NEEDLE_BISECTOR {
        return Err(needle(input, c));
    }
    Ok(fr.v + d * (fr.m1 + fr.m2) / (1.0 + fr.c))
}

/// Eq. (2) needs no face normal: only the reflex-inward option asks which corners are
/// reflex, and a face of no area has none (its corners keep the printed rule). So faces a
/// previous step flattened (α > ¼ folds them) do not stop the rule.
pub(super) fn vector_sum(input: &RuleInput, c: usize, alpha: f64, reflex: ReflexMode) -> DVec3 {
    let (m, t) = (input.mesh, input.topo);
    let at = |corner: u32| m.positions[m.corner_verts[corner as usize] as usize];
    let normal = input.normals[t.corner_face(c) as usize];
    let v = at(c as u32);
    let (d, _) = corner_move(at(t.prev(c)), v, at(t.next(c)), normal, reflex);
    v + alpha * d
}

/// The displacement per unit of α (`±(e₁ + e₂)`) of the corner at `v` between `prev` and
/// `next` on a face of unit normal `normal`, and whether it is a reflex corner.
fn corner_move(
    prev: DVec3,
    v: DVec3,
    next: DVec3,
    normal: DVec3,
    reflex: ReflexMode,
) -> (DVec3, bool) {
    let (e1, e2) = (next - v, prev - v);
    let reflex_corner = normal != DVec3::ZERO && normal.dot(e1.cross(e2)) < 0.0;
    let sign = if reflex == ReflexMode::Inward && reflex_corner {
        -1.0
    } else {
        1.0
    };
    (sign * (e1 + e2), reflex_corner)
}

/// Eq. (2) on one face: each corner's vertex and displacement per unit of α, in the face's
/// corner order, and whether any corner is reflex. One value serves every face in turn
/// ([`FaceMoves::load`]), so the clamp allocates nothing per face.
struct FaceMoves {
    from: Vec<DVec3>,
    moves: Vec<DVec3>,
    any_reflex: bool,
    /// The share of the narrowest width and of each side the clamp keeps
    /// ([`super::RoundingOptions::kept_share`]: what a triangle keeps at α = ¼, shrinking by
    /// 1 − 3α about its centroid).
    kept: f64,
    /// [`super::RoundingOptions::reflex_sin`].
    reflex_sin: f64,
}

impl FaceMoves {
    fn new(options: &super::RoundingOptions) -> FaceMoves {
        FaceMoves {
            from: Vec::new(),
            moves: Vec::new(),
            any_reflex: false,
            kept: options.kept_share,
            reflex_sin: options.reflex_sin,
        }
    }

    /// Face `f` of unit normal `normal`, in place of the face held before.
    fn load(&mut self, m: &PolyMesh, normal: DVec3, f: usize, reflex: ReflexMode) {
        self.from.clear();
        self.moves.clear();
        self.any_reflex = false;
        for l in m.face_loops(f) {
            let vs = m.loop_verts(l);
            let at = |i: usize| m.positions[vs[i % vs.len()] as usize];
            for i in 0..vs.len() {
                let (d, r) = corner_move(at(i + vs.len() - 1), at(i), at(i + 1), normal, reflex);
                self.from.push(at(i));
                self.moves.push(d);
                self.any_reflex |= r;
            }
        }
    }

    /// The largest α' ≤ `alpha` at which the face's new outline keeps at least `kept` (a
    /// quarter) of the face's narrowest width (the least distance from a corner to an edge not its own)
    /// all the way from α = 0: the outline cannot cross itself without a corner first
    /// reaching an edge.
    fn clamped(&self, m: &PolyMesh, f: usize, alpha: f64) -> f64 {
        let base = m.face_corners(f).start;
        let loops: Vec<_> = m
            .face_loops(f)
            .map(|l| {
                let r = m.loop_corners(l);
                r.start - base..r.end - base
            })
            .collect();
        let width = |s: f64| narrowest_width(&self.from, &self.moves, s, &loops);
        let keep = self.kept * width(0.0);
        largest_fitting(alpha, |s| width(s) >= keep)
    }

    /// As [`FaceMoves::clamped`], and every side of the new outline keeps at least `kept` (a
    /// quarter) of its old side's length along it: a side that turns back flips the strip between it
    /// and the next face's (Doo–Sabin's reflex corners).
    fn clamped_keeping_sides(&self, m: &PolyMesh, f: usize, most: f64) -> f64 {
        let n = self.from.len();
        let sides = |s: f64| {
            (0..n).all(|i| {
                let j = (i + 1) % n;
                let old = self.from[j] - self.from[i];
                let new = old + s * (self.moves[j] - self.moves[i]);
                new.dot(old) >= self.kept * old.length_squared()
            })
        };
        let s = largest_fitting(most, sides);
        self.clamped(m, f, s)
    }
}

/// The vector sum's per-face clamp (docs/algorithms/chamfers.md, "Clamp"). At a convex
/// corner eq. (2) moves the point along its own edges only (by α of each, so α ≤ ¼ keeps a
/// quarter of every edge), but at a reflex corner — moved inwards or, as printed, outwards —
/// the point travels across the face and can meet the far side: the tripod's L-shaped bottom
/// face at α = 0.2 with `reflex=inward` has its reflex corner and the opposite convex corner
/// land on the same point (0.6, 0.6, 0), and every later step folds there. So on a face with
/// a reflex corner α is lowered to [`FaceMoves::clamped`]; faces without one keep α.
fn vector_sum_alphas(input: &RuleInput, alpha: f64, reflex: ReflexMode) -> (Vec<f64>, usize) {
    let m = input.mesh;
    let mut lowered = 0;
    let mut fm = FaceMoves::new(input.options);
    let params = (0..m.num_faces())
        .map(|f| {
            fm.load(m, input.normals[f], f, reflex);
            if !fm.any_reflex {
                return alpha;
            }
            let a = fm.clamped(m, f, alpha);
            if a < alpha {
                lowered += 1;
            }
            a
        })
        .collect();
    (params, lowered)
}

/// Doo–Sabin's clamp ([`super::concave`]): on a face with a reflex corner where eq. (1) would
/// turn a strip over, the share `s` ≤ 1 of the width offset that keeps the new outline a
/// quarter of the face's narrowest width and every side a quarter of its length; −1 (eq. (1)
/// as printed) on the others and on faces with holes. Also how many faces take the offset.
pub(super) fn doo_sabin_shares(input: &RuleInput) -> (Vec<f64>, usize) {
    let m = input.mesh;
    let mut offset = 0;
    let mut fm = FaceMoves::new(input.options);
    let params = (0..m.num_faces())
        .map(|f| {
            let s = doo_sabin_share(m, input.normals[f], f, false, &mut fm);
            offset += usize::from(s >= 0.0);
            s
        })
        .collect();
    (params, offset)
}

/// [`doo_sabin_shares`] for face `f` of unit normal `n`: the share of the width offset, or −1
/// for eq. (1) as printed; with `near_only`, −1 too where an offset point would land farther
/// from the face's centroid than its farthest corner ([`super::concave::stays_near`]). `fm` is
/// scratch space.
fn doo_sabin_share(m: &PolyMesh, n: DVec3, f: usize, near_only: bool, fm: &mut FaceMoves) -> f64 {
    if m.face_has_holes(f) {
        return -1.0;
    }
    let v = super::concave::corners(m, f);
    if !super::concave::has_reflex_corner(&v, n, fm.reflex_sin)
        || super::concave::doo_sabin_holds(m, n, f)
    {
        return -1.0;
    }
    fm.moves = super::concave::width_offset(&v, n);
    fm.from = v;
    let s = fm.clamped_keeping_sides(m, f, 1.0);
    if near_only && !super::concave::stays_near(&fm.from, &fm.moves, s) {
        return -1.0;
    }
    s
}

/// Doo–Sabin's points of face `f` (unit normal `n`, one loop) written to `pts` (indexed by
/// corner): the width offset's share where [`doo_sabin_shares`] gives one and its points stay
/// near the face, else eq. (1). The combination rule's fold guard places a face it moves into the
/// vertex blend so (the fold guard, `mend/fold_guard.rs`; cylindrical.md, "Fold guard").
pub(super) fn offset_doo_sabin_points(
    m: &PolyMesh,
    n: DVec3,
    f: usize,
    options: &super::RoundingOptions,
    pts: &mut [DVec3],
) {
    let mut fm = FaceMoves::new(options);
    let s = doo_sabin_share(m, n, f, true, &mut fm);
    let l = m.face_loops(f).start;
    if s < 0.0 {
        super::doo_sabin::loop_points(m, l, pts, 0);
        return;
    }
    let start = m.loop_corners(l).start;
    for (i, (v, d)) in fm.from.iter().zip(&fm.moves).enumerate() {
        pts[start + i] = *v + s * *d;
    }
}

/// The least distance from a corner of the outline `from + s·moves` (loops given as index
/// ranges) to an edge of any loop that does not end at it.
fn narrowest_width(
    from: &[DVec3],
    moves: &[DVec3],
    s: f64,
    loops: &[std::ops::Range<usize>],
) -> f64 {
    let at = |i: usize| from[i] + s * moves[i];
    let mut least = f64::INFINITY;
    for l in loops {
        for j in l.clone() {
            let k = if j + 1 == l.end { l.start } else { j + 1 };
            let (a, b) = (at(j), at(k));
            for i in 0..from.len() {
                if i != j && i != k {
                    least = least.min(crate::geometry::segment_distance(at(i), a, b));
                }
            }
        }
    }
    least
}

/// The largest `s` in `[0, most]` such that `fits` holds on all of `[0, s]`, found by eight
/// even samples and then bisection (to 2⁻¹² of `most`). `fits(0)` is taken to hold.
fn largest_fitting(most: f64, fits: impl Fn(f64) -> bool) -> f64 {
    const SAMPLES: usize = 8;
    let mut lo = 0.0;
    for k in 1..=SAMPLES {
        let s = most * k as f64 / SAMPLES as f64;
        if !fits(s) {
            let mut hi = s;
            for _ in 0..9 {
                let mid = 0.5 * (lo + hi);
                if fits(mid) { lo = mid } else { hi = mid }
            }
            return lo;
        }
        lo = s;
    }
    most
}

/// The per-face clamp of the absolute chamfers (seed 000 §3.1, docs/algorithms/chamfers.md,
/// "Clamp"): a face's parameter is lowered so that no convex corner moves along either of its
/// edges by more than a quarter of the shorter one — along an edge, the cut-width point
/// moves `d·cot(φ/2)` and the bisector point `l·cos(φ/2)` — and, on a face with a reflex
/// corner, so that its new outline keeps a quarter of its narrowest width
/// ([`FaceMoves::clamped`]); the vector sum's α is lowered on faces whose reflex corners would
/// cross them ([`vector_sum_alphas`]). Returns the parameter
/// of every face and how many were lowered.
pub(super) fn face_params(input: &RuleInput, rule: &super::CornerRule) -> (Vec<f64>, usize) {
    let m = input.mesh;
    let p = match *rule {
        super::CornerRule::CutWidth { d } => d,
        super::CornerRule::AngleBisector { l } => l,
        super::CornerRule::VectorSum { alpha, reflex } => {
            return vector_sum_alphas(input, alpha, reflex);
        }
        super::CornerRule::DooSabin => return doo_sabin_shares(input),
        _ => return (Vec::new(), 0),
    };
    // Along-edge move per unit of the parameter at a convex corner (c = m₁·m₂ = −cos φ):
    // cot(φ/2) = (1 − c)/sin φ for the cut width, cos(φ/2) = √((1 − c)/2) for the bisector.
    let along = |fr: &super::CornerFrame| match rule {
        super::CornerRule::CutWidth { .. } => (1.0 - fr.c) / fr.sin_phi,
        _ => ((1.0 - fr.c) / 2.0).max(0.0).sqrt(),
    };
    // The move per unit of the parameter: (m₁ + m₂)/(1 + c) for the cut width, the unit
    // bisector for the angle bisector.
    let per_unit = |fr: &super::CornerFrame| {
        let s = fr.m1 + fr.m2;
        match rule {
            super::CornerRule::CutWidth { .. } if 1.0 + fr.c >= NEEDLE_BISECTOR => s / (1.0 + fr.c),
            super::CornerRule::AngleBisector { .. } if s.length() >= NEEDLE_BISECTOR => {
                s / s.length()
            }
            _ => DVec3::ZERO,
        }
    };
    let mut lowered = 0;
    let mut fm = FaceMoves::new(input.options);
    let params = (0..m.num_faces())
        .map(|f| {
            let mut x = p;
            let mut reflex = false;
            fm.from.clear();
            fm.moves.clear();
            for c in m.face_corners(f) {
                fm.from.push(m.positions[m.corner_verts[c] as usize]);
                let Ok(fr) = corner_frame(input, c) else {
                    fm.moves.push(DVec3::ZERO);
                    continue;
                };
                fm.moves.push(per_unit(&fr));
                if fr.sin_phi <= 0.0 {
                    reflex |= fr.sin_phi < 0.0;
                    continue;
                }
                let room = input.options.kept_share * fr.e1.length().min(fr.e2.length());
                let a = along(&fr);
                if a > 0.0 {
                    x = x.min(room / a);
                }
            }
            // A reflex corner's point travels across the face and can meet the far side
            // (the tripod's L-shaped bottom after an inward vector sum and Doo–Sabin: its
            // reflex corner and the convex one across the neck pass each other at d = 0.05):
            // the new outline keeps a quarter of the face's narrowest width, as the vector
            // sum's does.
            if reflex {
                x = fm.clamped(m, f, x);
            }
            if x < p {
                lowered += 1;
            }
            x
        })
        .collect();
    (params, lowered)
}

#[cfg(test)]
mod tests {
    use crate::rules::{CornerRule, ReflexMode, RuleInput, corner_points};
    use crate::{mesh::PolyMesh, topology::Topology};
    use glam::DVec3;

    /// An L-shaped hexagon in the plane z = 0 (one reflex corner at (1,1)), as a single face.
    fn l_face() -> PolyMesh {
        let p = [(0., 0.), (2., 0.), (2., 1.), (1., 1.), (1., 2.), (0., 2.)]
            .map(|(x, y)| DVec3::new(x, y, 0.0))
            .to_vec();
        PolyMesh::from_polygons(p, &[vec![0, 1, 2, 3, 4, 5]])
    }

    fn points(rule: CornerRule) -> Vec<DVec3> {
        let m = l_face();
        let t = Topology::build(&m).unwrap();
        let n = vec![DVec3::Z];
        let input = RuleInput {
            mesh: &m,
            topo: &t,
            normals: &n,
            cut_widths: &[],
            face_params: &[],
            vertex_neighbourhood: &[],
            options: &crate::rules::RoundingOptions::default(),
        };
        corner_points(&rule, &input).unwrap().0
    }

    #[test]
    fn cut_width_by_hand() {
        let p = points(CornerRule::CutWidth { d: 0.1 });
        assert!((p[0] - DVec3::new(0.1, 0.1, 0.0)).length() < 1e-15);
        assert!((p[2] - DVec3::new(1.9, 0.9, 0.0)).length() < 1e-15);
        // Reflex corner (1,1): the offset lines meet at (0.9, 0.9).
        assert!((p[3] - DVec3::new(0.9, 0.9, 0.0)).length() < 1e-15);
    }

    #[test]
    fn angle_bisector_by_hand() {
        let l = 0.2;
        let p = points(CornerRule::AngleBisector { l });
        let h = l / 2f64.sqrt();
        assert!((p[0] - DVec3::new(h, h, 0.0)).length() < 1e-15);
        assert!((p[3] - DVec3::new(1.0 - h, 1.0 - h, 0.0)).length() < 1e-15);
    }

    #[test]
    fn vector_sum_by_hand() {
        let p = points(CornerRule::VectorSum {
            alpha: 0.25,
            reflex: ReflexMode::AsPrinted,
        });
        // Corner (0,0): e1 = (2,0), e2 = (0,2) → (0.5, 0.5).
        assert!((p[0] - DVec3::new(0.5, 0.5, 0.0)).length() < 1e-15);
        // Reflex corner (1,1): e1 = (0,1), e2 = (1,0) → (1.25, 1.25), outside the face.
        assert!((p[3] - DVec3::new(1.25, 1.25, 0.0)).length() < 1e-15);
        let p = points(CornerRule::VectorSum {
            alpha: 0.25,
            reflex: ReflexMode::Inward,
        });
        assert!((p[3] - DVec3::new(0.75, 0.75, 0.0)).length() < 1e-15);
        assert!((p[0] - DVec3::new(0.5, 0.5, 0.0)).length() < 1e-15);
    }
}
