//! Scripted scenes shared by the demo, the tests and the benchmarks.

use crate::hand::{Bone, BoneShape, Capsule, HandPose, Palm, Side};
use crate::object::{ObjectDesc, ObjectId, StaticDesc};
use crate::pipeline::{HandId, InteractionConfig, InteractionWorld, WorldError};
use crate::FrictionState;
use glam::{Quat, Vec3};

/// Smooth 0→1 ramp of `t` over `[t0, t1]` (zero slope at both ends).
pub fn smoothstep(t0: f32, t1: f32, t: f32) -> f32 {
    let x = ((t - t0) / (t1 - t0)).clamp(0.0, 1.0);
    x * x * (3.0 - 2.0 * x)
}

/// A precision grasp from above: the thumb on the −x face of a cube, four
/// fingertips on the +x face, the palm above. `closure` 0 leaves a 2 cm gap
/// on each side; 1 sinks each distal pad `squeeze` metres into the faces.
/// The cube is centred at the origin with half size `h`.
pub fn claw_grasp(h: f32, closure: f32, squeeze: f32) -> HandPose {
    let gap = 0.02;
    let offset = |r: f32| h + r - squeeze * closure + gap * (1.0 - closure);
    let palm = Palm::from_normal_direction(
        Vec3::new(0.0, h + 0.025, 0.0),
        -Vec3::Y,
        Vec3::X,
        Vec3::new(0.045, 0.01, 0.04),
    )
    .unwrap_or(Palm { center: Vec3::new(0.0, h + 0.025, 0.0), rotation: Quat::IDENTITY, half_extents: Vec3::new(0.045, 0.01, 0.04) });
    let radii = [0.0095, 0.0085, 0.0085, 0.008, 0.007];
    let finger_z = [0.0, -0.0225, -0.0075, 0.0075, 0.0225];
    let joints = std::array::from_fn(|f| {
        let r = radii[f];
        let z = finger_z[f];
        let x = offset(r);
        // The thumb (f = 0) mirrors the fingers onto the −x face.
        let s = if f == 0 { -1.0 } else { 1.0 };
        [
            Vec3::new(s * 0.035, h + 0.02, z),
            Vec3::new(s * (x + 0.02), h + 0.008, z),
            Vec3::new(s * x, h - 0.013, z),
            Vec3::new(s * x, h - 0.035, z),
        ]
    });
    HandPose::from_joints(palm, joints, radii)
}

/// Result of [`GraspLiftCarry::run`].
#[derive(Debug, Clone, serde::Serialize)]
pub struct GraspReport {
    /// Largest drift of the cube's position in the hand frame between the
    /// closed grasp and the end of the carry (m).
    pub max_drift: f32,
    /// Largest drift of its orientation in the hand frame (degrees).
    pub max_drift_deg: f32,
    /// Cube height when the hand starts to open (m).
    pub held_height: f32,
    /// Cube height at the end, after the hand opened (m).
    pub final_height: f32,
    /// Hand contacts when the carry ended and after release.
    pub contacts_held: usize,
    pub contacts_after_release: usize,
    /// Maximum cube speed over the run (m/s).
    pub max_speed: f32,
    pub timeline: Vec<TimelineRow>,
}

/// One printed row of the demo.
#[derive(Debug, Clone, serde::Serialize)]
pub struct TimelineRow {
    pub t: f32,
    pub phase: &'static str,
    pub palm: [f32; 3],
    pub cube: [f32; 3],
    pub cube_speed: f32,
    pub contacts_static: usize,
    pub contacts_dynamic: usize,
    pub contacts_separated: usize,
    pub hand_force: f32,
    pub began: usize,
    pub ended: usize,
}

/// The headless demo and acceptance scene: thumb plus four fingers grasp a
/// 5 cm, 50 g wooden cube, lift it 20 cm, turn the hand 90° and open.
pub struct GraspLiftCarry {
    pub world: InteractionWorld,
    pub hand: HandId,
    pub cube: ObjectId,
    /// Half size of the cube (m).
    pub half: f32,
}

impl GraspLiftCarry {
    /// Phase boundaries (s).
    pub const CLOSE: (f32, f32) = (0.5, 1.0);
    pub const LIFT: (f32, f32) = (1.3, 2.3);
    pub const TURN: (f32, f32) = (2.3, 3.3);
    pub const OPEN: (f32, f32) = (3.8, 4.3);
    pub const END: f32 = 5.0;
    /// How far the hand lifts (m) and turns (rad, about +z).
    pub const LIFT_HEIGHT: f32 = 0.2;
    pub const TURN_ANGLE: f32 = std::f32::consts::FRAC_PI_2;
    /// How deep each distal pad sinks into the cube when closed (m).
    pub const SQUEEZE: f32 = 0.004;

