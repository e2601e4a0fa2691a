//! Hands the app poses itself: an entity with [`AppHand`], whose
//! [`HandInput`] the app's systems write each frame (from an XR runtime's
//! hand joints, a tracker read by another plugin, mouse and keyboard).
//!
//! The plugin adds a hand to the world for each such entity, and again to
//! any [`HandPhysics`] that replaces the world, so the entity outlives
//! worlds. The app writes at its frame or tracker rate, the physics steps
//! at its own: each write is due at the last of the frame's steps, and
//! the frame's steps take the hand there in a straight line from where
//! it was, by the core's one rule for such hands
//! ([`coulomb_hands::run::sampled`]), rather than holding it still and
//! jumping. Despawning the entity leaves its hand untracked (its contacts
//! end).
//!
//! Any other core [`HandSource`](coulomb_hands::run::drive::HandSource)
//! (a scenario's hand, a recording's track, the live Leap stream's
//! [`coulomb_hands::run::live::LiveFeed`] hands, which never block a
//! frame) is added with [`HandPhysics::add_hand`].

use crate::clock::HandClock;
use crate::physics::HandPhysics;
use crate::reflect::SideReflect;
use bevy::prelude::*;
use coulomb_hands::hand::{HandPose, HandSample, Side};
pub use coulomb_hands::input::layouts::JointsError;
use coulomb_hands::input::layouts::{Joint, Layout, hand_pose_from_joints, openxr};
use coulomb_hands::run::sampled::SampledHand;

/// A hand whose poses the app's own systems write into its
/// [`HandInput`]. Spawn it, and the plugin makes it an
/// [`crate::entities::InteractionHand`] of the world, with its 16 bones as
/// child entities.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Component, Debug, PartialEq)]
#[require(HandInput, Transform)]
pub struct AppHand {
    /// Which hand.
    #[reflect(remote = SideReflect)]
    pub side: Side,
}

impl AppHand {
    /// A `side` hand, untracked until its input gets a pose.
    pub fn new(side: Side) -> AppHand {
        AppHand { side }
    }
}

/// What the app's tracker says of an [`AppHand`] now.
#[derive(Component, Reflect, Debug, Clone, Default)]
#[reflect(Component, Default)]
pub struct HandInput {
    /// The pose for the next physics steps, or `None` while the hand is
    /// not tracked.
    #[reflect(ignore)]
    sample: Option<HandSample>,
}

impl HandInput {
    /// Poses the hand by the 16 bones of the core's model.
    pub fn set_pose(&mut self, pose: HandPose) {
        self.sample = Some(HandSample::from_pose(pose));
    }

    /// Poses the hand by a tracker's sample (a pose with grab and pinch
    /// strengths), or loses it for `None` (its contacts end).
    pub fn set(&mut self, sample: Option<HandSample>) {
        self.sample = sample;
    }

    /// Poses the hand by the 26 joints of OpenXR's `XR_EXT_hand_tracking`
    /// (in `XrHandJointEXT` order; world, m, y up). Joints that make no
    /// valid hand leave it lost, and say why.
    pub fn set_openxr(
        &mut self,
        side: Side,
        joints: &[Joint; openxr::COUNT],
    ) -> Result<(), JointsError> {
        let sample = openxr_sample(side, joints);
        self.sample = sample.as_ref().ok().cloned();
        sample.map(|_| ())
    }

    /// The pose the physics reads, if the hand is tracked.
    pub fn sample(&self) -> Option<&HandSample> {
        self.sample.as_ref()
    }
}

/// The hand of one frame's OpenXR joints (world, m, y up), as the core's
/// OpenXR layout reads them.
pub fn openxr_sample(
    side: Side,
    joints: &[Joint; openxr::COUNT],
) -> Result<HandSample, JointsError> {
    let positions = joints.map(|j| j.position);
    let (radii, orientations) = (joints.map(|j| j.radius), joints.map(|j| j.orientation));
    let id = u32::from(side == Side::Right);
    let given = (Some(&radii[..]), Some(&orientations[..]));
    let pose = hand_pose_from_joints(Layout::OpenXr, id, side, &positions, given.0, given.1)?;
    Ok(HandSample::from_pose(pose))
}

/// An [`AppHand`]'s place in the current world: its source, whose clone
/// the world steps. Its drop (the entity despawned, or the world replaced)
/// leaves the hand untracked.
#[derive(Component, Debug)]
pub(crate) struct AppHandLink {
    /// The [`HandPhysics::serial`] of the world it is in.
    pub serial: u64,
    hand: SampledHand,
}

impl Drop for AppHandLink {
    fn drop(&mut self) {
        // A due time is finite: this cannot fail.
        let _ = self.hand.set(0.0, None);
    }
}

/// Adds `hand` to `physics`' world, and links it.
pub(crate) fn attach(
    physics: &mut HandPhysics,
    hand: AppHand,
) -> (coulomb_hands::hand::HandId, AppHandLink) {
    let source = SampledHand::new(hand.side);
    let id = physics.add_hand(source.clone());
    (id, AppHandLink { serial: physics.serial(), hand: source })
}

/// An app hand whose input changed, or which was just linked to a world.
type NewInput = Or<(Changed<HandInput>, Added<AppHandLink>)>;

/// Hands each app hand's newest input to its world's source, due at the
/// last of the steps this frame runs ([`HandClock::steps_in`], as
/// [`crate::clock::run_steps`] counts them).
pub(crate) fn push_inputs(
    hands: Query<(&HandInput, &AppHandLink), NewInput>,
    physics: Option<Res<HandPhysics>>,
    clock: Res<Time<HandClock>>,
    time: Res<Time>,
) {
    let Some(physics) = physics else { return };
    let dt = physics.timestep();
    let steps = clock.context().steps_in(time.delta(), dt);
    let last = steps.saturating_sub(1) as f64 * dt.as_secs_f64();
    let due = physics.world().time() + last;
    for (input, link) in &hands {
        // The world's time and a frame's delta are finite.
        let _ = link.hand.set(due, input.sample.clone());
    }
}
