//! Gregory patches over the skin's curve network, G1 across every inner border (seed 003 §2
//! step 5; docs/algorithms/skin.md, "Patches and G1").
//!
//! Cell (k, i) is bounded by the piece of section k from chain i to chain i + 1 (v = 0), the
//! same on section k + 1 (v = 1), and the pieces of chains i (u = 0) and i + 1 (u = 1) between
//! the two sections. Each border's interior copies come from its cross-derivative function
//! `k(t) g(t) + h(t) C′(t)/3` with the **virtual basis** `g(t) = (1 − t) g₀ + t g₃`, where g₀,
//! g₃ are the unit tangents of the curves crossing the border at its ends: the section curve
//! for a chain piece, the chain for an intermediate section piece. Both cells of a border use
//! the same g, fitted to their own end legs (`a₀ = k₀ g₀ + h₀ ℓ₀`, `a₃ = k₁ g₃ + h₁ ℓ₂`), so
//! both cross derivatives lie in span(g(t), C′(t)): one tangent plane along the whole border,
//! whatever the numbering. Borders on the end sections and chains through corners (creases)
//! take the basis construction, `a₁ = (2a₀ + a₃)/3`, `a₂ = (a₀ + 2a₃)/3`.

use super::sections::Section;
use crate::freeform::g1::fit;
use crate::freeform::gregory::Gregory;
use crate::freeform::spline::{self, Cubic};
use glam::DVec3;

/// The two interior cross vectors of a border `c` whose cell has end legs `a0` (at c₀) and `a3`
/// (at c₃) into the cell: linear (`basis = None`) or from the virtual basis `(g₀, g₃)`.
pub fn cross_vectors(c: &Cubic, a0: DVec3, a3: DVec3, basis: Option<(DVec3, DVec3)>) -> [DVec3; 2] {
    let Some((g0, g3)) = basis else {
        return [(2.0 * a0 + a3) / 3.0, (a0 + 2.0 * a3) / 3.0];
    };
    let l = [c[1] - c[0], c[2] - c[1], c[3] - c[2]];
    let (k0, h0) = fit(a0, g0, l[0]);
    let (k1, h1) = fit(a3, g3, l[2]);
    [
        ((k0 + k1) * g0 + k0 * g3) / 3.0 + (h1 * l[0] + 2.0 * h0 * l[1]) / 3.0,
        (k1 * g0 + (k0 + k1) * g3) / 3.0 + (2.0 * h1 * l[1] + h0 * l[2]) / 3.0,
    ]
}

/// Unit tangent of a curve piece at its start (t = 0) or end.
fn tangent(c: &Cubic, at_end: bool) -> DVec3 {
    spline::derivative(c, if at_end { 1.0 } else { 0.0 }).normalize_or_zero()
}

/// Everything the patches are built from.
pub struct Network<'a> {
    pub sections: &'a [Section],
    /// Per chain, its pieces between consecutive sections.
    pub chains: &'a [Vec<Cubic>],
    /// Per section, the vertex of chain 0.
    pub offset: &'a [usize],
    /// Per chain, whether it is a crease (it passes through a corner of some section).
    pub crease: &'a [bool],
    /// Which G1 construction the inner borders take.
    pub basis: Basis,
}

/// The G1 construction of inner borders (docs/algorithms/skin.md, "Patches and G1").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Basis {
    /// Both sides from the unit tangents of the crossing curves: independent of numbering.
    #[default]
    Virtual,
    /// The paper's literal reading: the cell listed first is the basis (its cross derivative
    /// linear), the other follows it. Depends on the numbering.
    OneSided,
}

impl Network<'_> {
    fn n(&self) -> usize {
        self.sections[0].points.len()
    }

    /// The vertex of section k on chain i.
    fn vertex(&self, k: usize, i: usize) -> usize {
        (i + self.offset[k]) % self.n()
    }

    /// Unit tangent of section k's curve at its vertex on chain i (leaving it).
    fn section_tangent(&self, k: usize, i: usize) -> DVec3 {
        tangent(&self.sections[k].curve[self.vertex(k, i)], false)
    }

    /// Unit tangent of chain i at section k.
    fn chain_tangent(&self, k: usize, i: usize) -> DVec3 {
        let c = &self.chains[i];
        if k < c.len() {
            tangent(&c[k], false)
        } else {
            tangent(&c[k - 1], true)
        }
    }

    /// The four borders of cell (k, i): v = 0, v = 1, u = 0, u = 1.
    fn borders(&self, k: usize, i: usize) -> [&Cubic; 4] {
        let n = self.n();
        [
            &self.sections[k].curve[self.vertex(k, i)],
            &self.sections[k + 1].curve[self.vertex(k + 1, i)],
            &self.chains[i][k],
            &self.chains[(i + 1) % n][k],
        ]
    }

    /// The legs into cell (k, i) at the two ends of its border `side` ([`border_legs`]).
    fn legs(&self, k: usize, i: usize, side: usize) -> (DVec3, DVec3) {
        border_legs(self.borders(k, i), side)
    }

    /// The Gregory patch of cell (k, i).
    pub fn patch(&self, k: usize, i: usize) -> Gregory {
        let n = self.n();
        let i1 = (i + 1) % n;
        let one_sided = self.basis == Basis::OneSided;
        // One-sided: the cell listed first (smaller k·n + i) is the basis (None); the other
        // follows its legs.
        let chain_basis = |ci: usize| -> Option<(DVec3, DVec3)> {
            if self.crease[ci] {
                return None;
            }
            if !one_sided {
                return Some((self.section_tangent(k, ci), self.section_tangent(k + 1, ci)));
            }
            // The neighbour across chain ci: (k, ci − 1) on the left when ci == i, (k, i1)
            // on the right when ci == i1.
            let (other, other_side) = if ci == i {
                ((i + n - 1) % n, 1)
            } else {
                (i1, 0)
            };
            (other < i).then(|| self.legs(k, other, other_side))
        };
        let last = self.sections.len() - 1;
        let section_basis = |kk: usize| -> Option<(DVec3, DVec3)> {
            if kk == 0 || kk == last {
                return None;
            }
            if !one_sided {
                return Some((self.chain_tangent(kk, i), self.chain_tangent(kk, i1)));
            }
            // Across section kk: the cell below (kk − 1, i) is listed first.
            (kk == k).then(|| self.legs(kk - 1, i, 3))
        };
        with_borders(
            self.borders(k, i),
            [
                chain_basis(i),
                chain_basis(i1),
                section_basis(k),
                section_basis(k + 1),
            ],
        )
    }
}

