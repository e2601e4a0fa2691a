//! The runs that `coulomb-hands report` shows, as the report's data
//! ([`crate::output::report`]): scenarios with every object's hand force
//! and height per step, recordings replayed with an object at every
//! closing of their hands, judged ([`super::closing`]), and the bundled
//! hand–object capture replayed with each method ([`super::capture`]). A
//! run that fails is a section entry with its error, not an error of the
//! report.

use super::RunError;
use super::capture::{CaptureOptions, replay_capture};
use super::clock::Clock;
use super::closing::{ClosingVerdict, Hold};
use super::drive::{Observer, StepView};
use super::grasp::{SAMPLE_STEP, find_grasps, is_power_grasp};
use super::replay::{GraspObject, replay, replay_closings, replay_world};
use super::scenario::Scenario;
use crate::input::capture::{self, Capture};
use crate::input::playback::{DEFAULT_GRACE, Playback};
use crate::input::recording::{self, Recording};
use crate::output::report::{
    CaptureMethodRun, CaptureRuns, ObjectSeries, ReplayObject, ReplayRun, ScenarioRun, Verdict,
};
use crate::pipeline::{InteractionConfig, Method};
use std::path::{Path, PathBuf};

/// Records every object's hand force (magnitude, N) and height (m) after
/// each step.
#[derive(Debug, Clone, Default)]
pub struct ObjectSeriesRecorder {
    /// One series per object, by id.
    pub objects: Vec<ObjectSeries>,
    steps: usize,
}

impl Observer for ObjectSeriesRecorder {
    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        let world = step.world;
        for (id, state) in world.object_slots() {
            let k = id.0 as usize;
            if k == self.objects.len() {
                // An object added during the run: not there before.
                let name = world.object_name(id).unwrap_or("").to_string();
                let missing = vec![f32::NAN; self.steps];
                let (hand_force_n, height_m) = (missing.clone(), missing);
                self.objects.push(ObjectSeries { name, hand_force_n, height_m });
            }
            // A removed object's series goes on as NaN.
            let o = &mut self.objects[k];
            o.hand_force_n.push(state.map_or(f32::NAN, |s| s.hand_force.length()));
            o.height_m.push(state.map_or(f32::NAN, |s| s.position.y));
        }
        self.steps += 1;
        Ok(())
    }
}

/// Runs `scenario` once, recording its objects; the run's verdict, or its
/// error. Its wall time is the system clock's.
#[cfg(not(target_arch = "wasm32"))]
pub fn scenario_run(scenario: &Scenario) -> ScenarioRun {
    scenario_run_with(scenario, &super::clock::SystemClock::new())
}

/// [`scenario_run`], its wall time read from `clock`.
pub fn scenario_run_with(scenario: &Scenario, clock: &dyn Clock) -> ScenarioRun {
    let mut recorder = ObjectSeriesRecorder::default();
    let started = clock.now();
    let result = scenario.run(&mut [&mut recorder]);
    let wall_s = clock.now().saturating_sub(started).as_secs_f64();
    let (passed, checks, error) = match result {
        Ok(r) => {
            let verdict = |c: &super::scenario::check::CheckResult| Verdict {
                name: c.name.clone(),
                value: c.value.into(),
                bound: c.bound.clone(),
                passed: c.passed,
            };
            (r.passed, r.checks.iter().map(verdict).collect(), None)
        }
        Err(e) => (false, Vec::new(), Some(e.to_string())),
    };
    ScenarioRun {
        name: scenario.name.clone(),
        description: scenario.description.clone(),
        passed,
        wall_s,
        checks,
        error,
        dt: scenario.config.dt.into(),
        objects: recorder.objects,
    }
}

/// The Leap recordings bundled in the repository's `data/leap/`
/// (`.json.lz` and `.json`), sorted; none if it cannot be read.
pub fn bundled_recordings() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/leap");
    let Ok(entries) = std::fs::read_dir(&dir) else { return Vec::new() };
    let mut files: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.to_str().is_some_and(|s| s.ends_with(".json.lz") || s.ends_with(".json")))
        .collect();
    files.sort();
    files
}

