//! coulomb-hands: tracked hands move virtual objects only through Coulomb
//! friction contact forces, on top of rapier3d.
//!
//! The data path is the module layout:
//! [`input`] (recordings, trackers, coordinate conversions) →
//! [`hand`] (tracked skeletal poses) → [`contact`] (contact points, skin
//! patches, slipping surface points) → [`friction`] (the pure contact law,
//! thesis Eq. 3.4–3.11) → [`pipeline`] (applies the forces and steps
//! rapier) → [`output`] (traces, sessions, the HTML report). What hands touch is in
//! [`scene`]; [`run`] drives worlds through time (replays, scenarios, the
//! live stream, the demo).
//!
//! ```
//! use coulomb_hands::{InteractionConfig, InteractionWorld, ObjectDesc, Side, StaticDesc};
//! use glam::{Quat, Vec3};
//!
//! # fn main() -> Result<(), coulomb_hands::WorldError> {
//! let mut world = InteractionWorld::new(InteractionConfig::default())?;
//! world.add_static(&StaticDesc::ground(0.0, 0.5))?;
//! let size = Vec3::splat(0.05);
//! let at = Vec3::new(0.0, 0.025, 0.0);
//! let cube = world.add_object(&ObjectDesc::cuboid("cube", size, 0.05, at))?;
//! let hand = world.add_hand(Side::Right);
//! let rig = coulomb_hands::hand::rig::HandRig::adult(Side::Right);
//! let pose = rig.pose(Vec3::new(0.0, 0.3, 0.0), Quat::IDENTITY, [0.0; 5]);
//! world.set_hand_pose(hand, &pose)?;
//! world.step();
//! assert!(world.contacts().is_empty()); // the hand is 30 cm above the cube
//! assert!(world.object_state(cube)?.position.y > 0.0);
//! # Ok(())
//! # }
//! ```

#![warn(missing_docs)]

pub mod contact;
pub mod eval;
pub mod file_error;
pub mod files;
pub mod friction;
pub mod grab;
pub mod hand;
pub mod input;
pub mod output;
pub mod pipeline;
pub mod run;
pub mod scene;

pub use contact::{Contact, ContactEvent, ContactEventKind};
pub use file_error::FileError;
pub use friction::{FrictionCoefficients, FrictionState, KineticFriction};
pub use hand::{
    Bone, Capsule, Finger, HandId, HandPose, HandSample, Palm, Phalanx, PoseError, Side,
};
pub use pipeline::{
    ConfigError, HandWrench, HostBody, InteractionConfig, InteractionWorld, Method, ObjectFriction,
    ObjectState, WorldError,
};
pub use run::RunError;
pub use scene::{
    GammaMode, HandSurface, Material, MeshBody, MeshShape, ObjectDesc, ObjectError, ObjectId,
    ShapeDesc, StaticDesc,
};
