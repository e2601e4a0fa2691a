//! `coulomb-hands`: the headless command line.

mod cli;

use clap::{Parser, Subcommand};
use cli::args::{at_least_zero, parse_gamma, parse_vec3, positive};
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
    /// times, every shipped scenario and the bundled replays, with plots.
    Report {
        /// The directory to write index.html to; checked before any work.
        #[arg(long, default_value = "report")]
        out: std::path::PathBuf,
        /// The placement-accuracy study's JSON (`eval accuracy --json`).
        #[arg(long, value_name = "FILE")]
        accuracy: Option<std::path::PathBuf>,
        /// The benchmark's JSON (`bench --json`).
        #[arg(long, value_name = "FILE")]
        bench: Option<std::path::PathBuf>,
        /// Only these scenarios (shipped names or files), comma-separated.
        #[arg(long, value_name = "NAME,...", value_delimiter = ',')]
        scenarios: Option<Vec<String>>,
        /// Only these recordings, comma-separated (default: every one in data/leap/).
        #[arg(long, value_name = "FILE,...", value_delimiter = ',')]
        replays: Option<Vec<std::path::PathBuf>>,
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
        /// Timed steps per figure, after a warm-up.
        #[arg(long, default_value_t = 5000, value_parser = clap::value_parser!(u32).range(1..))]
        steps: u32,
        /// Held boxes in the reference scene (2 bones in contact each), 1..=16.
        #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u16).range(1..=16))]
        boxes: u16,
        /// Leave the reference scene's tower out.
        #[arg(long)]
        no_tower: bool,
        /// Print one JSON object instead of the table.
        #[arg(long)]
        json: bool,
        /// Also time MuJoCo's mj_step on the reference scene (bench/mujoco_reference.py).
        #[arg(long)]
        mujoco: bool,
        /// The Python with pip's mujoco [default: target/mujoco-venv/bin/python if there,
        /// else python3].
        #[arg(long, requires = "mujoco")]
        python: Option<std::path::PathBuf>,
    },
}

#[derive(Subcommand)]
enum Study {
    /// The positioning-accuracy study (§5.2, Table 5.2): synthetic users move a cube to a
    /// target square with each method.
    Accuracy {
        /// Synthetic users.
        #[arg(long, default_value_t = 6, value_parser = clap::value_parser!(u16).range(1..))]
        users: u16,
        /// Trials per user.
        #[arg(long, default_value_t = 20, value_parser = clap::value_parser!(u16).range(1..))]
        trials: u16,
        /// Seed of users, squares and tracking jitter.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// The methods to compare, comma-separated.
        #[arg(long, value_delimiter = ',', default_value = "coulomb,thesis,kinematic,heuristic")]
        method: Vec<coulomb_hands::Method>,
        /// Print one JSON object instead of the table.
        #[arg(long)]
        json: bool,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command.unwrap_or(Command::Demo {
        json: false,
        thesis_kinetic: false,
        every: 0.25,
    }) {
        Command::Demo { json, thesis_kinetic, every } => {
            cli::demo::demo(json, thesis_kinetic, every as f32)
        }
        Command::Bench { steps, boxes, no_tower, json, mujoco, python } => {
            let (steps, boxes, tower) = (steps as usize, boxes.into(), !no_tower);
            cli::bench::bench(cli::bench::BenchArgs { steps, boxes, tower, json, mujoco, python })
        }
        Command::Eval { study: Study::Accuracy { users, trials, seed, method, json } } => {
            let options = coulomb_hands::eval::AccuracyOptions {
                users: users.into(),
                trials: trials.into(),
                seed,
                methods: method,
            };
            cli::eval::run(&options, json).map(|_| ()).map_err(|e| e.to_string())
        }
        Command::Report { out, accuracy, bench, scenarios, replays } => {
            cli::report::report(cli::report::ReportArgs {
                out: &out,
                accuracy: accuracy.as_deref(),
                bench: bench.as_deref(),
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
