//! The loops of a mesh's corners: the face of every corner and the next and previous corner
//! of its loop.
//!
//! Where every face is one loop of four corners (every Catmull–Clark level after the first)
//! or of three (every Loop level), corner c lies in face ⌊c / k⌋ and its neighbours in the loop
//! are the next and previous index modulo k within the face: arithmetic on the index, not
//! three stored arrays (48 MB for a million quads, written once and read by every pass).
//! Other meshes list them.

use crate::mesh::PolyMesh;
use crate::parallel::{filled, split_at_bounds};
use rayon::prelude::*;

/// The loops of a mesh's corners.
#[derive(Debug, Clone)]
pub enum Loops {
    /// Every face is one loop of four corners, corners 4f … 4f + 3.
    Quads,
    /// Every face is one loop of three corners, corners 3f … 3f + 2.
    Triangles,
    /// Listed per corner.
    Listed(Listed),
}

/// Face, next and previous corner of every corner.
#[derive(Debug, Clone, Default)]
pub struct Listed {
    pub corner_face: Vec<u32>,
    pub next: Vec<u32>,
    pub prev: Vec<u32>,
}

impl Default for Loops {
    fn default() -> Self {
        Loops::Listed(Listed::default())
    }
}

/// Face and loop neighbours of the corners, by arithmetic or from the lists: the hot passes
/// are compiled once per kind of [`Loops`] (`with_loops!`), so that the
/// arithmetic inlines into them with no branch on the kind per corner.
pub trait CornerLoops: Copy + Send + Sync {
    /// The next corner of corner `c`'s loop.
    fn next(self, c: usize) -> u32;
    /// The previous corner of corner `c`'s loop.
    fn prev(self, c: usize) -> u32;
    /// The face of corner `c`.
    fn face(self, c: usize) -> u32;
    /// The corners of face `f` of `mesh` (whose loops these are).
    fn face_corners(self, mesh: &PolyMesh, f: usize) -> std::ops::Range<usize>;
}

/// [`Loops::Quads`]: corners 4f … 4f + 3.
#[derive(Debug, Clone, Copy)]
pub struct QuadLoops;

/// [`Loops::Triangles`]: corners 3f … 3f + 2.
#[derive(Debug, Clone, Copy)]
pub struct TriLoops;

impl CornerLoops for QuadLoops {
    #[inline(always)]
    fn next(self, c: usize) -> u32 {
        ((c & !3) | ((c + 1) & 3)) as u32
    }
    #[inline(always)]
    fn prev(self, c: usize) -> u32 {
        ((c & !3) | ((c + 3) & 3)) as u32
    }
    #[inline(always)]
    fn face(self, c: usize) -> u32 {
        (c / 4) as u32
    }
    #[inline(always)]
    fn face_corners(self, _: &PolyMesh, f: usize) -> std::ops::Range<usize> {
        4 * f..4 * f + 4
    }
}

impl CornerLoops for TriLoops {
    #[inline(always)]
    fn next(self, c: usize) -> u32 {
        (if c % 3 == 2 { c - 2 } else { c + 1 }) as u32
    }
    #[inline(always)]
    fn prev(self, c: usize) -> u32 {
        (if c.is_multiple_of(3) { c + 2 } else { c - 1 }) as u32
    }
    #[inline(always)]
    fn face(self, c: usize) -> u32 {
        (c / 3) as u32
    }
    #[inline(always)]
    fn face_corners(self, _: &PolyMesh, f: usize) -> std::ops::Range<usize> {
        3 * f..3 * f + 3
    }
}

impl CornerLoops for &Listed {
    #[inline(always)]
    fn next(self, c: usize) -> u32 {
        self.next[c]
    }
    #[inline(always)]
    fn prev(self, c: usize) -> u32 {
        self.prev[c]
    }
    #[inline(always)]
    fn face(self, c: usize) -> u32 {
        self.corner_face[c]
    }
    #[inline(always)]
    fn face_corners(self, mesh: &PolyMesh, f: usize) -> std::ops::Range<usize> {
        mesh.face_corners(f)
    }
}

/// Runs `$body` with `$l` bound to the [`CornerLoops`] of `$loops` (a `&Loops`), the body
/// compiled once per kind.
macro_rules! with_loops {
    ($loops:expr, $l:ident => $body:expr) => {
        match $loops {
            $crate::topology::Loops::Quads => {
                let $l = $crate::topology::QuadLoops;
                $body
            }
            $crate::topology::Loops::Triangles => {
                let $l = $crate::topology::TriLoops;
                $body
            }
            $crate::topology::Loops::Listed(listed) => {
                let $l = listed;
                $body
            }
        }
    };
}

pub(crate) use with_loops;

impl Loops {
    /// The next corner of corner `c`'s loop.
    #[inline]
    pub fn next(&self, c: usize) -> u32 {
        with_loops!(self, l => l.next(c))
    }

    /// The previous corner of corner `c`'s loop.
    #[inline]
    pub fn prev(&self, c: usize) -> u32 {
        with_loops!(self, l => l.prev(c))
    }

    /// The face of corner `c`.
    #[inline]
    pub fn face(&self, c: usize) -> u32 {
        with_loops!(self, l => l.face(c))
    }

    /// Whether `self` and `other` give every one of `corners` corners the same face and
    /// neighbours, however each holds them.
    pub fn same(&self, other: &Loops, corners: usize) -> bool {
        (0..corners).all(|c| {
            self.next(c) == other.next(c)
                && self.prev(c) == other.prev(c)
                && self.face(c) == other.face(c)
        })
    }

    /// The loops of `mesh`, arithmetic when `uniform` (3 or 4: every face is one loop of
    /// that many corners), else listed on every core in chunks of faces (`first_faces` and
    /// `bounds` from [`crate::parallel::face_chunks`]; each chunk owns its corners).
    pub(super) fn of(
        mesh: &PolyMesh,
        uniform: Option<usize>,
        first_faces: &[usize],
        bounds: &[usize],
    ) -> Loops {
        match uniform {
            Some(4) => return Loops::Quads,
            Some(3) => return Loops::Triangles,
            _ => {}
        }
        let nc = mesh.num_corners();
        let mut l = Listed {
            corner_face: filled(nc, 0),
            next: filled(nc, 0),
            prev: filled(nc, 0),
        };
        split_at_bounds(&mut l.corner_face, bounds)
            .into_par_iter()
            .zip(split_at_bounds(&mut l.next, bounds))
            .zip(split_at_bounds(&mut l.prev, bounds))
            .enumerate()
            .for_each(|(i, ((cf, nx), pv))| {
                let base = bounds[i];
                for f in first_faces[i]..first_faces[i + 1] {
                    for lp in mesh.face_loops(f) {
                        let r = mesh.loop_corners(lp);
                        for c in r.clone() {
                            cf[c - base] = f as u32;
                            nx[c - base] = (c + 1) as u32;
                            pv[c - base] = c.wrapping_sub(1) as u32;
                        }
                        if !r.is_empty() {
                            nx[r.end - 1 - base] = r.start as u32;
                            pv[r.start - base] = (r.end - 1) as u32;
                        }
                    }
                }
            });
        Loops::Listed(l)
    }
}
