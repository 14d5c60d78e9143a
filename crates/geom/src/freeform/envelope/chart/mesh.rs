//! The conforming tessellation of the charts (docs/algorithms/envelope.md, "Tessellation").
//!
//! 1. Every network curve is sampled once, piece by piece between its pins (ends, T-points),
//!    in arc length with the spacing in its middle and, towards an end, no longer than the
//!    shortest piece at that network vertex grown by half a segment at a time: both regions
//!    beside a curve take these very points, so the mesh is welded along every border by
//!    construction, a T-point is an ordinary border vertex, and a short piece is met by short
//!    segments rather than by a needle.
//! 2. Each region's domain gets, besides its border samples, the points of a triangular
//!    lattice of the spacing (in chart units) lying at least half a spacing inside every side.
//! 3. The constrained Delaunay triangulation of these points with the border's segments as
//!    constraints (the `spade` crate), refined (Ruppert–Chew) until no triangle has an angle
//!    under [`ANGLE_LIMIT`] — the border segments are kept, so both sides of a curve still
//!    share its samples — covers exactly the domain; the slivers rounding may leave between
//!    three samples of one side, outside the border chain, are dropped. A short border
//!    segment (a T-point near a corner) gets a graded fan of small triangles, not a needle.
//! 4. Interior points are mapped by the chart's graph, border points are the curves' own.

use super::Chart;
use crate::freeform::envelope::EnvelopeError;
use crate::freeform::envelope::network::Network;
use crate::freeform::envelope::tolerances::TOLERANCES;
use crate::mesh::PolyMesh;
use crate::progress::Progress;
use glam::{DVec2, DVec3};
use rayon::prelude::*;
use spade::{
    AngleLimit, ConstrainedDelaunayTriangulation, Point2, RefinementParameters, Triangulation,
};

/// [`TOLERANCES`]`.angle_limit`.
pub const ANGLE_LIMIT: f64 = TOLERANCES.angle_limit;

/// The points of each curve in the mesh: (τ, mesh vertex), ascending in τ.
pub struct CurveSamples {
    pub params: Vec<Vec<(f64, u32)>>,
}

/// [`TOLERANCES`]`.growth`.
const GROWTH: f64 = TOLERANCES.growth;

/// Parameters at which a curve piece from τ = a to b is cut: spacing `spacing` in its middle,
/// growing from `s0` at a and `s1` at b by at most [`GROWTH`] a segment (arc length measured
/// on 64 chords), a and b included.
fn graded_params(
    net: &Network,
    c: usize,
    (a, b): (f64, f64),
    (s0, s1): (f64, f64),
    spacing: f64,
    most: usize,
) -> Vec<f64> {
    const CHORDS: usize = 64;
    let bez = &net.curves[c].bezier;
    let mut cum = vec![0.0; CHORDS + 1];
    let mut prev = bez.eval(a);
    for j in 1..=CHORDS {
        let p = bez.eval(a + (b - a) * j as f64 / CHORDS as f64);
        cum[j] = cum[j - 1] + p.distance(prev);
        prev = p;
    }
    let total = cum[CHORDS];
    // The spacing at arc length x, and the number of segments ∫ dx / h(x) (midpoint rule).
    let h = |x: f64| {
        spacing
            .min(s0 + (GROWTH - 1.0) * x)
            .min(s1 + (GROWTH - 1.0) * (total - x))
            .max(1e-300)
    };
    const STEPS: usize = 128;
    let mut count = vec![0.0; STEPS + 1];
    for i in 0..STEPS {
        let x = total * (i as f64 + 0.5) / STEPS as f64;
        count[i + 1] = count[i] + total / STEPS as f64 / h(x);
    }
    let n = (count[STEPS].ceil() as usize).clamp(1, most);
    let mut out = Vec::with_capacity(n + 1);
    out.push(a);
    for i in 1..n {
        // Arc length where the count reaches i·(total count)/n, then τ there.
        let target = count[STEPS] * i as f64 / n as f64;
        let k = count.partition_point(|&x| x < target).clamp(1, STEPS);
        let f = (target - count[k - 1]) / (count[k] - count[k - 1]).max(1e-300);
        let x = total * (k as f64 - 1.0 + f) / STEPS as f64;
        let j = cum.partition_point(|&y| y < x).clamp(1, CHORDS);
        let g = (x - cum[j - 1]) / (cum[j] - cum[j - 1]).max(1e-300);
        out.push(a + (b - a) * (j as f64 - 1.0 + g) / CHORDS as f64);
    }
    out.push(b);
    out
}

