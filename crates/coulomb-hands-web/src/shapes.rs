//! What the page draws: every collider as triangles, taken from rapier's
//! own shapes (so what is drawn is what the hands touch), as the viewer's
//! `shapes.rs` draws them.

use coulomb_hands::{InteractionWorld, ObjectId};
use rapier3d::geometry::{Shape, TypedShape};
use rapier3d::math::{Pose, Vector};

/// Subdivisions of a round shape's triangles.
const ROUND: u32 = 24;

/// The triangles of `shape` placed by `place`, appended to `out`: 9
/// numbers each, three corners, counter-clockwise seen from outside.
/// A shape of a kind the scenes never make is left out.
fn triangles(shape: &dyn Shape, place: &Pose, out: &mut Vec<f32>) {
    let (vertices, indices): (Vec<Vector>, Vec<[u32; 3]>) = match shape.as_typed_shape() {
        TypedShape::Ball(b) => b.to_trimesh(ROUND, ROUND / 2),
        TypedShape::Cuboid(c) => c.to_trimesh(),
        TypedShape::Capsule(c) => c.to_trimesh(ROUND, ROUND / 2),
        TypedShape::Cylinder(c) => c.to_trimesh(ROUND),
        TypedShape::Cone(c) => c.to_trimesh(ROUND),
        TypedShape::ConvexPolyhedron(p) => p.to_trimesh(),
        TypedShape::TriMesh(t) => (t.vertices().to_vec(), t.indices().to_vec()),
        TypedShape::Voxels(v) => v.to_trimesh(),
        TypedShape::RoundCuboid(c) => c.inner_shape.to_trimesh(),
        TypedShape::RoundCylinder(c) => c.inner_shape.to_trimesh(ROUND),
        TypedShape::RoundConvexPolyhedron(p) => p.inner_shape.to_trimesh(),
        TypedShape::Compound(c) => {
            for (pose, part) in c.shapes() {
                triangles(&**part, &(*place * *pose), out);
            }
            return;
        }
        _ => return,
    };
    for tri in indices {
        for i in tri {
            let p = place.transform_point(vertices[i as usize]);
            out.extend([p.x, p.y, p.z]);
        }
    }
}

/// An object's triangles in its body's frame (the frame its state's
/// position and rotation place), or `None` for no such object.
pub fn object(world: &InteractionWorld, id: ObjectId) -> Option<Vec<f32>> {
    let body = world.object_body(id)?;
    let physics = world.physics();
    let mut out = Vec::new();
    for &handle in physics.bodies.get(body)?.colliders() {
        let collider = &physics.colliders[handle];
        let place = collider.position_wrt_parent().copied().unwrap_or(Pose::IDENTITY);
        triangles(collider.shape(), &place, &mut out);
    }
    Some(out)
}

/// The static colliders' triangles (ground, tables, ramps: every collider
/// that is no object's), in the world's frame.
pub fn statics(world: &InteractionWorld) -> Vec<f32> {
    let objects: Vec<_> = world.object_ids().filter_map(|id| world.object_body(id)).collect();
    let mut out = Vec::new();
    for (_, collider) in world.physics().colliders.iter() {
        if collider.parent().is_none_or(|body| !objects.contains(&body)) {
            triangles(collider.shape(), collider.position(), &mut out);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use coulomb_hands::{InteractionConfig, ObjectDesc, StaticDesc};
    use glam::Vec3;

    #[test]
    fn a_box_is_drawn_at_its_size_in_its_own_frame_and_the_ground_where_it_is() {
        let mut world = InteractionWorld::new(InteractionConfig::default()).expect("a world");
        world.add_static(&StaticDesc::ground(0.1, 0.5)).expect("a ground");
        let size = Vec3::new(0.06, 0.022, 0.14);
        let desc = ObjectDesc::cuboid("box", size, 0.1, Vec3::new(1.0, 2.0, 3.0));
        let id = world.add_object(&desc).expect("a box");
        let drawn = object(&world, id).expect("drawn");
        assert_eq!(drawn.len(), 12 * 9, "12 triangles");
        let max = drawn.chunks(3).fold(Vec3::ZERO, |m, p| m.max(Vec3::from_slice(p).abs()));
        assert!((max - size / 2.0).abs().max_element() < 1e-6, "{max}");
        let ground = statics(&world);
        let top = ground.chunks(3).map(|p| p[1]).fold(f32::MIN, f32::max);
        assert!((top - 0.1).abs() < 1e-6, "the ground's top face: {top}");
    }
}
