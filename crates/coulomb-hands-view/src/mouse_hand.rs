//! A hand driven by mouse and keyboard, for use without a tracker: the
//! rig's adult right hand ([`HandRig::adult`]), posed each frame from the
//! keys held ([`crate::keys`]) and written to the input of its app hand
//! (an entity with [`AppHand`] and [`HandDriver::Mouse`]). It touches
//! objects only through the friction contacts, like a tracked hand. A new
//! world (a restart, a seek back) starts it at its start pose again.

use crate::hud::{HudLines, HudSection};
use crate::keys::{self, Group};
use crate::sets::ViewerSystems;
use crate::source::HandDriver;
use crate::transport::Transport;
use bevy::input::mouse::AccumulatedMouseMotion;
use bevy::prelude::*;
use coulomb_hands::hand::rig::HandRig;
use coulomb_hands::hand::{HandSample, Side};
use coulomb_hands_bevy::convert;
use coulomb_hands_bevy::prelude::*;

/// Palm speed with the keys (m/s).
pub const SPEED: f32 = 0.12;
/// Palm speed with Shift held (m/s).
pub const FINE_SPEED: f32 = 0.03;
/// Palm travel per pixel of right-drag (m).
pub const DRAG: f32 = 0.0006;
/// Turning rate (rad/s).
pub const TURN: f32 = std::f32::consts::FRAC_PI_3;
/// Curling rate (fraction of a full curl per s).
pub const CURL_RATE: f32 = 0.6;
/// Thumb opposition rate (per s).
pub const OPPOSE_RATE: f32 = 3.0;

/// Where the hand starts: above and behind the scene's centre, palm down,
/// fingers away from the default camera, slightly curled.
pub const START_PALM: Vec3 = Vec3::new(0.0, 0.15, -0.2);

/// The mouse hand's state.
#[derive(Resource, Debug, Clone)]
pub struct MouseHand {
    /// Palm centre (world, m).
    pub palm: Vec3,
    /// Palm orientation: yaw, pitch, roll (rad) after palm-down.
    pub turn: Vec3,
    /// Curl of each finger, thumb first, 0 straight to 1 a fist.
    pub curl: [f32; 5],
    /// Thumb opposition now, 0 to 1.
    pub opposition: f32,
    /// Whether the thumb is moving to opposed.
    pub opposing: bool,
    rig: HandRig,
}

impl Default for MouseHand {
    fn default() -> Self {
        MouseHand {
            palm: START_PALM,
            turn: Vec3::ZERO,
            curl: [0.1; 5],
            opposition: 0.0,
            opposing: false,
            rig: HandRig::adult(Side::Right),
        }
    }
}

impl MouseHand {
    /// Palm orientation: palm down (normal −y), fingers +z, then turned.
    pub fn rotation(&self) -> Quat {
        let down = Quat::from_rotation_z(std::f32::consts::PI);
        Quat::from_euler(EulerRot::YXZ, self.turn.x, self.turn.y, self.turn.z) * down
    }

    /// The hand's pose now.
    pub fn sample(&self) -> HandSample {
        let palm = convert::to_core_vec3(self.palm);
        let rotation = convert::to_core_quat(self.rotation());
        HandSample::from_pose(self.rig.pose_opposed(palm, rotation, self.curl, self.opposition))
    }
}

/// What a person drives the hand with: the keys, and the mouse if there is one.
#[derive(bevy::ecs::system::SystemParam)]
pub struct Controls<'w> {
    keys: Res<'w, ButtonInput<KeyCode>>,
    buttons: Option<Res<'w, ButtonInput<MouseButton>>>,
    motion: Option<Res<'w, AccumulatedMouseMotion>>,
}

