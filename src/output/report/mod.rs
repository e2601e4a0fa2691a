//! The HTML report of `coulomb-hands report`: one self-contained page
//! (inline CSS and SVG plots, nothing loaded from anywhere) with the
//! placement-accuracy study (thesis Table 5.2), the step-time benchmark
//! (Fig. 5.6), the shipped scenarios, the bundled replays, the placement
//! study swept over tracking noise, the thesis's law given its departures
//! back one at a time, and a real hand–object capture replayed with each
//! method.
//!
//! [`html`] is a pure function from a [`ReportData`] to the page's text.
//! Every section is optional: a missing one says how to produce it. The
//! data types here are plain numbers and text, and they are what the runs
//! produce: `eval` builds the [`AccuracyStudy`], `run::bench` the
//! [`BenchReport`] (their JSON reads back with [`AccuracyStudy::load`] and
//! [`BenchReport::load`]) and the `run` stage the scenario, replay and
//! capture runs. Nothing in the data can make the page builder panic: non-finite numbers are
//! shown as `—`, they and any beyond 10¹² are left out of plots, and empty
//! lists give empty plots.

mod capture_page;
mod markup;
mod page;
mod plots;
pub(crate) use plots::quantile;
mod scenario_plot;
mod study;
mod study_page;
#[cfg(test)]
mod tests;

pub use capture_page::{capture_errors, capture_heights};
pub use page::html;
pub use study::{
    Ablation, AblationRow, Estimate, LatencyRow, LatencyStudy, NoiseSummary, SweepRow, SweepStudy,
};

use crate::file_error::FileError;
use serde::{Deserialize, Deserializer, Serialize};
use std::path::Path;

/// Everything a report shows; `None` sections say how to produce them.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ReportData {
    /// Version, date, machine and command line.
    pub header: Header,
    /// The placement-accuracy study (`eval accuracy --json`).
    pub accuracy: Option<Sourced<AccuracyStudy>>,
    /// The placement study swept over tracking noise (`eval sweep --json`).
    pub sweep: Option<Sourced<SweepStudy>>,
    /// The thesis's law given its departures back (`eval ablation --json`).
    pub ablation: Option<Sourced<Ablation>>,
    /// The step-time benchmark (`bench --json`).
    pub bench: Option<Sourced<BenchReport>>,
    /// The scenarios that ran.
    pub scenarios: Option<Sourced<Vec<ScenarioRun>>>,
    /// The recordings replayed.
    pub replays: Option<Sourced<Vec<ReplayRun>>>,
    /// The bundled hand–object capture replayed with each method.
    pub captures: Option<Sourced<CaptureRuns>>,
}

/// A section's data and, in a sentence, where it came from.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Sourced<T> {
    /// Where the data came from: a file and the command that writes it,
    /// or the run that made it.
    pub source: String,
    /// The data.
    pub data: T,
}

/// What made the report, shown at its top.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Header {
    /// The crate's version.
    pub version: String,
    /// When the report was made, e.g. `2025-01-31 14:05 UTC`.
    pub date: String,
    /// The machine: cores, OS, architecture.
    pub machine: String,
    /// The build: release or debug, features.
    pub build: String,
    /// The command line that made the report.
    pub command: String,
}

/// `coulomb-hands eval accuracy --json`: the placement-accuracy study.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AccuracyStudy {
    /// Synthetic users.
    pub users: usize,
    /// Trials per user and method.
    pub trials: usize,
    /// The study's random seed.
    pub seed: u64,
    /// Tracking noise, times the bundled recordings' (absent from files
    /// written before the study had it: jitter of 0.2–1.2 mm then).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub noise: Option<f32>,
    /// That noise's rms per joint and axis (mm; absent from files written
    /// before the study had it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub noise_rms_mm: Option<f64>,
    /// Where that noise came from: the recordings whose residuals it
    /// replays, or the white jitter drawn (absent from files written
    /// before the study recorded it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub noise_source: Option<NoiseSummary>,
    /// The users' glance errors, times the display's (absent: exact).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub perception: Option<f32>,
    /// One result per method (and strategy).
    pub methods: Vec<MethodResult>,
    /// The thesis's Table 5.2, as the study compares with it.
    pub thesis: Vec<ThesisResult>,
}

