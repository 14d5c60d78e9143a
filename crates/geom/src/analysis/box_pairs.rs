//! Every pair of overlapping boxes among many of very different sizes and shapes: a bounding
//! volume hierarchy tested against itself (Ericson, *Real-Time Collision Detection*, 2005,
//! §6.5 "Hierarchy traversal").
//!
//! A rounded solid's face boxes span five orders of magnitude and many are long and thin (the
//! fillet strips along a desk's edges after five steps), so no uniform grid suits them: cells
//! the size of the mean face held thousands of fillet faces each (36 million candidate pairs
//! for the Computer room's 129,066 faces, which have 516,316 overlapping box pairs), and cells
//! of the median face cut the long strips into millions. Here the boxes are split at the
//! median of their centres along the longest side of the centres' spread until at most
//! [`LEAF`] are left; a node keeps its boxes' joint box. The pairs of a node are those of
//! each child and those across the two children; the pairs across two nodes are none when
//! their boxes miss each other, else those of the larger node's children with the other.
//! Every pair of boxes is met once, under the one node that parts them.

use glam::DVec3;

/// The most boxes a leaf holds.
const LEAF: usize = 4;

/// Subtrees with fewer boxes than this are built and walked on one thread.
const SERIAL: usize = 1 << 12;

type Aabb = (DVec3, DVec3);

/// Whether two closed boxes overlap or touch.
pub(super) fn boxes_meet(a: &Aabb, b: &Aabb) -> bool {
    a.0.cmple(b.1).all() && b.0.cmple(a.1).all()
}

fn join(a: &Aabb, b: &Aabb) -> Aabb {
    (a.0.min(b.0), a.1.max(b.1))
}

/// A node: its joint box and the boxes it holds (`items[start..end]`), and its children
/// (none for a leaf).
struct Node {
    bounds: Aabb,
    start: usize,
    end: usize,
    children: Option<Box<(Node, Node)>>,
}

impl Node {
    fn len(&self) -> usize {
        self.end - self.start
    }
}

/// Builds the hierarchy over `items` (box indices, reordered in place; `centres` their boxes'
/// centres, twice over), whose first one is `items[0]` of the whole list at `offset`.
fn build(boxes: &[Aabb], centres: &[DVec3], items: &mut [u32], offset: usize) -> Node {
    let bounds = items.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |b, &i| join(&b, &boxes[i as usize]),
    );
    let (start, end) = (offset, offset + items.len());
    if items.len() <= LEAF {
        return Node {
            bounds,
            start,
            end,
            children: None,
        };
    }
    let centre = |i: u32| centres[i as usize];
    let (lo, hi) = items.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), &i| (lo.min(centre(i)), hi.max(centre(i))),
    );
    let spread = hi - lo;
    let axis = if spread.x >= spread.y && spread.x >= spread.z {
        0
    } else if spread.y >= spread.z {
        1
    } else {
        2
    };
    let mid = items.len() / 2;
    // Ties broken by index: the split, and so the walk, never depend on the order given.
    items.select_nth_unstable_by(mid, |&a, &b| {
        centre(a)[axis].total_cmp(&centre(b)[axis]).then(a.cmp(&b))
    });
    let (left, right) = items.split_at_mut(mid);
    let (l, r) = if items_len_parallel(mid) {
        rayon::join(
            || build(boxes, centres, left, offset),
            || build(boxes, centres, right, offset + mid),
        )
    } else {
        (
            build(boxes, centres, left, offset),
            build(boxes, centres, right, offset + mid),
        )
    };
    Node {
        bounds,
        start,
        end,
        children: Some(Box::new((l, r))),
    }
}

fn items_len_parallel(n: usize) -> bool {
    n >= SERIAL
}

/// The walk: `items` in the hierarchy's order, and what each pair must pass.
struct Walk<'a, K> {
    boxes: &'a [Aabb],
    items: &'a [u32],
    keep: &'a K,
}

