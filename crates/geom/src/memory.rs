//! What a refinement will hold in memory, estimated before the work: the memory guard.
//!
//! A pipeline keeps levels while it steps; a step holds, besides them, the topology of the
//! level it refines (built, or carried from the split before), the new level, that level's
//! provenance and, when the next step wants it, the new level's topology. Every size follows
//! from four counts — vertices V, corners C, loops L and faces F — and the edges E (C / 2 on
//! a closed mesh), and every scheme's counts after a step follow from those before it:
//!
//! | scheme family | V′ | C′ | L′ | F′ |
//! | --- | --- | --- | --- | --- |
//! | Catmull–Clark and its variants | V + E + F | 4C | C | C |
//! | Loop | V + E | 4C | 4F | 4F |
//! | biquadratic (Doo–Sabin, the cylindrical rules, the chamfers) | C | 2C + 4E | L + E + V | F + E + V |
//!
//! So a pipeline's peak is known from its input before any level is built
//! ([`crate::Pipeline::estimate_peak`]), and checked again before each step against the
//! levels actually kept. Bytes per element are the arrays' own (`PolyMesh`, `Topology`,
//! `Provenance`), with the topology build's temporary vertex rings; the whole is multiplied by
//! [`SAFETY`] for the allocator's slack and the scheme's scratch arrays (point rules, normals)
//! and a fixed [`BASELINE`] is added for the process itself. docs/reliability.md gives the
//! estimate next to the measured peak on three sizes.

use crate::io::ExportFormat;
use crate::mesh::PolyMesh;
use crate::primal::PrimalScheme;
use crate::scheme::Scheme;

/// Bytes the process holds besides the meshes (code, threads, small tables).
pub const BASELINE: u64 = 48 << 20;

/// Factor on the counted arrays: allocator slack, vectors grown by doubling, the scheme's
/// scratch arrays.
pub const SAFETY: f64 = 1.5;

/// The four counts that size a mesh, and its edges.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Counts {
    pub vertices: u64,
    pub corners: u64,
    pub loops: u64,
    pub faces: u64,
    pub edges: u64,
}

impl Counts {
    /// The counts of `mesh`; its edges taken as C / 2 (exact for a closed mesh) unless given.
    pub fn of(mesh: &PolyMesh, edges: Option<usize>) -> Counts {
        let corners = mesh.num_corners() as u64;
        Counts {
            vertices: mesh.num_vertices() as u64,
            corners,
            loops: mesh.num_loops() as u64,
            faces: mesh.num_faces() as u64,
            edges: edges.map_or(corners.div_ceil(2), |e| e as u64),
        }
    }

    /// The counts after one step of `scheme` (the table above; closed-mesh formulas, which
    /// bound an open mesh's from above).
    pub fn after(&self, scheme: &Scheme) -> Counts {
        let Counts {
            vertices: v,
            corners: c,
            loops: l,
            faces: f,
            edges: e,
        } = *self;
        match scheme {
            Scheme::Biquadratic(_) => Counts {
                vertices: c,
                corners: 2 * c + 4 * e,
                loops: l + e + v,
                faces: f + e + v,
                edges: 4 * e,
            },
            Scheme::Primal(PrimalScheme::Loop) => Counts {
                vertices: v + e,
                corners: 4 * c,
                loops: 4 * f,
                faces: 4 * f,
                edges: 2 * e + c,
            },
            Scheme::Primal(_) => Counts {
                vertices: v + e + f,
                corners: 4 * c,
                loops: c,
                faces: c,
                edges: 2 * e + c,
            },
        }
    }

    /// The triangles a mesh of these counts is cut into (C − 2F for faces without holes).
    pub fn triangles(&self) -> u64 {
        self.corners.saturating_sub(2 * self.faces)
    }

    /// Bytes of a mesh of these counts: positions, corner vertices, loop and face starts.
    pub fn mesh_bytes(&self) -> u64 {
        24 * self.vertices + 4 * self.corners + 4 * (self.loops + 1) + 4 * (self.faces + 1)
    }

    /// Bytes of the topology of a mesh of these counts (five arrays per corner, one per edge
    /// and vertex) at its build's peak (the vertex rings: a destination and a corner per
    /// corner, an offset per vertex).
    pub fn topology_bytes(&self) -> u64 {
        (20 + 8) * self.corners + 4 * self.edges + (4 + 4) * self.vertices
    }

