//! Observers that most runs share: the trace writer and the summary of
//! what each object did.

use super::RunError;
use super::drive::{Observer, StepView};
use crate::contact::ContactEventKind;
use crate::output::{TraceHand, TraceLine};
use crate::pipeline::{InteractionWorld, WorldError};
use glam::Vec3;
use std::io::Write;

/// Writes one trace line per step ([`crate::output::trace`]).
pub struct TraceWriter<W: Write> {
    out: W,
}

impl<W: Write> TraceWriter<W> {
    /// A writer of trace lines to `out`.
    pub fn new(out: W) -> Self {
        TraceWriter { out }
    }

    /// Flushes and returns the output.
    pub fn finish(mut self) -> Result<W, RunError> {
        self.out.flush()?;
        Ok(self.out)
    }
}

/// The trace line of a step: the tracked hands, then every object.
pub fn trace_line(step: &StepView) -> TraceLine {
    let hands = step
        .hands
        .iter()
        .filter_map(|h| {
            let acting = step.world.hand_pose(h.id);
            h.sample.as_ref().map(|s| TraceHand::of(h.label, h.side, s, acting))
        })
        .collect();
    TraceLine::of(step.world, hands)
}

impl<W: Write> Observer for TraceWriter<W> {
    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        trace_line(step).write(&mut self.out)?;
        Ok(())
    }
}

/// What happened to one object over a run.
#[derive(Debug, Clone, serde::Serialize)]
pub struct ObjectSummary {
    /// Its name in the scene.
    pub name: String,
    /// Start-to-end displacement (m).
    pub displacement: f32,
    /// Largest speed during the run (m/s).
    pub max_speed: f32,
    /// Where it started and ended (m).
    pub start: [f32; 3],
    /// Where it ended (m).
    pub end: [f32; 3],
}

/// Counts contacts begun, and follows every object's top speed, and
/// whether every traced number stayed finite.
#[derive(Debug, Clone)]
pub struct Summary {
    start: Vec<Vec3>,
    max_speed: Vec<f32>,
    /// Contacts begun so far.
    pub contacts_begun: usize,
    /// Whether every hand and object number so far was finite.
    pub all_finite: bool,
}

impl Summary {
    /// A summary from `world`'s objects as they are now.
    pub fn new(world: &InteractionWorld) -> Result<Summary, WorldError> {
        let mut summary = Summary {
            start: Vec::new(),
            max_speed: Vec::new(),
            contacts_begun: 0,
            all_finite: true,
        };
        summary.follow_new_objects(world);
        Ok(summary)
    }

    /// Follows the objects added since the last call, by id, from where
    /// they are now (one removed before it was seen, from nowhere).
    fn follow_new_objects(&mut self, world: &InteractionWorld) {
        for (_, state) in world.object_slots().skip(self.start.len()) {
            self.start.push(state.map_or(Vec3::NAN, |s| s.position));
            self.max_speed.push(0.0);
        }
    }

    /// Each object's summary, ending where it is in `world` now; a
    /// removed object has none.
    pub fn objects(&self, world: &InteractionWorld) -> Result<Vec<ObjectSummary>, WorldError> {
        let mut out = Vec::new();
        for id in world.object_ids() {
            let end = world.object_state(id)?.position;
            let k = id.0 as usize;
            // An object added since the last step observed starts now.
            let start = self.start.get(k).copied().unwrap_or(end);
            out.push(ObjectSummary {
                name: world.object_name(id).unwrap_or("").to_string(),
                displacement: (end - start).length(),
                max_speed: self.max_speed.get(k).copied().unwrap_or(0.0),
                start: start.to_array(),
                end: end.to_array(),
            });
        }
        Ok(out)
    }
}

impl Summary {
    /// Counts this step's contacts begun and follows the objects' speeds,
    /// for a world stepped without hand sources (a session replay).
    /// An object added during the run is followed from where it is first
    /// seen.
    pub fn observe_world(&mut self, world: &InteractionWorld) -> Result<(), WorldError> {
        self.follow_new_objects(world);
        let began = world.events().iter().filter(|e| e.kind == ContactEventKind::Began);
        self.contacts_begun += began.count();
        for id in world.object_ids() {
            let s = world.object_state(id)?;
            let max = &mut self.max_speed[id.0 as usize];
            *max = max.max(s.linvel.length());
            self.all_finite &=
                s.position.is_finite() && s.rotation.is_finite() && s.linvel.is_finite();
        }
        Ok(())
    }
}

impl Observer for Summary {
    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        let hands = step.hands.iter().filter_map(|h| h.sample.as_ref());
        self.all_finite &= hands.map(|s| s.pose.palm_surface()).all(|p| p.is_finite());
        Ok(self.observe_world(step.world)?)
    }
}