impl<K: Fn(u32, u32) -> bool + Sync> Walk<'_, K> {
    fn push(&self, f: u32, g: u32, out: &mut Vec<(u32, u32)>) {
        if boxes_meet(&self.boxes[f as usize], &self.boxes[g as usize]) {
            let pair = (f.min(g), f.max(g));
            if (self.keep)(pair.0, pair.1) {
                out.push(pair);
            }
        }
    }

    /// The pairs of boxes under `n`.
    fn within(&self, n: &Node, out: &mut Vec<(u32, u32)>) {
        match &n.children {
            None => {
                let items = &self.items[n.start..n.end];
                for (k, &f) in items.iter().enumerate() {
                    for &g in &items[k + 1..] {
                        self.push(f, g, out);
                    }
                }
            }
            Some(c) => {
                if items_len_parallel(n.len()) {
                    let (mut a, b) = rayon::join(
                        || {
                            let mut v = Vec::new();
                            self.within(&c.0, &mut v);
                            self.within(&c.1, &mut v);
                            v
                        },
                        || {
                            let mut v = Vec::new();
                            self.across(&c.0, &c.1, &mut v);
                            v
                        },
                    );
                    a.extend(b);
                    out.extend(a);
                } else {
                    self.within(&c.0, out);
                    self.within(&c.1, out);
                    self.across(&c.0, &c.1, out);
                }
            }
        }
    }

    /// The pairs of a box under `a` and one under `b` (disjoint nodes).
    fn across(&self, a: &Node, b: &Node, out: &mut Vec<(u32, u32)>) {
        if !boxes_meet(&a.bounds, &b.bounds) {
            return;
        }
        // Split the node with more boxes (a leaf never).
        let (big, small) = match (&a.children, &b.children) {
            (None, None) => {
                for &f in &self.items[a.start..a.end] {
                    for &g in &self.items[b.start..b.end] {
                        self.push(f, g, out);
                    }
                }
                return;
            }
            (Some(_), None) => (a, b),
            (None, Some(_)) => (b, a),
            (Some(_), Some(_)) => {
                if a.len() >= b.len() {
                    (a, b)
                } else {
                    (b, a)
                }
            }
        };
        let c = big.children.as_ref().expect("split nodes have children");
        if items_len_parallel(big.len() + small.len()) {
            let (mut x, y) = rayon::join(
                || {
                    let mut v = Vec::new();
                    self.across(&c.0, small, &mut v);
                    v
                },
                || {
                    let mut v = Vec::new();
                    self.across(&c.1, small, &mut v);
                    v
                },
            );
            x.extend(y);
            out.extend(x);
        } else {
            self.across(&c.0, small, out);
            self.across(&c.1, small, out);
        }
    }
}

/// Every pair `(f, g)`, `f < g`, of `boxes` that overlap or touch and that `keep` accepts,
/// each once, in no particular order (only the kept pairs are stored). A box that is not
/// finite (a NaN corner) overlaps nothing.
pub fn overlapping_pairs(
    boxes: &[Aabb],
    keep: impl Fn(u32, u32) -> bool + Sync,
) -> Vec<(u32, u32)> {
    let mut items: Vec<u32> = (0..boxes.len() as u32)
        .filter(|&i| {
            let b = &boxes[i as usize];
            b.0.is_finite() && b.1.is_finite() && b.0.cmple(b.1).all()
        })
        .collect();
    if items.len() < 2 {
        return Vec::new();
    }
    let centres: Vec<DVec3> = boxes.iter().map(|b| b.0 + b.1).collect();
    let root = build(boxes, &centres, &mut items, 0);
    let walk = Walk {
        boxes,
        items: &items,
        keep: &keep,
    };
    let mut out = Vec::new();
    walk.within(&root, &mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scan(b: &[Aabb]) -> Vec<(u32, u32)> {
        let mut out = Vec::new();
        for f in 0..b.len() {
            for g in f + 1..b.len() {
                if boxes_meet(&b[f], &b[g]) {
                    out.push((f as u32, g as u32));
                }
            }
        }
        out
    }

    /// Boxes of sizes over five orders of magnitude, long thin ones, points, boxes touching
    /// at a face, one inside another, one with a NaN corner: the pairs are a scan's, each
    /// once.
    #[test]
    fn the_pairs_are_those_of_a_scan() {
        let mut state = 7u64;
        let mut draw = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut boxes = Vec::new();
        for i in 0..6000 {
            let c = DVec3::new(draw(), draw(), draw()) * 10.0;
            let size = 10f64.powf(-4.0 + 4.0 * draw()) * if i % 100 == 0 { 0.0 } else { 1.0 };
            let mut h = DVec3::new(draw(), draw(), draw()) * size;
            if i % 7 == 0 {
                // A strip: long on one axis.
                h[i % 3] = 3.0 * draw();
            }
            boxes.push((c - h, c + h));
        }
        boxes.push((DVec3::ZERO, DVec3::ONE));
        boxes.push((DVec3::new(1.0, 0.0, 0.0), DVec3::new(2.0, 1.0, 1.0)));
        boxes.push((DVec3::splat(0.25), DVec3::splat(0.5)));
        boxes.push((DVec3::new(f64::NAN, 0.0, 0.0), DVec3::ONE));
        let mut pairs = overlapping_pairs(&boxes, |_, _| true);
        pairs.sort_unstable();
        let want = scan(&boxes);
        assert!(want.len() > 2_000, "{}", want.len());
        assert_eq!(pairs, want);
        // `keep` filters.
        let mut odd = overlapping_pairs(&boxes, |f, g| (f + g) % 2 == 1);
        odd.sort_unstable();
        let want: Vec<_> = want.into_iter().filter(|p| (p.0 + p.1) % 2 == 1).collect();
        assert_eq!(odd, want);
        assert!(overlapping_pairs(&[], |_, _| true).is_empty());
        // All boxes one point.
        let same = vec![(DVec3::ONE, DVec3::ONE); 9];
        let mut pairs = overlapping_pairs(&same, |_, _| true);
        pairs.sort_unstable();
        assert_eq!(pairs, scan(&same));
    }
}
