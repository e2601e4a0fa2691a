//! coulomb-hands from Python: the `coulomb_hands` package's extension module.
//!
//! A thin layer over the library: every call goes to the library function
//! the command line calls, with NumPy arrays in and out. Nothing here
//! computes physics, parses a format or checks a value the library checks.
//!
//! * `config.rs`: `Config`, `InteractionConfig` as the config files have it;
//! * `world.rs`: `World`, an `InteractionWorld`;
//! * `arrays.rs`: arrays in (shapes checked, named) and out, and hand poses
//!   as dicts of arrays;
//! * `runs.rs`: the runs the CLI has (`replay`, `replay_capture`,
//!   `run_scenario`, `eval_accuracy`, `bench`), each returning its `--json`
//!   data, and the recordings' loader;
//! * `values.rs`: a method's name, a γ argument, and results as JSON's
//!   Python objects, which the others take from it, so no two import each
//!   other;
//! * here: the exceptions, one per library error kind, and the module.

mod arrays;
mod config;
mod runs;
mod values;
mod world;

use coulomb_hands::run::bench::BenchError as LibBenchError;
use coulomb_hands::{RunError, WorldError};
use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;

create_exception!(_coulomb_hands, CoulombHandsError, PyException, "Any error of coulomb-hands.");
create_exception!(
    _coulomb_hands,
    ConfigError,
    CoulombHandsError,
    "A config field was rejected: `config: FIELD: REASON`."
);
create_exception!(
    _coulomb_hands,
    PoseError,
    CoulombHandsError,
    "A hand pose was rejected; names the hand and the bone."
);
create_exception!(
    _coulomb_hands,
    ObjectError,
    CoulombHandsError,
    "An object or static description was rejected; names the object and the field."
);
create_exception!(_coulomb_hands, NoSuchHandError, CoulombHandsError, "No hand has this id.");
create_exception!(_coulomb_hands, NoSuchObjectError, CoulombHandsError, "No object has this id.");
create_exception!(
    _coulomb_hands,
    InputError,
    CoulombHandsError,
    "Tracking input was bad or unreadable; names the file, the frame and the field."
);
create_exception!(
    _coulomb_hands,
    LayoutError,
    CoulombHandsError,
    "A joint set could not become a hand (an unknown layout, a joint that is not finite)."
);
create_exception!(
    _coulomb_hands,
    SkeletonError,
    CoulombHandsError,
    "Tracked joints could not become the 16-bone hand."
);
create_exception!(
    _coulomb_hands,
    FileError,
    CoulombHandsError,
    "A scene, scenario or mesh file was bad or unreadable; names the file."
);
create_exception!(
    _coulomb_hands,
    SessionError,
    CoulombHandsError,
    "A session file could not be read, written or replayed."
);
create_exception!(_coulomb_hands, OutputError, CoulombHandsError, "Writing an output failed.");
create_exception!(
    _coulomb_hands,
    StudyError,
    CoulombHandsError,
    "A study's option is out of range."
);
create_exception!(
    _coulomb_hands,
    NoGraspError,
    CoulombHandsError,
    "An object was asked for at a grasp the recording does not have."
);
create_exception!(
    _coulomb_hands,
    GraspObjectError,
    CoulombHandsError,
    "An object_at_grasp text is not SHAPE:SIZE_M:MASS_KG."
);
create_exception!(
    _coulomb_hands,
    UnknownMethodError,
    CoulombHandsError,
    "A method name is not coulomb, thesis, kinematic or heuristic."
);
create_exception!(_coulomb_hands, BenchError, CoulombHandsError, "A bench run failed.");
create_exception!(
    _coulomb_hands,
    ShapeError,
    CoulombHandsError,
    "An array argument has the wrong shape or is not numbers; names the argument."
);
create_exception!(
    _coulomb_hands,
    ArgumentError,
    CoulombHandsError,
    "An argument is not one the call knows (a side, a material, a strategy)."
);

/// A world call's error as its exception, with the library's message.
pub(crate) fn world_error(e: WorldError) -> PyErr {
    let message = e.to_string();
    match e {
        WorldError::Pose(_) => PoseError::new_err(message),
        WorldError::Object(_) => ObjectError::new_err(message),
        // A method host mode cannot run is the config's.
        WorldError::Config(_) | WorldError::HostGrab(_) => ConfigError::new_err(message),
        WorldError::NoSuchHand(_) => NoSuchHandError::new_err(message),
        WorldError::NoSuchObject(_) => NoSuchObjectError::new_err(message),
    }
}

/// A run's error as its exception, with the library's message.
pub(crate) fn run_error(e: RunError) -> PyErr {
    let message = e.to_string();
    match e {
        RunError::Input(_) => InputError::new_err(message),
        RunError::World(e) => world_error(e),
        RunError::Session(_) => SessionError::new_err(message),
        RunError::File(_) => FileError::new_err(message),
        RunError::Output(_) => OutputError::new_err(message),
        RunError::Study { .. } => StudyError::new_err(message),
        RunError::NoGrasp { .. } => NoGraspError::new_err(message),
    }
}

/// A bench's error as its exception, with the library's message.
pub(crate) fn bench_error(e: LibBenchError) -> PyErr {
    match e {
        LibBenchError::World(e) => world_error(e),
        LibBenchError::Run(e) => run_error(e),
        e @ LibBenchError::Options { .. } => ArgumentError::new_err(e.to_string()),
        e => BenchError::new_err(e.to_string()),
    }
}

#[pymodule]
fn _coulomb_hands(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add_class::<config::Config>()?;
    m.add_class::<world::World>()?;
    runs::add(m)?;
    m.add("FRICTION_STATES", arrays::FRICTION_STATES)?;
    m.add("EVENT_KINDS", arrays::EVENT_KINDS)?;
    m.add("BONES", arrays::bone_names())?;
    for (name, class) in [
        ("CoulombHandsError", py.get_type::<CoulombHandsError>()),
        ("ConfigError", py.get_type::<ConfigError>()),
        ("PoseError", py.get_type::<PoseError>()),
        ("ObjectError", py.get_type::<ObjectError>()),
        ("NoSuchHandError", py.get_type::<NoSuchHandError>()),
        ("NoSuchObjectError", py.get_type::<NoSuchObjectError>()),
        ("InputError", py.get_type::<InputError>()),
        ("LayoutError", py.get_type::<LayoutError>()),
        ("SkeletonError", py.get_type::<SkeletonError>()),
        ("FileError", py.get_type::<FileError>()),
        ("SessionError", py.get_type::<SessionError>()),
        ("OutputError", py.get_type::<OutputError>()),
        ("StudyError", py.get_type::<StudyError>()),
        ("NoGraspError", py.get_type::<NoGraspError>()),
        ("GraspObjectError", py.get_type::<GraspObjectError>()),
        ("UnknownMethodError", py.get_type::<UnknownMethodError>()),
        ("BenchError", py.get_type::<BenchError>()),
        ("ShapeError", py.get_type::<ShapeError>()),
        ("ArgumentError", py.get_type::<ArgumentError>()),
    ] {
        m.add(name, class)?;
    }
    Ok(())
}
