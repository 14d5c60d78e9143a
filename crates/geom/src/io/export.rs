//! Export of a computed level for other programs: binary STL (50 bytes a triangle after an
//! 84-byte header, written here; `stl_io` reads it back in the tests) and binary glTF
//! (`.glb`; the JSON part built with `gltf-json`, the typed serde model of the glTF 2.0
//! schema). Both are streamed into the save's temporary file, never assembled whole. Both formats hold triangles only: polygon faces, concave ones and faces with
//! holes included, are cut by [`crate::triangulate`]; hole faces of the primal schemes are
//! left out. Coordinates are written as `f32`, which both formats prescribe.
//!
//! The glTF file carries positions, normals and indices. The normals are smooth within
//! fans between edges sharper than 40° ([`crate::normals`], the viewport's smooth shading),
//! so a rounded solid looks round in other viewers while chamfers and creases stay crisp.

use super::{IoError, write_atomically_with};
use crate::edge_attrs::EdgeAttrs;
use crate::geometry::{face_normal_raw, unit_or_zero};
use crate::mesh::PolyMesh;
use crate::normals::smooth_corner_normals;
use gltf_json as json;
use json::validation::Checked::Valid;
use json::validation::USize64;
use std::collections::HashMap;
use std::io::Write;
use std::path::Path;

/// Formats a level can be exported to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExportFormat {
    Stl,
    Glb,
}

impl ExportFormat {
    /// By the file name's extension (`.stl`, `.glb`).
    pub fn of(path: &Path) -> Option<ExportFormat> {
        let ext = path.extension()?.to_string_lossy().to_lowercase();
        match ext.as_str() {
            "stl" => Some(ExportFormat::Stl),
            "glb" => Some(ExportFormat::Glb),
            _ => None,
        }
    }
}

/// Binary STL of `mesh` (faces for which `skip` is true are left out).
pub fn stl_bytes(mesh: &PolyMesh, skip: &dyn Fn(usize) -> bool) -> Vec<u8> {
    let mut out = Vec::new();
    write_stl_to(&mut out, mesh, skip).expect("writing into memory cannot fail");
    out
}

/// Binary STL of `mesh` streamed into `w`: the triangles are counted first (the header
/// holds their number), then written one by one.
pub fn write_stl_to(
    w: &mut dyn Write,
    mesh: &PolyMesh,
    skip: &dyn Fn(usize) -> bool,
) -> std::io::Result<()> {
    let faces = || (0..mesh.num_faces()).filter(|&f| !skip(f));
    let count: usize = faces()
        .map(|f| {
            let corners = mesh.face_corners(f).len();
            if mesh.face_loops(f).len() == 1 && corners <= 4 {
                corners - 2
            } else {
                crate::triangulate::face_vertex_triangles(mesh, f).len()
            }
        })
        .sum();
    let count = u32::try_from(count)
        .map_err(|_| std::io::Error::other("more triangles than binary STL can count"))?;
    // The 80-byte header says who wrote the file (not starting with "solid", which would
    // make readers take it for ASCII STL).
    let header = format!("Prism {} binary STL", env!("CARGO_PKG_VERSION"));
    let mut head = [b' '; 80];
    for (o, b) in head.iter_mut().zip(header.bytes()) {
        *o = b;
    }
    w.write_all(&head)?;
    w.write_all(&count.to_le_bytes())?;
    let mut rec = [0u8; 50];
    for f in faces() {
        let n = unit_or_zero(face_normal_raw(mesh, f));
        for t in crate::triangulate::face_vertex_triangles(mesh, f) {
            let mut k = 0;
            let mut put = |x: f64| {
                rec[k..k + 4].copy_from_slice(&(x as f32).to_le_bytes());
                k += 4;
            };
            put(n.x);
            put(n.y);
            put(n.z);
            for v in t {
                let q = mesh.positions[v as usize];
                put(q.x);
                put(q.y);
                put(q.z);
            }
            w.write_all(&rec)?;
        }
    }
    Ok(())
}

/// Edges whose faces meet at more than this keep separate normals in the glTF export (the
/// viewport's smooth shading uses the same default).
pub const GLB_CREASE_ANGLE_DEG: f64 = 40.0;

