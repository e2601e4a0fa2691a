//! `replay`: a recording, a session file, or a soak.

use super::options::{JsonOutput, MethodChoice, SessionArgs, TraceOutput};
use super::{Outcome, print_objects, progress_bar};
use coulomb_hands::input::recording::Format;
use coulomb_hands::run::replay::{ReplayOptions, ReplaySummary};
use coulomb_hands::{GammaMode, RunError};
use std::path::{Path, PathBuf};
use std::time::Duration;

/// Replay a Leap Motion recording (.json.lz or .json), a joint recording, a recorded
/// session, or a hand–object capture (the object then starts at its first captured pose and
/// is measured against the capture at every frame), headlessly.
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
    /// A capture's object mass in kg, or a comma-separated grid of them (the capture gives
    /// none).
    #[arg(long, value_delimiter = ',', value_name = "KG")]
    mass: Option<Vec<f32>>,
    /// A capture's skin–object material, or a comma-separated list (see `coulomb-hands
    /// materials`).
    #[arg(long, value_delimiter = ',', value_name = "NAME")]
    material: Option<Vec<String>>,
    /// What of a capture's object the hand touches: "exact", the mesh's own surface where
    /// the mesh is closed (else its convex parts), or "body", the convex parts the engine
    /// moves.
    #[arg(long, value_name = "SURFACE",
          value_parser = clap::value_parser!(coulomb_hands::HandSurface))]
    hand_surface: Option<coulomb_hands::HandSurface>,
}

impl ReplayArgs {
    /// One replay, a session's replay, or a soak.
    pub fn run(self) -> Outcome {
        use coulomb_hands::run::replay::{is_session_file, place_at_grasp, replay_recording};
        if !is_session_file(&self.file)
            && let Some(capture) = coulomb_hands::input::capture::load_if_capture(&self.file)
        {
            return self.run_capture(capture?);
        }
        if self.mass.is_some() || self.material.is_some() || self.hand_surface.is_some() {
            return Err("--mass, --material and --hand-surface are for a hand–object capture; \
                        give the object in a recording's replay with --object"
                .into());
        }
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

impl ReplayArgs {
    /// `replay` on a hand–object capture: one replay for every mass and
    /// material asked for, each measured against the capture.
    fn run_capture(self, capture: coulomb_hands::input::capture::Capture) -> Outcome {
        use coulomb_hands::run::capture::{CaptureGrid, replay_grid};
        if self.trace.trace.is_some() || self.soak.is_some() || self.session.record.is_some() {
            return Err("a capture replays once, without --trace, --loop or --record".into());
        }
        let mut grid = CaptureGrid::new(self.method.method, self.gamma, self.mass, self.material)?;
        grid.hand_surface = self.hand_surface.unwrap_or(grid.hand_surface);
        let report = replay_grid(&capture, &grid)?;
        self.output.print(&report, print_capture)?;
        Ok(())
    }
}

/// A capture's replays as text: the capture, then one block per replay.
fn print_capture(report: &coulomb_hands::run::capture::CaptureReport) {
    let c = &report.capture;
    let hand = match c.hand {
        "surface" => "fitted to 778 surface points",
        _ => "from 21 keypoints",
    };
    let w = c.finger_widths_mm.map(|w| format!("{w:.1}")).join(" ");
    println!("replayed capture {} ({} frames at {} Hz)", c.source, c.frames, c.frame_rate_hz);
    let side = |s: coulomb_hands::Side| format!("{s:?}").to_lowercase();
    println!(
        "hand: {}, {hand}: finger widths {w} mm (thumb first), palm skin {:.1} mm before its \
         bones",
        side(c.side),
        c.palm_depth_mm
    );
    if c.shape != c.side {
        println!(
            "  its fingers curl as a {} hand's do (the capture's frame is mirrored): built as one",
            side(c.shape)
        );
    }
    println!("the hand touches {}", c.touched);
    for r in &report.replays {
        let s = &r.score;
        let yes = |b: bool| if b { "yes" } else { "no" };
        println!("{} with a {:.2} kg object, {}:", r.method, r.mass_kg, r.material);
        println!(
            "  translation error: mean {:.1} mm, largest {:.1} mm (target 10, 30)",
            s.translation_mean_mm, s.translation_max_mm
        );
        println!(
            "  rotation error: mean {:.1}°, largest {:.1}° (target 5, 15)",
            s.rotation_mean_deg, s.rotation_max_deg
        );
        println!(
            "  lift: {:.0} mm, captured {:.0} mm (lifted: {})",
            s.simulated_lift_mm,
            s.captured_lift_mm,
            yes(s.lifted())
        );
        println!(
            "  set down {:.0} mm from the captured place, {:.1} mm above its start, captured {:.1} \
             mm (set down: {})",
            s.set_down.distance_mm,
            s.set_down.height_mm,
            s.set_down.captured_height_mm,
            yes(s.landed())
        );
        println!("  on target: {}; all values finite: {}", yes(s.on_target()), s.all_finite);
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
