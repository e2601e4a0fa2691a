//! Every error the library and the CLI return, triggered as a user would,
//! with its message checked to name what is wrong: the file, the field or
//! JSON path, the frame, the bad value. One module per area.

mod bench;
mod capture;
mod cli;
mod input;
mod joints;
#[cfg(feature = "live")]
mod live;
mod mesh;
mod report;
mod scenario;
mod scene;
mod session;
mod world;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Asserts that `message` names every one of `parts`.
#[track_caller]
pub fn names(message: impl std::fmt::Display, parts: &[&str]) {
    let message = message.to_string();
    let missing: Vec<&&str> = parts.iter().filter(|p| !message.contains(**p)).collect();
    assert!(missing.is_empty(), "the message\n  {message}\ndoes not name {missing:?}");
}

/// A fresh directory under the system temp dir, removed when dropped.
pub struct Scratch(PathBuf);

impl Scratch {
    /// A new directory, named after the test and unique in this run.
    pub fn new(test: &str) -> Scratch {
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let name = format!("coulomb-hands-errors-{}-{n}-{test}", std::process::id());
        let dir = std::env::temp_dir().join(name);
        std::fs::create_dir_all(&dir).expect("a temp dir");
        Scratch(dir)
    }

    /// The path of `name` in the directory.
    pub fn path(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }

    /// Writes `name` and returns its path.
    pub fn file(&self, name: &str, contents: impl AsRef<[u8]>) -> PathBuf {
        let path = self.path(name);
        std::fs::write(&path, contents).expect("a temp file");
        path
    }

    /// The path as text, for command lines and messages.
    pub fn text(&self, name: &str) -> String {
        self.path(name).display().to_string()
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        std::fs::remove_dir_all(&self.0).ok();
    }
}

/// A file of the repository.
pub fn repo(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(path)
}

/// Runs the binary; returns (exit code, stdout, stderr).
pub fn run(args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_coulomb-hands"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs");
    let text = |b: Vec<u8>| String::from_utf8(b).expect("UTF-8 output");
    (out.status.code(), text(out.stdout), text(out.stderr))
}

/// Runs the binary, which must fail with exit code 1 and one `error:`
/// line (no panic); returns that line's message.
#[track_caller]
pub fn cli_error(args: &[&str]) -> String {
    let (code, _, stderr) = run(args);
    assert_eq!(code, Some(1), "{args:?} should fail with exit code 1: {stderr}");
    assert!(!stderr.contains("panicked"), "{args:?} panicked: {stderr}");
    let message = stderr.strip_prefix("error: ").unwrap_or_else(|| panic!("{stderr}"));
    message.trim_end().to_string()
}

/// Runs the binary, whose arguments clap must reject (exit code 2);
/// returns its message.
#[track_caller]
pub fn usage_error(args: &[&str]) -> String {
    let (code, _, stderr) = run(args);
    assert_eq!(code, Some(2), "{args:?} should be a usage error: {stderr}");
    stderr
}

/// A Leap recording (format 1) of these frames, as JSON text.
pub fn recording(frames: &[serde_json::Value]) -> String {
    serde_json::json!({"metadata": {"formatVersion": 1}, "frames": frames}).to_string()
}

/// A frame at `timestamp` (µs) with these hands (each a hand object and
/// its five pointables).
pub fn frame(
    timestamp: i64,
    hands: &[(serde_json::Value, Vec<serde_json::Value>)],
) -> serde_json::Value {
    let pointables: Vec<_> = hands.iter().flat_map(|h| h.1.clone()).collect();
    let hands: Vec<_> = hands.iter().map(|h| h.0.clone()).collect();
    serde_json::json!({"timestamp": timestamp, "hands": hands, "pointables": pointables})
}

/// A flat right hand 20 cm above the device, palm down, as Leap reports
/// it (mm): its hand object and five pointables.
pub fn leap_hand(id: i64) -> (serde_json::Value, Vec<serde_json::Value>) {
    let hand = serde_json::json!({
        "id": id, "type": "right",
        "palmPosition": [0.0, 200.0, 0.0], "palmNormal": [0.0, -1.0, 0.0],
        "direction": [0.0, 0.0, -1.0]
    });
    let pointable = |f: i64| {
        let x = 20.0 * f as f64 - 40.0;
        serde_json::json!({
            "handId": id, "id": 10 * id + f, "type": f, "width": 18.0,
            "mcpPosition": [x, 200.0, -40.0], "pipPosition": [x, 200.0, -80.0],
            "dipPosition": [x, 200.0, -105.0], "tipPosition": [x, 200.0, -125.0]
        })
    };
    (hand, (0..5).map(pointable).collect())
}