/// The chord length of a curve piece.
fn piece_length(net: &Network, c: usize, a: f64, b: f64) -> f64 {
    const CHORDS: usize = 32;
    let bez = &net.curves[c].bezier;
    (0..CHORDS)
        .map(|j| {
            let t = |k: usize| a + (b - a) * k as f64 / CHORDS as f64;
            bez.eval(t(j)).distance(bez.eval(t(j + 1)))
        })
        .sum()
}

/// Samples every curve that bounds a region; new mesh vertices go to `positions` (network
/// vertices keep their indices). The spacing at a network vertex is the shortest piece of any
/// curve there (at most `spacing`), so a short piece is met by short segments on every curve
/// at its ends, and both regions beside a curve take the same points.
pub fn sample_curves(
    net: &Network,
    used: &[bool],
    spacing: f64,
    most: usize,
    positions: &mut Vec<DVec3>,
) -> CurveSamples {
    let mut size = vec![spacing; net.vertices.len()];
    for (c, curve) in net.curves.iter().enumerate() {
        if !used[c] {
            continue;
        }
        for w in curve.pins.windows(2) {
            let ((a, va), (b, vb)) = (w[0], w[1]);
            let l = piece_length(net, c, a, b);
            size[va] = size[va].min(l);
            size[vb] = size[vb].min(l);
        }
    }
    let mut params = Vec::with_capacity(net.curves.len());
    for (c, curve) in net.curves.iter().enumerate() {
        let mut ps: Vec<(f64, u32)> = Vec::new();
        if used[c] {
            for w in curve.pins.windows(2) {
                let ((a, va), (b, vb)) = (w[0], w[1]);
                let ts = graded_params(net, c, (a, b), (size[va], size[vb]), spacing, most);
                if ps.is_empty() {
                    ps.push((a, va as u32));
                }
                for &t in &ts[1..ts.len() - 1] {
                    positions.push(curve.bezier.eval(t));
                    ps.push((t, (positions.len() - 1) as u32));
                }
                ps.push((b, vb as u32));
            }
        }
        params.push(ps);
    }
    CurveSamples { params }
}

impl CurveSamples {
    /// The samples from τ = a to b (a > b: backwards), both ends included.
    fn between(&self, curve: usize, a: f64, b: f64) -> Vec<(f64, u32)> {
        const SAME: f64 = TOLERANCES.same_parameter;
        let (lo, hi) = (a.min(b), a.max(b));
        let p = &self.params[curve];
        let from = p.partition_point(|&(t, _)| t < lo - SAME);
        let to = p.partition_point(|&(t, _)| t <= hi + SAME);
        let mut v = p[from..to].to_vec();
        if a > b {
            v.reverse();
        }
        v
    }
}

/// A chart's own new points and its triangles; a vertex with [`LOCAL`] set is its own point
/// `id & !LOCAL`, else a vertex of the curves' samples.
pub struct ChartMesh {
    pub points: Vec<DVec3>,
    pub triangles: Vec<[u32; 3]>,
}

/// The mark of a chart's own point in [`ChartMesh::triangles`].
pub const LOCAL: u32 = 1 << 31;

