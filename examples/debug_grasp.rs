use coulomb_hands::scenes::GraspLiftCarry;
use coulomb_hands::InteractionConfig;
fn main() {
    let mut s = GraspLiftCarry::new(InteractionConfig::default()).unwrap();
    let dt = s.world.config().dt;
    let until: f32 = std::env::args().nth(1).map(|a| a.parse().unwrap()).unwrap_or(1.0);
    let every: usize = std::env::args().nth(2).map(|a| a.parse().unwrap()).unwrap_or(12);
    for i in 0..((until / dt) as usize) {
        let t = i as f32 * dt;
        let pose = s.hand_pose(t);
        s.world.set_hand_pose(s.hand, &pose).unwrap();
        s.world.step();
        if i % every == 0 && !s.world.contacts().is_empty() {
            let st = s.world.object_state(s.cube).unwrap();
            println!("t={t:.3} cube={:?} v={:?}", st.position, st.linvel);
            for c in s.world.contacts() {
                println!("  {:>20} {:?} depth={:+.4} f={:?} |f|={:.3} n={:?} C={:?} p={:?}", c.bone.to_string(), c.state, c.depth, c.force, c.force.length(), c.normal, c.point, c.bone_point);
            }
        }
    }
}
