//! The driver loop, the one place where hands are posed and the world is
//! stepped: sample every hand source at the physics clock, set or clear
//! its pose, step, and show the step to every observer.
//!
//! Replays, scenarios, the live stream, the demo and the tests all run
//! through [`Driver::run`]; what differs is where poses come from
//! ([`HandSource`]) and who watches ([`Observer`]). An app with a loop of
//! its own (the Bevy plugin's fixed tick) calls [`Driver::step`], the
//! loop's body, once per tick; `run` is that body in a loop.

use super::RunError;
use crate::hand::{HandId, HandPose, HandSample, Side};
use crate::input::playback::Playback;
use crate::pipeline::{HandWrench, InteractionWorld};
use std::borrow::BorrowMut;
use std::sync::{Mutex, PoisonError};

/// Where one hand's poses come from, sampled on the physics clock.
///
/// `Send`, so that a world and its sources can live in an app's resource
/// and be stepped from whichever thread the app's scheduler picks.
pub trait HandSource: Send {
    /// Which hand it is.
    fn side(&self) -> Side;

    /// The tracker's id for this hand, for trace lines; `None` if it has
    /// none (the hand's index in the driver is used).
    fn tracker_id(&self) -> Option<i64> {
        None
    }

    /// The hand at `t` on the driver's clock (s), or `None` while it is
    /// not tracked. The clock is the world's time: it starts at 0 for a
    /// fresh world, and at the world's time when a [`Driver`] takes one
    /// that has already run.
    fn sample(&mut self, t: f64) -> Result<Option<HandSample>, RunError>;

    /// Whether the source has nothing more to give (a live stream that
    /// closed). The driver stops when every source has finished.
    fn finished(&self) -> bool {
        false
    }
}

/// A boxed or borrowed source is a source: the driver boxes its own, and
/// a caller that reads a source after the run lends it.
macro_rules! forward_hand_source {
    ($($source:ty),*) => {$(
        impl<S: HandSource + ?Sized> HandSource for $source {
            fn side(&self) -> Side {
                (**self).side()
            }

            fn tracker_id(&self) -> Option<i64> {
                (**self).tracker_id()
            }

            fn sample(&mut self, t: f64) -> Result<Option<HandSample>, RunError> {
                (**self).sample(t)
            }

            fn finished(&self) -> bool {
                (**self).finished()
            }
        }
    )*};
}

forward_hand_source!(Box<S>, &mut S);

/// A hand posed by a function of time (s): scripted motion, generated or
/// synthetic poses, tests.
pub struct PoseFn<F> {
    side: Side,
    pose: F,
}

impl<F: FnMut(f64) -> Option<HandPose> + Send> PoseFn<F> {
    /// A `side` hand whose pose at `t` is `pose(t)`, or untracked for `None`.
    pub fn new(side: Side, pose: F) -> Self {
        PoseFn { side, pose }
    }
}

impl<F: FnMut(f64) -> Option<HandPose> + Send> HandSource for PoseFn<F> {
    fn side(&self) -> Side {
        self.side
    }

    fn sample(&mut self, t: f64) -> Result<Option<HandSample>, RunError> {
        Ok((self.pose)(t).map(HandSample::from_pose))
    }
}

/// One hand of a recording, interpolated on the physics clock.
#[derive(Debug, Clone, Copy)]
pub struct RecordedHand<'a> {
    /// The recording.
    pub playback: &'a Playback,
    /// Which of its tracks.
    pub track: usize,
}

impl HandSource for RecordedHand<'_> {
    fn side(&self) -> Side {
        self.playback.tracks[self.track].side
    }

    fn tracker_id(&self) -> Option<i64> {
        Some(self.playback.tracks[self.track].id)
    }

    fn sample(&mut self, t: f64) -> Result<Option<HandSample>, RunError> {
        Ok(self.playback.sample(self.track, t))
    }
}

/// A driver's source, whose lock is never taken (so never poisoned).
fn unlocked<'a, 's>(
    source: &'a mut Mutex<Box<dyn HandSource + 's>>,
) -> &'a mut (dyn HandSource + 's) {
    &mut **source.get_mut().unwrap_or_else(PoisonError::into_inner)
}

/// A driven hand as one step saw it.
#[derive(Debug, Clone)]
pub struct HandFrame {
    /// The hand in the world.
    pub id: HandId,
    /// Its label on trace lines: the tracker's id, or its index.
    pub label: i64,
    /// Which hand.
    pub side: Side,
    /// Its pose this step, or `None` while untracked.
    pub sample: Option<HandSample>,
}

