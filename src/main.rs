//! `coulomb-hands`: the headless command line.

use clap::{Parser, Subcommand};
use coulomb_hands::output::trace::TraceFile;
use coulomb_hands::run::bench::{held_boxes_scene, time_steps};
use coulomb_hands::run::demo::GraspLiftCarry;
use coulomb_hands::{InteractionConfig, KineticFriction, RunError};
use std::process::ExitCode;
use std::time::Instant;

#[derive(Parser)]
#[command(
    version,
    about = "Hands that move virtual objects only through Coulomb friction contact forces"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Scripted grasp, lift, carry and release of a cube (the default).
    Demo {
        /// Print one JSON object instead of the table.
        #[arg(long)]
        json: bool,
        /// Use Eq. 3.8 as written instead of Coulomb's kinetic friction.
        #[arg(long)]
        thesis_kinetic: bool,
        /// Seconds between printed rows.
        #[arg(long, default_value_t = 0.25, value_parser = positive)]
        every: f64,
    },
    /// Replay a Leap Motion recording (.json.lz or .json), or a recorded session, headlessly.
    Replay {
        /// The recording.
        file: std::path::PathBuf,
        /// Write one JSON line per physics step to this file.
        #[arg(long)]
        trace: Option<std::path::PathBuf>,
        /// Print one JSON object instead of the summary.
        #[arg(long)]
        json: bool,
        /// Where the desktop device sits in the world, "x,y,z" in metres.
        #[arg(long, default_value = "0,0,0", value_parser = parse_vec3)]
        device: glam::Vec3,
        /// Add the static scenery and objects of this scene file (JSON; see the
        /// `scene` module docs).
        #[arg(long)]
        scene: Option<std::path::PathBuf>,
        /// Record the whole session (scene, poses, steps) to this file; replaying
        /// that file reproduces the run bit for bit.
        #[arg(long)]
        record: Option<std::path::PathBuf>,
        /// Put an object where the hand grasps: SHAPE:SIZE_M:MASS_KG, SHAPE box or sphere.
        #[arg(long, value_name = "SHAPE:SIZE_M:MASS_KG")]
        object_at_grasp: Option<coulomb_hands::run::replay::GraspObject>,
        /// Contact stiffness: "auto" (Eq. 3.11, per object) or a fixed γ in N/m.
        #[arg(long, default_value = "400", value_parser = parse_gamma)]
        gamma: coulomb_hands::GammaMode,
        /// Tracking gaps up to this long (s) are bridged; longer ones release the hand.
        #[arg(long, default_value_t = coulomb_hands::input::playback::DEFAULT_GRACE,
              value_parser = at_least_zero)]
        grace: f64,
        /// Soak: replay over and over in one world for this wall-clock time (90s, 10m,
        /// 1h30m), putting the objects back and re-locking their fixtures before each
        /// loop; report memory, steps per second and the peak object speed.
        #[arg(long = "loop", value_name = "DURATION", conflicts_with = "record",
              value_parser = coulomb_hands::run::soak::parse_duration)]
        soak: Option<std::time::Duration>,
    },
    /// Run the physics on a live Leap Motion service's WebSocket stream.
    Live {
        /// The service's WebSocket URL.
        #[arg(long, default_value = coulomb_hands::input::live::DEFAULT_URL)]
        url: String,
        /// Stop after this many seconds of tracking time.
        #[arg(long, default_value_t = 10.0, value_parser = positive)]
        seconds: f64,
        /// Where the desktop device sits in the world, "x,y,z" in metres.
        #[arg(long, default_value = "0,0,0", value_parser = parse_vec3)]
        device: glam::Vec3,
    },
    /// Run a scenario of the interaction catalogue and print its checks.
    Scenario {
        /// A shipped scenario's name (e.g. push) or a scenario file.
        #[arg(required_unless_present = "all", conflicts_with = "all")]
        scenario: Option<String>,
        /// Run every shipped scenario and print a pass/fail table.
        #[arg(long)]
        all: bool,
        /// Write one JSON line per physics step to this file (as `replay --trace`).
        #[arg(long, conflicts_with = "all")]
        trace: Option<std::path::PathBuf>,
        /// Print one JSON object: {"scenarios": [{"name", "passed", "checks": [..]}]}.
        #[arg(long)]
        json: bool,
    },
    /// Write the project's generated meshes (U bracket, chess pawn) as OBJ files.
    Mesh {
        /// The directory to write them to.
        #[arg(long, default_value = "assets/meshes")]
        out: std::path::PathBuf,
    },
    /// Time steps of the benchmark scene (2 hands, 16 held boxes, 54-block tower).
    Bench {
        /// Steps to time after warm-up.
        #[arg(long, default_value_t = 2000)]
        steps: usize,
        /// Held boxes (2 bones in contact each), 1..=16.
        #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u16).range(1..=16))]
        boxes: u16,
        /// Leave the tower out.
        #[arg(long)]
        no_tower: bool,
    },
}

