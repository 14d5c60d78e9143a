//! The skin as one welded mesh (docs/algorithms/skin.md, "Tessellation"): every patch sampled on a
//! (K+1)×(K+1) grid, K×K quads a patch. The grid of the whole skin is one cylinder of
//! `(m − 1)K + 1` rows and `nK` columns, so every vertex on a border is computed once, from one
//! patch, and shared by both sides: section vertices are mesh vertices exactly (a patch's
//! corner is its boundary point), each section curve is `nK` mesh edges, and the mesh is
//! closed with the two planar caps (one polygon each, facing away from the skin) or has exactly
//! two boundary loops without them.

use super::{Skin, SkinError};
use crate::mesh::PolyMesh;
use crate::progress::Progress;

/// Largest number of quads along a patch side.
pub const MAX_RESOLUTION: usize = 256;

impl Skin {
    /// The skin tessellated at `k` quads a patch side, with or without caps.
    pub fn tessellate(&self, k: usize, caps: bool) -> Result<PolyMesh, SkinError> {
        self.tessellate_with(k, caps, &Progress::default())
    }

    /// [`Skin::tessellate`], counting its rows of vertices done in `progress` and stopping with
    /// [`SkinError::Cancelled`] at the next row once it is cancelled (the Skin tab's progress
    /// bar and Cancel).
    pub fn tessellate_with(
        &self,
        k: usize,
        caps: bool,
        progress: &Progress,
    ) -> Result<PolyMesh, SkinError> {
        if k == 0 || k > MAX_RESOLUTION {
            return Err(SkinError::Resolution(k));
        }
        let n = self.points_per_section();
        let m = self.sections.len();
        let rows = (m - 1) * k + 1;
        let cols = n * k;
        let mut positions = Vec::with_capacity(rows * cols);
        progress.restart(rows as u64);
        for r in 0..rows {
            progress.check().map_err(|_| SkinError::Cancelled)?;
            progress.add(1);
            let cell_k = (r / k).min(m - 2);
            let v = (r - cell_k * k) as f64 / k as f64;
            for c in 0..cols {
                let (i, step) = (c / k, c % k);
                positions.push(self.patch(cell_k, i).point(step as f64 / k as f64, v));
            }
        }
        let id = |r: usize, c: usize| (r * cols + c % cols) as u32;
        let mut faces: Vec<Vec<u32>> = Vec::with_capacity((rows - 1) * cols + 2);
        for r in 0..rows - 1 {
            for c in 0..cols {
                faces.push(vec![id(r, c), id(r, c + 1), id(r + 1, c + 1), id(r + 1, c)]);
            }
        }
        if caps {
            faces.push((0..cols).rev().map(|c| id(0, c)).collect());
            faces.push((0..cols).map(|c| id(rows - 1, c)).collect());
        }
        Ok(PolyMesh::from_polygons(positions, &faces))
    }
}
