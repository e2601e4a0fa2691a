//! Scenarios: the thesis's interaction catalogue (Ch. 4) as files that run
//! headlessly and check their own outcome.
//!
//! A scenario file (JSON) holds a [scene](crate::scene::file), the hands that act
//! in it, and checks with stated bounds:
//!
//! ```json
//! {
//!   "name": "push",
//!   "description": "Fingertips push a box along the ground.",
//!   "duration": 3.0,
//!   "config": {"gamma": "Auto"},
//!   "scene": {"ground": {"height": 0.0, "friction": 0.3},
//!             "objects": [{"name": "box", "shape": {"Box": {"half_extents": [0.03, 0.03, 0.03]}},
//!                          "mass": 0.1, "material": "wood", "position": [0.0, 0.03, 0.0]}]},
//!   "hands": [{"side": "right", "keys": [
//!       {"t": 0.0, "palm": [0.0, 0.05, -0.15], "rotation_deg": [0, 0, 90], "curl": 0.2},
//!       {"t": 2.0, "palm": [0.0, 0.05, 0.0], "rotation_deg": [0, 0, 90], "curl": 0.2}]}],
//!   "checks": [{"name": "pushed forward", "measure": {"kind": "displacement", "object": "box",
//!               "from": 0.0, "axis": [0, 0, 1]}, "min": 0.05}]
//! }
//! ```
//!
//! * `config`: any [`InteractionConfig`] fields; the others keep their
//!   defaults.
//! * `hands`: each either scripted, `{"side", "keys": [Key, ..]}` (see
//!   [`script::Key`]: time, palm centre, palm rotation in degrees, flexion
//!   per finger, optional knuckle flexion, thumb opposition, finger spread;
//!   optional `"scale"` for
//!   the hand's size),
//!   or a recording (Leap Motion, or a joint recording,
//!   [`crate::input::joints`]),
//!   `{"recording": "path.json.lz", "offset": [x, y, z]}`, whose path is
//!   relative to the scenario file; `offset` is where the recording's
//!   origin sits in the world (m).
//! * `checks`: see [`check::Measure`] for what can be measured; `contacts`
//!   counts only the hand contacts that press (normal force > 0), and an
//!   object's release (`release_speed`, `landing_error`,
//!   `landing_distance`, [`flight`]) is the last step such a contact
//!   pressed on it.
//!
//! Unknown fields are errors; every name, bound and key is checked before
//! the run starts. The shipped scenarios are in `scenarios/` and built into
//! the binary ([`shipped`]), with the files they name ([`shipped_files`]).

#[cfg(all(test, target_arch = "x86_64"))]
mod builds;
pub mod check;
pub mod flight;
pub mod history;
pub mod script;

use super::RunError;
use super::drive::{self, Driver, HandSource, Observer, RecordedHand};
use crate::file_error::FileError;
use crate::files::{FileSystem, Files};
use crate::hand::rig::HandRig;
use crate::hand::{HandSample, Side};
use crate::input::playback::{DEFAULT_GRACE, Playback};
use crate::pipeline::{InteractionConfig, InteractionWorld, Method};
use crate::scene::file::SceneEntry;
use crate::scene::{GammaMode, Scene};
use check::{Check, CheckResult, History};
use glam::Vec3;
use script::{Key, Script};
use std::path::{Path, PathBuf};

/// The scenarios shipped in `scenarios/`, by name, with their file text.
pub fn shipped() -> &'static [(&'static str, &'static str)] {
    macro_rules! shipped {
        ($($name:literal),* $(,)?) => {
            &[$(($name, include_str!(concat!("../../../scenarios/", $name, ".json")))),*]
        };
    }
    shipped![
        "push",
        "push-steady",
        "pull",
        "grasp-lift",
        "palmar-grasp",
        "motion-control",
        "handover",
        "two-hand-balance",
        "spin-one-hand",
        "spin-two-hands",
        "tool-knock-tower",
        "jenga-one-hand",
        "jenga-two-hands",
        "flat-hand-lift",
        "plate-carry",
        "ball-roll",
        "catch",
        "slide-slippery",
        "tilt-wooden",
        "throw",
    ]
}

