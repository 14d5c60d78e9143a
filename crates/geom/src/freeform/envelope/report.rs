//! What a built envelope says about itself: the quality of its mesh, its folds, crossings and
//! removed primitives in words, its regions described for a message, its border jump.

use super::*;

impl Envelope {
    /// The quality report ([`chart::quality`]) of [`Envelope::mesh`]'s mesh and regions; a
    /// paper build's polygons are measured as fans, a triangle counted inward when it faces
    /// its primitive's centre or the segment between a fusion strip's two centres.
    pub fn quality_of(&self, mesh: &PolyMesh, regions: &[u32]) -> chart::quality::Quality {
        self.local_quality_of(&self.to_local(mesh), regions)
    }

    /// [`Envelope::quality_of`] a mesh in local coordinates.
    fn local_quality_of(&self, mesh: &PolyMesh, regions: &[u32]) -> chart::quality::Quality {
        if self.surfacing == Surfacing::Charts {
            return chart::quality::quality(mesh, regions, &self.charts, &self.primitives);
        }
        let mut fans = PolyMesh::new();
        fans.positions = mesh.positions.clone();
        let mut fan_regions = Vec::new();
        for (f, &region) in regions.iter().enumerate().take(mesh.num_faces()) {
            let c: Vec<u32> = mesh.face_corners(f).map(|i| mesh.corner_verts[i]).collect();
            for j in 1..c.len().saturating_sub(1) {
                fans.push_face(&[&[c[0], c[j], c[j + 1]]]);
                fan_regions.push(region);
            }
        }
        chart::quality::quality_with(&fans, &fan_regions, &self.primitives, |r, x| {
            match self.network.regions.get(r as usize)?.kind {
                RegionKind::Primitive { primitive, .. } => {
                    Some(x - self.primitives[primitive].centre)
                }
                // Away from the segment between the two centres.
                RegionKind::Fusion { from, to } => {
                    let (a, b) = (self.primitives[from].centre, self.primitives[to].centre);
                    let d = b - a;
                    let s = ((x - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
                    Some(x - (a + s * d))
                }
                RegionKind::Lid { .. } => None,
            }
        })
    }

    /// The tessellation at resolution `k` and its quality report.
    pub fn quality(&self, k: usize) -> Result<(PolyMesh, chart::quality::Quality), EnvelopeError> {
        let (mesh, regions) = self.local_mesh(k, &Progress::default())?;
        let q = self.local_quality_of(&mesh, &regions);
        Ok((self.to_world(mesh), q))
    }

    /// The number of surface pieces: patches, or one chart a region.
    pub fn patch_count(&self) -> usize {
        match self.surfacing {
            Surfacing::Charts => self.charts.len(),
            Surfacing::Paper => self.patches.len(),
        }
    }

    /// The folded cells of its patches ([`folds::folds`], [`folds::FOLD_CELLS`] a side).
    pub fn folds(&self) -> Vec<folds::Fold> {
        self.folded.clone()
    }

    /// The note naming the swallowed primitives (none when none is).
    pub fn removed_note(&self) -> Option<String> {
        if self.removed.is_empty() {
            return None;
        }
        let list: Vec<String> = self.removed.iter().map(|i| i.to_string()).collect();
        Some(format!(
            "swallowed by the others (centre inside, or within r/10 of, the hull of the others' centres, or inside a larger primitive's sphere and the others' envelope; seed 004 §5.1.3): primitive(s) {}",
            list.join(", ")
        ))
    }

    /// The warning for `folds` (none when empty): how many cells of how many patches, and
    /// where the first lies.
    pub fn fold_warning(&self, folds: &[folds::Fold]) -> Option<String> {
        let first = folds.first()?;
        let mut patches: Vec<usize> = folds.iter().map(|f| f.patch).collect();
        patches.dedup();
        Some(format!(
            "{} of {} sampled cells fold ({} of {} patches: the surface turns more than 90° from the tangent planes at the patch's corners and along its nearest side), the first on {} (patch {}, u = {:.2}, v = {:.2}); a larger t or primitives further apart usually clear it",
            folds.len(),
            self.patches.len() * folds::FOLD_CELLS * folds::FOLD_CELLS,
            patches.len(),
            self.patches.len(),
            self.describe_region(first.region),
            first.patch,
            first.u,
            first.v
        ))
    }

    /// The warning for [`folds::crossings`] of its tessellation at `k` quads a patch side
    /// (none when there are none): how many pairs and where the first lies.
    pub fn crossing_warning(&self, points: &[DVec3], k: usize) -> Option<String> {
        let p = points.first()?;
        Some(format!(
            "the surface passes through itself at {} pair(s) of faces of its tessellation at {k}×{k} quads a patch, the first near ({:.4}, {:.4}, {:.4}); a t nearer 1, per-vertex t closer together or primitives further apart usually clear it",
            points.len(),
            p.x,
            p.y,
            p.z,
        ))
    }

    /// What region `r` lies on, in words: "primitive P face F", or "region R (between
    /// primitives)" for a fusion strip's quad or a lid.
    pub fn describe_region(&self, r: usize) -> String {
        match self.network.regions.get(r).map(|x| x.kind) {
            Some(network::RegionKind::Primitive { primitive, face }) => {
                format!("primitive {primitive} face {face}")
            }
            Some(network::RegionKind::Fusion { from, to }) => {
                format!("region {r} (between primitives {from} and {to})")
            }
            Some(network::RegionKind::Lid { .. }) => {
                format!("region {r} (a lid between three or more primitives)")
            }
            None => format!("region {r}"),
        }
    }

    /// The largest angle in degrees between the two sides' normals along the patch borders
    /// (analytic, 16 samples a side).
    pub fn largest_border_jump(&self) -> f64 {
        if self.surfacing == Surfacing::Charts {
            return chart::largest_border_jump(&self.network, &self.charts, 16);
        }
        patches::largest_border_jump(&self.network, &self.patches, 16)
    }
}
