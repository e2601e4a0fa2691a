use coulomb_hands::*;
use glam::{Quat, Vec3};
fn main() {
    let damped = std::env::args().nth(1).is_some();
    let config = InteractionConfig { damping_ratio: if damped { Some(0.5) } else { None }, ..InteractionConfig::default() };
    let mut world = InteractionWorld::new(config).unwrap();
    let id = world.add_object(&ObjectDesc::cuboid("box", Vec3::new(0.06, 0.02, 0.06), 0.06, Vec3::new(0.0, 0.32, 0.0))).unwrap();
    let hand = world.add_hand(Side::Right);
    let mut pose = hand::rig::HandRig::adult(Side::Right).pose(Vec3::new(1.0, 3.0, 0.0), Quat::IDENTITY, [0.0; 5]);
    pose.palm = Palm { center: Vec3::new(0.0, 0.3, 0.0), rotation: Quat::IDENTITY, half_extents: Vec3::new(0.045, 0.01, 0.05) };
    for i in 0..300 {
        world.set_hand_pose(hand, &pose).unwrap();
        world.step();
        if i % 10 == 0 || i < 5 {
            let s = world.object_state(id).unwrap();
            print!("{i} pos={:?} v={:?} w={:?}", s.position, s.linvel, s.angvel);
            for c in world.contacts() { print!(" | {:?} d={:.5} f={:?} k={}", c.state, c.depth, c.force, c.stiffness); }
            println!();
        }
    }
}