fn demo(json: bool, thesis_kinetic: bool, every: f32) -> Result<(), String> {
    let config = InteractionConfig {
        kinetic: if thesis_kinetic { KineticFriction::Thesis } else { KineticFriction::Coulomb },
        ..InteractionConfig::default()
    };
    let scene = GraspLiftCarry::new(config).map_err(|e| e.to_string())?;
    let report = scene.run(every).map_err(|e| e.to_string())?;
    if json {
        println!("{}", serde_json::to_string_pretty(&report).map_err(|e| e.to_string())?);
        return Ok(());
    }
    println!(
        "grasp-lift-carry: a 5 cm, 50 g wooden cube; thumb + 4 fingers; lift 20 cm; turn 90°; open"
    );
    println!(
        "{:>5} {:<8} {:>22} {:>22} {:>7} {:>4} {:>4} {:>4} {:>7} {:>5} {:>5}",
        "t[s]",
        "phase",
        "palm [m]",
        "cube [m]",
        "v[m/s]",
        "stat",
        "dyn",
        "sep",
        "F[N]",
        "begin",
        "end"
    );
    for r in &report.timeline {
        let v = |a: [f32; 3]| format!("({:6.3},{:6.3},{:6.3})", a[0], a[1], a[2]);
        println!(
            "{:5.2} {:<8} {:>22} {:>22} {:7.3} {:4} {:4} {:4} {:7.3} {:5} {:5}",
            r.t,
            r.phase,
            v(r.palm),
            v(r.cube),
            r.cube_speed,
            r.contacts_static,
            r.contacts_dynamic,
            r.contacts_separated,
            r.hand_force,
            r.began,
            r.ended
        );
    }
    println!();
    println!(
        "cube drift in the hand while carried: {:.1} mm, {:.1}°",
        report.max_drift * 1e3,
        report.max_drift_deg
    );
    println!(
        "held at {:.3} m with {} contacts; after opening: {:.3} m, {} contacts",
        report.held_height,
        report.contacts_held,
        report.final_height,
        report.contacts_after_release
    );
    println!("max cube speed {:.2} m/s", report.max_speed);
    let held = report.held_height > 0.15;
    let dropped = report.final_height < report.held_height - 0.1;
    println!(
        "outcome: {} and {}",
        if held { "held through lift and turn" } else { "NOT held" },
        if dropped { "fell when the hand opened" } else { "did NOT fall" }
    );
    if held && dropped { Ok(()) } else { Err("the demo's physical outcome was wrong".into()) }
}

/// A finite number > 0.
fn positive(s: &str) -> Result<f64, String> {
    let v: f64 = s.trim().parse().map_err(|e| format!("expected a number, got {s:?} ({e})"))?;
    if v.is_finite() && v > 0.0 && (v as f32) > 0.0 {
        Ok(v)
    } else {
        Err(format!("must be a finite number > 0, got {s}"))
    }
}

