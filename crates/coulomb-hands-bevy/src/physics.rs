//! [`HandPhysics`]: the app's interaction world and the core's driver that
//! poses its hands and steps it, one step per tick of the plugin's clock.

use bevy::platform::cell::SyncCell;
use coulomb_hands::hand::HandId;
use coulomb_hands::pipeline::{InteractionWorld, WorldError};
use coulomb_hands::run::RunError;
use coulomb_hands::run::drive::{Driver, HandFrame, HandSource, Observer, StepView};
use coulomb_hands::run::scenario::Scenario;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Duration;

/// The next [`HandPhysics`]'s serial number.
static SERIAL: AtomicU64 = AtomicU64::new(0);

/// Why the physics stopped stepping.
#[derive(Debug)]
pub enum Stopped {
    /// Every hand source has finished (a live stream closed).
    Finished,
    /// A step failed: a source's error, or a pose the world rejected. The
    /// failed step moved nothing.
    Failed(RunError),
}

/// A new [`HandPhysics`] was inserted (the first, or one replacing
/// another): the plugin has cleared the old world's entities. Views of the
/// old world start over.
#[derive(bevy::prelude::Message, bevy::prelude::Reflect, Debug, Clone, Copy, PartialEq, Eq)]
pub struct HandPhysicsReplaced {
    /// The new world's [`HandPhysics::serial`].
    pub serial: u64,
}

/// The interaction world of an app, with its hands' sources and its
/// observers: the resource the plugin steps. It steps through
/// [`Driver::step`], the body of the core's driver loop, so the app's
/// physics is the headless runs' physics.
///
/// Insert it with `App::insert_resource`; inserting another replaces the
/// world, and the plugin replaces its entities (and sends
/// [`HandPhysicsReplaced`]).
///
/// Reflected for its serial only: the world, its sources and observers are
/// the core's, which has no Bevy (read them through [`HandPhysics::world`]).
#[derive(bevy::prelude::Resource, bevy::prelude::Reflect)]
#[reflect(from_reflect = false)]
pub struct HandPhysics {
    #[reflect(ignore)]
    driver: Driver<'static, InteractionWorld>,
    /// In a `SyncCell`, reached only through `&mut self`: observers need
    /// only be `Send`.
    #[reflect(ignore)]
    observers: SyncCell<Observers>,
    #[reflect(ignore)]
    stopped: Option<Stopped>,
    /// Tells this world from one it replaced in an app.
    serial: u64,
}

impl HandPhysics {
    /// Drives `world`, with no hands yet.
    pub fn new(world: InteractionWorld) -> HandPhysics {
        let serial = SERIAL.fetch_add(1, Ordering::Relaxed);
        let observers = SyncCell::new(Observers(Vec::new()));
        HandPhysics { driver: Driver::new(world), observers, stopped: None, serial }
    }

    /// A scenario's world, scene and hands (scripted or recorded).
    pub fn of_scenario(scenario: &Scenario) -> Result<HandPhysics, WorldError> {
        let mut world = InteractionWorld::new(scenario.config)?;
        world.add_scene(&scenario.scene)?;
        let mut physics = HandPhysics::new(world);
        for hand in &scenario.hands {
            physics.add_hand(hand.clone());
        }
        Ok(physics)
    }

    /// Adds a hand to the world, posed by `source` from the next step on.
    /// (A hand the app's own systems pose is an entity with
    /// [`crate::input::AppHand`] instead.)
    pub fn add_hand(&mut self, source: impl HandSource + 'static) -> HandId {
        self.driver.add_hand(source)
    }

    /// Shows every step to `observer` (a trace writer, a session recorder).
    pub fn observe(&mut self, observer: impl Observer + Send + 'static) {
        self.observers.get().0.push(Box::new(observer));
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

    /// A number no other `HandPhysics` of this process has.
    pub fn serial(&self) -> u64 {
        self.serial
    }

    /// Physics steps run so far.
    pub fn steps(&self) -> usize {
        self.driver.steps()
    }

    /// The physics time step, the world's `dt`, as the plugin's clock ticks
    /// it: zero for a `dt` under a nanosecond, which the clock never ticks.
    pub fn timestep(&self) -> Duration {
        Duration::from_secs_f64(f64::from(self.world().config().dt))
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
        let observers: &mut dyn Observer = self.observers.get();
        match self.driver.step(&mut [observers]) {
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

/// The app's observers, shown each step in the order they were added: one
/// observer for the driver, so a step needs no list of its own.
struct Observers(Vec<Box<dyn Observer + Send>>);

impl Observer for Observers {
    fn before_step(&mut self, world: &mut InteractionWorld, t: f64) -> Result<(), RunError> {
        self.0.iter_mut().try_for_each(|o| o.before_step(world, t))
    }

    fn after_hand_forces(&mut self, world: &mut InteractionWorld) -> Result<(), RunError> {
        self.0.iter_mut().try_for_each(|o| o.after_hand_forces(world))
    }

    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        self.0.iter_mut().try_for_each(|o| o.after_step(step))
    }
}
