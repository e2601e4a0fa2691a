//! Recording a session (every call that builds and drives a world: scene,
//! hands, poses, fixtures, steps) to a file, and replaying it. Replays are
//! deterministic: the same file gives bit-identical object trajectories.
//!
//! A [`Session`] is the world's [`Recorder`]: start one with
//! [`Session::start`] on a new world, take it back with [`Session::take`].
//! Changes made directly through `physics_mut()` are not recorded.

use crate::hand::HandId;
use crate::pipeline::{
    Call, InteractionConfig, InteractionWorld, ObjectState, Recorder, WorldError,
};
use crate::scene::ObjectId;
use std::path::Path;

/// The file's format marker.
pub const FORMAT: &str = "coulomb-hands-session/1";

/// How a session written before a config field existed ran.
type AsItRan = fn(&mut InteractionConfig);

/// Config fields added since [`FORMAT`] began, as they appear in a session
/// file, and how a session written before each ran.
const FIELDS_ADDED: [(&str, AsItRan); 1] = [("\"line_contacts\"", |c| c.line_contacts = false)];

/// A recorded session.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Session {
    /// Always [`FORMAT`].
    pub format: String,
    /// The world's config.
    pub config: InteractionConfig,
    /// The calls, in order.
    pub calls: Vec<Call>,
}

/// Why a session file could not be read, written or replayed.
#[derive(Debug, thiserror::Error)]
pub enum SessionError {
    /// The file could not be read or written, or is not a session.
    #[error("{path}: {reason}")]
    File {
        /// The file.
        path: String,
        /// What went wrong.
        reason: String,
    },
    /// The session's config was rejected on replay.
    #[error("session {0}")]
    Config(WorldError),
    /// A recorded call failed on replay.
    #[error("session call {call}: {source}")]
    Replay {
        /// Its index in [`Session::calls`].
        call: usize,
        /// The world's error.
        source: WorldError,
    },
}

impl SessionError {
    /// The error as one of the session file at `path`, for messages: a
    /// replay's error then names the file too.
    pub fn in_file(self, path: &Path) -> SessionError {
        match self {
            SessionError::File { .. } => self,
            e => SessionError::File { path: path.display().to_string(), reason: e.to_string() },
        }
    }
}

impl Recorder for Session {
    fn record(&mut self, call: &Call) {
        self.calls.push(call.clone());
    }
}

impl Session {
    /// An empty session of a world with this config.
    pub fn new(config: InteractionConfig) -> Self {
        Session { format: FORMAT.to_string(), config, calls: Vec::new() }
    }

    /// Records every later call on `world`. Start it on a new world: calls
    /// made before are not in the session.
    pub fn start(world: &mut InteractionWorld) {
        world.set_recorder(Box::new(Session::new(*world.config())));
    }

    /// Stops recording on `world` and returns the session, if it was
    /// recording one.
    pub fn take(world: &mut InteractionWorld) -> Option<Session> {
        world.take_recorder::<Session>()
    }

    /// Number of recorded steps.
    pub fn steps(&self) -> usize {
        self.calls.iter().filter(|c| matches!(c, Call::Step | Call::HostStep)).count()
    }

    /// Replays every call into a fresh world; `each` sees the world after
    /// each step. Returns the final world.
    pub fn replay(
        &self,
        mut each: impl FnMut(&InteractionWorld),
    ) -> Result<InteractionWorld, SessionError> {
        let mut world = InteractionWorld::new(self.config).map_err(SessionError::Config)?;
        for (i, call) in self.calls.iter().enumerate() {
            let fail = |source| SessionError::Replay { call: i, source };
            match call {
                Call::AddStatic(s) => world.add_static(s).map(drop).map_err(fail)?,
                Call::AddObject(o) => world.add_object(o).map(drop).map_err(fail)?,
                Call::AddHand(side) => drop(world.add_hand(*side)),
                Call::SetHandPose(h, pose) => {
                    world.set_hand_pose(HandId(*h), pose).map_err(fail)?
                }
                Call::ClearHandPose(h) => world.clear_hand_pose(HandId(*h)).map_err(fail)?,
                Call::SetObjectLocked(o, locked) => {
                    world.set_object_locked(ObjectId(*o), *locked).map_err(fail)?
                }
                Call::ReseatContacts(o) => world.reseat_contacts(ObjectId(*o)).map_err(fail)?,
                Call::PlaceObject(o, position, rotation) => {
                    world.place_object(ObjectId(*o), *position, *rotation).map_err(fail)?
                }
                Call::RemoveObject(o) => world.remove_object(ObjectId(*o)).map_err(fail)?,
                Call::Step => {
                    world.step();
                    each(&world);
                }
                Call::SetHostBody(o, state) => {
                    world.set_host_body(ObjectId(*o), state).map_err(fail)?
                }
                Call::HostStep => {
                    world.host_step().map_err(fail)?;
                    each(&world);
                }
            }
        }
        Ok(world)
    }

    /// Writes the session as JSON.
    pub fn save(&self, path: &Path) -> Result<(), SessionError> {
        let fail = |reason: String| SessionError::File { path: path.display().to_string(), reason };
        let text = serde_json::to_string(self).map_err(|e| fail(e.to_string()))?;
        std::fs::write(path, text).map_err(|e| fail(e.to_string()))
    }

    /// Reads a session file written by [`Self::save`], and checks its
    /// config.
    pub fn load(path: &Path) -> Result<Session, SessionError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path)
            .map_err(|e| SessionError::File { path: file.clone(), reason: e.to_string() })?;
        Self::parse(&file, &text)
    }

    /// Parses session text (`file` names it in errors) and checks its
    /// format marker. The calls themselves are checked when replayed.
    pub fn parse(file: &str, text: &str) -> Result<Session, SessionError> {
        let fail = |reason: String| SessionError::File { path: file.to_string(), reason };
        let mut session: Session =
            serde_json::from_str(text).map_err(|e| fail(crate::file_error::json_reason(&e)))?;
        // A session records every field of its config. One written before a
        // field existed ran without what it turns on, and replays so.
        for (field, as_it_ran) in FIELDS_ADDED {
            if !text.contains(field) {
                as_it_ran(&mut session.config);
            }
        }
        if session.format != FORMAT {
            return Err(fail(format!("format is \"{}\", expected \"{FORMAT}\"", session.format)));
        }
        session.config.validate().map_err(|e| fail(e.to_string()))?;
        Ok(session)
    }

    /// Whether a file looks like a session (by its format marker).
    pub fn sniff(text: &str) -> bool {
        text.trim_start().starts_with('{') && text.contains(FORMAT)
    }
}

/// The states of all objects, in id order.
pub fn object_states(world: &InteractionWorld) -> Vec<ObjectState> {
    world.object_ids().filter_map(|id| world.object_state(id).ok()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_session_written_before_line_contacts_replays_without_them() {
        let now = serde_json::to_string(&Session::new(InteractionConfig::default())).unwrap();
        assert!(Session::parse("now", &now).unwrap().config.line_contacts);
        let before = now.replace(r#""line_contacts":true,"#, "");
        assert_ne!(before, now);
        assert!(!Session::parse("before", &before).unwrap().config.line_contacts);
    }
}
