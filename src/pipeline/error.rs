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
    /// A grab baseline was asked to step in host mode, where the host's
    /// bodies cannot be carried from here.
    #[error(
        "the {0:?} grab baseline moves objects itself, which a host's bodies cannot be made to \
         do: host mode takes the friction methods (coulomb, thesis)"
    )]
    HostGrab(crate::grab::GrabMethod),
}
