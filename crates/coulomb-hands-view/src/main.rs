//! `coulomb-hands-view [SCENARIO|RECORDING|CAPTURE|SCENE]`: opens a window
//! onto an interaction. With no argument, a desk scene and a hand driven by mouse
//! and keyboard; `--leap` or `--openxr` take live hands instead.

use clap::Parser;
use coulomb_hands::input::convert::MountPreset;
use coulomb_hands::pipeline::Method;
use coulomb_hands::run::replay::{GraspObject, ObjectPlace};
use coulomb_hands_bevy::convert::to_core_vec3;
use coulomb_hands_view::ar::Background;
use coulomb_hands_view::camera::{StartView, Stereo};
use coulomb_hands_view::head::{HeadMount, HeadPose, parse_mount};
use coulomb_hands_view::source::{LoadOptions, Source};
use coulomb_hands_view::task::{ChessboardTask, TaskOptions};
use coulomb_hands_view::transport::Shot;
use coulomb_hands_view::xr_hands::RoomPlacement;
use coulomb_hands_view::{Viewer, display};
use std::process::ExitCode;

/// Shows an interaction in a window: the hand semi-transparent before
/// contact and opaque during it, red force and yellow motion arrows, a HUD,
/// playback controls, and (for a scene) a hand you drive.
#[derive(Parser, Debug)]
#[command(name = "coulomb-hands-view", version)]
struct Args {
    /// A shipped scenario's name (e.g. grasp-lift), or a scenario, recording
    /// (.json.lz, .jsonl, Leap JSON), hand–object capture (replayed beside a
    /// ghost of the captured object) or scene file; none for the desk scene.
    input: Option<String>,
    /// How hands move objects: coulomb (default), thesis, kinematic or heuristic.
    #[arg(long, default_value = "coulomb")]
    method: Method,
    /// With a recording: the scenery and objects of this scene file.
    #[arg(long)]
    scene: Option<std::path::PathBuf>,
    /// With a recording: an object (see --object) at each closing of a hand ("grasp"), or once
    /// with its centre at "x,y,z" in metres.
    #[arg(long, value_name = "grasp|X,Y,Z")]
    object_at: Option<ObjectPlace>,
    /// The --object-at object: SHAPE:SIZE_M:MASS_KG, SHAPE box (SIZE its side) or sphere (SIZE
    /// its diameter), of wood.
    #[arg(
        long,
        value_name = "SHAPE:SIZE_M:MASS_KG",
        default_value = coulomb_hands::run::held::GraspObject::DEFAULT,
        requires = "object_at"
    )]
    object: GraspObject,
    /// The old spelling of `--object SHAPE:SIZE_M:MASS_KG --object-at grasp`, still read.
    #[arg(long, value_name = "SHAPE:SIZE_M:MASS_KG", hide = true, conflicts_with = "object_at")]
    object_at_grasp: Option<GraspObject>,
    /// Save a PNG screenshot when the simulated time reaches T seconds (repeatable).
    #[arg(long, value_name = "T=PATH.png")]
    screenshot: Vec<Shot>,
    /// Quit once the simulated time reaches this many seconds and the screenshots are saved.
    #[arg(long, value_name = "SECONDS")]
    exit_after: Option<f64>,
    /// Start paused.
    #[arg(long)]
    paused: bool,
    /// Start with the raw tracked skeleton shown (Tab toggles it).
    #[arg(long)]
    skeleton: bool,
    /// Side-by-side stereo (§3.8.2) with this virtual camera distance: ipd (63 mm), leap
    /// (40 mm, the Leap's camera distance, for its image pass-through) or millimetres.
    #[arg(long, value_name = "ipd|leap|MM")]
    stereo: Option<Stereo>,
    /// Where the camera starts: yaw and pitch in degrees, and a distance in metres (default:
    /// the direction that shows the most of the run's grasps, else 0,32, at the distance that
    /// frames the whole run).
    #[arg(long, value_name = "YAW,PITCH[,DISTANCE]", conflicts_with = "head_mounted")]
    view: Option<StartView>,
    /// With a Leap recording made on a headset (§3.8.1): the tracker's mount, dk2 (8 cm ahead
    /// of the eyes) or hololens (7 cm up, 5 cm ahead). The camera is then the wearer's eyes.
    #[arg(long, value_name = "dk2|hololens", value_parser = parse_mount)]
    head_mounted: Option<MountPreset>,
    /// AR mode (§3.6): draw over this image (PNG or JPEG; a pass-through camera frame); the
    /// hand, and the scenery, become masks that hide the virtual objects behind them.
    #[arg(long, value_name = "IMAGE")]
    background: Option<std::path::PathBuf>,
    /// The placement task of the thesis's §5.2 for a person (chessboard): move the cube to the
    /// yellow square with the mouse hand, then Enter; trial after trial.
    #[arg(long, value_name = "chessboard", value_parser = ["chessboard"], conflicts_with = "input")]
    task: Option<String>,
    /// With --task: trials in the session, 1 to 1000.
    #[arg(long, default_value_t = 20, requires = "task",
          value_parser = clap::value_parser!(u16).range(1..=1000))]
    trials: u16,
    /// With --task: the seed of the squares (the same seed, the same trials).
    #[arg(long, default_value_t = 1, requires = "task")]
    seed: u64,
    /// With --task: add this person's row to this accuracy JSON (`eval accuracy --json`'s),
    /// rewritten after every trial; made if missing.
    #[arg(long, value_name = "FILE", requires = "task")]
    log: Option<std::path::PathBuf>,
    /// With --task: the person's name, for the row `METHOD (NAME)`.
    #[arg(long, default_value = "person", requires = "task")]
    person: String,
    /// Live hands from an OpenXR runtime's hand tracking (a headset, or Monado), in the desk
    /// scene or INPUT's scene; the view is the headset's. Needs `--features openxr`.
    #[arg(long, conflicts_with_all = ["task", "stereo", "background", "view", "head_mounted"])]
    openxr: bool,
    /// With --openxr: where the scene's origin sits in the room, in metres in the runtime's
    /// stage space (floor at y = 0; default 0,0.8,-0.35: at a table's height, ahead).
    #[arg(long, value_name = "X,Y,Z", requires = "openxr")]
    xr_origin: Option<RoomPlacement>,
    /// Live hands from a Leap Motion service's WebSocket stream (default URL
    /// ws://127.0.0.1:6437/v6.json), in the desk scene or INPUT's scene.
    #[arg(long, value_name = "URL", num_args = 0..=1,
          default_missing_value = coulomb_hands::input::live::DEFAULT_URL,
          conflicts_with_all = ["task", "openxr", "head_mounted"])]
    leap: Option<String>,
    /// With --leap: where the desktop device sits in the scene, X,Y,Z in metres (default
    /// 0,-0.2,0: 20 cm under the origin, so a hand at the device's usual 20–30 cm reaches the
    /// table).
    #[arg(long, value_name = "X,Y,Z", requires = "leap")]
    leap_device: Option<RoomPlacement>,
    /// No contact sound (it is off anyway when there is no audio device).
    #[arg(long)]
    mute: bool,
    /// With --head-mounted: the eyes' position in metres, and yaw and pitch in degrees
    /// (default 0,0.5,0.35,0,-30: hands held ahead land about 20 cm over the origin).
    #[arg(long, value_name = "X,Y,Z,YAW,PITCH", requires = "head_mounted")]
    head: Option<HeadPose>,
}