/// A finite number ≥ 0.
fn at_least_zero(s: &str) -> Result<f64, String> {
    let v: f64 = s.trim().parse().map_err(|e| format!("expected a number, got {s:?} ({e})"))?;
    if v.is_finite() && v >= 0.0 {
        Ok(v)
    } else {
        Err(format!("must be a finite number ≥ 0, got {s}"))
    }
}

fn parse_gamma(s: &str) -> Result<coulomb_hands::GammaMode, String> {
    if s == "auto" {
        return Ok(coulomb_hands::GammaMode::Auto);
    }
    match s.parse::<f32>() {
        Ok(g) if g.is_finite() && g > 0.0 => Ok(coulomb_hands::GammaMode::Fixed(g)),
        _ => Err(format!("expected \"auto\" or a positive number of N/m, got \"{s}\"")),
    }
}

fn parse_vec3(s: &str) -> Result<glam::Vec3, String> {
    let v: Vec<f32> = s
        .split(',')
        .map(|p| p.trim().parse::<f32>())
        .collect::<Result<_, _>>()
        .map_err(|e| format!("expected three finite numbers \"x,y,z\", got \"{s}\" ({e})"))?;
    match v.as_slice() {
        [x, y, z] if v.iter().all(|c| c.is_finite()) => Ok(glam::Vec3::new(*x, *y, *z)),
        _ => Err(format!("expected three finite numbers \"x,y,z\", got \"{s}\"")),
    }
}

struct ReplayArgs<'a> {
    file: &'a std::path::Path,
    trace: Option<&'a std::path::Path>,
    json: bool,
    device: glam::Vec3,
    grace: f64,
    gamma: coulomb_hands::GammaMode,
    object: Option<coulomb_hands::run::replay::GraspObject>,
    record: Option<&'a std::path::Path>,
    scene: Option<&'a std::path::Path>,
    soak: Option<std::time::Duration>,
}

