//! Shaders validated by naga; offscreen renders compared with stored golden pictures.
//!
//! The renders need a wgpu adapter; on a machine without a GPU that is Mesa's software
//! Vulkan (`apt-get install mesa-vulkan-drivers`, which `.ci/run` installs). Set
//! `PRISM_WRITE_GOLDEN=1` to rewrite the golden PNGs after a deliberate change, and look
//! at them before committing.

use prism_geom::{EdgeAttrs, Pipeline, parse_pipeline, primitives};
use prism_viewport::{Camera, ColorBy, Offscreen, Scene, SceneOptions, Shading, View};
use std::path::PathBuf;

/// The shaders as the renderer compiles them (each with `globals.wgsl` before it).
#[test]
fn every_shader_validates() {
    use prism_viewport::renderer::{LINES_WGSL, MESH_WGSL};
    for (name, src) in [("mesh.wgsl", MESH_WGSL), ("lines.wgsl", LINES_WGSL)] {
        let module = naga::front::wgsl::parse_str(src)
            .unwrap_or_else(|e| panic!("{name}: {}", e.emit_to_string(src)));
        naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::all(),
        )
        .validate(&module)
        .unwrap_or_else(|e| panic!("{name}: {e:?}"));
    }
}

/// Mean absolute difference per channel (0..255) and the share of pixels off by more
/// than 48 in some channel.
fn difference(a: &image::RgbaImage, b: &image::RgbaImage) -> (f64, f64) {
    assert_eq!(a.dimensions(), b.dimensions());
    let mut sum = 0u64;
    let mut off = 0usize;
    for (p, q) in a.pixels().zip(b.pixels()) {
        let d: Vec<u32> = (0..3).map(|k| p.0[k].abs_diff(q.0[k]) as u32).collect();
        sum += d.iter().map(|&x| x as u64).sum::<u64>();
        if d.iter().any(|&x| x > 48) {
            off += 1;
        }
    }
    let n = (a.width() * a.height()) as f64;
    (sum as f64 / (3.0 * n), off as f64 / n)
}

fn golden(name: &str, img: &image::RgbaImage) {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(name);
    if std::env::var_os("PRISM_WRITE_GOLDEN").is_some() {
        img.save(&path).unwrap();
    }
    let want = image::open(&path)
        .unwrap_or_else(|e| panic!("{}: {e} (PRISM_WRITE_GOLDEN=1 writes it)", path.display()))
        .to_rgba8();
    let (mean, off) = difference(img, &want);
    if mean > 1.5 || off > 0.005 {
        let got = std::env::temp_dir().join(format!("got-{name}"));
        img.save(&got).unwrap();
        panic!(
            "{name}: mean difference {mean:.2}/255, {:.2} % of pixels off; this render is at {}",
            100.0 * off,
            got.display()
        );
    }
}

fn tripod_scene(pipeline: &str, opts: &SceneOptions, cage: bool) -> Scene {
    let mut p = Pipeline::new(
        primitives::tripod(),
        EdgeAttrs::new(),
        parse_pipeline(pipeline).unwrap(),
    );
    p.compute().unwrap();
    let levels = p.levels();
    let last = levels.last().unwrap();
    let kinds = last.provenance.as_ref().and_then(|p| p.face_kinds());
    let mut scene = Scene::build(&last.mesh, &last.edge_attrs, kinds, &|_| false, opts);
    if cage {
        scene.add_cage(&levels[levels.len() - 2].mesh, [0.95, 0.75, 0.25]);
    }
    scene
}

/// An edit's scene written over the buffers of the one before renders as the scene
/// uploaded afresh: a radius changed (same counts, written over), then a level more (more
/// triangles: new buffers), then the first again (fewer: written over the larger buffers).
#[test]
fn refilled_buffers_render_as_fresh_ones() {
    let gpu = Offscreen::new().expect("a wgpu adapter (install mesa-vulkan-drivers)");
    let opts = SceneOptions {
        wireframe: true,
        ..SceneOptions::default()
    };
    let a = tripod_scene("combination:r=0.2,combination:r=0.2", &opts, false);
    let b = tripod_scene("combination:r=0.35,combination:r=0.35", &opts, false);
    let c = tripod_scene(
        "combination:r=0.3,combination:r=0.3,combination:r=0.3",
        &opts,
        false,
    );
    assert_eq!(a.indices.len(), b.indices.len());
    let camera = Camera::looking(View::Iso, glam::Vec3::ZERO, a.radius());
    let mut kept = gpu.upload(&a).unwrap();
    for next in [&b, &c, &a] {
        gpu.refill(&mut kept, next).unwrap();
        let refilled = gpu.render_uploaded(&kept, &camera, 160, 120).unwrap();
        let fresh = gpu.render(next, &camera, 160, 120).unwrap();
        assert!(refilled == fresh, "a refilled scene renders differently");
    }
    let first = gpu.render(&a, &camera, 160, 120).unwrap();
    let second = gpu.render(&b, &camera, 160, 120).unwrap();
    assert!(first != second, "the test needs scenes that look different");
}

