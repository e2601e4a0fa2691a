//! `coulomb-hands`: the headless command line.

mod cli;

use clap::{Parser, Subcommand};
use cli::args::{at_least_zero, parse_gamma, parse_vec3, positive};
use cli::options::{AblationArgs, BenchRunArgs, StudyArgs, SweepArgs};
use std::process::ExitCode;

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
        /// How hands move objects: coulomb (default), thesis, kinematic or heuristic.
        #[arg(long, default_value = "coulomb")]
        method: coulomb_hands::Method,
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
        /// Tracking gaps up to this long (s) are bridged; longer ones release the hand.
        #[arg(long, default_value_t = coulomb_hands::input::playback::DEFAULT_GRACE,
              value_parser = at_least_zero)]
        grace: f64,
        /// Add the static scenery and objects of this scene file (JSON; see the
        /// `scene` module docs).
        #[arg(long)]
        scene: Option<std::path::PathBuf>,
        /// Put an object (see --object) with its centre here, "x,y,z" in metres.
        #[arg(long, value_parser = parse_vec3)]
        object_at: Option<glam::Vec3>,
        /// The --object-at object: SHAPE:SIZE_M:MASS_KG, SHAPE box or sphere, wood.
        #[arg(
            long,
            value_name = "SHAPE:SIZE_M:MASS_KG",
            default_value = "box:0.04:0.05",
            requires = "object_at"
        )]
        object: coulomb_hands::run::replay::GraspObject,
        /// Record the whole session (scene, poses, steps) to this file; replaying
        /// that file reproduces the run bit for bit.
        #[arg(long)]
        record: Option<std::path::PathBuf>,
        /// Print one JSON object instead of the summary.
        #[arg(long)]
        json: bool,
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
        /// How hands move objects: coulomb (default), thesis, kinematic or heuristic.
        /// A scenario's checks were written for friction hands.
        #[arg(long, default_value = "coulomb")]
        method: coulomb_hands::Method,
    },
    /// The evaluation of thesis Ch. 5.
    Eval {
        #[command(subcommand)]
        study: Study,
    },
    /// Write a self-contained HTML report (index.html): placement accuracy, step
    /// times, every shipped scenario and the bundled replays, with plots. Without
    /// --accuracy or --bench, it runs the accuracy study and the bench itself.
    Report {
        /// The directory to write index.html to; checked before any work.
        #[arg(long, default_value = "report")]
        out: std::path::PathBuf,
        /// The placement-accuracy study's JSON (`eval accuracy --json`), instead of
        /// running the study.
        #[arg(long, value_name = "FILE")]
        accuracy: Option<std::path::PathBuf>,
        /// The benchmark's JSON (`bench --json`), instead of running the bench.
        #[arg(long, value_name = "FILE")]
        bench: Option<std::path::PathBuf>,
        /// The placement study over tracking noise (`eval sweep --json`); the report
        /// does not run it (it takes minutes).
        #[arg(long, value_name = "FILE")]
        sweep: Option<std::path::PathBuf>,
        /// The ablation of the thesis's law (`eval ablation --json`).
        #[arg(long, value_name = "FILE")]
        ablation: Option<std::path::PathBuf>,
        /// Leave the accuracy study out.
        #[arg(long, conflicts_with = "accuracy")]
        no_accuracy: bool,
        /// Leave the benchmark out.
        #[arg(long, conflicts_with = "bench")]
        no_bench: bool,
        /// Only these scenarios (shipped names or files), comma-separated.
        #[arg(long, value_name = "NAME,...", value_delimiter = ',')]
        scenarios: Option<Vec<String>>,
        /// Only these recordings (Leap or joint recordings), comma-separated (default: every one in
        /// data/leap/).
        #[arg(long, value_name = "FILE,...", value_delimiter = ',')]
        replays: Option<Vec<std::path::PathBuf>>,
        #[command(flatten, next_help_heading = "Accuracy study (without --accuracy)")]
        study: StudyArgs,
        #[command(flatten, next_help_heading = "Bench (without --bench)")]
        timing: BenchRunArgs,
    },
    /// Write the project's generated meshes (U bracket, chess pawn) as OBJ files.
    Mesh {
        /// The directory to write them to.
        #[arg(long, default_value = "assets/meshes")]
        out: std::path::PathBuf,
    },
    /// Time steps against bones in contact (6..128) and the reference scene awake and
    /// asleep (thesis §5.3, Fig. 5.6); with --mujoco, MuJoCo's step beside them.
    Bench {
        #[command(flatten)]
        timing: BenchRunArgs,
        /// Print one JSON object instead of the table.
        #[arg(long)]
        json: bool,
    },
}