/// The files the shipped scenarios name (the pawn's mesh), built in beside
/// them: by their paths joined to the shipped scenarios' folder,
/// `scenarios/` of the crate's source, as [`Scenario::find`] looks them up.
/// Any other path is not found.
pub fn shipped_files(path: &Path) -> std::io::Result<Vec<u8>> {
    const FILES: [(&str, &[u8]); 1] =
        [("../assets/meshes/pawn.obj", include_bytes!("../../../assets/meshes/pawn.obj"))];
    let dir = shipped_dir();
    let found = FILES.iter().find(|(name, _)| dir.join(name) == path);
    found.map(|(_, bytes)| bytes.to_vec()).ok_or_else(crate::files::not_given)
}

/// The folder of the shipped scenarios: `scenarios/` of the crate's source.
fn shipped_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios")
}

#[derive(Debug, Clone, serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct ScenarioEntry {
    name: String,
    #[serde(default)]
    description: String,
    duration: f32,
    #[serde(default)]
    config: InteractionConfig,
    scene: SceneEntry,
    #[serde(default)]
    hands: Vec<HandEntry>,
    checks: Vec<Check>,
}

#[derive(Debug, Clone, serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct HandEntry {
    side: Option<Side>,
    #[serde(default)]
    keys: Vec<Key>,
    recording: Option<PathBuf>,
    /// Where the recording's origin (a Leap device) sits in the world (m).
    #[serde(default)]
    offset: Vec3,
    /// Size of a scripted hand relative to the average adult's (1).
    #[serde(default = "one")]
    scale: f32,
}

fn one() -> f32 {
    1.0
}

/// Where a scenario hand's poses come from.
#[derive(Debug, Clone)]
pub enum ScenarioHand {
    /// Keyframes on the rig.
    Script(Script),
    /// One hand of a recording.
    Recording {
        /// The recording, converted.
        playback: Box<Playback>,
        /// Which of its tracks.
        track: usize,
    },
}

impl ScenarioHand {
    /// This hand as the driver's source.
    pub fn source(&self) -> Box<dyn HandSource + '_> {
        match self {
            ScenarioHand::Script(s) => Box::new(s),
            ScenarioHand::Recording { playback, track } => {
                Box::new(RecordedHand { playback, track: *track })
            }
        }
    }
}

/// An owned scenario hand is a source too, for a driver that outlives the
/// scenario (an app's, which keeps its driver in a resource).
impl HandSource for ScenarioHand {
    fn side(&self) -> Side {
        match self {
            ScenarioHand::Script(s) => s.rig.side,
            ScenarioHand::Recording { playback, track } => {
                RecordedHand { playback, track: *track }.side()
            }
        }
    }

    fn tracker_id(&self) -> Option<i64> {
        match self {
            ScenarioHand::Script(_) => None,
            ScenarioHand::Recording { playback, track } => {
                RecordedHand { playback, track: *track }.tracker_id()
            }
        }
    }

    fn sample(&mut self, t: f64) -> Result<Option<HandSample>, RunError> {
        match self {
            ScenarioHand::Script(s) => (&*s).sample(t),
            ScenarioHand::Recording { playback, track } => {
                RecordedHand { playback, track: *track }.sample(t)
            }
        }
    }
}

/// A checked scenario, ready to run.
#[derive(Debug, Clone)]
pub struct Scenario {
    /// Its name.
    pub name: String,
    /// What it shows, in a sentence or two.
    pub description: String,
    /// Simulated length (s).
    pub duration: f32,
    /// The world's config, with the scene's gravity.
    pub config: InteractionConfig,
    /// What is in the world.
    pub scene: Scene,
    /// The hands, in file order.
    pub hands: Vec<ScenarioHand>,
    /// What must hold of the run.
    pub checks: Vec<Check>,
}

/// Why a scenario could not be loaded; names the file and where.
pub type ScenarioError = FileError;

