//! A hand a program poses at its own rate (a display's frames at 60 to
//! 120 Hz, a headset's or a webcam's tracker at 30 to 90 Hz) while the
//! physics steps at its own (1 kHz): the one rule every binding uses to
//! step such a hand across the physics steps between two of its samples.
//!
//! Each sample comes with the time it is due on the world's clock (the
//! last physics step of the program's frame), and the hand goes there in
//! a straight line from where it last was: the pose by
//! [`crate::hand::HandPose::lerp`], the strengths linearly. Held instead,
//! the pose would stand still for a frame's steps and then jump in one:
//! the bones' velocities, each step's change of pose over `dt`, would be
//! zero for all of a frame's steps but one, and that one as many times the
//! hand's speed as the frame has steps. The contacts' dampers would feel
//! the jump; a ramp moves the hand at the speed its samples give. What
//! it costs is the time to get there: a sample is reached when it is due,
//! half a frame later on average than a held one, and never passed (no
//! extrapolation, which would overshoot every stop).
//!
//! * A sample due no later than the step after the last is taken at once:
//!   a program that poses its hand before every single step poses it as
//!   the world's own `set_hand_pose` does.
//! * Past its due time the hand holds the sample until the next one.
//! * A hand that was lost, or never seen, starts where it is first seen:
//!   nothing ramps in from nowhere. A lost hand (`None`) is lost at once.

use super::RunError;
use super::drive::HandSource;
use crate::hand::{HandId, HandSample, Side};
use crate::pipeline::{InteractionWorld, WorldError};
use std::sync::{Arc, Mutex, PoisonError};

/// A hand posed by a program at its own rate, stepped at the physics
/// rate as this module says. Clones share one hand: a program keeps one
/// to [`SampledHand::set`], and gives another to the driver as the
/// hand's source.
#[derive(Debug, Clone)]
pub struct SampledHand {
    side: Side,
    ramp: Arc<Mutex<Ramp>>,
}

/// A due time that is not a time.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("hand sample: the time it is due must be finite, got {0} s")]
pub struct DueError(pub f64);

/// Where the hand was last given and where it goes.
#[derive(Debug, Default)]
struct Ramp {
    /// The sample last given and when (world clock, s); `None` while lost.
    shown: Option<(f64, HandSample)>,
    /// The newest sample and when it is due (world clock, s); `None`
    /// while the hand is lost.
    next: Option<(f64, HandSample)>,
}

impl SampledHand {
    /// A `side` hand, lost until it is first set.
    pub fn new(side: Side) -> SampledHand {
        SampledHand { side, ramp: Arc::default() }
    }

    /// The hand's newest sample, due at `due` (world clock, s), or `None`
    /// when the tracker lost it. The pose is checked when the world takes
    /// it, at the next step.
    pub fn set(&self, due: f64, sample: Option<HandSample>) -> Result<(), DueError> {
        if !due.is_finite() {
            return Err(DueError(due));
        }
        let mut ramp = self.ramp.lock().unwrap_or_else(PoisonError::into_inner);
        match sample {
            Some(sample) => ramp.next = Some((due, sample)),
            None => *ramp = Ramp::default(),
        }
        Ok(())
    }

    /// When the newest sample is due (world clock, s); `None` while lost.
    pub fn due(&self) -> Option<f64> {
        self.ramp.lock().unwrap_or_else(PoisonError::into_inner).next.as_ref().map(|n| n.0)
    }

    /// The hand at `t` (world clock, s): on its way to the newest sample.
    pub fn at(&self, t: f64) -> Option<HandSample> {
        self.ramp.lock().unwrap_or_else(PoisonError::into_inner).at(t)
    }
}

impl Ramp {
    fn at(&mut self, t: f64) -> Option<HandSample> {
        let (due, target) = self.next.as_mut()?;
        let hand = match &self.shown {
            // On the way: from where it was, the share of the time left.
            Some((was, from)) if *was < t && t < *due => {
                from.lerp(target, ((t - was) / (*due - was)) as f32)
            }
            // Found, due already, or a clock that went back (a new world):
            // where the sample says, and held there from now on.
            _ => {
                *due = due.min(t);
                target.clone()
            }
        };
        self.shown = Some((t, hand.clone()));
        Some(hand)
    }
}

/// The hands a program poses once per frame of its own and then steps the
/// world by the frame's steps (a web page, a C or Python caller): what
/// [`SampledHand`] is to a driver, for a world stepped directly. Each
/// hand's pose set since the last steps is reached at the last of the
/// next ones.
#[derive(Debug, Default)]
pub struct FrameHands {
    hands: Vec<FrameHand>,
}

/// One of [`FrameHands`].
#[derive(Debug)]
struct FrameHand {
    id: HandId,
    hand: SampledHand,
    /// The sample set since the last steps, due at the last of the next
    /// steps, when their count is known.
    waiting: Option<HandSample>,
    /// Whether the world has been given the hand's newest sample: it holds
    /// it from then on without being given it again.
    settled: bool,
}

