//! The data of the studies that go beyond Table 5.2: the placement study
//! swept over tracking noise (`eval sweep --json`) and the thesis's law
//! given its departures back one at a time (`eval ablation --json`), with
//! their confidence intervals. `eval` builds them; the report shows them.

use super::{load_json, null_as_nan};
use crate::file_error::FileError;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// A mean with its 95 % confidence interval (Student's t, trials taken as
/// independent), or a proportion with its Wilson interval.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Estimate {
    /// The mean, or the proportion.
    #[serde(deserialize_with = "null_as_nan")]
    pub value: f64,
    /// The interval's lower end.
    #[serde(deserialize_with = "null_as_nan")]
    pub low: f64,
    /// The interval's upper end.
    #[serde(deserialize_with = "null_as_nan")]
    pub high: f64,
}

impl Estimate {
    /// Not a number: the estimate of nothing.
    pub const NONE: Estimate = Estimate { value: f64::NAN, low: f64::NAN, high: f64::NAN };
}

/// Where the noise came from and how strong it is at scale 1.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NoiseSummary {
    /// The recordings, or the white noise drawn.
    pub sources: Vec<String>,
    /// The residuals' rms per joint and axis (mm).
    pub rms_mm: f64,
    /// Dropouts per second of tracked hand.
    pub dropouts_per_s: f64,
    /// Their mean length (ms; 0 without dropouts).
    pub dropout_ms: f64,
}

impl NoiseSummary {
    /// Its dropouts in words: "0.70 dropouts a second, 18 ms each", or "no
    /// dropouts".
    pub fn dropouts(&self) -> String {
        if self.dropouts_per_s > 0.0 {
            format!("{:.2} dropouts a second, {:.0} ms each", self.dropouts_per_s, self.dropout_ms)
        } else {
            "no dropouts".into()
        }
    }

    /// What the noise is, in words: "white jitter at 100 Hz", or "the
    /// residuals of grab.json.lz, pinch.json.lz" (file names only).
    pub fn kind(&self) -> String {
        match self.sources.as_slice() {
            [] => "no recorded noise".into(),
            [white] if white.starts_with("white") => white.clone(),
            files => {
                let name = |f: &String| {
                    Path::new(f).file_name().map_or(f.clone(), |n| n.to_string_lossy().into())
                };
                let names: Vec<String> = files.iter().map(name).collect();
                format!("the residuals of {}", names.join(", "))
            }
        }
    }

    /// The residuals' rms per joint and axis at `scale` times their own
    /// (mm): what a row of that strength shook the hand by.
    pub fn rms_mm_at(&self, scale: f32) -> f64 {
        f64::from(scale) * self.rms_mm
    }
}

/// One method, strategy and noise strength, over every seed's trials.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepRow {
    /// The method.
    pub method: String,
    /// `lift` or `slide`.
    pub strategy: String,
    /// The noise strength, times the recordings'.
    pub noise: f32,
    /// Trials run (over every seed).
    pub trials: usize,
    /// Placement error of the completed trials (mm).
    pub error_mm: Estimate,
    /// Its median (mm).
    #[serde(deserialize_with = "null_as_nan")]
    pub median_mm: f64,
    /// Time of the completed trials (s).
    pub time_s: Estimate,
    /// The share of trials not completed.
    pub failed: Estimate,
    /// Drops per trial.
    pub drops: Estimate,
    /// Where the cube sat across the grip as the hand began to open on
    /// it (mm, from the grip's centre towards the fingers), on average.
    pub held_across_mm: Option<f64>,
}

/// `coulomb-hands eval sweep --json`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepStudy {
    /// Users per seed.
    pub users: usize,
    /// Trials per user.
    pub trials: usize,
    /// The seeds.
    pub seeds: Vec<u64>,
    /// The glances' errors, times the display's.
    pub perception: f32,
    /// The noise at scale 1.
    pub noise: NoiseSummary,
    /// One row per method, strategy and noise strength.
    pub rows: Vec<SweepRow>,
}

/// One configuration's outcome with one strategy.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AblationRow {
    /// `thesis as written`, `+ <departure>`, or `coulomb (all of them)`.
    pub config: String,
    /// `lift` or `slide`.
    pub strategy: String,
    /// Trials run.
    pub trials: usize,
    /// Trials completed.
    pub completed: usize,
    /// The share of trials not completed.
    pub failed: Estimate,
    /// Drops per trial.
    pub drops: Estimate,
    /// Placement error of the completed trials (mm).
    pub error_mm: Estimate,
}

/// `coulomb-hands eval ablation --json`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Ablation {
    /// Synthetic users.
    pub users: usize,
    /// Trials per user.
    pub trials: usize,
    /// The seed.
    pub seed: u64,
    /// One row per configuration and strategy.
    pub rows: Vec<AblationRow>,
}

impl SweepStudy {
    /// Reads `eval sweep --json` output; errors name the file, the line and
    /// what is wrong.
    pub fn load(path: &Path) -> Result<SweepStudy, FileError> {
        load_json(path)
    }
}

impl Ablation {
    /// Reads `eval ablation --json` output; errors name the file, the line
    /// and what is wrong.
    pub fn load(path: &Path) -> Result<Ablation, FileError> {
        load_json(path)
    }
}

/// `eval latency --json`: how far the hand that acts lags the tracked hand.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LatencyStudy {
    /// Noise streams averaged per noise strength.
    pub streams: usize,
    /// One row per noise strength and motion.
    pub rows: Vec<LatencyRow>,
}

/// One motion at one noise strength.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LatencyRow {
    /// `hand step`, `hand sine`, `hand reach`, `grip step`, `grip sine` or `grip reach`.
    pub motion: String,
    /// The noise strength, times the recordings'.
    pub noise: f32,
    /// Its rms per joint and axis (mm).
    pub noise_rms_mm: f64,
    /// On a step, the time until the acting hand covered half of it; on a
    /// sine, the delay of its 1 Hz component (ms).
    #[serde(deserialize_with = "null_as_nan")]
    pub latency_ms: f64,
    /// On a sine, the acting hand's amplitude over the tracked hand's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gain: Option<f64>,
}
