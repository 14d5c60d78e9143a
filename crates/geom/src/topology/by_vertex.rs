//! Twins, ring starts and the single-fan check in one pass over the vertices, on every core,
//! each vertex reading only its own list of outgoing half-edges.
//!
//! Every half-edge `d: a → b` of vertex a's list ([`Outgoing`]) follows, in its loop, the
//! half-edge `p = prev d: x → a` coming in; so a's list also gives every half-edge that ends
//! at a, once. The twin of the incoming `p` is the outgoing `a → x`: a looks it up in its own
//! list and writes `twin[p]`, and as every half-edge ends at exactly one vertex, every slot is
//! written once. Each vertex checks what it sees: no destination twice among its outgoing
//! half-edges and no origin twice among its incoming ones (else two faces run an edge the
//! same way or an edge is used three times). When every vertex passes, the pairs are mutual
//! (`twin[a → x]` is written by x, from the one `x → a`) and unique: the twins of the serial
//! pass in `super::build::serial_twins`, which runs instead, naming the first bad edge, when one
//! does not.
//!
//! The same lookups give the ring start (the first outgoing half-edge that no incoming one
//! pairs with, else the first) and the fan: `ring_next(d) = twin[prev d]`, the outgoing
//! half-edge found for `prev d`. A vertex whose walk from its start does not visit its whole
//! list is not a single fan; [`super::Topology::require_single_fans`] then walks again to
//! name it. As it writes each twin, a task counts the half-edges that lead their edge per
//! block of corners (`super::edges::Leads`), which spares the edge numbering a counting pass.

use super::edges::{Leads, leads};
use super::outgoing::Outgoing;
use super::{CornerLoops, Loops, NONE, with_loops};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering::Relaxed};

/// Lists longer than this look vertices up in a sorted copy instead of scanning.
const SHORT: usize = 16;
/// Lists up to this long (valence 8: nearly every vertex) scan half the lanes.
const SHORTER: usize = 8;

/// What the pass found.
pub(super) struct ByVertex {
    pub twin: Vec<u32>,
    /// One outgoing half-edge per vertex ([`NONE`] for an unused one).
    pub ring_start: Vec<u32>,
    /// Whether every vertex's faces form a single fan.
    pub single_fans: bool,
    /// The leading half-edges per block, for the edge numbering.
    pub leads: Leads,
}

/// Scratch for a vertex with a long list (rare: a fresh one each, which keeps the hot loop
/// free of per-task state).
#[derive(Default)]
struct Scratch {
    /// Origin of the incoming half-edge before each outgoing one.
    from: Vec<u32>,
    /// Index in the list of the outgoing half-edge paired with each incoming one, or NONE.
    pair: Vec<u32>,
    /// Whether each outgoing half-edge has a twin.
    paired: Vec<bool>,
    /// (vertex, index) sorted by vertex.
    sorted: Vec<(u32, u32)>,
}

/// What one vertex found: its ring start and whether its faces form a single fan, or
/// `None` when a pair is not mutual and unique.
type Found = Option<(u32, bool)>;

/// The twins of the half-edges of corners `cv` with loops `loops`, or `None` when some
/// pair is not mutual and unique.
pub(super) fn twins(cv: &[u32], loops: &Loops, outgoing: &Outgoing) -> Option<ByVertex> {
    with_loops!(loops, l => twins_in(cv, l, outgoing))
}

