//! Contacts for the app, by entity: every contact's begin and end as Bevy
//! messages, each object's first touch and final release as events
//! triggered on the object's entity (for its observers), and the active
//! contacts as a resource.

use crate::convert::to_bevy_vec3;
use crate::entities::{InteractionEntities, spawn_new};
use crate::physics::HandPhysics;
use crate::reflect::{BoneReflect, FrictionStateReflect};
use bevy::math::Vec3;
use bevy::prelude::*;
use coulomb_hands::contact::{Contact, ContactEvent, ContactEventKind};
use coulomb_hands::friction::FrictionState;
use coulomb_hands::hand::Bone;
use coulomb_hands::scene::ObjectId;

/// Which bone touched which object, where and when: what a contact's begin
/// or end carries.
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
pub struct ContactChange {
    /// The object's entity.
    pub object: Entity,
    /// The bone's entity (a [`crate::entities::HandBone`]).
    pub bone: Entity,
    /// Its hand's entity.
    pub hand: Entity,
    /// Which bone of the hand it is.
    #[reflect(remote = BoneReflect)]
    pub kind: Bone,
    /// The contact point C at that moment (world, m).
    pub point: Vec3,
    /// The physics time at the end of the step (s).
    pub time: f64,
}

/// A bone came within the contact offset of an object.
#[derive(Message, Reflect, Debug, Clone, Copy, PartialEq, Deref)]
pub struct ContactBegan(pub ContactChange);

/// A bone left the release offset, its hand lost tracking, or its object's
/// contacts were re-seated.
#[derive(Message, Reflect, Debug, Clone, Copy, PartialEq, Deref)]
pub struct ContactEnded(pub ContactChange);

/// Triggered on an object's entity when a hand touches it while no bone
/// did: the bone that touched first. (Contacts re-seated within a step do
/// not count: the object was touched throughout.)
#[derive(EntityEvent, Reflect, Debug, Clone, Copy, PartialEq)]
pub struct ObjectTouched {
    /// The object.
    pub entity: Entity,
    /// How its first contact began.
    pub contact: ContactChange,
}

/// Triggered on an object's entity when its last contact with a hand
/// ends: the bone that left last.
#[derive(EntityEvent, Reflect, Debug, Clone, Copy, PartialEq)]
pub struct ObjectReleased {
    /// The object.
    pub entity: Entity,
    /// How its last contact ended.
    pub contact: ContactChange,
}

/// One active contact after the frame's last physics step.
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
pub struct ContactView {
    /// The object touched.
    pub object: Entity,
    /// The bone that touches.
    pub bone: Entity,
    /// The bone's hand.
    pub hand: Entity,
    /// Which bone of the hand it is.
    #[reflect(remote = BoneReflect)]
    pub kind: Bone,
    /// The contact point C on the object's surface (world, m).
    pub point: Vec3,
    /// The contact normal at C (world, unit).
    pub normal: Vec3,
    /// The bone's point that pushes into the object (world, m).
    pub bone_point: Vec3,
    /// The force on the object in the last step (N).
    pub force: Vec3,
    /// Whether it stuck, slipped or did not press.
    #[reflect(remote = FrictionStateReflect)]
    pub state: FrictionState,
}

/// The active hand–object contacts after the frame's last physics step,
/// ordered by (object, hand, bone).
#[derive(Resource, Reflect, Debug, Clone, Default)]
#[reflect(Resource, Default)]
pub struct Contacts(pub Vec<ContactView>);

/// The entities of a contact's object, bone and hand; `None` only for a
/// world changed behind the plugin's back within a step.
fn entities_of(
    entities: &InteractionEntities,
    object: ObjectId,
    hand: coulomb_hands::hand::HandId,
    bone: Bone,
) -> Option<(Entity, Entity, Entity)> {
    Some((entities.object(object)?, entities.bone(hand, bone)?, entities.hand(hand)?))
}

fn change(entities: &InteractionEntities, e: &ContactEvent) -> Option<ContactChange> {
    let (object, bone, hand) = entities_of(entities, e.object, e.hand, e.bone)?;
    let point = to_bevy_vec3(e.point);
    Some(ContactChange { object, bone, hand, kind: e.bone, point, time: e.time })
}