/// The normals an export carries, as the app shows the level: smooth (the viewport's smooth
/// shading: split at edges sharper than [`GLB_CREASE_ANGLE_DEG`]) or flat (one per face).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Normals {
    #[default]
    Smooth,
    Flat,
}

impl Normals {
    /// A unit normal per corner of `mesh`.
    pub fn corner_normals(self, mesh: &PolyMesh) -> Vec<glam::DVec3> {
        self.corner_normals_from(mesh, &crate::geometry::face_normals_raw(mesh))
    }

    /// [`Normals::corner_normals`] from the faces' raw normals already computed.
    pub fn corner_normals_from(self, mesh: &PolyMesh, raw: &[glam::DVec3]) -> Vec<glam::DVec3> {
        let angle = match self {
            Normals::Smooth => GLB_CREASE_ANGLE_DEG,
            Normals::Flat => 0.0,
        };
        smooth_corner_normals(mesh, raw, &EdgeAttrs::new(), angle)
    }
}

/// Binary glTF 2.0 (`.glb`) of `mesh`: one mesh, one node, one scene; positions, normals
/// ([`Normals`]: a vertex on an edge where they split is written once per side), triangles.
pub fn glb_bytes(mesh: &PolyMesh, skip: &dyn Fn(usize) -> bool, normals: Normals) -> Vec<u8> {
    let mut out = Vec::new();
    write_glb_to(&mut out, mesh, skip, normals).expect("writing into memory cannot fail");
    out
}

