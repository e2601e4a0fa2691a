//! Contacts for the app: begin and end as Bevy messages, one per contact
//! event of every physics step, and the active contacts as a resource.

use crate::convert::to_bevy_vec3;
use crate::interaction::Interaction;
use bevy::math::Vec3;
use bevy::prelude::*;
use coulomb_hands::contact::{Contact, ContactEvent};
use coulomb_hands::friction::FrictionState;
use coulomb_hands::hand::{Bone, HandId};
use coulomb_hands::scene::ObjectId;

/// Which bone touched which object, where and when: what a contact's begin
/// or end carries. [`crate::entities::InteractionEntities`] maps the ids
/// to entities.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactChange {
    /// The contact's hand.
    pub hand: HandId,
    /// The contact's bone.
    pub bone: Bone,
    /// The object touched.
    pub object: ObjectId,
    /// The contact point C at that moment (world, m).
    pub point: Vec3,
    /// The physics time at the end of the step (s).
    pub time: f64,
}

impl ContactChange {
    fn of(e: &ContactEvent) -> ContactChange {
        let point = to_bevy_vec3(e.point);
        ContactChange { hand: e.hand, bone: e.bone, object: e.object, point, time: e.time }
    }
}

/// A bone came within the contact offset of an object.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct ContactBegan(pub ContactChange);

/// A bone left the release offset, its hand lost tracking, or its object's
/// contacts were re-seated.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct ContactEnded(pub ContactChange);

/// One active contact after the frame's last physics step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactView {
    /// The hand whose bone touches.
    pub hand: HandId,
    /// The bone that touches.
    pub bone: Bone,
    /// The object touched.
    pub object: ObjectId,
    /// The contact point C on the object's surface (world, m).
    pub point: Vec3,
    /// The contact normal at C (world, unit).
    pub normal: Vec3,
    /// The bone's point that pushes into the object (world, m).
    pub bone_point: Vec3,
    /// The force on the object in the last step (N).
    pub force: Vec3,
    /// Whether it stuck, slipped or did not press.
    pub state: FrictionState,
}

impl ContactView {
    fn of(c: &Contact) -> ContactView {
        ContactView {
            hand: c.hand,
            bone: c.bone,
            object: c.object,
            point: to_bevy_vec3(c.point),
            normal: to_bevy_vec3(c.normal),
            bone_point: to_bevy_vec3(c.bone_point),
            force: to_bevy_vec3(c.force),
            state: c.state,
        }
    }
}

/// The active hand–object contacts after the frame's last physics step,
/// ordered by (object, hand, bone).
#[derive(Resource, Debug, Clone, Default)]
pub struct Contacts(pub Vec<ContactView>);

/// Runs one physics step per fixed tick and writes its contact events as
/// messages.
pub fn step_interaction(
    interaction: Option<NonSendMut<Interaction>>,
    mut began: MessageWriter<ContactBegan>,
    mut ended: MessageWriter<ContactEnded>,
) {
    let Some(mut interaction) = interaction else { return };
    if !interaction.step() {
        return;
    }
    for e in interaction.world().events() {
        match e.kind {
            coulomb_hands::contact::ContactEventKind::Began => {
                began.write(ContactBegan(ContactChange::of(e)));
            }
            coulomb_hands::contact::ContactEventKind::Ended => {
                ended.write(ContactEnded(ContactChange::of(e)));
            }
        }
    }
}

/// Copies the active contacts into [`Contacts`].
pub fn sync_contacts(interaction: Option<NonSend<Interaction>>, mut contacts: ResMut<Contacts>) {
    let Some(interaction) = interaction else { return };
    contacts.0.clear();
    contacts.0.extend(interaction.world().contacts().iter().map(ContactView::of));
}