    pub fn new(config: InteractionConfig) -> Result<Self, WorldError> {
        let half = 0.025;
        let mut world = InteractionWorld::new(config)?;
        world.add_static(&StaticDesc::ground(-half, 0.5))?;
        let cube = world.add_object(&ObjectDesc::cuboid("cube", Vec3::splat(2.0 * half), 0.05, Vec3::ZERO))?;
        let hand = world.add_hand(Side::Right);
        Ok(GraspLiftCarry { world, hand, cube, half })
    }

    pub fn phase(t: f32) -> &'static str {
        match t {
            t if t < Self::CLOSE.0 => "approach",
            t if t < Self::CLOSE.1 => "close",
            t if t < Self::LIFT.0 => "settle",
            t if t < Self::LIFT.1 => "lift",
            t if t < Self::TURN.1 => "turn",
            t if t < Self::OPEN.0 => "hold",
            t if t < Self::OPEN.1 => "open",
            _ => "fall",
        }
    }

    /// The hand's rigid motion at `t`: rotation about the cube's start
    /// centre, then a translation.
    pub fn hand_motion(t: f32) -> (Quat, Vec3) {
        let lift = Self::LIFT_HEIGHT * smoothstep(Self::LIFT.0, Self::LIFT.1, t);
        let turn = Self::TURN_ANGLE * smoothstep(Self::TURN.0, Self::TURN.1, t);
        (Quat::from_rotation_z(turn), Vec3::new(0.0, lift, 0.0))
    }

    pub fn hand_pose(&self, t: f32) -> HandPose {
        let closure = smoothstep(Self::CLOSE.0, Self::CLOSE.1, t) * (1.0 - smoothstep(Self::OPEN.0, Self::OPEN.1, t));
        let (rot, shift) = Self::hand_motion(t);
        claw_grasp(self.half, closure, Self::SQUEEZE).transformed(Vec3::ZERO, rot, shift)
    }

    /// Runs the whole script; `every` is the timeline's row interval (s).
    pub fn run(mut self, every: f32) -> Result<GraspReport, WorldError> {
        let dt = self.world.config().dt;
        let steps = (Self::END / dt).round() as usize;
        let row_every = ((every / dt).round() as usize).max(1);
        let mut reference: Option<(Vec3, Quat)> = None;
        let (mut max_drift, mut max_drift_deg, mut max_speed) = (0.0f32, 0.0f32, 0.0f32);
        let (mut held_height, mut contacts_held) = (0.0, 0);
        let (mut began, mut ended) = (0, 0);
        let mut timeline = Vec::new();
        for i in 0..steps {
            let t = i as f32 * dt;
            self.world.set_hand_pose(self.hand, &self.hand_pose(t))?;
            self.world.step();
            let t = (i + 1) as f32 * dt;
            let s = self.world.object_state(self.cube)?;
            max_speed = max_speed.max(s.linvel.length());
            for e in self.world.events() {
                match e.kind {
                    crate::ContactEventKind::Began => began += 1,
                    crate::ContactEventKind::Ended => ended += 1,
                }
            }
            // The cube's pose in the hand frame.
            let (rot, shift) = Self::hand_motion(t);
            let rel_pos = rot.inverse() * (s.position - shift);
            let rel_rot = rot.inverse() * s.rotation;
            if t >= Self::LIFT.0 && t < Self::OPEN.0 {
                let (p0, q0) = *reference.get_or_insert((rel_pos, rel_rot));
                max_drift = max_drift.max((rel_pos - p0).length());
                max_drift_deg = max_drift_deg.max(q0.angle_between(rel_rot).to_degrees());
            }
            if (i + 1) == (Self::OPEN.0 / dt).round() as usize {
                held_height = s.position.y;
                contacts_held = self.world.contacts().len();
            }
            if (i + 1) % row_every == 0 {
                let count = |state| self.world.contacts().iter().filter(|c| c.state == state).count();
                let palm = self.world.hand_pose(self.hand).map_or(Vec3::ZERO, |p| p.palm.center);
                timeline.push(TimelineRow {
                    t,
                    phase: Self::phase(t),
                    palm: palm.to_array(),
                    cube: s.position.to_array(),
                    cube_speed: s.linvel.length(),
                    contacts_static: count(FrictionState::Static),
                    contacts_dynamic: count(FrictionState::Dynamic),
                    contacts_separated: count(FrictionState::Separated),
                    hand_force: s.hand_force.length(),
                    began: std::mem::take(&mut began),
                    ended: std::mem::take(&mut ended),
                });
            }
        }
        let s = self.world.object_state(self.cube)?;
        Ok(GraspReport {
            max_drift,
            max_drift_deg,
            held_height,
            final_height: s.position.y,
            contacts_held,
            contacts_after_release: self.world.contacts().len(),
            max_speed,
            timeline,
        })
    }
}