/// [`twins`], compiled for one kind of loops.
fn twins_in<L: CornerLoops>(cv: &[u32], loops: L, outgoing: &Outgoing) -> Option<ByVertex> {
    let nc = cv.len();
    let nv = outgoing.vertices();
    let mut twin: Vec<u32> = Vec::with_capacity(nc);
    let slots = Slots(twin.spare_capacity_mut().as_mut_ptr().cast::<u32>());
    let sound = AtomicBool::new(true);
    let fans = AtomicBool::new(true);
    let blocks = nc.div_ceil(LEAD_BLOCK);
    let vertex = |a: usize, w: &mut Writer| {
        let list = outgoing.list(a as u32);
        let found = match list.len() {
            0 => return NONE,
            n if n <= SHORTER => short::<L, SHORTER>(list, cv, loops, w),
            _ => longer(list, cv, loops, w),
        };
        match found {
            Some((start, single)) => {
                if !single {
                    fans.store(false, Relaxed);
                }
                start
            }
            None => {
                sound.store(false, Relaxed);
                NONE
            }
        }
    };
    // Each task of vertices writes their ring starts and counts the leading half-edges it
    // paired per block of corners.
    let mut ring_start: Vec<u32> = Vec::with_capacity(nv);
    let (leads, open) = ring_start.spare_capacity_mut()[..nv]
        .par_chunks_mut(VERTEX_TASK)
        .enumerate()
        .map(|(k, chunk)| {
            let mut w = Writer {
                slots: &slots,
                leads: vec![0; blocks],
                open: 0,
            };
            for (i, slot) in chunk.iter_mut().enumerate() {
                slot.write(vertex(k * VERTEX_TASK + i, &mut w));
            }
            (w.leads, w.open)
        })
        .reduce(
            || (vec![0; blocks], 0),
            |(mut a, oa), (b, ob)| {
                a.iter_mut().zip(b).for_each(|(x, y)| *x += y);
                (a, oa + ob)
            },
        );
    // SAFETY: the chunks cover all nv slots and each was written.
    unsafe { ring_start.set_len(nv) };
    if !sound.load(Relaxed) {
        return None;
    }
    // SAFETY: the lists hold every corner once (a counting sort of the corners), and each
    // list's vertex wrote the slot of the half-edge before each of its corners: every slot.
    unsafe { twin.set_len(nc) };
    Some(ByVertex {
        twin,
        ring_start,
        single_fans: fans.load(Relaxed),
        leads: Leads {
            per_block: leads,
            open,
        },
    })
}

/// Vertices a task of the pass takes.
const VERTEX_TASK: usize = 1 << 12;

/// Corners a block of the edge numbering's counts holds.
const LEAD_BLOCK: usize = super::edges::BLOCK;

/// A task's writes of twins, with its counts.
struct Writer<'a> {
    slots: &'a Slots,
    leads: Vec<u32>,
    open: usize,
}

impl Writer<'_> {
    /// Writes the twin `t` of half-edge `p`, which ends at the calling vertex, and counts
    /// `p` if it leads its edge.
    #[inline(always)]
    fn write(&mut self, p: u32, t: u32) {
        self.slots.write(p, t);
        self.leads[p as usize / LEAD_BLOCK] += u32::from(leads(p, t));
        self.open += usize::from(t == NONE);
    }
}

/// A vertex of at most `N` ≤ 16 half-edges (nearly all): everything on the stack.
#[inline(always)]
fn short<L: CornerLoops, const N: usize>(
    list: &[u32],
    cv: &[u32],
    loops: L,
    w: &mut Writer,
) -> Found {
    let n = list.len();
    // Past n, `to` holds NONE, which no vertex is: the lookups below compare all N lanes at
    // once.
    let (mut to, mut from) = ([NONE; N], [0u32; N]);
    for (i, &d) in list.iter().enumerate() {
        to[i] = cv[loops.next(d as usize) as usize];
        from[i] = cv[loops.prev(d as usize) as usize];
    }
    let from = &from[..n];
    // Pair each incoming half-edge (from[i] → a) with the outgoing one back (a → from[i]).
    // A destination found twice, or an outgoing half-edge taken twice, is an edge used three
    // times or run twice the same way; so is an origin or a destination twice among the
    // half-edges left without a partner, which the pairing does not see.
    let mut pair = [NONE; N];
    let (mut paired, mut open) = (0u32, 0u32);
    for i in 0..n {
        let hits = lanes_equal(&to, from[i]);
        let t = if hits == 0 {
            open |= 1 << i;
            NONE
        } else {
            if hits & (hits - 1) != 0 || paired & hits != 0 {
                return None;
            }
            paired |= hits;
            let j = hits.trailing_zeros() as usize;
            pair[i] = j as u32;
            list[j]
        };
        w.write(loops.prev(list[i] as usize), t);
    }
    let all = (1u32 << n) - 1; // n ≤ 16
    if open | (all & !paired) != 0 {
        let twice = |vs: &[u32], mask: u32| {
            (0..n)
                .any(|i| mask >> i & 1 == 1 && (0..i).any(|j| mask >> j & 1 == 1 && vs[j] == vs[i]))
        };
        if twice(from, open) || twice(&to[..n], all & !paired) {
            return None;
        }
    }
    // The first outgoing half-edge without a twin, else the first.
    let first = (!paired).trailing_zeros() as usize;
    let first = if first < n { first } else { 0 };
    Some((list[first], fan(&pair[..n], first) == n))
}

