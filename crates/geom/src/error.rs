//! Errors and warnings about mesh input, each naming the element at fault.
//!
//! Indices are 0-based everywhere in Prism (as in OpenSubdiv's OBJ tag lines); the OBJ
//! reader adds the file's line number where it knows it.

use thiserror::Error;

/// Why a polygon mesh cannot be used.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MeshError {
    #[error("vertex {vertex} has a non-finite coordinate ({x}, {y}, {z})")]
    NonFinite { vertex: u32, x: f64, y: f64, z: f64 },
    #[error("face {face} refers to vertex {index}, but the mesh has only {count} vertices")]
    IndexOutOfRange { face: u32, index: u32, count: u32 },
    #[error("face {face} has no loop")]
    EmptyFace { face: u32 },
    #[error(
        "face {face}, loop {lp}: a loop needs at least 3 distinct vertices, this one has {distinct}"
    )]
    DegenerateLoop { face: u32, lp: u32, distinct: u32 },
    #[error("face {face} uses vertex {vertex} twice")]
    RepeatedVertex { face: u32, vertex: u32 },
    #[error("edge {a}-{b} is used by more than two faces (faces {faces:?})")]
    NonManifoldEdge { a: u32, b: u32, faces: Vec<u32> },
    #[error(
        "edge {a}-{b} is traversed {a}→{b} by both face {f1} and face {f2}: the faces are inconsistently oriented"
    )]
    InconsistentOrientation { a: u32, b: u32, f1: u32, f2: u32 },
    #[error("the mesh is open: edge {a}-{b} of face {face} has no face on its other side")]
    BoundaryEdge { a: u32, b: u32, face: u32 },
    #[error("vertex {vertex} is non-manifold: its faces form {fans} separate fans")]
    NonManifoldVertex { vertex: u32, fans: u32 },
    #[error("the mesh has no faces")]
    NoFaces,
    #[error("the mesh is too large: {what} exceeds the 32-bit index range")]
    TooLarge { what: &'static str },
}

/// A step whose result would not fit the memory budget, refused before it starts.
#[derive(Debug, Clone, PartialEq, Error)]
#[error(
    "the next level would need about {needed_mib} MiB, more than the budget of {budget_mib} MiB ({faces} faces)"
)]
pub struct OverBudget {
    pub needed_mib: u64,
    pub budget_mib: u64,
    pub faces: u64,
}

impl OverBudget {
    /// Refuses `needed` bytes over `budget`.
    pub fn check(needed: u64, budget: u64, faces: u64) -> Result<(), OverBudget> {
        if needed > budget {
            Err(OverBudget {
                needed_mib: needed >> 20,
                budget_mib: budget >> 20,
                faces,
            })
        } else {
            Ok(())
        }
    }
}

/// Something odd about the input that does not stop the work.
#[derive(Debug, Clone, PartialEq)]
pub enum MeshWarning {
    /// A vertex that no face uses; it is carried along but takes part in nothing.
    UnusedVertices { count: u32, first: u32 },
}

impl std::fmt::Display for MeshWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            MeshWarning::UnusedVertices { count, first } => write!(
                f,
                "{count} vertex(es) are used by no face (the first is vertex {first}); they are ignored"
            ),
        }
    }
}
