//! The clamp's reach (docs/algorithms/cylindrical.md, "Reach"): the first step of a clamped
//! combination run, taken again with the clamped radii capped where the rule would miss them.
//!
//! The clamp ([`crate::rules::overlap`]) lowers each edge until its finished round fits its
//! faces. The combination rule reaches such a radius only where its fold guard leaves the
//! edge's strips alone; where fillets of very different radii meet at a vertex (the tripod's
//! arm edge 0-9 clamped to 0.88 beside 0.12: four to one and more) the guard moves the strips
//! into the vertex blend and the fillet comes out a third smaller, at every level. So the
//! step is measured a few levels on ([`ReachOptions::depth`], at most as far as the run goes):
//! after k steps a fillet of radius r over an edge of bend ψ is the polygon whose fitted
//! circle has radius `r/cos(ψ/2^(k+1))`. Where a clamped edge misses that by more than
//! [`ReachOptions::tolerance`]·[`ReachOptions::search_share`], the clamped radii are capped at
//! c — the cap written as the edges' `fits`, which later steps keep — with c the largest
//! value, found by halving between the smallest and the largest clamped radius, at which every
//! clamped and capped edge reaches (an edge whose section has too few points to fit says
//! nothing either way); c is said rounded down to four digits, and the step taken at it is the
//! one kept. Where even the smallest misses, the clamp's own step stands and the report says
//! so.

use super::Level;
use crate::analysis::{FilletError, measure_edges};
use crate::edge_attrs::{EdgeAttrs, EdgeKey};
use crate::mesh::PolyMesh;
use crate::rules::RoundingOptions;
use crate::rules::overlap::round_down;
use crate::rules::{CornerRule, EdgeFit, Overlap, ReachOptions, Reached};
use crate::step::{StepError, StepOutput, biquadratic_step_carrying};
use crate::topology::Topology;

/// One step's result with the topology it hands on.
type Stepped = (StepOutput, Option<Topology>);

/// The edges a clamped step names and the radius each was lowered to.
fn targets(out: &StepOutput) -> Vec<(EdgeKey, f64)> {
    out.report
        .clamped
        .iter()
        .map(|f| (EdgeKey::new(f.a, f.b), f.fits))
        .collect()
}

/// Whether `level`, `depth` steps of a run from `prev`, reaches every one of `edges` (key,
/// radius): the fitted radius within `tol` of the rule's polygon there.
fn reaches(
    prev: &PolyMesh,
    level: &PolyMesh,
    depth: usize,
    edges: &[(EdgeKey, f64)],
    tol: f64,
) -> bool {
    let Ok(measured) = measure_edges(prev, level, edges) else {
        return false;
    };
    measured.iter().zip(edges).all(|(m, &(_, r))| match m {
        Ok(m) => m.polygon_error(r, depth).abs() <= tol,
        // A section with too few points says nothing either way (a small radius beside a
        // coarse level); another error is a miss.
        Err(FilletError::TooFewPoints { .. }) => true,
        Err(_) => false,
    })
}

/// The first step of a run of `rule` from level `prev`: taken once, and where it clamps
/// a radius the rule then misses (combination rule, [`Overlap::Clamp`],
/// [`ReachOptions::search`]), again with the clamped radii capped ([`super::reach`]).
pub(super) fn first_step(
    prev: &Level,
    rule: &CornerRule,
    options: &RoundingOptions,
    known: Option<Topology>,
    child_topology: bool,
    run: usize,
) -> Result<Stepped, StepError> {
    let (mesh, attrs, state) = (&prev.mesh, &prev.edge_attrs, prev.combination.as_ref());
    let step = |attrs: &EdgeAttrs, known| {
        biquadratic_step_carrying(mesh, attrs, rule, state, options, known, child_topology)
    };
    let ReachOptions {
        search,
        tolerance,
        search_share,
        depth,
        halvings,
    } = options.reach;
    let tolerance = tolerance * search_share;
    // No deeper than the run goes: a trial costs the levels it takes.
    let depth = depth.min(run).max(1);
    // The level `depth` steps on from a first step's result, the run continued as the
    // pipeline continues it.
    let on = |first: &StepOutput| -> Option<PolyMesh> {
        let go_on = RoundingOptions {
            overlap: Overlap::Unchecked { clamped: true },
            ..*options
        };
        let (mut mesh, mut attrs, mut state) = (
            first.mesh.clone(),
            first.edge_attrs.clone(),
            first.combination.clone(),
        );
        for _ in 1..depth {
            let (out, _) =
                biquadratic_step_carrying(&mesh, &attrs, rule, state.as_ref(), &go_on, None, false)
                    .ok()?;
            (mesh, attrs, state) = (out.mesh, out.edge_attrs, out.combination);
        }
        Some(mesh)
    };
    let check = |out: &StepOutput, edges: &[(EdgeKey, f64)]| {
        on(out).is_some_and(|level| reaches(mesh, &level, depth, edges, tolerance))
    };
    let first = step(attrs, known)?;
    let clamped = first.0.report.clamped.clone();
    if !search
        || options.overlap != Overlap::Clamp
        || !matches!(rule, CornerRule::Combination { .. })
        || clamped.is_empty()
        || check(&first.0, &targets(&first.0))
    {
        return Ok(first);
    }
    let mut steps = 1;
    // The step with every clamped edge capped at c, and whether it reaches them all.
    let mut capped_at = |c: f64| -> Option<(Stepped, Vec<EdgeFit>)> {
        steps += 1;
        let mut caps = Vec::new();
        let mut attrs = attrs.clone();
        for f in clamped.iter().filter(|f| f.radius > c) {
            let attr = attrs.entry(EdgeKey::new(f.a, f.b)).or_default();
            attr.fits = Some(attr.fits.map_or(c, |x| x.min(c)));
            caps.push(EdgeFit { fits: c, ..*f });
        }
        let out = step(&attrs, None).ok()?;
        let mut edges = targets(&out.0);
        edges.extend(caps.iter().map(|f| (EdgeKey::new(f.a, f.b), f.fits)));
        check(&out.0, &edges).then_some((out, caps))
    };
    let lo = clamped.iter().map(|f| f.fits).fold(f64::INFINITY, f64::min);
    let hi = clamped.iter().map(|f| f.fits).fold(0.0, f64::max);
    let Some(mut best) = capped_at(lo).map(|s| (lo, s)) else {
        let mut out = first;
        out.0.report.reached = Some(Reached {
            cap: None,
            capped: 0,
            steps,
        });
        return Ok(out);
    };
    let (mut a, mut b) = (lo, hi);
    for _ in 0..halvings {
        let c = 0.5 * (a + b);
        match capped_at(c) {
            Some(s) => {
                a = c;
                best = (c, s);
            }
            None => b = c,
        }
    }
    // The cap as it is said: four digits, rounded down.
    let said = round_down(best.0);
    if said != best.0
        && said > lo
        && let Some(s) = capped_at(said)
    {
        best = (said, s);
    }
    let (cap, ((mut out, topo), caps)) = best;
    // The capped edges are clamped edges too, to the cap, as the clamp names them.
    let report = &mut out.report;
    for f in &caps {
        if !report
            .clamped
            .iter()
            .any(|g| EdgeKey::new(g.a, g.b) == EdgeKey::new(f.a, f.b))
        {
            report.clamped.push(*f);
        }
    }
    report.reached = Some(Reached {
        cap: Some(cap),
        capped: caps.len(),
        steps,
    });
    Ok((out, topo))
}
