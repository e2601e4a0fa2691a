//! What the viewer shows: a shipped or filed scenario, a tracking recording,
//! a hand–object capture, or a scene driven by the mouse-and-keyboard hand,
//! an XR runtime's hands or a Leap Motion service's. Each is loaded and
//! checked once, by the core's own loaders (so a bad file is the same error
//! as in the CLI), and can build a fresh [`HandPhysics`] from the start any
//! number of times: a timeline scrub back in time replays from t = 0, which
//! is exact because a run is deterministic.

use crate::head::HeadMount;
use coulomb_hands::eval::board::{self, Placement};
use coulomb_hands::hand::Side;
use coulomb_hands::input::capture::{self, Capture};
use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::playback::{DEFAULT_GRACE, Playback};
use coulomb_hands::pipeline::{InteractionConfig, InteractionWorld, Method};
use coulomb_hands::run::capture::{CaptureOptions, capture_world};
use coulomb_hands::run::closing::Closings;
use coulomb_hands::run::live::LiveFeed;
use coulomb_hands::run::replay::{GraspObject, ObjectPlace, replay_world};
use coulomb_hands::run::scenario::{Scenario, ScenarioHand};
use coulomb_hands::scene::Scene;
use coulomb_hands_bevy::physics::HandPhysics;
use std::path::Path;
use std::sync::Arc;

/// The scene the viewer opens with no argument: a few objects on a table
/// for the mouse hand to push, grasp and lift.
pub const DESK: &str = include_str!("../scenes/desk.json");

/// Why the viewer could not load its input: the core's message, naming the
/// file and where.
pub type LoadError = Box<dyn std::error::Error + Send + Sync>;

/// A loaded input.
#[derive(Debug, Clone)]
pub enum Source {
    /// A scenario: its scene and scripted or recorded hands.
    Scenario(Box<Scenario>),
    /// A tracking recording, played in an optional scene, with an object
    /// put at each closing of a hand when asked (as `replay --object-at grasp`).
    Recording {
        /// The file's name, for the HUD.
        name: String,
        /// The recording on the world's clock.
        playback: Box<Playback>,
        /// Static scenery and objects around it.
        scene: Option<Scene>,
        /// The object for each closing.
        object: Option<GraspObject>,
        /// The head the tracker was worn on, if it was (§3.8.1).
        head: Option<HeadMount>,
    },
    /// A hand–object capture (TACO's, say), replayed as `replay` does
    /// ([`coulomb_hands::run::capture`]): the captured hand moves the object,
    /// which starts at its first captured pose on a table, through contacts
    /// alone; the captured object is drawn beside it ([`crate::ghost`]).
    Capture {
        /// The file's name, for the HUD.
        name: String,
        /// The capture: its object's mesh and poses, and the fitted hand.
        /// Shared, as it is large and never changes (a restart clones
        /// the source).
        capture: Arc<Capture>,
        /// Its hand on the world's clock.
        playback: Box<Playback>,
        /// The file's `source` note, which credits the data set the
        /// capture came from (TACO's: its paper and licence), if it has one.
        credit: Option<String>,
    },
    /// One trial of the chessboard placement task (§5.2): the board, the
    /// cube on its start square, and the mouse hand.
    Task {
        /// The trial's number, from 1.
        trial: usize,
        /// Its squares.
        placement: Placement,
    },
    /// A scene with both hands from an XR runtime's hand tracking
    /// ([`crate::xr_hands`]).
    LiveXr {
        /// The file's name, for the HUD.
        name: String,
        /// What is in it.
        scene: Scene,
    },
    /// A scene with both hands from a Leap Motion service's stream, read
    /// on a thread of its own so that no frame waits for the network.
    LiveLeap {
        /// The file's name, for the HUD.
        name: String,
        /// What is in it.
        scene: Scene,
        /// The stream, and what it has sent.
        feed: LiveFeed,
    },
    /// A scene with one hand driven by mouse and keyboard.
    Scene {
        /// The file's name, for the HUD.
        name: String,
        /// What is in it.
        scene: Scene,
    },
}

