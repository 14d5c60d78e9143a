//! Export of a computed level for other programs: binary STL (`stl_io`) and binary glTF
//! (`.glb`; the JSON part built with `gltf-json`, the typed serde model of the glTF 2.0
//! schema). Both formats hold triangles only: polygon faces, concave ones and faces with
//! holes included, are cut by [`crate::triangulate`]; hole faces of the primal schemes are
//! left out. Coordinates are written as `f32`, which both formats prescribe.
//!
//! The glTF file carries positions, normals and indices. The normals are smooth within
//! fans between edges sharper than 40° ([`crate::normals`], the viewport's smooth shading),
//! so a rounded solid looks round in other viewers while chamfers and creases stay crisp.

use super::{IoError, write_atomically};
use crate::edge_attrs::EdgeAttrs;
use crate::geometry::{face_normal_raw, unit_or_zero};
use crate::mesh::PolyMesh;
use crate::normals::smooth_corner_normals;
use gltf_json as json;
use json::validation::Checked::Valid;
use json::validation::USize64;
use std::collections::HashMap;
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
    let p = |v: u32| {
        let q = mesh.positions[v as usize];
        stl_io::Vertex::new([q.x as f32, q.y as f32, q.z as f32])
    };
    let mut tris = Vec::new();
    for f in (0..mesh.num_faces()).filter(|&f| !skip(f)) {
        let n = unit_or_zero(face_normal_raw(mesh, f));
        for t in crate::triangulate::face_vertex_triangles(mesh, f) {
            tris.push(stl_io::Triangle {
                normal: stl_io::Normal::new([n.x as f32, n.y as f32, n.z as f32]),
                vertices: t.map(p),
            });
        }
    }
    let mut out = Vec::with_capacity(84 + 50 * tris.len());
    stl_io::write_stl(&mut out, tris.iter()).expect("writing into memory cannot fail");
    // The 80-byte header says who wrote the file (not starting with "solid", which would
    // make readers take it for ASCII STL).
    let header = format!("Prism {} binary STL", env!("CARGO_PKG_VERSION"));
    for (o, b) in out[..80]
        .iter_mut()
        .zip(header.bytes().chain(std::iter::repeat(b' ')))
    {
        *o = b;
    }
    out
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
    let mut bin: Vec<u8> = positions.iter().flat_map(|x| x.to_le_bytes()).collect();
    let pos_len = bin.len();
    bin.extend(normals.iter().flat_map(|x| x.to_le_bytes()));
    let nrm_len = bin.len() - pos_len;
    bin.extend(tris.iter().flatten().flat_map(|i| i.to_le_bytes()));
    let idx_len = bin.len() - pos_len - nrm_len;

    let mut root = json::Root::default();
    root.asset.generator = Some(format!("Prism {}", env!("CARGO_PKG_VERSION")));
    let buffer = root.push(json::Buffer {
        byte_length: USize64::from(bin.len()),
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
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }
    let total = 12 + 8 + text.len() + 8 + bin.len();
    let mut out = Vec::with_capacity(total);
    out.extend(b"glTF");
    out.extend(2u32.to_le_bytes());
    out.extend((total as u32).to_le_bytes());
    out.extend((text.len() as u32).to_le_bytes());
    out.extend(b"JSON");
    out.extend(text);
    out.extend((bin.len() as u32).to_le_bytes());
    out.extend(b"BIN\0");
    out.extend(bin);
    out
}

/// Writes `mesh` as STL or glTF by the file name, through a temporary file (STL's facet
/// normals are the triangles' own whatever `normals` says).
pub fn export(
    path: &Path,
    mesh: &PolyMesh,
    skip: &dyn Fn(usize) -> bool,
    normals: Normals,
) -> Result<(), IoError> {
    let bytes = match ExportFormat::of(path) {
        Some(ExportFormat::Stl) => stl_bytes(mesh, skip),
        Some(ExportFormat::Glb) => glb_bytes(mesh, skip, normals),
        None => return Err(IoError::UnknownExtension { path: path.into() }),
    };
    // The GLB header stores the length in 32 bits.
    if bytes.len() > u32::MAX as usize {
        return Err(IoError::Write {
            path: path.into(),
            source: std::io::Error::other("the mesh is larger than a 4 GiB file allows"),
        });
    }
    write_atomically(path, &bytes)
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
