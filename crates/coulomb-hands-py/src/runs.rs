//! The runs the CLI has, each the library function the CLI calls, its
//! result the CLI's `--json` data as Python objects (through JSON, so a
//! `json.dumps` of it is the CLI's text), a hand–object capture's replay
//! among them; and the recordings' loader.

use crate::arrays::{column, points_array, pose_dict};
use crate::values;
use crate::{ArgumentError, GraspObjectError, InputError, SkeletonError};
use crate::{bench_error, run_error};
use coulomb_hands::GammaMode;
use coulomb_hands::eval::{AccuracyOptions, Conditions, NoiseUnit, Strategy, accuracy};
use coulomb_hands::input::mediapipe::{self, Label};
use coulomb_hands::input::{capture, layouts, recording, skeleton};
use coulomb_hands::run::bench::{self as lib_bench, BenchOptions};
use coulomb_hands::run::capture::{CaptureGrid, replay_grid};
use coulomb_hands::run::replay::{GraspObject, ReplayOptions, replay_file};
use coulomb_hands::run::scenario::{Scenario, ScenarioReports};
use coulomb_hands::scene::Scene;
use glam::Vec3;
use numpy::PyArray2;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use std::path::PathBuf;

/// Replays a recording (Leap Motion, or a joint recording) or a recorded
/// session file, headlessly: `replay FILE --json`'s data.
#[pyfunction]
#[pyo3(signature = (
    path,
    *,
    device = None,
    grace = None,
    scene = None,
    gamma = None,
    method = "coulomb",
    object_at_grasp = None,
))]
#[allow(clippy::too_many_arguments)]
fn replay<'py>(
    py: Python<'py>,
    path: PathBuf,
    device: Option<&Bound<'_, PyAny>>,
    grace: Option<f64>,
    scene: Option<PathBuf>,
    gamma: Option<&Bound<'_, PyAny>>,
    method: &str,
    object_at_grasp: Option<&str>,
) -> PyResult<Bound<'py, PyAny>> {
    let defaults = ReplayOptions::default();
    let object_at_grasp = object_at_grasp
        .map(|o| o.parse::<GraspObject>())
        .transpose()
        .map_err(|e| GraspObjectError::new_err(e.to_string()))?;
    let gamma = gamma.map_or(Ok(defaults.gamma), values::gamma)?;
    let grace = grace.unwrap_or(defaults.grace);
    let device = device.map(|d| crate::arrays::vec3(d, "device")).transpose()?;
    let method = values::method(method)?;
    let summary = py.detach(|| {
        let scene = scene.as_deref().map(Scene::load).transpose()?;
        let options = ReplayOptions {
            device: device.unwrap_or(Vec3::ZERO),
            grace,
            scene,
            gamma,
            method,
            object_at_grasp,
            record: false,
        };
        replay_file(&path, &options)
    });
    values::to_python(py, &summary.map_err(run_error)?)
}

/// Replays a hand–object capture over a grid of object masses (kg; a
/// float or a list) and materials (a name or a list), each `None` for the
/// library's default, the hand touching `hand_surface` ("exact" or
/// "body"): `replay CAPTURE --json`'s data, `{"capture": {...},
/// "replays": [...]}`.
#[pyfunction]
#[pyo3(signature = (
    path, *, method = "coulomb", mass = None, material = None, gamma = None,
    hand_surface = "exact"
))]
fn replay_capture<'py>(
    py: Python<'py>,
    path: PathBuf,
    method: &str,
    mass: Option<&Bound<'_, PyAny>>,
    material: Option<&Bound<'_, PyAny>>,
    gamma: Option<&Bound<'_, PyAny>>,
    hand_surface: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let hand_surface = hand_surface
        .parse::<coulomb_hands::HandSurface>()
        .map_err(|e| ArgumentError::new_err(format!("hand_surface: {e}")))?;
    let masses = mass
        .map(|m| m.extract::<f32>().map(|m| vec![m]).or_else(|_| column(m, "mass", None)))
        .transpose()?;
    let materials = material.map(|m| names(m, "material")).transpose()?;
    let gamma = gamma.map_or(Ok(GammaMode::default()), values::gamma)?;
    let method = values::method(method)?;
    let report = py.detach(|| {
        let grid =
            CaptureGrid { hand_surface, ..CaptureGrid::new(method, gamma, masses, materials)? };
        let capture = capture::load(&path)?;
        replay_grid(&capture, &grid)
    });
    values::to_python(py, &report.map_err(run_error)?)
}

