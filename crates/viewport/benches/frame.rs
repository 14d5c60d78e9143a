//! Frame time offscreen: a 1M-triangle mesh (a 708 × 708 torus split into 1 002 528
//! triangles, flat shaded) at 1024 × 768 with the interactive sample count of the adapter
//! (none on a software rasterizer, 4× on a GPU), read back to the CPU. The scene is
//! uploaded once; one iteration is one frame. On Mesa's software Vulkan here a bare
//! probe drew such a frame in about 125 ms (docs/performance.md).

use prism_geom::{EdgeAttrs, primitives};
use prism_viewport::{Camera, Offscreen, Scene, SceneOptions, View};

fn main() {
    divan::main();
}

#[divan::bench(sample_count = 10)]
fn frame_1m_triangles_1024x768(b: divan::Bencher) {
    let mesh = primitives::fan_triangulated(&primitives::torus(708, 708, 3.0, 1.0));
    let scene = Scene::plain(&mesh);
    assert_eq!(scene.triangles(), 1_002_528);
    let gpu = Offscreen::interactive().expect("a wgpu adapter");
    eprintln!(
        "adapter: {} ({:?})",
        gpu.adapter_info.name, gpu.adapter_info.device_type
    );
    let uploaded = gpu.upload(&scene).unwrap();
    let camera = Camera::looking(View::Iso, glam::Vec3::ZERO, scene.radius());
    b.bench(|| gpu.render_uploaded(&uploaded, &camera, 1024, 768).unwrap());
}

/// Preparing the same mesh for drawing on the CPU (triangles, normals, wireframe lines):
/// what the app does once per new level or display change.
#[divan::bench(sample_count = 5, args = [false, true])]
fn scene_build_1m_triangles(b: divan::Bencher, smooth: bool) {
    let mesh = primitives::fan_triangulated(&primitives::torus(708, 708, 3.0, 1.0));
    let opts = SceneOptions {
        shading: if smooth {
            prism_viewport::Shading::Smooth
        } else {
            prism_viewport::Shading::Flat
        },
        wireframe: true,
        ..SceneOptions::default()
    };
    b.bench(|| Scene::build(&mesh, &EdgeAttrs::new(), None, &|_| false, &opts));
}
