use coulomb_hands::*;
use glam::{Quat, Vec3};
fn main() {
    let thesis = std::env::args().nth(1).is_some();
    let config = if thesis { InteractionConfig::thesis() } else { InteractionConfig::default() };
    let mut world = InteractionWorld::new(config).unwrap();
    world.add_static(&StaticDesc::ground(0.0, 0.5)).unwrap();
    let id = world.add_object(&ObjectDesc::cuboid("box", Vec3::splat(0.06), 0.05, Vec3::new(0.0, 0.03, 0.0))).unwrap();
    let hand = world.add_hand(Side::Right);
    let mut pose = hand::rig::HandRig::adult(Side::Right).pose(Vec3::new(1.0, 3.0, 0.0), Quat::IDENTITY, [0.0; 5]);
    pose.fingers[1][2] = Capsule { a: Vec3::new(-0.05, 0.03, 0.0), b: Vec3::new(0.0, 0.03, 0.0), radius: 0.008 };
    for i in 0..400 {
        world.set_hand_pose(hand, &pose).unwrap();
        world.step();
        if i % 10 == 0 {
            let s = world.object_state(id).unwrap();
            print!("{i} pos={:?} v={:?}", s.position, s.linvel);
            for c in world.contacts() { print!(" | {} {:?} d={:.4} f={:?} n={:?} C={:?} p={:?}", c.bone, c.state, c.depth, c.force, c.normal, c.point, c.bone_point); }
            println!();
        }
    }
}