/// A name or a list of names, the argument `what`.
fn names(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<String>> {
    let one = value.extract::<String>().map(|name| vec![name]);
    one.or_else(|_| value.extract::<Vec<String>>()).map_err(|e| {
        ArgumentError::new_err(format!("{what}: expected a name or a list of names ({e})"))
    })
}

/// Runs a shipped scenario by name (e.g. `push`) or a scenario file:
/// `scenario NAME --json`'s data, `{"scenarios": [report]}`.
#[pyfunction]
#[pyo3(signature = (name_or_path, method = "coulomb"))]
fn run_scenario<'py>(
    py: Python<'py>,
    name_or_path: &str,
    method: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let method = values::method(method)?;
    let report = py.detach(|| {
        let scenario = Scenario::find(name_or_path)?.with_method(method);
        scenario.run(&mut [])
    });
    let report = report.map_err(run_error)?;
    values::to_python(py, &ScenarioReports { scenarios: vec![&report] })
}

/// The positioning-accuracy study (thesis §5.2): `eval accuracy --json`'s
/// data.
#[pyfunction]
#[pyo3(signature = (
    *,
    users = AccuracyOptions::USERS,
    trials = AccuracyOptions::TRIALS,
    seed = AccuracyOptions::SEED,
    methods = None,
    strategies = None,
    noise = AccuracyOptions::NOISE,
    noise_mm = None,
    perception = Conditions::PERCEPTION,
    noise_from = None,
    noise_white = None,
    threads = None,
))]
#[allow(clippy::too_many_arguments)]
fn eval_accuracy<'py>(
    py: Python<'py>,
    users: usize,
    trials: usize,
    seed: u64,
    methods: Option<Vec<String>>,
    strategies: Option<Vec<String>>,
    noise: f32,
    noise_mm: Option<f32>,
    perception: f32,
    noise_from: Option<Vec<PathBuf>>,
    noise_white: Option<f32>,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyAny>> {
    let defaults = AccuracyOptions::default();
    let methods = match methods {
        None => defaults.methods,
        Some(names) => names.iter().map(|m| values::method(m)).collect::<PyResult<_>>()?,
    };
    let strategies = match strategies {
        None => defaults.strategies,
        Some(names) => names
            .iter()
            .map(|s| s.parse::<Strategy>().map_err(ArgumentError::new_err))
            .collect::<PyResult<_>>()?,
    };
    let (noise, noise_unit) = NoiseUnit::choose(noise, noise_mm);
    let conditions = Conditions {
        perception,
        noise_from: noise_from.unwrap_or_default(),
        noise_white,
        noise_unit,
        threads: threads.unwrap_or(defaults.conditions.threads),
    };
    let options = AccuracyOptions { users, trials, seed, methods, strategies, noise, conditions };
    let study = py.detach(|| accuracy(&options, &mut |_, _| {}));
    values::to_python(py, &study.map_err(run_error)?)
}

/// The performance analysis of thesis §5.3: `bench --json`'s data. With
/// `mujoco`, the Python with pip's mujoco to time MuJoCo's step by;
/// `objects`, the cluttered scenes' object counts (the CLI's by default).
#[pyfunction]
#[pyo3(name = "bench", signature = (
    *,
    steps = BenchOptions::STEPS,
    boxes = BenchOptions::MAX_BOXES,
    tower = true,
    mujoco = None,
    objects = lib_bench::DEFAULT_OBJECTS.to_vec(),
))]
fn run_bench<'py>(
    py: Python<'py>,
    steps: usize,
    boxes: usize,
    tower: bool,
    mujoco: Option<PathBuf>,
    objects: Vec<usize>,
) -> PyResult<Bound<'py, PyAny>> {
    let options = BenchOptions { steps, boxes, tower, mujoco, objects };
    let report = py.detach(|| lib_bench::run(&options, &mut |_| {}));
    values::to_python(py, &report.map_err(bench_error)?)
}

