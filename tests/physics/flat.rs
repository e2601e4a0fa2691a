//! Flat faces on a flat palm: a box resting on a tilting palm starts to
//! slide at atan μ_st whatever its height and mass, slides with Coulomb's
//! acceleration g(sin θ − μ_dyn cos θ), and a small cube's palm patch stays
//! on the face it rests on.

use super::*;
use coulomb_hands::{FrictionState, GammaMode, InteractionConfig, ObjectDesc, ObjectId, Palm};

/// The palm's centre, and its half extents: a 9 × 2 × 10 cm adult palm.
const PALM_CENTRE: Vec3 = Vec3::new(0.0, 0.3, 0.0);
const PALM_HALF: Vec3 = Vec3::new(0.045, 0.01, 0.05);

fn palm_at(tilt_deg: f32) -> Palm {
    Palm {
        center: PALM_CENTRE,
        rotation: Quat::from_rotation_z(tilt_deg.to_radians()),
        half_extents: PALM_HALF,
    }
}

/// A world with a `size` box of `mass` resting on the palm tilted by
/// `tilt_deg` about +z (down the slope is the palm's −x), its bottom face
/// on the palm's top face, offset along the palm's x by `along` (m).
fn box_on_palm(
    config: InteractionConfig,
    size: Vec3,
    mass: f32,
    material: Material,
    tilt_deg: f32,
    along: f32,
) -> (InteractionWorld, ObjectId, HandId) {
    let mut world = InteractionWorld::new(config).unwrap();
    let palm = palm_at(tilt_deg);
    // Sunk into the palm as far as its weight presses it at the world's γ,
    // so that it starts at rest.
    let sink = match config.gamma {
        GammaMode::Fixed(gamma) => mass * 9.81 * tilt_deg.to_radians().cos() / gamma,
        GammaMode::Auto => 0.0,
    };
    let centre = palm.to_world(Vec3::new(along, PALM_HALF.y + size.y / 2.0 - sink, 0.0));
    let mut desc = ObjectDesc::cuboid("box", size, mass, centre).with_material(material);
    desc.rotation = palm.rotation;
    let id = world.add_object(&desc).unwrap();
    let hand = world.add_hand(Side::Right);
    (world, id, hand)
}

fn pose_with(palm: Palm) -> HandPose {
    let mut pose = parked_hand(Side::Right);
    pose.palm = palm;
    pose
}

/// Where the middle of the box's bottom face (`height` tall) is in the
/// palm's frame (m): unlike its centre of mass, it does not move when the
/// box rocks on the soft contact.
fn base_in_palm(world: &InteractionWorld, id: ObjectId, height: f32, palm: &Palm) -> Vec3 {
    let state = world.object_state(id).unwrap();
    let base = state.position + state.rotation * Vec3::new(0.0, -height / 2.0, 0.0);
    palm.to_local(base)
}

struct Onset {
    /// The tilt at which the palm contact first went dynamic (°).
    dynamic: f32,
    /// The tilt at which the box had slid 3 mm down the palm (°).
    slid: f32,
}

/// Tilts the palm to 5° below atan μ_st in 1 s, then on at 1.2°/s, and
/// returns the tilts at which the box starts to slide.
fn tilt_onset(gamma: GammaMode, size: Vec3, mass: f32, mu_st: f32, mu_dyn: f32) -> Onset {
    let material = Material::custom("flat", mu_st, mu_dyn, 0.5);
    let config = InteractionConfig { gamma, ..InteractionConfig::default() };
    let (mut world, id, hand) = box_on_palm(config, size, mass, material, 0.0, 0.0);
    let start = mu_st.atan().to_degrees() - 5.0;
    let tilt = move |t: f32| {
        if t < 1.0 {
            let s = t * t * (3.0 - 2.0 * t);
            start * s
        } else {
            start + 1.2 * (t - 1.0)
        }
    };
    let (mut rest, mut dynamic, mut slid) = (None, None, None);
    run(
        &mut world,
        hand,
        1.0 + 10.0 / 1.2,
        |t| pose_with(palm_at(tilt(t))),
        |w, t| {
            let palm = palm_at(tilt(t));
            let local = base_in_palm(w, id, size.y, &palm);
            if t >= 1.5 && rest.is_none() {
                rest = Some(local);
            }
            let Some(rest) = rest else { return };
            let contacts = w.contacts_on(id);
            if dynamic.is_none() && contacts.iter().any(|c| c.state == FrictionState::Dynamic) {
                dynamic = Some(tilt(t));
            }
            if slid.is_none() && rest.x - local.x > 0.003 {
                slid = Some(tilt(t));
            }
        },
    );
    Onset { dynamic: dynamic.unwrap_or(f32::NAN), slid: slid.unwrap_or(f32::NAN) }
}