/// One method's placement results.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MethodResult {
    /// `coulomb`, `thesis`, `kinematic` or `heuristic`.
    pub method: String,
    /// How the users moved the cube: `lift` or `slide` (absent for a
    /// person's row, and from files written before the study had both).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub strategy: Option<String>,
    /// Placement error of each completed trial (mm).
    pub errors_mm: Vec<f64>,
    /// Mean placement error (mm); `null` reads as not a number.
    #[serde(deserialize_with = "null_as_nan")]
    pub mean_mm: f64,
    /// Standard deviation of the placement error (mm).
    #[serde(deserialize_with = "null_as_nan")]
    pub sd_mm: f64,
    /// Median placement error (mm).
    #[serde(deserialize_with = "null_as_nan")]
    pub median_mm: f64,
    /// Mean time per trial (s).
    #[serde(deserialize_with = "null_as_nan")]
    pub mean_time_s: f64,
    /// Time of each completed trial (s), in the order of `errors_mm`
    /// (absent from files written before it was kept).
    #[serde(default)]
    pub times_s: Vec<f64>,
    /// Trials not completed.
    pub failed: usize,
    /// Accidental drops.
    pub drops: usize,
    /// Where the cube sat across the grip as the hands began to open on
    /// it, on average (mm, from the grip's centre towards the fingers).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub held_across_mm: Option<f64>,
}

/// One row of the thesis's Table 5.2.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ThesisResult {
    /// The method of this crate it compares with.
    pub method: String,
    /// Mean placement error (mm).
    pub mean_mm: f64,
    /// Standard deviation (mm).
    pub sd_mm: f64,
    /// Median (mm).
    pub median_mm: f64,
}

/// The thesis's Table 5.2 (placement error, mm): this crate's method it
/// compares with, the thesis's name for the method, mean, sd and median.
pub const THESIS_TABLE_5_2: [(&str, &str, f64, f64, f64); 3] = [
    ("coulomb", "Our approach", 9.2, 5.5, 8.2),
    ("heuristic", "Leap Motion Interaction Engine", 11.1, 6.9, 9.6),
    ("kinematic", "re-implementation of [23] (kinematic)", 14.3, 8.5, 12.2),
];

/// The thesis's name for the method that `method` is compared with.
pub fn thesis_name(method: &str) -> Option<&'static str> {
    THESIS_TABLE_5_2.iter().find(|r| r.0 == method).map(|r| r.1)
}

/// The thesis's Fig. 5.6: total physics time per step (µs) at bones in
/// contact.
pub const THESIS_FIG_5_6: [(usize, f64); 2] = [(6, 600.0), (32, 1500.0)];

/// `coulomb-hands bench --json`: everything one bench run measured
/// (`run::bench` writes it).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BenchReport {
    /// Step time against bones in contact.
    pub sweep: Vec<SweepPoint>,
    /// The reference scene, asleep and awake.
    pub reference: ReferenceScene,
    /// MuJoCo's step on the same scene, when it was measured.
    pub mujoco: Option<MujocoStep>,
    /// Step time against objects in the scene (`bench --objects`), the
    /// same 32 bones pressing; absent from older files.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub objects: Vec<ObjectsPoint>,
}

/// Step time in a cluttered scene of a number of objects
/// (`run::bench::cluttered_scene`), rapier's sleeping on.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ObjectsPoint {
    /// Objects in the world.
    pub objects: usize,
    /// Bones pressing on a box after the run.
    pub bones_pressing: usize,
    /// Objects awake after the run (the held ones, and what still moves).
    pub awake: usize,
    /// The step times, as fields of the point itself in the JSON.
    #[serde(flatten)]
    pub times: StepTimes,
}

