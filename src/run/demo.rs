//! The headless demo: a scripted hand grasps, lifts, carries, turns and
//! lets go of a cube, and reports what the cube did.

use super::RunError;
use super::drive::{Driver, PoseFn, StepView};
use super::scenario::script::smoothstep;
use crate::contact::ContactEventKind;
use crate::friction::FrictionState;
use crate::hand::{Bone, Finger, HandId, HandPose, Palm, Side};
use crate::pipeline::{InteractionConfig, InteractionWorld, WorldError};
use crate::scene::{ObjectDesc, ObjectId, StaticDesc};
use glam::{Quat, Vec3};

/// A precision grasp from above: the thumb on the −x face of a cube, four
/// fingertips on the +x face, the palm above. `closure` 0 leaves a 2 cm gap
/// on each side; 1 sinks each distal pad `squeeze` metres into the faces.
/// The cube is centred at the origin with half size `h`.
pub fn claw_grasp(h: f32, closure: f32, squeeze: f32) -> HandPose {
    claw(h, closure, squeeze, 0.0)
}

/// [`claw_grasp`], whose fingertips also spread out as it opens: by
/// `spread` × 3 cm when fully open, the middle phalanx by a third of that,
/// so the fingers uncurl as a real hand's do. Fingers are 15 mm apart on a
/// 5 cm cube and closer on smaller ones, so each pad presses the face and
/// none its edge.
pub fn claw(h: f32, closure: f32, squeeze: f32, spread: f32) -> HandPose {
    let closure = closure.clamp(0.0, 1.0);
    let open = 1.0 - closure;
    let offset = |r: f32| h + r - squeeze * closure + 0.02 * open;
    let half_extents = Vec3::new(0.045, 0.01, 0.04);
    let center = Vec3::new(0.0, h + 0.025, 0.0);
    let palm = Palm::from_normal_direction(center, -Vec3::Y, Vec3::X, half_extents)
        .unwrap_or(Palm { center, rotation: Quat::IDENTITY, half_extents });
    let radii = [0.0095, 0.0085, 0.0085, 0.008, 0.007];
    let finger_z = [0.0, -0.0225, -0.0075, 0.0075, 0.0225].map(|z| z * (h / 0.025).min(1.0));
    let (flare, tip_flare) = (0.01 * open * spread, 0.03 * open * spread);
    let joints = std::array::from_fn(|f| {
        let x = offset(radii[f]);
        let z = finger_z[f];
        // The thumb (f = 0) mirrors the fingers onto the −x face.
        let s = if f == 0 { -1.0 } else { 1.0 };
        [
            Vec3::new(s * 0.035, h + 0.02, z),
            Vec3::new(s * (x + 0.02), h + 0.008, z),
            Vec3::new(s * (x + flare), h - 0.013, z),
            Vec3::new(s * (x + tip_flare), h - 0.035 + flare, z),
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
    /// Hand contacts at the end of the run, after release.
    pub contacts_after_release: usize,
    /// Of those, the ones of fingers other than the thumb that still
    /// press: none once the hand has let go. The thumb, which the turn
    /// put under the cube, may still carry it, as a real one would.
    pub fingers_after_release: usize,
    /// Maximum cube speed over the run (m/s).
    pub max_speed: f32,
    /// The printed rows, one per row interval.
    pub timeline: Vec<TimelineRow>,
}

/// One printed row of the demo.
#[derive(Debug, Clone, serde::Serialize)]
pub struct TimelineRow {
    /// Time (s).
    pub t: f32,
    /// The script's phase ([`GraspLiftCarry::phase`]).
    pub phase: &'static str,
    /// Palm centre (world, m).
    pub palm: [f32; 3],
    /// Cube position (world, m).
    pub cube: [f32; 3],
    /// Cube speed (m/s).
    pub cube_speed: f32,
    /// Hand contacts in the static state (inside the friction cone).
    pub contacts_static: usize,
    /// Hand contacts in the dynamic state (slipping).
    pub contacts_dynamic: usize,
    /// Hand contacts in the separated state (not pressing, no force).
    pub contacts_separated: usize,
    /// Magnitude of the hand contacts' total force on the cube (N).
    pub hand_force: f32,
    /// Contact-began events since the previous row.
    pub began: usize,
    /// Contact-ended events since the previous row.
    pub ended: usize,
}

/// The headless demo and acceptance scene: thumb plus four fingers grasp a
/// 5 cm, 50 g wooden cube, lift it 20 cm, turn the hand 90° and open.
pub struct GraspLiftCarry {
    /// The world: ground, cube and hand.
    pub world: InteractionWorld,
    /// The scripted right hand.
    pub hand: HandId,
    /// The cube.
    pub cube: ObjectId,
    /// Half size of the cube (m).
    pub half: f32,
}

impl GraspLiftCarry {
    /// Phase boundaries (s).
    pub const CLOSE: (f32, f32) = (0.5, 1.0);
    /// Start and end of the lift (s).
    pub const LIFT: (f32, f32) = (1.3, 2.3);
    /// Start and end of the turn (s).
    pub const TURN: (f32, f32) = (2.3, 3.3);
    /// Start and end of the hand opening (s).
    pub const OPEN: (f32, f32) = (3.8, 4.3);
    /// End of the run (s).
    pub const END: f32 = 5.0;
    /// How far the hand lifts (m) and turns (rad, about +z).
    pub const LIFT_HEIGHT: f32 = 0.2;
    /// How far the hand turns about world +z (rad).
    pub const TURN_ANGLE: f32 = std::f32::consts::FRAC_PI_2;
    /// How deep each distal pad sinks into the cube when closed (m).
    pub const SQUEEZE: f32 = 0.004;

    /// Builds the scene: a 5 cm, 50 g wooden cube at the origin resting on the
    /// ground (friction 0.5), and a right hand.
    pub fn new(config: InteractionConfig) -> Result<Self, WorldError> {
        let half = 0.025;
        let mut world = InteractionWorld::new(config)?;
        world.add_static(&StaticDesc::ground(-half, 0.5))?;
        let cube = world.add_object(&ObjectDesc::cuboid(
            "cube",
            Vec3::splat(2.0 * half),
            0.05,
            Vec3::ZERO,
        ))?;
        let hand = world.add_hand(Side::Right);
        Ok(GraspLiftCarry { world, hand, cube, half })
    }

    /// Name of the script's phase at `t` (s), e.g. `lift`.
    pub fn phase(t: f32) -> &'static str {
        match t {
            t if t < Self::CLOSE.0 => "approach",
            t if t < Self::CLOSE.1 => "close",
            t if t < Self::LIFT.0 => "settle",
            t if t < Self::LIFT.1 => "lift",
            t if t < Self::TURN.1 => "turn",
            t if t < Self::OPEN.0 => "hold",
            t if t < Self::OPEN.1 => "open",
            _ => "opened",
        }
    }

    /// The hand's rigid motion at `t`: rotation about the cube's start
    /// centre, then a translation.
    pub fn hand_motion(t: f32) -> (Quat, Vec3) {
        let lift = Self::LIFT_HEIGHT * smoothstep(Self::LIFT.0, Self::LIFT.1, t);
        let turn = Self::TURN_ANGLE * smoothstep(Self::TURN.0, Self::TURN.1, t);
        (Quat::from_rotation_z(turn), Vec3::new(0.0, lift, 0.0))
    }

    /// The scripted hand at `t` (s).
    pub fn hand_pose(&self, t: f32) -> HandPose {
        Self::pose_at(self.half, t)
    }

    /// The scripted hand at `t` (s) for a cube of half size `half` (m):
    /// the script without its world, for a driver that owns the world (the
    /// web page's).
    pub fn pose_at(half: f32, t: f32) -> HandPose {
        let close = smoothstep(Self::CLOSE.0, Self::CLOSE.1, t);
        let closure = close * (1.0 - smoothstep(Self::OPEN.0, Self::OPEN.1, t));
        let (rot, shift) = Self::hand_motion(t);
        claw_grasp(half, closure, Self::SQUEEZE).transformed(Vec3::ZERO, rot, shift)
    }

    /// The physics steps of `dt` (s) the whole script takes.
    pub fn steps(dt: f32) -> usize {
        (Self::END / dt).round() as usize
    }

    /// Runs the whole script; `every` is the timeline's row interval (s).
    pub fn run(mut self, every: f32) -> Result<GraspReport, RunError> {
        let dt = self.world.config().dt;
        let steps = Self::steps(dt);
        let row_every = ((every / dt).round() as usize).max(1);
        let open_step = (Self::OPEN.0 / dt).round() as usize;
        let mut watch = Watch::new(self.cube, self.hand, row_every, open_step);
        let half = self.half;
        let mut driver = Driver::new(&mut self.world);
        let script = PoseFn::new(Side::Right, move |t| Some(Self::pose_at(half, t as f32)));
        driver.drive(self.hand, script)?;
        driver.run(steps, &mut [&mut watch])?;
        let s = self.world.object_state(self.cube)?;
        Ok(GraspReport {
            max_drift: watch.max_drift,
            max_drift_deg: watch.max_drift_deg,
            held_height: watch.held_height,
            final_height: s.position.y,
            contacts_held: watch.contacts_held,
            contacts_after_release: self.world.contacts().len(),
            fingers_after_release: self
                .world
                .contacts()
                .iter()
                .filter(|c| c.normal_force > 0.0)
                .filter(|c| !matches!(c.bone, Bone::Finger(Finger::Thumb, _)))
                .count(),
            max_speed: watch.max_speed,
            timeline: watch.timeline,
        })
    }
}

/// What the demo follows after each step.
struct Watch {
    cube: ObjectId,
    hand: HandId,
    row_every: usize,
    open_step: usize,
    /// The cube's pose in the hand frame when the lift began.
    reference: Option<(Vec3, Quat)>,
    max_drift: f32,
    max_drift_deg: f32,
    max_speed: f32,
    held_height: f32,
    contacts_held: usize,
    /// Events since the last row.
    began: usize,
    ended: usize,
    timeline: Vec<TimelineRow>,
}

impl Watch {
    fn new(cube: ObjectId, hand: HandId, row_every: usize, open_step: usize) -> Watch {
        Watch {
            cube,
            hand,
            row_every,
            open_step,
            reference: None,
            max_drift: 0.0,
            max_drift_deg: 0.0,
            max_speed: 0.0,
            held_height: 0.0,
            contacts_held: 0,
            began: 0,
            ended: 0,
            timeline: Vec::new(),
        }
    }
}

impl super::drive::Observer for Watch {
    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        let world = step.world;
        let t = step.t as f32;
        let s = world.object_state(self.cube)?;
        self.max_speed = self.max_speed.max(s.linvel.length());
        for e in world.events() {
            match e.kind {
                ContactEventKind::Began => self.began += 1,
                ContactEventKind::Ended => self.ended += 1,
            }
        }
        // The cube's pose in the hand frame.
        let (rot, shift) = GraspLiftCarry::hand_motion(t);
        let rel_pos = rot.inverse() * (s.position - shift);
        let rel_rot = rot.inverse() * s.rotation;
        if t >= GraspLiftCarry::LIFT.0 && t < GraspLiftCarry::OPEN.0 {
            let (p0, q0) = *self.reference.get_or_insert((rel_pos, rel_rot));
            self.max_drift = self.max_drift.max((rel_pos - p0).length());
            self.max_drift_deg = self.max_drift_deg.max(q0.angle_between(rel_rot).to_degrees());
        }
        let done = step.index + 1;
        if done == self.open_step {
            self.held_height = s.position.y;
            self.contacts_held = world.contacts().len();
        }
        if done.is_multiple_of(self.row_every) {
            let count = |state| world.contacts().iter().filter(|c| c.state == state).count();
            let palm = world.hand_pose(self.hand).map_or(Vec3::ZERO, |p| p.palm.center);
            self.timeline.push(TimelineRow {
                t,
                phase: GraspLiftCarry::phase(t),
                palm: palm.to_array(),
                cube: s.position.to_array(),
                cube_speed: s.linvel.length(),
                contacts_static: count(FrictionState::Static),
                contacts_dynamic: count(FrictionState::Dynamic),
                contacts_separated: count(FrictionState::Separated),
                hand_force: s.hand_force.length(),
                began: std::mem::take(&mut self.began),
                ended: std::mem::take(&mut self.ended),
            });
        }
        Ok(())
    }
}