/// A recording read and ready to replay.
#[derive(Debug, Clone)]
pub struct ReplayInput {
    /// The file's name for the report: relative to the repository when
    /// it is in it.
    pub name: String,
    /// The recording.
    pub recording: Recording,
    /// Its hands on the physics clock.
    pub playback: Playback,
}

/// The object held at a grasp: a 4 cm, 50 g box in a fist
/// ([`is_power_grasp`] at the most closed instant), else a 2 cm, 10 g box,
/// as the book's replay examples hold. (A 4.5 cm box is wider than the gap
/// an opened hand leaves between its index and ring fingers, 37 mm in
/// `grab.json.lz`: it stays pinched between them.)
pub fn grasp_object(playback: &Playback, track: usize, closed_at: f64) -> GraspObject {
    let fist = playback.sample(track, closed_at).is_some_and(|s| is_power_grasp(&s));
    let (size, mass) = if fist { (0.04, 0.05) } else { (0.02, 0.01) };
    GraspObject { sphere: false, size, mass }
}

impl ReplayInput {
    /// Reads a recording of any format ([`recording::load`]); errors name
    /// the file, the frame and the field.
    pub fn load(path: &Path) -> Result<ReplayInput, RunError> {
        let recording = recording::load(path)?;
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let name = path.strip_prefix(root).unwrap_or(path).display().to_string();
        ReplayInput::new(name, recording)
    }

    /// A recording already read (from its bytes, [`recording::from_bytes`]),
    /// `name`d so in the report.
    pub fn new(name: String, recording: Recording) -> Result<ReplayInput, RunError> {
        let playback = recording.playback(glam::Vec3::ZERO, DEFAULT_GRACE)?;
        Ok(ReplayInput { name, recording, playback })
    }

    /// Replays it with the replay's defaults and an object
    /// ([`grasp_object`]) at every closing of its hands; what it did and
    /// each closing's verdicts, or its error.
    pub fn run(&self) -> ReplayRun {
        let mut out = ReplayRun {
            recording: self.name.clone(),
            format: self.recording.format.to_string(),
            frames: self.playback.frames,
            hands: self.playback.tracks.len(),
            duration_s: self.playback.duration,
            glitches: self.playback.skipped.len(),
            ..ReplayRun::default()
        };
        if let Err(e) = self.replay_into(&mut out) {
            out.error = Some(e.to_string());
        }
        out
    }

    fn replay_into(&self, out: &mut ReplayRun) -> Result<(), RunError> {
        let mut world = replay_world(InteractionConfig::default(), false)?;
        let playback = &self.playback;
        let name = &self.recording.source_name;
        let closings = find_grasps(playback, SAMPLE_STEP);
        let summary = match closings.iter().find(|c| c.sustained) {
            None => {
                out.placed = match closings.len() {
                    0 => "none: no hand closes in the recording".into(),
                    n => format!("none: each of its {n} closings is too short to judge"),
                };
                replay(name, playback, &mut world, &[], &mut [])?
            }
            Some(first) => {
                let object = grasp_object(playback, first.track, first.closed_at);
                let judged = closings.iter().filter(|c| c.sustained).count();
                out.placed = format!(
                    "a {:.1} cm, {:.0} g box at each of its {judged} closings long enough to judge",
                    object.size * 100.0,
                    object.mass * 1000.0,
                );
                replay_closings(name, playback, &mut world, object, &mut [])?
            }
        };
        let (judged, not): (Vec<_>, Vec<_>) =
            summary.closings.iter().partition(|c| c.hold == Hold::Judged);
        out.verdicts = judged.into_iter().flat_map(closing_verdicts).collect();
        out.not_judged = not.iter().map(ToString::to_string).collect();
        out.steps = summary.steps;
        out.contacts_begun = summary.contacts_begun;
        out.all_finite = summary.all_finite;
        let object = |o: &super::observe::ObjectSummary| ReplayObject {
            name: o.name.clone(),
            displacement_m: o.displacement.into(),
            max_speed_m_s: o.max_speed.into(),
        };
        out.objects = summary.objects.iter().map(object).collect();
        Ok(())
    }
}

