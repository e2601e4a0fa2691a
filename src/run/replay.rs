//! Headless replay of a hand-tracking recording through the interaction
//! world, with a summary, and objects put where the recorded hand grasps.

use super::RunError;
use super::closing::{self, ClosingVerdict, Closings};
use super::drive::{self, Driver, Observer, RecordedHand};
use super::grasp::{GraspSite, SAMPLE_STEP, find_grasps};
pub use super::held::{
    GraspObject, GraspObjectError, ObjectPlace, ObjectPlaceError, is_gripped, is_squeezed,
};
use super::observe::{ObjectSummary, Summary};
use crate::input::playback::{DEFAULT_GRACE, Playback};
use crate::input::recording::Recording;
use crate::output::Session;
use crate::pipeline::{InteractionConfig, InteractionWorld, Method, WorldError};
use crate::scene::{GammaMode, ObjectDesc, ObjectId, Scene, StaticDesc};
use glam::Vec3;
use std::path::Path;

/// The replay's numbers; `replay --json` prints exactly this.
#[derive(Debug, Clone, serde::Serialize)]
pub struct ReplaySummary {
    /// The recording's name.
    pub source: String,
    /// Frames in the recording.
    pub frames: usize,
    /// Distinct tracked hands.
    pub hands: usize,
    /// Recording length (s).
    pub duration: f64,
    /// Physics steps run.
    pub steps: usize,
    /// Contacts begun over the replay.
    pub contacts_begun: usize,
    /// What each object did.
    pub objects: Vec<ObjectSummary>,
    /// True when every traced number was finite.
    pub all_finite: bool,
    /// The frames and hands playback left out, one line each
    /// ([`crate::input::playback::Skipped`]).
    pub skipped: Vec<String>,
    /// A verdict for every closing of a hand, when an object was put at
    /// each ([`replay_closings`]); empty otherwise.
    pub closings: Vec<ClosingVerdict>,
}

/// A world to replay into, with a ground at y = 0, recording its session
/// if `record` ([`Session::take`] gets it).
pub fn replay_world(
    config: InteractionConfig,
    record: bool,
) -> Result<InteractionWorld, WorldError> {
    let mut world = InteractionWorld::new(config)?;
    if record {
        Session::start(&mut world);
    }
    world.add_static(&StaticDesc::ground(0.0, 0.5))?;
    Ok(world)
}

/// A world for `config` with `scene` in it (and the scene's gravity), over
/// [`replay_world`]'s ground, recording its session if `record`.
pub fn scene_world(
    config: InteractionConfig,
    scene: Option<&Scene>,
    record: bool,
) -> Result<InteractionWorld, WorldError> {
    let config = scene.map_or(config, |s| config.with_scene(s));
    let mut world = replay_world(config, record)?;
    if let Some(scene) = scene {
        world.add_scene(scene)?;
    }
    Ok(world)
}

/// What `replay` runs a recording with, besides the recording: the
/// command's options, and the Python package's `replay` keywords.
#[derive(Debug, Clone)]
pub struct ReplayOptions {
    /// Where the recording's origin (a desktop device) sits in the world (m).
    pub device: Vec3,
    /// Tracking gaps up to this long (s) are bridged.
    pub grace: f64,
    /// Static scenery and objects besides the ground.
    pub scene: Option<Scene>,
    /// Contact stiffness.
    pub gamma: GammaMode,
    /// How hands move objects.
    pub method: Method,
    /// An object put at every closing of a hand ([`replay_closings`]).
    pub object_at_grasp: Option<GraspObject>,
    /// Record the session ([`Session::take`] gets it from the world).
    pub record: bool,
}

impl Default for ReplayOptions {
    fn default() -> Self {
        ReplayOptions {
            device: Vec3::ZERO,
            grace: DEFAULT_GRACE,
            scene: None,
            gamma: GammaMode::default(),
            method: Method::default(),
            object_at_grasp: None,
            record: false,
        }
    }
}

impl ReplayOptions {
    /// The world these options replay into ([`scene_world`]).
    pub fn world(&self) -> Result<InteractionWorld, WorldError> {
        let base = InteractionConfig { gamma: self.gamma, ..InteractionConfig::default() };
        scene_world(self.method.config(base), self.scene.as_ref(), self.record)
    }
}

