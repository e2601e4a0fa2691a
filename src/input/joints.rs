//! Joint recordings: a JSON-lines format any hand tracker can write, one
//! frame per line, each hand as joint positions in one of the layouts of
//! [`super::layouts`].
//!
//! The first line is a header, then one line per frame:
//!
//! ```text
//! {"format": "coulomb-hands-joints", "version": 1}
//! {"t": 0.0, "hands": [{"side": "right", "layout": "openxr",
//!   "joints": [[0.01, 0.2, -0.03], ...], "radii": [...], "orientations": [...]}]}
//! ```
//!
//! (a frame is one line in the file; it is wrapped here to fit.)
//!
//! * `t`: the frame's time in seconds (≥ 0, increasing; a stale frame is
//!   left out by playback, as for any tracker).
//! * `hands`: zero or more hands. Each has
//!   * `side`: `"left"` or `"right"`, the subject's own hand (MediaPipe
//!     labels may be mirrored: [`super::mediapipe::Label`]);
//!   * `layout`: `"openxr"` (`XR_EXT_hand_tracking`, 26 joints in
//!     `XrHandJointEXT` order, palm first), `"webxr"` (WebXR Hand Input, 25
//!     in `XRHandJoint` order, wrist first) or `"mediapipe"` (MediaPipe
//!     Hands, 21 landmarks, wrist first);
//!   * `joints`: every joint's position `[x, y, z]` in metres, in the
//!     layout's order. A joint given as `null`, or a short list, is a
//!     missing joint and an error;
//!   * `radii` (optional, OpenXR and WebXR): each joint's radius in metres;
//!     without them, an average adult's finger widths
//!     ([`super::leap::DEFAULT_WIDTHS_MM`]);
//!   * `orientations` (optional, OpenXR and WebXR): each joint's unit
//!     quaternion `[x, y, z, w]` (−z along the bone, +y out of the back of
//!     the hand). Only OpenXR's palm joint is used, for the palm's normal
//!     and direction; without it they come from the wrist and knuckles, as
//!     for WebXR and MediaPipe;
//!   * `id` (optional): the tracker's id for the hand, stable while it is
//!     tracked (default 0 for the left hand, 1 for the right);
//!   * `grab`, `pinch` (optional): the tracker's strengths in \[0, 1\];
//!   * `confidence` (optional): the tracker's confidence in the hand's
//!     pose, in \[0, 1\] (a Leap Motion's per-hand `confidence`).
//!
//! **Frame.** Positions are metres in a right-handed frame with y up (the
//! world's, rapier's): OpenXR and WebXR poses in their reference space are
//! already so. MediaPipe's world landmarks have y down (image axes): rotate
//! them 180° about x (negate y and z, [`super::layouts::mediapipe_to_y_up`])
//! before writing. A replay puts the recording's origin at `--device`
//! (a scenario hand's `offset`) in the world: a translation, nothing else.
//!
//! Errors name the file, the frame (its index among the frame lines, and
//! the line) and the field, e.g. `hands[0].joints[7][1]`. Numbers must be
//! finite (`NaN` and `Infinity`, as some JSON writers emit them, are named
//! as such) and coordinates within 10 m of the origin.

use super::convert::Conversion;
use super::layouts::{self, Layout, LayoutError};
use super::{InputError, TrackedHand, TrackingFrame};
use crate::hand::Side;
use glam::{Quat, Vec3};
use serde_json::{Map, Value, json};

/// The header's `format`.
pub const FORMAT: &str = "coulomb-hands-joints";

/// The header's `version`: the one this crate reads and writes.
pub const VERSION: u64 = 1;

/// Coordinates beyond this (m) are rejected as absurd.
pub const MAX_COORDINATE_M: f64 = 10.0;

/// The header line.
pub fn header() -> String {
    json!({"format": FORMAT, "version": VERSION}).to_string()
}

/// Whether `text` starts with a joint recording's header line.
pub fn is_joints(text: &str) -> bool {
    let first = text.lines().find(|l| !l.trim().is_empty()).unwrap_or("");
    serde_json::from_str::<Value>(first).is_ok_and(|v| v.get("format") == Some(&json!(FORMAT)))
}

/// One line of the file being read: the frame's index and its line.
struct Place<'a> {
    source: &'a str,
    frame: Option<usize>,
    line: usize,
}

