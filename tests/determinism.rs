//! Determinism: the same recording, scene and settings give bit-identical
//! trajectories, in fresh worlds, in two worlds stepped in turn in one
//! process, in scripted scenarios and in soak loops. Each run is reduced
//! to two hashes: of the exact bytes the trace writer writes, and of the
//! bit patterns of every object's state and every contact after each
//! step. A 1 % heavier object must change both, so the hashes can fail.

use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::leap;
use coulomb_hands::input::playback::{DEFAULT_GRACE, Playback};
use coulomb_hands::output::Session;
use coulomb_hands::pipeline::Call;
use coulomb_hands::run::drive::{self, Driver, Observer, RecordedHand, StepView};
use coulomb_hands::run::observe::TraceWriter;
use coulomb_hands::run::replay::{Fixture, Fixtures, GraspObject, place_at_grasp, replay_world};
use coulomb_hands::run::scenario::Scenario;
use coulomb_hands::run::soak::{SoakLength, soak};
use coulomb_hands::{GammaMode, InteractionConfig, InteractionWorld, RunError};
use glam::Vec3;
use std::io::Write;

/// FNV-1a, 64 bits: a hash that is the same in every build and process.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Fnv(u64);

impl Fnv {
    fn new() -> Fnv {
        Fnv(0xcbf2_9ce4_8422_2325)
    }

    fn bytes(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0 ^ b as u64).wrapping_mul(0x0100_0000_01b3);
        }
    }

    fn floats(&mut self, values: &[f32]) {
        for v in values {
            self.bytes(&v.to_bits().to_le_bytes());
        }
    }
}

impl Write for Fnv {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.bytes(buf);
        Ok(buf.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// Hashes the bit patterns of every object's state (pose, velocities,
/// hand force) and every contact (point, normal, force) after each step.
struct StateHash {
    hash: Fnv,
    steps: usize,
}

impl StateHash {
    fn new() -> StateHash {
        StateHash { hash: Fnv::new(), steps: 0 }
    }

    /// Hashes `world` after a step.
    fn world(&mut self, world: &InteractionWorld) {
        self.hash.bytes(&world.time().to_bits().to_le_bytes());
        for id in world.object_ids() {
            let s = world.object_state(id).expect("the object exists");
            let vectors = [s.position, s.linvel, s.angvel, s.hand_force];
            self.hash.floats(&vectors.map(|v| v.to_array()).concat());
            self.hash.floats(&s.rotation.to_array());
        }
        for c in world.contacts() {
            self.hash.bytes(&[c.object.0 as u8, c.hand.0 as u8, c.bone.index() as u8]);
            let vectors = [c.point, c.normal, c.force];
            self.hash.floats(&vectors.map(|v| v.to_array()).concat());
        }
        self.steps += 1;
    }
}

impl Observer for StateHash {
    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        self.world(step.world);
        Ok(())
    }
}

/// A run's fingerprint: the trace bytes' hash, the state hash, the steps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Fingerprint {
    trace: u64,
    state: u64,
    steps: usize,
}

/// The trace writer and the state hash, observing one run.
struct Watch {
    trace: TraceWriter<Fnv>,
    state: StateHash,
}

impl Watch {
    fn new() -> Watch {
        Watch { trace: TraceWriter::new(Fnv::new()), state: StateHash::new() }
    }

    fn observers(&mut self) -> [&mut dyn Observer; 2] {
        [&mut self.trace, &mut self.state]
    }

    fn finish(self) -> Fingerprint {
        let trace = self.trace.finish().expect("hashing never fails").0;
        Fingerprint { trace, state: self.state.hash.0, steps: self.state.steps }
    }
}

fn playback(name: &str) -> Playback {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data/leap").join(name);
    let rec = leap::load(&path).unwrap();
    let conversion = Conversion::leap_desktop(Vec3::ZERO);
    Playback::new(name, &rec.frames, &conversion, DEFAULT_GRACE).unwrap()
}

/// The bundled fist (`grab.json.lz`), a 4.5 cm box of `mass` kg at its
/// first grasp, automatic γ: the box is gripped, lifted, dropped on the
/// ground and settles.
const GRAB: &str = "grab.json.lz";

fn grab_world(playback: &Playback, mass: f32) -> (InteractionWorld, Vec<Fixture>) {
    recorded_grab_world(playback, mass, false)
}

/// [`grab_world`], recording its session if `record`.
fn recorded_grab_world(
    playback: &Playback,
    mass: f32,
    record: bool,
) -> (InteractionWorld, Vec<Fixture>) {
    let config = InteractionConfig { gamma: GammaMode::Auto, ..InteractionConfig::default() };
    let mut world = replay_world(config, record).unwrap();
    let object = GraspObject { sphere: false, size: 0.045, mass };
    let (fixture, _) = place_at_grasp(&mut world, playback, object, 0).unwrap();
    (world, vec![fixture])
}

