//! The plugin's first set, [`crate::HandPhysicsSystems::Prepare`]: the
//! world and the app's entities linked before the frame's steps.

use crate::entities::{HandBone, InteractionEntities, InteractionObject, spawn_new};
use crate::input::{self, AppHand, AppHandLink};
use crate::objects;
use crate::physics::{HandPhysics, HandPhysicsReplaced};
use bevy::prelude::*;
use coulomb_hands::hand::Side;

/// Links the world and the app's entities before the frame's steps: a
/// newly inserted [`HandPhysics`] first clears the entities of the one it
/// replaced (told apart by [`HandPhysics::serial`]: inserting over a
/// resource does not mark it added), and says so; then the world's new
/// objects and hands get entities, the app's described objects are added
/// to the world ([`objects::add_described`]), and its unlinked
/// [`AppHand`]s too.
pub(crate) fn link_entities(
    physics: Option<ResMut<HandPhysics>>,
    mut entities: ResMut<InteractionEntities>,
    app_hands: Query<(Entity, &AppHand, Option<&AppHandLink>)>,
    described: Query<objects::Offered, Without<HandBone>>,
    linked: Query<&InteractionObject>,
    mut replaced: MessageWriter<HandPhysicsReplaced>,
    mut commands: Commands,
) {
    let Some(mut physics) = physics else { return };
    let entities = &mut *entities;
    if entities.start(&physics, &mut commands, |e| described.contains(e)) {
        replaced.write(HandPhysicsReplaced { serial: physics.serial() });
    }
    spawn_new(&physics, entities, &mut commands);
    objects::add_described(&mut physics, entities, &described, &linked, &mut commands);
    // Left hands first, then by entity, so a world's hand ids do not depend
    // on the query's order.
    let serial = physics.serial();
    let mut unlinked: Vec<(Entity, AppHand)> = (app_hands.iter())
        .filter(|(_, _, link)| link.is_none_or(|l| l.serial != serial))
        .map(|(entity, hand, _)| (entity, *hand))
        .collect();
    unlinked.sort_by_key(|(entity, hand)| (hand.side == Side::Right, *entity));
    for (entity, app_hand) in unlinked {
        let (id, link) = input::attach(&mut physics, app_hand);
        commands.entity(entity).insert(link);
        entities.push_app_hand(&mut commands, entity, id, app_hand.side);
    }
}