/// [`glb_bytes`] streamed into `w`: the vertices and triangles are gathered (the JSON
/// header holds their counts and bounds), then written straight from those arrays, without
/// a copy of the binary chunk.
pub fn write_glb_to(
    w: &mut dyn Write,
    mesh: &PolyMesh,
    skip: &dyn Fn(usize) -> bool,
    normals: Normals,
) -> std::io::Result<()> {
    let raw = crate::geometry::face_normals_raw(mesh);
    let corner_normals = normals.corner_normals_from(mesh, &raw);
    // One glTF vertex per distinct (mesh vertex, normal) pair.
    let mut index: HashMap<(u32, [u32; 3]), u32> = HashMap::new();
    let (mut positions, mut normals): (Vec<f32>, Vec<f32>) = (Vec::new(), Vec::new());
    let mut vertex_of = |c: u32| -> u32 {
        let v = mesh.corner_verts[c as usize];
        let n = corner_normals[c as usize].as_vec3();
        *index
            .entry((v, n.to_array().map(f32::to_bits)))
            .or_insert_with(|| {
                let p = mesh.positions[v as usize];
                positions.extend([p.x as f32, p.y as f32, p.z as f32]);
                normals.extend(n.to_array());
                (positions.len() / 3 - 1) as u32
            })
    };
    let mut tris: Vec<[u32; 3]> = Vec::new();
    for f in (0..mesh.num_faces()).filter(|&f| !skip(f)) {
        for t in crate::triangulate::face_triangles(mesh, f, unit_or_zero(raw[f])) {
            tris.push(t.map(&mut vertex_of));
        }
    }
    let vertices = positions.len() / 3;
    let mut min = [f32::MAX; 3];
    let mut max = [f32::MIN; 3];
    for p in positions.chunks_exact(3) {
        for i in 0..3 {
            min[i] = min[i].min(p[i]);
            max[i] = max[i].max(p[i]);
        }
    }
    if positions.is_empty() {
        (min, max) = ([0.0; 3], [0.0; 3]);
    }
    let pos_len = 4 * positions.len();
    let nrm_len = 4 * normals.len();
    let idx_len = 12 * tris.len();
    // Every part is a multiple of 4 bytes: the chunk needs no padding.
    let bin_len = pos_len + nrm_len + idx_len;

    let mut root = json::Root::default();
    root.asset.generator = Some(format!("Prism {}", env!("CARGO_PKG_VERSION")));
    let buffer = root.push(json::Buffer {
        byte_length: USize64::from(bin_len),
        name: None,
        uri: None,
        extensions: None,
        extras: Default::default(),
    });
    let view = |root: &mut json::Root, offset: usize, len: usize, target| {
        root.push(json::buffer::View {
            buffer,
            byte_length: USize64::from(len),
            byte_offset: Some(USize64::from(offset)),
            byte_stride: None,
            name: None,
            target: Some(Valid(target)),
            extensions: None,
            extras: Default::default(),
        })
    };
    let pos_view = view(&mut root, 0, pos_len, json::buffer::Target::ArrayBuffer);
    let nrm_view = view(
        &mut root,
        pos_len,
        nrm_len,
        json::buffer::Target::ArrayBuffer,
    );
    let idx_view = view(
        &mut root,
        pos_len + nrm_len,
        idx_len,
        json::buffer::Target::ElementArrayBuffer,
    );
    let accessor =
        |view, count: usize, ty, component, bounds: Option<([f32; 3], [f32; 3])>| json::Accessor {
            buffer_view: Some(view),
            byte_offset: Some(USize64(0)),
            count: USize64::from(count),
            component_type: Valid(json::accessor::GenericComponentType(component)),
            type_: Valid(ty),
            min: bounds.map(|b| json::Value::from(Vec::from(b.0))),
            max: bounds.map(|b| json::Value::from(Vec::from(b.1))),
            name: None,
            normalized: false,
            sparse: None,
            extensions: None,
            extras: Default::default(),
        };
    let pos = root.push(accessor(
        pos_view,
        vertices,
        json::accessor::Type::Vec3,
        json::accessor::ComponentType::F32,
        Some((min, max)),
    ));
    let nrm = root.push(accessor(
        nrm_view,
        vertices,
        json::accessor::Type::Vec3,
        json::accessor::ComponentType::F32,
        None,
    ));
    let idx = root.push(accessor(
        idx_view,
        3 * tris.len(),
        json::accessor::Type::Scalar,
        json::accessor::ComponentType::U32,
        None,
    ));
    let primitive = json::mesh::Primitive {
        attributes: [
            (Valid(json::mesh::Semantic::Positions), pos),
            (Valid(json::mesh::Semantic::Normals), nrm),
        ]
        .into(),
        indices: Some(idx),
        material: None,
        mode: Valid(json::mesh::Mode::Triangles),
        targets: None,
        extensions: None,
        extras: Default::default(),
    };
    let m = root.push(json::Mesh {
        name: Some("prism".into()),
        primitives: vec![primitive],
        weights: None,
        extensions: None,
        extras: Default::default(),
    });
    let node = root.push(json::Node {
        mesh: Some(m),
        ..Default::default()
    });
    let scene = root.push(json::Scene {
        name: None,
        nodes: vec![node],
        extensions: None,
        extras: Default::default(),
    });
    root.scene = Some(scene);

    let mut text = json::serialize::to_vec(&root).expect("the glTF model serialises");
    while !text.len().is_multiple_of(4) {
        text.push(b' ');
    }
    let total = 12 + 8 + text.len() + 8 + bin_len;
    // The GLB header stores the length in 32 bits.
    let total = u32::try_from(total)
        .map_err(|_| std::io::Error::other("the mesh is larger than a 4 GiB glTF file allows"))?;
    w.write_all(b"glTF")?;
    w.write_all(&2u32.to_le_bytes())?;
    w.write_all(&total.to_le_bytes())?;
    w.write_all(&(text.len() as u32).to_le_bytes())?;
    w.write_all(b"JSON")?;
    w.write_all(&text)?;
    w.write_all(&(bin_len as u32).to_le_bytes())?;
    w.write_all(b"BIN\0")?;
    for x in positions.iter().chain(&normals) {
        w.write_all(&x.to_le_bytes())?;
    }
    for i in tris.iter().flatten() {
        w.write_all(&i.to_le_bytes())?;
    }
    Ok(())
}

