//! Scenarios: the thesis's interaction catalogue (Ch. 4) as files that run
//! headlessly and check their own outcome.
//!
//! A scenario file (JSON) holds a [scene](crate::scene), the hands that act
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
//!   or a Leap recording,
//!   `{"recording": "path.json.lz", "offset": [x, y, z]}`, whose path is
//!   relative to the scenario file.
//! * `checks`: see [`check::Measure`] for what can be measured.
//!
//! Unknown fields are errors; every name, bound and key is checked before
//! the run starts. The shipped scenarios are in `scenarios/` and built into
//! the binary ([`shipped`]).

pub mod check;
pub mod script;

use crate::hand::Side;
use crate::input::convert::Conversion;
use crate::input::playback::{DEFAULT_GRACE, Playback};
use crate::pipeline::{HandId, InteractionConfig, InteractionWorld, WorldError};
use crate::replay::{TraceHand, TraceLine};
use crate::scene::{Scene, SceneEntry};
use check::{Check, CheckResult, History};
use glam::Vec3;
use script::{Key, Script};
use std::path::{Path, PathBuf};

/// The scenarios shipped in `scenarios/`, by name, with their file text.
pub fn shipped() -> &'static [(&'static str, &'static str)] {
    macro_rules! shipped {
        ($($name:literal),* $(,)?) => {
            &[$(($name, include_str!(concat!("../../scenarios/", $name, ".json")))),*]
        };
    }
    shipped!["push", "pull", "grasp-lift", "palmar-grasp", "motion-control", "handover", "two-hand-balance", "spin-one-hand", "spin-two-hands", "tool-knock-tower", "jenga-one-hand", "jenga-two-hands", "flat-hand-lift", "catch", "slide-slippery", "tilt-wooden"]
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
    /// Where the recording's device sits in the world (m).
    #[serde(default)]
    offset: Vec3,
    /// Size of a scripted hand relative to the average adult's (1).
    #[serde(default = "one")]
    scale: f32,
}

fn one() -> f32 {
    1.0
}

/// Where a hand's poses come from.
#[derive(Debug, Clone)]
pub enum HandSource {
    Script(Script),
    Recording { playback: Box<Playback>, track: usize },
}

impl HandSource {
    fn side(&self) -> Side {
        match self {
            HandSource::Script(s) => s.rig.side,
            HandSource::Recording { playback, track } => playback.tracks[*track].side,
        }
    }
}

/// A checked scenario, ready to run.
#[derive(Debug, Clone)]
pub struct Scenario {
    pub name: String,
    pub description: String,
    /// Simulated length (s).
    pub duration: f32,
    pub config: InteractionConfig,
    pub scene: Scene,
    pub hands: Vec<HandSource>,
    pub checks: Vec<Check>,
}

/// Why a scenario could not be loaded; names the file and where.
pub type ScenarioError = crate::FileError;

/// The outcome of a run.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ScenarioReport {
    pub name: String,
    pub passed: bool,
    pub checks: Vec<CheckResult>,
}

impl Scenario {
    /// A shipped scenario by name, or else a scenario file by path.
    pub fn find(name_or_file: &str) -> Result<Scenario, ScenarioError> {
        match shipped().iter().find(|(n, _)| *n == name_or_file) {
            Some((name, text)) => {
                let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
                Self::parse(&format!("scenarios/{name}.json"), text, &dir)
            }
            None => Self::load(Path::new(name_or_file)).map_err(|e| {
                if Path::new(name_or_file).exists() {
                    e
                } else {
                    let names: Vec<&str> = shipped().iter().map(|s| s.0).collect();
                    ScenarioError::new(name_or_file, format!("no such file, nor a shipped scenario ({})", names.join(", ")))
                }
            }),
        }
    }

    pub fn load(path: &Path) -> Result<Scenario, ScenarioError> {
        let text = ScenarioError::read(path)?;
        Self::parse(&path.display().to_string(), &text, path.parent().unwrap_or(Path::new(".")))
    }

