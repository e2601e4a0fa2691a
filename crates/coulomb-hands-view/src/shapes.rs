//! Render meshes of the world's collision shapes, read from its rapier
//! colliders, so what is drawn is exactly what the hands touch: primitives
//! are drawn smooth, and meshes and convex hulls face by face.

use bevy::asset::RenderAssetUsages;
use bevy::mesh::{Indices, PrimitiveTopology};
use bevy::prelude::*;
use coulomb_hands_bevy::convert;
use rapier3d::geometry::{Shape, TypedShape};

/// Subdivisions of a curved shape drawn as triangles (a round cone).
const SUBDIVISIONS: u32 = 24;

/// The meshes of `shape`, each with its place in the shape's frame: one
/// for a single shape, one per part for a compound. Shapes with no finite
/// surface (a half-space) have none.
pub fn meshes(shape: &dyn Shape) -> Vec<(Transform, Mesh)> {
    let part = |mesh: Mesh| vec![(Transform::IDENTITY, mesh)];
    match shape.as_typed_shape() {
        TypedShape::Ball(b) => part(Sphere::new(b.radius).mesh().uv(32, 18)),
        TypedShape::Cuboid(c) => {
            part(Cuboid::from_size(convert::to_bevy_vec3(c.half_extents) * 2.0).into())
        }
        TypedShape::Capsule(c) => {
            let (a, b) = (convert::to_bevy_vec3(c.segment.a), convert::to_bevy_vec3(c.segment.b));
            let rotation = Quat::from_rotation_arc(Vec3::Y, (b - a).normalize_or(Vec3::Y));
            let place = Transform::from_translation((a + b) / 2.0).with_rotation(rotation);
            vec![(place, Capsule3d::new(c.radius, a.distance(b)).into())]
        }
        TypedShape::Cylinder(c) => part(Cylinder::new(c.radius, 2.0 * c.half_height).into()),
        TypedShape::Cone(c) => part(Cone { radius: c.radius, height: 2.0 * c.half_height }.into()),
        TypedShape::TriMesh(t) => part(faceted(t.vertices(), t.indices())),
        TypedShape::ConvexPolyhedron(p) => {
            let (vertices, indices) = p.to_trimesh();
            part(faceted(&vertices, &indices))
        }
        TypedShape::RoundCylinder(c) => {
            let (vertices, indices) = c.inner_shape.to_trimesh(SUBDIVISIONS);
            part(faceted(&vertices, &indices))
        }
        TypedShape::RoundCuboid(c) => {
            let size = convert::to_bevy_vec3(c.inner_shape.half_extents + c.border_radius) * 2.0;
            part(Cuboid::from_size(size).into())
        }
        TypedShape::Compound(c) => c
            .shapes()
            .iter()
            .flat_map(|(pose, shape)| {
                let place = convert::transform(pose.translation, pose.rotation);
                meshes(&**shape).into_iter().map(move |(t, mesh)| (place * t, mesh))
            })
            .collect(),
        _ => Vec::new(),
    }
}

/// A triangle mesh with flat faces: each triangle gets its own vertices and
/// its face normal, so hard edges stay hard. (Also a capture's mesh, drawn
/// as it is: [`crate::ghost`].)
pub fn faceted(vertices: &[glam::Vec3], indices: &[[u32; 3]]) -> Mesh {
    let mut positions = Vec::with_capacity(indices.len() * 3);
    let mut normals = Vec::with_capacity(indices.len() * 3);
    for tri in indices {
        let [a, b, c] = tri.map(|i| convert::to_bevy_vec3(vertices[i as usize]));
        let normal = (b - a).cross(c - a).normalize_or_zero();
        positions.extend([a, b, c]);
        normals.extend([normal; 3]);
    }
    let count = positions.len() as u32;
    Mesh::new(PrimitiveTopology::TriangleList, RenderAssetUsages::RENDER_WORLD)
        .with_inserted_attribute(Mesh::ATTRIBUTE_POSITION, positions)
        .with_inserted_attribute(Mesh::ATTRIBUTE_NORMAL, normals)
        .with_inserted_indices(Indices::U32((0..count).collect()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapier3d::geometry::SharedShape;

    /// A mesh's vertex positions.
    fn positions(mesh: &Mesh) -> Vec<Vec3> {
        let attribute = mesh.attribute(Mesh::ATTRIBUTE_POSITION).expect("positions");
        attribute.as_float3().expect("float3").iter().map(|p| Vec3::from_array(*p)).collect()
    }

    #[test]
    fn a_box_is_drawn_at_its_collider_size() {
        let shape = SharedShape::cuboid(0.03, 0.011, 0.07);
        let drawn = meshes(&*shape);
        assert_eq!(drawn.len(), 1);
        let max = positions(&drawn[0].1).into_iter().fold(Vec3::ZERO, |m, p| m.max(p.abs()));
        assert!((max - Vec3::new(0.03, 0.011, 0.07)).abs().max_element() < 1e-6, "{max}");
    }

    #[test]
    fn a_compound_is_drawn_part_by_part_where_each_part_sits() {
        let handle = (Pose::translation(0.0, 0.2, 0.0), SharedShape::ball(0.025));
        let head = (Pose::translation(0.06, 0.35, 0.0), SharedShape::cuboid(0.08, 0.03, 0.01));
        let drawn = meshes(&*SharedShape::compound(vec![handle, head]));
        assert_eq!(drawn.len(), 2);
        assert!((drawn[1].0.translation - Vec3::new(0.06, 0.35, 0.0)).length() < 1e-6);
        let far = positions(&drawn[0].1).into_iter().map(|p| p.length()).fold(0.0, f32::max);
        assert!((far - 0.025).abs() < 1e-4, "a ball part's radius: {far}");
    }

    #[test]
    fn a_convex_hull_keeps_its_faces_flat() {
        let points = [[0.0, 0.0, 0.0], [0.05, 0.0, 0.0], [0.0, 0.05, 0.0], [0.0, 0.0, 0.05]]
            .map(glam::Vec3::from_array);
        let shape = SharedShape::convex_hull(&points).expect("a tetrahedron");
        let mesh = &meshes(&*shape)[0].1;
        let corners = positions(mesh);
        assert_eq!(corners.len(), 12, "4 faces of 3 vertices each");
        let normals = mesh.attribute(Mesh::ATTRIBUTE_NORMAL).and_then(|n| n.as_float3());
        let normals: Vec<Vec3> = normals.expect("normals").iter().map(|n| Vec3::from(*n)).collect();
        for (face, n) in corners.chunks(3).zip(normals.chunks(3)) {
            assert!(n[0] == n[1] && n[1] == n[2], "one normal per face: {n:?}");
            let across = (face[1] - face[0]).cross(face[2] - face[0]).normalize();
            assert!((across - n[0]).length() < 1e-5, "the face's own normal: {n:?}");
            let outward = face[0] - Vec3::splat(0.0125);
            assert!(n[0].dot(outward) > 0.0, "pointing out of the hull");
        }
    }

    use rapier3d::math::Pose;
}
