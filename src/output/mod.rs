//! What a run leaves behind: per-step trace lines, recorded sessions, and
//! (re-exported from where the pipeline makes them) contact events and
//! object states.
//!
//! * [`trace`]: the JSON Lines trace of `replay --trace` and
//!   `scenario --trace`;
//! * [`session`]: a world's every call, to a file and back, bit for bit;
//! * [`report`]: the self-contained HTML report of `coulomb-hands report`.

pub mod report;
pub mod session;
pub mod trace;

pub use crate::contact::{ContactEvent, ContactEventKind};
pub use crate::pipeline::ObjectState;
pub use session::{Session, SessionError};
pub use trace::{TraceHand, TraceLine, TraceObject};
