//! Where a skin passes through itself (docs/algorithms/skin.md, "Crossings"): the pairs of
//! faces of its mesh that cross ([`crate::analysis::crossings`]), named by the cells they lie
//! in — the patch between two sections on a chain, or an end cap — so that a message can say
//! which sections to move.

use super::Skin;
use crate::mesh::PolyMesh;
use glam::DVec3;
use std::fmt;

/// A cell of a skin's mesh.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Cell {
    /// The patch between sections `section` and `section + 1` from chain `chain` to the next.
    Patch { section: usize, chain: usize },
    /// The planar cap closing section `section` (the first or the last).
    Cap { section: usize },
}

impl Cell {
    /// The sections the cell touches.
    pub fn sections(self) -> std::ops::RangeInclusive<usize> {
        match self {
            Cell::Patch { section, .. } => section..=section + 1,
            Cell::Cap { section } => section..=section,
        }
    }
}

impl fmt::Display for Cell {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Cell::Patch { section, chain } => write!(
                f,
                "the patch between sections {section} and {} on chain {chain}",
                section + 1
            ),
            Cell::Cap { section } => write!(f, "the cap of section {section}"),
        }
    }
}

/// The crossings of a skin's mesh.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SkinCrossings {
    /// Pairs of faces that cross.
    pub faces: usize,
    /// The pairs of cells they lie in, each once, ascending.
    pub cells: Vec<(Cell, Cell)>,
    /// The midpoint of each pair of faces (where the view marks them).
    pub points: Vec<DVec3>,
}

impl SkinCrossings {
    /// The sections the crossing cells touch, ascending.
    pub fn sections(&self) -> Vec<usize> {
        let mut out: Vec<usize> = self
            .cells
            .iter()
            .flat_map(|(a, b)| a.sections().chain(b.sections()))
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    }

    /// What to tell the user, when the skin passes through itself: how many faces, the
    /// sections, and the first pairs of cells.
    pub fn warning(&self) -> Option<String> {
        if self.faces == 0 {
            return None;
        }
        let sections: Vec<String> = self.sections().iter().map(|s| s.to_string()).collect();
        let first: Vec<String> = self
            .cells
            .iter()
            .take(3)
            .map(|(a, b)| format!("{a} and {b}"))
            .collect();
        let more = match self.cells.len() {
            n if n > 3 => format!(" and {} more pair(s) of cells", n - 3),
            _ => String::new(),
        };
        Some(format!(
            "the skin passes through itself: {} pair(s) of faces cross, near sections {} — {}{more}",
            self.faces,
            sections.join(", "),
            first.join("; ")
        ))
    }
}

impl Skin {
    /// The cell of face `f` of the mesh [`Skin::tessellate`] made at `k` quads a patch side
    /// (the caps, when made, are its last two faces).
    pub fn cell_of(&self, f: usize, k: usize) -> Cell {
        let n = self.points_per_section();
        let m = self.sections.len();
        let cols = n * k;
        let quads = (m - 1) * k * cols;
        if f >= quads {
            return Cell::Cap {
                section: if f == quads { 0 } else { m - 1 },
            };
        }
        let (r, c) = (f / cols, f % cols);
        Cell::Patch {
            section: (r / k).min(m - 2),
            chain: c / k,
        }
    }

    /// Where `mesh` (this skin tessellated at `k`) passes through itself, by cell.
    pub fn crossings(&self, mesh: &PolyMesh, k: usize) -> SkinCrossings {
        let pairs = crate::analysis::crossings(mesh);
        let mut cells: Vec<(Cell, Cell)> = pairs
            .iter()
            .map(|&(f, g)| {
                let (a, b) = (self.cell_of(f as usize, k), self.cell_of(g as usize, k));
                (a.min(b), a.max(b))
            })
            .collect();
        cells.sort_unstable();
        cells.dedup();
        SkinCrossings {
            faces: pairs.len(),
            cells,
            points: crate::analysis::crossing_points(mesh, &pairs),
        }
    }
}
