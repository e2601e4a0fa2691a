//! Entities for the interaction world's objects and hands, and their
//! transforms kept in step with it.
//!
//! An object is one entity. A hand is an entity with its 16 bones as
//! children; the hand stays at the origin, so a bone's transform is its
//! pose in the world (m, y up). The plugin spawns the entities of the
//! world's objects and hands; an app's own object entities
//! ([`crate::objects::ObjectDescription`]) are added to the world, and its
//! own hand entities ([`crate::input::AppHand`]) are given their bones.

use crate::convert;
use crate::input::AppHandLink;
use crate::physics::HandPhysics;
use crate::reflect::{BoneReflect, HandIdReflect, ObjectIdReflect, SideReflect};
use bevy::math::{Quat, Vec3};
use bevy::prelude::*;
use coulomb_hands::hand::{BONES_PER_HAND, Bone, BoneShape, HandId, HandPose, Side};
use coulomb_hands::scene::ObjectId;

/// An object of the interaction world: the plugin gives it to the entities
/// of the world's objects, and to an app's entity once its
/// [`crate::objects::ObjectDescription`] is added to the world. Its `Transform` follows
/// the world. Despawning the entity, or removing this component, removes
/// the object from the world.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq, Eq)]
#[reflect(Component, Debug, PartialEq)]
#[require(Transform)]
pub struct InteractionObject(#[reflect(remote = ObjectIdReflect)] pub ObjectId);

/// A hand of the interaction world, with its 16 [`HandBone`]s as children.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq, Eq)]
#[reflect(Component, Debug, PartialEq)]
#[require(Transform)]
pub struct InteractionHand {
    /// The hand in the world.
    #[reflect(remote = HandIdReflect)]
    pub id: HandId,
    /// Which hand.
    #[reflect(remote = SideReflect)]
    pub side: Side,
    /// Whether its source gave a pose for the last step.
    pub tracked: bool,
}

/// One bone of a hand, posed by its `Transform` (world, m: the hand
/// entity stays at the origin).
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Component, Debug, PartialEq)]
#[require(Transform)]
pub struct HandBone {
    /// Its hand.
    #[reflect(remote = HandIdReflect)]
    pub hand: HandId,
    /// Which bone.
    #[reflect(remote = BoneReflect)]
    pub bone: Bone,
    /// Its size in the last tracked pose (trackers change bone lengths).
    pub size: BoneSize,
}

/// A bone's size, about its transform.
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
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

/// The entities of the world's objects and hands, by the world's ids.
#[derive(Resource, Reflect, Debug, Default)]
#[reflect(Resource, Default)]
pub struct InteractionEntities {
    /// The [`HandPhysics::serial`] they are for.
    serial: Option<u64>,
    /// By object id; `None` for an object the world added and removed
    /// before it had an entity.
    objects: Vec<Option<Entity>>,
    hands: Vec<HandEntities>,
}

/// A hand's entity and its bones'.
#[derive(Reflect, Debug, Clone, Copy)]
struct HandEntities {
    hand: Entity,
    bones: [Entity; BONES_PER_HAND],
    /// An [`crate::input::AppHand`]: the app's entity, which outlives the world.
    app: bool,
}

impl InteractionEntities {
    /// The entity of an object: also of one removed from the world since,
    /// so that its last contacts' ends name it.
    pub fn object(&self, id: ObjectId) -> Option<Entity> {
        self.objects.get(id.0 as usize).copied().flatten()
    }

    /// Whether they are `physics`' entities.
    pub(crate) fn is_for(&self, physics: &HandPhysics) -> bool {
        self.serial == Some(physics.serial())
    }

    /// Makes `entity` object `id`'s, the world having just added it.
    pub(crate) fn link_object(&mut self, id: ObjectId, entity: Entity) {
        let i = id.0 as usize;
        if self.objects.len() <= i {
            self.objects.resize(i + 1, None);
        }
        self.objects[i] = Some(entity);
    }

    /// The entity of a hand.
    pub fn hand(&self, id: HandId) -> Option<Entity> {
        self.hands.get(id.0 as usize).map(|h| h.hand)
    }