    /// Bytes of the provenance of a level of these counts: a kind and a parent per face, a
    /// parent edge for every edge that lies on one (at most all of them).
    pub fn provenance_bytes(&self) -> u64 {
        5 * self.faces + 16 * self.edges
    }

    /// Bytes of a level of these counts: its mesh, and its provenance when recorded.
    pub fn level_bytes(&self, provenance: bool) -> u64 {
        self.mesh_bytes()
            + if provenance {
                self.provenance_bytes()
            } else {
                0
            }
    }
}

/// `bytes` with the [`SAFETY`] factor.
fn padded(bytes: u64) -> u64 {
    (bytes as f64 * SAFETY) as u64
}

/// Bytes one step of `scheme` holds on top of the levels kept while it runs: the topology of
/// its input (`input_topology`: false when the split before carried it), the new level with
/// its provenance (when recorded), and its topology when the next step takes it (`carry`),
/// times [`SAFETY`].
pub fn step_bytes(
    input: &Counts,
    scheme: &Scheme,
    input_topology: bool,
    carry: bool,
    provenance: bool,
) -> u64 {
    let out = input.after(scheme);
    let mut b = out.level_bytes(provenance);
    if input_topology {
        b += input.topology_bytes();
    }
    if carry {
        b += out.topology_bytes();
    }
    if let Scheme::Biquadratic(rule) = scheme {
        // Corner points (one per input corner) and face normals, built before the split.
        b += 24 * input.corners + 24 * input.faces;
        if rule.is_cylindrical_family() {
            // The rounding rules' own per-corner and per-face arrays (offset lines, the
            // overlap clamp, the combination's two point sets and the fold guard):
            // measured, docs/reliability.md.
            b += 96 * input.corners + 48 * input.faces;
        }
    }
    padded(b)
}

/// Bytes a search of a level of these counts for faces that pass through each other
/// ([`crate::analysis::crossings`]) holds besides the level: a box a face (48), the
/// triangles' corners and normals (48 a triangle, built per chunk and then gathered, so
/// twice that at once), each face's first triangle (4), and the hierarchy over the boxes —
/// an index and a centre a face (4 + 24) and a node per two leaves of four (about 40 a
/// face). Measured beside it, docs/reliability.md.
pub fn crossing_bytes(counts: &Counts) -> u64 {
    padded(120 * counts.faces + 96 * counts.triangles())
}

/// Bytes an export of a level of these counts holds while it is written: glTF gathers its
/// vertices (a position and a normal, one a corner at most, with the map that shares them),
/// its indices and the corner normals before streaming them; OBJ, `.prism.json` and STL are
/// streamed as they are computed: nothing that grows with the mesh.
pub fn export_bytes(counts: &Counts, format: Option<ExportFormat>) -> u64 {
    let b = match format {
        None | Some(ExportFormat::Stl) => 0,
        Some(ExportFormat::Glb) => {
            88 * counts.corners + 12 * counts.triangles() + 24 * counts.faces
        }
    };
    padded(b)
}

/// Bytes the fillet report holds on top of the levels kept: a box and about eight grid
/// entries a face of the measured level (`counts`), the grid's cells, and the topology of
/// the level the rounding started from (a quarter of the measured one's at most).
pub fn fillet_report_bytes(counts: &Counts) -> u64 {
    let b = 80 * counts.faces + (16 << 20) + counts.topology_bytes() / 4;
    padded(b)
}

/// The counts of a tessellation of `patches` patches at `k`×`k` quads each (before the
/// welding of shared borders, which only lowers them).
pub fn tessellation_counts(patches: u64, k: u64) -> Counts {
    let quads = patches * k * k;
    Counts {
        vertices: patches * (k + 1) * (k + 1),
        corners: 4 * quads,
        loops: quads,
        faces: quads,
        edges: 2 * quads + 2 * patches * k,
    }
}

/// Bytes a tessellation of these counts holds while it is built: its mesh, a sampled point
/// and normal a vertex, the welding's map (about 32 bytes a vertex).
pub fn tessellation_bytes(counts: &Counts) -> u64 {
    let b = counts.mesh_bytes() + 80 * counts.vertices;
    padded(b) + BASELINE
}

/// Bytes an envelope's mesh of these counts holds while it is built and checked: its
/// tessellation, the quality report (vertex normals by region in hash maps, the ray-parity
/// bins and the face grid of the enclosure margins) and the crossing check, about 500 bytes a
/// triangle together (measured against the peak in docs/reliability.md).
pub fn surface_bytes(counts: &Counts) -> u64 {
    tessellation_bytes(counts) + 500 * counts.faces
}

