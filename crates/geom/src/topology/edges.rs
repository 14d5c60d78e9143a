//! Edge numbering: every edge is numbered by its smaller half-edge (a half-edge without a
//! twin is an edge of its own), in increasing order of that half-edge.
//!
//! On one thread this is one pass. On several, the half-edges are cut into blocks: each
//! block counts the edges it leads, the counts' prefix sums give every block its first edge
//! number, and each block numbers its own leading half-edges, writing each number to the
//! leader and to its twin. The numbers are the one pass's whatever the blocks.
//!
//! The count also gives the number of half-edges without a twin (the boundary edges), which
//! tells a closed level from an open one without another pass. Where the twins were paired
//! vertex by vertex (`super::by_vertex`), the pairing counted both per block as it wrote
//! each twin, and the numbering starts from those counts: one pass over the half-edges.

use super::NONE;
use crate::parallel::{filled, split_at_bounds};
use rayon::prelude::*;

/// Half-edges a block of the parallel numbering takes.
pub(super) const BLOCK: usize = 1 << 16;

/// What the numbering gives.
pub(super) struct Numbered {
    pub corner_edge: Vec<u32>,
    pub edge_corner: Vec<u32>,
    /// Half-edges without a twin.
    pub open: usize,
}

/// The half-edges that lead their edge per block of half-edges, and those without a twin:
/// counted by the numbering's first pass, or by the pairing as it writes the twins.
pub(super) struct Leads {
    pub per_block: Vec<u32>,
    pub open: usize,
}

/// The numbering of the half-edges whose twins are `twin`, from the counts per block of
/// [`BLOCK`] half-edges when the pairing made them.
pub(super) fn number_edges(twin: &[u32], counted: Option<&Leads>) -> Numbered {
    if rayon::current_num_threads() > 1 && twin.len() >= 4 * BLOCK {
        match counted {
            Some(leads) => from_counts(twin, BLOCK, leads),
            None => in_blocks(twin, BLOCK),
        }
    } else {
        one_pass(twin)
    }
}

/// Whether half-edge `c` with twin `t` numbers its edge: the smaller index of the two, or no
/// twin (NONE is above every index).
#[inline(always)]
pub(super) fn leads(c: u32, t: u32) -> bool {
    c < t
}

pub(super) fn one_pass(twin: &[u32]) -> Numbered {
    let n = twin.len();
    let mut corner_edge = vec![NONE; n];
    let mut edge_corner = Vec::with_capacity(n / 2 + 1);
    let mut open = 0;
    for c in 0..n {
        if leads(c as u32, twin[c]) {
            let e = edge_corner.len() as u32;
            edge_corner.push(c as u32);
            corner_edge[c] = e;
            let t = twin[c];
            if t != NONE {
                corner_edge[t as usize] = e;
            } else {
                open += 1;
            }
        }
    }
    Numbered {
        corner_edge,
        edge_corner,
        open,
    }
}

pub(super) fn in_blocks(twin: &[u32], block: usize) -> Numbered {
    let n = twin.len();
    let range = |b: usize| b * block..((b + 1) * block).min(n);
    // Per block: the edges it leads and its half-edges without a twin.
    let counts: Vec<(u32, usize)> = (0..n.div_ceil(block))
        .into_par_iter()
        .map(|b| {
            let r = range(b);
            let ts = &twin[r.clone()];
            let lead = ts
                .iter()
                .zip(r.start as u32..)
                .filter(|&(&t, c)| leads(c, t))
                .count();
            (lead as u32, ts.iter().filter(|&&t| t == NONE).count())
        })
        .collect();
    let counted = Leads {
        per_block: counts.iter().map(|&(k, _)| k).collect(),
        open: counts.iter().map(|&(_, o)| o).sum(),
    };
    from_counts(twin, block, &counted)
}

/// The numbering from the leading half-edges of each block of `block` half-edges.
pub(super) fn from_counts(twin: &[u32], block: usize, counted: &Leads) -> Numbered {
    let n = twin.len();
    let range = |b: usize| b * block..((b + 1) * block).min(n);
    let mut bounds = Vec::with_capacity(counted.per_block.len() + 1);
    bounds.push(0);
    for &k in &counted.per_block {
        bounds.push(bounds[bounds.len() - 1] + k as usize);
    }
    // Each block numbers its own leading half-edges and writes the number to the leader and
    // to its twin, wherever that lies: every half-edge is written exactly once, by the leader
    // of its edge (twins are mutual), so no slot is zeroed first or read back.
    let mut corner_edge: Vec<u32> = Vec::with_capacity(n);
    let slots = Slots(corner_edge.spare_capacity_mut().as_mut_ptr().cast::<u32>());
    let mut edge_corner = filled(bounds[bounds.len() - 1], 0);
    split_at_bounds(&mut edge_corner, &bounds)
        .into_par_iter()
        .enumerate()
        .for_each(|(b, firsts)| {
            let slots = &slots;
            let mut k = 0;
            for c in range(b) {
                if leads(c as u32, twin[c]) {
                    let e = (bounds[b] + k) as u32;
                    firsts[k] = c as u32;
                    k += 1;
                    // SAFETY: c < n and twin[c] < n lie in the allocation; each slot is
                    // written by one leader only (above), so no two writes race.
                    unsafe {
                        slots.0.add(c).write(e);
                        let t = twin[c];
                        if t != NONE {
                            slots.0.add(t as usize).write(e);
                        }
                    }
                }
            }
        });
    // SAFETY: all n slots were written (every half-edge leads or is its leader's twin).
    unsafe { corner_edge.set_len(n) };
    Numbered {
        corner_edge,
        edge_corner,
        open: counted.open,
    }
}

/// The slots of `corner_edge` that the blocks write at scattered places.
struct Slots(*mut u32);
// SAFETY: the blocks write disjoint slots (each half-edge by the leader of its edge) and
// nothing reads them until every block has finished.
unsafe impl Sync for Slots {}
