//! Hand sources for an app. Any core [`HandSource`] drives a hand of an
//! [`crate::interaction::Interaction`]: a scenario's scripted or recorded
//! hand ([`coulomb_hands::run::scenario::ScenarioHand`]), a recording's
//! track, a function of time ([`coulomb_hands::run::drive::PoseFn`]).
//!
//! The live Leap client's hands come from a
//! [`coulomb_hands::run::live::LiveFeed`]: it reads the service on a thread
//! of its own, so a frame never waits for the network, and plays the hands
//! a little behind the newest frame on the app's clock (`hands()` gives
//! both on one tie, for two-handed grasps). (Its sibling
//! `LiveHand` reads the stream when the physics needs a frame, and so
//! blocks: it is for headless runs that step through a stream.)
//!
//! A hand whose poses come from the app's own systems (an XR runtime's hand
//! joints, a hand driven by mouse and keyboard) is a [`PushedHand`]: the
//! app's system writes each new pose to its [`HandInlet`], a `Send + Sync`
//! component, and the driver reads the newest pose at every physics step.

use coulomb_hands::hand::{HandSample, Side};
use coulomb_hands::run::RunError;
use coulomb_hands::run::drive::HandSource;
use std::sync::{Arc, Mutex, PoisonError};

/// The newest pose an app pushed, shared by the inlet and the source.
type Slot = Arc<Mutex<Option<HandSample>>>;

/// A hand posed by the app's own systems: the driver's side of a
/// [`HandInlet`]. Each physics step takes the newest pushed pose, held
/// until the next push (the app pushes at its frame or tracker rate, the
/// physics samples at its own).
#[derive(Debug)]
pub struct PushedHand {
    side: Side,
    slot: Slot,
}

/// Where an app pushes a [`PushedHand`]'s poses.
#[derive(bevy::prelude::Component, Debug, Clone)]
pub struct HandInlet {
    slot: Slot,
}

impl PushedHand {
    /// A `side` hand, untracked until its inlet gets a pose.
    pub fn new(side: Side) -> (PushedHand, HandInlet) {
        let slot = Slot::default();
        (PushedHand { side, slot: Arc::clone(&slot) }, HandInlet { slot })
    }
}

impl HandInlet {
    /// The pose for the next physics steps, or `None` when tracking is
    /// lost (the hand's contacts end).
    pub fn push(&self, sample: Option<HandSample>) {
        *self.slot.lock().unwrap_or_else(PoisonError::into_inner) = sample;
    }
}

impl HandSource for PushedHand {
    fn side(&self) -> Side {
        self.side
    }

    fn sample(&mut self, _t: f64) -> Result<Option<HandSample>, RunError> {
        Ok(self.slot.lock().unwrap_or_else(PoisonError::into_inner).clone())
    }
}
