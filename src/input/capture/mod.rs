//! Hand–object captures: a real hand and the object it moved, frame by
//! frame, read into the world's frame (metres, y up).
//!
//! One JSON format, documented in the book's `captures.md`; TACO's export in
//! `data/taco/` is one instance of it:
//!
//! ```json
//! { "frame_rate_hz": 30, "units": "metres", "up": "+z",
//!   "hand": { "side": "right", "vertices": [[[x, y, z], …778], …] },
//!   "object": { "mesh": "object.obj", "poses": [[16 numbers, row-major 4×4], …] } }
//! ```
//!
//! The hand is either `vertices`, 778 points on its surface in MANO's
//! topology (TACO, ARCTIC, OakInk, GRAB, DexYCB and HO-3D's MANO fits), or
//! `keypoints`, 21 joints in MediaPipe's order (DexYCB's and HO-3D's
//! published joints). Surface points become keypoints and finger widths
//! through [`rings`]. The mesh is in the object's own frame and the
//! capture's units; its path is relative to the capture file.

pub mod fit;
pub mod rings;

use super::convert::Conversion;
use super::layouts::from_mediapipe;
use super::playback::Playback;
use super::{InputError, TrackingFrame};
use crate::hand::Side;
use crate::scene::mesh::TriangleMesh;
use glam::{Mat3, Quat, Vec3};
use std::path::Path;

/// A capture read into the world: metres, y up.
#[derive(Debug, Clone)]
pub struct Capture {
    /// The file it came from, for messages.
    pub source_name: String,
    /// Frames a second.
    pub frame_rate_hz: f64,
    /// Which hand, as the capture labels it.
    pub side: Side,
    /// The skeletal hand fitted to it (world, m): its keypoints per frame,
    /// finger widths measured from surface points ([`rings::widths`]) or the
    /// library's defaults for keypoints, its palm's depth, and the side its
    /// shape has, which may differ from `side` in a mirrored frame.
    pub hand: fit::HandFit,
    /// Whether the hand came as surface points (else as keypoints).
    pub from_surface: bool,
    /// The mesh file's name, as the capture gives it.
    pub mesh_file: String,
    /// The object's mesh in its own frame, scaled to metres.
    pub mesh: TriangleMesh,
    /// The object's pose per frame (world, m).
    pub poses: Vec<(Vec3, Quat)>,
    /// The capture's frame as the world sees it: `world = rotation · (scale · capture)`.
    pub frame: CaptureFrame,
}

/// How a capture's frame and units map into the world's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CaptureFrame {
    /// Turns the capture's up axis onto the world's +y.
    pub rotation: Quat,
    /// Metres per capture unit.
    pub scale: f32,
}

impl CaptureFrame {
    /// A capture-frame point into the world (m).
    pub fn point(&self, p: Vec3) -> Vec3 {
        self.rotation * (p * self.scale)
    }

    /// A world pose back into the capture's frame and units: position and
    /// rotation (world-from-object, as the capture's poses are).
    pub fn pose_back(&self, position: Vec3, rotation: Quat) -> (Vec3, Quat) {
        (self.point_back(position), (self.rotation.inverse() * rotation).normalize())
    }

    /// A world point back into the capture's frame and units.
    pub fn point_back(&self, point: Vec3) -> Vec3 {
        self.rotation.inverse() * point / self.scale
    }
}

/// How the capture file spells what it holds; other fields (TACO's
/// `source`, `points`, `pose_convention`) are notes for people.
#[derive(serde::Deserialize)]
struct RawCapture {
    frame_rate_hz: f64,
    units: String,
    up: String,
    hand: RawHand,
    object: RawObject,
}

#[derive(serde::Deserialize)]
struct RawHand {
    side: String,
    #[serde(default)]
    vertices: Option<Vec<Vec<Vec<f64>>>>,
    #[serde(default)]
    keypoints: Option<Vec<Vec<Vec<f64>>>>,
}

#[derive(serde::Deserialize)]
struct RawObject {
    mesh: String,
    poses: Vec<Vec<f64>>,
}

