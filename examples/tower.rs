use coulomb_hands::*;
use glam::Vec3;
fn main() {
    for f in [0.0f32, 120.0, 240.0, 500.0, 1000.0] {
        let mut w = InteractionWorld::new(InteractionConfig::default()).unwrap();
        if f > 0.0 {
            let p = &mut w.physics_mut().integration_parameters;
            p.contact_softness.natural_frequency = f;
            p.static_contact_softness.natural_frequency = f.max(p.static_contact_softness.natural_frequency);
        }
        w.add_static(&StaticDesc::ground(0.0, 0.5)).unwrap();
        let ids = scenes::add_tower(&mut w, Vec3::ZERO).unwrap();
        let top0 = w.object_state(*ids.last().unwrap()).unwrap().position;
        for _ in 0..2000 { w.step(); }
        let top = w.object_state(*ids.last().unwrap()).unwrap().position;
        let maxd = ids.iter().map(|&i| w.object_state(i).unwrap().sleeping as u32).sum::<u32>();
        println!("f {f}: top sank {:.2} mm, moved {:.2} mm; sleeping {maxd}/54", (top0.y - top.y) * 1e3, (top - top0).length() * 1e3);
    }
}
