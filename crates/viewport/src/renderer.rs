//! The wgpu renderer: one pipeline for faces, one for lines, 4× multisampling, a depth
//! buffer. The same code draws into the app's window and into an offscreen texture
//! ([`crate::offscreen`]).

use crate::camera::Camera;
use crate::parts;
use crate::scene::{LineVertex, Scene, Vertex};
use wgpu::util::DeviceExt;

/// The WGSL sources, each with the uniforms of `globals.wgsl` before it; validated by naga in
/// a test.
pub const MESH_WGSL: &str = concat!(
    include_str!("../../../shaders/globals.wgsl"),
    include_str!("../../../shaders/mesh.wgsl")
);
pub const LINES_WGSL: &str = concat!(
    include_str!("../../../shaders/globals.wgsl"),
    include_str!("../../../shaders/lines.wgsl")
);

pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
/// Multisampling for pictures (`prism render`, golden images).
pub const PICTURE_SAMPLES: u32 = 4;

/// Multisampling for interactive frames on an adapter: 4× on a GPU, none on a software
/// rasterizer, where it costs more than the picture gains while the user turns the model.
pub fn interactive_samples(info: &wgpu::AdapterInfo) -> u32 {
    if info.device_type == wgpu::DeviceType::Cpu {
        1
    } else {
        4
    }
}

/// Background colour (linear).
pub const BACKGROUND: wgpu::Color = wgpu::Color {
    r: 0.035,
    g: 0.040,
    b: 0.052,
    a: 1.0,
};

#[repr(C)]
#[derive(Debug, Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct Globals {
    view_proj: [[f32; 4]; 4],
    eye_dir: [f32; 4],
    params: [f32; 4],
}

/// A scene uploaded to the GPU: its triangles and its lines, each in one or more parts that
/// fit the device's largest buffer ([`crate::parts`]).
pub struct GpuScene {
    faces: Vec<(wgpu::Buffer, wgpu::Buffer, u32)>,
    lines: Vec<(wgpu::Buffer, u32)>,
    /// [`Scene::xray`].
    xray: bool,
}

impl GpuScene {
    /// How many parts the triangles were cut into (1 when they fit one buffer).
    pub fn face_parts(&self) -> usize {
        self.faces.len()
    }
}

/// Why a scene could not be put on the GPU.
#[derive(Debug, thiserror::Error)]
#[error(
    "the graphics device could not hold the scene ({triangles} triangles, {mib} MiB of buffers): {reason}"
)]
pub struct UploadError {
    pub triangles: usize,
    pub mib: u64,
    pub reason: String,
}

const VERTEX: wgpu::BufferUsages = wgpu::BufferUsages::VERTEX.union(wgpu::BufferUsages::COPY_DST);
const INDEX: wgpu::BufferUsages = wgpu::BufferUsages::INDEX.union(wgpu::BufferUsages::COPY_DST);

/// A buffer holding `data` (written again by [`Renderer::refill`]).
fn buffer<T: bytemuck::Pod>(
    device: &wgpu::Device,
    label: &str,
    data: &[T],
    usage: wgpu::BufferUsages,
) -> wgpu::Buffer {
    device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some(label),
        contents: bytemuck::cast_slice(data),
        usage,
    })
}

/// Writes `data` over `buf` when it fits, else replaces `buf` by a new buffer.
fn refill<T: bytemuck::Pod>(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    buf: &mut wgpu::Buffer,
    label: &str,
    data: &[T],
    usage: wgpu::BufferUsages,
) {
    let bytes: &[u8] = bytemuck::cast_slice(data);
    // wgpu writes whole 4-byte words; every vertex and index here is a multiple of 4.
    if !bytes.is_empty() && bytes.len() as u64 <= buf.size() {
        queue.write_buffer(buf, 0, bytes);
    } else {
        *buf = buffer(device, label, data, usage);
    }
}

/// The camera uniforms of one view; several views (the compare split) draw in one pass,
/// each with its own slot.
pub struct CameraSlot {
    globals: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
}

/// Pipelines for one colour format, and the camera slot of a single view.
pub struct Renderer {
    /// Sample count of the render passes this renderer draws into.
    pub samples: u32,
    mesh_pipeline: wgpu::RenderPipeline,
    line_pipeline: wgpu::RenderPipeline,
    /// Lines drawn whatever lies in front of them (no depth test, no depth written).
    xray_pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    slot: CameraSlot,
}

