//! A closed mesh as an exact solid, for the hand's contact queries
//! ([`crate::scene::HandSurface::Exact`]): parry tells inside from outside
//! by its pseudo-normals, which only a closed, outward-wound mesh has.

use super::{MeshProblem, TriangleMesh, generate};

impl TriangleMesh {
    /// The mesh as an exact solid for point, ray and contact queries, with
    /// parry's pseudo-normals telling inside from outside. It must be
    /// [`check`](Self::check)ed, closed (each edge a→b of a triangle matched
    /// by an edge b→a of another; vertices at the same place are one, so an
    /// STL's unshared corners close) and wound outwards.
    pub fn solid(&self) -> Result<rapier3d::parry::shape::TriMesh, MeshProblem> {
        use rapier3d::parry::shape::{TriMesh, TriMeshFlags};
        self.check()?;
        let edges = self.open_edges();
        if edges > 0 {
            return Err(MeshProblem::NotClosed { edges });
        }
        let volume = generate::signed_volume(self);
        if volume <= 0.0 {
            return Err(MeshProblem::InsideOut { volume });
        }
        let flags = TriMeshFlags::ORIENTED | TriMeshFlags::MERGE_DUPLICATE_VERTICES;
        TriMesh::with_flags(self.vertices.clone(), self.triangles.clone(), flags)
            .map_err(|e| MeshProblem::Unreadable(e.to_string()))
    }

    /// How many undirected edges are not matched: run a→b by as many
    /// triangles as b→a. Vertices are matched by position.
    pub fn open_edges(&self) -> usize {
        let mut at = std::collections::HashMap::new();
        let index: Vec<u32> = self
            .vertices
            .iter()
            .map(|v| {
                let next = at.len() as u32;
                *at.entry(v.to_array().map(f32::to_bits)).or_insert(next)
            })
            .collect();
        let mut balance = std::collections::HashMap::new();
        for t in &self.triangles {
            for k in 0..3 {
                let (a, b) = (index[t[k] as usize], index[t[(k + 1) % 3] as usize]);
                *balance.entry((a.min(b), a.max(b))).or_insert(0i32) += if a < b { 1 } else { -1 };
            }
        }
        balance.values().filter(|&&n| n != 0).count()
    }
}
