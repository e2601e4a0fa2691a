//! Live hands from an XR runtime's hand tracking (`XR_EXT_hand_tracking`).
//!
//! Each frame, bevy_mod_xr's hand trackers hold the 26 joints the runtime
//! located (bevy_mod_openxr fills them, with the `openxr` feature: see
//! `crate::openxr`). Here they become the skeletal hand by the core's
//! OpenXR layout ([`coulomb_hands_bevy::input::openxr_sample`], through
//! [`coulomb_hands::input::layouts::hand_pose_from_joints`]), written to the input of
//! the app hand of that side (with [`HandDriver::Xr`]). The hand then
//! touches objects only through the friction contacts, like any tracked
//! hand.
//!
//! A hand with an untracked joint, or one the layout or the pose check
//! refuses, is pushed as lost: its contacts end, as in a tracker dropout.
//!
//! This module needs no XR runtime: it reads bevy_mod_xr's components,
//! whoever wrote them, so its tests drive it with joints of their own.

use crate::hud::{HudLines, HudSection};
use crate::source::HandDriver;
use bevy::prelude::*;
use bevy_mod_xr::hands::{HAND_JOINT_COUNT, HandSide, XrHandBoneEntities, XrHandBoneRadius};
use bevy_mod_xr::session::XrTrackingRoot;
use bevy_mod_xr::spaces::{XrSpaceLocationFlags, XrSpaceSyncSet};
use coulomb_hands::hand::Side;
use coulomb_hands::input::layouts::{Joint, openxr};
use coulomb_hands_bevy::convert::{to_core_quat, to_core_vec3};
use coulomb_hands_bevy::prelude::*;

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

/// What became of the joints written to the XR hands.
#[derive(Resource, Debug, Clone, Default)]
pub struct XrHands {
    /// Whether each hand (left, right) was tracked in the last frame.
    pub tracked: [bool; 2],
    /// Frames whose joints were all tracked but made no valid hand.
    pub refused: u64,
}

impl XrHands {
    /// The HUD's line: whether each hand is tracked now.
    pub fn hud_line(&self) -> String {
        let state = |tracked: bool| if tracked { "tracked" } else { "lost" };
        let [left, right] = self.tracked.map(state);
        format!("XR hands: left {left}, right {right}")
    }
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

/// Writes each XR hand's pose from the joints the runtime located this
/// frame (after bevy_mod_xr's space sync, so the physics steps of this
/// frame see them), or writes it lost.
pub fn push_xr_hands(
    mut hands: ResMut<XrHands>,
    mut inputs: Query<(&AppHand, &HandDriver, &mut HandInput)>,
    trackers: Query<(&XrHandBoneEntities, &HandSide)>,
    joints: Query<(&Transform, &XrHandBoneRadius, &XrSpaceLocationFlags)>,
    roots: Query<&Transform, With<XrTrackingRoot>>,
) {
    let root = roots.iter().next().copied().unwrap_or_default();
    for (hand, driver, mut input) in &mut inputs {
        if *driver != HandDriver::Xr {
            continue;
        }
        let side = hand.side;
        let bones = trackers.iter().find(|(_, h)| side_of(h) == side);
        let joints = bones.and_then(|(bones, _)| world_joints(bones, &joints, &root));
        let tracked = match joints.map(|j| input.set_openxr(side, &j)) {
            Some(Ok(())) => true,
            Some(Err(why)) => {
                hands.refused += 1;
                debug!("the {side:?} hand's joints made no hand: {why}");
                false
            }
            None => {
                input.set(None);
                false
            }
        };
        let s = usize::from(side == Side::Right);
        if tracked != hands.tracked[s] {
            info!("the {side:?} hand is {}", if tracked { "tracked" } else { "lost" });
            hands.tracked[s] = tracked;
        }
    }
}

/// The HUD's line, when there are XR hands.
fn hud_line(
    hands: Res<XrHands>,
    drivers: Query<&HandDriver, With<AppHand>>,
    mut hud: ResMut<HudLines>,
) {
    if drivers.iter().any(|d| *d == HandDriver::Xr) {
        hud.set(HudSection::LiveHands, vec![hands.hud_line()]);
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
            .init_resource::<HudLines>()
            .add_systems(PreUpdate, (place_room, push_xr_hands).chain().after(XrSpaceSyncSet))
            .add_systems(Update, hud_line.in_set(crate::sets::ViewerSystems::HudLines));
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
        let hands = XrHands { tracked: [true, false], refused: 0 };
        assert_eq!(hands.hud_line(), "XR hands: left tracked, right lost");
    }
}
