// Polygon edges and cages as lines, pulled slightly towards the eye so that they win the
// depth test against the faces they lie on.

// `Globals` and `globals`: globals.wgsl.

struct VsIn {
    @location(0) position: vec3<f32>,
    @location(1) color: vec3<f32>,
};

struct VsOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec3<f32>,
};

@vertex
fn vs_main(v: VsIn) -> VsOut {
    var o: VsOut;
    var c = globals.view_proj * vec4<f32>(v.position, 1.0);
    c.z = c.z - globals.params.x * c.w;
    o.clip = c;
    o.color = v.color;
    return o;
}

@fragment
fn fs_main(i: VsOut) -> @location(0) vec4<f32> {
    return vec4<f32>(i.color, 1.0);
}