impl Place<'_> {
    fn err(&self, field: impl Into<String>, reason: impl std::fmt::Display) -> InputError {
        InputError {
            source_name: self.source.to_string(),
            frame: self.frame,
            field: field.into(),
            reason: format!("{reason} (line {})", self.line),
        }
    }

    fn number(&self, path: &str, v: &Value, limit: f64) -> Result<f64, InputError> {
        let x = match v {
            Value::Number(n) => n.as_f64(),
            // Non-JSON tokens (NaN, Infinity), quoted by `quote_non_finite`.
            Value::String(s) if NON_FINITE.contains(&s.as_str()) => {
                return Err(self.err(path, format!("not a finite number: {s}")));
            }
            _ => None,
        };
        let x = x.ok_or_else(|| self.err(path, format!("not a number: {v}")))?;
        if x.abs() > limit {
            return Err(self.err(path, format!("absurd value {x} (at most {limit} in size)")));
        }
        Ok(x)
    }

    fn array<'v>(&self, path: &str, v: &'v Value, n: usize) -> Result<&'v [Value], InputError> {
        match v.as_array() {
            Some(a) if a.len() == n => Ok(a),
            _ => Err(self.err(path, format!("expected a list of {n} numbers, got {v}"))),
        }
    }

    fn vec3(&self, path: &str, v: &Value) -> Result<Vec3, InputError> {
        let a = self.array(path, v, 3)?;
        let c = |i: usize| self.number(&format!("{path}[{i}]"), &a[i], MAX_COORDINATE_M);
        Ok(Vec3::new(c(0)? as f32, c(1)? as f32, c(2)? as f32))
    }
}

const NON_FINITE: [&str; 3] = ["NaN", "Infinity", "-Infinity"];

/// Quotes the bare tokens `NaN`, `Infinity` and `-Infinity` outside
/// strings, which are not JSON, so the line parses and the field holding
/// one can be named.
fn quote_non_finite(line: &str) -> String {
    let mut out = String::with_capacity(line.len());
    let (mut in_string, mut escaped) = (false, false);
    let mut rest = line;
    while let Some(c) = rest.chars().next() {
        if !in_string && let Some(token) = NON_FINITE.iter().rev().find(|t| rest.starts_with(**t)) {
            out.push('"');
            out.push_str(token);
            out.push('"');
            rest = &rest[token.len()..];
            continue;
        }
        match (in_string, escaped, c) {
            (true, true, _) => escaped = false,
            (true, false, '\\') => escaped = true,
            (_, false, '"') => in_string = !in_string,
            _ => {}
        }
        out.push(c);
        rest = &rest[c.len_utf8()..];
    }
    out
}

/// Reads a joint recording's text (header line, then frame lines; blank
/// lines are passed over). `source` names it in errors.
pub fn parse(source: &str, text: &str) -> Result<Vec<TrackingFrame>, InputError> {
    let mut lines = text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty());
    let (h, first) = lines.next().unwrap_or((0, ""));
    let place = Place { source, frame: None, line: h + 1 };
    check_header(&place, first)?;
    let mut frames = Vec::new();
    for (i, line) in lines {
        let place = Place { source, frame: Some(frames.len()), line: i + 1 };
        let value: Value = serde_json::from_str(&quote_non_finite(line)).map_err(|e| {
            let message = e.to_string();
            let place_text = format!(" at line {} column {}", e.line(), e.column());
            let what = message.strip_suffix(&place_text).unwrap_or(&message);
            place.err("json", format!("invalid JSON at column {}: {what}", e.column()))
        })?;
        frames.push(frame(&place, &value)?);
    }
    if frames.is_empty() {
        return Err(Place { source, frame: None, line: h + 1 }
            .err("frames", "the recording has no frame lines after its header"));
    }
    Ok(frames)
}

fn check_header(place: &Place, line: &str) -> Result<(), InputError> {
    let expected = header();
    let v: Value = serde_json::from_str(line).unwrap_or(Value::Null);
    if v.get("format") != Some(&json!(FORMAT)) {
        return Err(place.err("format", format!("the first line must be the header {expected}")));
    }
    match v.get("version").and_then(Value::as_u64) {
        Some(VERSION) => Ok(()),
        _ => {
            let got = v.get("version").map_or("none".to_string(), Value::to_string);
            Err(place.err("version", format!("unknown version {got} (known: {VERSION})")))
        }
    }
}

fn object<'v>(
    place: &Place,
    path: &str,
    v: &'v Value,
) -> Result<&'v Map<String, Value>, InputError> {
    v.as_object().ok_or_else(|| place.err(path, format!("expected an object, got {v}")))
}