/// Triangulates one chart with border samples `samples` (their positions in `positions`);
/// `spacing` is the surface spacing.
pub fn tessellate_chart(
    chart: &Chart,
    samples: &CurveSamples,
    spacing: f64,
    positions: &[DVec3],
) -> Result<ChartMesh, EnvelopeError> {
    let fail = |why: &str| EnvelopeError::Chart {
        region: chart.region,
        why: why.to_string(),
    };
    // Border: (chart point, mesh vertex, the sides it lies on as a bit set).
    let mut border: Vec<(DVec2, u32, u64)> = Vec::new();
    let n = chart.sides.len();
    for (i, pieces) in chart.pieces.iter().enumerate() {
        let mut run: Vec<u32> = Vec::new();
        for s in pieces {
            let pts = samples.between(s.curve, s.t0, s.t1);
            let skip = usize::from(!run.is_empty());
            run.extend(pts[skip..].iter().map(|&(_, v)| v));
        }
        // The run's last point is the next side's first.
        run.pop();
        for (j, v) in run.into_iter().enumerate() {
            let x = positions[v as usize];
            let (c, _) = chart
                .frame
                .chart(x)
                .ok_or_else(|| fail("a border sample leaves its chart"))?;
            let mut on = 1u64 << (i % 64);
            if j == 0 {
                on |= 1u64 << ((i + n - 1) % n % 64);
            }
            border.push((c, v, on));
        }
    }
    // The chart's scale: surface length per chart length, at the corners.
    let corners = chart.corners();
    let scale = corners
        .iter()
        .map(|&c| chart.frame.scale(chart.value(c)))
        .sum::<f64>()
        / corners.len() as f64;
    let step = spacing / scale.max(1e-12);
    let (mut lo, mut hi) = (corners[0], corners[0]);
    for c in &corners {
        lo = lo.min(*c);
        hi = hi.max(*c);
    }
    // A layer inside the border where its segments are short or it turns sharply: a point on
    // the bisector at each such border point, 0.6 of its shorter segment in, so that the
    // triangles there are graded and a corner's angle is split.
    let nb = border.len();
    let mut layer: Vec<DVec2> = Vec::new();
    for k in 0..nb {
        let (p, c, q) = (
            border[(k + nb - 1) % nb].0,
            border[k].0,
            border[(k + 1) % nb].0,
        );
        let (u, v) = ((p - c).normalize_or_zero(), (q - c).normalize_or_zero());
        let l = (p - c).length().min((q - c).length());
        let turn = u.perp_dot(v).atan2(u.dot(v)); // interior angle, from the next to the previous
        let interior = (-turn).rem_euclid(std::f64::consts::TAU);
        let corner = border[k].2.count_ones() > 1;
        if l < 0.75 * step || (corner && interior > 2.0 * std::f64::consts::FRAC_PI_3) {
            let bis = (u + v).normalize_or_zero();
            let dir = if bis.length() == 0.0 {
                DVec2::new(-v.y, v.x)
            } else if v.perp_dot(bis) < 0.0 {
                -bis
            } else {
                bis
            };
            let x = c + dir * (0.6 * l);
            if chart.sides.iter().all(|s| s.coords(x).1 > 0.3 * l) {
                layer.push(x);
            }
        }
    }
    let mut inner: Vec<DVec2> = Vec::new();
    let dy = step * 3f64.sqrt() / 2.0;
    let rows = ((hi.y - lo.y) / dy).ceil() as i64;
    let cols = ((hi.x - lo.x) / step).ceil() as i64 + 1;
    if (rows + 1).saturating_mul(cols + 1) > 50_000_000 {
        return Err(fail("it would take too many points"));
    }
    // Lattice anchored at the chart's origin, so that it does not depend on the corners' order.
    let j0 = (lo.y / dy).floor() as i64;
    for j in j0..=j0 + rows + 1 {
        let y = j as f64 * dy;
        let shift = if j.rem_euclid(2) == 1 {
            0.5 * step
        } else {
            0.0
        };
        let i0 = ((lo.x - shift) / step).floor() as i64;
        for i in i0..=i0 + cols {
            let c = DVec2::new(i as f64 * step + shift, y);
            if chart.sides.iter().all(|s| s.coords(c).1 >= 0.5 * step)
                && layer.iter().all(|x| x.distance(c) >= 0.5 * step)
            {
                inner.push(c);
            }
        }
    }
    // Layer points that coincide (two border points' bisectors meeting) are one.
    let mut kept: Vec<DVec2> = Vec::with_capacity(layer.len());
    for x in layer {
        if kept.iter().all(|y| y.distance(x) > 1e-9 * step) {
            kept.push(x);
        }
    }
    inner.extend(kept);
    let pts: Vec<Point2<f64>> = border
        .iter()
        .map(|b| Point2::new(b.0.x, b.0.y))
        .chain(inner.iter().map(|c| Point2::new(c.x, c.y)))
        .collect();
    if pts.iter().any(|p| !(p.x.is_finite() && p.y.is_finite())) {
        return Err(fail("a point of its domain is not finite"));
    }
    let edges: Vec<[usize; 2]> = (0..nb).map(|k| [k, (k + 1) % nb]).collect();
    let mut conflicts = 0;
    let mut dt =
        ConstrainedDelaunayTriangulation::<Point2<f64>>::try_bulk_load_cdt(pts, edges, |_| {
            conflicts += 1
        })
        .map_err(|_| fail("its points could not be triangulated"))?;
    if dt.num_vertices() != nb + inner.len() {
        return Err(fail("two of its border samples coincide in the chart"));
    }
    if conflicts > 0 {
        return Err(fail("its border crosses itself in the chart"));
    }
    let before_refining = dt.num_vertices();
    let result = dt.refine(
        RefinementParameters::<f64>::new()
            .with_angle_limit(AngleLimit::from_deg(ANGLE_LIMIT))
            .keep_constraint_edges()
            .exclude_outer_faces(true)
            .with_max_additional_vertices(4 * before_refining + 64),
    );
    let outer: std::collections::HashSet<_> = result.excluded_faces.into_iter().collect();
    let inner: Vec<DVec2> = dt
        .vertices()
        .skip(nb)
        .map(|v| {
            let p = v.position();
            DVec2::new(p.x, p.y)
        })
        .collect();
    let points = chart.points(&inner);
    let id = |k: usize| -> u32 {
        if k < nb {
            border[k].1
        } else {
            LOCAL | (k - nb) as u32
        }
    };
    let mut triangles = Vec::new();
    let sides_of = |k: usize| if k < nb { border[k].2 } else { 0 };
    for f in dt.inner_faces() {
        if outer.contains(&f.fix()) {
            continue;
        }
        let [a, b, c] = f.vertices().map(|v| v.fix().index());
        if sides_of(a) & sides_of(b) & sides_of(c) != 0 {
            continue;
        }
        triangles.push([id(a), id(b), id(c)]);
    }
    Ok(ChartMesh { points, triangles })
}