/// `replay`: one replay, a session's replay, or a soak.
fn replay(args: ReplayArgs) -> Result<(), Box<dyn std::error::Error>> {
    use coulomb_hands::input::{convert::Conversion, leap, playback::Playback};
    use coulomb_hands::output::Session;
    use coulomb_hands::run::observe::TraceWriter;
    use coulomb_hands::run::replay::{place_at_grasp, replay, replay_world};
    let ReplayArgs { file, trace, json, device, grace, gamma, object, record, scene, soak } = args;
    let scene = scene.map(coulomb_hands::scene::Scene::load).transpose()?;
    if std::fs::read_to_string(file).is_ok_and(|t| Session::sniff(&t)) {
        if soak.is_some() {
            return Err("--loop replays Leap recordings; a session file replays once".into());
        }
        return Ok(replay_session(file, json)?);
    }
    let recording = leap::load(file)?;
    let conversion = Conversion::leap_desktop(device);
    let playback = Playback::new(&recording.source_name, &recording.frames, &conversion, grace)?;
    let mut config = InteractionConfig { gamma, ..InteractionConfig::default() };
    if let Some(scene) = &scene {
        config = config.with_scene(scene);
    }
    let mut world = replay_world(config, record.is_some())?;
    if let Some(scene) = &scene {
        world.add_scene(scene)?;
    }
    let mut fixtures = Vec::new();
    let mut site = None;
    if let Some(object) = object {
        let (fixture, s) = place_at_grasp(&mut world, &playback, object, 0)?;
        fixtures.push(fixture);
        site = Some(s);
    }
    let mut writer = trace.map(create).transpose()?.map(TraceWriter::new);
    if let Some(duration) = soak {
        let mut observers: Vec<&mut dyn coulomb_hands::run::drive::Observer> = Vec::new();
        observers.extend(writer.as_mut().map(|w| w as _));
        let source = &recording.source_name;
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
    let summary = match writer.as_mut() {
        Some(w) => replay(&recording.source_name, &playback, &mut world, &fixtures, &mut [w])?,
        None => replay(&recording.source_name, &playback, &mut world, &fixtures, &mut [])?,
    };
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
    println!("replayed {} (format {})", summary.source, recording.format_version);
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
    if let Some(s) = site {
        println!(
            "first grasp at ({:.3}, {:.3}, {:.3}) m: closed {:.2}-{:.2} s, most closed at {:.2} s",
            s.point.x, s.point.y, s.point.z, s.closing_at, s.open_at, s.closed_at
        );
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

/// Prints a soak's report.
fn print_soak(r: &coulomb_hands::run::soak::SoakReport, json: bool) -> Result<(), RunError> {
    if json {
        println!("{}", serde_json::to_string_pretty(r).map_err(std::io::Error::other)?);
    } else {
        print!("{r}");
    }
    Ok(())
}

/// A progress bar of `len` steps drawn with `template`, or a hidden one.
fn progress_bar(show: bool, len: u64, template: &str) -> indicatif::ProgressBar {
    if !show {
        return indicatif::ProgressBar::hidden();
    }
    let style = indicatif::ProgressStyle::with_template(template).expect("a valid template");
    indicatif::ProgressBar::new(len).with_style(style)
}

/// A buffered output file; its errors name it.
fn create(path: &std::path::Path) -> Result<TraceFile, RunError> {
    Ok(TraceFile::create(path)?)
}

fn live(url: &str, seconds: f64, device: glam::Vec3) -> Result<(), RunError> {
    use coulomb_hands::input::{convert::Conversion, playback::DEFAULT_GRACE};
    use coulomb_hands::run::{live::run_live, replay::replay_world};
    let mut world = replay_world(InteractionConfig::default(), false)?;
    let conversion = Conversion::leap_desktop(device);
    let s = run_live(url, &mut world, conversion, DEFAULT_GRACE, seconds, &mut [])?;
    println!(
        "live {url}: {} frames, {} skipped, {} hands seen, {:.2} s simulated, {} contacts begun",
        s.frames, s.skipped, s.hands_seen, s.simulated, s.contacts_begun
    );
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

fn bench(steps: usize, boxes: usize, tower: bool) -> Result<(), String> {
    let (mut world, _) =
        held_boxes_scene(InteractionConfig::default(), boxes, tower).map_err(|e| e.to_string())?;
    let r = time_steps(&mut world, steps);
    println!(
        "scene: 2 hands, {boxes} held boxes, tower: {tower}; {} bones pressing, {} objects",
        r.bones_pressing, r.objects
    );
    println!("interaction layer (contacts + forces): {:8.2} µs/step", r.interaction_layer_us);
    println!("full step (with rapier):               {:8.2} µs/step", r.full_step_us);
    println!("full step in the first second (settling): {:5.2} µs/step", r.settling_us);
    Ok(())
}

/// Runs one scenario or all shipped ones. Returns the failed checks, as
/// `scenario: check`.
fn scenario(
    name: Option<&str>,
    all: bool,
    trace: Option<&std::path::Path>,
    json: bool,
) -> Result<Vec<String>, RunError> {
    use coulomb_hands::run::observe::TraceWriter;
    use coulomb_hands::run::scenario::{Scenario, shipped};
    let names: Vec<String> = match name {
        Some(n) if !all => vec![n.to_string()],
        _ => shipped().iter().map(|s| s.0.to_string()).collect(),
    };
    // Every file is checked before anything runs.
    let scenarios = names.iter().map(|n| Scenario::find(n)).collect::<Result<Vec<_>, _>>()?;
    let mut writer = trace.map(create).transpose()?.map(TraceWriter::new);
    let template = "{bar:30} {pos}/{len} {msg} ({elapsed})";
    let bar = progress_bar(all && !json, scenarios.len() as u64, template);
    let mut reports = Vec::new();
    let started = Instant::now();
    for s in &scenarios {
        bar.set_message(s.name.clone());
        let t0 = Instant::now();
        let report = match writer.as_mut() {
            Some(w) => s.run(&mut [w])?,
            None => s.run(&mut [])?,
        };
        reports.push((report, t0.elapsed().as_secs_f64(), s.description.clone()));
        bar.inc(1);
    }
    bar.finish_and_clear();
    if let Some(w) = writer {
        w.finish()?;
    }
    let failed: Vec<String> = reports
        .iter()
        .flat_map(|(r, ..)| r.checks.iter().filter(|c| !c.passed).map(|c| (&r.name, &c.name)))
        .map(|(scenario, check)| format!("{scenario}: {check}"))
        .collect();
    if json {
        let list: Vec<_> = reports.iter().map(|r| &r.0).collect();
        println!("{}", serde_json::json!({ "scenarios": list }));
        return Ok(failed);
    }
    if all {
        println!("{:<20} {:<6} {:>7}  failed checks", "scenario", "result", "wall[s]");
        for (r, wall, _) in &reports {
            let failed: Vec<&str> =
                r.checks.iter().filter(|c| !c.passed).map(|c| c.name.as_str()).collect();
            let result = if r.passed { "pass" } else { "FAIL" };
            let row = format!("{:<20} {result:<6} {wall:>7.2}  {}", r.name, failed.join("; "));
            println!("{}", row.trim_end());
        }
        let n = reports.iter().filter(|r| r.0.passed).count();
        println!("{n}/{} passed in {:.1} s", reports.len(), started.elapsed().as_secs_f64());
    } else {
        for (r, wall, description) in &reports {
            println!("{}: {description}", r.name);
            for c in &r.checks {
                println!(
                    "  {:<4} {:<40} {:>10.4}  bound {}",
                    if c.passed { "ok" } else { "FAIL" },
                    c.name,
                    c.value,
                    c.bound
                );
            }
            println!("{} in {wall:.2} s", if r.passed { "passed" } else { "FAILED" });
        }
    }
    Ok(failed)
}

/// Writes `mesh::generate::shipped()` as OBJ files into `out`.
fn write_meshes(out: &std::path::Path) -> std::io::Result<()> {
    use coulomb_hands::scene::mesh::generate::{header, shipped};
    let named = |path: &std::path::Path, e: std::io::Error| {
        std::io::Error::new(e.kind(), format!("{}: {e}", path.display()))
    };
    std::fs::create_dir_all(out).map_err(|e| named(out, e))?;
    for (name, mesh) in shipped() {
        let path = out.join(format!("{name}.obj"));
        std::fs::write(&path, mesh.to_obj(&header(name))).map_err(|e| named(&path, e))?;
        println!("wrote {} ({} triangles)", path.display(), mesh.triangles.len());
    }
    Ok(())
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command.unwrap_or(Command::Demo {
        json: false,
        thesis_kinetic: false,
        every: 0.25,
    }) {
        Command::Demo { json, thesis_kinetic, every } => demo(json, thesis_kinetic, every as f32),
        Command::Bench { steps, boxes, no_tower } => bench(steps, boxes.into(), !no_tower),
        Command::Mesh { out } => write_meshes(&out).map_err(|e| e.to_string()),
        Command::Scenario { scenario: name, all, trace, json } => {
            match scenario(name.as_deref(), all, trace.as_deref(), json) {
                Ok(failed) if failed.is_empty() => Ok(()),
                Ok(failed) => Err(format!("failed checks: {}", failed.join("; "))),
                Err(e) => Err(e.to_string()),
            }
        }
        Command::Live { url, seconds, device } => {
            live(&url, seconds, device).map_err(|e| e.to_string())
        }
        Command::Replay {
            file,
            trace,
            json,
            device,
            scene,
            record,
            object_at_grasp,
            gamma,
            grace,
            soak,
        } => replay(ReplayArgs {
            file: &file,
            trace: trace.as_deref(),
            json,
            device,
            grace,
            gamma,
            object: object_at_grasp,
            record: record.as_deref(),
            scene: scene.as_deref(),
            soak,
        })
        .map_err(|e| e.to_string()),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
