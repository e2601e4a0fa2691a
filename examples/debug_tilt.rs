use coulomb_hands::*;
use glam::{Quat, Vec3};
fn main() {
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    let palm_half = Vec3::new(0.045, 0.01, 0.05);
    let centre = Vec3::new(0.0, 0.3, 0.0);
    let size = Vec3::new(0.06, 0.02, 0.06);
    let id = world.add_object(&ObjectDesc::cuboid("box", size, 0.06, centre + Vec3::Y * (palm_half.y + size.y / 2.0)).with_material(Material::custom("t", 0.5, 0.4, 0.5))).unwrap();
    let hand = world.add_hand(Side::Right);
    let base = hand::rig::HandRig::adult(Side::Right).pose(Vec3::new(1.0, 3.0, 0.0), Quat::IDENTITY, [0.0; 5]);
    let dt = world.config().dt;
    for i in 0..9000 {
        let t = i as f32 * dt;
        let tilt = (3.0 * t).to_radians();
        let mut pose = base.clone();
        pose.palm = Palm { center: centre, rotation: Quat::from_rotation_z(tilt), half_extents: palm_half };
        world.set_hand_pose(hand, &pose).unwrap();
        world.step();
        if (i % 250 == 0) || (i > 7700 && i < 8000 && i % 10 == 0) {
            let s = world.object_state(id).unwrap();
            let local = pose.palm.to_local(s.position);
            print!("tilt={:.2} local={:?} rot={:.2}", 3.0*t, local, (pose.palm.rotation.inverse()*s.rotation).angle_between(Quat::IDENTITY).to_degrees());
            for c in world.contacts() {
                let ft = (c.force + c.normal_force * c.normal).length();
                print!(" | {:?} fn={:.4} ft/fn={:.3} C={:?} p={:?}", c.state, c.normal_force, ft / c.normal_force, c.point, c.bone_point);
            }
            println!();
        }
    }
}
