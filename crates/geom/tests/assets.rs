//! The bundled samples in `assets/` are the builders of `primitives` written to disk; this
//! test keeps them from drifting apart (run with PRISM_WRITE_ASSETS=1 to rewrite them).

use prism_geom::io::{self, Document};
use prism_geom::{EdgeAttrs, PolyMesh, Topology, primitives};
use std::path::PathBuf;

fn assets() -> Vec<(&'static str, PolyMesh)> {
    vec![
        ("tripod.obj", primitives::tripod()),
        ("cube.obj", primitives::cube3()),
        ("l-block.obj", primitives::l_block()),
        ("holed-block.prism.json", primitives::holed_block()),
        ("computer-room.obj", primitives::computer_room()),
    ]
}

#[test]
fn bundled_assets_are_the_builders_and_are_closed() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../assets");
    for (name, mesh) in assets() {
        let path = dir.join(name);
        let doc = Document {
            mesh: mesh.clone(),
            edge_attrs: EdgeAttrs::new(),
            tags: Default::default(),
            ..Default::default()
        };
        if std::env::var_os("PRISM_WRITE_ASSETS").is_some() {
            io::save(&path, &doc).unwrap();
        }
        let (back, _) = io::load(&path).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(back.mesh, mesh, "{name} differs from its builder");
        let t = Topology::build(&back.mesh).unwrap();
        t.require_closed(&back.mesh).unwrap();
        assert!(prism_geom::geometry::signed_volume(&back.mesh) > 0.0);
    }
}

/// The cube whose top rim is creased, with the circle-preserving Catmull–Clark pipeline:
/// the sample for seed 002's weight on surfaces (docs/curves.md).
#[test]
fn the_creased_rim_sample_is_the_cube_with_four_creases_and_its_pipeline() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../assets/cube-rim.prism.json");
    let (doc, _) = io::load(&path).unwrap();
    assert_eq!(doc.mesh, primitives::cube3());
    assert_eq!(doc.edge_attrs.len(), 4);
    assert!(doc.edge_attrs.iter().all(|(e, a)| {
        a.crease == 10.0
            && doc.mesh.positions[e.0 as usize].z == 3.0
            && doc.mesh.positions[e.1 as usize].z == 3.0
    }));
    assert_eq!(
        prism_geom::scheme::format_pipeline(&doc.pipeline.unwrap()),
        "catmull-clark-circle,catmull-clark-circle,catmull-clark-circle,catmull-clark-circle"
    );
}

/// The bare scene files open as documents holding just their block (the app opens what
/// `prism envelope` and `prism skin` read): every `.envelope.json` and `.skin.json` sample;
/// a JSON with neither a version nor such a block is still a document error.
#[test]
fn bare_scene_files_open_as_documents() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../assets");
    let mut seen = (0, 0);
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let (doc, _) = if name.ends_with(".envelope.json") || name.ends_with(".skin.json") {
            io::load(&path).unwrap_or_else(|e| panic!("{name}: {e}"))
        } else {
            continue;
        };
        assert_eq!(doc.mesh.num_faces(), 0, "{name}");
        if name.ends_with(".envelope.json") {
            let spec = io::scene_from_str(&path, &std::fs::read_to_string(&path).unwrap()).unwrap();
            assert_eq!(doc.envelope, Some(spec), "{name}");
            seen.0 += 1;
        } else {
            assert!(doc.skin.is_some_and(|s| !s.sections.is_empty()), "{name}");
            seen.1 += 1;
        }
    }
    assert_eq!(seen, (6, 3));
    let e = io::load_str(std::path::Path::new("x.prism.json"), r#"{"t": 1.0}"#).unwrap_err();
    assert!(e.to_string().contains("missing field `version`"), "{e}");
}