/// The legs into a cell with borders `[v = 0, v = 1, u = 0, u = 1]` at the two ends of its
/// border `side` (0: u = 0, 1: u = 1, 2: v = 0, 3: v = 1): the first legs of the two borders
/// that cross it, pointing into the cell.
fn border_legs([s0, s1, c0, c1]: [&Cubic; 4], side: usize) -> (DVec3, DVec3) {
    match side {
        0 => (s0[1] - s0[0], s1[1] - s1[0]),
        1 => (s0[2] - s0[3], s1[2] - s1[3]),
        2 => (c0[1] - c0[0], c1[1] - c1[0]),
        _ => (c0[2] - c0[3], c1[2] - c1[3]),
    }
}

/// The Gregory patch with borders `[v = 0, v = 1, u = 0, u = 1]`: their control points are its
/// boundary points, and each border's interior copies come from [`cross_vectors`] with the
/// cell's own legs and the basis given for that border, in the order u = 0, u = 1, v = 0,
/// v = 1 (`None`: the basis construction).
pub fn with_borders(borders: [&Cubic; 4], bases: [Option<(DVec3, DVec3)>; 4]) -> Gregory {
    let [s0, s1, c0, c1] = borders;
    let mut g = Gregory {
        points: [[DVec3::ZERO; 4]; 4],
        u_copies: [[DVec3::ZERO; 2]; 2],
    };
    for t in 0..4 {
        g.points[t][0] = s0[t];
        g.points[t][3] = s1[t];
        g.points[0][t] = c0[t];
        g.points[3][t] = c1[t];
    }
    let copies = |side: usize, c: &Cubic| {
        let (a0, a3) = border_legs(borders, side);
        let x = cross_vectors(c, a0, a3, bases[side]);
        [c[1] + x[0], c[2] + x[1]]
    };
    g.u_copies[0] = copies(0, c0);
    g.u_copies[1] = copies(1, c1);
    [g.points[1][1], g.points[2][1]] = copies(2, s0);
    [g.points[1][2], g.points[2][2]] = copies(3, s1);
    g
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(a: DVec3, b: DVec3) -> Cubic {
        [a, a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b]
    }

    /// Four straight borders of a bilinear patch with the basis construction on every border
    /// reproduce the bilinear patch (skin.md, "Patches and G1"): its cross derivatives are linear.
    #[test]
    fn straight_borders_reproduce_a_bilinear_patch() {
        let c = [
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(2.0, 0.1, 0.3),
            DVec3::new(-0.2, 1.5, 0.4),
            DVec3::new(2.3, 1.8, -0.5),
        ];
        let bilinear = |u: f64, v: f64| {
            (1.0 - u) * (1.0 - v) * c[0]
                + u * (1.0 - v) * c[1]
                + (1.0 - u) * v * c[2]
                + u * v * c[3]
        };
        let (s0, s1) = (line(c[0], c[1]), line(c[2], c[3]));
        let (c0, c1) = (line(c[0], c[2]), line(c[1], c[3]));
        let g = with_borders([&s0, &s1, &c0, &c1], [None; 4]);
        for k in 0..=8 {
            for l in 0..=8 {
                let (u, v) = (k as f64 / 8.0, l as f64 / 8.0);
                assert!((g.point(u, v) - bilinear(u, v)).length() < 1e-14, "{u} {v}");
            }
        }
    }

    /// The virtual basis: with g along the crossing legs, both sides' cross vectors lie in
    /// span(g(t), C′(t)) for every t (one tangent plane), whatever each side's own legs.
    #[test]
    fn both_sides_share_the_tangent_plane() {
        let c: Cubic = [
            DVec3::ZERO,
            DVec3::new(0.3, 0.1, 1.0),
            DVec3::new(0.1, -0.2, 2.0),
            DVec3::new(0.4, 0.0, 3.0),
        ];
        let (g0, g3) = (DVec3::X, DVec3::new(0.8, 0.6, 0.0));
        let a = cross_vectors(&c, 0.7 * g0, 0.4 * g3, Some((g0, g3)));
        let b = cross_vectors(&c, -1.3 * g0, -0.2 * g3, Some((g0, g3)));
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            let g = (1.0 - t) * g0 + t * g3;
            let d = spline::derivative(&c, t);
            let n = g.cross(d).normalize();
            let s = 1.0 - t;
            let side = |x: &[DVec3; 2], a0: DVec3, a3: DVec3| {
                s * s * s * a0 + 3.0 * s * s * t * x[0] + 3.0 * s * t * t * x[1] + t * t * t * a3
            };
            let xa = side(&a, 0.7 * g0, 0.4 * g3);
            let xb = side(&b, -1.3 * g0, -0.2 * g3);
            assert!(xa.dot(n).abs() < 1e-14 && xb.dot(n).abs() < 1e-14, "{t}");
        }
    }
}
