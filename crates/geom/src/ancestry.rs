//! Which edge of the control mesh an edge of a refined level descends from, so that an edge
//! picked on any level can be marked on the control mesh (the document) and the marks shown
//! on every level.
//!
//! Each level records the parent edge of every child edge lying on one
//! ([`crate::refine::Provenance::edge_parent`], from its split's
//! [`crate::refine::Numbering::edge_children`]: the four sides of an EDGE-face, the two halves
//! of a primal edge; edges inside a parent face have none); this module composes those maps
//! down the levels. They are the same maps by which [`crate::refine::propagate`] hands
//! attributes down, so a marked edge and its traced descendants agree (tested).
//! - A cylindrical step that first merged coplanar faces renumbers the parent: edges of its
//!   level have no ancestry (reported as [`AncestryError::Dissolved`]).

use crate::edge_attrs::EdgeKey;
use crate::pipeline::Level;
use std::collections::HashMap;
use thiserror::Error;

#[derive(Debug, Clone, PartialEq, Error)]
pub enum AncestryError {
    #[error(
        "step {step} merged coplanar faces before refining, so the edges after it cannot be traced to the control mesh; pick on level {} or earlier",
        step - 1
    )]
    Dissolved { step: usize },
    #[error("level {level} was computed without recording where its edges come from")]
    Unrecorded { level: usize },
}

/// The control-mesh edge (level 0) of every edge of level `k` that descends from one,
/// composed from each level's [`crate::refine::Provenance::edge_parent`].
pub fn edge_origins(
    levels: &[Level],
    k: usize,
) -> Result<HashMap<EdgeKey, EdgeKey>, AncestryError> {
    let mut map: Option<HashMap<EdgeKey, EdgeKey>> = None;
    for (j, level) in levels
        .iter()
        .enumerate()
        .take(k.min(levels.len().saturating_sub(1)) + 1)
        .skip(1)
    {
        if level.report.as_ref().is_some_and(|r| r.dissolved_edges > 0) {
            return Err(AncestryError::Dissolved { step: j });
        }
        let Some(prov) = level.provenance.as_ref() else {
            return Err(AncestryError::Unrecorded { level: j });
        };
        map = Some(match map {
            None => prov.edge_parent.iter().copied().collect(),
            Some(prev) => prov
                .edge_parent
                .iter()
                .filter_map(|(c, p)| prev.get(p).map(|&o| (*c, o)))
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
    use crate::scheme::Scheme;
    use crate::topology::Topology;
    use crate::{PrimalScheme, ReflexMode};

    /// The edges traced back to control edge `key`, sorted.
    fn descendants(origins: &HashMap<EdgeKey, EdgeKey>, key: EdgeKey) -> Vec<EdgeKey> {
        let mut t: Vec<EdgeKey> = origins
            .iter()
            .filter(|(_, o)| **o == key)
            .map(|(c, _)| *c)
            .collect();
        t.sort();
        t
    }

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
            attrs.insert(key, EdgeAttr::rounded(0.1));
            let steps = vec![
                Scheme::Biquadratic(CornerRule::VectorSum {
                    alpha: 0.2,
                    reflex: ReflexMode::AsPrinted,
                }),
                Scheme::Biquadratic(CornerRule::DooSabin),
            ];
            let mut p = Pipeline::new(m.clone(), attrs, steps.clone());
            p.compute().unwrap();
            let origins = edge_origins(p.levels(), 2).unwrap();
            let lv = &p.levels()[2];
            let marked: Vec<EdgeKey> = lv.edge_attrs.keys().copied().collect();
            assert_eq!(marked, descendants(&origins, key), "edge {e}");
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
            let o = edge_origins(p.levels(), 1).unwrap();
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

    /// The primal step hands a crease to the two halves of its edge and ancestry traces
    /// exactly those halves back, through two levels: the same edge maps.
    #[test]
    fn primal_ancestry_agrees_with_crease_propagation() {
        let m = primitives::cube3();
        let topo = Topology::build(&m).unwrap();
        let (a, b) = topo.edge_verts(&m, 5);
        let key = EdgeKey::new(a, b);
        let mut attrs = EdgeAttrs::new();
        attrs.insert(key, EdgeAttr::creased(10.0));
        let steps = vec![Scheme::Primal(PrimalScheme::CatmullClark); 2];
        let mut p = Pipeline::new(m, attrs, steps);
        p.compute().unwrap();
        let origins = edge_origins(p.levels(), 2).unwrap();
        let marked: Vec<EdgeKey> = p.levels()[2].edge_attrs.keys().copied().collect();
        assert_eq!(marked.len(), 4);
        assert_eq!(marked, descendants(&origins, key));
    }

    #[test]
    fn level_zero_maps_to_itself() {
        let m = primitives::cube3();
        let p = Pipeline::new(m, EdgeAttrs::new(), vec![]);
        let o = edge_origins(p.levels(), 0).unwrap();
        assert_eq!(o.len(), 12);
        assert!(o.iter().all(|(a, b)| a == b));
    }
}
