//! The outgoing half-edges of every vertex (CSR): a counting sort of the corners by vertex,
//! on every core.
//!
//! The corners are cut into one run per thread; each run counts its own vertices, the counts
//! give every run its slots (per vertex, the runs in corner order), and each run writes its
//! corners into its slots. Within a vertex the half-edges come in increasing corner order
//! whatever the number of runs, so the lists are those of the one-thread sort bit for bit.
//! The runs write into one array at interleaved places (disjoint slots, through a raw
//! pointer), each slot once, with no zeroed buffer first.

use super::Loops;
use rayon::prelude::*;

/// Vertices a task of the offset pass takes.
const VERTEX_BLOCK: usize = 1 << 14;
/// Corners a run takes at least.
const MIN_RUN: usize = 1 << 16;

/// The runs the corners are cut into: one per thread, none shorter than [`MIN_RUN`].
fn runs(corners: usize) -> usize {
    rayon::current_num_threads().min(corners / MIN_RUN).max(1)
}

/// Outgoing half-edges per vertex.
pub(super) struct Outgoing<'a> {
    /// `start[v]..start[v + 1]` are vertex v's slots.
    start: Vec<u32>,
    /// The half-edges (corners), vertex after vertex.
    slots: Vec<u32>,
    /// The corners' vertices and loops, for the destinations.
    cv: &'a [u32],
    loops: &'a Loops,
}

