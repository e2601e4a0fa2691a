//! `replay`: a recording, a session file, or a soak.

use super::{create, progress_bar};
use coulomb_hands::{InteractionConfig, RunError};

pub struct ReplayArgs<'a> {
    pub file: &'a std::path::Path,
    pub trace: Option<&'a std::path::Path>,
    pub json: bool,
    pub device: glam::Vec3,
    pub grace: f64,
    pub gamma: coulomb_hands::GammaMode,
    pub method: coulomb_hands::Method,
    pub object: Option<coulomb_hands::run::replay::GraspObject>,
    pub record: Option<&'a std::path::Path>,
    pub scene: Option<&'a std::path::Path>,
    pub soak: Option<std::time::Duration>,
}

/// `replay`: one replay, a session's replay, or a soak.
pub fn replay(args: ReplayArgs) -> Result<(), Box<dyn std::error::Error>> {
    use coulomb_hands::output::Session;
    use coulomb_hands::run::observe::TraceWriter;
    use coulomb_hands::run::replay::{place_at_grasp, replay, replay_closings, replay_world};
    let ReplayArgs { file, trace, json, device, grace, gamma, method, .. } = args;
    let ReplayArgs { object, record, scene, soak, .. } = args;
    let scene = scene.map(coulomb_hands::scene::Scene::load).transpose()?;
    if std::fs::read_to_string(file).is_ok_and(|t| Session::sniff(&t)) {
        if soak.is_some() {
            return Err("--loop replays Leap recordings; a session file replays once".into());
        }
        return Ok(replay_session(file, json)?);
    }
    let recording = coulomb_hands::input::recording::load(file)?;
    let playback = recording.playback(device, grace)?;
    let mut config = method.config(InteractionConfig { gamma, ..InteractionConfig::default() });
    if let Some(scene) = &scene {
        config = config.with_scene(scene);
    }
    let mut world = replay_world(config, record.is_some())?;
    if let Some(scene) = &scene {
        world.add_scene(scene)?;
    }
    let mut writer = trace.map(create).transpose()?.map(TraceWriter::new);
    let mut observers: Vec<&mut dyn coulomb_hands::run::drive::Observer> = Vec::new();
    observers.extend(writer.as_mut().map(|w| w as _));
    let source = &recording.source_name;
    if let Some(duration) = soak {
        // A soak puts its objects back before each loop, so they must
        // exist from the start: one object, at the first closing.
        let mut fixtures = Vec::new();
        if let Some(object) = object {
            fixtures.push(place_at_grasp(&mut world, &playback, object, 0)?.0);
        }
        let report = soak_loop(source, &playback, &mut world, &fixtures, duration, &mut observers)?;
        if let Some(w) = writer {
            w.finish()?;
        }
        print_soak(&report, json)?;
        if report.memory.grew {
            return Err("memory grew by more than 5 % after the first loop".into());
        }
        return Ok(());
    }
    let summary = match object {
        Some(object) => replay_closings(source, &playback, &mut world, object, &mut observers)?,
        None => replay(source, &playback, &mut world, &[], &mut observers)?,
    };
    drop(observers);
    if let Some(w) = writer {
        w.finish()?;
    }
    if let (Some(path), Some(session)) = (record, Session::take(&mut world)) {
        session.save(path)?;
    }
    if json {
        println!("{}", serde_json::to_string_pretty(&summary).map_err(std::io::Error::other)?);
        return Ok(());
    }
    println!("replayed {} (format {})", summary.source, recording.format);
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
    if object.is_some() {
        print_closings(&summary.closings);
    }
    println!("contacts begun: {}", summary.contacts_begun);
    for o in &summary.objects {
        println!(
            "object {}: moved {:.3} m, max speed {:.3} m/s",
            o.name, o.displacement, o.max_speed
        );
    }
    println!("all values finite: {}", summary.all_finite);
    Ok(())
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
pub fn soak_loop(
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

/// Prints a soak's report.
pub fn print_soak(r: &coulomb_hands::run::soak::SoakReport, json: bool) -> Result<(), RunError> {
    if json {
        println!("{}", serde_json::to_string_pretty(r).map_err(std::io::Error::other)?);
    } else {
        print!("{r}");
    }
    Ok(())
}

/// Replays a recorded session file and prints what its objects did.
fn replay_session(file: &std::path::Path, json: bool) -> Result<(), RunError> {
    use coulomb_hands::output::Session;
    use coulomb_hands::run::observe::Summary;
    let session = Session::load(file)?;
    // Objects are followed from the end of the first step, when all exist.
    let mut summary: Option<Result<Summary, coulomb_hands::WorldError>> = None;
    let replayed = session.replay(|w| {
        let s = summary.get_or_insert_with(|| Summary::new(w));
        if let Ok(s) = s
            && let Err(e) = s.observe_world(w)
        {
            summary = Some(Err(e));
        }
    });
    let world = replayed.map_err(|e| e.in_file(file))?;
    let objects = match summary.transpose()? {
        Some(s) => s.objects(&world)?,
        None => Vec::new(),
    };
    if json {
        let summary = serde_json::json!({
            "session": file.display().to_string(),
            "steps": session.steps(),
            "objects": objects
        });
        println!("{}", serde_json::to_string_pretty(&summary).map_err(std::io::Error::other)?);
        return Ok(());
    }
    println!(
        "replayed session {} ({} steps, {:.2} s)",
        file.display(),
        session.steps(),
        world.time()
    );
    for o in &objects {
        println!(
            "object {}: moved {:.3} m, max speed {:.3} m/s",
            o.name, o.displacement, o.max_speed
        );
    }
    Ok(())
}