/// Step time at one number of bones in contact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SweepPoint {
    /// Bones pressing on a box (checked after the warm-up).
    pub bones: usize,
    /// Hands they belong to.
    pub hands: usize,
    /// Skin-patch samples per contact.
    pub samples_per_contact: usize,
    /// The step times, as fields of the point itself in the JSON.
    #[serde(flatten)]
    pub times: StepTimes,
}

/// µs per step, the interaction layer timed apart from rapier's step.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct StepTimes {
    /// Contacts and forces (`InteractionWorld::apply_hand_forces`).
    pub interaction_us: f64,
    /// rapier's step (`InteractionWorld::step_physics`).
    pub rapier_us: f64,
    /// The whole step: both (the median block's sum).
    pub full_us: f64,
}

/// The reference scene: ground, tower and held boxes.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ReferenceScene {
    /// Bones pressing on a box at the end of the asleep run.
    pub bones_pressing: usize,
    /// Objects in the world (tower blocks and boxes).
    pub objects: usize,
    /// With rapier's sleeping: the tower asleep, the held boxes awake.
    pub asleep: StepTimes,
    /// With sleeping off: every object awake.
    pub awake: StepTimes,
    /// The mean full step over the first simulated second (sleeping on),
    /// while the tower settles and falls asleep (µs).
    pub settling_us: f64,
}

/// MuJoCo's step on the reference scene, beside ours: each block of our
/// steps was followed by a block as long of MuJoCo's, so that both saw the
/// machine alike.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MujocoStep {
    /// µs per `mj_step`: the median over its blocks.
    pub step_us: f64,
    /// MuJoCo's settings (`run::bench::mujoco::SETTINGS`).
    pub settings: String,
    /// Our awake full step over MuJoCo's step: the median over pairs of
    /// blocks of ours over the MuJoCo block after it.
    pub ratio_awake: f64,
    /// The same, asleep.
    pub ratio_asleep: f64,
}

/// One scenario's run: its verdict and what its objects did.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ScenarioRun {
    /// Its name.
    pub name: String,
    /// What it shows.
    pub description: String,
    /// Whether every check passed (false if the run failed).
    pub passed: bool,
    /// Wall-clock time of the run (s).
    pub wall_s: f64,
    /// Each check's verdict.
    pub checks: Vec<Verdict>,
    /// Why the run stopped, if it did not finish.
    pub error: Option<String>,
    /// The physics step (s): sample `i` is at `(i + 1) · dt`.
    pub dt: f64,
    /// Each object's series, in scene order.
    pub objects: Vec<ObjectSeries>,
}

/// A check of an outcome: what, how much, against what.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Verdict {
    /// The check's name (with its unit).
    pub name: String,
    /// The measured value.
    pub value: f64,
    /// The bound, e.g. `>= 0.05`.
    pub bound: String,
    /// Whether the value is within the bound.
    pub passed: bool,
}

/// One object over a run, one sample per step.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ObjectSeries {
    /// Its name in the scene.
    pub name: String,
    /// The magnitude of the total hand force on it (N, Eq. 3.10).
    pub hand_force_n: Vec<f32>,
    /// Its centre's height (m).
    pub height_m: Vec<f32>,
}

/// One recording replayed with an object at every closing of its hands.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ReplayRun {
    /// The recording's file.
    pub recording: String,
    /// Its format version.
    pub format: String,
    /// Frames in the recording.
    pub frames: usize,
    /// Tracked hands.
    pub hands: usize,
    /// Length (s).
    pub duration_s: f64,
    /// Physics steps run.
    pub steps: usize,
    /// The objects put at the closings, or why there are none.
    pub placed: String,
    /// Contacts begun.
    pub contacts_begun: usize,
    /// What each object did.
    pub objects: Vec<ReplayObject>,
    /// Whether every traced number stayed finite.
    pub all_finite: bool,
    /// Tracking glitches playback left out.
    pub glitches: usize,
    /// Why the replay stopped, if it did not finish.
    pub error: Option<String>,
    /// Verdicts per judged closing of the hand (two each: held, released).
    pub verdicts: Vec<Verdict>,
    /// The closings not judged, one line each with why (too short, never
    /// pressed its object, opened before the grip settled).
    pub not_judged: Vec<String>,
}

