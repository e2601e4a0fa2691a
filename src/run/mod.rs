//! Running worlds: everything that drives an [`crate::InteractionWorld`]
//! through time goes through one loop, [`drive::Driver`].
//!
//! * [`drive`]: the driver loop, hand sources and observers;
//! * [`observe`]: the trace writer and the per-object summary;
//! * [`replay`]: recordings replayed, with objects at a recorded grasp
//!   ([`grasp`] finds where a recorded hand closes, [`closing`] judges
//!   each closing's hold, [`held`] is the object put there and whether a
//!   hand holds it);
//! * [`soak`]: a recording replayed in a loop in one world, watching
//!   memory and speed by the system's clock (not on wasm32);
//! * [`live`]: a live Leap Motion stream (feature `live`, on by default);
//! * [`scenario`]: the interaction catalogue, scenario files and checks;
//! * [`demo`]: the scripted grasp-lift-carry demo;
//! * [`report`]: the scenario and replay runs that `coulomb-hands report`
//!   shows;
//! * [`sampled`]: a hand a program poses at its own frame or tracker rate,
//!   stepped at the physics rate (the rule the Bevy plugin and the web page
//!   share);
//! * [`mod@bench`]: the benchmark scenes, their timing and MuJoCo's side;
//! * [`clock`]: the wall clock the timed runs are given;
//! * [`euler_host`]: a host engine in a few lines, semi-implicit Euler, for
//!   host mode's tests and measurements.

pub mod bench;
pub mod capture;
pub mod clock;
pub mod closing;
pub mod demo;
pub mod drive;
pub mod euler_host;
pub mod grasp;
pub mod held;
#[cfg(feature = "live")]
pub mod live;
pub mod observe;
pub mod replay;
pub mod report;
pub mod sampled;
pub mod scenario;
#[cfg(not(target_arch = "wasm32"))]
pub mod soak;

use crate::file_error::FileError;
use crate::input::InputError;
use crate::output::SessionError;
use crate::pipeline::WorldError;

/// Why a run failed: whatever it read, built, drove or wrote.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// A recording or stream was bad, or the stream failed.
    #[error(transparent)]
    Input(#[from] InputError),
    /// The world rejected a call.
    #[error(transparent)]
    World(#[from] WorldError),
    /// A session could not be read, written or replayed.
    #[error(transparent)]
    Session(#[from] SessionError),
    /// A scene or scenario file was bad.
    #[error(transparent)]
    File(#[from] FileError),
    /// Writing an output (a trace) failed.
    #[error("output: {0}")]
    Output(#[from] std::io::Error),
    /// A study's option is out of range.
    #[error("study: {field}: {reason}")]
    Study {
        /// The option, as the command line names it.
        field: &'static str,
        /// What is wrong with its value.
        reason: String,
    },
    /// An object was asked for at a grasp the recording does not have.
    #[error(
        "the recording has {found} grasps held long enough to judge, so there is no grasp {}",
        wanted + 1
    )]
    NoGrasp {
        /// Grasps the recording has that hold long enough to judge.
        found: usize,
        /// The grasp asked for (0 is the first).
        wanted: usize,
    },
}