/// Fails on a key that is not in `known`.
fn known_keys(
    place: &Place,
    path: &str,
    o: &Map<String, Value>,
    known: &[&str],
) -> Result<(), InputError> {
    match o.keys().find(|k| !known.contains(&k.as_str())) {
        None => Ok(()),
        Some(k) => {
            let at = if path.is_empty() { k.clone() } else { format!("{path}.{k}") };
            Err(place.err(at, format!("unknown field (known: {})", known.join(", "))))
        }
    }
}

fn frame(place: &Place, v: &Value) -> Result<TrackingFrame, InputError> {
    let o = object(place, "frame", v)?;
    known_keys(place, "", o, &["t", "hands"])?;
    let t = o.get("t").ok_or_else(|| place.err("t", "missing"))?;
    let t = place.number("t", t, super::playback::MAX_DURATION)?;
    if t < 0.0 {
        return Err(place.err("t", format!("must be ≥ 0 s, got {t}")));
    }
    let hands = match o.get("hands") {
        Some(Value::Array(hands)) => hands.as_slice(),
        Some(other) => return Err(place.err("hands", format!("expected a list, got {other}"))),
        None => return Err(place.err("hands", "missing (an empty list for no hands)")),
    };
    let hands = hands
        .iter()
        .enumerate()
        .map(|(h, hand)| tracked_hand(place, &format!("hands[{h}]"), hand))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(TrackingFrame { timestamp_us: (t * 1e6).round() as i64, hands })
}

fn tracked_hand(place: &Place, path: &str, v: &Value) -> Result<TrackedHand, InputError> {
    let at = |field: &str| format!("{path}.{field}");
    let o = object(place, path, v)?;
    let keys =
        ["side", "layout", "joints", "radii", "orientations", "id", "grab", "pinch", "confidence"];
    known_keys(place, path, o, &keys)?;
    let side = o.get("side").and_then(Value::as_str).and_then(|s| s.parse::<Side>().ok());
    let side = side.ok_or_else(|| {
        let got = o.get("side").map_or("nothing".into(), Value::to_string);
        place.err(at("side"), format!("expected \"left\" or \"right\", got {got}"))
    })?;
    let layout = o.get("layout").and_then(Value::as_str).and_then(|n| n.parse::<Layout>().ok());
    let layout = layout.ok_or_else(|| {
        let got = o.get("layout").map_or("nothing".into(), Value::to_string);
        place.err(at("layout"), format!("unknown layout {got} (known: {})", Layout::KNOWN))
    })?;
    let (name, count) = (layout.name(), layout.count());
    let joints = o.get("joints").ok_or_else(|| place.err(at("joints"), "missing"))?;
    let joints = joints.as_array().ok_or_else(|| place.err(at("joints"), "expected a list"))?;
    let positions = (0..count)
        .map(|j| match joints.get(j) {
            Some(Value::Null) | None => Err(place.err(
                format!("{path}.joints[{j}]"),
                format!("missing joint {j} of {count} ({name} {})", joint_name(name, j)),
            )),
            Some(p) => place.vec3(&format!("{path}.joints[{j}]"), p),
        })
        .collect::<Result<Vec<_>, _>>()?;
    if joints.len() > count {
        let why = format!("{} joints, but {name} has {count}", joints.len());
        return Err(place.err(at("joints"), why));
    }
    let id = match o.get("id") {
        None => side as i64,
        Some(id) => id.as_i64().ok_or_else(|| place.err(at("id"), "not an integer"))?,
    };
    let strength = |key: &str| -> Result<Option<f32>, InputError> {
        let Some(v) = o.get(key) else { return Ok(None) };
        let x = place.number(&at(key), v, 1.0)?;
        if x < 0.0 {
            return Err(place.err(at(key), format!("must be in [0, 1], got {x}")));
        }
        Ok(Some(x as f32))
    };
    let (grab, pinch, confidence) =
        (strength("grab")?, strength("pinch")?, strength("confidence")?);
    if layout == Layout::MediaPipe
        && let Some(key) = ["radii", "orientations"].into_iter().find(|k| o.contains_key(*k))
    {
        return Err(place.err(at(key), "mediapipe landmarks have none; leave it out"));
    }
    let radii = o.get("radii").map(|r| radii(place, &at("radii"), r, count)).transpose()?;
    let orientations = orientations(place, &at("orientations"), o.get("orientations"), count)?;
    let hand = layouts::from_layout(
        layout,
        id,
        side,
        &positions,
        radii.as_deref(),
        orientations.as_deref(),
    );
    let hand =
        hand.map_err(|e: LayoutError| place.err(format!("{path}.joints[{}]", e.joint), e.reason))?;
    Ok(TrackedHand { grab, pinch, confidence, ..hand })
}