/// Replays `recording` with `options` (no soak): with an object at every
/// closing if [`ReplayOptions::object_at_grasp`], else with the scene's
/// objects only. Returns the summary and the world, whose session a
/// caller that asked for one saves.
pub fn replay_recording(
    recording: &Recording,
    options: &ReplayOptions,
    observers: &mut [&mut dyn Observer],
) -> Result<(ReplaySummary, InteractionWorld), RunError> {
    let playback = recording.playback(options.device, options.grace)?;
    let mut world = options.world()?;
    let source = &recording.source_name;
    let summary = match options.object_at_grasp {
        Some(object) => replay_closings(source, &playback, &mut world, object, observers)?,
        None => replay(source, &playback, &mut world, &[], observers)?,
    };
    Ok((summary, world))
}

/// What replaying a recorded session did; `replay --json` prints exactly
/// this for a session file.
#[derive(Debug, Clone, serde::Serialize)]
pub struct SessionSummary {
    /// The session file.
    pub session: String,
    /// Physics steps it recorded.
    pub steps: usize,
    /// What each object did, followed from the end of the first step.
    pub objects: Vec<ObjectSummary>,
    /// Simulated time at its end (s).
    #[serde(skip)]
    pub time: f64,
}

/// Whether `path` is a recorded session file (not a recording).
pub fn is_session_file(path: &Path) -> bool {
    std::fs::read_to_string(path).is_ok_and(|t| Session::sniff(&t))
}

/// Replays a recorded session file, bit for bit, and sums up its objects.
pub fn replay_session_file(file: &Path) -> Result<SessionSummary, RunError> {
    let session = Session::load(file)?;
    replay_session(&file.display().to_string(), &session)
}

/// Replays a session (read from its text by [`Session::parse`]; `name`
/// is its file's, for the summary), bit for bit, and sums up its objects.
pub fn replay_session(name: &str, session: &Session) -> Result<SessionSummary, RunError> {
    // Objects are followed from the end of the first step, when all exist.
    let mut summary: Option<Result<Summary, WorldError>> = None;
    let replayed = session.replay(|w| {
        let s = summary.get_or_insert_with(|| Summary::new(w));
        if let Ok(s) = s
            && let Err(e) = s.observe_world(w)
        {
            summary = Some(Err(e));
        }
    });
    let world = replayed.map_err(|e| e.in_file(Path::new(name)))?;
    let objects = match summary.transpose()? {
        Some(s) => s.objects(&world)?,
        None => Vec::new(),
    };
    Ok(SessionSummary {
        session: name.to_string(),
        steps: session.steps(),
        objects,
        time: world.time(),
    })
}

/// A replay's summary, of a recording or of a session file.
#[derive(Debug, Clone, serde::Serialize)]
#[serde(untagged)]
pub enum Replayed {
    /// A recording's.
    Recording(ReplaySummary),
    /// A session file's.
    Session(SessionSummary),
}

/// `replay FILE --json`'s data without a soak, trace or recorded session:
/// a session file replayed ([`replay_session_file`]), else a recording of
/// any format ([`replay_recording`]).
pub fn replay_file(path: &Path, options: &ReplayOptions) -> Result<Replayed, RunError> {
    if is_session_file(path) {
        return Ok(Replayed::Session(replay_session_file(path)?));
    }
    let recording = crate::input::recording::load(path)?;
    Ok(Replayed::Recording(replay_recording(&recording, options, &mut [])?.0))
}

/// [`replay_file`] of a file's bytes (`name` is the file's name, whose
/// extension says whether a recording is JSON Lines).
pub fn replay_bytes(
    name: &str,
    bytes: Vec<u8>,
    options: &ReplayOptions,
) -> Result<Replayed, RunError> {
    let bytes = match String::from_utf8(bytes) {
        Ok(text) if Session::sniff(&text) => {
            let session = Session::parse(name, &text)?;
            return Ok(Replayed::Session(replay_session(name, &session)?));
        }
        Ok(text) => text.into_bytes(),
        Err(e) => e.into_bytes(),
    };
    let recording = crate::input::recording::from_bytes(name, bytes)?;
    Ok(Replayed::Recording(replay_recording(&recording, options, &mut [])?.0))
}

/// A world to replay into: ground at y = 0 plus the given objects.
pub fn world_with_objects(
    config: InteractionConfig,
    objects: &[ObjectDesc],
) -> Result<(InteractionWorld, Vec<ObjectId>), WorldError> {
    let mut world = replay_world(config, false)?;
    let ids = objects.iter().map(|o| world.add_object(o)).collect::<Result<Vec<_>, _>>()?;
    Ok((world, ids))
}

