//! Where a pinch stops holding as a host engine's step grows (the book's
//! "In your engine"): a 4 cm, 50 g box squeezed mid-air between two
//! fingertips pressed a fixed depth in, in host mode, its host a plain
//! semi-implicit Euler integrator (`run::euler_host`), held 2 s and then let
//! go. With the config's step-aware springs (backward Euler, the default)
//! and without them (softened).
//!
//! `cargo run --release --example host_steps`

use coulomb_hands::hand::rig::HandRig;
use coulomb_hands::run::drive::{Driver, PoseFn, StepView};
use coulomb_hands::run::euler_host::EulerHost;
use coulomb_hands::{
    Capsule, Finger, HandPose, HostBody, InteractionConfig, InteractionWorld, Material, ObjectDesc,
    ObjectId, Phalanx, Side,
};
use glam::{Quat, Vec3};

const HALF: f32 = 0.02;
const MASS: f32 = 0.05;
const RADIUS: f32 = 0.008;
const AT: Vec3 = Vec3::new(0.0, 0.5, 0.0);

/// How a run ended: the largest drop while held (m), whether it fell out,
/// and after the fingers open, whether it is free and how fast it drifts
/// sideways (m/s).
struct Outcome {
    sag: f32,
    dropped: bool,
    released: bool,
    drift: f32,
}

/// A hand parked far away but for its index fingertip, `depth` into the
/// box's `side` face (or 2 cm clear of it, open).
fn hand(side: Side, depth: f32) -> HandPose {
    let s = if side == Side::Left { -1.0 } else { 1.0 };
    let mut pose = HandRig::adult(side).pose(Vec3::new(s, 3.0, 0.0), Quat::IDENTITY, [0.0; 5]);
    let x = s * (HALF + RADIUS - depth);
    let (a, b) = (Vec3::new(x, AT.y, -0.012), Vec3::new(x, AT.y, 0.012));
    pose.fingers[Finger::Index as usize][Phalanx::Distal as usize] =
        Capsule { a, b, radius: RADIUS };
    pose
}

fn run(dt: f32, depth: f32, step_aware: bool) -> Outcome {
    let config = InteractionConfig { dt, step_aware, ..InteractionConfig::default() };
    let mut world = InteractionWorld::new(config).expect("a valid config");
    let material = Material::custom("skin 0.5", 0.5, 0.4, 0.5);
    let desc = ObjectDesc::cuboid("box", Vec3::splat(2.0 * HALF), MASS, AT).with_material(material);
    let id = world.add_object(&desc).expect("a valid box");
    let inertia = MASS * (2.0 * HALF) * (2.0 * HALF) / 6.0;
    let body = HostBody {
        position: AT,
        rotation: Quat::IDENTITY,
        linvel: Vec3::ZERO,
        angvel: Vec3::ZERO,
        mass: MASS,
        center_of_mass: Vec3::ZERO,
        principal_inertia: Vec3::splat(inertia),
        inertia_rotation: Quat::IDENTITY,
    };
    let hands = [world.add_hand(Side::Left), world.add_hand(Side::Right)];
    let host = EulerHost { bodies: vec![body], gravity: config.gravity, dt };
    let (hold, open) = (2.0, 0.5);
    let mut outcome = Outcome { sag: 0.0, dropped: false, released: false, drift: 0.0 };
    let mut watch = |step: &StepView| {
        let state = step.world.object_state(ObjectId(0)).expect("the box");
        if step.t <= hold {
            outcome.sag = outcome.sag.max(AT.y - state.position.y);
        } else {
            outcome.released = step.world.contacts_on(id).is_empty();
            outcome.drift = Vec3::new(state.linvel.x, 0.0, state.linvel.z).length();
        }
        Ok(())
    };
    let mut driver = Driver::new(&mut world);
    driver.set_host(Box::new(host)).expect("the host's states");
    for (hand_id, side) in hands.into_iter().zip([Side::Left, Side::Right]) {
        let pose = move |t: f64| Some(hand(side, if t < hold { depth } else { -0.02 }));
        driver.drive(hand_id, PoseFn::new(side, pose)).expect("the hand");
    }
    let steps = ((hold + open) / f64::from(dt)).round() as usize;
    driver.run(steps, &mut [&mut watch]).expect("the run");
    outcome.dropped = outcome.sag > 0.005;
    outcome
}

fn main() {
    let steps = [(1e-3, "1 ms"), (1.0 / 240.0, "1/240 s"), (1.0 / 120.0, "1/120 s")];
    let steps = steps.into_iter().chain([(1.0 / 90.0, "1/90 s"), (1.0 / 72.0, "1/72 s")]);
    let longer = [(1.0 / 60.0, "1/60 s"), (1.0 / 45.0, "1/45 s"), (1.0 / 30.0, "1/30 s")];
    let steps: Vec<(f32, &str)> = steps.chain(longer).chain([(0.05, "1/20 s")]).collect();
    let depths = [0.0015, 0.003, 0.005, 0.01];
    let threshold = MASS * 9.81 / (2.0 * 0.5 * 400.0);
    println!("threshold depth {:.2} mm (2 μ γ depth = m g)", threshold * 1e3);
    for step_aware in [true, false] {
        println!("\nstep_aware: {step_aware}");
        let header: Vec<String> = depths.iter().map(|d| format!("{:.1} mm", d * 1e3)).collect();
        println!("| step | {} | let go |", header.join(" | "));
        println!("|---|{}---|", "---|".repeat(depths.len()));
        for &(dt, name) in &steps {
            let mut cells = Vec::new();
            let mut release = String::new();
            for &depth in &depths {
                let o = run(dt, depth, step_aware);
                cells.push(if o.dropped {
                    "dropped".to_string()
                } else {
                    format!("held ({:.1} mm sag)", o.sag * 1e3)
                });
                if depth == 0.005 {
                    release = if o.released {
                        format!("free, {:.0} mm/s sideways", o.drift * 1e3)
                    } else {
                        "still touched".into()
                    };
                }
            }
            println!("| {name} | {} | {release} |", cells.join(" | "));
        }
    }
}
