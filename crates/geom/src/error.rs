//! Errors and warnings about mesh input, each naming the element at fault.
//!
//! Indices are 0-based everywhere in Prism (as in OpenSubdiv's OBJ tag lines); messages
//! about an input file say them as the file counts them (`crate::numbering::Numbering`, which
//! also writes these types' `Display`, 0-based).

use thiserror::Error;

/// Why a polygon mesh cannot be used. Its message numbers elements from 0, as Prism does;
/// `Numbering::describe` says it as the input file counts them.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MeshError {
    NonFinite { vertex: u32, x: f64, y: f64, z: f64 },
    IndexOutOfRange { face: u32, index: u32, count: u32 },
    EmptyFace { face: u32 },
    DegenerateLoop { face: u32, lp: u32, distinct: u32 },
    RepeatedVertex { face: u32, vertex: u32 },
    NonManifoldEdge { a: u32, b: u32, faces: Vec<u32> },
    InconsistentOrientation { a: u32, b: u32, f1: u32, f2: u32 },
    BoundaryEdge { a: u32, b: u32, face: u32 },
    NonManifoldVertex { vertex: u32, fans: u32 },
    NoFaces,
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
                needed_mib: needed.div_ceil(1 << 20),
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
