//! Twins, ring starts and the single-fan check in one pass over the vertices, on every core.
//!
//! Vertex a holds its outgoing half-edges `d: a → b` in corner order ([`Outgoing`]). The
//! twin of d is the one half-edge `b → a` in b's list. Each vertex checks what it can see
//! on its own: no destination twice in its list (two faces running a → b the same way, or
//! a third use of the edge) and at most one `b → a` in each neighbour's list. When every
//! vertex passes, the pairs are mutual (b's list holds the one `b → a`, a's the one
//! `a → b`) and unique: the twins of the serial pass in `super::serial_twins`, which runs
//! instead, naming the first bad edge, when one does not.
//!
//! The same list gives the ring start (the first half-edge without a twin, else the first)
//! and the fan: `ring_next(c) = twin[prev[c]]`, and `prev[c]` runs `x → a`, so its twin is
//! the half-edge `a → x` of a's own list. A vertex whose walk from its start does not visit
//! its whole list is not a single fan; [`super::Topology::require_single_fans`] then walks
//! again to name it.

use super::NONE;
use super::outgoing::{Outgoing, unpack};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering::Relaxed};

/// Lists longer than this look destinations up in a sorted copy instead of scanning.
const SHORT: usize = 16;

/// What the pass found.
pub(super) struct ByVertex {
    pub twin: Vec<u32>,
    /// One outgoing half-edge per vertex ([`NONE`] for an unused one).
    pub ring_start: Vec<u32>,
    /// Whether every vertex's faces form a single fan.
    pub single_fans: bool,
}

/// The twins of the half-edges of corners `cv` (loops given by `prev`), or `None` when
/// some pair is not mutual and unique.
pub(super) fn twins(cv: &[u32], prev: &[u32], outgoing: &Outgoing) -> Option<ByVertex> {
    let nc = cv.len();
    let nv = outgoing.vertices();
    let mut twin: Vec<u32> = Vec::with_capacity(nc);
    let slots = Slots(twin.spare_capacity_mut().as_mut_ptr().cast::<u32>());
    let sound = AtomicBool::new(true);
    let fans = AtomicBool::new(true);
    let ring_start: Vec<u32> = (0..nv)
        .into_par_iter()
        .with_min_len(1 << 12)
        .map_init(Vec::new, |scratch, a| {
            let slots = &slots;
            let list = outgoing.list(a as u32);
            if list.is_empty() {
                return NONE;
            }
            let Some(lookup) = Lookup::new(list, scratch) else {
                sound.store(false, Relaxed);
                return NONE;
            };
            let (mut first_open, a) = (NONE, a as u32);
            for &s in list {
                let (d, b) = unpack(s);
                let mut found = NONE;
                for &s in outgoing.list(b) {
                    let (t, dst) = unpack(s);
                    if dst == a {
                        if found != NONE {
                            sound.store(false, Relaxed);
                            return NONE;
                        }
                        found = t;
                    }
                }
                if found == NONE && first_open == NONE {
                    first_open = d;
                }
                // SAFETY: d < nc (a corner index); every corner lies in exactly one vertex's
                // list, so this slot is written by this vertex only.
                unsafe { slots.0.add(d as usize).write(found) };
            }
            let start = if first_open == NONE {
                unpack(list[0]).0
            } else {
                first_open
            };
            // The fan from `start`: ring_next(c) is the half-edge a → cv[prev[c]] when a's
            // list has it (its twin is then prev[c]), else the walk ends at a boundary.
            let (mut c, mut k) = (start, 0);
            loop {
                k += 1;
                let x = cv[prev[c as usize] as usize];
                match lookup.find(list, x) {
                    Some(n) if n != start && k < list.len() => c = n,
                    Some(n) if n == start => break,
                    Some(_) => {
                        k = list.len() + 1;
                        break;
                    }
                    None => break,
                }
            }
            if k != list.len() {
                fans.store(false, Relaxed);
            }
            start
        })
        .collect();
    if !sound.load(Relaxed) {
        return None;
    }
    // SAFETY: the lists hold every corner once (a counting sort of the corners), and every
    // vertex wrote the slot of each of its half-edges.
    unsafe { twin.set_len(nc) };
    Some(ByVertex {
        twin,
        ring_start,
        single_fans: fans.load(Relaxed),
    })
}

/// Finds the half-edge of a list by its destination; `None` from [`Lookup::new`] when a
/// destination comes twice.
enum Lookup<'s> {
    Scan,
    Sorted(&'s [(u32, u32)]),
}

impl<'s> Lookup<'s> {
    fn new(list: &[u64], scratch: &'s mut Vec<(u32, u32)>) -> Option<Lookup<'s>> {
        if list.len() <= SHORT {
            let twice = list
                .iter()
                .enumerate()
                .any(|(i, &s)| list[..i].iter().any(|&x| x >> 32 == s >> 32));
            return (!twice).then_some(Lookup::Scan);
        }
        scratch.clear();
        scratch.extend(list.iter().map(|&s| {
            let (d, b) = unpack(s);
            (b, d)
        }));
        scratch.sort_unstable();
        if scratch.windows(2).any(|w| w[0].0 == w[1].0) {
            return None;
        }
        Some(Lookup::Sorted(scratch))
    }

    /// The half-edge of `list` ending at `x`.
    fn find(&self, list: &[u64], x: u32) -> Option<u32> {
        match self {
            Lookup::Scan => list
                .iter()
                .map(|&s| unpack(s))
                .find(|&(_, b)| b == x)
                .map(|(d, _)| d),
            Lookup::Sorted(by_dst) => by_dst
                .binary_search_by_key(&x, |&(b, _)| b)
                .ok()
                .map(|i| by_dst[i].1),
        }
    }
}

/// The twin slots, written at scattered places by the vertices.
struct Slots(*mut u32);
// SAFETY: the vertices write disjoint slots (each corner belongs to one vertex's list) and
// nothing reads them until the pass has finished.
unsafe impl Sync for Slots {}