impl FrameHands {
    /// Poses `world`'s hand `hand` by `sample` over its next steps, or
    /// loses it (`None`). A hand the world does not track yet is posed at
    /// once, and a lost one is lost at once, as
    /// [`InteractionWorld::set_hand_pose`] and
    /// [`InteractionWorld::clear_hand_pose`] do. The hand and pose are
    /// checked first: a bad one is an error and changes nothing.
    pub fn set(
        &mut self,
        world: &mut InteractionWorld,
        hand: HandId,
        sample: Option<HandSample>,
    ) -> Result<(), WorldError> {
        let side = world.hand_side(hand).ok_or(WorldError::NoSuchHand(hand))?;
        if let Some(s) = &sample {
            s.pose.validate(hand.0)?;
        }
        let at = match self.hands.iter().position(|h| h.id == hand) {
            Some(at) => at,
            None => {
                let hand = FrameHand {
                    id: hand,
                    hand: SampledHand::new(side),
                    waiting: None,
                    settled: false,
                };
                self.hands.push(hand);
                self.hands.len() - 1
            }
        };
        let h = &mut self.hands[at];
        let now = world.time();
        match sample {
            Some(sample) if world.hand_pose(hand).is_some() => {
                h.waiting = Some(sample);
                return Ok(());
            }
            Some(sample) => {
                world.set_hand_pose(hand, &sample.pose)?;
                // A world's time is finite: this cannot fail. Found now,
                // from where the next ramp starts.
                let _ = h.hand.set(now, Some(sample));
                h.hand.at(now);
            }
            None => {
                world.clear_hand_pose(hand)?;
                let _ = h.hand.set(now, None);
            }
        }
        (h.waiting, h.settled) = (None, true);
        Ok(())
    }

    /// `n` steps of `world`, each after [`Self::pose`]: its hands reach
    /// the poses set since the last steps at the last of these.
    pub fn step(&mut self, world: &mut InteractionWorld, n: usize) -> Result<(), WorldError> {
        self.begin(world, n);
        for _ in 0..n {
            self.pose(world)?;
            world.step();
        }
        Ok(())
    }

    /// Before `world`'s next `n` steps: the poses set since the last steps
    /// are due at the last of them (nothing is due before a step).
    pub fn begin(&mut self, world: &InteractionWorld, n: usize) {
        let Some(last) = n.checked_sub(1) else { return };
        let due = world.time() + last as f64 * f64::from(world.config().dt);
        for h in &mut self.hands {
            if let Some(sample) = h.waiting.take() {
                // A world's time and step are finite: this cannot fail.
                let _ = h.hand.set(due, Some(sample));
                h.settled = false;
            }
        }
    }

    /// Before each step: every hand where its samples put it at the
    /// world's time; a hand that has reached its newest sample is left
    /// holding it, as a world holds a pose it was given once (its ramp
    /// still marks the step, where the next one starts).
    pub fn pose(&mut self, world: &mut InteractionWorld) -> Result<(), WorldError> {
        let t = world.time();
        for h in &mut self.hands {
            let reached = h.hand.due().is_none_or(|due| due <= t);
            let sample = h.hand.at(t);
            if h.settled {
                continue;
            }
            match sample {
                Some(sample) => world.set_hand_pose(h.id, &sample.pose)?,
                None => world.clear_hand_pose(h.id)?,
            }
            h.settled = reached;
        }
        Ok(())
    }
}

impl HandSource for SampledHand {
    fn side(&self) -> Side {
        self.side
    }

