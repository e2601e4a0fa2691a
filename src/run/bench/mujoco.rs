//! MuJoCo's side of the bench: `bench/mujoco_reference.py`, built into the
//! binary, run by a Python that has pip's `mujoco` (`bench/mujoco.sh` makes
//! a virtualenv with it under `target/`). It builds the reference scene in
//! MJCF (mocap capsule bones, dt 1 ms, [`SETTINGS`]) and, kept running
//! ([`Rival`]), times blocks of `mj_step`s on request, so that the bench
//! alternates them with its own: on a machine whose speed drifts, each of
//! our blocks is compared with the MuJoCo block run right after it.

use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, ChildStdout, Command, Stdio};

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

/// MuJoCo stepping the reference scene in a Python kept running
/// (`--serve`), timing blocks of steps when asked. Between blocks it waits,
/// so it takes no time from ours. Ended (killed) when dropped.
pub struct Rival {
    python: String,
    child: Child,
    /// Its standard input, closed (`None`) when it is being ended, so that
    /// a wrapper's own child sees the end of its input too.
    input: Option<ChildStdin>,
    output: BufReader<ChildStdout>,
    /// Its error output, read as it comes (a full pipe would stall it): the
    /// last line.
    errors: Option<std::thread::JoinHandle<String>>,
    /// MuJoCo's settings ([`SETTINGS`]).
    pub settings: String,
}

/// The script's first line in `--serve` mode, after its warm-up.
#[derive(serde::Deserialize)]
struct Ready {
    settings: String,
}

/// The script's answer to a block.
#[derive(serde::Deserialize)]
struct Block {
    step_us: f64,
}

impl Rival {
    /// Starts the script on the reference scene with `boxes` held boxes,
    /// with or without its tower, and waits for its 200-step warm-up.
    pub fn start(python: &Path, boxes: usize, tower: bool) -> Result<Rival, MujocoError> {
        let name = python.display().to_string();
        let mut command = Command::new(python);
        command.arg("-c").arg(SCRIPT).args(["--serve", "--boxes", &boxes.to_string()]);
        if !tower {
            command.arg("--no-tower");
        }
        let mut child = command
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| MujocoError::NoPython { python: name.clone(), message: e.to_string() })?;
        let pipes = (child.stdin.take(), child.stdout.take(), child.stderr.take());
        let (Some(input), Some(output), Some(errors)) = pipes else {
            let message = "its standard streams are not pipes".to_string();
            return Err(MujocoError::Script { python: name, message });
        };
        let mut rival = Rival {
            python: name,
            child,
            input: Some(input),
            output: BufReader::new(output),
            errors: Some(std::thread::spawn(move || last_line(errors))),
            settings: String::new(),
        };
        rival.settings = rival.answer::<Ready>()?.settings;
        Ok(rival)
    }

    /// Times `steps` more `mj_step`s: µs per step.
    pub fn time(&mut self, steps: usize) -> Result<f64, MujocoError> {
        // Writing to a script that has ended would raise SIGPIPE, whose
        // default (restored by the CLI) ends this process without a word.
        if !matches!(self.child.try_wait(), Ok(None)) {
            return Err(self.failed("it ended"));
        }
        let asked = match self.input.as_mut() {
            Some(input) => writeln!(input, "{steps}").and_then(|()| input.flush()),
            None => Err(std::io::ErrorKind::BrokenPipe.into()),
        };
        if let Err(e) = asked {
            return Err(self.failed(&format!("cannot ask for a block: {e}")));
        }
        let step_us = self.answer::<Block>()?.step_us;
        if !(step_us.is_finite() && step_us > 0.0) {
            let message = format!("µs per step must be a positive number, got {step_us}");
            return Err(MujocoError::Script { python: self.python.clone(), message });
        }
        Ok(step_us)
    }

    /// The script's next JSON line.
    fn answer<T: serde::de::DeserializeOwned>(&mut self) -> Result<T, MujocoError> {
        let mut line = String::new();
        match self.output.read_line(&mut line) {
            Ok(0) => Err(self.failed("it ended")),
            Ok(_) => parse(Path::new(&self.python), &line),
            Err(e) => Err(self.failed(&format!("cannot read its answer: {e}"))),
        }
    }

    /// Ends the script: its input closed, then killed; how it ended.
    fn end(&mut self) -> Option<std::process::ExitStatus> {
        self.input = None;
        self.child.kill().ok();
        self.child.wait().ok()
    }

    /// The error of a script that stopped answering while doing `what`.
    fn failed(&mut self, what: &str) -> MujocoError {
        let status = self.end();
        // Its error output ends with it (or with a wrapper's child, which
        // ends at the end of its input).
        let last = self.errors.take().and_then(|e| e.join().ok()).unwrap_or_default();
        ended(self.python.clone(), status, Some(what), &last)
    }
}

/// The error of a script that ended with `status`: no mujoco module (exit
/// code 3), or else how it ended, after `what` it was doing if said, and
/// `last`, the last line of its error output.
fn ended(
    python: String,
    status: Option<std::process::ExitStatus>,
    what: Option<&str>,
    last: &str,
) -> MujocoError {
    if status.and_then(|s| s.code()) == Some(3) {
        return MujocoError::NoMujoco { python };
    }
    let last = if last.is_empty() { "no message" } else { last };
    let status = status.map_or("not waited for".to_string(), |s| s.to_string());
    let message = match what {
        Some(what) => format!("{what} ({status}): {last}"),
        None => format!("{status}: {last}"),
    };
    MujocoError::Script { python, message }
}

impl Drop for Rival {
    fn drop(&mut self) {
        self.end();
    }
}

/// The last line of `stream` that is not blank, read to its end.
fn last_line(stream: impl Read) -> String {
    let lines = BufReader::new(stream).lines().map_while(Result::ok);
    lines.filter(|l| !l.trim().is_empty()).last().map(|l| l.trim().to_string()).unwrap_or_default()
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
    match out.status.code() {
        Some(0) => Ok(String::from_utf8_lossy(&out.stdout).into_owned()),
        _ => Err(ended(name, Some(out.status), None, &last_line(&out.stderr[..]))),
    }
}

/// The script's JSON line.
fn parse<T: serde::de::DeserializeOwned>(python: &Path, out: &str) -> Result<T, MujocoError> {
    serde_json::from_str(out.trim()).map_err(|e| MujocoError::Script {
        python: python.display().to_string(),
        message: format!("its output is not the expected JSON ({e}): {:?}", out.trim()),
    })
}