impl<'a> Outgoing<'a> {
    /// The lists of the `nv` vertices of corners `cv` with loops `loops`.
    pub(super) fn new(nv: usize, cv: &'a [u32], loops: &'a Loops) -> Outgoing<'a> {
        Self::in_runs(nv, cv, loops, runs(cv.len()))
    }

    /// The same, the corners cut into `runs` runs (at least one).
    pub(super) fn in_runs(nv: usize, cv: &'a [u32], loops: &'a Loops, runs: usize) -> Outgoing<'a> {
        let nc = cv.len();
        let runs = runs.max(1);
        let bounds: Vec<usize> = (0..=runs).map(|k| k * nc / runs).collect();
        let counts: Vec<Vec<u32>> = (0..runs)
            .into_par_iter()
            .map(|k| {
                let mut count = vec![0u32; nv];
                for &v in &cv[bounds[k]..bounds[k + 1]] {
                    count[v as usize] += 1;
                }
                count
            })
            .collect();
        Self::from_counts(nv, cv, loops, &bounds, counts)
    }

    /// The lists of a mesh whose faces are all one loop of `K` corners, looking at each
    /// face as it is counted: `None` when some face needs the full check (not a plain
    /// triangle or quad of distinct vertices below `nv`; the caller then looks for the first
    /// such face and names what is wrong). One read of the corners where a look of its own
    /// took another.
    pub(super) fn of_uniform<const K: usize>(
        nv: usize,
        cv: &'a [u32],
        loops: &'a Loops,
    ) -> Option<Outgoing<'a>> {
        let nf = cv.len() / K;
        let runs = runs(cv.len());
        let bounds: Vec<usize> = (0..=runs).map(|k| k * nf / runs * K).collect();
        let counts: Vec<Vec<u32>> = (0..runs)
            .into_par_iter()
            .map(|k| {
                let mut count = vec![0u32; nv];
                for face in cv[bounds[k]..bounds[k + 1]].as_chunks::<K>().0 {
                    if needs_full_check(face, nv) {
                        return None;
                    }
                    for &v in face {
                        count[v as usize] += 1;
                    }
                }
                Some(count)
            })
            .collect::<Option<_>>()?;
        Some(Self::from_counts(nv, cv, loops, &bounds, counts))
    }

    /// The lists from each run's counts (run k holds corners `bounds[k]..bounds[k + 1]`).
    fn from_counts(
        nv: usize,
        cv: &'a [u32],
        loops: &'a Loops,
        bounds: &[usize],
        mut counts: Vec<Vec<u32>>,
    ) -> Outgoing<'a> {
        let nc = cv.len();
        let runs = counts.len();
        // Block totals, their prefix sums, then per vertex its start and each run's first
        // slot (the counts become the runs' write positions).
        let blocks = nv.div_ceil(VERTEX_BLOCK);
        let totals: Vec<u32> = (0..blocks)
            .into_par_iter()
            .map(|b| {
                let r = b * VERTEX_BLOCK..((b + 1) * VERTEX_BLOCK).min(nv);
                counts
                    .iter()
                    .map(|c| c[r.clone()].iter().sum::<u32>())
                    .sum()
            })
            .collect();
        let mut base = Vec::with_capacity(blocks);
        let mut sum = 0u32;
        for t in totals {
            base.push(sum);
            sum += t;
        }
        let mut start = vec![0u32; nv + 1];
        start[nv] = sum;
        let mut pieces: Vec<(&mut [u32], Vec<&mut [u32]>)> = start[..nv]
            .chunks_mut(VERTEX_BLOCK)
            .map(|s| (s, Vec::with_capacity(runs)))
            .collect();
        for count in &mut counts {
            for (piece, c) in pieces.iter_mut().zip(count.chunks_mut(VERTEX_BLOCK)) {
                piece.1.push(c);
            }
        }
        pieces
            .into_par_iter()
            .zip(base)
            .for_each(|((start, mut runs), mut at)| {
                for (i, s) in start.iter_mut().enumerate() {
                    *s = at;
                    for count in runs.iter_mut() {
                        let n = count[i];
                        count[i] = at;
                        at += n;
                    }
                }
            });

        // Every slot is written once, by the run that owns its corner, with no zeroed buffer
        // first.
        let mut slots: Vec<u32> = Vec::with_capacity(nc);
        let out = Slots(slots.spare_capacity_mut().as_mut_ptr().cast::<u32>());
        counts.into_par_iter().enumerate().for_each(|(k, mut at)| {
            let out = &out;
            let first = bounds[k];
            for (c, &v) in (first..).zip(&cv[first..bounds[k + 1]]) {
                let v = v as usize;
                // SAFETY: the slots `at[v]` of the runs are disjoint and lie in 0..nc (the
                // prefix sums of the counts above).
                unsafe { out.0.add(at[v] as usize).write(c as u32) };
                at[v] += 1;
            }
        });
        // SAFETY: the counts cover every corner, so all nc slots were written.
        unsafe { slots.set_len(nc) };
        Outgoing {
            start,
            slots,
            cv,
            loops,
        }
    }

    /// The number of vertices.
    pub(super) fn vertices(&self) -> usize {
        self.start.len() - 1
    }

    /// Vertex `v`'s outgoing half-edges in corner order.
    #[inline]
    pub(super) fn list(&self, v: u32) -> &[u32] {
        &self.slots[self.start[v as usize] as usize..self.start[v as usize + 1] as usize]
    }

    /// Vertex `v`'s outgoing half-edges in corner order, each with its destination vertex.
    #[inline]
    pub(super) fn of(&self, v: u32) -> impl Iterator<Item = (u32, u32)> + Clone + '_ {
        self.list(v)
            .iter()
            .map(|&d| (d, self.cv[self.loops.next(d as usize) as usize]))
    }
}

/// The slots the runs write at interleaved places.
struct Slots(*mut u32);
// SAFETY: the runs write disjoint slots and nothing reads them until every run has finished.
unsafe impl Sync for Slots {}

/// Whether the corners `vs` of a one-loop face are anything but a plain triangle or quad of
/// distinct vertices below `nv`: such a face gets `build.rs`'s `check_face`, which names what is wrong.
/// No branch per compare: vector code over many faces.
#[inline(always)]
pub(super) fn needs_full_check(vs: &[u32], nv: usize) -> bool {
    match *vs {
        [a, b, c] => (a.max(b).max(c) as usize >= nv) | (a == b) | (a == c) | (b == c),
        [a, b, c, d] => {
            (a.max(b).max(c).max(d) as usize >= nv)
                | (a == b)
                | (a == c)
                | (a == d)
                | (b == c)
                | (b == d)
                | (c == d)
        }
        _ => true,
    }
}