#[derive(Subcommand)]
enum Study {
    /// The positioning-accuracy study (§5.2, Table 5.2): synthetic users move a cube to a
    /// target square with each method.
    Accuracy {
        #[command(flatten)]
        study: StudyArgs,
        /// Print one JSON object instead of the table.
        #[arg(long)]
        json: bool,
    },
    /// The accuracy study at several strengths of real tracking noise, on several seeds'
    /// users, with 95 % confidence intervals.
    Sweep {
        #[command(flatten)]
        sweep: SweepArgs,
        /// Print one JSON object instead of the table.
        #[arg(long)]
        json: bool,
    },
    /// The thesis's law as written, given this crate's departures back one at a time:
    /// which of them let the users carry the cube.
    Ablation {
        #[command(flatten)]
        ablation: AblationArgs,
        /// Print one JSON object instead of the table.
        #[arg(long)]
        json: bool,
    },
}

/// A reader that stops reading early (`coulomb-hands replay … | head`)
/// ends the program quietly, as it does other Unix tools, instead of
/// making `println!` panic on the closed pipe: Rust's runtime ignores
/// SIGPIPE, and this gives it back its default.
#[cfg(unix)]
fn end_quietly_on_a_closed_pipe() {
    // SAFETY: first thing in `main`, before any other thread exists;
    // `signal` with `SIG_DFL` only resets a disposition.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}

fn main() -> ExitCode {
    #[cfg(unix)]
    end_quietly_on_a_closed_pipe();
    let cli = Cli::parse();
    let result = match cli.command.unwrap_or(Command::Demo {
        json: false,
        thesis_kinetic: false,
        every: 0.25,
    }) {
        Command::Demo { json, thesis_kinetic, every } => {
            cli::demo::demo(json, thesis_kinetic, every as f32)
        }
        Command::Bench { timing, json } => cli::bench::bench(&timing.options(), json),
        Command::Eval { study: Study::Accuracy { study, json } } => {
            cli::eval::run(&study.options(), json).map_err(|e| e.to_string())
        }
        Command::Eval { study: Study::Sweep { sweep, json } } => {
            cli::eval::sweep(&sweep.options(), json).map_err(|e| e.to_string())
        }
        Command::Eval { study: Study::Ablation { ablation, json } } => {
            cli::eval::ablation(&ablation.options(), json).map_err(|e| e.to_string())
        }
        Command::Report {
            out,
            accuracy,
            bench,
            sweep,
            ablation,
            no_accuracy,
            no_bench,
            scenarios,
            replays,
            study,
            timing,
        } => {
            use cli::report::Source;
            let accuracy = Source::new(accuracy.as_deref(), no_accuracy, || study.options());
            let bench = Source::new(bench.as_deref(), no_bench, || timing.options());
            cli::report::report(cli::report::ReportArgs {
                out: &out,
                accuracy,
                bench,
                sweep: sweep.as_deref(),
                ablation: ablation.as_deref(),
                scenarios: scenarios.as_deref(),
                replays: replays.as_deref(),
            })
            .map_err(|e| e.to_string())
        }
        Command::Mesh { out } => cli::write_meshes(&out).map_err(|e| e.to_string()),
        Command::Scenario { scenario: name, all, trace, json, method } => {
            match cli::scenario::scenario(name.as_deref(), all, trace.as_deref(), json, method) {
                Ok(failed) if failed.is_empty() => Ok(()),
                Ok(failed) => Err(format!("failed checks: {}", failed.join("; "))),
                Err(e) => Err(e.to_string()),
            }
        }
        Command::Live { url, seconds, device, grace, scene, object_at, object, record, json } => {
            cli::live::live(cli::live::LiveArgs {
                url: &url,
                seconds,
                device,
                grace,
                scene: scene.as_deref(),
                object: object_at.map(|at| (object, at)),
                record: record.as_deref(),
                json,
            })
            .map_err(|e| e.to_string())
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
            method,
            grace,
            soak,
        } => cli::replay::replay(cli::replay::ReplayArgs {
            file: &file,
            trace: trace.as_deref(),
            json,
            device,
            grace,
            gamma,
            method,
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