    fn sample(&mut self, t: f64) -> Result<Option<HandSample>, RunError> {
        Ok(self.at(t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hand::rig::HandRig;
    use glam::{Quat, Vec3};

    fn at(x: f32, grab: Option<f32>) -> HandSample {
        let pose =
            HandRig::adult(Side::Right).pose(Vec3::new(x, 0.2, 0.0), Quat::IDENTITY, [0.3; 5]);
        HandSample { grab, ..HandSample::from_pose(pose) }
    }

    fn palm_x(s: &Option<HandSample>) -> f32 {
        s.as_ref().expect("tracked").pose.palm.center.x
    }

    #[test]
    fn a_sample_is_reached_in_a_straight_line_when_it_is_due_and_held_after() {
        let hand = SampledHand::new(Side::Right);
        hand.set(0.0, Some(at(0.0, Some(0.0)))).unwrap();
        assert_eq!(palm_x(&hand.at(0.0)), 0.0, "found where first seen");
        // A frame 11 ms later, due when the physics reaches it.
        hand.set(0.011, Some(at(0.022, Some(0.5)))).unwrap();
        let xs: Vec<f32> = (1..=13).map(|k| palm_x(&hand.at(k as f64 * 0.001))).collect();
        for (k, x) in xs.iter().enumerate().take(11) {
            let want = 0.002 * (k + 1) as f32;
            assert!((x - want).abs() < 1e-6, "step {}: {x} m, want {want}", k + 1);
        }
        assert_eq!(&xs[10..], &[0.022; 3], "held once due, never passed");
        let grab = hand.at(0.014).and_then(|s| s.grab);
        assert_eq!(grab, Some(0.5));
    }

    #[test]
    fn a_new_sample_mid_way_ramps_from_where_the_hand_is() {
        let hand = SampledHand::new(Side::Left);
        hand.set(0.0, Some(at(0.0, None))).unwrap();
        hand.at(0.0);
        hand.set(0.010, Some(at(0.05, None))).unwrap();
        let mid = palm_x(&hand.at(0.004));
        assert!((mid - 0.02).abs() < 1e-6, "{mid}");
        // Turned back before it arrived: from 2 cm back to 0 over 4 ms.
        hand.set(0.008, Some(at(0.0, None))).unwrap();
        let back = palm_x(&hand.at(0.006));
        assert!((back - 0.01).abs() < 1e-6, "{back}");
    }

    #[test]
    fn a_late_sample_is_taken_at_once_and_a_lost_hand_is_lost_at_once() {
        let hand = SampledHand::new(Side::Right);
        hand.set(0.0, Some(at(0.0, None))).unwrap();
        hand.at(0.0);
        hand.at(0.005);
        hand.set(0.003, Some(at(0.03, None))).unwrap();
        assert_eq!(palm_x(&hand.at(0.006)), 0.03);
        hand.set(0.1, None).unwrap();
        assert!(hand.at(0.007).is_none());
        // Found again far away: there at once, not ramped from the old place.
        hand.set(0.1, Some(at(0.4, None))).unwrap();
        assert_eq!(palm_x(&hand.at(0.008)), 0.4);
    }

    #[test]
    fn a_due_time_that_is_not_a_time_is_an_error_and_changes_nothing() {
        let hand = SampledHand::new(Side::Right);
        hand.set(0.0, Some(at(0.01, None))).unwrap();
        let err = hand.set(f64::NAN, Some(at(0.5, None))).unwrap_err();
        assert!(err.to_string().contains("due"), "{err}");
        assert_eq!(palm_x(&hand.at(0.0)), 0.01);
    }

    #[test]
    fn a_frames_pose_is_reached_at_its_last_step_and_one_step_poses_at_once() {
        use crate::pipeline::{InteractionConfig, InteractionWorld};
        let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
        let id = world.add_hand(Side::Right);
        let mut hands = FrameHands::default();
        let x = |w: &InteractionWorld| w.hand_pose(id).expect("posed").palm.center.x;
        hands.set(&mut world, id, Some(at(0.0, None))).unwrap();
        assert_eq!(x(&world), 0.0, "first seen: posed at once");
        hands.step(&mut world, 1).unwrap();
        assert_eq!(x(&world), 0.0);
        // One frame's 4 steps: a quarter of the way each.
        hands.set(&mut world, id, Some(at(0.008, None))).unwrap();
        let mut seen = Vec::new();
        hands.begin(&world, 4);
        for _ in 0..4 {
            hands.pose(&mut world).unwrap();
            world.step();
            seen.push(x(&world));
        }
        let want = [0.002, 0.004, 0.006, 0.008];
        assert!(seen.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-6), "{seen:?}");
        // Posed before a single step: there at that step, as set_hand_pose.
        hands.set(&mut world, id, Some(at(0.05, None))).unwrap();
        hands.step(&mut world, 1).unwrap();
        assert_eq!(x(&world), 0.05);
        // A bad hand or pose is refused and changes nothing.
        let mut bad = at(0.3, None);
        bad.pose.palm.center.y = f32::NAN;
        assert!(hands.set(&mut world, id, Some(bad)).is_err());
        assert!(hands.set(&mut world, HandId(7), Some(at(0.3, None))).is_err());
        hands.step(&mut world, 3).unwrap();
        assert_eq!(x(&world), 0.05);
        hands.set(&mut world, id, None).unwrap();
        assert!(world.hand_pose(id).is_none(), "lost at once");
        hands.step(&mut world, 2).unwrap();
        assert!(world.hand_pose(id).is_none());
        // Held for 5 steps, then a frame of 2: half the way at the first.
        hands.set(&mut world, id, Some(at(0.1, None))).unwrap();
        hands.step(&mut world, 5).unwrap();
        hands.set(&mut world, id, Some(at(0.104, None))).unwrap();
        hands.begin(&world, 2);
        hands.pose(&mut world).unwrap();
        world.step();
        assert!((x(&world) - 0.102).abs() < 1e-6, "{}", x(&world));
    }
}