/// A recording's frames as the library loads them: a list of
/// `{"t": s, "hands": [{"id", "side", "pose"}]}`, each pose (a dict of
/// arrays, as `World.hand_pose` gives) in the world with the recording's
/// origin at `device` (m).
#[pyfunction]
#[pyo3(signature = (path, device = None))]
fn load_recording<'py>(
    py: Python<'py>,
    path: PathBuf,
    device: Option<&Bound<'_, PyAny>>,
) -> PyResult<Bound<'py, PyList>> {
    let device =
        device.map(|d| crate::arrays::vec3(d, "device")).transpose()?.unwrap_or(Vec3::ZERO);
    let recording =
        py.detach(|| recording::load(&path)).map_err(|e| InputError::new_err(e.to_string()))?;
    let conversion = recording.conversion(device);
    let start = recording.frames.first().map_or(0, |f| f.timestamp_us);
    let frames = PyList::empty(py);
    for frame in &recording.frames {
        let hands = PyList::empty(py);
        for hand in &frame.hands {
            let pose = skeleton::hand_pose(hand, &conversion)
                .map_err(|e| SkeletonError::new_err(e.to_string()))?;
            let entry = PyDict::new(py);
            entry.set_item("id", hand.id)?;
            entry.set_item(
                "side",
                if hand.side == coulomb_hands::Side::Left { "left" } else { "right" },
            )?;
            entry.set_item("pose", pose_dict(py, &pose)?)?;
            hands.append(entry)?;
        }
        let entry = PyDict::new(py);
        entry.set_item("t", (frame.timestamp_us - start) as f64 * 1e-6)?;
        entry.set_item("hands", hands)?;
        frames.append(entry)?;
    }
    Ok(frames)
}

/// MediaPipe's world landmarks (y down, its image axes) turned y up, as the
/// library turns them ([`layouts::mediapipe_to_y_up`]): an (n, 3) array.
#[pyfunction]
fn mediapipe_to_y_up<'py>(
    py: Python<'py>,
    landmarks: &Bound<'_, PyAny>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let up = layouts::mediapipe_to_y_up();
    let rows = crate::arrays::rows::<3>(landmarks, "landmarks", None)?;
    points_array(py, rows.into_iter().map(|p| up.point(Vec3::from_array(p))))
}

/// A MediaPipe hand landmarker result (`.pbtxt`), as the library reads it:
/// `side` (from its label: `subject`, the subject's own hand, or
/// `mirrored`, as MediaPipe Hands and its own test data label hands),
/// `joints` (21, 3), its world landmarks in metres turned y up, ready for
/// `set_hand_joints(..., "mediapipe")`.
#[pyfunction]
#[pyo3(signature = (path, label = "subject"))]
fn load_mediapipe<'py>(
    py: Python<'py>,
    path: PathBuf,
    label: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let label = match label {
        "subject" => Label::Subject,
        "mirrored" => Label::Mirrored,
        _ => {
            return Err(ArgumentError::new_err(format!(
                "label: \"subject\" or \"mirrored\", got {label:?}"
            )));
        }
    };
    let input = |e: coulomb_hands::input::InputError| InputError::new_err(e.to_string());
    let landmarks = py.detach(|| mediapipe::load(&path)).map_err(input)?;
    let hand = landmarks.tracked_hand(&path.display().to_string(), 0, label).map_err(input)?;
    let dict = PyDict::new(py);
    dict.set_item("side", if hand.side == coulomb_hands::Side::Left { "left" } else { "right" })?;
    let up = layouts::mediapipe_to_y_up();
    let world = landmarks.world_landmarks.unwrap_or_default();
    dict.set_item("joints", points_array(py, world.iter().map(|&p| up.point(p)))?)?;
    Ok(dict)
}

/// Adds the runs to the module.
pub fn add(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(replay, m)?)?;
    m.add_function(wrap_pyfunction!(replay_capture, m)?)?;
    m.add_function(wrap_pyfunction!(run_scenario, m)?)?;
    m.add_function(wrap_pyfunction!(eval_accuracy, m)?)?;
    m.add_function(wrap_pyfunction!(run_bench, m)?)?;
    m.add_function(wrap_pyfunction!(load_recording, m)?)?;
    m.add_function(wrap_pyfunction!(load_mediapipe, m)?)?;
    m.add_function(wrap_pyfunction!(mediapipe_to_y_up, m)?)?;
    Ok(())
}