/// An object held in place at a grasp site until the hand grips it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fixture {
    /// The object held.
    pub object: ObjectId,
    /// Released when the hand grips it, or at the latest at the most
    /// closed instant of the grasp that leaves the grip time to be judged
    /// ([`super::closing::ClosingVerdict::closed_at`]) (s).
    pub release_by: f64,
}

/// Places `object` at the site of the recording's `index`-th grasp (in
/// time order) that holds long enough to judge ([`GraspSite::sustained`]),
/// held fixed in place (as if on a support) until the hand grips it. The
/// recorded hand grasped nothing, so without the fixture a finger arriving
/// early would knock the object away before the others close on it.
pub fn place_at_grasp(
    world: &mut InteractionWorld,
    playback: &Playback,
    object: GraspObject,
    index: usize,
) -> Result<(Fixture, GraspSite), RunError> {
    let mut grasps = find_grasps(playback, SAMPLE_STEP);
    grasps.retain(|g| g.sustained);
    let site =
        *grasps.get(index).ok_or(RunError::NoGrasp { found: grasps.len(), wanted: index })?;
    let id = world.add_object(&object.at(&site, "grasped"))?;
    world.set_object_locked(id, true)?;
    let hold = (&closing::hold_sites(playback, &site)[..], &site);
    let (settle, bound) = (closing::grip_settling(world, id), closing::slip_bound(playback, &site));
    let at = closing::seat_for_judging(world, id, hold, settle, bound)?;
    Ok((Fixture { object: id, release_by: at.closed_at }, at))
}

/// Releases each fixture when its object is gripped ([`is_gripped`]), or
/// at its deadline with its contacts re-seated
/// ([`InteractionWorld::reseat_contacts`]).
#[derive(Debug, Clone)]
pub struct Fixtures(pub Vec<Fixture>);

impl Observer for Fixtures {
    fn before_step(&mut self, world: &mut InteractionWorld, t: f64) -> Result<(), RunError> {
        for f in std::mem::take(&mut self.0) {
            let gripped = is_gripped(world, f.object);
            if gripped || f.release_by <= t {
                world.set_object_locked(f.object, false)?;
                if !gripped {
                    world.reseat_contacts(f.object)?;
                }
            } else {
                self.0.push(f);
            }
        }
        Ok(())
    }
}

/// Replays `playback` into `world` for its whole duration (one hand per
/// track), with `fixtures` released as [`Fixtures`] says, showing every
/// step to `observers`. `source` names the recording in the summary.
pub fn replay(
    source: &str,
    playback: &Playback,
    world: &mut InteractionWorld,
    fixtures: &[Fixture],
    observers: &mut [&mut dyn Observer],
) -> Result<ReplaySummary, RunError> {
    let mut fixtures = Fixtures(fixtures.to_vec());
    replay_with(source, playback, world, &mut fixtures, observers)
}

/// Replays `playback` as [`replay`] does, with an `object` put at every
/// closing of its hands ([`Closings`]), and judges each closing: the
/// summary's `closings`.
pub fn replay_closings(
    source: &str,
    playback: &Playback,
    world: &mut InteractionWorld,
    object: GraspObject,
    observers: &mut [&mut dyn Observer],
) -> Result<ReplaySummary, RunError> {
    let mut closings = Closings::new(playback, object)?;
    let mut summary = replay_with(source, playback, world, &mut closings, observers)?;
    summary.closings = closings.verdicts();
    Ok(summary)
}

/// The replay loop, with `objects` (fixtures or closings) shown each step
/// first.
fn replay_with(
    source: &str,
    playback: &Playback,
    world: &mut InteractionWorld,
    objects: &mut dyn Observer,
    observers: &mut [&mut dyn Observer],
) -> Result<ReplaySummary, RunError> {
    let mut summary = Summary::new(world)?;
    let steps = playback.steps(world.config().dt);
    let mut driver = Driver::new(world);
    for track in 0..playback.tracks.len() {
        driver.add_hand(RecordedHand { playback, track });
    }
    driver.run(steps, &mut drive::observers(vec![objects, &mut summary], observers))?;
    Ok(ReplaySummary {
        source: source.to_string(),
        frames: playback.frames,
        hands: playback.tracks.len(),
        duration: playback.duration,
        steps,
        contacts_begun: summary.contacts_begun,
        objects: summary.objects(driver.world())?,
        all_finite: summary.all_finite,
        skipped: playback.skipped.iter().map(ToString::to_string).collect(),
        closings: Vec::new(),
    })
}
