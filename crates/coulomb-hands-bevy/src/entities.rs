//! Entities for the interaction world's objects and hands, and their
//! transforms kept in step with it.
//!
//! An object is one entity. A hand is an entity with its 16 bones as
//! children; the hand stays at the origin, so a bone's transform is its
//! pose in the world (m, y up).

use crate::convert;
use crate::interaction::Interaction;
use bevy::math::{Quat, Vec3};
use bevy::prelude::*;
use coulomb_hands::hand::{BONES_PER_HAND, Bone, BoneShape, HandId, HandPose, Side};
use coulomb_hands::scene::ObjectId;

/// An object of the interaction world.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct InteractionObject(pub ObjectId);

/// A hand of the interaction world.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct InteractionHand {
    /// The hand in the world.
    pub id: HandId,
    /// Which hand.
    pub side: Side,
    /// Whether its source gave a pose for the last step.
    pub tracked: bool,
}

/// One bone of a hand, posed by its transform.
#[derive(Component, Debug, Clone, Copy, PartialEq)]
pub struct HandBone {
    /// Its hand.
    pub hand: HandId,
    /// Which bone.
    pub bone: Bone,
    /// Its size in the last tracked pose (trackers change bone lengths).
    pub size: BoneSize,
}

/// A bone's size, about its transform.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BoneSize {
    /// Not posed yet.
    Unknown,
    /// The palm's box, with these half extents along its local x, y, z (m).
    Palm(Vec3),
    /// A phalanx: a capsule along its local y, with half the length of its
    /// axis and its radius (m).
    Capsule {
        /// Half the axis length, between the end caps' centres (m).
        half_length: f32,
        /// Radius (m).
        radius: f32,
    },
}

/// The entities the plugin spawned, by the world's ids.
#[derive(Resource, Debug, Default)]
pub struct InteractionEntities {
    /// The [`Interaction::serial`] they were spawned for.
    serial: Option<u64>,
    objects: Vec<Entity>,
    hands: Vec<(Entity, [Entity; BONES_PER_HAND])>,
}

impl InteractionEntities {
    /// The entity of an object.
    pub fn object(&self, id: ObjectId) -> Option<Entity> {
        self.objects.get(id.0 as usize).copied()
    }

    /// The entity of a hand.
    pub fn hand(&self, id: HandId) -> Option<Entity> {
        self.hands.get(id.0 as usize).map(|h| h.0)
    }

    /// The entity of one bone of a hand.
    pub fn bone(&self, id: HandId, bone: Bone) -> Option<Entity> {
        self.hands.get(id.0 as usize).map(|h| h.1[bone.index()])
    }
}

/// A bone's transform and size in a pose.
pub fn bone_transform(pose: &HandPose, bone: Bone) -> (Transform, BoneSize) {
    match pose.bone(bone) {
        BoneShape::Palm(p) => (
            convert::transform(p.center, p.rotation),
            BoneSize::Palm(convert::to_bevy_vec3(p.half_extents)),
        ),
        BoneShape::Capsule(c) => {
            let (a, b) = (convert::to_bevy_vec3(c.a), convert::to_bevy_vec3(c.b));
            let axis = b - a;
            let rotation = Quat::from_rotation_arc(Vec3::Y, axis.normalize_or(Vec3::Y));
            let transform = Transform::from_translation((a + b) / 2.0).with_rotation(rotation);
            (transform, BoneSize::Capsule { half_length: axis.length() / 2.0, radius: c.radius })
        }
    }
}

/// Spawns entities for the objects and hands that have none yet; a newly
/// inserted [`Interaction`] first despawns those of the one it replaced
/// (told apart by [`Interaction::serial`]: inserting over non-send data
/// does not mark it added).
pub fn spawn_entities(
    interaction: Option<NonSend<Interaction>>,
    mut entities: ResMut<InteractionEntities>,
    mut commands: Commands,
) {
    let Some(interaction) = interaction else { return };
    let entities = &mut *entities;
    if entities.serial != Some(interaction.serial()) {
        entities.serial = Some(interaction.serial());
        let hands = entities.hands.drain(..).map(|h| h.0);
        for entity in entities.objects.drain(..).chain(hands) {
            commands.entity(entity).despawn();
        }
    }
    let world = interaction.world();
    for id in world.object_ids().skip(entities.objects.len()) {
        let state = world.object_state(id).ok();
        let transform =
            state.map_or(Transform::IDENTITY, |s| convert::transform(s.position, s.rotation));
        let name = Name::new(world.object_name(id).unwrap_or("").to_string());
        entities.objects.push(commands.spawn((InteractionObject(id), name, transform)).id());
    }
    for i in entities.hands.len()..world.hand_count() {
        let id = HandId(i as u32);
        let Some(side) = world.hand_side(id) else { continue };
        let hand = InteractionHand { id, side, tracked: false };
        let parent = commands.spawn((hand, Transform::IDENTITY)).id();
        let bones = std::array::from_fn(|i| {
            let bone = HandBone { hand: id, bone: Bone::from_index(i), size: BoneSize::Unknown };
            commands.spawn((bone, Transform::IDENTITY, ChildOf(parent))).id()
        });
        entities.hands.push((parent, bones));
    }
}

/// Sets every object's and bone's transform from the world after the
/// frame's physics steps. An untracked hand's bones keep their last pose.
pub fn sync_transforms(
    interaction: Option<NonSend<Interaction>>,
    mut objects: Query<(&InteractionObject, &mut Transform), Without<HandBone>>,
    mut hands: Query<&mut InteractionHand>,
    mut bones: Query<(&mut HandBone, &mut Transform), Without<InteractionObject>>,
) {
    let Some(interaction) = interaction else { return };
    let world = interaction.world();
    for (object, mut transform) in &mut objects {
        if let Ok(s) = world.object_state(object.0) {
            *transform = convert::transform(s.position, s.rotation);
        }
    }
    for mut hand in &mut hands {
        hand.tracked = world.hand_pose(hand.id).is_some();
    }
    for (mut bone, mut transform) in &mut bones {
        if let Some(pose) = world.hand_pose(bone.hand) {
            let (t, size) = bone_transform(pose, bone.bone);
            (*transform, bone.size) = (t, size);
        }
    }
}
