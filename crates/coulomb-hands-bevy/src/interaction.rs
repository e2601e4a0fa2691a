//! [`Interaction`]: the app's interaction world and the core's driver that
//! poses its hands and steps it, one step per fixed tick.
//!
//! It is kept in the app as non-send data (`App::insert_non_send`): hand
//! sources need not be `Send` (a live stream's two hands share one
//! connection), and the physics runs on the main thread anyway.

use coulomb_hands::hand::HandId;
use coulomb_hands::pipeline::{InteractionWorld, WorldError};
use coulomb_hands::run::RunError;
use coulomb_hands::run::drive::{Driver, HandFrame, HandSource, Observer};
use coulomb_hands::run::scenario::Scenario;
use std::sync::atomic::{AtomicU64, Ordering};

/// The next [`Interaction`]'s serial number.
static SERIAL: AtomicU64 = AtomicU64::new(0);

/// Why the interaction stopped stepping.
#[derive(Debug)]
pub enum Stopped {
    /// Every hand source has finished (a live stream closed).
    Finished,
    /// A step failed: a source's error, or a pose the world rejected. The
    /// failed step moved nothing.
    Failed(RunError),
}

/// The interaction world of an app, with its hands' sources and its
/// observers. The plugin steps it through [`Driver::step`], the body of the
/// core's driver loop, so the app's physics is the headless runs' physics.
pub struct Interaction {
    driver: Driver<'static, InteractionWorld>,
    observers: Vec<Box<dyn Observer>>,
    stopped: Option<Stopped>,
    /// Tells this interaction from one it replaced in an app.
    serial: u64,
}

impl Interaction {
    /// Drives `world`, with no hands yet.
    pub fn new(world: InteractionWorld) -> Interaction {
        let serial = SERIAL.fetch_add(1, Ordering::Relaxed);
        Interaction { driver: Driver::new(world), observers: Vec::new(), stopped: None, serial }
    }

    /// A scenario's world, scene and hands (scripted or recorded).
    pub fn of_scenario(scenario: &Scenario) -> Result<Interaction, WorldError> {
        let mut world = InteractionWorld::new(scenario.config)?;
        world.add_scene(&scenario.scene)?;
        let mut interaction = Interaction::new(world);
        for hand in &scenario.hands {
            interaction.add_hand(hand.clone());
        }
        Ok(interaction)
    }

    /// Adds a hand to the world, posed by `source` from the next step on.
    pub fn add_hand(&mut self, source: impl HandSource + 'static) -> HandId {
        self.driver.add_hand(source)
    }

    /// Shows every step to `observer` (a trace writer, a session recorder).
    pub fn observe(&mut self, observer: impl Observer + 'static) {
        self.observers.push(Box::new(observer));
    }

    /// The world.
    pub fn world(&self) -> &InteractionWorld {
        self.driver.world()
    }

    /// The world, to change between steps (add an object, place one).
    pub fn world_mut(&mut self) -> &mut InteractionWorld {
        self.driver.world_mut()
    }

    /// The hands as the last step saw them, in the order they were added.
    pub fn hands(&self) -> &[HandFrame] {
        self.driver.hands()
    }

    /// A number no other interaction of this process has.
    pub fn serial(&self) -> u64 {
        self.serial
    }

    /// Physics steps run so far.
    pub fn steps(&self) -> usize {
        self.driver.steps()
    }

    /// Why stepping stopped, if it has.
    pub fn stopped(&self) -> Option<&Stopped> {
        self.stopped.as_ref()
    }

    /// One physics step, unless stepping has stopped; returns whether the
    /// world moved.
    pub fn step(&mut self) -> bool {
        if self.stopped.is_some() {
            return false;
        }
        let mut observers: Vec<&mut dyn Observer> =
            self.observers.iter_mut().map(|o| &mut **o as &mut dyn Observer).collect();
        match self.driver.step(&mut observers) {
            Ok(true) => true,
            Ok(false) => {
                self.stopped = Some(Stopped::Finished);
                false
            }
            Err(e) => {
                self.stopped = Some(Stopped::Failed(e));
                false
            }
        }
    }
}
