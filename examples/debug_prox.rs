use rapier3d::parry::query;
use rapier3d::parry::shape::{Segment, Cuboid, Ball};
use rapier3d::math::Pose;
use glam::Vec3;
fn main() {
    let cube = Cuboid::new(Vec3::splat(0.025));
    let ball = Ball::new(0.03);
    for gap in [0.006f32, 0.004, 0.002, 0.0, -0.002, -0.01] {
        let y = 0.025 + 0.008 + gap;
        let seg = Segment::new(Vec3::new(0.0, y, -0.01), Vec3::new(0.0, y, 0.01));
        let c = query::contact(&Pose::identity(), &seg, &Pose::identity(), &cube, 0.004 + 0.008).unwrap().map(|c| (c.dist - 0.008, c.point1, c.normal2));
        let yb = 0.03 + 0.008 + gap;
        let segb = Segment::new(Vec3::new(0.0, yb, -0.01), Vec3::new(0.0, yb, 0.01));
        let cb = query::contact(&Pose::identity(), &segb, &Pose::identity(), &ball, 0.012).unwrap().map(|c| c.dist - 0.008);
        println!("gap {gap}: seg-cube {:?}  seg-ball {:?}", c, cb);
    }
}