/// The thesis's fixed γ (400 N/m) for two materials, and Eq. 3.11's γ for
/// one: a 480 g box sinks 12 mm into the first, and every box 6–8 mm into
/// the second.
#[test]
fn boxes_of_any_height_and_mass_start_sliding_at_the_friction_angle() {
    let mut report = Vec::new();
    let fixed = GammaMode::default();
    for (gamma, mu_st, mu_dyn) in
        [(fixed, 0.44f32, 0.31f32), (fixed, 0.58, 0.47), (GammaMode::Auto, 0.58, 0.47)]
    {
        let expected = mu_st.atan().to_degrees();
        for height in [0.005, 0.021, 0.05] {
            for mass in [0.012, 0.17, 0.48] {
                let size = Vec3::new(0.04, height, 0.045);
                let onset = tilt_onset(gamma, size, mass, mu_st, mu_dyn);
                let bad = !((onset.dynamic - expected).abs() <= 1.0
                    && (onset.slid - expected).abs() <= 1.0);
                report.push(format!(
                    "{}{gamma:?} h {:>4.1} mm m {:>3.0} g μ {mu_st}: dynamic {:.2}°, \
                     slid {:.2}° (atan μ_st {expected:.2}°)",
                    if bad { "FAIL " } else { "ok   " },
                    height * 1e3,
                    mass * 1e3,
                    onset.dynamic,
                    onset.slid,
                ));
            }
        }
    }
    let text = report.join("\n");
    assert!(!text.contains("FAIL"), "{text}");
}

/// The box's acceleration down a palm held at `tilt_deg` (m/s²): a
/// least-squares parabola through its slide along the palm, from 20 ms
/// after release (the contact's spring settles) until it has slid 3 cm.
fn sliding_acceleration(
    config: InteractionConfig,
    size: Vec3,
    mass: f32,
    (mu_st, mu_dyn): (f32, f32),
    tilt_deg: f32,
) -> f32 {
    let material = Material::custom("sliding", mu_st, mu_dyn, 0.5);
    let start = PALM_HALF.x - size.x / 2.0;
    let (mut world, id, hand) = box_on_palm(config, size, mass, material, tilt_deg, start);
    let palm = palm_at(tilt_deg);
    let mut track: Vec<(f64, f64)> = Vec::new();
    let mut done = false;
    run(
        &mut world,
        hand,
        0.6,
        |_| pose_with(palm),
        |w, t| {
            let down = f64::from(start - base_in_palm(w, id, size.y, &palm).x);
            done |= down > 0.03;
            if t >= 0.02 && !done {
                track.push((f64::from(t), down));
            }
        },
    );
    // At least 50 ms of sliding to fit.
    let sliding = track.len() as f32 * config.dt;
    assert!(done && sliding > 0.05, "the box did not slide 3 cm: {:?}", track.last());
    // Fit down(t) = c0 + c1 t + c2 t² by the normal equations.
    let mut m = [[0.0f64; 4]; 3];
    for &(t, x) in &track {
        let powers = [1.0, t, t * t];
        for (row, &p) in m.iter_mut().zip(&powers) {
            for (cell, &q) in row.iter_mut().zip(&powers) {
                *cell += p * q;
            }
            row[3] += p * x;
        }
    }
    for i in 0..3 {
        for j in 0..3 {
            if i != j {
                let f = m[j][i] / m[i][i];
                let pivot = m[i];
                for (cell, p) in m[j].iter_mut().zip(pivot) {
                    *cell -= f * p;
                }
            }
        }
    }
    (2.0 * m[2][3] / m[2][2]) as f32
}

