//! Flat-hand tilt: a box on a slowly tilting palm starts to slide at the
//! friction angle atan(μ_st).

use super::*;
use coulomb_hands::{FrictionState, InteractionConfig, ObjectDesc, Palm};

const DEG_PER_S: f32 = 3.0;

/// Returns the tilt (degrees) at which the box has slid 3 mm down the palm
/// beyond where it rested, and the tilt at which its contact first went
/// dynamic.
fn slide_angle(material: Material) -> (f32, f32) {
    slide_angle_at(material, InteractionConfig::default().dt)
}

/// [`slide_angle`] with the world stepping at `dt` (s).
fn slide_angle_at(material: Material, dt: f32) -> (f32, f32) {
    let config = InteractionConfig { dt, ..InteractionConfig::default() };
    let mut world = InteractionWorld::new(config).unwrap();
    let palm_half = Vec3::new(0.045, 0.01, 0.05);
    let centre = Vec3::new(0.0, 0.3, 0.0);
    // A flat 6 × 2 × 6 cm, 60 g box resting on the palm's top face.
    let size = Vec3::new(0.06, 0.02, 0.06);
    let desc =
        ObjectDesc::cuboid("box", size, 0.06, centre + Vec3::Y * (palm_half.y + size.y / 2.0))
            .with_material(material);
    let id = world.add_object(&desc).unwrap();
    let hand = world.add_hand(Side::Right);
    let base = parked_hand(Side::Right);
    // The palm tilts about +z through its centre; "down the slope" is −x.
    let pose_at = |t: f32| {
        let tilt = (DEG_PER_S * t).to_radians();
        let mut pose = base.clone();
        pose.palm =
            Palm { center: centre, rotation: Quat::from_rotation_z(tilt), half_extents: palm_half };
        pose
    };
    let mut rest: Option<Vec3> = None;
    let mut first_dynamic = None;
    let mut slid = None;
    let mut watch = |step: &StepView| {
        let tilt = DEG_PER_S * step.t as f32;
        // The box's position in the palm frame.
        let pose = &step.hands[0].sample.as_ref().expect("the palm is tracked").pose;
        let local = pose.palm.to_local(position(step.world, id));
        if tilt >= 1.0 && rest.is_none() {
            rest = Some(local);
        }
        let contacts = step.world.contacts();
        if first_dynamic.is_none() && contacts.iter().any(|c| c.state == FrictionState::Dynamic) {
            first_dynamic = Some(tilt);
        }
        if let Some(r) = rest
            && (local - r).length() > 0.003
            && slid.is_none()
        {
            assert_eq!(contacts.len(), 1, "only the palm touches the box");
            slid = Some(tilt);
        }
        Ok(())
    };
    let mut driver = Driver::new(&mut world);
    driver.drive(hand, PoseFn::new(Side::Right, |t| Some(pose_at(t as f32)))).unwrap();
    driver.run(((40.0 / DEG_PER_S) / dt) as usize, &mut [&mut watch]).unwrap();
    let slid = slid.expect("the box slid before 40°");
    (slid, first_dynamic.unwrap_or(f32::NAN))
}

#[test]
fn box_slides_at_the_friction_angle() {
    let (angle, dynamic_at) = slide_angle(test_material(0.5));
    let expected = 0.5f32.atan().to_degrees(); // 26.57°
    assert!((angle - expected).abs() < 2.0, "slid at {angle:.2}°, expected {expected:.2}°");
    assert!((dynamic_at - expected).abs() < 2.0, "went dynamic at {dynamic_at:.2}°");
}

#[test]
fn a_grippier_material_slides_later() {
    // μ_st 0.7: sliding must wait until atan 0.7 = 35°.
    let (angle, _) = slide_angle(Material::custom("grippy", 0.7, 0.6, 0.5));
    let expected = 0.7f32.atan().to_degrees(); // 34.99°
    assert!((angle - expected).abs() < 2.0, "slid at {angle:.2}°, expected {expected:.2}°");
}

#[test]
fn at_a_host_engines_90_hz_the_box_still_slides_at_the_friction_angle() {
    // μ_st 0.6: atan 0.6 = 30.96°, at a step 11 times the haptic one, where
    // this 60 g box's springs step by backward Euler.
    let (angle, dynamic_at) = slide_angle_at(Material::custom("tacky", 0.6, 0.5, 0.5), 1.0 / 90.0);
    let expected = 0.6f32.atan().to_degrees();
    assert!((angle - expected).abs() < 2.0, "slid at {angle:.2}°, expected {expected:.2}°");
    assert!((dynamic_at - expected).abs() < 2.0, "went dynamic at {dynamic_at:.2}°");
}