    /// Parses and checks a scenario; `dir` is where relative recording
    /// paths start.
    pub fn parse(file: &str, text: &str, dir: &Path) -> Result<Scenario, ScenarioError> {
        let fail = |reason: String| ScenarioError::new(file, reason);
        let entry: ScenarioEntry = ScenarioError::json(file, text)?;
        if !(entry.duration.is_finite() && entry.duration > 0.0) {
            return Err(fail(format!("duration: must be a positive number of seconds, got {}", entry.duration)));
        }
        let scene = Scene::from_entry(file, entry.scene, dir)?;
        let config = scene.config(entry.config);
        config.validate().map_err(|e| fail(format!("config: {e}")))?;
        let hands = entry
            .hands
            .into_iter()
            .enumerate()
            .map(|(i, h)| hand_source(h, dir).map_err(|e| fail(format!("hands[{i}].{e}"))))
            .collect::<Result<Vec<_>, _>>()?;
        let mut names: Vec<String> = scene.objects.iter().map(|o| o.name.clone()).collect();
        if !scene.towers.is_empty() {
            use crate::scenes::{TOWER_LEVELS, TOWER_SLOTS, tower_block_name};
            names.extend((0..TOWER_LEVELS).flat_map(|l| (0..TOWER_SLOTS).map(move |s| tower_block_name(l, s))));
        }
        for (i, c) in entry.checks.iter().enumerate() {
            let at = |why: String| fail(format!("checks[{i}] '{}': {why}", c.name));
            c.validate().map_err(at)?;
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
        Ok(Scenario { name: entry.name, description: entry.description, duration: entry.duration, config, scene, hands, checks: entry.checks })
    }

    /// Runs the scenario, calling `each` with the world and its trace line
    /// after every step, then evaluates the checks.
    pub fn run<E: From<WorldError>>(
        &self,
        mut each: impl FnMut(&InteractionWorld, &TraceLine) -> Result<(), E>,
    ) -> Result<ScenarioReport, E> {
        let mut world = InteractionWorld::new(self.config)?;
        self.scene.add_to(&mut world)?;
        let ids: Vec<HandId> = self.hands.iter().map(|h| world.add_hand(h.side())).collect();
        let dt = self.config.dt;
        let steps = (self.duration / dt).round() as usize;
        let objects = world.object_count();
        let mut history = History {
            dt,
            names: (0..objects as u32).map(|o| world.object_name(crate::ObjectId(o)).unwrap_or("").to_string()).collect(),
            ..History::default()
        };
        for i in 0..steps {
            let t = i as f32 * dt;
            let mut palms = Vec::with_capacity(self.hands.len());
            let mut trace_hands = Vec::with_capacity(self.hands.len());
            for (k, (hand, id)) in self.hands.iter().zip(&ids).enumerate() {
                let (pose, grab, pinch) = match hand {
                    HandSource::Script(s) => (Some(s.pose(t)), None, None),
                    HandSource::Recording { playback, track } => match playback.sample(*track, t as f64) {
                        Some(s) => (Some(s.pose), s.grab, s.pinch),
                        None => (None, None, None),
                    },
                };
                match &pose {
                    Some(p) => world.set_hand_pose(*id, p)?,
                    None => world.clear_hand_pose(*id)?,
                }
                palms.push(pose.as_ref().map(|p| (p.palm.center, p.palm.rotation)));
                if let Some(p) = pose {
                    trace_hands.push(TraceHand {
                        id: k as i64,
                        side: hand.side(),
                        palm: p.palm.to_world(Vec3::Y * p.palm.half_extents.y).to_array(),
                        grab,
                        pinch,
                    });
                }
            }
            world.step();
            let mut poses = Vec::with_capacity(objects);
            let mut speeds = Vec::with_capacity(objects);
            let mut contacts = vec![0u32; objects];
            for o in 0..objects as u32 {
                let s = world.object_state(crate::ObjectId(o))?;
                poses.push((s.position, s.rotation));
                speeds.push(s.linvel.length());
            }
            for c in world.contacts() {
                contacts[c.object.0 as usize] += 1;
            }
            history.poses.push(poses);
            history.speeds.push(speeds);
            history.contacts.push(contacts);
            history.palms.push(palms);
            each(&world, &TraceLine::of(&world, trace_hands))?;
        }
        let checks: Vec<CheckResult> = self.checks.iter().map(|c| c.evaluate(&history)).collect();
        Ok(ScenarioReport { name: self.name.clone(), passed: checks.iter().all(|c| c.passed), checks })
    }
}

fn hand_source(h: HandEntry, dir: &Path) -> Result<HandSource, String> {
    match (h.recording, h.keys.is_empty()) {
        (Some(_), false) => Err("keys: a hand is either scripted (keys) or recorded (recording), not both".into()),
        (None, true) => Err("keys: a scripted hand needs keys (or give a recording)".into()),
        (None, false) => {
            let side = h.side.ok_or("side: a scripted hand needs \"left\" or \"right\"")?;
            if h.offset != Vec3::ZERO {
                return Err("offset: only for recordings; key palm positions are in world coordinates".into());
            }
            if !(h.scale.is_finite() && (0.5..=1.5).contains(&h.scale)) {
                return Err(format!("scale: must be in [0.5, 1.5] (relative to an average adult hand), got {}", h.scale));
            }
            Script::with_rig(crate::hand::rig::HandRig::adult(side).scaled(h.scale), h.keys).map(HandSource::Script)
        }
        (Some(path), true) => {
            if h.scale != 1.0 {
                return Err("scale: only for scripted hands; a recording has its own hand size".into());
            }
            let path = dir.join(path);
            if !h.offset.is_finite() {
                return Err(format!("offset: must be finite, got {:?}", h.offset));
            }
            let recording = crate::input::leap::load(&path).map_err(|e| format!("recording: {e}"))?;
            let playback = Playback::new(&recording.source_name, &recording.frames, &Conversion::leap_desktop(h.offset), DEFAULT_GRACE)
                .map_err(|e| format!("recording: {e}"))?;
            let track = match h.side {
                None => 0,
                Some(side) => playback
                    .tracks
                    .iter()
                    .position(|t| t.side == side)
                    .ok_or(format!("side: the recording has no {side:?} hand"))?,
            };
            if playback.tracks.is_empty() {
                return Err("recording: it tracks no hands".into());
            }
            Ok(HandSource::Recording { playback: Box::new(playback), track })
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
        let base = r#"{"name": "x", "duration": 1.0, "scene": {"objects": [{"name": "box",
            "shape": {"Sphere": {"radius": 0.02}}, "mass": 0.1, "material": "wood", "position": [0, 0.1, 0]}]},
            "hands": [{"side": "right", "keys": [{"t": 0.0, "palm": [0, 0.3, 0]}]}],
            "checks": [CHECK]}"#;
        let parse = |check: &str| Scenario::parse("x.json", &base.replace("CHECK", check), Path::new(".")).map(|_| ());
        let ok = r#"{"name": "h", "measure": {"kind": "height", "object": "box", "at": 0.5}, "min": 0.0}"#;
        parse(ok).unwrap();
        let e = parse(&ok.replace("\"box\"", "\"bxo\"")).unwrap_err().to_string();
        assert!(e.contains("x.json") && e.contains("checks[0] 'h'") && e.contains("'bxo'"), "{e}");
        let e = parse(&ok.replace("\"at\"", "\"when\"")).unwrap_err().to_string();
        assert!(e.contains("x.json: line") && e.contains("when"), "{e}");
        let e = parse(&ok.replace(", \"min\": 0.0", "")).unwrap_err().to_string();
        assert!(e.contains("needs a bound"), "{e}");
        let e = Scenario::parse("x.json", &base.replace("CHECK", ok).replace("\"mass\": 0.1", "\"mass\": 0"), Path::new("."))
            .unwrap_err()
            .to_string();
        assert!(e.contains("'box'") && e.contains("mass"), "{e}");
        let e = Scenario::parse("x.json", &base.replace("CHECK", ok).replace("[0, 0.3, 0]", "[0, 0.3, 0]}, {\"t\": 0.0, \"palm\": [0, 0, 0]"), Path::new("."))
            .unwrap_err()
            .to_string();
        assert!(e.contains("hands[0].keys[1].t"), "{e}");
        let e = Scenario::find("no-such-scenario").unwrap_err().to_string();
        assert!(e.contains("push"), "lists the shipped ones: {e}");
    }
}
