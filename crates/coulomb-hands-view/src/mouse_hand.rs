//! A hand driven by mouse and keyboard, for use without a tracker: the
//! rig's adult right hand ([`HandRig::adult`]), posed each frame from the
//! keys held and pushed to the interaction as a
//! [`coulomb_hands_bevy::sources::PushedHand`]. It touches objects only
//! through the friction contacts, like a tracked hand.
//!
//! | input | does |
//! |---|---|
//! | W / S, A / D | palm away from / towards the camera, left / right |
//! | E / Q | palm up / down |
//! | right-drag | palm across the view (left-right, up-down) |
//! | Shift | slow (fine) motion |
//! | J / L, I / K, U / O | turn the palm: yaw, pitch, roll |
//! | G / H | curl / open all fingers |
//! | 1 … 5 (Shift+1 … 5) | curl (open) one finger, thumb first |
//! | T | oppose the thumb, or bring it back |

use bevy::input::mouse::AccumulatedMouseMotion;
use bevy::prelude::*;
use coulomb_hands::hand::rig::HandRig;
use coulomb_hands::hand::{HandSample, Side};
use coulomb_hands_bevy::convert;
use coulomb_hands_bevy::sources::HandInlet;

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

/// The mouse hand's state, and the inlet its poses go to (none when the
/// viewed input has its own hands).
#[derive(Resource, Debug, Clone)]
pub struct MouseHand {
    inlet: Option<HandInlet>,
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
            inlet: None,
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
    /// Drives the hand of `inlet` (a restarted interaction's), from the
    /// starting pose, which it pushes at once; `None` for an input with its
    /// own hands.
    pub fn attach(&mut self, inlet: Option<HandInlet>) {
        *self = MouseHand { inlet, ..MouseHand::default() };
        if let Some(inlet) = &self.inlet {
            inlet.push(Some(self.sample()));
        }
    }

    /// Whether there is a hand to drive.
    pub fn active(&self) -> bool {
        self.inlet.is_some()
    }

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

/// Moves, turns and curls the hand from the keys and mouse held this frame,
/// and pushes its pose. Motion is relative to the camera's heading when
/// there is a camera. Rates are per second of simulated time (Bevy's
/// virtual clock, which the playback speed scales), and the hand holds
/// still while the playback is paused, so it never outruns the physics.
pub fn drive_mouse_hand(
    mut hand: ResMut<MouseHand>,
    keys: Res<ButtonInput<KeyCode>>,
    buttons: Option<Res<ButtonInput<MouseButton>>>,
    motion: Option<Res<AccumulatedMouseMotion>>,
    cameras: Query<&GlobalTransform, With<Camera3d>>,
    time: Res<Time<Virtual>>,
    transport: Option<Res<crate::transport::Transport>>,
) {
    if !hand.active() || transport.is_some_and(|t| t.paused) {
        return;
    }
    let dt = time.delta_secs();
    let held = |k: KeyCode| if keys.pressed(k) { 1.0 } else { 0.0 };
    let axis = |plus: KeyCode, minus: KeyCode| held(plus) - held(minus);
    let fine = keys.any_pressed([KeyCode::ShiftLeft, KeyCode::ShiftRight]);
    let (forward, right) = heading(cameras.iter().next());
    let speed = if fine { FINE_SPEED } else { SPEED };
    let along = axis(KeyCode::KeyW, KeyCode::KeyS) * forward
        + axis(KeyCode::KeyD, KeyCode::KeyA) * right
        + axis(KeyCode::KeyE, KeyCode::KeyQ) * Vec3::Y;
    hand.palm += along * speed * dt;
    let dragging = buttons.is_some_and(|b| b.pressed(MouseButton::Right));
    if let (true, Some(motion)) = (dragging, motion) {
        let scale = if fine { DRAG * FINE_SPEED / SPEED } else { DRAG };
        hand.palm += (motion.delta.x * right - motion.delta.y * Vec3::Y) * scale;
    }
    let turn = Vec3::new(
        axis(KeyCode::KeyJ, KeyCode::KeyL),
        axis(KeyCode::KeyI, KeyCode::KeyK),
        axis(KeyCode::KeyO, KeyCode::KeyU),
    );
    hand.turn += turn * TURN * dt;
    let all = axis(KeyCode::KeyG, KeyCode::KeyH);
    let digits = [KeyCode::Digit1, KeyCode::Digit2, KeyCode::Digit3, KeyCode::Digit4];
    let digits = [digits[0], digits[1], digits[2], digits[3], KeyCode::Digit5];
    for (f, digit) in digits.into_iter().enumerate() {
        let own = if keys.pressed(digit) { if fine { -1.0 } else { 1.0 } } else { 0.0 };
        hand.curl[f] = (hand.curl[f] + (all + own) * CURL_RATE * dt).clamp(0.0, 1.0);
    }
    if keys.just_pressed(KeyCode::KeyT) {
        hand.opposing = !hand.opposing;
    }
    let target = if hand.opposing { 1.0 } else { 0.0 };
    let step = OPPOSE_RATE * dt;
    hand.opposition += (target - hand.opposition).clamp(-step, step);
    let sample = hand.sample();
    if let Some(inlet) = &hand.inlet {
        inlet.push(Some(sample));
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
