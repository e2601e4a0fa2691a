//! Live hands from an XR runtime's hand tracking (`XR_EXT_hand_tracking`).
//!
//! Each frame, bevy_mod_xr's hand trackers hold the 26 joints the runtime
//! located (bevy_mod_openxr fills them, with the `openxr` feature: see
//! `crate::openxr`). Here they become a tracked hand by the core's
//! OpenXR layout ([`layouts::from_openxr`]), then the skeletal hand
//! ([`hand_pose`]), pushed to a [`coulomb_hands_bevy::sources::PushedHand`]
//! of the interaction. The hand then touches objects only through the
//! friction contacts, like any tracked hand.
//!
//! A hand with an untracked joint, or one the layout or the pose check
//! refuses, is pushed as lost: its contacts end, as in a tracker dropout.
//!
//! This module needs no XR runtime: it reads bevy_mod_xr's components,
//! whoever wrote them, so its tests drive it with joints of their own.

use bevy::prelude::*;
use bevy_mod_xr::hands::{HAND_JOINT_COUNT, HandSide, XrHandBoneEntities, XrHandBoneRadius};
use bevy_mod_xr::session::XrTrackingRoot;
use bevy_mod_xr::spaces::{XrSpaceLocationFlags, XrSpaceSyncSet};
use coulomb_hands::hand::{HandSample, Side};
use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::layouts::{self, Joint, openxr};
use coulomb_hands::input::skeleton::hand_pose;
use coulomb_hands_bevy::convert::{to_core_quat, to_core_vec3};
use coulomb_hands_bevy::sources::HandInlet;

// bevy_mod_xr's bone order is XrHandJointEXT's, as the core's layout expects.
const _: () = assert!(HAND_JOINT_COUNT == openxr::COUNT);

/// How far the scene's origin may be put from the room's (m).
pub const MAX_ORIGIN: f32 = 10.0;

/// Where the scene's origin sits in the room: a point of the runtime's
/// reference space (m; y up, the floor at 0 in a stage space). The default
/// puts it at a table's height (0.8 m), 35 cm ahead of where the wearer
/// stood at start (−z), so a scene's ground is a table top at hand.
#[derive(Resource, Debug, Clone, Copy, PartialEq)]
pub struct RoomPlacement {
    /// The scene's origin in the room (m).
    pub origin: Vec3,
}

impl Default for RoomPlacement {
    fn default() -> Self {
        RoomPlacement { origin: Vec3::new(0.0, 0.8, -0.35) }
    }
}

impl std::str::FromStr for RoomPlacement {
    type Err = String;
    /// `X,Y,Z` in metres, each within ±[`MAX_ORIGIN`].
    fn from_str(s: &str) -> Result<RoomPlacement, String> {
        let parts: Vec<&str> = s.split(',').map(str::trim).collect();
        let bad = || format!("expected X,Y,Z in metres within ±{MAX_ORIGIN}, got {s:?}");
        let [x, y, z] = parts[..] else { return Err(bad()) };
        let mut origin = [0.0f32; 3];
        for (v, part) in origin.iter_mut().zip([x, y, z]) {
            *v = part.parse().map_err(|_| bad())?;
            if !(v.is_finite() && v.abs() <= MAX_ORIGIN) {
                return Err(bad());
            }
        }
        Ok(RoomPlacement { origin: Vec3::from_array(origin) })
    }
}

/// The tracking root's transform: it carries the runtime's space (the
/// headset's cameras and the hand joints) so that the room's `origin` is
/// the scene's.
pub fn place_room(
    placement: Res<RoomPlacement>,
    mut roots: Query<&mut Transform, With<XrTrackingRoot>>,
) {
    for mut root in &mut roots {
        *root = Transform::from_translation(-placement.origin);
    }
}

/// The interaction's XR hands (left, then right) and what became of the
/// joints pushed to them.
#[derive(Resource, Debug, Clone, Default)]
pub struct XrHands {
    inlets: Option<[HandInlet; 2]>,
    /// Whether each hand (left, right) was tracked in the last frame.
    pub tracked: [bool; 2],
    /// Frames whose joints were all tracked but made no valid hand.
    pub refused: u64,
}

impl XrHands {
    /// Drives the hands of `inlets` (a restarted interaction's), lost
    /// until their joints come.
    pub fn attach(&mut self, inlets: Option<[HandInlet; 2]>) {
        *self = XrHands { inlets, ..XrHands::default() };
    }

    /// The HUD's line: whether each hand is tracked now, if the hands are
    /// live.
    pub fn hud_line(&self) -> Option<String> {
        let state = |tracked: bool| if tracked { "tracked" } else { "lost" };
        self.inlets.as_ref()?;
        let [left, right] = self.tracked.map(state);
        Some(format!("XR hands: left {left}, right {right}"))
    }
}