impl Renderer {
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat, samples: u32) -> Renderer {
        let bgl = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("prism globals"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            }],
        });
        let slot = camera_slot(device, &bgl);
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("prism"),
            bind_group_layouts: &[Some(&bgl)],
            ..Default::default()
        });
        let pipeline = |src: &str,
                        attrs: &[wgpu::VertexAttribute],
                        stride: usize,
                        topology: wgpu::PrimitiveTopology,
                        depth: bool| {
            let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("prism shader"),
                source: wgpu::ShaderSource::Wgsl(src.into()),
            });
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("prism pipeline"),
                layout: Some(&layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_main"),
                    compilation_options: Default::default(),
                    buffers: &[Some(wgpu::VertexBufferLayout {
                        array_stride: stride as u64,
                        step_mode: wgpu::VertexStepMode::Vertex,
                        attributes: attrs,
                    })],
                },
                primitive: wgpu::PrimitiveState {
                    topology,
                    cull_mode: None,
                    ..Default::default()
                },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH_FORMAT,
                    depth_write_enabled: Some(depth),
                    depth_compare: Some(if depth {
                        wgpu::CompareFunction::LessEqual
                    } else {
                        wgpu::CompareFunction::Always
                    }),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: wgpu::MultisampleState {
                    count: samples,
                    mask: !0,
                    alpha_to_coverage_enabled: false,
                },
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some("fs_main"),
                    compilation_options: Default::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format,
                        blend: Some(wgpu::BlendState::REPLACE),
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        let mesh_pipeline = pipeline(
            MESH_WGSL,
            &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x3],
            std::mem::size_of::<Vertex>(),
            wgpu::PrimitiveTopology::TriangleList,
            true,
        );
        // Lines with the depth test, and without it (x-ray).
        let [line_pipeline, xray_pipeline] = [true, false].map(|depth| {
            pipeline(
                LINES_WGSL,
                &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3],
                std::mem::size_of::<LineVertex>(),
                wgpu::PrimitiveTopology::LineList,
                depth,
            )
        });
        Renderer {
            samples,
            mesh_pipeline,
            line_pipeline,
            xray_pipeline,
            layout: bgl,
            slot,
        }
    }

    /// A camera slot for one more view.
    pub fn camera_slot(&self, device: &wgpu::Device) -> CameraSlot {
        camera_slot(device, &self.layout)
    }

    /// Uploads a scene into new buffers, in parts where it is larger than the device's largest
    /// buffer. Running out of GPU memory is an error, not a crash.
    pub fn upload(&self, device: &wgpu::Device, scene: &Scene) -> Result<GpuScene, UploadError> {
        self.upload_within(device, scene, device.limits().max_buffer_size)
    }

    /// [`Renderer::upload`] with buffers of at most `max_bytes` (tests cut small scenes).
    pub fn upload_within(
        &self,
        device: &wgpu::Device,
        scene: &Scene,
        max_bytes: u64,
    ) -> Result<GpuScene, UploadError> {
        let memory = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let invalid = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let faces = if parts::faces_fit(&scene.vertices, &scene.indices, max_bytes) {
            vec![face_buffers(device, &scene.vertices, &scene.indices)]
        } else {
            parts::split_faces(&scene.vertices, &scene.indices, max_bytes)
                .iter()
                .map(|p| face_buffers(device, &p.vertices, &p.indices))
                .collect()
        };
        let lines = parts::split_lines(&scene.lines, max_bytes)
            .map(|run| (buffer(device, "prism lines", run, VERTEX), run.len() as u32))
            .collect();
        let errors = [invalid.pop(), memory.pop()].map(pollster::block_on);
        match errors.into_iter().flatten().next() {
            None => Ok(GpuScene {
                faces,
                lines,
                xray: scene.xray,
            }),
            Some(e) => Err(UploadError {
                triangles: scene.indices.len() / 3,
                mib: scene_bytes(scene).div_ceil(1 << 20),
                reason: e.to_string(),
            }),
        }
    }

    /// Uploads a scene into `gpu`'s buffers where it fits them (an edit that keeps the
    /// counts — a vertex dragged, a radius changed — writes over the old data without a new
    /// allocation on the GPU), into new ones where it does not.
    pub fn refill(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        gpu: &mut GpuScene,
        scene: &Scene,
    ) -> Result<(), UploadError> {
        let max = device.limits().max_buffer_size;
        if gpu.faces.len() > 1
            || gpu.lines.len() > 1
            || !parts::faces_fit(&scene.vertices, &scene.indices, max)
            || !parts::fits::<LineVertex>(scene.lines.len(), max)
        {
            *gpu = self.upload(device, scene)?;
            return Ok(());
        }
        gpu.xray = scene.xray;
        match gpu.faces.first_mut() {
            Some((vertices, indices, count)) => {
                refill(
                    device,
                    queue,
                    vertices,
                    "prism vertices",
                    &scene.vertices,
                    VERTEX,
                );
                refill(
                    device,
                    queue,
                    indices,
                    "prism indices",
                    &scene.indices,
                    INDEX,
                );
                *count = scene.indices.len() as u32;
            }
            None => gpu.faces = vec![face_buffers(device, &scene.vertices, &scene.indices)],
        }
        match (gpu.lines.first_mut(), scene.lines.is_empty()) {
            (_, true) => gpu.lines.clear(),
            (Some((buf, n)), false) => {
                refill(device, queue, buf, "prism lines", &scene.lines, VERTEX);
                *n = scene.lines.len() as u32;
            }
            (None, false) => {
                gpu.lines = vec![(
                    buffer(device, "prism lines", &scene.lines, VERTEX),
                    scene.lines.len() as u32,
                )]
            }
        }
        Ok(())
    }

    /// Sets the camera for the next [`Renderer::draw`].
    pub fn set_camera(&self, queue: &wgpu::Queue, camera: &Camera, aspect: f32) {
        set_slot_camera(queue, &self.slot, camera, aspect);
    }

    /// Sets the camera of one view's slot.
    pub fn set_slot_camera(
        &self,
        queue: &wgpu::Queue,
        slot: &CameraSlot,
        camera: &Camera,
        aspect: f32,
    ) {
        set_slot_camera(queue, slot, camera, aspect);
    }

    /// Draws a scene into a render pass (with `self.samples` samples and [`DEPTH_FORMAT`]).
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, scene: &GpuScene) {
        self.draw_in(pass, &self.slot, scene);
    }

    /// Draws a scene with the camera of `slot`.
    pub fn draw_in(&self, pass: &mut wgpu::RenderPass<'_>, slot: &CameraSlot, scene: &GpuScene) {
        pass.set_bind_group(0, &slot.bind_group, &[]);
        pass.set_pipeline(&self.mesh_pipeline);
        for (vertices, indices, count) in scene.faces.iter().filter(|f| f.2 > 0) {
            pass.set_vertex_buffer(0, vertices.slice(..));
            pass.set_index_buffer(indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..*count, 0, 0..1);
        }
        pass.set_pipeline(if scene.xray {
            &self.xray_pipeline
        } else {
            &self.line_pipeline
        });
        for (buf, n) in scene.lines.iter().filter(|l| l.1 > 0) {
            pass.set_vertex_buffer(0, buf.slice(..));
            pass.draw(0..*n, 0..1);
        }
    }
}