/// Bytes an envelope's construction holds for primitives of `faces` faces in all (before its
/// mesh): the network, the charts with their sides and the lifts, about 25 KiB a face at most
/// (measured: a 20,000-face primitive peaks at 518 MB with its mesh at resolution 1, 80,000
/// faces at 1,521 MB; 3,000 cubes, most swallowed, at 196 MB; docs/reliability.md). Without
/// the process's [`BASELINE`], which the mesh's estimate holds.
pub fn envelope_construction_bytes(faces: u64) -> u64 {
    25 * 1024 * faces
}

/// The budget when none is given: half of the memory available now (Linux's
/// `MemAvailable`), else 4 GiB.
pub fn default_budget() -> u64 {
    std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|t| {
            t.lines()
                .find_map(|l| l.strip_prefix("MemAvailable:"))
                .and_then(|v| v.trim().trim_end_matches("kB").trim().parse::<u64>().ok())
        })
        .map_or(4 << 30, |kib| kib * 1024 / 2)
}

/// Parses a size: a number with an optional unit — `K`, `M`, `G`, `T` or `KiB`, `MiB`,
/// `GiB`, `TiB` are powers of 1024; `kB`, `MB`, `GB`, `TB` powers of 1000; `B` or none, bytes.
pub fn parse_size(text: &str) -> Result<u64, String> {
    let t = text.trim();
    let split = t
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(t.len());
    let (num, unit) = t.split_at(split);
    let value: f64 = num
        .parse()
        .map_err(|_| format!("'{text}' is not a size (e.g. 512M, 4GiB, 2GB)"))?;
    let factor: f64 = match unit.trim() {
        "" | "B" => 1.0,
        "K" | "KiB" | "k" => 1024.0,
        "M" | "MiB" => 1024f64.powi(2),
        "G" | "GiB" => 1024f64.powi(3),
        "T" | "TiB" => 1024f64.powi(4),
        "kB" | "KB" => 1e3,
        "MB" => 1e6,
        "GB" => 1e9,
        "TB" => 1e12,
        u => {
            return Err(format!(
                "'{text}': unknown unit '{u}' (K, M, G, T or KiB, MiB, GiB, TiB are powers of 1024; kB, MB, GB, TB of 1000)"
            ));
        }
    };
    let bytes = value * factor;
    if !(1.0..1.8e19).contains(&bytes) {
        return Err(format!("'{text}' is out of range (at least 1 byte)"));
    }
    Ok(bytes as u64)
}

/// `bytes` in MiB, for messages.
pub fn mib(bytes: u64) -> u64 {
    bytes.div_ceil(1 << 20)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitives;

    #[test]
    fn sizes_parse_in_both_unit_systems() {
        assert_eq!(parse_size("512M").unwrap(), 512 << 20);
        assert_eq!(parse_size("4GiB").unwrap(), 4 << 30);
        assert_eq!(parse_size("2GB").unwrap(), 2_000_000_000);
        assert_eq!(parse_size("1.5G").unwrap(), 3 << 29);
        assert_eq!(parse_size("100kB").unwrap(), 100_000);
        assert_eq!(parse_size("4096").unwrap(), 4096);
        for bad in ["", "G", "-1G", "4 parsecs", "0", "1e30"] {
            assert!(parse_size(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn predicted_counts_match_the_refined_meshes() {
        use crate::Pipeline;
        let cube = primitives::cube3();
        for pipe in [
            "catmull-clark,catmull-clark",
            "doo-sabin,doo-sabin",
            "combination:r=0.1,catmull-clark",
        ] {
            let steps = crate::scheme::parse_pipeline(pipe).unwrap();
            let mut p = Pipeline::new(cube.clone(), Default::default(), steps.clone());
            p.compute().unwrap();
            let mut c = Counts::of(&cube, None);
            for (k, s) in steps.iter().enumerate() {
                c = c.after(s);
                let m = &p.levels()[k + 1].mesh;
                assert_eq!(c, Counts::of(m, None), "{pipe}, level {}", k + 1);
            }
        }
        let tet = primitives::tetrahedron();
        let steps = crate::scheme::parse_pipeline("loop,loop").unwrap();
        let mut p = Pipeline::new(tet.clone(), Default::default(), steps.clone());
        p.compute().unwrap();
        let c = Counts::of(&tet, None).after(&steps[0]).after(&steps[1]);
        assert_eq!(c, Counts::of(&p.levels()[2].mesh, None));
    }
}