fn radii(place: &Place, path: &str, v: &Value, count: usize) -> Result<Vec<f32>, InputError> {
    let a = place.array(path, v, count)?;
    a.iter()
        .enumerate()
        .map(|(j, r)| {
            let r = place.number(&format!("{path}[{j}]"), r, MAX_COORDINATE_M)?;
            if r < 0.0 {
                return Err(place.err(format!("{path}[{j}]"), format!("negative radius {r}")));
            }
            Ok(r as f32)
        })
        .collect()
}

fn orientations(
    place: &Place,
    path: &str,
    v: Option<&Value>,
    count: usize,
) -> Result<Option<Vec<Quat>>, InputError> {
    let Some(v) = v else { return Ok(None) };
    let a = place.array(path, v, count)?;
    let quat = |(j, q): (usize, &Value)| {
        let at = format!("{path}[{j}]");
        let c = place.array(&at, q, 4)?;
        let x = |i: usize| place.number(&format!("{at}[{i}]"), &c[i], 2.0).map(|x| x as f32);
        super::layouts::rotation([x(0)?, x(1)?, x(2)?, x(3)?])
            .ok_or_else(|| place.err(at, "zero-length quaternion"))
    };
    a.iter().enumerate().map(quat).collect::<Result<Vec<_>, _>>().map(Some)
}

/// A joint's name in its layout, for messages.
fn joint_name(layout: &str, j: usize) -> String {
    const FINGERS: [&str; 5] = ["thumb", "index", "middle", "ring", "little"];
    match layout {
        "mediapipe" => {
            let parts = ["cmc", "mcp", "ip", "tip"];
            let finger_parts = ["mcp", "pip", "dip", "tip"];
            match j.checked_sub(1) {
                None => "wrist".into(),
                Some(k) if k < 4 => format!("thumb {}", parts[k]),
                Some(k) => format!("{} {}", FINGERS[k / 4], finger_parts[k % 4]),
            }
        }
        _ => {
            let first = if layout == "openxr" { 2 } else { 1 };
            let parts = ["metacarpal", "proximal", "intermediate", "distal", "tip"];
            match j.checked_sub(first) {
                None if layout == "openxr" && j == 0 => "palm".into(),
                None => "wrist".into(),
                Some(k) if k < 4 => {
                    format!("thumb {}", ["metacarpal", "proximal", "distal", "tip"][k])
                }
                Some(k) => format!("{} {}", FINGERS[1 + (k - 4) / 5], parts[(k - 4) % 5]),
            }
        }
    }
}

/// Rounds to a micrometre (or a millionth), which keeps lines short.
fn round(x: f32) -> Value {
    json!((f64::from(x) * 1e6).round() / 1e6)
}

/// One frame line at `t` (s) with `hands` (metres, y up) in the OpenXR
/// layout ([`layouts::to_openxr`]): positions, radii and orientations.
pub fn openxr_line(t: f64, hands: &[TrackedHand]) -> String {
    let hands: Vec<Value> = hands
        .iter()
        .map(|hand| {
            let joints = layouts::to_openxr(hand);
            let positions: Vec<_> =
                joints.iter().map(|j| j.position.to_array().map(round)).collect();
            let mut o = json!({
                "id": hand.id,
                "side": if hand.side == Side::Left { "left" } else { "right" },
                "layout": "openxr",
                "joints": positions,
                "radii": joints.iter().map(|j| round(j.radius)).collect::<Vec<_>>(),
                "orientations":
                    joints.iter().map(|j| j.orientation.to_array().map(round)).collect::<Vec<_>>(),
            });
            let values =
                [("grab", hand.grab), ("pinch", hand.pinch), ("confidence", hand.confidence)];
            for (key, s) in values {
                if let Some(s) = s {
                    o[key] = round(s);
                }
            }
            o
        })
        .collect();
    json!({"t": (t * 1e6).round() / 1e6, "hands": hands}).to_string()
}

/// A whole joint recording of `frames` (e.g. a Leap recording's), each hand
/// taken into metres, y up, by `conversion`; times from the first frame.
pub fn openxr_recording(frames: &[TrackingFrame], conversion: &Conversion) -> String {
    let start = frames.first().map_or(0, |f| f.timestamp_us);
    let mut out = header() + "\n";
    for f in frames {
        let hands: Vec<TrackedHand> = f.hands.iter().map(|h| h.converted(conversion)).collect();
        let t = f.timestamp_us.saturating_sub(start) as f64 * 1e-6;
        out += &openxr_line(t, &hands);
        out.push('\n');
    }
    out
}
