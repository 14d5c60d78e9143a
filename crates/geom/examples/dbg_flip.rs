use glam::DVec3;
use prism_geom::*;
use std::path::Path;
fn pts(m: &mesh::PolyMesh, f: usize) -> Vec<DVec3> {
    m.loop_verts(m.face_loops(f).start)
        .iter()
        .map(|&v| m.positions[v as usize])
        .collect()
}
fn main() {
    let file = std::env::var("FILE").unwrap();
    let p = std::env::var("P").unwrap();
    let lvl: usize = std::env::var("L").unwrap().parse().unwrap();
    let doc = io::load(Path::new(&file)).unwrap().0;
    let steps: Vec<scheme::Scheme> = p.split(',').map(|s| s.parse().unwrap()).collect();
    let mut pl = pipeline::Pipeline::with_tags(
        doc.mesh.clone(),
        doc.edge_attrs.clone(),
        doc.tags.clone(),
        steps,
    );
    pl.options.overlap = rules::Overlap::Clamp;
    pl.options.mend_crossings = true;
    let _ = pl.compute();
    let lv = &pl.levels()[lvl];
    let r = lv.report.as_ref().unwrap();
    let prov = lv.provenance.as_ref().unwrap();
    let m = &lv.mesh;
    let par = &pl.levels()[lvl - 1];
    let pm = &par.mesh;
    let topo = topology::Topology::build(pm).unwrap();
    let flags = par
        .combination
        .as_ref()
        .map(|c| c.flags.clone())
        .unwrap_or_default();
    println!(
        "flipped {:?} parent faces {} (dissolved {})",
        r.flipped,
        pm.num_faces(),
        r.dissolved_edges
    );
    for &f in r.flipped.iter().take(4) {
        let f = f as usize;
        let n = geometry::face_normal_raw(m, f);
        println!(
            "face {f} {:?} parent {} area {:.2e} pts {:.5?}",
            prov.face_kind[f],
            prov.face_parent[f],
            n.length(),
            pts(m, f)
        );
        let pf: Vec<usize> = match prov.face_kind[f] {
            refine::FaceKind::Face => vec![prov.face_parent[f] as usize],
            refine::FaceKind::Edge => {
                let e = prov.face_parent[f] as usize;
                if e >= topo.num_edges() {
                    vec![]
                } else {
                    topo.edge_faces(e).iter().map(|&x| x as usize).collect()
                }
            }
            refine::FaceKind::Vertex => {
                let v = prov.face_parent[f] as usize;
                topo.corners_around(v)
                    .map(|c| topo.corner_face(c as usize) as usize)
                    .collect()
            }
        };
        for g in pf {
            if g >= pm.num_faces() {
                continue;
            }
            let n = geometry::face_normal_raw(pm, g);
            println!(
                "   parent face {g} flag {} area {:.2e} n {:.3?} pts {:.5?}",
                flags.get(g).copied().unwrap_or(false),
                n.length(),
                n.normalize_or_zero(),
                pts(pm, g)
            );
        }
    }
}