/// A closing's verdict as the report's rows: held (its drift in the palm
/// frame against the slip bound), and let go after opening (how long after
/// the hand began to open).
fn closing_verdicts(c: &ClosingVerdict) -> [Verdict; 2] {
    let label = c.label();
    let let_go = c.released_at.map_or(f64::NAN, |t| t - c.opening_at);
    [
        Verdict {
            name: format!("{label}: held, drift in the palm frame (mm)"),
            value: f64::from(c.drift) * 1e3,
            bound: format!("< {:.1}", c.slip_bound * 1e3),
            passed: c.held(),
        },
        Verdict {
            name: format!("{label}: released, after the hand began to open (s)"),
            value: let_go,
            bound: format!("≤ {:.2}", c.release_by - c.opening_at),
            passed: c.released == Some(true),
        },
    ]
}

/// The hand–object capture bundled in the repository's `data/taco/`.
pub const BUNDLED_CAPTURE: &str = "data/taco/taco_20231104_017.json";

/// The bundled capture's credit, which its licence asks for wherever the
/// data or figures drawn from it are shown (`data/taco/README.md`).
pub const TACO_CREDIT: &str = "TACO (Liu et al., CVPR 2024), CC BY 4.0";

/// A hand–object capture read and ready to replay with each method.
#[derive(Debug, Clone)]
pub struct CaptureInput {
    /// The file's name for the report, relative to the repository.
    pub name: String,
    /// Whose data it is and under which licence.
    pub credit: String,
    /// The capture.
    pub capture: Capture,
}

impl CaptureInput {
    /// The bundled capture ([`BUNDLED_CAPTURE`]), read; `None` if it is not
    /// beside this build (the published crate leaves it out). An error
    /// names the file and what is wrong with it.
    pub fn bundled() -> Result<Option<CaptureInput>, RunError> {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(BUNDLED_CAPTURE);
        if !path.is_file() {
            return Ok(None);
        }
        let (name, credit) = (BUNDLED_CAPTURE.to_string(), TACO_CREDIT.to_string());
        Ok(Some(CaptureInput { name, credit, capture: capture::load(&path)? }))
    }

    /// Replays it with `method` at the default mass and material
    /// ([`CaptureOptions::default`]): the score and the per-frame series
    /// the report plots, or why it stopped.
    pub fn run(&self, method: Method) -> CaptureMethodRun {
        let mut out = CaptureMethodRun { method: method.to_string(), ..Default::default() };
        let options = CaptureOptions { method, ..CaptureOptions::default() };
        match replay_capture(&self.capture, &options) {
            Ok(r) => {
                let s = r.score;
                out.translation_mean_mm = s.translation_mean_mm.into();
                out.translation_max_mm = s.translation_max_mm.into();
                out.rotation_mean_deg = s.rotation_mean_deg.into();
                out.rotation_max_deg = s.rotation_max_deg.into();
                out.simulated_lift_mm = s.simulated_lift_mm.into();
                out.captured_lift_mm = s.captured_lift_mm.into();
                out.on_target = s.on_target();
                out.simulated_height_mm = r.frames.iter().map(|f| f.simulated_height_mm).collect();
                out.translation_error_mm =
                    r.frames.iter().map(|f| f.translation_error_mm).collect();
            }
            Err(e) => out.error = Some(e.to_string()),
        }
        out
    }

    /// The report's section of `runs` of it: the captured object's height
    /// at every frame beside them.
    pub fn runs(&self, methods: Vec<CaptureMethodRun>) -> CaptureRuns {
        let c = &self.capture;
        let start = c.poses.first().map_or(0.0, |p| p.0.y);
        let options = CaptureOptions::default();
        CaptureRuns {
            capture: self.name.clone(),
            credit: self.credit.clone(),
            mass_kg: options.mass,
            material: options.material.name,
            time_s: (0..c.poses.len()).map(|i| c.time(i)).collect(),
            captured_height_mm: c.poses.iter().map(|p| (p.0.y - start) * 1e3).collect(),
            methods,
        }
    }

    /// Replayed with every method ([`Method::ALL`]), as the report shows it.
    pub fn run_every_method(&self) -> CaptureRuns {
        self.runs(Method::ALL.into_iter().map(|m| self.run(m)).collect())
    }
}
