//! Stage 0: the hands that act follow the tracked hands
//! ([`crate::hand::acting`]), each by one step.

use crate::pipeline::InteractionWorld;

impl InteractionWorld {
    /// Moves each tracked hand that acts one step after its tracked pose,
    /// with the config's tracking filter; a hand whose acting pose changed
    /// gets a new mark.
    pub(super) fn follow_hands(&mut self) {
        let dt = self.config.dt;
        for slot in &mut self.hands {
            let (Some(acting), Some(tracked), Some(pose)) =
                (slot.acting.as_mut(), slot.tracked.as_ref(), slot.pose.as_mut())
            else {
                continue;
            };
            if acting.advance(tracked, pose, dt) {
                slot.pose_mark += 1;
            }
        }
    }
}
