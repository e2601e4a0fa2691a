//! `coulomb-hands-view [SCENARIO|RECORDING|SCENE]`: opens a window onto an
//! interaction. With no argument, a desk scene and a hand driven by mouse
//! and keyboard.

use clap::Parser;
use coulomb_hands::pipeline::Method;
use coulomb_hands::run::replay::GraspObject;
use coulomb_hands_view::camera::{StartView, Stereo};
use coulomb_hands_view::source::{LoadOptions, Source};
use coulomb_hands_view::transport::Shot;
use coulomb_hands_view::{Viewer, display};
use std::process::ExitCode;

/// Shows an interaction in a window: the hand semi-transparent before
/// contact and opaque during it, red force and yellow motion arrows, a HUD,
/// playback controls, and (for a scene) a hand you drive.
#[derive(Parser, Debug)]
#[command(name = "coulomb-hands-view", version)]
struct Args {
    /// A shipped scenario's name (e.g. grasp-lift), or a scenario, recording
    /// (.json.lz, .jsonl, Leap JSON) or scene file; none for the desk scene.
    input: Option<String>,
    /// How hands move objects: coulomb (default), thesis, kinematic or heuristic.
    #[arg(long, default_value = "coulomb")]
    method: Method,
    /// With a recording: the scenery and objects of this scene file.
    #[arg(long)]
    scene: Option<std::path::PathBuf>,
    /// With a recording: an object at each closing of a hand, SHAPE:SIZE_M:MASS_KG.
    #[arg(long, value_name = "SHAPE:SIZE_M:MASS_KG")]
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
    /// Where the camera starts: yaw and pitch in degrees, distance in metres (default 0,32,0.55).
    #[arg(long, value_name = "YAW,PITCH,DISTANCE")]
    view: Option<StartView>,
}

fn main() -> ExitCode {
    let args = Args::parse();
    let options = LoadOptions {
        method: args.method,
        scene: args.scene,
        object_at_grasp: args.object_at_grasp,
    };
    let source = match Source::load(args.input.as_deref(), &options) {
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
