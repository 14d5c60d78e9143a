//! Offscreen rendering to an RGBA image with the same renderer as the window: a
//! multisampled colour target resolved into a texture, copied into a buffer, read back.
//! Works on any adapter wgpu finds, Mesa's software Vulkan (lavapipe) included.

use crate::camera::Camera;
use crate::renderer::{
    BACKGROUND, DEPTH_FORMAT, GpuScene, PICTURE_SAMPLES, Renderer, interactive_samples,
};
use crate::scene::Scene;
use thiserror::Error;

#[derive(Debug, Error)]
pub enum RenderError {
    #[error(
        "no graphics adapter found ({0}); on a machine without a GPU install Mesa's software Vulkan (apt-get install mesa-vulkan-drivers)"
    )]
    NoAdapter(String),
    #[error("the graphics device could not be opened: {0}")]
    Device(String),
    #[error("image size {w}×{h} is out of range (1 to {max} pixels per side)")]
    Size { w: u32, h: u32, max: u32 },
    #[error(transparent)]
    Upload(#[from] crate::renderer::UploadError),
    #[error("reading the picture back failed: {0}")]
    Readback(String),
}

/// A device for offscreen work.
pub struct Offscreen {
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    /// The adapter's name and type, for messages and benchmarks.
    pub adapter_info: wgpu::AdapterInfo,
    renderer: Renderer,
}

const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

impl Offscreen {
    /// Opens the best adapter (`WGPU_BACKEND` and friends steer the choice), for pictures
    /// (4× multisampling).
    pub fn new() -> Result<Offscreen, RenderError> {
        Self::with_samples(|_| PICTURE_SAMPLES)
    }

    /// As [`Offscreen::new`] with the sample count of interactive frames on this adapter
    /// (what a frame-time benchmark measures).
    pub fn interactive() -> Result<Offscreen, RenderError> {
        Self::with_samples(interactive_samples)
    }

    fn with_samples(samples: impl Fn(&wgpu::AdapterInfo) -> u32) -> Result<Offscreen, RenderError> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            force_fallback_adapter: false,
            compatible_surface: None,
            ..Default::default()
        }))
        .map_err(|e| RenderError::NoAdapter(e.to_string()))?;
        let adapter_info = adapter.get_info();
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("prism offscreen"),
            required_limits: adapter.limits(),
            ..Default::default()
        }))
        .map_err(|e| RenderError::Device(e.to_string()))?;
        let renderer = Renderer::new(&device, FORMAT, samples(&adapter_info));
        Ok(Offscreen {
            device,
            queue,
            adapter_info,
            renderer,
        })
    }

    /// Renders `scene` seen by `camera` into a `width × height` RGBA image.
    pub fn render(
        &self,
        scene: &Scene,
        camera: &Camera,
        width: u32,
        height: u32,
    ) -> Result<image::RgbaImage, RenderError> {
        let gpu = self.upload(scene)?;
        self.render_uploaded(&gpu, camera, width, height)
    }

    /// Uploads a scene once, to render it many times (a frame-time benchmark, a turntable).
    pub fn upload(&self, scene: &Scene) -> Result<GpuScene, RenderError> {
        Ok(self.renderer.upload(&self.device, scene)?)
    }

    /// [`Offscreen::upload`] in buffers of at most `max_bytes` (a test of the parts).
    pub fn upload_within(&self, scene: &Scene, max_bytes: u64) -> Result<GpuScene, RenderError> {
        Ok(self
            .renderer
            .upload_within(&self.device, scene, max_bytes)?)
    }

    /// Writes `scene` over an uploaded one where it fits ([`Renderer::refill`]).
    pub fn refill(&self, gpu: &mut GpuScene, scene: &Scene) -> Result<(), RenderError> {
        Ok(self
            .renderer
            .refill(&self.device, &self.queue, gpu, scene)?)
    }

    /// Renders an uploaded scene: one frame, read back as an image.
    pub fn render_uploaded(
        &self,
        gpu: &GpuScene,
        camera: &Camera,
        width: u32,
        height: u32,
    ) -> Result<image::RgbaImage, RenderError> {
        let max = self.device.limits().max_texture_dimension_2d;
        if width == 0 || height == 0 || width > max || height > max {
            return Err(RenderError::Size {
                w: width,
                h: height,
                max,
            });
        }
        self.renderer
            .set_camera(&self.queue, camera, width as f32 / height as f32);
        let size = wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        };
        let texture = |label, samples, format, usage| {
            self.device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size,
                mip_level_count: 1,
                sample_count: samples,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let samples = self.renderer.samples;
        let msaa = (samples > 1).then(|| {
            texture(
                "prism msaa",
                samples,
                FORMAT,
                wgpu::TextureUsages::RENDER_ATTACHMENT,
            )
        });
        let resolved = texture(
            "prism resolved",
            1,
            FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        );
        let depth = texture(
            "prism depth",
            samples,
            DEPTH_FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        );
        let (msaa_v, resolved_v, depth_v) = (
            msaa.as_ref().map(|t| t.create_view(&Default::default())),
            resolved.create_view(&Default::default()),
            depth.create_view(&Default::default()),
        );
        // With multisampling draw into the samples and resolve; without, draw directly.
        let (target, resolve) = match &msaa_v {
            Some(m) => (m, Some(&resolved_v)),
            None => (&resolved_v, None),
        };
        let padded = (4 * width).div_ceil(256) * 256;
        let readback = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("prism readback"),
            size: padded as u64 * height as u64,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let mut enc = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("prism"),
            });
        {
            let mut pass = enc.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("prism offscreen"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: target,
                    depth_slice: None,
                    resolve_target: resolve,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(BACKGROUND),
                        store: if resolve.is_some() {
                            wgpu::StoreOp::Discard
                        } else {
                            wgpu::StoreOp::Store
                        },
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &depth_v,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(1.0),
                        store: wgpu::StoreOp::Discard,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            self.renderer.draw(&mut pass, gpu);
        }
        enc.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &resolved,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &readback,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(padded),
                    rows_per_image: Some(height),
                },
            },
            size,
        );
        self.queue.submit([enc.finish()]);
        let slice = readback.slice(..);
        let (tx, rx) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| RenderError::Readback(e.to_string()))?;
        rx.recv()
            .map_err(|e| RenderError::Readback(e.to_string()))?
            .map_err(|e| RenderError::Readback(e.to_string()))?;
        let data = slice
            .get_mapped_range()
            .map_err(|e| RenderError::Readback(e.to_string()))?;
        let mut img = image::RgbaImage::new(width, height);
        for (y, row) in data
            .chunks(padded as usize)
            .take(height as usize)
            .enumerate()
        {
            let dst = &mut img.as_mut()[(y * 4 * width as usize)..((y + 1) * 4 * width as usize)];
            dst.copy_from_slice(&row[..4 * width as usize]);
        }
        Ok(img)
    }
}
