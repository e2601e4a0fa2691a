//! MuJoCo's side of the bench: `bench/mujoco_reference.py`, built into the
//! binary, run by a Python that has pip's `mujoco` (`bench/mujoco.sh` makes
//! a virtualenv with it under `target/`). It builds the reference scene in
//! MJCF (mocap capsule bones, dt 1 ms, [`SETTINGS`]) and prints one JSON
//! object with µs per `mj_step`.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The script, as committed in `bench/`.
pub const SCRIPT: &str = include_str!("../../../bench/mujoco_reference.py");
/// MuJoCo's settings in the script: its fastest sensible ones here.
pub const SETTINGS: &str = "pyramidal cone, Euler integrator, dt 1 ms";
/// Where `bench/mujoco.sh` puts its virtualenv's Python by default.
pub const VENV_PYTHON: &str = "target/mujoco-venv/bin/python";
/// The Python `--mujoco` runs without that virtualenv: the system's.
pub const SYSTEM_PYTHON: &str = "python3";

/// What to install, said by every error that a missing MuJoCo causes.
const INSTALL: &str = "--mujoco needs Python 3 with pip's mujoco: run bench/mujoco.sh (a \
                       virtualenv under target/ with mujoco), or `pip install mujoco` and pass \
                       that Python with --python";

/// Why MuJoCo's side could not run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MujocoError {
    /// The Python could not be started.
    #[error("cannot run {python}: {message}; {INSTALL}")]
    NoPython {
        /// The Python asked for.
        python: String,
        /// Why not.
        message: String,
    },
    /// The Python has no `mujoco` module.
    #[error("{python} cannot import mujoco; {INSTALL}")]
    NoMujoco {
        /// The Python asked for.
        python: String,
    },
    /// The script failed, or printed something else than its JSON.
    #[error("{python} bench/mujoco_reference.py failed: {message}")]
    Script {
        /// The Python asked for.
        python: String,
        /// Its error output, or what was wrong with its output.
        message: String,
    },
}

/// The script's answer.
#[derive(Debug, Clone, PartialEq, serde::Deserialize)]
pub struct MujocoRun {
    /// µs per `mj_step` (median of 100-step blocks).
    pub step_us: f64,
    /// Its settings ([`SETTINGS`]).
    pub settings: String,
    /// Steps timed.
    pub steps: usize,
    /// MuJoCo's version.
    pub mujoco: String,
    /// Held boxes still within 1 cm of where they began.
    pub boxes_held: usize,
    /// Held boxes in the scene.
    pub boxes: usize,
}

/// The Python `--mujoco` uses when none is given: `bench/mujoco.sh`'s
/// virtualenv if it is there (relative to the working directory), else
/// the system's.
pub fn default_python() -> PathBuf {
    let venv = Path::new(VENV_PYTHON);
    if venv.exists() { venv.to_path_buf() } else { PathBuf::from(SYSTEM_PYTHON) }
}

/// Checks that `python` runs and imports mujoco; returns MuJoCo's version.
pub fn check(python: &Path) -> Result<String, MujocoError> {
    #[derive(serde::Deserialize)]
    struct Version {
        mujoco: String,
    }
    let out = script(python, &["--check".to_string()])?;
    parse::<Version>(python, &out).map(|v| v.mujoco)
}

/// Times `steps` `mj_step`s (after a 200-step warm-up) of the reference
/// scene with `boxes` held boxes, with or without its tower.
pub fn run(
    python: &Path,
    steps: usize,
    boxes: usize,
    tower: bool,
) -> Result<MujocoRun, MujocoError> {
    let mut args = vec!["--steps".into(), steps.to_string(), "--boxes".into(), boxes.to_string()];
    if !tower {
        args.push("--no-tower".into());
    }
    let run: MujocoRun = parse(python, &script(python, &args)?)?;
    if !(run.step_us.is_finite() && run.step_us > 0.0) {
        let message = format!("µs per step must be a positive number, got {}", run.step_us);
        return Err(MujocoError::Script { python: python.display().to_string(), message });
    }
    Ok(run)
}

/// Runs the script with `args`; returns its standard output.
fn script(python: &Path, args: &[String]) -> Result<String, MujocoError> {
    let name = python.display().to_string();
    let out = Command::new(python)
        .arg("-c")
        .arg(SCRIPT)
        .args(args)
        .output()
        .map_err(|e| MujocoError::NoPython { python: name.clone(), message: e.to_string() })?;
    let stderr = String::from_utf8_lossy(&out.stderr);
    match out.status.code() {
        Some(0) => Ok(String::from_utf8_lossy(&out.stdout).into_owned()),
        Some(3) => Err(MujocoError::NoMujoco { python: name }),
        _ => {
            let message = stderr.trim().lines().last().unwrap_or("no message").to_string();
            Err(MujocoError::Script { python: name, message: format!("{}: {message}", out.status) })
        }
    }
}

/// The script's JSON line.
fn parse<T: serde::de::DeserializeOwned>(python: &Path, out: &str) -> Result<T, MujocoError> {
    serde_json::from_str(out.trim()).map_err(|e| MujocoError::Script {
        python: python.display().to_string(),
        message: format!("its output is not the expected JSON ({e}): {:?}", out.trim()),
    })
}
