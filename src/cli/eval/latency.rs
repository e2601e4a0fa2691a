//! `eval latency`: how far the hand that acts lags the tracked hand.

use super::num;
use super::options::{NoiseSourceArgs, comma_list, scale};
use crate::cli::Outcome;
use crate::cli::args::count;
use crate::cli::options::JsonOutput;
use coulomb_hands::eval::NoiseUnit;
use coulomb_hands::eval::latency::{LatencyOptions, LatencyStudy, latency};
use std::sync::LazyLock;

/// The default noise strengths, as `--noise-mm` takes them.
static NOISE_MM: LazyLock<String> = LazyLock::new(|| comma_list(&LatencyOptions::NOISE_MM));

/// How far the hand that acts lags the tracked hand under the tracking filter: on a step,
/// a 1 Hz sine and a minimum-jerk reach, of the whole hand and of its grip, clean and under
/// tracking noise.
#[derive(clap::Args)]
pub struct LatencyArgs {
    /// Tracking noise strengths by their rms per joint and axis, comma-separated (0: a
    /// clean tracker).
    #[arg(long, value_name = "MM,...", value_delimiter = ',', default_value = NOISE_MM.as_str(),
          value_parser = scale)]
    noise_mm: Vec<f32>,
    /// Tracking noise strengths, times the recordings', comma-separated (instead of
    /// --noise-mm).
    #[arg(long, value_name = "SCALE,...", value_delimiter = ',', value_parser = scale,
          conflicts_with = "noise_mm")]
    noise: Option<Vec<f32>>,
    #[command(flatten)]
    noise_source: NoiseSourceArgs,
    /// Noise streams averaged per strength.
    #[arg(long, default_value_t = LatencyOptions::STREAMS, value_parser = count())]
    streams: usize,
    #[command(flatten)]
    output: JsonOutput,
}

impl LatencyArgs {
    /// Runs the study and prints its table, or one JSON object.
    pub fn run(self) -> Outcome {
        let (noise, noise_unit) = match self.noise {
            Some(times) => (times, NoiseUnit::Times),
            None => (self.noise_mm, NoiseUnit::RmsMm),
        };
        let options = LatencyOptions {
            noise,
            noise_unit,
            noise_from: self.noise_source.noise_from,
            noise_white: self.noise_source.noise_white,
            streams: self.streams,
            ..LatencyOptions::default()
        };
        let study = latency(&options)?;
        Ok(self.output.print(&study, print_latency)?)
    }
}

fn print_latency(s: &LatencyStudy) {
    println!(
        "the hand that acts behind the tracked hand (the tracking filter), {} noise streams \
         averaged per strength",
        s.streams
    );
    println!("{:<10} {:>7} {:>11} {:>6}", "motion", "rms mm", "latency ms", "gain");
    for r in &s.rows {
        let gain = r.gain.map_or("—".into(), |g| num(g, 3));
        println!(
            "{:<10} {:>7.2} {:>11} {:>6}",
            r.motion,
            r.noise_rms_mm,
            num(r.latency_ms, 1),
            gain
        );
    }
    println!(
        "(step: until the acting hand covered half the step; reach: until it covered half a \
         minimum-jerk move of 150 ms after the tracked hand did; sine: the delay of its 1 Hz \
         component; hand: the palm's centre, 5 cm; grip: the index fingertip)"
    );
}