/// The capture at `path`, read once, if it looks like one: a `.json` file
/// whose text has a `"frame_rate_hz"`, a `"hand"` and an `"object"` (a
/// Leap recording has none of them; a scenario or a session no frame
/// rate). `None` for any other file, or one that cannot be read, for its
/// own loader to report.
pub fn load_if_capture(path: &Path) -> Option<Result<Capture, InputError>> {
    if !path.extension().is_some_and(|e| e.eq_ignore_ascii_case("json")) {
        return None;
    }
    let bytes = std::fs::read(path).ok()?;
    let has = |key: &[u8]| bytes.windows(key.len()).any(|w| w == key);
    if !(has(b"\"frame_rate_hz\"") && has(b"\"object\"") && has(b"\"hand\"")) {
        return None;
    }
    let name = path.display().to_string();
    let text = super::text_of(&name, bytes);
    Some(text.and_then(|text| parse_at(path, &name, &text, &crate::files::FileSystem)))
}

/// Reads a capture file and its mesh (beside it).
pub fn load(path: &Path) -> Result<Capture, InputError> {
    load_from(path, &crate::files::FileSystem)
}

/// [`load`], the capture and its mesh read from `files`, as a recording
/// and a scene's meshes are.
pub fn load_from(path: &Path, files: &dyn crate::files::Files) -> Result<Capture, InputError> {
    let (name, text) = super::read_text(path, files)?;
    parse_at(path, &name, &text, files)
}

/// [`parse`] of the text of the capture at `path`, its mesh read from
/// beside it through `files`.
fn parse_at(
    path: &Path,
    name: &str,
    text: &str,
    files: &dyn crate::files::Files,
) -> Result<Capture, InputError> {
    let dir = path.parent().unwrap_or(Path::new("."));
    let mesh =
        |file: &str| TriangleMesh::load_from(&dir.join(file), files).map_err(|e| e.to_string());
    parse(name, text, &mesh)
}

/// Parses a capture's text; `mesh` reads the mesh file it names.
pub fn parse(
    name: &str,
    text: &str,
    mesh: &dyn Fn(&str) -> Result<TriangleMesh, String>,
) -> Result<Capture, InputError> {
    if text.trim().is_empty() {
        return Err(fail(name, None, "file", "empty"));
    }
    let raw: RawCapture = serde_json::from_str(text).map_err(|e| fail(name, None, "file", e))?;
    let rate = raw.frame_rate_hz;
    if !(rate.is_finite() && rate > 0.0 && rate <= 100_000.0) {
        return Err(fail(name, None, "frame_rate_hz", format!("{rate} is not in (0, 100000]")));
    }
    let scale = units(&raw.units).ok_or_else(|| {
        let why = format!("{:?}: expected metres, centimetres or millimetres", raw.units);
        fail(name, None, "units", why)
    })?;
    let up = up_axis(&raw.up).ok_or_else(|| {
        let why = format!("{:?}: expected an axis, +x, -x, +y, -y, +z or -z", raw.up);
        fail(name, None, "up", why)
    })?;
    let frame = CaptureFrame { rotation: Quat::from_rotation_arc(up, Vec3::Y), scale };
    let side: Side =
        raw.hand.side.parse().map_err(|e| fail(name, None, "hand.side", format!("{e}")))?;
    let (field, frames, count) = match (&raw.hand.vertices, &raw.hand.keypoints) {
        (Some(v), None) => ("hand.vertices", v, rings::POINTS),
        (None, Some(k)) => ("hand.keypoints", k, 21),
        _ => {
            let why = "give exactly one of vertices (778 surface points) or keypoints (21 joints)";
            return Err(fail(name, None, "hand", why));
        }
    };
    let n = raw.object.poses.len();
    if frames.len() != n {
        let why = format!("{} frames, but object.poses has {n}", frames.len());
        return Err(fail(name, None, field, why));
    }
    if n < 2 {
        return Err(fail(name, None, "object.poses", format!("{n} frames; a replay needs 2")));
    }
    let points = frames
        .iter()
        .enumerate()
        .map(|(i, f)| points_of(name, i, field, f, count, &frame))
        .collect::<Result<Vec<_>, _>>()?;
    let poses = raw
        .object
        .poses
        .iter()
        .enumerate()
        .map(|(i, p)| pose_of(p, &frame).map_err(|why| fail(name, Some(i), "object.poses", why)))
        .collect::<Result<Vec<_>, _>>()?;
    let from_surface = count == rings::POINTS;
    let hand = if from_surface {
        fit::from_surface(side, &points)
    } else {
        fit::from_keypoints(side, points.iter().map(|p| std::array::from_fn(|j| p[j])).collect())
    }
    .map_err(|(i, e)| fail(name, Some(i), field, format!("the points make no hand: {e}")))?;
    let mut mesh = mesh(&raw.object.mesh).map_err(|why| fail(name, None, "object.mesh", why))?;
    mesh.vertices.iter_mut().for_each(|v| *v *= scale);
    Ok(Capture {
        source_name: name.to_string(),
        frame_rate_hz: rate,
        side,
        hand,
        from_surface,
        mesh_file: raw.object.mesh,
        mesh,
        poses,
        frame,
    })
}