/// The outcome of a run.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ScenarioReport {
    /// The scenario's name.
    pub name: String,
    /// Whether every check passed.
    pub passed: bool,
    /// Each check's value and bound.
    pub checks: Vec<CheckResult>,
}

/// `scenario --json`'s one object: the reports of the scenarios run.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ScenarioReports<'a> {
    /// One report per scenario, in the order run.
    pub scenarios: Vec<&'a ScenarioReport>,
}

impl Scenario {
    /// A shipped scenario by name, or else a scenario file by path.
    pub fn find(name_or_file: &str) -> Result<Scenario, ScenarioError> {
        match shipped().iter().find(|(n, _)| *n == name_or_file) {
            Some((name, text)) => {
                let file = format!("scenarios/{name}.json");
                Self::parse_with(&file, text, &shipped_dir(), &shipped_files)
            }
            None => Self::load(Path::new(name_or_file)).map_err(|e| {
                if Path::new(name_or_file).exists() {
                    e
                } else {
                    let names: Vec<&str> = shipped().iter().map(|s| s.0).collect();
                    let why =
                        format!("no such file, nor a shipped scenario ({})", names.join(", "));
                    ScenarioError::new(name_or_file, why)
                }
            }),
        }
    }

    /// The same scenario with its hands moving objects by `method`: its
    /// config through [`Method::config`].
    pub fn with_method(self, method: Method) -> Scenario {
        Scenario { config: method.config(self.config), ..self }
    }

    /// Reads and checks a scenario file.
    pub fn load(path: &Path) -> Result<Scenario, ScenarioError> {
        let text = ScenarioError::read(path)?;
        Self::parse(&path.display().to_string(), &text, path.parent().unwrap_or(Path::new(".")))
    }

    /// Parses and checks a scenario; `dir` is where relative recording
    /// and mesh paths start.
    pub fn parse(file: &str, text: &str, dir: &Path) -> Result<Scenario, ScenarioError> {
        Self::parse_with(file, text, dir, &FileSystem)
    }

    /// [`Self::parse`], the recordings and meshes it names read from
    /// `files` ([`crate::files`]).
    pub fn parse_with(
        file: &str,
        text: &str,
        dir: &Path,
        files: &dyn Files,
    ) -> Result<Scenario, ScenarioError> {
        let fail = |reason: String| ScenarioError::new(file, reason);
        let entry: ScenarioEntry = ScenarioError::json(file, text)?;
        if !(entry.duration.is_finite() && entry.duration > 0.0) {
            let d = entry.duration;
            return Err(fail(format!("duration: must be a positive number of seconds, got {d}")));
        }
        let scene = Scene::from_entry(file, entry.scene, dir, files)?;
        let config = entry.config.with_scene(&scene);
        config.validate().map_err(|e| fail(e.to_string()))?;
        if entry.duration < config.dt {
            let (d, dt) = (entry.duration, config.dt);
            return Err(fail(format!("duration: must be at least one step (dt {dt} s), got {d}")));
        }
        auto_gamma_needs(&scene, &config).map_err(fail)?;
        let hands = entry
            .hands
            .into_iter()
            .enumerate()
            .map(|(i, h)| scenario_hand(h, dir, files).map_err(|e| fail(format!("hands[{i}].{e}"))))
            .collect::<Result<Vec<_>, _>>()?;
        let names = scene.object_names();
        for (i, c) in entry.checks.iter().enumerate() {
            let at = |why: String| fail(format!("checks[{i}] '{}': {why}", c.name));
            c.validate().map_err(|e| at(e.to_string()))?;
            let (objects, hand) = c.references();
            if let Some(o) = objects.iter().find(|o| !names.iter().any(|n| n == *o)) {
                return Err(at(format!("no object named '{o}' in the scene")));
            }
            if let Some(h) = hand.filter(|&h| h >= hands.len()) {
                return Err(at(format!("hand {h}: the scenario has {} hands", hands.len())));
            }
        }
        if entry.checks.is_empty() {
            return Err(fail("checks: a scenario needs at least one check".into()));
        }
        let (name, description, duration) = (entry.name, entry.description, entry.duration);
        Ok(Scenario { name, description, duration, config, scene, hands, checks: entry.checks })
    }