/// One step, as observers see it after the step.
pub struct StepView<'a> {
    /// The world after the step.
    pub world: &'a InteractionWorld,
    /// The step's index since the driver began, from 0.
    pub index: usize,
    /// The time at the end of the step, on the driver's clock (s).
    pub t: f64,
    /// The driven hands, in the order they were added.
    pub hands: &'a [HandFrame],
}

/// Watches a run step by step: trace writers, summaries, the scenario
/// history, fixtures.
pub trait Observer {
    /// Before each step, with the world open to changes (releasing a
    /// fixture, say). `t` is the step's start time on the driver's clock (s).
    fn before_step(&mut self, _world: &mut InteractionWorld, _t: f64) -> Result<(), RunError> {
        Ok(())
    }

    /// Between the step's halves: hand forces are set and rapier has not
    /// moved anything yet (as between MuJoCo's `mj_step1` and `mj_step2`).
    /// Forces added to bodies here act in this step.
    fn after_hand_forces(&mut self, _world: &mut InteractionWorld) -> Result<(), RunError> {
        Ok(())
    }

    /// After each step.
    fn after_step(&mut self, _step: &StepView) -> Result<(), RunError> {
        Ok(())
    }
}

/// `first`, then `rest`: one observer list for [`Driver::run`].
pub fn observers<'a>(
    first: Vec<&'a mut dyn Observer>,
    rest: &'a mut [&mut dyn Observer],
) -> Vec<&'a mut dyn Observer> {
    let mut all = first;
    for o in rest.iter_mut() {
        all.push(&mut **o);
    }
    all
}

impl<F: FnMut(&StepView) -> Result<(), RunError>> Observer for F {
    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        self(step)
    }
}

/// A host engine that integrates a driven world's steps (host mode,
/// [`crate::pipeline::host`]): it gives each object's state, and takes each
/// step's hand wrenches to apply and integrate. `Send`, as a driver's hand
/// sources are.
pub trait Host: Send {
    /// Gives the world every object's state as the host has it now
    /// ([`InteractionWorld::set_host_body`]): before the first step and
    /// after each step the host integrates, so observers see the objects
    /// where the host has them.
    fn give_states(&mut self, world: &mut InteractionWorld) -> Result<(), RunError>;

    /// Applies a step's wrenches (one per object, in id order) and
    /// integrates the step.
    fn integrate(&mut self, wrenches: &[HandWrench]) -> Result<(), RunError>;
}

/// Drives a world: hand sources in, observers out. It borrows the world
/// (`Driver::new(&mut world)`), or owns it (`Driver::new(world)`) where the
/// driver must outlive the caller's stack, as in an app's resource.
pub struct Driver<'s, W: BorrowMut<InteractionWorld>> {
    world: W,
    /// Each behind a lock that is never taken (only `get_mut`, which the
    /// driver's `&mut self` allows): sources need only be `Send`, and a
    /// driver is still `Sync`, as an app's resource must be.
    sources: Vec<Mutex<Box<dyn HandSource + 's>>>,
    frames: Vec<HandFrame>,
    /// The world's time when the driver took it (s).
    start: f64,
    /// Steps run so far.
    steps: usize,
    /// The host that integrates the steps, if not the world's own rapier;
    /// behind a lock for the sources' reason.
    host: Option<Mutex<Box<dyn Host + 's>>>,
}

impl<'s, W: BorrowMut<InteractionWorld>> Driver<'s, W> {
    /// A driver of `world`, whose clock starts at the world's time.
    pub fn new(world: W) -> Self {
        let start = world.borrow().time();
        Driver { world, sources: Vec::new(), frames: Vec::new(), start, steps: 0, host: None }
    }

    /// Adds a hand to the world, posed by `source` from the next step on.
    pub fn add_hand(&mut self, source: impl HandSource + 's) -> HandId {
        let id = self.world.borrow_mut().add_hand(source.side());
        self.push(id, Box::new(source));
        id
    }

    /// Hands the steps to `host` (host mode) instead of the world's own
    /// rapier, which then integrates nothing; the host gives its states at
    /// once.
    pub fn set_host(&mut self, mut host: Box<dyn Host + 's>) -> Result<(), RunError> {
        host.give_states(self.world.borrow_mut())?;
        self.host = Some(Mutex::new(host));
        Ok(())
    }

    /// Poses a hand already in the world by `source`.
    pub fn drive(&mut self, hand: HandId, source: impl HandSource + 's) -> Result<(), RunError> {
        if self.world().hand_side(hand).is_none() {
            return Err(crate::pipeline::WorldError::NoSuchHand(hand).into());
        }
        self.push(hand, Box::new(source));
        Ok(())
    }

