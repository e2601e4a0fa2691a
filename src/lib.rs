//! coulomb-hands: tracked hands move virtual objects only through Coulomb
//! friction contact forces, on top of rapier3d.
//!
//! The data path is the module layout:
//! [`input`] (recordings, trackers, coordinate conversions) →
//! [`hand`] (tracked skeletal poses) → [`contact`] (contact points, skin
//! patches, slipping surface points) → [`friction`] (the pure contact law,
//! thesis Eq. 3.4–3.11) → [`pipeline`] (applies the forces and steps rapier).
//!
//! ```
//! use coulomb_hands::{InteractionConfig, InteractionWorld, ObjectDesc, Side, StaticDesc};
//! use glam::{Quat, Vec3};
//!
//! # fn main() -> Result<(), coulomb_hands::WorldError> {
//! let mut world = InteractionWorld::new(InteractionConfig::default())?;
//! world.add_static(&StaticDesc::ground(0.0, 0.5))?;
//! let cube = world.add_object(&ObjectDesc::cuboid("cube", Vec3::splat(0.05), 0.05, Vec3::new(0.0, 0.025, 0.0)))?;
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

pub mod contact;
pub mod file_error;
pub mod friction;
pub mod hand;
pub mod input;
pub mod material;
pub mod mesh;
pub mod object;
pub mod pipeline;
pub mod replay;
pub mod scenario;
pub mod scene;
pub mod scenes;
pub mod session;

pub use contact::{Contact, ContactEvent, ContactEventKind};
pub use file_error::FileError;
pub use friction::{FrictionCoefficients, FrictionState, KineticFriction};
pub use hand::{Bone, Capsule, Finger, HandPose, Palm, Phalanx, PoseError, Side};
pub use material::Material;
pub use object::{GammaMode, MeshBody, MeshShape, ObjectDesc, ObjectError, ObjectId, ShapeDesc, StaticDesc};
pub use pipeline::{ConfigError, HandId, InteractionConfig, InteractionWorld, ObjectFriction, ObjectState, WorldError};