    /// Runs the scenario, showing every step to `observers` too, then
    /// evaluates the checks.
    pub fn run(&self, observers: &mut [&mut dyn Observer]) -> Result<ScenarioReport, RunError> {
        self.run_in(None, observers)
    }

    /// The physics steps a run takes: its duration, and at least one, so
    /// the checks have a state to measure.
    pub fn steps(&self) -> usize {
        ((self.duration / self.config.dt).round() as usize).max(1)
    }

    /// [`Self::run`] in host mode: `host` gives the objects' states and
    /// integrates every step ([`drive::Host`]); its world holds the same
    /// scene, object for object.
    pub fn run_hosted(
        &self,
        host: Box<dyn drive::Host + '_>,
        observers: &mut [&mut dyn Observer],
    ) -> Result<ScenarioReport, RunError> {
        self.run_in(Some(host), observers)
    }

    fn run_in(
        &self,
        host: Option<Box<dyn drive::Host + '_>>,
        observers: &mut [&mut dyn Observer],
    ) -> Result<ScenarioReport, RunError> {
        let mut world = InteractionWorld::new(self.config)?;
        world.add_scene(&self.scene)?;
        let mut history = History::new(&world);
        let mut driver = Driver::new(&mut world);
        for hand in &self.hands {
            driver.add_hand(hand.source());
        }
        if let Some(host) = host {
            driver.set_host(host)?;
        }
        driver.run(self.steps(), &mut drive::observers(vec![&mut history], observers))?;
        let checks: Vec<CheckResult> = self.checks.iter().map(|c| c.evaluate(&history)).collect();
        Ok(ScenarioReport {
            name: self.name.clone(),
            passed: checks.iter().all(|c| c.passed),
            checks,
        })
    }
}