/// A scene larger than the device's largest buffer is drawn in parts, each a run of
/// triangles with its own vertices: cut into parts of at most 8 KiB, the tripod with its
/// wireframe renders pixel for pixel as in one buffer.
#[test]
fn a_scene_in_parts_renders_as_in_one_buffer() {
    let gpu = Offscreen::new().expect("a wgpu adapter (install mesa-vulkan-drivers)");
    let opts = SceneOptions {
        wireframe: true,
        shading: Shading::Smooth,
        ..SceneOptions::default()
    };
    let scene = tripod_scene(
        "combination:r=0.3,combination:r=0.3,combination:r=0.3",
        &opts,
        false,
    );
    let camera = Camera::looking(View::Iso, glam::Vec3::ZERO, scene.radius());
    let whole = gpu.upload(&scene).unwrap();
    let parts = gpu.upload_within(&scene, 8 << 10).unwrap();
    assert_eq!(whole.face_parts(), 1);
    assert!(parts.face_parts() > 4, "{} parts", parts.face_parts());
    let one = gpu.render_uploaded(&whole, &camera, 200, 150).unwrap();
    let cut = gpu.render_uploaded(&parts, &camera, 200, 150).unwrap();
    let differ = one
        .pixels()
        .zip(cut.pixels())
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(differ, 0, "a scene in parts renders differently");
}

#[test]
fn golden_renders() {
    let gpu = Offscreen::new().expect("a wgpu adapter (install mesa-vulkan-drivers)");
    let cases = [
        (
            "tripod-smooth.png",
            "combination:r=0.2,combination:r=0.2,combination:r=0.2,combination:r=0.2",
            SceneOptions {
                shading: Shading::Smooth,
                ..SceneOptions::default()
            },
            false,
            View::Iso,
        ),
        (
            "tripod-kinds-wireframe.png",
            "combination:r=0.3,combination:r=0.3",
            SceneOptions {
                color_by: ColorBy::Kind,
                wireframe: true,
                ..SceneOptions::default()
            },
            true,
            View::Iso,
        ),
        (
            "tripod-front-catmull-clark.png",
            "cut-width:d=0.1,catmull-clark,catmull-clark",
            SceneOptions {
                shading: Shading::Smooth,
                wireframe: true,
                ..SceneOptions::default()
            },
            false,
            View::Front,
        ),
    ];
    for (name, pipeline, opts, cage, view) in cases {
        let scene = tripod_scene(pipeline, &opts, cage);
        let camera = Camera::looking(view, glam::Vec3::ZERO, scene.radius());
        let img = gpu.render(&scene, &camera, 320, 240).unwrap();
        // Something was drawn: the model covers a good part of the picture.
        let bg = img.get_pixel(0, 0).0;
        let covered = img.pixels().filter(|p| p.0 != bg).count() as f64 / (320.0 * 240.0);
        assert!(
            covered > 0.15,
            "{name}: only {:.1} % covered",
            100.0 * covered
        );
        golden(name, &img);
    }
    // Bad sizes are refused, not a panic.
    let scene = tripod_scene("doo-sabin", &SceneOptions::default(), false);
    assert!(gpu.render(&scene, &Camera::default(), 0, 10).is_err());
}

/// X-ray: a red segment inside a cube is hidden by its faces, and drawn through them when the
/// scene's lines are x-rayed; the faces themselves look the same.
#[test]
fn xray_lines_show_through_the_surface() {
    let gpu = Offscreen::new().expect("a wgpu adapter (install mesa-vulkan-drivers)");
    let cube = primitives::cube3();
    let camera = Camera::looking(View::Iso, glam::Vec3::ZERO, 1.0);
    let red = |img: &image::RgbaImage| {
        img.pixels()
            .filter(|p| p[0] > 180 && p[1] < 80 && p[2] < 80)
            .count()
    };
    let render = |xray: bool| {
        let mut scene = Scene::build(
            &cube,
            &EdgeAttrs::new(),
            None,
            &|_| false,
            &SceneOptions::default(),
        );
        let c = scene.origin;
        scene.add_segments(
            &[
                (c - glam::DVec3::splat(0.3), c + glam::DVec3::splat(0.3)),
                (
                    c - glam::DVec3::new(0.3, -0.3, 0.0),
                    c + glam::DVec3::new(0.3, -0.3, 0.0),
                ),
            ],
            [1.0, 0.0, 0.0],
        );
        scene.xray = xray;
        gpu.render(&scene, &camera, 160, 120).unwrap()
    };
    let (hidden, through) = (render(false), render(true));
    assert_eq!(red(&hidden), 0, "inside the cube, hidden");
    assert!(red(&through) > 20, "x-rayed: {} red pixels", red(&through));
}
