//! What hands touch: objects, their materials and shapes, static scenery,
//! and scenes of them read from files.
//!
//! * [`object`]: [`ObjectDesc`], [`StaticDesc`], shapes and γ modes;
//! * [`material`]: the skin-vs-material friction table, with sources;
//! * [`mesh`]: triangle meshes from files, voxelized or decomposed;
//! * [`mod@file`]: JSON scene files;
//! * [`tower`]: the 54-block tower of the thesis's Jenga scenes.
//!
//! Everything here is a description: nothing touches a physics world
//! until [`crate::InteractionWorld`] adds it, after checking it whole.

pub mod file;
pub mod gamma;
pub mod material;
pub mod mesh;
pub mod object;
pub mod tower;

pub use file::{Ground, Scene, SceneError};
pub use material::Material;
pub use object::{
    GammaError, GammaMode, HandSurface, MeshBody, MeshShape, ObjectDesc, ObjectError, ObjectId,
    Part, ShapeDesc, StaticDesc,
};
pub use tower::Tower;