#[test]
fn a_sliding_box_accelerates_as_coulomb_says() {
    for (size, mass, mu_st, mu_dyn, tilt) in [
        (Vec3::new(0.04, 0.012, 0.04), 0.09, 0.52, 0.38, 33.0f32),
        (Vec3::new(0.035, 0.03, 0.045), 0.04, 0.31, 0.22, 24.0),
    ] {
        let (s, c) = tilt.to_radians().sin_cos();
        let expected = 9.81 * (s - mu_dyn * c);
        let config = InteractionConfig::default();
        let a = sliding_acceleration(config, size, mass, (mu_st, mu_dyn), tilt);
        assert!(
            (a / expected - 1.0).abs() < 0.05,
            "{mass} kg at {tilt}° (μ_dyn {mu_dyn}): {a:.3} m/s², Coulomb says {expected:.3}"
        );
    }
}

#[test]
fn at_a_host_engines_90_hz_a_sliding_box_still_accelerates_as_coulomb_says() {
    // A light box on a steep palm, light enough that its springs step by
    // backward Euler at 1/90 s (`friction/implicit.rs`).
    let config = InteractionConfig { dt: 1.0 / 90.0, ..InteractionConfig::default() };
    let (size, mass, mu_st, mu_dyn, tilt) = (Vec3::new(0.05, 0.015, 0.03), 0.03, 0.44, 0.33, 31.0);
    let (s, c) = f32::to_radians(tilt).sin_cos();
    let expected = 9.81 * (s - mu_dyn * c);
    let a = sliding_acceleration(config, size, mass, (mu_st, mu_dyn), tilt);
    assert!(
        (a / expected - 1.0).abs() < 0.05,
        "{mass} kg at {tilt}° and 90 Hz: {a:.3} m/s², Coulomb says {expected:.3}"
    );
}

#[test]
fn a_small_cube_s_palm_patch_stays_on_the_face_it_rests_on() {
    // A 2 cm, 15 g cube on a level palm: the 3 cm palm ring cannot fit.
    let half = 0.01;
    let config = InteractionConfig::default();
    let size = Vec3::splat(2.0 * half);
    let material = Material::custom("small", 0.6, 0.5, 0.5);
    let (mut world, id, hand) = box_on_palm(config, size, 0.015, material, 0.0, 0.004);
    let start = position(&world, id);
    let mut checked = 0;
    run(
        &mut world,
        hand,
        1.0,
        |_| pose_with(palm_at(0.0)),
        |w, _| {
            let state = w.object_state(id).unwrap();
            for contact in w.contacts_on(id) {
                for sample in &contact.samples {
                    let local = state.rotation.inverse() * (*sample - state.position);
                    let on_bottom = (local.y + half).abs() < 2.0e-4
                        && local.x.abs() < half - 1.0e-4
                        && local.z.abs() < half - 1.0e-4;
                    assert!(on_bottom, "a palm sample left the bottom face: {local:?}");
                    checked += 1;
                }
            }
        },
    );
    assert!(checked > 1000, "the palm held the cube with its patch ({checked} samples seen)");
    let state = world.object_state(id).unwrap();
    let drift = (state.position - start).length();
    let turned = state.rotation.angle_between(Quat::IDENTITY).to_degrees();
    assert!(drift < 0.001 && turned < 1.0, "the cube moved {drift} m, turned {turned}°");
}

#[test]
fn a_ball_on_a_gently_tilted_palm_rolls_away() {
    // A flat box would stay at 12° (μ_st 0.6); a 4 cm ball must roll: the
    // palm holds only planar faces as a rigid support.
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    let palm = palm_at(12.0);
    let centre = palm.to_world(Vec3::new(0.02, PALM_HALF.y + 0.02 - 0.001, 0.0));
    let mut desc = ObjectDesc::cuboid("ball", Vec3::splat(0.04), 0.05, centre)
        .with_material(Material::custom("rubber", 0.6, 0.5, 0.5));
    desc.shape = coulomb_hands::ShapeDesc::Sphere { radius: 0.02 };
    let id = world.add_object(&desc).unwrap();
    let hand = world.add_hand(Side::Right);
    let start = palm.to_local(position(&world, id));
    run(&mut world, hand, 0.6, |_| pose_with(palm), |_, _| {});
    let rolled = start.x - palm.to_local(position(&world, id)).x;
    assert!(rolled > 0.01, "the ball rolled only {:.1} mm down the palm", rolled * 1e3);
}