/// Writes `mesh` as STL or glTF by the file name, through a temporary file (STL's facet
/// normals are the triangles' own whatever `normals` says).
pub fn export(
    path: &Path,
    mesh: &PolyMesh,
    skip: &dyn Fn(usize) -> bool,
    normals: Normals,
) -> Result<(), IoError> {
    let format =
        ExportFormat::of(path).ok_or_else(|| IoError::UnknownExtension { path: path.into() })?;
    super::check_finite_points(path, mesh)?;
    write_atomically_with(path, |w| match format {
        ExportFormat::Stl => write_stl_to(w, mesh, skip),
        ExportFormat::Glb => write_glb_to(w, mesh, skip, normals),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;

    #[test]
    fn stl_reads_back_with_every_triangle() {
        let m = primitives::cube3();
        let bytes = stl_bytes(&m, &|_| false);
        assert!(bytes.starts_with(b"Prism ") && !bytes.starts_with(b"solid"));
        let back = stl_io::read_stl(&mut std::io::Cursor::new(&bytes)).unwrap();
        assert_eq!(back.faces.len(), 12);
        assert_eq!(back.vertices.len(), 8);
        // Normals point out of the cube.
        for f in &back.faces {
            let c: [f32; 3] = std::array::from_fn(|i| {
                f.vertices
                    .iter()
                    .map(|&v| back.vertices[v].0[i])
                    .sum::<f32>()
                    / 3.0
            });
            let (lo, hi) = m.bbox();
            let mid = 0.5 * (lo + hi);
            let d = [
                c[0] - mid.x as f32,
                c[1] - mid.y as f32,
                c[2] - mid.z as f32,
            ];
            assert!(f.normal.0.iter().zip(d).map(|(a, b)| a * b).sum::<f32>() > 0.0);
        }
        assert_eq!(stl_bytes(&m, &|f| f < 3).len(), 84 + 50 * 6);
    }

    #[test]
    fn glb_is_valid_gltf_with_the_mesh() {
        let m = primitives::cube3();
        let bytes = glb_bytes(&m, &|_| false, Normals::Smooth);
        assert_eq!(&bytes[0..4], b"glTF");
        let u32_at = |i: usize| u32::from_le_bytes(bytes[i..i + 4].try_into().unwrap());
        assert_eq!(u32_at(8) as usize, bytes.len());
        let json_len = u32_at(12) as usize;
        assert_eq!(&bytes[16..20], b"JSON");
        let root: json::Root = json::deserialize::from_slice(&bytes[20..20 + json_len]).unwrap();
        let mut errors = Vec::new();
        use json::validation::Validate;
        root.validate(&root, json::Path::new, &mut |p, e| errors.push((p(), e)));
        assert!(errors.is_empty(), "{errors:?}");
        let bin_at = 20 + json_len;
        assert_eq!(&bytes[bin_at + 4..bin_at + 8], b"BIN\0");
        let bin = &bytes[bin_at + 8..];
        // A cube's edges are all sharp: each corner vertex is written once per face (24),
        // with its face's normal.
        assert_eq!(root.accessors[0].count.0, 24);
        assert_eq!(root.accessors[1].count.0, 24);
        assert_eq!(root.accessors[2].count.0, 36);
        let f32_at = |i: usize| f32::from_le_bytes(bin[i..i + 4].try_into().unwrap());
        let (pos_at, nrm_at, idx_at) = (0, 24 * 12, 48 * 12);
        let centre = 0.5 * (m.bbox().0 + m.bbox().1);
        for k in 0..36 {
            let i = u32::from_le_bytes(bin[idx_at + 4 * k..idx_at + 4 * k + 4].try_into().unwrap())
                as usize;
            assert!(i < 24);
            let p = glam::DVec3::from_array(std::array::from_fn(|a| {
                f32_at(pos_at + 12 * i + 4 * a) as f64
            }));
            let n = glam::DVec3::from_array(std::array::from_fn(|a| {
                f32_at(nrm_at + 12 * i + 4 * a) as f64
            }));
            assert!((n.length() - 1.0).abs() < 1e-6 && n.dot(p - centre) > 0.0);
            assert!(m.positions.iter().any(|q| q.distance(p) < 1e-6));
        }
        // A smooth solid shares its vertices: the torus's 1152 are written once each.
        let t = primitives::torus(48, 24, 3.0, 1.0);
        let bytes = glb_bytes(&t, &|_| false, Normals::Smooth);
        let json_len = u32::from_le_bytes(bytes[12..16].try_into().unwrap()) as usize;
        let root: json::Root = json::deserialize::from_slice(&bytes[20..20 + json_len]).unwrap();
        assert_eq!(root.accessors[0].count.0, 48 * 24);
    }

    #[test]
    fn unknown_extension_is_an_error() {
        let e = export(
            Path::new("/tmp/x.ply"),
            &primitives::cube3(),
            &|_| false,
            Normals::Smooth,
        )
        .unwrap_err();
        assert!(e.to_string().contains("x.ply"));
    }
}
