//! The combination rule's state (seed 000 §3.2(3); docs/algorithms/cylindrical.md): Doo–Sabin
//! on the faces of the vertex neighbourhoods, the simple cylindrical rule elsewhere. Which
//! faces are vertex-neighbourhood faces is decided by the steps before: a run of combination
//! steps carries one [`CombinationState`] from level to level; any other step ends the run
//! (its level carries none) and the next combination step starts a new one.

use crate::mesh::PolyMesh;
use crate::refine::{FaceKind, Provenance};
use crate::topology::Topology;

/// Which faces of a level made by a combination step are vertex-neighbourhood faces.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CombinationState {
    /// One flag per face of the level.
    pub flags: Vec<bool>,
}

impl CombinationState {
    /// The state after a combination step of `mesh` (topology `topo`) whose split gave
    /// `prov`: on the first step of a run (`parent` is `None`) the VERTEX-faces; afterwards
    /// the FACE-face of a flagged face, the EDGE-faces of its edges and the VERTEX-faces of
    /// its vertices. `unfolded` are the faces of `mesh` the fold guard moved into the blend
    /// (the fold guard, `mend/fold_guard.rs`): they count as flagged.
    pub fn next(
        mesh: &PolyMesh,
        topo: &Topology,
        prov: &Provenance,
        parent: Option<&[bool]>,
        unfolded: &[u32],
    ) -> CombinationState {
        let first = || prov.face_kind.iter().map(|&k| k == FaceKind::Vertex);
        let owned;
        let pf = match (parent, unfolded.is_empty()) {
            (Some(pf), true) => pf,
            (None, true) => {
                return CombinationState {
                    flags: first().collect(),
                };
            }
            (p, false) => {
                let mut f = p.map_or_else(|| vec![false; mesh.num_faces()], <[bool]>::to_vec);
                for &u in unfolded {
                    f[u as usize] = true;
                }
                owned = f;
                &owned
            }
        };
        let mut edge_flag = vec![false; topo.num_edges()];
        let mut vert_flag = vec![false; mesh.num_vertices()];
        for c in 0..mesh.num_corners() {
            if pf[topo.corner_face(c) as usize] {
                edge_flag[topo.corner_edge[c] as usize] = true;
                vert_flag[mesh.corner_verts[c] as usize] = true;
            }
        }
        let flags = prov
            .face_kind
            .iter()
            .zip(&prov.face_parent)
            .map(|(&k, &p)| match k {
                FaceKind::Face => pf[p as usize],
                FaceKind::Edge => edge_flag[p as usize],
                FaceKind::Vertex => vert_flag[p as usize],
            })
            .collect::<Vec<bool>>();
        let flags = if parent.is_none() {
            flags.iter().zip(first()).map(|(&a, b)| a || b).collect()
        } else {
            flags
        };
        CombinationState { flags }
    }
}
