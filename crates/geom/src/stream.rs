//! Writes that bypass the cache for arrays larger than it.
//!
//! A plain store to memory not in the cache first reads its line (to own it), so writing a
//! fresh 64 MB array moves 128 MB. A non-temporal store (`movnti`) writes the line without
//! reading it. The big outputs of a step (the child's points and faces: 160 MB for a
//! million quads) are written once, in order, and not read again before they have left the
//! cache anyway, so they are written this way on x86-64; elsewhere, and for values not
//! made of whole aligned 8-byte words, the plain store.

use std::mem::{MaybeUninit, align_of, size_of};

/// Writes `v` into `slot`, past the cache where that is possible. A block of such writes
/// must end with [`fence`] before another thread reads the slots.
#[inline(always)]
pub(crate) fn write<T: Copy>(slot: &mut MaybeUninit<T>, v: T) {
    #[cfg(target_arch = "x86_64")]
    {
        let p = slot.as_mut_ptr();
        if size_of::<T>().is_multiple_of(8)
            && (align_of::<T>() >= 8 || (p as usize).is_multiple_of(8))
        {
            let words = size_of::<T>() / 8;
            let src = (&v as *const T).cast::<i64>();
            let dst = p.cast::<i64>();
            for k in 0..words {
                // SAFETY: `dst` is 8-byte aligned (checked) and points to `words` writable
                // words of the slot; `src` to as many readable words of `v` (read
                // unaligned: `v` may be 4-byte aligned).
                unsafe {
                    std::arch::x86_64::_mm_stream_si64(dst.add(k), src.add(k).read_unaligned())
                };
            }
            return;
        }
    }
    slot.write(v);
}

/// Orders the non-temporal writes of this thread before what follows (an `sfence`), so
/// that a thread that later reads the slots sees them.
#[inline(always)]
pub(crate) fn fence() {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: `sfence` has no operands and no preconditions.
    unsafe {
        std::arch::x86_64::_mm_sfence()
    };
}

/// `[f(0), …, f(n − 1)]`, written past the cache on rayon's pool in chunks of 4,096, each
/// value once where it belongs (no zeroed buffer first), each chunk fenced.
pub(crate) fn collect<T: Copy + Send>(n: usize, f: impl Fn(usize) -> T + Sync) -> Vec<T> {
    use rayon::prelude::*;
    const CHUNK: usize = 1 << 12;
    let mut v: Vec<T> = Vec::with_capacity(n);
    v.spare_capacity_mut()[..n]
        .par_chunks_mut(CHUNK)
        .enumerate()
        .for_each(|(i, chunk)| {
            for (j, slot) in chunk.iter_mut().enumerate() {
                write(slot, f(i * CHUNK + j));
            }
            fence();
        });
    // SAFETY: the chunks cover slots 0..n, and each was written.
    unsafe { v.set_len(n) };
    v
}
