//! Small helpers for writing arrays on rayon's pool.

use rayon::prelude::*;

/// `n` copies of `x`, written on every core. `vec![x; n]` writes them on one thread (for
/// zeros, `calloc` clears the memory it reuses on one thread): for the arrays of a
/// million-face level that is milliseconds the other core stands idle.
pub(crate) fn filled<T: Clone + Send + Sync>(n: usize, x: T) -> Vec<T> {
    let mut v = Vec::with_capacity(n);
    v.par_extend(rayon::iter::repeat_n(x, n).with_min_len(1 << 16));
    v
}

/// The first `i < n` for which `bad(i)` holds, in index order. Every index is looked at
/// on every core first (`any`); only when one is bad does a plain pass find the first, so
/// a check that usually passes costs one parallel pass and names what one pass would
/// (rayon's `position_first` costs several times a plain pass).
pub(crate) fn first_where(n: usize, bad: impl Fn(usize) -> bool + Sync + Send) -> Option<usize> {
    // Each block looks at every element without stopping (no branch per element, so the
    // look compiles to vector code where `bad` allows); the blocks stop early.
    const BLOCK: usize = 1 << 14;
    let block_bad =
        |b: usize| (b * BLOCK..((b + 1) * BLOCK).min(n)).fold(false, |acc, i| acc | bad(i));
    if (0..n.div_ceil(BLOCK)).into_par_iter().any(block_bad) {
        (0..n).find(|&i| bad(i))
    } else {
        None
    }
}

/// `s` cut at `bounds` (ascending, from 0 to `s.len()`): one piece per window.
pub(crate) fn split_at_bounds<'a, T>(mut s: &'a mut [T], bounds: &[usize]) -> Vec<&'a mut [T]> {
    let mut pieces = Vec::with_capacity(bounds.len().saturating_sub(1));
    for w in bounds.windows(2) {
        let (head, tail) = std::mem::take(&mut s).split_at_mut(w[1] - w[0]);
        pieces.push(head);
        s = tail;
    }
    pieces
}

/// Faces a task takes in [`face_chunks`].
const FACE_CHUNK: usize = 1 << 12;

/// `mesh`'s faces cut into chunks of 4,096 for rayon's pool: the first face of each chunk
/// (and the face count), and the first corner of each (and the corner count), ready for
/// [`split_at_bounds`] of per-corner arrays.
pub(crate) fn face_chunks(mesh: &crate::mesh::PolyMesh) -> (Vec<usize>, Vec<usize>) {
    let nf = mesh.num_faces();
    let faces: Vec<usize> = (0..nf).step_by(FACE_CHUNK).chain([nf]).collect();
    let corners = faces
        .iter()
        .map(|&f| {
            if f == nf {
                mesh.num_corners()
            } else {
                mesh.face_corners(f).start
            }
        })
        .collect();
    (faces, corners)
}