fn main() -> ExitCode {
    let args = Args::parse();
    if let Err(e) = openxr_built(args.openxr) {
        eprintln!("error: {e}");
        return ExitCode::FAILURE;
    }
    let options = LoadOptions {
        method: args.method,
        scene: args.scene,
        object: match (args.object_at, args.object_at_grasp) {
            (Some(at), _) => Some((args.object, at)),
            (None, old) => old.map(|object| (object, ObjectPlace::Grasp)),
        },
        head: args
            .head_mounted
            .map(|mount| HeadMount { mount, head: args.head.unwrap_or_default() }),
    };
    let task = args.task.as_ref().map(|_| {
        let log = args.log.clone();
        let options = TaskOptions {
            trials: usize::from(args.trials),
            seed: args.seed,
            log,
            person: args.person,
        };
        ChessboardTask::drawn(options, args.method)
    });
    if let Some(e) = task.as_ref().and_then(task_error) {
        eprintln!("error: {e}");
        return ExitCode::FAILURE;
    }
    let loaded = match &task {
        Some(_) if options.for_recording() => Err("--task takes no recording options".into()),
        Some(task) => task.source().ok_or_else(|| "--task has no trials".into()),
        None if args.openxr => Source::load(args.input.as_deref(), &options)
            .and_then(Source::live_xr)
            .and_then(|source| openxr_runtime().map(|()| source)),
        None if args.leap.is_some() => {
            let url = args.leap.as_deref().unwrap_or_default();
            let device = args.leap_device.map_or(LEAP_DEVICE, |d| to_core_vec3(d.origin));
            Source::load(args.input.as_deref(), &options)
                .and_then(|source| source.live_leap(url, device))
        }
        None => Source::load(args.input.as_deref(), &options),
    };
    let source = match loaded {
        Ok(source) => source,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    if let Some(t) = args.exit_after.filter(|t| !(t.is_finite() && *t >= 0.0)) {
        eprintln!("error: --exit-after must be a time in seconds ≥ 0, got {t}");
        return ExitCode::FAILURE;
    }
    if args.paused && (args.exit_after.is_some() || !args.screenshot.is_empty()) {
        eprintln!("error: --paused never reaches the time of --exit-after or --screenshot");
        return ExitCode::FAILURE;
    }
    for shot in &args.screenshot {
        let dir = shot.path.parent().filter(|d| !d.as_os_str().is_empty());
        if let Some(Err(e)) = dir.map(std::fs::create_dir_all) {
            eprintln!("error: {}: cannot make its directory: {e}", shot.path.display());
            return ExitCode::FAILURE;
        }
    }
    let background = match args.background.as_deref().map(Background::load).transpose() {
        Ok(background) => background,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    if let Err(e) = display::check() {
        eprintln!("error: {e}");
        return ExitCode::FAILURE;
    }
    let viewer = Viewer {
        source,
        method: args.method,
        shots: args.screenshot,
        exit_after: args.exit_after,
        paused: args.paused,
        view: args.view,
        skeleton: args.skeleton,
        stereo: args.stereo,
        background,
        mute: args.mute,
        task,
        room: args.xr_origin.unwrap_or_default(),
    };
    let mut app = match viewer.app() {
        Ok(app) => app,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    match app.run() {
        bevy::app::AppExit::Success => ExitCode::SUCCESS,
        bevy::app::AppExit::Error(_) => ExitCode::FAILURE,
    }
}

/// Where a live Leap device sits in the scene by default (m).
const LEAP_DEVICE: glam::Vec3 = glam::Vec3::new(0.0, -0.2, 0.0);

/// Why a task session cannot start: a log that is not an accuracy JSON, or
/// has this person's row already (checked before any trial, so none is lost).
fn task_error(task: &ChessboardTask) -> Option<String> {
    task.check_log().err()
}

/// Why `--openxr` cannot work in this build, if asked for.
fn openxr_built(asked: bool) -> Result<(), &'static str> {
    match asked && cfg!(not(feature = "openxr")) {
        true => Err(coulomb_hands_view::NO_OPENXR),
        false => Ok(()),
    }
}

/// Why there are no live hands: no OpenXR loader, runtime or hand tracking.
fn openxr_runtime() -> Result<(), coulomb_hands_view::source::LoadError> {
    #[cfg(feature = "openxr")]
    coulomb_hands_view::openxr::check_runtime()?;
    Ok(())
}