/// What an object did in a replay.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ReplayObject {
    /// Its name.
    pub name: String,
    /// Start-to-end displacement (m).
    pub displacement_m: f64,
    /// Top speed (m/s).
    pub max_speed_m_s: f64,
}

/// A hand–object capture replayed with each method: a real hand moving a
/// real object, and how far each method's object followed it.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct CaptureRuns {
    /// The capture's file.
    pub capture: String,
    /// Whose data it is and under which licence, shown with its figures.
    pub credit: String,
    /// The object's mass in every replay (kg; the capture gives none).
    pub mass_kg: f32,
    /// The skin–object material in every replay.
    pub material: String,
    /// Each captured frame's time (s).
    pub time_s: Vec<f64>,
    /// The captured object's height above its first pose at each frame (mm).
    pub captured_height_mm: Vec<f32>,
    /// One replay per method.
    pub methods: Vec<CaptureMethodRun>,
}

/// The capture replayed with one method.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct CaptureMethodRun {
    /// `coulomb`, `thesis`, `kinematic` or `heuristic`.
    pub method: String,
    /// Why the replay stopped, if it did not finish.
    pub error: Option<String>,
    /// Mean translation error over the frames after the first (mm).
    pub translation_mean_mm: f64,
    /// Largest translation error (mm).
    pub translation_max_mm: f64,
    /// Mean rotation error over the frames after the first (°).
    pub rotation_mean_deg: f64,
    /// Largest rotation error (°).
    pub rotation_max_deg: f64,
    /// The simulated object's highest rise above its first pose (mm).
    pub simulated_lift_mm: f64,
    /// The captured object's highest rise above its first pose (mm).
    pub captured_lift_mm: f64,
    /// Whether the replay met the targets (`CaptureScore::on_target`):
    /// lifted at least half as high as the captured object, set down within
    /// 1 cm of its height, translation error at most 10 mm on average and
    /// 30 mm at worst, rotation error at most 5° and 15°.
    pub on_target: bool,
    /// The simulated object's height above its first pose at each captured
    /// frame (mm), in the order of [`CaptureRuns::time_s`].
    pub simulated_height_mm: Vec<f32>,
    /// Its distance from the captured object at each captured frame (mm).
    pub translation_error_mm: Vec<f32>,
}

impl MethodResult {
    /// The row's name: its method, and its strategy if it has one.
    pub fn label(&self) -> String {
        match &self.strategy {
            Some(s) => format!("{} {s}", self.method),
            None => self.method.clone(),
        }
    }
}

impl AccuracyStudy {
    /// Reads `eval accuracy --json` output; errors name the file, the line
    /// and what is wrong.
    pub fn load(path: &Path) -> Result<AccuracyStudy, FileError> {
        load_json(path)
    }
}

impl BenchReport {
    /// Reads `bench --json` output; errors name the file, the line and
    /// what is wrong.
    pub fn load(path: &Path) -> Result<BenchReport, FileError> {
        load_json(path)
    }
}

fn load_json<T: serde::de::DeserializeOwned>(path: &Path) -> Result<T, FileError> {
    FileError::json(&path.display().to_string(), &FileError::read(path)?)
}

/// A number, or `null` (how serde_json writes a NaN) as NaN.
pub(crate) fn null_as_nan<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::NAN))
}

/// `secs` since the Unix epoch as `YYYY-MM-DD HH:MM UTC`.
pub fn utc_date(secs: u64) -> String {
    let (days, rest) = (secs / 86_400, secs % 86_400);
    // Howard Hinnant's civil_from_days, for days since 1970-01-01.
    let z = days as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    let (hour, minute) = (rest / 3600, rest % 3600 / 60);
    format!("{year:04}-{month:02}-{day:02} {hour:02}:{minute:02} UTC")
}
