//! Prism's viewport: GPU buffers for polygon meshes (concave faces and holes triangulated),
//! an orbit camera, flat and smooth shading with normals split at creases, the wireframe of
//! the polygon edges, cages, face-kind colours; drawn with wgpu into the app's window or
//! offscreen into an image. No egui here.

pub mod camera;
pub mod offscreen;
pub mod parts;
pub mod renderer;
pub mod scene;

pub use camera::{Camera, View};
pub use offscreen::{Offscreen, RenderError};
pub use renderer::{CameraSlot, GpuScene, Renderer, UploadError};
pub use scene::{ColorBy, Scene, SceneOptions, SectionPlane, Shading};