/// A captured object's pose at time `t` (s) from its `poses` at
/// `frame_rate_hz`: between the two frames about `t`, the position
/// interpolated linearly and the rotation by slerp; the first pose before
/// the start (and for a time that is not a number), the last after the
/// end, where the capture holds it. What a viewer draws as the captured
/// object; the replay itself never reads it.
pub fn pose_at(poses: &[(Vec3, Quat)], frame_rate_hz: f64, t: f64) -> (Vec3, Quat) {
    // `max` takes the number: NaN and negative times are frame 0.
    let at = (t * frame_rate_hz).max(0.0);
    let i = at.floor() as usize;
    match (poses.get(i), poses.get(i + 1)) {
        (Some(a), Some(b)) if at > i as f64 => {
            let s = (at - i as f64) as f32;
            (a.0.lerp(b.0, s), a.1.slerp(b.1, s).normalize())
        }
        (Some(a), Some(_)) => *a,
        _ => poses.last().copied().unwrap_or_default(),
    }
}

impl Capture {
    /// The time of frame `i` (s).
    pub fn time(&self, i: usize) -> f64 {
        i as f64 / self.frame_rate_hz
    }

    /// What a replay needs of a capture built in code rather than read:
    /// at least one frame, a hand for each of the object's poses, and a
    /// frame rate that is a number above zero.
    pub fn check(&self) -> Result<(), InputError> {
        let name = &self.source_name;
        if !(self.frame_rate_hz.is_finite() && self.frame_rate_hz > 0.0) {
            let why = format!("must be above 0, got {}", self.frame_rate_hz);
            return Err(fail(name, None, "frame_rate_hz", why));
        }
        if self.poses.is_empty() {
            return Err(fail(name, None, "object.poses", "a capture needs at least one frame"));
        }
        if self.poses.len() != self.hand.keypoints.len() {
            let why = format!(
                "{} poses of the object for {} frames of the hand",
                self.poses.len(),
                self.hand.keypoints.len()
            );
            return Err(fail(name, None, "object.poses", why));
        }
        Ok(())
    }

    /// The captured object's pose at time `t` (s) ([`pose_at`]).
    pub fn pose_at(&self, t: f64) -> (Vec3, Quat) {
        pose_at(&self.poses, self.frame_rate_hz, t)
    }

    /// The hand as a playback, one tracked hand per frame. Between frames
    /// the hand is interpolated as any recording is
    /// ([`super::playback::interpolate`]): each bone's ends linearly and the
    /// palm's turn by normalised lerp, which at 30 frames a second and a
    /// hand's 1-3 rad/s differs from a slerp by under 0.1 mm.
    pub fn playback(&self) -> Result<Playback, InputError> {
        let frames = self
            .hand
            .keypoints
            .iter()
            .enumerate()
            .map(|(i, keys)| {
                let fit = &self.hand;
                let mut hand = from_mediapipe(1, fit.shape, keys).map_err(|e| {
                    fail(&self.source_name, Some(i), "hand", format!("no hand: {e}"))
                })?;
                hand.widths = fit.widths;
                hand.palm_position += hand.palm_normal * fit.palm_depth;
                let timestamp_us = (self.time(i) * 1e6).round() as i64;
                Ok(TrackingFrame { timestamp_us, hands: vec![hand] })
            })
            .collect::<Result<Vec<_>, InputError>>()?;
        // Two frames' grace: a frame the playback leaves out as a glitch is
        // bridged, a longer loss is not.
        let grace = 2.0 / self.frame_rate_hz + 1e-9;
        Playback::new(&self.source_name, &frames, &Conversion::identity(), grace)
    }
}

