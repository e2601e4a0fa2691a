use coulomb_hands::*;
use glam::{Quat, Vec3};
fn main() {
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    world.add_static(&StaticDesc::ground(0.0, 1.0)).unwrap();
    let start = Vec3::new(0.2, 0.025, 0.0);
    let id = world.add_object(&ObjectDesc::cuboid("box", Vec3::splat(0.05), 0.1, start).with_material(Material { surface_friction: 1.0, ..Material::wood() })).unwrap();
    let hand = world.add_hand(Side::Right);
    let rig = hand::rig::HandRig::adult(Side::Right);
    let palm = Palm::from_normal_direction(Vec3::ZERO, -Vec3::Y, Vec3::X, rig.palm_half_extents).unwrap();
    let pointing = rig.pose(Vec3::ZERO, palm.rotation, [1.0, 0.0, 1.0, 1.0, 1.0]);
    let index = pointing.fingers[1][2];
    let tip = index.b + (index.b - index.a).normalize() * index.radius;
    let offset = Vec3::new(start.x - 0.025 - 0.02, 0.045, 0.0) - tip;
    for i in 0..2500 {
        let t = i as f32 * 0.001;
        world.set_hand_pose(hand, &pointing.transformed(Vec3::ZERO, Quat::IDENTITY, offset + Vec3::X * (0.1 * t.min(1.2) - 0.1 * (t - 1.2).clamp(0.0, 0.5)))).unwrap();
        world.step();
        if i % 50 == 0 {
            let s = world.object_state(id).unwrap();
            print!("t={t:.2} pos={:?} tilt={:.1}", s.position, s.rotation.angle_between(Quat::IDENTITY).to_degrees());
            for c in world.contacts() { print!(" | {} {:?} d={:.4} |f|={:.3}", c.bone, c.state, c.depth, c.force.length()); }
            println!();
        }
    }
}
