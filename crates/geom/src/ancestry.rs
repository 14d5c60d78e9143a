//! Which edge of the control mesh an edge of a refined level descends from, so that an edge
//! picked on any level can be marked on the control mesh (the document) and the marks shown
//! on every level.
//!
//! - **Biquadratic step** (docs/algorithms/biquadratic.md): the child's vertices are the parent's corners,
//!   and every child edge lies on exactly one EDGE-face, the face `(next c, c, next t, t)` of
//!   the parent edge of half-edge `c` (twin `t`): its long sides `(c, next c)` run along the
//!   edge inside one parent face, its short sides `(c, next t)` cross it at a vertex. So a
//!   child edge between corners `a`, `b` descends from `edge(a)` when `b = next a` or
//!   `b = next(twin a)`, and from `edge(b)` in the mirrored cases. This is the same rule by
//!   which [`crate::edge_attrs::propagate_biquadratic`] hands attributes down.
//! - **Primal step** (child numbering of [`crate::primal`]): a child edge from the vertex
//!   point of `v` to the edge point of an edge `e` at `v` is half of `e`; edges to face points
//!   and the Loop middle-triangle edges lie inside a parent face and descend from no edge.
//! - A cylindrical step that first merged coplanar faces renumbers the parent: edges of its
//!   level have no ancestry (reported as [`AncestryError::Dissolved`]).

use crate::edge_attrs::EdgeKey;
use crate::error::MeshError;
use crate::mesh::PolyMesh;
use crate::pipeline::Level;
use crate::scheme::Scheme;
use crate::topology::{NONE, Topology};
use std::collections::HashMap;
use thiserror::Error;

#[derive(Debug, Clone, PartialEq, Error)]
pub enum AncestryError {
    #[error(
        "step {step} merged coplanar faces before refining, so the edges after it cannot be traced to the control mesh; pick on level {} or earlier",
        step - 1
    )]
    Dissolved { step: usize },
    #[error("level {level}: {source}")]
    Mesh {
        level: usize,
        #[source]
        source: MeshError,
    },
}

/// The parent edge of every child edge that has one, for one step `scheme` from `parent` to
/// `child` (whose `mesh` the step computed from `parent`'s).
pub fn parent_edges(
    parent: &PolyMesh,
    child: &PolyMesh,
    scheme: Scheme,
) -> Result<HashMap<EdgeKey, EdgeKey>, MeshError> {
    let topo = &Topology::build(parent)?;
    let key_of = |e: u32| {
        let (a, b) = topo.edge_verts(parent, e as usize);
        EdgeKey::new(a, b)
    };
    let parent_of: Box<dyn Fn(u32, u32) -> Option<u32> + '_> = match scheme {
        Scheme::Biquadratic(_) => Box::new(|a: u32, b: u32| {
            let (a, b) = (a as usize, b as usize);
            if a >= topo.next.len() || b >= topo.next.len() {
                return None;
            }
            let across = |x: usize, y: usize| {
                topo.twin[x] != NONE && topo.next[topo.twin[x] as usize] as usize == y
            };
            if topo.next[a] as usize == b || across(a, b) {
                Some(topo.corner_edge[a])
            } else if topo.next[b] as usize == a || across(b, a) {
                Some(topo.corner_edge[b])
            } else {
                None
            }
        }),
        Scheme::Primal(_) => {
            let nv = parent.num_vertices() as u32;
            let ne = topo.num_edges() as u32;
            Box::new(move |a: u32, b: u32| {
                let (v, p) = (a.min(b), a.max(b));
                if v >= nv || p < nv || p >= nv + ne {
                    return None;
                }
                let e = p - nv;
                let (x, y) = topo.edge_verts(parent, e as usize);
                (x == v || y == v).then_some(e)
            })
        }
    };
    let mut out = HashMap::new();
    for l in 0..child.num_loops() {
        let vs = child.loop_verts(l);
        for i in 0..vs.len() {
            let (a, b) = (vs[i], vs[(i + 1) % vs.len()]);
            let key = EdgeKey::new(a, b);
            if out.contains_key(&key) {
                continue;
            }
            if let Some(e) = parent_of(a, b) {
                out.insert(key, key_of(e));
            }
        }
    }
    Ok(out)
}