/// The skeletal hand of one frame's 26 joints (world, m, in
/// `XrHandJointEXT` order), or why there is none.
pub fn sample(side: Side, joints: &[Joint; openxr::COUNT]) -> Result<HandSample, String> {
    let id = i64::from(side == Side::Right);
    let hand = layouts::from_openxr(id, side, joints).map_err(|e| e.to_string())?;
    let pose = hand_pose(&hand, &Conversion::identity()).map_err(|e| e.to_string())?;
    pose.validate(0).map_err(|e| e.to_string())?;
    Ok(HandSample::from_pose(pose))
}

/// The core's side of bevy_mod_xr's.
fn side_of(side: &HandSide) -> Side {
    match side {
        HandSide::Left => Side::Left,
        HandSide::Right => Side::Right,
    }
}

/// The joints of one tracker's bones in the world, or `None` if any is
/// not tracked (in position and orientation) or missing.
fn world_joints(
    bones: &XrHandBoneEntities,
    joints: &Query<(&Transform, &XrHandBoneRadius, &XrSpaceLocationFlags)>,
    root: &Transform,
) -> Option<[Joint; openxr::COUNT]> {
    let mut out =
        [Joint { position: glam::Vec3::ZERO, orientation: glam::Quat::IDENTITY, radius: 0.0 };
            openxr::COUNT];
    for (joint, entity) in out.iter_mut().zip(bones.0) {
        let (local, radius, flags) = joints.get(entity).ok()?;
        if !(flags.position_tracked && flags.rotation_tracked) {
            return None;
        }
        let world = root.mul_transform(*local);
        *joint = Joint {
            position: to_core_vec3(world.translation),
            orientation: to_core_quat(world.rotation),
            radius: radius.0,
        };
    }
    Some(out)
}

/// Pushes each hand's pose from the joints the runtime located this
/// frame (after bevy_mod_xr's space sync, so the physics steps of this
/// frame see them), or pushes it lost.
pub fn push_xr_hands(
    hands: Option<ResMut<XrHands>>,
    trackers: Query<(&XrHandBoneEntities, &HandSide)>,
    joints: Query<(&Transform, &XrHandBoneRadius, &XrSpaceLocationFlags)>,
    roots: Query<&Transform, With<XrTrackingRoot>>,
) {
    let Some(mut hands) = hands else { return };
    let Some(inlets) = hands.inlets.clone() else { return };
    let root = roots.iter().next().copied().unwrap_or_default();
    for (s, side) in [Side::Left, Side::Right].into_iter().enumerate() {
        let bones = trackers.iter().find(|(_, h)| side_of(h) == side);
        let joints = bones.and_then(|(bones, _)| world_joints(bones, &joints, &root));
        let pose = joints.map(|j| sample(side, &j));
        if let Some(Err(why)) = &pose {
            hands.refused += 1;
            debug!("the {side:?} hand's joints made no hand: {why}");
        }
        let pose = pose.and_then(Result::ok);
        let tracked = pose.is_some();
        if tracked != hands.tracked[s] {
            info!("the {side:?} hand is {}", if tracked { "tracked" } else { "lost" });
            hands.tracked[s] = tracked;
        }
        inlets[s].push(pose);
    }
}

/// The XR hands' systems: the room placed under the scene, and the hands
/// pushed each frame. It expects [`XrHands`] and [`RoomPlacement`].
#[derive(Debug, Clone, Copy, Default)]
pub struct XrHandsPlugin;

impl Plugin for XrHandsPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<RoomPlacement>()
            .init_resource::<XrHands>()
            .add_systems(PreUpdate, (place_room, push_xr_hands).chain().after(XrSpaceSyncSet));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_room_placement_is_three_finite_metres_within_reach() {
        let placed: RoomPlacement = " 0.3, 1.1 ,-0.6".parse().expect("X,Y,Z");
        assert_eq!(placed.origin, Vec3::new(0.3, 1.1, -0.6));
        for bad in ["0.3,1.1", "0,1,2,3", "0,NaN,0", "0,inf,0", "0,10.5,0", "a,b,c", ""] {
            let err = bad.parse::<RoomPlacement>().expect_err(bad);
            assert!(err.contains("X,Y,Z") && err.contains(bad), "{bad}: {err}");
        }
    }

    #[test]
    fn the_hud_says_which_live_hand_is_tracked() {
        let mut hands = XrHands::default();
        assert_eq!(hands.hud_line(), None, "no live hands, no line");
        let inlet = || coulomb_hands_bevy::sources::PushedHand::new(Side::Left).1;
        hands.attach(Some([inlet(), inlet()]));
        hands.tracked = [true, false];
        assert_eq!(hands.hud_line().as_deref(), Some("XR hands: left tracked, right lost"));
    }
}
