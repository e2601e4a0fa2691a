//! The drawn hand of thesis §3.6 (Fig. 3.19): semi-transparent while it
//! touches nothing, and opaque during contact. At the physics step a contact
//! first presses, the hand is frozen in its pose of that moment and carried
//! along with the object, so the picture never shows fingers sunk into what
//! they hold (the tracked bones may sink in: they are not bodies). The pose
//! is refined when another finger (or the palm) begins to press: that part
//! takes its pose of that moment. The freeze lasts while the hand touches
//! the object at all, pressing or hovering in the offset band. Before any
//! press, hovering contacts leave the hand drawn where it is tracked: it has
//! not reached the surface, and a hand that grazes an object on its way to a
//! grasp is not frozen open.
//!
//! The drawn pose is kept in the touched object's frame and mapped back to
//! the world with the object's current pose, the thesis's
//! `T_HandMesh = T_HandMesh⁻¹ · T_VirtualObject`.

use crate::sets::ViewerSystems;
use bevy::prelude::*;
use coulomb_hands::contact::Contact;
use coulomb_hands::hand::{Bone, HandId, HandPose};
use coulomb_hands::pipeline::InteractionWorld;
use coulomb_hands::scene::ObjectId;
use coulomb_hands_bevy::entities::bone_transform;
use coulomb_hands_bevy::prelude::*;
use std::collections::HashMap;

/// Opacity of a hand that touches nothing (the thesis's "semi-transparent").
pub const FREE_ALPHA: f32 = 0.4;
/// The stylized hand's colour (sRGB), a light skin tone.
pub const SKIN: Color = Color::srgb(0.93, 0.72, 0.58);
/// Parts of a hand: the palm, then the five fingers.
const PARTS: usize = 6;

/// A hand in contact: its pose in the touched object's frame, and which
/// parts had touched when that pose was taken.
#[derive(Debug, Clone, PartialEq)]
pub struct Grip {
    /// The object the drawn hand moves with.
    pub object: ObjectId,
    /// The drawn pose, in the object's frame (m).
    pub local: HandPose,
    /// Palm, thumb … pinky: whether each part's pose is from the moment it
    /// began to press.
    pub parts: [bool; PARTS],
}

/// The part (palm 0, fingers 1 … 5) a bone belongs to.
fn part(bone: Bone) -> usize {
    match bone {
        Bone::Palm => 0,
        Bone::Finger(finger, _) => 1 + finger as usize,
    }
}

/// `pose` moved from the world into the frame of an object at `position`
/// turned by `rotation`, or back with `inverse` false.
fn into_frame(
    pose: &HandPose,
    position: glam::Vec3,
    rotation: glam::Quat,
    inverse: bool,
) -> HandPose {
    if inverse {
        pose.transformed(position, rotation.inverse(), -position)
    } else {
        pose.transformed(glam::Vec3::ZERO, rotation, position)
    }
}

/// The next grip of a hand, from its last one, its tracked pose and its
/// contacts after a physics step. A grip begins when a contact presses
/// (normal force > 0) and lasts while the hand touches that object at all
/// (pressing or hovering in the offset band), so a contact that stops
/// pressing for a step does not snap the drawn hand into the tracked one.
/// `None` when there is no grip.
pub fn next_grip(
    last: Option<Grip>,
    tracked: &HandPose,
    contacts: &[&Contact],
    world: &InteractionWorld,
) -> Option<Grip> {
    let pressing: Vec<&Contact> =
        contacts.iter().copied().filter(|c| c.normal_force > 0.0).collect();
    let kept = last.filter(|g| contacts.iter().any(|c| c.object == g.object));
    let object = kept.as_ref().map(|g| g.object).or(pressing.first().map(|c| c.object))?;
    let state = world.object_state(object).ok()?;
    let local_now = into_frame(tracked, state.position, state.rotation, true);
    let mut grip = kept.unwrap_or(Grip { object, local: local_now.clone(), parts: [false; PARTS] });
    let contacts = &pressing[..];
    for c in contacts.iter().filter(|c| c.object == object) {
        let p = part(c.bone);
        if !grip.parts[p] {
            grip.parts[p] = true;
            match c.bone {
                Bone::Palm => grip.local.palm = local_now.palm,
                Bone::Finger(finger, _) => {
                    grip.local.fingers[finger as usize] = local_now.fingers[finger as usize];
                }
            }
        }
    }
    Some(grip)
}

/// The pose to draw for a grip, with the object where it is now.
pub fn drawn_pose(grip: &Grip, world: &InteractionWorld) -> Option<HandPose> {
    let state = world.object_state(grip.object).ok()?;
    Some(into_frame(&grip.local, state.position, state.rotation, false))
}

/// One drawn bone.
#[derive(Component, Debug, Clone, Copy)]
pub struct DrawnBone {
    /// Its hand.
    pub hand: HandId,
    /// Which bone.
    pub bone: Bone,
}

/// The drawn hands' state: per hand, whether it is in contact (drawn
/// opaque) and its grip (drawn frozen).
#[derive(Resource, Default)]
pub struct DrawnHands {
    /// Per hand: its grip, whether it is in contact, its material, its
    /// bones' entities.
    hands: Vec<DrawnHand>,
    /// Capsule meshes of radius 1 by axis length over radius (tenths).
    capsules: HashMap<u32, Handle<Mesh>>,
    /// The palm's box of side 1.
    cube: Option<Handle<Mesh>>,
}

/// Every hand's grip, updated after each physics step, so a hand freezes
/// at the step its contact first presses whatever the frame rate.
#[derive(Resource, Debug, Default)]
pub struct Grips {
    /// Per hand, in the world's order.
    pub grips: Vec<Option<Grip>>,
}

