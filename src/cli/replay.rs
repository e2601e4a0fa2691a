//! `replay`: a recording, a session file, or a soak.

use super::options::{JsonOutput, MethodChoice, SessionArgs, TraceOutput};
use super::{Outcome, print_objects, progress_bar};
use coulomb_hands::input::recording::Format;
use coulomb_hands::run::replay::{ReplayOptions, ReplaySummary};
use coulomb_hands::{GammaMode, RunError};
use std::path::{Path, PathBuf};
use std::time::Duration;

/// Replay a Leap Motion recording (.json.lz or .json), or a recorded session, headlessly.
#[derive(clap::Args)]
pub struct ReplayArgs {
    /// The recording.
    file: PathBuf,
    #[command(flatten)]
    trace: TraceOutput,
    #[command(flatten)]
    output: JsonOutput,
    #[command(flatten)]
    session: SessionArgs,
    /// Contact stiffness: "auto" (Eq. 3.11, per object) or a fixed γ in N/m.
    #[arg(long, default_value_t = GammaMode::default(),
          value_parser = clap::value_parser!(GammaMode))]
    gamma: GammaMode,
    #[command(flatten)]
    method: MethodChoice,
    /// Soak: replay over and over in one world for this wall-clock time (90s, 10m,
    /// 1h30m), putting the objects back and re-locking their fixtures before each
    /// loop; report memory, steps per second and the peak object speed.
    #[arg(long = "loop", value_name = "DURATION", conflicts_with = "record",
          value_parser = coulomb_hands::run::soak::parse_duration)]
    soak: Option<Duration>,
}

impl ReplayArgs {
    /// One replay, a session's replay, or a soak.
    pub fn run(self) -> Outcome {
        use coulomb_hands::run::replay::{is_session_file, place_at_grasp, replay_recording};
        let options = ReplayOptions {
            device: self.session.device,
            grace: self.session.grace,
            scene: self.session.load_scene()?,
            gamma: self.gamma,
            method: self.method.method,
            object_at_grasp: self.session.grasp_object(),
            record: self.session.record.is_some(),
        };
        if is_session_file(&self.file) {
            if self.soak.is_some() {
                return Err("--loop replays Leap recordings; a session file replays once".into());
            }
            return Ok(replay_session(&self.file, &self.output)?);
        }
        let recording = coulomb_hands::input::recording::load(&self.file)?;
        let mut writer = self.trace.writer()?;
        let mut observers: Vec<&mut dyn coulomb_hands::run::drive::Observer> = Vec::new();
        observers.extend(writer.as_mut().map(|w| w as _));
        if let Some(duration) = self.soak {
            let playback = recording.playback(options.device, options.grace)?;
            let mut world = options.world()?;
            // A soak puts its objects back before each loop, so they must
            // exist from the start: one object, at the first closing.
            let mut fixtures = Vec::new();
            if let Some(object) = options.object_at_grasp {
                fixtures.push(place_at_grasp(&mut world, &playback, object, 0)?.0);
            }
            let source = &recording.source_name;
            let report =
                soak_loop(source, &playback, &mut world, &fixtures, duration, &mut observers)?;
            if let Some(w) = writer {
                w.finish()?;
            }
            self.output.print(&report, |r| print!("{r}"))?;
            if report.memory.grew {
                return Err("memory grew by more than 5 % after the first loop".into());
            }
            return Ok(());
        }
        let (summary, mut world) = replay_recording(&recording, &options, &mut observers)?;
        drop(observers);
        if let Some(w) = writer {
            w.finish()?;
        }
        self.session.save(&mut world)?;
        let closings = options.object_at_grasp.is_some();
        let format = &recording.format;
        self.output.print(&summary, |s| print_summary(s, format, closings))?;
        Ok(())
    }
}

/// What a replay did: its recording, glitches left out, closings (if an
/// object was put at them), contacts and objects.
fn print_summary(summary: &ReplaySummary, format: &Format, closings: bool) {
    println!("replayed {} (format {format})", summary.source);
    println!(
        "frames: {}, hands: {}, duration: {:.2} s, physics steps: {}",
        summary.frames, summary.hands, summary.duration, summary.steps
    );
    let n = summary.skipped.len();
    if n > 0 {
        let more = if n > 10 { " (the first 10; all in --json)" } else { "" };
        println!("left out {n} tracking glitches{more}:");
        for line in summary.skipped.iter().take(10) {
            println!("  {line}");
        }
    }
    if closings {
        print_closings(&summary.closings);
    }
    println!("contacts begun: {}", summary.contacts_begun);
    print_objects(&summary.objects);
    println!("all values finite: {}", summary.all_finite);
}

/// One line per closing, and how many held and were let go.
fn print_closings(closings: &[coulomb_hands::run::closing::ClosingVerdict]) {
    use coulomb_hands::run::closing::Hold;
    if closings.is_empty() {
        println!(
            "closings: 0 (no hand closes by its grab or pinch strength, its curl or its aperture)"
        );
        return;
    }
    let held = closings.iter().filter(|c| c.held()).count();
    let released = closings.iter().filter(|c| c.released == Some(true)).count();
    let not = match closings.iter().filter(|c| c.hold != Hold::Judged).count() {
        0 => String::new(),
        n => format!(", {n} not judged"),
    };
    println!("closings: {} ({held} held, {released} released after opening{not})", closings.len());
    for c in closings {
        println!("  {c}");
    }
}

/// `replay --loop`: the soak, with a progress bar on a terminal.
fn soak_loop(
    source: &str,
    playback: &coulomb_hands::input::playback::Playback,
    world: &mut coulomb_hands::InteractionWorld,
    fixtures: &[coulomb_hands::run::replay::Fixture],
    duration: std::time::Duration,
    observers: &mut [&mut dyn coulomb_hands::run::drive::Observer],
) -> Result<coulomb_hands::run::soak::SoakReport, RunError> {
    use coulomb_hands::run::soak::{SoakLength, SoakProgress, soak};
    use std::io::IsTerminal;
    let show = std::io::stderr().is_terminal();
    let bar = progress_bar(show, duration.as_secs().max(1), "{bar:30} {elapsed}/{len}s {msg}");
    let mut progress = |p: &SoakProgress| {
        bar.set_position(p.elapsed.as_secs());
        let rate = p.steps as f64 / p.elapsed.as_secs_f64().max(1e-9);
        bar.set_message(format!("{} loops, {} steps, {rate:.0} steps/s", p.loops, p.steps));
    };
    let length = SoakLength::Wall(duration);
    let report = soak(source, playback, world, fixtures, length, observers, &mut progress);
    bar.finish_and_clear();
    report
}

/// Replays a recorded session file and prints what its objects did.
fn replay_session(file: &Path, output: &JsonOutput) -> Result<(), RunError> {
    let summary = coulomb_hands::run::replay::replay_session_file(file)?;
    output.print(&summary, |s| {
        println!("replayed session {} ({} steps, {:.2} s)", file.display(), s.steps, s.time);
        print_objects(&s.objects);
    })?;
    Ok(())
}
