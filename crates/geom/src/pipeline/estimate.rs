//! The pipeline's memory estimate, before any work: the levels kept plus each step's own
//! arrays, the largest over the steps ([`crate::memory`], docs/reliability.md).

use super::{Keep, Level, Pipeline};
use crate::memory;
use crate::scheme::Scheme;

impl Pipeline {
    /// Bytes the levels kept now hold ([`Level::bytes`]), with the topologies kept
    /// for moved points and the levels a moved pipeline reuses.
    pub fn kept_bytes(&self) -> u64 {
        self.levels.iter().map(Level::bytes).sum::<u64>()
            + self
                .topologies
                .iter()
                .flatten()
                .map(|t| t.heap_bytes())
                .sum::<u64>()
            + self
                .reuse
                .iter()
                .flatten()
                .map(|r| r.topo.heap_bytes() + r.child.bytes())
                .sum::<u64>()
    }

    /// The most memory computing the remaining steps will hold at once, in bytes, estimated
    /// from the counts of the last level before any work ([`crate::memory`]): the levels
    /// kept plus each step's own, the largest over the steps, plus the process's baseline.
    pub fn estimate_peak(&self) -> u64 {
        self.estimate_peak_then(0)
    }

    /// [`Pipeline::estimate_peak`] when, after the last step, `after` more bytes are held
    /// beside the levels still kept (an export assembled in memory, the fillet report).
    pub fn estimate_peak_then(&self, after: u64) -> u64 {
        let mut kept = self.kept_bytes();
        let mut peak = kept;
        let last = self.levels.len() - 1;
        let mut counts = memory::Counts::of(&self.levels[last].mesh, None);
        let mut cur_bytes = self.levels[last].bytes();
        for k in last..self.steps.len() {
            let s = &self.steps[k];
            let carried_in = k > last && self.carries(k - 1);
            let step = self.step_bytes(&counts, s, !carried_in, self.carries(k));
            peak = peak.max(kept + step);
            let next = counts.after(s);
            let next_bytes = next.level_bytes(self.provenance(s));
            kept += next_bytes;
            if self.keep == Keep::All && matches!(s, Scheme::Primal(_)) {
                kept += counts.topology_bytes();
            }
            if !self.kept_after_next(k) {
                kept -= cur_bytes.min(kept);
            }
            counts = next;
            cur_bytes = next_bytes;
        }
        peak.max(kept + after) + memory::BASELINE
    }

    /// [`memory::step_bytes`] of a step of `scheme` from a level of `counts`, with the search
    /// of the new level for crossings when the options mend them and the step takes the last
    /// whole-level search ([`crate::rules::Mend::EveryCrossing`] in
    /// [`crate::rules::CornerRule::mends`]).
    pub(super) fn step_bytes(
        &self,
        counts: &memory::Counts,
        scheme: &Scheme,
        topology: bool,
        carry: bool,
    ) -> u64 {
        let mut b = memory::step_bytes(counts, scheme, topology, carry, self.provenance(scheme));
        if let Scheme::Biquadratic(rule) = scheme
            && rule
                .mends(&self.options)
                .contains(&crate::rules::Mend::EveryCrossing)
        {
            b += memory::crossing_bytes(&counts.after(scheme));
        }
        b
    }

    /// The counts the last level will have once every step is computed ([`memory::Counts`]).
    pub fn predicted_counts(&self) -> memory::Counts {
        let last = self.levels.len() - 1;
        self.steps[last..]
            .iter()
            .fold(memory::Counts::of(&self.levels[last].mesh, None), |c, s| {
                c.after(s)
            })
    }
}