/// A vertex of more than [`SHORTER`] half-edges, out of the hot loop (inlined with a
/// scratch per task, the pass took a tenth longer).
#[inline(never)]
fn longer<L: CornerLoops>(list: &[u32], cv: &[u32], loops: L, w: &mut Writer) -> Found {
    if list.len() <= SHORT {
        short::<L, SHORT>(list, cv, loops, w)
    } else {
        long(list, cv, loops, w, &mut Scratch::default())
    }
}

/// Bit j set where `to[j] == x`.
#[inline(always)]
fn lanes_equal<const N: usize>(to: &[u32; N], x: u32) -> u32 {
    let mut hits = 0u32;
    for (j, &b) in to.iter().enumerate() {
        hits |= u32::from(b == x) << j;
    }
    hits
}

/// A vertex of more than [`SHORT`] half-edges: lookups in a sorted copy.
fn long<L: CornerLoops>(
    list: &[u32],
    cv: &[u32],
    loops: L,
    w: &mut Writer,
    s: &mut Scratch,
) -> Found {
    let n = list.len();
    s.from.clear();
    s.from
        .extend(list.iter().map(|&d| cv[loops.prev(d as usize) as usize]));
    s.sorted.clear();
    s.sorted.extend(s.from.iter().map(|&x| (x, 0)));
    s.sorted.sort_unstable();
    if s.sorted.windows(2).any(|w| w[0].0 == w[1].0) {
        return None;
    }
    s.sorted.clear();
    s.sorted.extend(
        list.iter()
            .enumerate()
            .map(|(i, &d)| (cv[loops.next(d as usize) as usize], i as u32)),
    );
    s.sorted.sort_unstable();
    if s.sorted.windows(2).any(|w| w[0].0 == w[1].0) {
        return None;
    }
    s.pair.clear();
    s.paired.clear();
    s.paired.resize(n, false);
    for i in 0..n {
        let j = s
            .sorted
            .binary_search_by_key(&s.from[i], |&(b, _)| b)
            .map_or(NONE, |k| s.sorted[k].1);
        s.pair.push(j);
        let t = if j == NONE {
            NONE
        } else {
            s.paired[j as usize] = true;
            list[j as usize]
        };
        w.write(loops.prev(list[i] as usize), t);
    }
    let first = s.paired.iter().position(|&p| !p).unwrap_or(0);
    Some((list[first], fan(&s.pair, first) == n))
}

/// The number of half-edges the fan walk from list index `first` visits, following `pair`
/// (the next outgoing half-edge of the ring, NONE at a boundary); more than the list's length
/// when it runs on.
fn fan(pair: &[u32], first: usize) -> usize {
    let (mut i, mut k) = (first, 0);
    loop {
        k += 1;
        let j = pair[i];
        if j == NONE || j as usize == first {
            return k;
        }
        if k >= pair.len() {
            return pair.len() + 1;
        }
        i = j as usize;
    }
}

/// The twin slots, written at scattered places by the vertices.
struct Slots(*mut u32);
// SAFETY: the vertices write disjoint slots (each corner ends at one vertex) and nothing
// reads them until the pass has finished.
unsafe impl Sync for Slots {}

impl Slots {
    /// Writes the twin of half-edge `p`, which ends at the calling vertex.
    #[inline(always)]
    fn write(&self, p: u32, t: u32) {
        // SAFETY: p < nc, the capacity; every half-edge ends at exactly one vertex and comes
        // before exactly one of that vertex's outgoing half-edges, so each slot is written by
        // one call only, and none is read before the pass ends.
        unsafe { self.0.add(p as usize).write(t) };
    }
}