/// Moves, turns and curls the hand from the keys and mouse held this frame,
/// and writes its pose. Motion is relative to the camera's heading when
/// there is a camera. Rates are per second of simulated time (Bevy's
/// virtual clock, which the playback speed scales), and the hand holds
/// still while the playback is paused, so it never outruns the physics.
pub fn drive_mouse_hand(
    mut hand: ResMut<MouseHand>,
    mut inputs: Query<(&HandDriver, &mut HandInput), With<AppHand>>,
    controls: Controls,
    cameras: Query<&GlobalTransform, With<Camera3d>>,
    time: Res<Time<Virtual>>,
    transport: Option<Res<Transport>>,
) {
    let Some(mut input) = inputs.iter_mut().find(|(d, _)| **d == HandDriver::Mouse).map(|x| x.1)
    else {
        return;
    };
    if transport.is_some_and(|t| t.paused) {
        return;
    }
    let Controls { keys: held, buttons, motion } = controls;
    let dt = time.delta_secs();
    let fine = keys::FINE.held(&held);
    let (forward, right) = heading(cameras.iter().next());
    let speed = if fine { FINE_SPEED } else { SPEED };
    let along = keys::AWAY.axis(&held) * forward
        + keys::SIDEWAYS.axis(&held) * right
        + keys::UP.axis(&held) * Vec3::Y;
    hand.palm += along * speed * dt;
    let dragging = buttons.is_some_and(|b| b.pressed(MouseButton::Right));
    if let (true, Some(motion)) = (dragging, motion) {
        let scale = if fine { DRAG * FINE_SPEED / SPEED } else { DRAG };
        hand.palm += (motion.delta.x * right - motion.delta.y * Vec3::Y) * scale;
    }
    let turn = Vec3::new(keys::YAW.axis(&held), keys::PITCH.axis(&held), keys::ROLL.axis(&held));
    hand.turn += turn * TURN * dt;
    let all = keys::CURL.axis(&held);
    for (f, digit) in keys::FINGER.keys.iter().enumerate() {
        let own = if held.pressed(*digit) { if fine { -1.0 } else { 1.0 } } else { 0.0 };
        hand.curl[f] = (hand.curl[f] + (all + own) * CURL_RATE * dt).clamp(0.0, 1.0);
    }
    if keys::THUMB.just_pressed(&held) {
        hand.opposing = !hand.opposing;
    }
    let target = if hand.opposing { 1.0 } else { 0.0 };
    let step = OPPOSE_RATE * dt;
    hand.opposition += (target - hand.opposition).clamp(-step, step);
    input.set(Some(hand.sample()));
}

/// A new world starts the hand over at its start pose, written at once.
pub fn restart_mouse_hand(
    mut replaced: MessageReader<HandPhysicsReplaced>,
    mut hand: ResMut<MouseHand>,
    mut inputs: Query<(&HandDriver, &mut HandInput), With<AppHand>>,
) {
    if replaced.read().last().is_none() {
        return;
    }
    *hand = MouseHand::default();
    for (_, mut input) in inputs.iter_mut().filter(|(d, _)| **d == HandDriver::Mouse) {
        input.set(Some(hand.sample()));
    }
}

/// The HUD's lines: the hand's keys, when there is a mouse hand.
fn hud_lines(drivers: Query<&HandDriver, With<AppHand>>, mut hud: ResMut<HudLines>) {
    let lines = match drivers.iter().any(|d| *d == HandDriver::Mouse) {
        true => vec![
            format!("hand: {}", keys::hud_line(Group::Hand, false)),
            format!("      {}", keys::hud_line(Group::Fingers, false)),
        ],
        false => Vec::new(),
    };
    hud.set(HudSection::MouseHand, lines);
}

/// The mouse hand's systems (it expects the plugin added).
#[derive(Debug, Clone, Copy, Default)]
pub struct MouseHandPlugin;

impl Plugin for MouseHandPlugin {
    fn build(&self, app: &mut App) {
        crate::sets::configure(app);
        app.init_resource::<MouseHand>()
            .init_resource::<HudLines>()
            .add_systems(
                Update,
                (restart_mouse_hand, drive_mouse_hand).chain().in_set(ViewerSystems::Drive),
            )
            .add_systems(Update, hud_lines.in_set(ViewerSystems::HudLines));
    }
}

/// The camera's horizontal forward and right directions (world), or the
/// world's +z and −x without a camera (the default camera's view).
fn heading(camera: Option<&GlobalTransform>) -> (Vec3, Vec3) {
    let forward = camera
        .map(|c| c.forward().as_vec3().with_y(0.0))
        .and_then(|f| f.try_normalize())
        .unwrap_or(Vec3::Z);
    (forward, forward.cross(Vec3::Y))
}
