//! Any supported recording, by its content: a joint recording
//! ([`super::joints`], JSON lines with its header, or any `.jsonl` file)
//! or a Leap Motion recording ([`super::leap`], `.json.lz` or `.json`).
//! `replay FILE` and a scenario hand's `recording` both load through here.

use super::convert::Conversion;
use super::playback::Playback;
use super::{InputError, TrackingFrame, joints, leap};
use crate::files::{FileSystem, Files};
use glam::{Quat, Vec3};
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

    /// The map into the world for a Leap Motion worn on a head (§3.8.1):
    /// desktop→HMD, mm→m, the mount's tilt (`R_x·R_y·R_z`, rad) and offset
    /// from the eyes (m), then the head's pose in the world. A joint
    /// recording is already in world coordinates, so it has no such map.
    pub fn head_mounted_conversion(
        &self,
        mount: Vec3,
        tilt: (f32, f32, f32),
        head: (Quat, Vec3),
    ) -> Result<Conversion, InputError> {
        match self.format {
            Format::Leap(_) => Ok(Conversion::leap_head_mounted(mount, tilt, head)),
            Format::Joints(_) => Err(InputError {
                source_name: self.source_name.clone(),
                frame: None,
                field: "format".into(),
                reason: "a joint recording is in world coordinates already; only a Leap \
                         Motion recording can be head-mounted"
                    .into(),
            }),
        }
    }

    /// The recording played back in the world, its origin at `device` (m),
    /// gaps up to `grace` (s) bridged.
    pub fn playback(&self, device: Vec3, grace: f64) -> Result<Playback, InputError> {
        self.playback_through(&self.conversion(device), grace)
    }

    /// The recording played back through `conversion`, gaps up to `grace`
    /// (s) bridged.
    pub fn playback_through(
        &self,
        conversion: &Conversion,
        grace: f64,
    ) -> Result<Playback, InputError> {
        Playback::new(&self.source_name, &self.frames, conversion, grace)
    }
}

/// Reads a recording of any supported format from disk.
pub fn load(path: &Path) -> Result<Recording, InputError> {
    load_from(path, &FileSystem)
}

/// [`load`], the file read from `files`.
pub fn load_from(path: &Path, files: &dyn Files) -> Result<Recording, InputError> {
    let (name, text) = super::read_text(path, files)?;
    parse(&name, &text, is_jsonl(path))
}

/// A recording file's bytes, as [`load`] reads them: `name` (the file's
/// name) says by its extension whether it is JSON Lines, and names it in
/// errors.
pub fn from_bytes(name: &str, bytes: Vec<u8>) -> Result<Recording, InputError> {
    parse(name, &super::text_of(name, bytes)?, is_jsonl(Path::new(name)))
}

/// Whether the file's extension says it is JSON Lines (a joint recording).
fn is_jsonl(path: &Path) -> bool {
    path.extension().is_some_and(|e| e == "jsonl")
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

#[cfg(test)]
mod tests {
    use super::*;

    /// One Leap frame (format 1, mm) of a right hand in the device's frame.
    fn leap_text(palm: [f32; 3], normal: [f32; 3], direction: [f32; 3]) -> String {
        let p = Vec3::from(palm);
        let (d, across) = (Vec3::from(direction), Vec3::from(normal).cross(direction.into()));
        let pointable = |f: i32| {
            let base = p + across * (20.0 * f as f32 - 40.0) + d * 40.0;
            let at = |along: f32| (base + d * along).to_array();
            serde_json::json!({"handId": 1, "id": 10 + f, "type": f, "width": 18.0,
                "mcpPosition": at(0.0), "pipPosition": at(40.0),
                "dipPosition": at(65.0), "tipPosition": at(85.0)})
        };
        let hand = serde_json::json!({"id": 1, "type": "right", "palmPosition": palm,
            "palmNormal": normal, "direction": direction});
        let frame = serde_json::json!({"timestamp": 0, "hands": [hand],
            "pointables": (0..5).map(pointable).collect::<Vec<_>>()});
        serde_json::json!({"metadata": {"formatVersion": 1}, "frames": [frame]}).to_string()
    }

    #[test]
    fn a_head_mounted_leap_puts_the_hand_in_front_of_the_eyes() {
        // Worn, the device looks forward: a hand 300 mm out along its +y, fingers
        // pointing further out, palm towards the device's +z (the wearer's down).
        let text = leap_text([0.0, 300.0, 100.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]);
        let recording = parse("worn.json", &text, false).expect("a Leap recording");
        // A DK2 on a head at (0.5, 1.2, -1) facing the world's -z.
        let head = (Quat::IDENTITY, Vec3::new(0.5, 1.2, -1.0));
        let mount = super::super::convert::MountPreset::OculusDk2.translation();
        let conversion = recording.head_mounted_conversion(mount, (0.0, 0.0, 0.0), head);
        let playback = recording.playback_through(&conversion.expect("Leap"), 0.1).expect("ok");
        let pose = playback.sample(0, 0.0).expect("the hand").pose;
        // 300 mm out of the device plus the device's 80 mm ahead of the eyes, 100 mm
        // below them: forward is -z in this world. The palm box's centre is half its
        // 18 mm thickness behind the palm's face.
        let palm = pose.palm.center;
        assert!((palm - Vec3::new(0.5, 1.109, -1.38)).length() < 1e-4, "{palm}");
        // Fingers point away from the wearer, the palm faces down.
        let tip = pose.fingers[2][2].b;
        assert!(tip.z < palm.z - 0.08, "fingertip {tip} ahead of the palm {palm}");
        assert!((pose.palm.normal() - Vec3::NEG_Y).length() < 1e-3);
    }

    #[test]
    fn a_recording_s_bytes_read_as_its_file_does() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        for file in ["data/joints/pinch-57fps.jsonl", "data/leap/pinch.json.lz"] {
            let path = root.join(file);
            let name = path.display().to_string();
            let bytes = std::fs::read(&path).unwrap();
            assert_eq!(from_bytes(&name, bytes).unwrap(), load(&path).unwrap(), "{file}");
        }
        let e = from_bytes("x.json", vec![0xff]).unwrap_err().to_string();
        assert_eq!(e, "x.json: file: not UTF-8 text");
    }

    #[test]
    fn a_joint_recording_cannot_be_head_mounted() {
        let recording = Recording {
            source_name: "hands.jsonl".into(),
            format: Format::Joints(joints::VERSION),
            frames: Vec::new(),
        };
        let e = recording
            .head_mounted_conversion(Vec3::ZERO, (0.0, 0.0, 0.0), (Quat::IDENTITY, Vec3::ZERO))
            .expect_err("joints are in the world already");
        assert!(e.to_string().starts_with("hands.jsonl: format: a joint recording"), "{e}");
    }
}
