//! [`WorldError`]: why an [`super::InteractionWorld`] call was refused.

use crate::hand::{HandId, PoseError};
use crate::scene::{ObjectError, ObjectId};

/// Errors of [`super::InteractionWorld`] calls.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WorldError {
    /// A hand pose was rejected.
    #[error(transparent)]
    Pose(#[from] PoseError),
    /// An object or static description was rejected.
    #[error(transparent)]
    Object(#[from] ObjectError),
    /// The config was rejected.
    #[error(transparent)]
    Config(#[from] super::ConfigError),
    /// No hand has this id.
    #[error("{0} does not exist")]
    NoSuchHand(HandId),
    /// No object has this id.
    #[error("{0} does not exist")]
    NoSuchObject(ObjectId),
}