/// The control-mesh edge (level 0) of every edge of level `k` that descends from one.
pub fn edge_origins(
    levels: &[Level],
    steps: &[Scheme],
    k: usize,
) -> Result<HashMap<EdgeKey, EdgeKey>, AncestryError> {
    let mut map: Option<HashMap<EdgeKey, EdgeKey>> = None;
    for j in 1..=k.min(levels.len().saturating_sub(1)) {
        if levels[j]
            .report
            .as_ref()
            .is_some_and(|r| r.dissolved_edges > 0)
        {
            return Err(AncestryError::Dissolved { step: j });
        }
        let step =
            parent_edges(&levels[j - 1].mesh, &levels[j].mesh, steps[j - 1]).map_err(|source| {
                AncestryError::Mesh {
                    level: j - 1,
                    source,
                }
            })?;
        map = Some(match map {
            None => step,
            Some(prev) => step
                .into_iter()
                .filter_map(|(c, p)| prev.get(&p).map(|&o| (c, o)))
                .collect(),
        });
    }
    Ok(map.unwrap_or_else(|| {
        let mut id = HashMap::new();
        let m = &levels[0].mesh;
        for l in 0..m.num_loops() {
            let vs = m.loop_verts(l);
            for i in 0..vs.len() {
                let key = EdgeKey::new(vs[i], vs[(i + 1) % vs.len()]);
                id.insert(key, key);
            }
        }
        id
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::edge_attrs::{EdgeAttr, EdgeAttrs};
    use crate::pipeline::Pipeline;
    use crate::primitives;
    use crate::rules::CornerRule;
    use crate::{PrimalScheme, ReflexMode};

    /// Marks one control edge with a radius and checks that exactly the child edges the
    /// step handed the attribute to trace back to it.
    #[test]
    fn biquadratic_ancestry_agrees_with_attribute_propagation() {
        let m = primitives::tripod();
        let topo = Topology::build(&m).unwrap();
        for e in [0usize, 7, 20] {
            let (a, b) = topo.edge_verts(&m, e);
            let key = EdgeKey::new(a, b);
            let mut attrs = EdgeAttrs::new();
            attrs.insert(
                key,
                EdgeAttr {
                    crease: 0.0,
                    radius: Some(0.1),
                },
            );
            let steps = vec![
                Scheme::Biquadratic(CornerRule::VectorSum {
                    alpha: 0.2,
                    reflex: ReflexMode::AsPrinted,
                }),
                Scheme::Biquadratic(CornerRule::DooSabin),
            ];
            let mut p = Pipeline::new(m.clone(), attrs, steps.clone());
            p.compute().unwrap();
            let origins = edge_origins(p.levels(), &steps, 2).unwrap();
            let lv = &p.levels()[2];
            let marked: Vec<EdgeKey> = lv.edge_attrs.keys().copied().collect();
            let traced: Vec<EdgeKey> = {
                let mut t: Vec<EdgeKey> = origins
                    .iter()
                    .filter(|(_, o)| **o == key)
                    .map(|(c, _)| *c)
                    .collect();
                t.sort();
                t
            };
            assert_eq!(marked, traced, "edge {e}");
            // Every edge of a biquadratic level descends from some control edge.
            let child_topo = Topology::build(&lv.mesh).unwrap();
            assert_eq!(origins.len(), child_topo.num_edges());
        }
    }

    #[test]
    fn primal_edges_halve_their_parent_and_face_edges_have_none() {
        let m = primitives::cube3();
        for s in [PrimalScheme::CatmullClark, PrimalScheme::Loop] {
            let base = if s == PrimalScheme::Loop {
                primitives::fan_triangulated(&m)
            } else {
                m.clone()
            };
            let steps = vec![Scheme::Primal(s)];
            let mut p = Pipeline::new(base.clone(), EdgeAttrs::new(), steps.clone());
            p.compute().unwrap();
            let o = edge_origins(p.levels(), &steps, 1).unwrap();
            let pe = Topology::build(&base).unwrap().num_edges();
            // Each parent edge has two halves.
            assert_eq!(o.len(), 2 * pe, "{s:?}");
            let mut count: HashMap<EdgeKey, usize> = HashMap::new();
            for v in o.values() {
                *count.entry(*v).or_default() += 1;
            }
            assert!(count.values().all(|&c| c == 2));
            // A half lies on its parent: its far end is the parent edge's midpoint here.
            let lv = &p.levels()[1].mesh;
            for (c, par) in &o {
                let mid = 0.5 * (base.positions[par.0 as usize] + base.positions[par.1 as usize]);
                let ends = [lv.positions[c.0 as usize], lv.positions[c.1 as usize]];
                let d = base.positions[par.0 as usize] - base.positions[par.1 as usize];
                // Edge points of a smooth cube are not midpoints; both ends lie near the
                // parent edge's line through its midpoint region.
                assert!(ends.iter().any(|q| (*q - mid).length() < 0.5 * d.length()));
            }
        }
    }

    #[test]
    fn level_zero_maps_to_itself() {
        let m = primitives::cube3();
        let p = Pipeline::new(m, EdgeAttrs::new(), vec![]);
        let o = edge_origins(p.levels(), &[], 0).unwrap();
        assert_eq!(o.len(), 12);
        assert!(o.iter().all(|(a, b)| a == b));
    }
}