/// The mesh of every chart: welded, and the region of each triangle.
pub fn tessellate(
    net: &Network,
    charts: &[Chart],
    spacing: f64,
    most: usize,
    progress: &Progress,
) -> Result<(PolyMesh, Vec<u32>), EnvelopeError> {
    let mut positions: Vec<DVec3> = net.vertices.iter().map(|v| v.position).collect();
    let mut used = vec![false; net.curves.len()];
    for ch in charts {
        for s in ch.pieces.iter().flatten() {
            used[s.curve] = true;
        }
    }
    let samples = sample_curves(net, &used, spacing, most, &mut positions);
    // The charts are independent once the curves are sampled: triangulated in parallel, then
    // numbered in chart order (the same mesh whatever the number of threads).
    // One unit of `progress` a chart; a cancel stops the charts not yet begun.
    progress.restart(charts.len() as u64);
    let parts: Vec<Result<ChartMesh, EnvelopeError>> = charts
        .par_iter()
        .map(|ch| {
            progress.check().map_err(|_| EnvelopeError::Cancelled)?;
            let part = tessellate_chart(ch, &samples, spacing, &positions);
            progress.add(1);
            part
        })
        .collect();
    let mut triangles = Vec::new();
    let mut regions = Vec::new();
    for (ch, part) in charts.iter().zip(parts) {
        let part = part?;
        let base = positions.len() as u32;
        positions.extend(part.points);
        for t in part.triangles {
            triangles.push(t.map(|v| {
                if v & LOCAL != 0 {
                    base + (v & !LOCAL)
                } else {
                    v
                }
            }));
        }
        regions.extend(std::iter::repeat_n(
            ch.region as u32,
            triangles.len() - regions.len(),
        ));
    }
    let mut mesh = PolyMesh::with_capacity(
        positions.len(),
        triangles.len(),
        triangles.len(),
        3 * triangles.len(),
    );
    mesh.positions = positions;
    for t in &triangles {
        mesh.push_face(&[t.as_slice()]);
    }
    Ok((mesh, regions))
}
