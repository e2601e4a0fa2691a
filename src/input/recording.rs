//! Any supported recording, by its content: a joint recording
//! ([`super::joints`], JSON lines with its header, or any `.jsonl` file)
//! or a Leap Motion recording ([`super::leap`], `.json.lz` or `.json`).
//! `replay FILE` and a scenario hand's `recording` both load through here.

use super::convert::Conversion;
use super::playback::Playback;
use super::{InputError, TrackingFrame, joints, leap};
use glam::Vec3;
use std::path::Path;

/// Which format a recording was in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Format {
    /// Leap Motion, with its `metadata.formatVersion` (0.1, 1 or 2):
    /// millimetres, the desktop device's axes.
    Leap(f64),
    /// A joint recording of this version: metres, y up.
    Joints(u64),
}

impl std::fmt::Display for Format {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Format::Leap(version) => write!(f, "{version}"),
            Format::Joints(version) => write!(f, "{} {version}", joints::FORMAT),
        }
    }
}

/// A decoded recording of any format.
#[derive(Debug, Clone, PartialEq)]
pub struct Recording {
    /// The file it came from, for messages.
    pub source_name: String,
    /// Its format.
    pub format: Format,
    /// Frames in file order, in the format's units and axes.
    pub frames: Vec<TrackingFrame>,
}

impl Recording {
    /// The map into the world for a recording whose origin (a desktop
    /// device, or a joint recording's origin) sits at `device` (m).
    pub fn conversion(&self, device: Vec3) -> Conversion {
        match self.format {
            Format::Leap(_) => Conversion::leap_desktop(device),
            Format::Joints(_) => Conversion::translation(device),
        }
    }

    /// The recording played back in the world, its origin at `device` (m),
    /// gaps up to `grace` (s) bridged.
    pub fn playback(&self, device: Vec3, grace: f64) -> Result<Playback, InputError> {
        Playback::new(&self.source_name, &self.frames, &self.conversion(device), grace)
    }
}

/// Reads a recording of any supported format from disk.
pub fn load(path: &Path) -> Result<Recording, InputError> {
    let (name, text) = super::read_text(path)?;
    let jsonl = path.extension().is_some_and(|e| e == "jsonl");
    parse(&name, &text, jsonl)
}

/// Decodes a recording's text: a joint recording if it starts with that
/// header or `jsonl` says so (a `.jsonl` file), else a Leap recording.
pub fn parse(source: &str, text: &str, jsonl: bool) -> Result<Recording, InputError> {
    if jsonl || joints::is_joints(text) {
        let frames = joints::parse(source, text)?;
        Ok(Recording {
            source_name: source.into(),
            format: Format::Joints(joints::VERSION),
            frames,
        })
    } else {
        let leap = leap::parse(source, text)?;
        let format = Format::Leap(leap.format_version);
        Ok(Recording { source_name: leap.source_name, format, frames: leap.frames })
    }
}