/// The benchmark scene of the issue tracker: optional ground and 54-block
/// wooden tower, and `boxes` (≤ 16) 3 cm, 20 g boxes held mid-air, box k
/// squeezed between bone k of the left hand and bone k of the right hand.
/// Bone 0 is the palm box; the others are capsules of radius 8 mm.
/// Returns the world and both hands' poses (already set).
pub fn held_boxes_scene(
    config: InteractionConfig,
    boxes: usize,
    tower: bool,
) -> Result<(InteractionWorld, [HandId; 2]), WorldError> {
    let boxes = boxes.min(crate::hand::BONES_PER_HAND);
    let mut world = InteractionWorld::new(config)?;
    world.add_static(&StaticDesc::ground(0.0, 0.5))?;
    if tower {
        add_tower(&mut world, Vec3::new(-0.4, 0.0, 0.0))?;
    }
    let half = 0.015;
    let squeeze = 0.002;
    let radius = 0.008;
    let centre = |k: usize| Vec3::new(0.2 + 0.08 * (k % 4) as f32, 0.3 + 0.08 * (k / 4) as f32, 0.0);
    for k in 0..boxes {
        world.add_object(&ObjectDesc::cuboid(&format!("box{k}"), Vec3::splat(2.0 * half), 0.02, centre(k)))?;
    }
    let mut hands = [HandId(0); 2];
    for (i, side) in [Side::Left, Side::Right].into_iter().enumerate() {
        let s = if i == 0 { -1.0 } else { 1.0 };
        let mut pose = crate::hand::rig::HandRig::adult(side).pose(Vec3::ZERO, Quat::IDENTITY, [0.0; 5]);
        for bone in Bone::all() {
            let k = bone.index();
            // Unused bones wait 2 m away from everything, spread apart.
            let c = if k < boxes { centre(k) } else { Vec3::new(3.0 + 0.1 * k as f32, 2.0, s) };
            match pose.bone(bone) {
                BoneShape::Palm(_) => {
                    pose.palm = Palm::from_normal_direction(
                        c + Vec3::X * s * (half + 0.01 - squeeze),
                        -Vec3::X * s,
                        Vec3::Y,
                        Vec3::new(0.04, 0.01, 0.045),
                    )
                    .unwrap_or(pose.palm);
                }
                BoneShape::Capsule(_) => {
                    let x = c.x + s * (half + radius - squeeze);
                    let cap = Capsule {
                        a: Vec3::new(x, c.y - 0.015, c.z),
                        b: Vec3::new(x, c.y + 0.015, c.z),
                        radius,
                    };
                    if let Bone::Finger(f, p) = bone {
                        pose.fingers[f as usize][p as usize] = cap;
                    }
                }
            }
        }
        hands[i] = world.add_hand(side);
        world.set_hand_pose(hands[i], &pose)?;
    }
    Ok((world, hands))
}

/// Levels and blocks per level of [`add_tower`].
pub const TOWER_LEVELS: usize = 18;
pub const TOWER_SLOTS: usize = 3;

/// The name [`add_tower`] gives the block in `slot` (0..3) of `level` (0..18).
pub fn tower_block_name(level: usize, slot: usize) -> String {
    format!("block{level}-{slot}")
}

/// A tower of 18 levels × 3 wooden blocks of 7.5 × 2.5 × 1.5 cm, alternate
/// levels turned 90°, standing on y = 0 at `base`.
pub fn add_tower(world: &mut InteractionWorld, base: Vec3) -> Result<Vec<ObjectId>, WorldError> {
    let (long, wide, tall) = (0.075, 0.025, 0.015);
    let mass = 600.0 * long * wide * tall; // wood, 600 kg/m³
    let mut ids = Vec::with_capacity(TOWER_LEVELS * TOWER_SLOTS);
    for level in 0..TOWER_LEVELS {
        for slot in 0..TOWER_SLOTS {
            let across = (slot as f32 - 1.0) * wide;
            let y = tall * (level as f32 + 0.5);
            let (offset, size) = if level % 2 == 0 {
                (Vec3::new(across, y, 0.0), Vec3::new(wide, tall, long))
            } else {
                (Vec3::new(0.0, y, across), Vec3::new(long, tall, wide))
            };
            ids.push(world.add_object(&ObjectDesc::cuboid(&tower_block_name(level, slot), size, mass, base + offset))?);
        }
    }
    Ok(ids)
}
