// Faces of a polygon mesh: per-corner normal and colour, a key light above-left of the eye
// plus a headlight, lit from both sides (a face seen from behind is darker).

// `Globals` and `globals`: globals.wgsl.

struct VsIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) color: vec3<f32>,
};

struct VsOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) normal: vec3<f32>,
    @location(1) color: vec3<f32>,
};

@vertex
fn vs_main(v: VsIn) -> VsOut {
    var o: VsOut;
    o.clip = globals.view_proj * vec4<f32>(v.position, 1.0);
    o.normal = v.normal;
    o.color = v.color;
    return o;
}

@fragment
fn fs_main(i: VsOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    var n = normalize(i.normal);
    if (length(i.normal) < 1e-6) {
        n = globals.eye_dir.xyz;
    }
    // Two-sided: light the side that faces the eye.
    if (dot(n, globals.eye_dir.xyz) < 0.0) {
        n = -n;
    }
    let head = max(dot(n, globals.eye_dir.xyz), 0.0);
    let key = max(dot(n, globals.params.yzw), 0.0);
    var shade = 0.12 + 0.30 * head + 0.62 * key;
    if (!front) {
        shade = shade * 0.55;
    }
    return vec4<f32>(i.color * shade, 1.0);
}