/// After each physics step: every hand's next grip ([`next_grip`]).
pub fn track_grips(
    physics: Option<Res<HandPhysics>>,
    mut replaced: MessageReader<HandPhysicsReplaced>,
    mut grips: ResMut<Grips>,
) {
    let Some(physics) = physics else { return };
    if replaced.read().last().is_some() {
        grips.grips.clear();
    }
    let world = physics.world();
    grips.grips.resize(world.hand_count(), None);
    for (i, grip) in grips.grips.iter_mut().enumerate() {
        let id = HandId(i as u32);
        let contacts: Vec<&Contact> = world.contacts().iter().filter(|c| c.hand == id).collect();
        let tracked = world.hand_pose(id);
        *grip = tracked.and_then(|t| next_grip(grip.take(), t, &contacts, world));
    }
}

/// One drawn hand.
struct DrawnHand {
    /// Whether it has contacts (drawn opaque).
    in_contact: bool,
    /// Its material, shared by its bones.
    material: Handle<StandardMaterial>,
    /// Its bones' entities.
    bones: Vec<Entity>,
}

impl DrawnHands {
    /// Whether hand `i` is drawn in contact (opaque).
    pub fn in_contact(&self, i: usize) -> bool {
        self.hands.get(i).is_some_and(|h| h.in_contact)
    }
}

/// Poses every hand's bones, frozen in its grip or as tracked, and sets its
/// opacity from its contacts.
pub fn draw_hands(
    (physics, mut replaced): (Option<Res<HandPhysics>>, MessageReader<HandPhysicsReplaced>),
    grips: Res<Grips>,
    mut drawn: ResMut<DrawnHands>,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
    mut bones: Query<(&DrawnBone, &mut Transform, &mut Mesh3d, &mut Visibility)>,
    mut commands: Commands,
) {
    let Some(physics) = physics else { return };
    let drawn = &mut *drawn;
    if replaced.read().last().is_some() {
        for hand in drawn.hands.drain(..) {
            hand.bones.into_iter().for_each(|e| commands.entity(e).despawn());
        }
    }
    let world = physics.world();
    let cube = drawn.cube.get_or_insert_with(|| meshes.add(Cuboid::from_length(1.0))).clone();
    while drawn.hands.len() < world.hand_count() {
        let id = HandId(drawn.hands.len() as u32);
        let material = materials.add(material(false));
        let bones = Bone::all()
            .map(|bone| {
                let bundle =
                    (DrawnBone { hand: id, bone }, Transform::IDENTITY, Visibility::Hidden);
                commands
                    .spawn((bundle, Mesh3d(cube.clone()), MeshMaterial3d(material.clone())))
                    .id()
            })
            .collect();
        drawn.hands.push(DrawnHand { in_contact: false, material, bones });
    }
    let mut poses = Vec::with_capacity(drawn.hands.len());
    for (i, hand) in drawn.hands.iter_mut().enumerate() {
        let id = HandId(i as u32);
        let tracked = world.hand_pose(id);
        let in_contact = tracked.is_some() && world.contacts().iter().any(|c| c.hand == id);
        if in_contact != hand.in_contact
            && let Some(mut m) = materials.get_mut(&hand.material)
        {
            *m = material(in_contact);
        }
        hand.in_contact = in_contact;
        let grip = grips.grips.get(i).and_then(Option::as_ref).filter(|_| tracked.is_some());
        let frozen = grip.and_then(|g| drawn_pose(g, world));
        poses.push(frozen.or_else(|| tracked.cloned()));
    }
    for (bone, mut transform, mut mesh, mut visibility) in &mut bones {
        let Some(Some(pose)) = poses.get(bone.hand.0 as usize) else {
            *visibility = Visibility::Hidden;
            continue;
        };
        let (place, size) = bone_transform(pose, bone.bone);
        *visibility = Visibility::Inherited;
        *transform = match size {
            BoneSize::Palm(half) => place.with_scale(half * 2.0),
            BoneSize::Capsule { half_length, radius } => {
                let tenths = (2.0 * half_length / radius * 10.0).round().max(0.0) as u32;
                let handle = drawn
                    .capsules
                    .entry(tenths)
                    .or_insert_with(|| meshes.add(Capsule3d::new(1.0, tenths as f32 / 10.0)));
                mesh.0 = handle.clone();
                place.with_scale(Vec3::splat(radius))
            }
            BoneSize::Unknown => place,
        };
        if matches!(size, BoneSize::Palm(_)) {
            mesh.0 = cube.clone();
        }
    }
}

/// The stylized skin, opaque or at [`FREE_ALPHA`].
fn material(opaque: bool) -> StandardMaterial {
    let (color, alpha_mode) = if opaque {
        (SKIN, AlphaMode::Opaque)
    } else {
        (SKIN.with_alpha(FREE_ALPHA), AlphaMode::Blend)
    };
    StandardMaterial { base_color: color, alpha_mode, perceptual_roughness: 0.7, ..default() }
}

/// The drawn hands' systems: grips after each physics step, bones each
/// frame. Headless apps add [`track_grips`] alone.
#[derive(Debug, Clone, Copy, Default)]
pub struct HandVisualPlugin;

impl Plugin for HandVisualPlugin {
    fn build(&self, app: &mut App) {
        crate::sets::configure(app);
        app.init_resource::<Grips>()
            .init_resource::<DrawnHands>()
            .add_systems(HandPhysicsStep, track_grips.after(WorldStep))
            .add_systems(Update, draw_hands.in_set(ViewerSystems::Draw));
    }
}