fn view(entities: &InteractionEntities, c: &Contact) -> Option<ContactView> {
    let (object, bone, hand) = entities_of(entities, c.object, c.hand, c.bone)?;
    Some(ContactView {
        object,
        bone,
        hand,
        kind: c.bone,
        point: to_bevy_vec3(c.point),
        normal: to_bevy_vec3(c.normal),
        bone_point: to_bevy_vec3(c.bone_point),
        force: to_bevy_vec3(c.force),
        state: c.state,
    })
}

/// The objects a hand touched after the last step, by [`ObjectId`] index,
/// and the step's scratch, kept so that a step allocates nothing.
#[derive(Resource, Debug, Default)]
pub(crate) struct Touched {
    serial: Option<u64>,
    objects: Vec<bool>,
    /// This step's `objects`.
    now: Vec<bool>,
    /// Each object's first contact that began this step, and last that
    /// ended.
    first: Vec<Option<ContactChange>>,
    last: Vec<Option<ContactChange>>,
}

impl Touched {
    /// Empties the step's scratch for `objects` objects, and notes which
    /// the world's contacts touch now.
    fn start(&mut self, objects: usize, contacts: &[Contact]) {
        for list in [&mut self.now, &mut self.objects] {
            list.resize(objects, false);
        }
        self.now.fill(false);
        for c in contacts {
            self.now[c.object.0 as usize] = true;
        }
        for list in [&mut self.first, &mut self.last] {
            list.clear();
            list.resize(objects, None);
        }
    }
}

/// Runs one physics step, writes its contact events as messages, and
/// triggers the objects' touches and releases. Objects and hands added to
/// the world since the frame began (by an app's system in this schedule)
/// get their entities first.
pub(crate) fn step_physics(
    physics: Option<ResMut<HandPhysics>>,
    mut entities: ResMut<InteractionEntities>,
    mut touched: ResMut<Touched>,
    mut began: MessageWriter<ContactBegan>,
    mut ended: MessageWriter<ContactEnded>,
    mut commands: Commands,
) {
    let Some(mut physics) = physics else { return };
    if !entities.is_for(&physics) {
        // A world inserted since the frame began: `link_entities` starts
        // it, in the next frame.
        return;
    }
    spawn_new(&physics, &mut entities, &mut commands);
    if touched.serial != Some(physics.serial()) {
        touched.serial = Some(physics.serial());
        touched.objects.clear();
    }
    if !physics.step() {
        return;
    }
    let world = physics.world();
    let touched = &mut *touched;
    touched.start(world.object_count(), world.contacts());
    for e in world.events() {
        let Some(change) = change(&entities, e) else { continue };
        match e.kind {
            ContactEventKind::Began => {
                began.write(ContactBegan(change));
                touched.first[e.object.0 as usize].get_or_insert(change);
            }
            ContactEventKind::Ended => {
                ended.write(ContactEnded(change));
                touched.last[e.object.0 as usize] = Some(change);
            }
        }
    }
    for (i, (&was, &touching)) in touched.objects.iter().zip(&touched.now).enumerate() {
        match (was, touching, touched.first[i], touched.last[i]) {
            (false, true, Some(contact), _) => {
                commands.trigger(ObjectTouched { entity: contact.object, contact });
            }
            (true, false, _, Some(contact)) => {
                commands.trigger(ObjectReleased { entity: contact.object, contact });
            }
            _ => {}
        }
    }
    std::mem::swap(&mut touched.objects, &mut touched.now);
}

/// Copies the active contacts into [`Contacts`].
pub(crate) fn sync_contacts(
    physics: Option<Res<HandPhysics>>,
    entities: Res<InteractionEntities>,
    mut contacts: ResMut<Contacts>,
) {
    let Some(physics) = physics else { return };
    contacts.0.clear();
    contacts.0.extend(physics.world().contacts().iter().filter_map(|c| view(&entities, c)));
}
