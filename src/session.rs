//! Recording a session's input (scene, settings and every step's hand
//! poses) to a file, and replaying it. Replays are deterministic: the same
//! file gives bit-identical object trajectories.

use crate::hand::{HandPose, Side};
use crate::object::{ObjectDesc, ObjectId, StaticDesc};
use crate::pipeline::{HandId, InteractionConfig, InteractionWorld, ObjectState, WorldError};
use std::path::Path;

/// The file's format marker.
pub const FORMAT: &str = "coulomb-hands-session/1";

/// Everything needed to reproduce a session.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Session {
    /// Always [`FORMAT`].
    pub format: String,
    pub config: InteractionConfig,
    pub statics: Vec<StaticDesc>,
    pub objects: Vec<ObjectDesc>,
    /// One entry per hand, in the order hands were added.
    pub hands: Vec<Side>,
    /// Per physics step, per hand: the pose set before the step, or `None`
    /// when the hand was untracked.
    pub steps: Vec<Vec<Option<HandPose>>>,
}

/// Why a session file could not be read or written.
#[derive(Debug, thiserror::Error)]
pub enum SessionError {
    #[error("{path}: {reason}")]
    File { path: String, reason: String },
}

impl Session {
    /// A session over a scene, with no steps yet.
    pub fn new(config: InteractionConfig, statics: Vec<StaticDesc>, objects: Vec<ObjectDesc>, hands: Vec<Side>) -> Self {
        Session { format: FORMAT.to_string(), config, statics, objects, hands, steps: Vec::new() }
    }

    /// Builds the session's world: statics, then objects, then hands, so
    /// ids follow the lists' order.
    pub fn world(&self) -> Result<(InteractionWorld, Vec<ObjectId>, Vec<HandId>), WorldError> {
        let mut world = InteractionWorld::new(self.config)?;
        for s in &self.statics {
            world.add_static(s)?;
        }
        let objects = self.objects.iter().map(|o| world.add_object(o)).collect::<Result<Vec<_>, _>>()?;
        let hands = self.hands.iter().map(|&side| world.add_hand(side)).collect();
        Ok((world, objects, hands))
    }

    /// Sets this step's poses on `world`, steps it, and records the poses.
    pub fn step(&mut self, world: &mut InteractionWorld, hands: &[HandId], poses: Vec<Option<HandPose>>) -> Result<(), WorldError> {
        apply(world, hands, &poses)?;
        world.step();
        self.steps.push(poses);
        Ok(())
    }

    /// Replays every recorded step into a fresh world; `each` sees the
    /// world after each step. Returns the final world.
    pub fn replay(&self, mut each: impl FnMut(usize, &InteractionWorld)) -> Result<InteractionWorld, (usize, WorldError)> {
        let (mut world, _, hands) = self.world().map_err(|e| (0, e))?;
        for (i, poses) in self.steps.iter().enumerate() {
            apply(&mut world, &hands, poses).map_err(|e| (i, e))?;
            world.step();
            each(i, &world);
        }
        Ok(world)
    }

    pub fn save(&self, path: &Path) -> Result<(), SessionError> {
        let fail = |reason: String| SessionError::File { path: path.display().to_string(), reason };
        let text = serde_json::to_string(self).map_err(|e| fail(e.to_string()))?;
        std::fs::write(path, text).map_err(|e| fail(e.to_string()))
    }

    pub fn load(path: &Path) -> Result<Session, SessionError> {
        let fail = |reason: String| SessionError::File { path: path.display().to_string(), reason };
        let text = std::fs::read_to_string(path).map_err(|e| fail(e.to_string()))?;
        let session: Session = serde_json::from_str(&text).map_err(|e| fail(format!("line {} column {}: {e}", e.line(), e.column())))?;
        if session.format != FORMAT {
            return Err(fail(format!("format is \"{}\", expected \"{FORMAT}\"", session.format)));
        }
        if let Some((i, step)) = session.steps.iter().enumerate().find(|(_, s)| s.len() != session.hands.len()) {
            return Err(fail(format!("step {i} has {} poses for {} hands", step.len(), session.hands.len())));
        }
        Ok(session)
    }
}

fn apply(world: &mut InteractionWorld, hands: &[HandId], poses: &[Option<HandPose>]) -> Result<(), WorldError> {
    for (hand, pose) in hands.iter().zip(poses) {
        match pose {
            Some(p) => world.set_hand_pose(*hand, p)?,
            None => world.clear_hand_pose(*hand)?,
        }
    }
    Ok(())
}

/// The states of all objects, in id order.
pub fn object_states(world: &InteractionWorld) -> Vec<ObjectState> {
    (0..world.object_count() as u32).filter_map(|i| world.object_state(ObjectId(i)).ok()).collect()
}
