//! What an app needs: `use coulomb_hands_bevy::prelude::*;`.

pub use crate::clock::{HandClock, HandPhysicsStep};
pub use crate::contacts::{
    ContactBegan, ContactChange, ContactEnded, ContactView, Contacts, ObjectReleased, ObjectTouched,
};
pub use crate::entities::{
    BoneSize, HandBone, InteractionEntities, InteractionHand, InteractionObject,
};
pub use crate::input::{AppHand, HandInput, JointsError};
pub use crate::objects::{ObjectDescription, ObjectRejected};
pub use crate::physics::{HandPhysics, HandPhysicsReplaced, Stopped};
pub use crate::{CoulombHandsPlugin, HandPhysicsSystems, WorldStep};