/// How to load: the method and the extras a recording may take.
#[derive(Debug, Clone, Default)]
pub struct LoadOptions {
    /// How hands move objects.
    pub method: Method,
    /// Scenery for a recording.
    pub scene: Option<std::path::PathBuf>,
    /// An object for a recording, and where: at each closing of a hand,
    /// or once at a fixed place.
    pub object: Option<(GraspObject, ObjectPlace)>,
    /// A recording's tracker was worn on this head (§3.8.1).
    pub head: Option<HeadMount>,
}

impl LoadOptions {
    /// The options that only a recording takes.
    pub fn for_recording(&self) -> bool {
        self.scene.is_some() || self.object.is_some() || self.head.is_some()
    }
}

/// What poses a hand the viewer's own systems track: a component on its
/// [`coulomb_hands_bevy::input::AppHand`] entity.
#[derive(bevy::prelude::Component, Debug, Clone, Copy, PartialEq, Eq)]
pub enum HandDriver {
    /// The mouse and keyboard ([`crate::mouse_hand`]).
    Mouse,
    /// An XR runtime's hand tracking ([`crate::xr_hands`]).
    Xr,
}

/// Why a recording's options were refused for another input.
const RECORDING_ONLY: &str = "--scene, --object-at and --head-mounted go with a recording";

impl Source {
    /// Loads `input`: nothing (the desk scene), a shipped scenario's name,
    /// or a file. A file is a recording if the core's recording loader
    /// knows its format (`.json.lz`, `.jsonl`, a Leap JSON), a scenario if
    /// it has `hands`, else a scene.
    pub fn load(input: Option<&str>, options: &LoadOptions) -> Result<Source, LoadError> {
        let Some(input) = input else {
            if options.for_recording() {
                return Err(RECORDING_ONLY.into());
            }
            let scene = Scene::parse("scenes/desk.json", DESK)?;
            return Ok(Source::Scene { name: "desk".into(), scene });
        };
        // A scenario may have a `hand` and an `object` as a capture has:
        // its `hands` decide first, as the core's replay never takes one.
        let file = Path::new(input).exists() && !is_scenario(input);
        let capture = file.then(|| capture::load_if_capture(Path::new(input))).flatten();
        let recording = file && capture.is_none() && is_recording(input);
        if !recording && options.for_recording() {
            return Err(format!("{input}: {RECORDING_ONLY}").into());
        }
        if !file {
            return Ok(Source::Scenario(Box::new(Scenario::find(input)?)));
        }
        if let Some(capture) = capture {
            return Source::capture(capture?, Path::new(input));
        }
        if recording {
            let recording = coulomb_hands::input::recording::load(Path::new(input))?;
            let playback = match &options.head {
                Some(head) => {
                    recording.playback_through(&head.conversion(&recording)?, DEFAULT_GRACE)
                }
                None => recording.playback(glam::Vec3::ZERO, DEFAULT_GRACE),
            }?;
            let mut scene = options.scene.as_deref().map(Scene::load).transpose()?;
            let object = match options.object {
                Some((object, ObjectPlace::Grasp)) => Some(object),
                Some((object, ObjectPlace::At(at))) => {
                    let objects = &mut scene.get_or_insert_with(Scene::default).objects;
                    objects.push(object.desc("object", at));
                    None
                }
                None => None,
            };
            let name = recording.source_name.clone();
            let (head, playback) = (options.head, Box::new(playback));
            return Ok(Source::Recording { name, playback, scene, object, head });
        }
        Ok(Source::Scene { name: input.to_string(), scene: Scene::load(Path::new(input))? })
    }

    /// The capture at `path`, read by the core's loader (a bad capture is
    /// its error, naming the file, frame and field).
    fn capture(capture: Capture, path: &Path) -> Result<Source, LoadError> {
        let playback = Box::new(capture.playback()?);
        let (name, credit) = (capture.source_name.clone(), credit(path));
        Ok(Source::Capture { name, capture: Arc::new(capture), playback, credit })
    }

