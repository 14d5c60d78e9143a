// The uniforms every shader reads (prepended to each by `renderer.rs`).

struct Globals {
    view_proj: mat4x4<f32>,
    // xyz: direction from the model towards the eye; w unused.
    eye_dir: vec4<f32>,
    // x: depth pull of lines towards the eye (clip units); yzw: key light direction.
    params: vec4<f32>,
};

@group(0) @binding(0) var<uniform> globals: Globals;