    fn push(&mut self, id: HandId, source: Box<dyn HandSource + 's>) {
        let label = source.tracker_id().unwrap_or(self.sources.len() as i64);
        self.frames.push(HandFrame { id, label, side: source.side(), sample: None });
        self.sources.push(Mutex::new(source));
    }

    /// The world being driven.
    pub fn world(&self) -> &InteractionWorld {
        self.world.borrow()
    }

    /// The world being driven, to change between runs.
    pub fn world_mut(&mut self) -> &mut InteractionWorld {
        self.world.borrow_mut()
    }

    /// The driven hands as the last step saw them, in the order they were
    /// added (no samples before the first step).
    pub fn hands(&self) -> &[HandFrame] {
        &self.frames
    }

    /// Steps run so far.
    pub fn steps(&self) -> usize {
        self.steps
    }

    /// The time on the driver's clock after `steps` steps (s).
    fn clock(&self, steps: usize) -> f64 {
        self.start + steps as f64 * self.world().config().dt as f64
    }

    /// Runs up to `steps` steps of [`Driver::step`]; stops early, before a
    /// step, once every source has finished. Returns the steps run.
    pub fn run(
        &mut self,
        steps: usize,
        observers: &mut [&mut dyn Observer],
    ) -> Result<usize, RunError> {
        for i in 0..steps {
            if !self.step(observers)? {
                return Ok(i);
            }
        }
        Ok(steps)
    }

    /// Runs one step, unless every source has finished (then it returns
    /// `false` having sampled them, and nothing moved): observers'
    /// `before_step`, every source sampled and its hand posed or cleared,
    /// the hand forces, observers' `after_hand_forces`, rapier's step, then
    /// observers' `after_step`.
    pub fn step(&mut self, observers: &mut [&mut dyn Observer]) -> Result<bool, RunError> {
        let t = self.clock(self.steps);
        let world = self.world.borrow_mut();
        for o in observers.iter_mut() {
            o.before_step(world, t)?;
        }
        for (source, frame) in self.sources.iter_mut().zip(self.frames.iter_mut()) {
            frame.sample = unlocked(source).sample(t)?;
            match &frame.sample {
                Some(s) => world.set_hand_pose(frame.id, &s.pose)?,
                None => world.clear_hand_pose(frame.id)?,
            }
        }
        if !self.sources.is_empty() && self.sources.iter_mut().all(|s| unlocked(s).finished()) {
            return Ok(false);
        }
        world.apply_hand_forces();
        for o in observers.iter_mut() {
            o.after_hand_forces(world)?;
        }
        match &mut self.host {
            Some(host) => {
                let host = host.get_mut().unwrap_or_else(PoisonError::into_inner);
                let wrenches = world.host_forces()?;
                host.integrate(&wrenches)?;
                host.give_states(world)?;
            }
            None => world.step_physics(),
        }
        let index = self.steps;
        self.steps += 1;
        let view = StepView {
            world: self.world.borrow(),
            index,
            t: self.clock(self.steps),
            hands: &self.frames,
        };
        for o in observers.iter_mut() {
            o.after_step(&view)?;
        }
        Ok(true)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::InteractionConfig;

    /// An untracked hand whose source finishes at its `n`-th sample.
    struct Ends(usize);

    impl HandSource for Ends {
        fn side(&self) -> Side {
            Side::Right
        }

        fn sample(&mut self, _t: f64) -> Result<Option<HandSample>, RunError> {
            self.0 = self.0.saturating_sub(1);
            Ok(None)
        }

        fn finished(&self) -> bool {
            self.0 == 0
        }
    }

    #[test]
    fn steps_one_at_a_time_as_run_does_and_not_once_sources_finish() {
        let world = InteractionWorld::new(InteractionConfig::default()).unwrap();
        let dt = world.config().dt as f64;
        let mut owned = Driver::new(world);
        owned.add_hand(Ends(3));
        let stepped: Vec<bool> = (0..4).map(|_| owned.step(&mut []).unwrap()).collect();
        assert_eq!(stepped, [true, true, false, false]);
        assert_eq!((owned.steps(), owned.world().time()), (2, 2.0 * dt));
        let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
        let mut borrowing = Driver::new(&mut world);
        borrowing.add_hand(Ends(3));
        assert_eq!(borrowing.run(4, &mut []).unwrap(), 2);
        assert_eq!(world.time(), 2.0 * dt);
    }
}