/// Metres per unit.
fn units(name: &str) -> Option<f32> {
    match name.trim().to_ascii_lowercase().as_str() {
        "m" | "metres" | "meters" | "metre" | "meter" => Some(1.0),
        "cm" | "centimetres" | "centimeters" => Some(0.01),
        "mm" | "millimetres" | "millimeters" => Some(0.001),
        _ => None,
    }
}

/// The up axis, from text that starts with it (`"+z (the table is …)"`).
fn up_axis(text: &str) -> Option<Vec3> {
    let word = text.split_whitespace().next()?.to_ascii_lowercase();
    let (sign, axis) = match word.strip_prefix('-') {
        Some(axis) => (-1.0, axis),
        None => (1.0, word.strip_prefix('+').unwrap_or(&word)),
    };
    let unit = match axis {
        "x" => Vec3::X,
        "y" => Vec3::Y,
        "z" => Vec3::Z,
        _ => return None,
    };
    Some(unit * sign)
}

/// One frame's points, checked: `count` finite triples, into the world.
fn points_of(
    name: &str,
    i: usize,
    field: &str,
    frame_points: &[Vec<f64>],
    count: usize,
    frame: &CaptureFrame,
) -> Result<Vec<Vec3>, InputError> {
    if frame_points.len() != count {
        let why = format!("{} points, expected {count}", frame_points.len());
        return Err(fail(name, Some(i), field, why));
    }
    frame_points
        .iter()
        .enumerate()
        .map(|(j, p)| {
            let v = triple(p).ok_or_else(|| {
                fail(
                    name,
                    Some(i),
                    &format!("{field}[{j}]"),
                    format!("{p:?} is not 3 finite numbers"),
                )
            })?;
            Ok(frame.point(v))
        })
        .collect()
}

/// Three finite numbers that stay finite as `f32`.
fn triple(p: &[f64]) -> Option<Vec3> {
    let v = match p {
        [x, y, z] => Vec3::new(*x as f32, *y as f32, *z as f32),
        _ => return None,
    };
    v.is_finite().then_some(v)
}

/// A row-major 4×4 world-from-object transform into a world pose; its
/// rotation must be a rotation (orthonormal to 1e-3, no mirror) and its
/// last row `0 0 0 1`.
fn pose_of(m: &[f64], frame: &CaptureFrame) -> Result<(Vec3, Quat), String> {
    if m.len() != 16 {
        return Err(format!("{} numbers, expected 16 (a row-major 4×4)", m.len()));
    }
    let f: Vec<f32> = m.iter().map(|&x| x as f32).collect();
    if f.iter().any(|x| !x.is_finite()) {
        return Err("a number is not finite".into());
    }
    let last = [f[12], f[13], f[14], f[15]];
    if last.iter().zip([0.0, 0.0, 0.0, 1.0]).any(|(a, b)| (a - b).abs() > 1e-6) {
        return Err(format!("last row {last:?}, expected [0, 0, 0, 1]"));
    }
    let r = Mat3::from_cols_array(&[f[0], f[4], f[8], f[1], f[5], f[9], f[2], f[6], f[10]]);
    let off = (r.transpose() * r - Mat3::IDENTITY).to_cols_array();
    if off.iter().any(|x| x.abs() > 1e-3) || r.determinant() < 0.0 {
        return Err("its 3×3 part is not a rotation".into());
    }
    let t = Vec3::new(f[3], f[7], f[11]);
    Ok((frame.point(t), (frame.rotation * Quat::from_mat3(&r)).normalize()))
}

/// An error in `name`, at `frame` when there is one, in `field`.
fn fail(name: &str, frame: Option<usize>, field: &str, why: impl ToString) -> InputError {
    InputError {
        source_name: name.to_string(),
        frame,
        field: field.to_string(),
        reason: why.to_string(),
    }
}
