// throwaway: print bone end points of a keyframe
use coulomb_hands::hand::rig::HandRig;
use coulomb_hands::Side;
use glam::{EulerRot, Quat, Vec3};
fn main() {
    let a: Vec<f32> = std::env::args().skip(1).map(|s| s.parse().unwrap()).collect();
    // side(0 right/1 left) px py pz rx ry rz c0..c4 opp
    let side = if a[0] == 0.0 { Side::Right } else { Side::Left };
    let r = Vec3::new(a[4], a[5], a[6]) * (std::f32::consts::PI / 180.0);
    let rot = Quat::from_euler(EulerRot::ZYX, r.z, r.y, r.x);
    let pose = HandRig::adult(side).pose_opposed(Vec3::new(a[1], a[2], a[3]), rot, [a[7], a[8], a[9], a[10], a[11]], a[12]);
    println!("palm c {:?} normal {:?}", pose.palm.center, pose.palm.normal());
    for (f, fi) in pose.fingers.iter().enumerate() {
        for (p, b) in fi.iter().enumerate() {
            println!("f{f} p{p} a [{:7.4} {:7.4} {:7.4}] b [{:7.4} {:7.4} {:7.4}] r {:.4}", b.a.x, b.a.y, b.a.z, b.b.x, b.b.y, b.b.z, b.radius);
        }
    }
}