/// The whole recording replayed into a fresh world.
fn replay_once(playback: &Playback, mass: f32) -> Fingerprint {
    let (mut world, fixtures) = grab_world(playback, mass);
    let mut watch = Watch::new();
    let summary = coulomb_hands::run::replay::replay(
        GRAB,
        playback,
        &mut world,
        &fixtures,
        &mut watch.observers(),
    )
    .unwrap();
    assert!(summary.all_finite && summary.contacts_begun > 0, "{summary:?}");
    assert!(summary.objects[0].displacement > 0.01, "the box moved: {summary:?}");
    watch.finish()
}

#[test]
fn the_same_replay_twice_gives_the_same_trace_bytes_and_state_bits() {
    let playback = playback(GRAB);
    let a = replay_once(&playback, 0.05);
    let b = replay_once(&playback, 0.05);
    assert_eq!(a, b);
    assert_eq!(a.steps, (playback.duration / 0.001).floor() as usize + 1);
}

#[test]
fn a_one_percent_heavier_box_changes_both_hashes() {
    let playback = playback(GRAB);
    let a = replay_once(&playback, 0.05);
    let b = replay_once(&playback, 0.0505);
    assert_ne!(a.trace, b.trace, "the trace did not see a 1 % heavier box");
    assert_ne!(a.state, b.state, "the state did not see a 1 % heavier box");
}

#[test]
fn two_worlds_stepped_in_turn_match_a_world_stepped_alone() {
    let playback = playback(GRAB);
    let alone = replay_once(&playback, 0.05);
    // Two worlds in one process, each step of one followed by a step of
    // the other: nothing global (allocator state, caches, statics) may
    // leak from one into the other.
    let (mut w1, f1) = grab_world(&playback, 0.05);
    let (mut w2, f2) = grab_world(&playback, 0.05);
    let (mut fix1, mut fix2) = (Fixtures(f1), Fixtures(f2));
    let (mut watch1, mut watch2) = (Watch::new(), Watch::new());
    let mut d1 = Driver::new(&mut w1);
    let mut d2 = Driver::new(&mut w2);
    for track in 0..playback.tracks.len() {
        d1.add_hand(RecordedHand { playback: &playback, track });
        d2.add_hand(RecordedHand { playback: &playback, track });
    }
    for _ in 0..alone.steps {
        let mut o1 = watch1.observers();
        d1.run(1, &mut drive::observers(vec![&mut fix1], &mut o1)).unwrap();
        let mut o2 = watch2.observers();
        d2.run(1, &mut drive::observers(vec![&mut fix2], &mut o2)).unwrap();
    }
    assert_eq!(watch1.finish(), alone);
    assert_eq!(watch2.finish(), alone);
}

/// A shipped scenario run through its script, with `mass_scale` on its
/// first object's mass.
fn scenario_once(name: &str, mass_scale: f32) -> Fingerprint {
    let mut scenario = Scenario::find(name).unwrap();
    scenario.scene.objects[0].mass *= mass_scale;
    let mut watch = Watch::new();
    scenario.run(&mut watch.observers()).unwrap();
    watch.finish()
}

#[test]
fn a_scripted_scenario_with_object_collisions_is_deterministic() {
    // A mallet gripped by a scripted hand knocks down a tower of four
    // cubes: rapier's object–object contacts, islands and sleeping too.
    let a = scenario_once("tool-knock-tower", 1.0);
    assert_eq!(a, scenario_once("tool-knock-tower", 1.0));
    let heavier = scenario_once("tool-knock-tower", 1.01);
    assert_ne!(a.trace, heavier.trace);
    assert_ne!(a.state, heavier.state);
}

/// `loops` soak loops of the fist, hashed.
fn soak_once(playback: &Playback, loops: usize) -> Fingerprint {
    let (mut world, fixtures) = grab_world(playback, 0.05);
    let mut watch = Watch::new();
    let length = SoakLength::Loops(loops);
    let mut observers = watch.observers();
    let r = soak(GRAB, playback, &mut world, &fixtures, length, &mut observers, &mut |_| {});
    assert_eq!(r.unwrap().loops, loops);
    watch.finish()
}

#[test]
fn a_soak_is_deterministic_and_its_first_loop_is_the_plain_replay() {
    let playback = playback(GRAB);
    assert_eq!(soak_once(&playback, 1), replay_once(&playback, 0.05));
    let three = soak_once(&playback, 3);
    assert_eq!(three, soak_once(&playback, 3));
    assert_eq!(three.steps, 3 * soak_once(&playback, 1).steps);
}

#[test]
fn a_recorded_soak_replays_bit_for_bit_from_its_session() {
    // The objects put back before each loop are calls in the session.
    let playback = playback(GRAB);
    let (mut world, fixtures) = recorded_grab_world(&playback, 0.05, true);
    let mut live = StateHash::new();
    let length = SoakLength::Loops(2);
    soak(GRAB, &playback, &mut world, &fixtures, length, &mut [&mut live], &mut |_| {}).unwrap();
    let session = Session::take(&mut world).unwrap();
    assert!(session.calls.iter().any(|c| matches!(c, Call::PlaceObject(..))));
    let mut replayed = StateHash::new();
    session.replay(|w| replayed.world(w)).unwrap();
    assert_eq!((replayed.hash, replayed.steps), (live.hash, live.steps));
}
