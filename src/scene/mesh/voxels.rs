//! A concave mesh voxelized into boxes, the thesis's way of making it a
//! dynamic body (§3.7).

use super::{MeshProblem, TriangleMesh};
use glam::Vec3;

impl TriangleMesh {
    /// Voxelizes the solid into boxes of side `voxel` (m): of the voxels
    /// parry's flood fill marks (inside or crossing the surface), those whose
    /// centre is inside the mesh, so that thin walls do not grow by a voxel
    /// on each side. A mesh too broken to tell inside from outside keeps all
    /// of them. Voxels are merged into runs along x, so a row is one box.
    /// Returns (centre, half extents) per box, at most `max_boxes` of them.
    pub fn voxel_boxes(
        &self,
        voxel: f32,
        max_boxes: usize,
    ) -> Result<Vec<(Vec3, Vec3)>, MeshProblem> {
        use rapier3d::parry::query::PointQuery;
        use rapier3d::parry::shape::{TriMesh, TriMeshFlags};
        use rapier3d::parry::transformation::voxelization::{FillMode, VoxelSet};
        let (lo, hi) = self.bounds();
        let cells = ((hi - lo) / voxel).ceil();
        // A voxel larger than the mesh fills nothing; at 1e19 m, f32 rounding
        // once put one 1e19 m box "inside" a 6 cm mesh.
        let too_large = voxel > (hi - lo).max_element();
        if !(voxel.is_finite() && voxel > 0.0) || too_large || cells.x * cells.y * cells.z > 4.0e6 {
            return Err(MeshProblem::VoxelSize { voxel, size: hi - lo });
        }
        let set = VoxelSet::with_voxel_size(
            &self.vertices,
            &self.triangles,
            voxel,
            FillMode::default(),
            false,
        );
        let mut cells: Vec<[i32; 3]> = set.voxels().iter().map(|v| v.coords.to_array()).collect();
        cells.sort_by_key(|c| (c[2], c[1], c[0]));
        cells.dedup();
        let scale = set.scale;
        let centre_of = |c: [i32; 3]| {
            set.origin + Vec3::new(c[0] as f32 + 0.5, c[1] as f32 + 0.5, c[2] as f32 + 0.5) * scale
        };
        if let Ok(solid) = TriMesh::with_flags(
            self.vertices.clone(),
            self.triangles.clone(),
            TriMeshFlags::ORIENTED,
        ) {
            cells.retain(|&c| solid.contains_local_point(centre_of(c)));
        }
        let mut boxes = Vec::new();
        let mut i = 0;
        while i < cells.len() {
            let start = cells[i];
            let mut end = start;
            while i + 1 < cells.len() && cells[i + 1] == [end[0] + 1, end[1], end[2]] {
                i += 1;
                end = cells[i];
            }
            let (a, b) = (centre_of(start), centre_of(end));
            boxes.push((
                0.5 * (a + b),
                Vec3::new(0.5 * (b.x - a.x) + 0.5 * scale, 0.5 * scale, 0.5 * scale),
            ));
            i += 1;
        }
        if boxes.is_empty() {
            return Err(MeshProblem::NoVoxels { voxel });
        }
        if boxes.len() > max_boxes {
            return Err(MeshProblem::TooManyVoxels { voxel, boxes: boxes.len(), max: max_boxes });
        }
        Ok(boxes)
    }
}