    /// The entity of one bone of a hand.
    pub fn bone(&self, id: HandId, bone: Bone) -> Option<Entity> {
        self.hands.get(id.0 as usize).map(|h| h.bones[bone.index()])
    }

    /// Makes them `physics`' if they are another world's, and says whether
    /// they were: the other world's are forgotten ([`Self::clear`]).
    pub(crate) fn start(
        &mut self,
        physics: &HandPhysics,
        commands: &mut Commands,
        described: impl Fn(Entity) -> bool,
    ) -> bool {
        if self.is_for(physics) {
            return false;
        }
        self.clear(commands, described);
        self.serial = Some(physics.serial());
        true
    }

    /// Makes the app's entity `hand` the world's `side` hand `id`, giving
    /// it bones.
    pub(crate) fn push_app_hand(
        &mut self,
        commands: &mut Commands,
        hand: Entity,
        id: HandId,
        side: Side,
    ) {
        self.hands.push(give_bones(commands, hand, id, side, true));
    }

    /// Forgets the entities of a replaced world: despawns the plugin's
    /// objects and hands, and unlinks the app's hands (their bones go).
    /// The app's objects stay, for the new world to add.
    fn clear(&mut self, commands: &mut Commands, described: impl Fn(Entity) -> bool) {
        // `try_`: the app may have despawned any of them already.
        for object in self.objects.drain(..).flatten() {
            if !described(object) {
                commands.entity(object).try_despawn();
            }
        }
        for hand in self.hands.drain(..) {
            if hand.app {
                commands.entity(hand.hand).try_remove::<(InteractionHand, AppHandLink)>();
                for bone in hand.bones {
                    commands.entity(bone).try_despawn();
                }
            } else {
                commands.entity(hand.hand).try_despawn();
            }
        }
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

/// Spawns entities for the objects and hands added to the world since
/// the last call (through [`HandPhysics::world_mut`] or
/// [`HandPhysics::add_hand`]): a comparison of counts when there are none,
/// so each physics step can afford it.
pub(crate) fn spawn_new(
    physics: &HandPhysics,
    entities: &mut InteractionEntities,
    commands: &mut Commands,
) {
    let world = physics.world();
    for i in entities.objects.len()..world.object_count() {
        let id = ObjectId(i as u32);
        // An object added and removed before it had an entity gets none.
        let entity = world.object_state(id).ok().map(|s| {
            let transform = convert::transform(s.position, s.rotation);
            let name = Name::new(world.object_name(id).unwrap_or("").to_string());
            commands.spawn((InteractionObject(id), name, transform)).id()
        });
        entities.objects.push(entity);
    }
    for i in entities.hands.len()..world.hand_count() {
        let id = HandId(i as u32);
        let side = world.hand_side(id).unwrap_or(Side::Right);
        let hand = commands.spawn(Name::new(format!("{side:?} hand"))).id();
        entities.hands.push(give_bones(commands, hand, id, side, false));
    }
}

/// Makes `hand` the world's hand `id`, with 16 bone entities as children.
fn give_bones(
    commands: &mut Commands,
    hand: Entity,
    id: HandId,
    side: Side,
    app: bool,
) -> HandEntities {
    commands.entity(hand).insert(InteractionHand { id, side, tracked: false });
    let bones = std::array::from_fn(|i| {
        let bone = HandBone { hand: id, bone: Bone::from_index(i), size: BoneSize::Unknown };
        commands.spawn((bone, ChildOf(hand))).id()
    });
    HandEntities { hand, bones, app }
}

/// Sets every object's and bone's transform from the world after the
/// frame's physics steps. An untracked hand's bones keep their last pose.
pub(crate) fn sync_transforms(
    physics: Option<Res<HandPhysics>>,
    mut objects: Query<(&InteractionObject, &mut Transform), Without<HandBone>>,
    mut hands: Query<&mut InteractionHand>,
    mut bones: Query<(&mut HandBone, &mut Transform), Without<InteractionObject>>,
) {
    let Some(physics) = physics else { return };
    let world = physics.world();
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
