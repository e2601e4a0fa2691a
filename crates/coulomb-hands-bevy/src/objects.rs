//! Objects the app spawns, ECS-first: an entity with an
//! [`ObjectDescription`] (its `Transform` placing it) is added to the
//! world, and gets its [`InteractionObject`]; despawning the entity, or
//! removing its `InteractionObject`, removes the object from the world.
//! The world's own objects (a scenario's, those added through
//! [`HandPhysics::world_mut`]) get entities too ([`crate::entities`]).
//!
//! An object that the world rejects (a mass that is not positive, a shape
//! too thin) is not added: the plugin logs why and triggers
//! [`ObjectRejected`] on the entity. A new [`HandPhysics`] gets the
//! described objects again, where their transforms are then.

use crate::convert;
use crate::entities::{InteractionEntities, InteractionObject};
use crate::physics::HandPhysics;
use bevy::prelude::*;
use coulomb_hands::pipeline::WorldError;
use coulomb_hands::scene::ObjectDesc;

/// What an object of the app is: its shape, mass, material, γ and name, as
/// the core describes them (an entity without a `Name` gets the
/// description's). The entity's `Transform` places it (world, m;
/// its scale is not read): the description's own `position` and
/// `rotation` are replaced by the transform's, and a description that
/// placed it elsewhere is warned of. To change an object, insert a new
/// description: the old object leaves the world and the new one enters
/// it, with a new id.
#[derive(Component, Debug, Clone, PartialEq)]
#[require(Transform)]
pub struct ObjectDescription(pub ObjectDesc);

/// The world rejected an entity's [`ObjectDescription`]: it has no
/// [`InteractionObject`] until a new description is inserted.
#[derive(EntityEvent, Debug, Clone, PartialEq)]
pub struct ObjectRejected {
    /// The entity.
    pub entity: Entity,
    /// Why.
    pub error: WorldError,
}

/// Which world (its [`HandPhysics::serial`]) an entity's description was
/// last offered to.
#[derive(Component, Debug, Clone, Copy)]
pub(crate) struct ObjectLink {
    serial: u64,
}

/// A described entity the current world has not seen, or whose
/// description changed.
pub(crate) type Offered<'a> =
    (Entity, Ref<'a, ObjectDescription>, &'a Transform, Option<&'a ObjectLink>, Has<Name>);

/// Adds the described entities that the current world has not seen (or
/// whose description changed since) to it, in entity order, so that the
/// ids do not depend on the query's order.
pub(crate) fn add_described(
    physics: &mut HandPhysics,
    entities: &mut InteractionEntities,
    described: &Query<Offered, Without<crate::entities::HandBone>>,
    linked: &Query<&InteractionObject>,
    commands: &mut Commands,
) {
    let serial = physics.serial();
    let mut offered: Vec<Entity> = (described.iter())
        .filter(|(_, d, _, link, _)| link.is_none_or(|l| l.serial != serial) || d.is_changed())
        .map(|(entity, ..)| entity)
        .collect();
    offered.sort_unstable();
    for entity in offered {
        let Ok((_, description, transform, link, named)) = described.get(entity) else { continue };
        if link.is_some_and(|l| l.serial == serial)
            && let Ok(old) = linked.get(entity)
            && entities.object(old.0) == Some(entity)
        {
            // A new description: the old object leaves.
            let _ = physics.world_mut().remove_object(old.0);
        }
        let desc = placed(&description.0, transform, entity);
        let mut commands = commands.entity(entity);
        commands.insert(ObjectLink { serial });
        match physics.world_mut().add_object(&desc) {
            Ok(id) => {
                entities.link_object(id, entity);
                commands.insert(InteractionObject(id));
                if !named {
                    commands.insert(Name::new(desc.name.clone()));
                }
            }
            Err(error) => {
                warn!("object {entity} ({:?}) not added: {error}", desc.name);
                commands.try_remove::<InteractionObject>();
                commands.trigger(|entity| ObjectRejected { entity, error });
            }
        }
    }
}

/// `desc` placed by the entity's transform.
fn placed(desc: &ObjectDesc, transform: &Transform, entity: Entity) -> ObjectDesc {
    let position = convert::to_core_vec3(transform.translation);
    let rotation = convert::to_core_quat(transform.rotation);
    let unplaced = desc.position == glam::Vec3::ZERO && desc.rotation == glam::Quat::IDENTITY;
    if !unplaced && (desc.position, desc.rotation) != (position, rotation) {
        warn!(
            "object {entity} ({:?}): its Transform places it, not its description's position",
            desc.name
        );
    }
    ObjectDesc { position, rotation, ..desc.clone() }
}

/// Removes an entity's object from the world when its
/// [`InteractionObject`] goes (the entity despawned, or the component
/// removed), if it is the current world's.
pub(crate) fn remove_object(
    removed: On<Remove, InteractionObject>,
    objects: Query<&InteractionObject>,
    physics: Option<ResMut<HandPhysics>>,
    entities: Res<InteractionEntities>,
) {
    let (Some(mut physics), Ok(object)) = (physics, objects.get(removed.entity)) else { return };
    if entities.object(object.0) != Some(removed.entity) || !entities.is_for(&physics) {
        return;
    }
    // The only error is an id the world no longer has: nothing to remove.
    let _ = physics.world_mut().remove_object(object.0);
}