    /// The capture viewed, if it is one.
    pub fn captured(&self) -> Option<&Capture> {
        match self {
            Source::Capture { capture, .. } => Some(capture),
            _ => None,
        }
    }

    /// The head a recording's tracker was worn on, whose eyes the camera takes.
    pub fn head(&self) -> Option<&HeadMount> {
        match self {
            Source::Recording { head, .. } => head.as_ref(),
            _ => None,
        }
    }

    /// A name for the HUD.
    pub fn name(&self) -> &str {
        match self {
            Source::Scenario(s) => &s.name,
            Source::Recording { name, .. }
            | Source::Capture { name, .. }
            | Source::Scene { name, .. }
            | Source::LiveXr { name, .. }
            | Source::LiveLeap { name, .. } => name,
            Source::Task { .. } => "chessboard task",
        }
    }

    /// How long it plays (s), or `None` for a scene, which runs until
    /// closed.
    pub fn duration(&self) -> Option<f64> {
        match self {
            Source::Scenario(s) => Some(f64::from(s.duration)),
            Source::Recording { playback, .. } | Source::Capture { playback, .. } => {
                Some(playback.duration)
            }
            Source::Scene { .. }
            | Source::LiveXr { .. }
            | Source::LiveLeap { .. }
            | Source::Task { .. } => None,
        }
    }

    /// The same scene with both hands from an XR runtime: the desk's, or
    /// a scene's (a scenario or recording has hands of its own).
    pub fn live_xr(self) -> Result<Source, LoadError> {
        match self {
            Source::Scene { name, scene } => Ok(Source::LiveXr { name, scene }),
            _ => Err(format!("{}: --openxr takes a scene file, or none", self.name()).into()),
        }
    }

    /// The same scene with both hands from the Leap Motion service at
    /// `url`, a desktop device at `device` in the scene (m). Connects now,
    /// so a service that is not there is an error before any window.
    pub fn live_leap(self, url: &str, device: glam::Vec3) -> Result<Source, LoadError> {
        match self {
            Source::Scene { name, scene } => {
                let conversion = Conversion::leap_desktop(device);
                let feed = LiveFeed::connect(url, conversion, DEFAULT_GRACE)?;
                Ok(Source::LiveLeap { name, scene, feed })
            }
            _ => Err(format!("{}: --leap takes a scene file, or none", self.name()).into()),
        }
    }

    /// Whether the hands come from a live tracker (Leap or XR), which plays
    /// at its own pace.
    pub fn is_live(&self) -> bool {
        matches!(self, Source::LiveXr { .. } | Source::LiveLeap { .. })
    }

    /// The live Leap stream, when the hands are its.
    pub fn leap_feed(&self) -> Option<&LiveFeed> {
        match self {
            Source::LiveLeap { feed, .. } => Some(feed),
            _ => None,
        }
    }

    /// A fresh world at t = 0 under `method`, with the hands it poses
    /// itself (a scenario's, a recording's, a live stream's). The hands the
    /// viewer's systems pose are [`Source::app_hands`].
    pub fn build(&self, method: Method) -> Result<HandPhysics, LoadError> {
        match self {
            Source::Scenario(s) => {
                let mut scenario = (**s).clone();
                scenario.config = method.config(scenario.config);
                Ok(HandPhysics::of_scenario(&scenario)?)
            }
            Source::Recording { playback, scene, object, .. } => {
                // The CLI's replay world: a ground at y = 0, then the scene.
                let mut physics = HandPhysics::new(world(scene.as_ref(), method, true)?);
                add_recorded_hands(&mut physics, playback);
                if let Some(object) = object {
                    physics.observe(Closings::new(playback, *object)?);
                }
                Ok(physics)
            }
            Source::Capture { capture, playback, .. } => {
                // `replay_capture`'s world and hand: the table, the object
                // at its first captured pose, the fitted hand's playback.
                let options = CaptureOptions { method, ..CaptureOptions::default() };
                let (world, _object) = capture_world(capture, &options)?;
                let mut physics = HandPhysics::new(world);
                add_recorded_hands(&mut physics, playback);
                Ok(physics)
            }
            Source::LiveLeap { scene, feed, .. } => {
                // Each build's hands tie their clock to the stream afresh
                // (both on one tie): a restart plays on from the newest
                // frames.
                let mut physics = HandPhysics::new(world(Some(scene), method, false)?);
                for hand in feed.hands() {
                    physics.add_hand(hand);
                }
                Ok(physics)
            }
            Source::LiveXr { scene, .. } | Source::Scene { scene, .. } => {
                Ok(HandPhysics::new(world(Some(scene), method, false)?))
            }
            Source::Task { placement, .. } => {
                let config = method.config(InteractionConfig::default());
                let (world, _cube) = board::world(config, placement.start, placement.yaw)?;
                Ok(HandPhysics::new(world))
            }
        }
    }

