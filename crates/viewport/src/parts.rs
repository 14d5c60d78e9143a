//! A scene cut into parts that each fit one GPU buffer.
//!
//! A device has a largest buffer (`wgpu::Limits::max_buffer_size`: 256 MiB by default, often
//! more on the adapter). Nine Catmull–Clark steps on a cube give 1.6 M quads, 3.1 M triangles:
//! 340 MiB of vertices drawn flat. Such a scene is drawn as several parts, each a run of
//! consecutive triangles with its own vertices, renumbered from 0 (a run of `n` triangles holds
//! at most `3n` vertices, whatever the mesh's numbering), and its lines as runs of whole
//! segments. A scene that fits is one part, not copied.

use crate::scene::{LineVertex, Vertex};

/// One run of triangles with its own vertices.
pub struct FacePart {
    pub vertices: Vec<Vertex>,
    pub indices: Vec<u32>,
}

/// Whether `count` items of `T` fit in a buffer of `max_bytes`.
pub fn fits<T>(count: usize, max_bytes: u64) -> bool {
    (count as u64).saturating_mul(std::mem::size_of::<T>() as u64) <= max_bytes
}

/// Whether a scene's triangles fit one vertex and one index buffer of `max_bytes` each.
pub fn faces_fit(vertices: &[Vertex], indices: &[u32], max_bytes: u64) -> bool {
    fits::<Vertex>(vertices.len(), max_bytes) && fits::<u32>(indices.len(), max_bytes)
}

/// The triangles `indices` (three a triangle, into `vertices`) in runs whose vertex and index
/// buffers each fit `max_bytes`. Every triangle is in exactly one run, in order.
pub fn split_faces(vertices: &[Vertex], indices: &[u32], max_bytes: u64) -> Vec<FacePart> {
    let per_triangle = 3 * std::mem::size_of::<Vertex>().max(std::mem::size_of::<u32>()) as u64;
    let triangles = (max_bytes / per_triangle).max(1) as usize;
    // The new number of each old vertex in the current run (u32::MAX: not yet in it).
    let mut new_index = vec![u32::MAX; vertices.len()];
    indices
        .chunks(3 * triangles)
        .map(|run| {
            let mut part = FacePart {
                vertices: Vec::with_capacity(run.len()),
                indices: Vec::with_capacity(run.len()),
            };
            for &i in run {
                let slot = &mut new_index[i as usize];
                if *slot == u32::MAX {
                    *slot = part.vertices.len() as u32;
                    part.vertices.push(vertices[i as usize]);
                }
                part.indices.push(*slot);
            }
            for &i in run {
                new_index[i as usize] = u32::MAX;
            }
            part
        })
        .collect()
}

/// Line vertices (two a segment) in runs of whole segments that each fit `max_bytes`.
pub fn split_lines(lines: &[LineVertex], max_bytes: u64) -> impl Iterator<Item = &[LineVertex]> {
    let segments = (max_bytes / (2 * std::mem::size_of::<LineVertex>() as u64)).max(1) as usize;
    lines.chunks(2 * segments)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn vertex(i: usize) -> Vertex {
        Vertex {
            position: [i as f32, 0.0, 0.0],
            normal: [0.0, 0.0, 1.0],
            color: [1.0; 3],
        }
    }

    #[test]
    fn every_triangle_is_in_one_part_with_its_own_corners() {
        // A fan of shared vertices, numbered out of order, split into runs of 2 triangles.
        let vertices: Vec<Vertex> = (0..40).map(vertex).collect();
        let indices: Vec<u32> = (0..30u32)
            .flat_map(|t| [0, (t * 7) % 39 + 1, (t * 11 + 3) % 39 + 1])
            .collect();
        let max = 2 * 3 * std::mem::size_of::<Vertex>() as u64;
        assert!(!faces_fit(&vertices, &indices, max));
        let parts = split_faces(&vertices, &indices, max);
        assert_eq!(parts.len(), 15);
        let mut again = Vec::new();
        for p in &parts {
            assert!(faces_fit(&p.vertices, &p.indices, max));
            for &i in &p.indices {
                again.push(p.vertices[i as usize].position);
            }
        }
        let expected: Vec<[f32; 3]> = indices
            .iter()
            .map(|&i| vertices[i as usize].position)
            .collect();
        assert_eq!(again, expected);
    }

    #[test]
    fn lines_split_between_segments() {
        let lines: Vec<LineVertex> = (0..10)
            .map(|i| LineVertex {
                position: [i as f32, 0.0, 0.0],
                color: [0.0; 3],
            })
            .collect();
        let max = 3 * 2 * std::mem::size_of::<LineVertex>() as u64;
        let runs: Vec<usize> = split_lines(&lines, max).map(|r| r.len()).collect();
        assert_eq!(runs, [6, 4]);
    }
}