/// Why a scenario hand is wrong; the text starts with the field.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum HandError {
    /// A bad keyframe.
    #[error(transparent)]
    Key(#[from] script::KeyError),
    /// A field that does not fit the hand's kind or range.
    #[error("{field}: {reason}")]
    Field {
        /// The field, e.g. `scale`.
        field: &'static str,
        /// What is wrong.
        reason: String,
    },
    /// The recording could not be read.
    #[error("recording: {0}")]
    Recording(#[from] crate::input::InputError),
}

/// The automatic γ (`gamma: "Auto"`, §3.5.6) needs gravity and skin
/// friction: an object without either is an error before the run.
fn auto_gamma_needs(scene: &Scene, config: &InteractionConfig) -> Result<(), String> {
    let blocks = scene.towers.iter().flat_map(|t| t.blocks());
    for o in scene.objects.iter().cloned().chain(blocks) {
        let (g, mu) = (config.gravity.length(), o.material.skin.static_mu);
        if o.gamma.unwrap_or(config.gamma) == GammaMode::Auto && !(g > 0.0 && mu > 0.0) {
            let why = format!(
                "\"Auto\" needs gravity and material.skin.static_mu > 0, got {g} m/s² and {mu}"
            );
            return Err(format!("object '{}': gamma: {why}", o.name));
        }
    }
    Ok(())
}

fn scenario_hand(h: HandEntry, dir: &Path, files: &dyn Files) -> Result<ScenarioHand, HandError> {
    let field = |field, reason: &str| HandError::Field { field, reason: reason.to_string() };
    match (h.recording, h.keys.is_empty()) {
        (Some(_), false) => {
            Err(field("keys", "a hand is either scripted (keys) or recorded (recording), not both"))
        }
        (None, true) => Err(field("keys", "a scripted hand needs keys (or give a recording)")),
        (None, false) => {
            let side =
                h.side.ok_or(field("side", "a scripted hand needs \"left\" or \"right\""))?;
            if h.offset != Vec3::ZERO {
                let why = "only for recordings; key palm positions are in world coordinates";
                return Err(field("offset", why));
            }
            if !(h.scale.is_finite() && (0.5..=1.5).contains(&h.scale)) {
                let why = format!(
                    "must be in [0.5, 1.5] (relative to an average adult hand), got {}",
                    h.scale
                );
                return Err(field("scale", &why));
            }
            let rig = HandRig::adult(side).scaled(h.scale);
            Ok(ScenarioHand::Script(Script::with_rig(rig, h.keys)?))
        }
        (Some(path), true) => {
            if h.scale != 1.0 {
                let why = "only for scripted hands; a recording has its own hand size";
                return Err(field("scale", why));
            }
            if !h.offset.is_finite() {
                return Err(field("offset", &format!("must be finite, got {:?}", h.offset)));
            }
            let recording = crate::input::recording::load_from(&dir.join(path), files)?;
            let playback = recording.playback(h.offset, DEFAULT_GRACE)?;
            let track = match h.side {
                None => 0,
                Some(side) => {
                    playback.tracks.iter().position(|t| t.side == side).ok_or_else(|| {
                        let side = format!("{side:?}").to_lowercase();
                        field("side", &format!("the recording has no {side} hand"))
                    })?
                }
            };
            if playback.tracks.is_empty() {
                let mut why = String::from("it tracks no hands");
                let left_out: Vec<String> =
                    playback.skipped.iter().map(|s| s.to_string()).collect();
                if !left_out.is_empty() {
                    why += &format!(" (left out: {})", left_out.join("; "));
                }
                return Err(field("recording", &why));
            }
            Ok(ScenarioHand::Recording { playback: Box::new(playback), track })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shipped_scenario_parses() {
        for (name, _) in shipped() {
            let s = Scenario::find(name).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(&s.name, name);
        }
    }

    #[test]
    fn bad_files_are_rejected_before_a_run_naming_the_place() {
        let base = concat!(
            r#"{"name": "x", "duration": 1.0, "scene": {"objects": [{"name": "box",
            "shape": {"Sphere": {"radius": 0.02}}, "mass": 0.1, "material": "wood", "#,
            r#""position": [0, 0.1, 0]}]},
            "hands": [{"side": "right", "keys": [{"t": 0.0, "palm": [0, 0.3, 0]}]}],
            "checks": [CHECK]}"#
        );
        let parse = |check: &str| {
            Scenario::parse("x.json", &base.replace("CHECK", check), Path::new(".")).map(|_| ())
        };
        let ok = concat!(
            r#"{"name": "h", "measure": {"kind": "height", "object": "box", "at": 0.5}, "#,
            r#""min": 0.0}"#
        );
        parse(ok).unwrap();
        let e = parse(&ok.replace("\"box\"", "\"bxo\"")).unwrap_err().to_string();
        assert!(e.contains("x.json") && e.contains("checks[0] 'h'") && e.contains("'bxo'"), "{e}");
        let e = parse(&ok.replace("\"at\"", "\"when\"")).unwrap_err().to_string();
        assert!(e.contains("x.json: line") && e.contains("when"), "{e}");
        let e = parse(&ok.replace(", \"min\": 0.0", "")).unwrap_err().to_string();
        assert!(e.contains("needs a bound"), "{e}");
        let e = Scenario::parse(
            "x.json",
            &base.replace("CHECK", ok).replace("\"mass\": 0.1", "\"mass\": 0"),
            Path::new("."),
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("'box'") && e.contains("mass"), "{e}");
        let e = Scenario::parse(
            "x.json",
            &base
                .replace("CHECK", ok)
                .replace("[0, 0.3, 0]", "[0, 0.3, 0]}, {\"t\": 0.0, \"palm\": [0, 0, 0]"),
            Path::new("."),
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("hands[0].keys[1].t"), "{e}");
        let e = Scenario::find("no-such-scenario").unwrap_err().to_string();
        assert!(e.contains("push"), "lists the shipped ones: {e}");
    }
}