    /// The hands the viewer's own systems pose, as app hands that outlive
    /// each rebuilt world: a scene's and the task's mouse hand, or an XR
    /// runtime's two hands.
    pub fn app_hands(&self) -> &'static [(Side, HandDriver)] {
        match self {
            Source::Scene { .. } | Source::Task { .. } => &[(Side::Right, HandDriver::Mouse)],
            Source::LiveXr { .. } => &[(Side::Left, HandDriver::Xr), (Side::Right, HandDriver::Xr)],
            Source::Scenario(_)
            | Source::Recording { .. }
            | Source::Capture { .. }
            | Source::LiveLeap { .. } => &[],
        }
    }
}

/// Adds one hand per track of `playback`, each replaying it.
fn add_recorded_hands(physics: &mut HandPhysics, playback: &Playback) {
    for track in 0..playback.tracks.len() {
        let playback = Box::new(playback.clone());
        physics.add_hand(ScenarioHand::Recording { playback, track });
    }
}

/// The `source` note of the capture file at `path`, a string beside its
/// data that credits where it came from (TACO's names its paper and its
/// licence, CC BY 4.0, which asks for that credit wherever it is shown).
/// The core reads no notes, so the viewer reads this one itself, without
/// parsing the file's frames a second time.
fn credit(path: &Path) -> Option<String> {
    let text = std::fs::read_to_string(path).ok()?;
    let at = text.find("\"source\"")?;
    let value = text[at + "\"source\"".len()..].trim_start().strip_prefix(':')?;
    serde_json::Deserializer::from_str(value).into_iter::<String>().next()?.ok()
}

/// A world under `method` with `scene` in it, on the replays' ground at
/// y = 0 if `ground`.
fn world(
    scene: Option<&Scene>,
    method: Method,
    ground: bool,
) -> Result<InteractionWorld, LoadError> {
    let mut config = method.config(InteractionConfig::default());
    if let Some(scene) = scene {
        config = config.with_scene(scene);
    }
    let mut world = match ground {
        true => replay_world(config, false)?,
        false => InteractionWorld::new(config)?,
    };
    if let Some(scene) = scene {
        world.add_scene(scene)?;
    }
    Ok(world)
}

/// Whether the file at `path` is a scenario: a JSON object with `hands`.
fn is_scenario(path: &str) -> bool {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    serde_json::from_str::<serde_json::Value>(&text).is_ok_and(|v| v.get("hands").is_some())
}

/// Whether the file at `path` is a tracking recording: compressed or JSON
/// lines by its name, or a Leap recording's JSON (`frames` or `metadata`).
fn is_recording(path: &str) -> bool {
    if path.ends_with(".lz") || path.ends_with(".jsonl") {
        return true;
    }
    let text = std::fs::read_to_string(path).unwrap_or_default();
    serde_json::from_str::<serde_json::Value>(&text)
        .is_ok_and(|v| v.get("frames").is_some() || v.get("metadata").is_some())
}