/// The vertex and index buffers of one part and its index count.
fn face_buffers(
    device: &wgpu::Device,
    vertices: &[Vertex],
    indices: &[u32],
) -> (wgpu::Buffer, wgpu::Buffer, u32) {
    (
        buffer(device, "prism vertices", vertices, VERTEX),
        buffer(device, "prism indices", indices, INDEX),
        indices.len() as u32,
    )
}

/// Bytes a scene takes on the GPU.
pub fn scene_bytes(scene: &Scene) -> u64 {
    (scene.vertices.len() * std::mem::size_of::<Vertex>()
        + scene.indices.len() * 4
        + scene.lines.len() * std::mem::size_of::<LineVertex>()) as u64
}

fn camera_slot(device: &wgpu::Device, layout: &wgpu::BindGroupLayout) -> CameraSlot {
    let globals = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("prism globals"),
        size: std::mem::size_of::<Globals>() as u64,
        usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("prism globals"),
        layout,
        entries: &[wgpu::BindGroupEntry {
            binding: 0,
            resource: globals.as_entire_binding(),
        }],
    });
    CameraSlot {
        globals,
        bind_group,
    }
}

fn set_slot_camera(queue: &wgpu::Queue, slot: &CameraSlot, camera: &Camera, aspect: f32) {
    let eye_dir = (camera.eye() - camera.target).normalize_or_zero();
    // A key light above and to the left of the eye, fixed to the camera.
    let right = (-eye_dir).cross(glam::Vec3::Z).normalize_or(glam::Vec3::X);
    let up = right.cross(-eye_dir);
    let key = (eye_dir + 0.7 * up - 0.5 * right).normalize_or_zero();
    let g = Globals {
        view_proj: camera.view_proj(aspect).to_cols_array_2d(),
        eye_dir: [eye_dir.x, eye_dir.y, eye_dir.z, 0.0],
        params: [2e-4, key.x, key.y, key.z],
    };
    queue.write_buffer(&slot.globals, 0, bytemuck::bytes_of(&g));
}
