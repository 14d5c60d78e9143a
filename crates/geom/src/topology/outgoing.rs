//! The outgoing half-edges of every vertex (CSR), each stored with its destination vertex so
//! that the twin search reads one contiguous run: a counting sort of the corners by vertex,
//! on every core.
//!
//! The corners are cut into one run per thread; each run counts its own vertices, the counts
//! give every run its slots (per vertex, the runs in corner order), and each run writes its
//! corners into its slots. Within a vertex the half-edges come in increasing corner order
//! whatever the number of runs, so the lists are those of the one-thread sort bit for bit.
//! The slots are atomics only so that the runs may write into one array at interleaved
//! places (relaxed stores and loads: plain moves on x86 and ARM).

use rayon::prelude::*;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

/// Vertices a task of the offset pass takes.
const VERTEX_BLOCK: usize = 1 << 14;
/// Corners a run takes at least.
const MIN_RUN: usize = 1 << 16;

/// Outgoing half-edges per vertex.
pub(super) struct Outgoing {
    /// `start[v]..start[v + 1]` are vertex v's slots.
    start: Vec<u32>,
    /// Half-edge `d` and its destination vertex `w`, as `d | w << 32`.
    slots: Vec<AtomicU64>,
}

impl Outgoing {
    /// The lists of the `nv` vertices of corners `cv` whose loops `next` gives.
    pub(super) fn new(nv: usize, cv: &[u32], next: &[u32]) -> Outgoing {
        let runs = rayon::current_num_threads().min(cv.len() / MIN_RUN).max(1);
        Self::in_runs(nv, cv, next, runs)
    }

    /// The same, the corners cut into `runs` runs (at least one).
    pub(super) fn in_runs(nv: usize, cv: &[u32], next: &[u32], runs: usize) -> Outgoing {
        let nc = cv.len();
        let runs = runs.max(1);
        let bound = |k: usize| k * nc / runs;
        let mut counts: Vec<Vec<u32>> = (0..runs)
            .into_par_iter()
            .map(|k| {
                let mut count = vec![0u32; nv];
                for &v in &cv[bound(k)..bound(k + 1)] {
                    count[v as usize] += 1;
                }
                count
            })
            .collect();

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

        let slots: Vec<AtomicU64> = (0..nc)
            .into_par_iter()
            .with_min_len(MIN_RUN)
            .map(|_| AtomicU64::new(0))
            .collect();
        counts.into_par_iter().enumerate().for_each(|(k, mut at)| {
            for c in bound(k)..bound(k + 1) {
                let v = cv[c] as usize;
                let w = cv[next[c] as usize];
                slots[at[v] as usize].store(c as u64 | (w as u64) << 32, Relaxed);
                at[v] += 1;
            }
        });
        Outgoing { start, slots }
    }

    /// Vertex `v`'s outgoing half-edges in corner order, each with its destination vertex.
    #[inline]
    pub(super) fn of(&self, v: u32) -> impl Iterator<Item = (u32, u32)> + Clone + '_ {
        let r = self.start[v as usize] as usize..self.start[v as usize + 1] as usize;
        self.slots[r].iter().map(|s| {
            let s = s.load(Relaxed);
            (s as u32, (s >> 32) as u32)
        })
    }
}
