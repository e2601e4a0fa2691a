//! Leap Motion recordings as leapjs-playback writes them: LZ-String
//! `compressToBase64` text (`.json.lz`) or plain JSON, protocol v6 frames,
//! `metadata.formatVersion` 0.1 or 1 (a frame is an object) or 2 (packed:
//! frame 0 is a header of key names, later frames are arrays in its order).
//!
//! Units stay Leap's: millimetres, desktop axes; see [`super::convert`].

use super::{InputError, TrackedHand, TrackingFrame};
use crate::hand::Side;
use glam::Vec3;
use serde_json::{Map, Value};
use std::path::Path;

/// Coordinates beyond this (mm, 10 m) are rejected as absurd.
pub const MAX_COORDINATE_MM: f32 = 1.0e4;

/// Finger widths (mm) when a recording has none (format 2 drops them): the
/// widths the Leap service 2.x reports for an average adult hand, thumb first.
pub const DEFAULT_WIDTHS_MM: [f32; 5] = [19.6, 18.7, 18.4, 17.5, 15.5];

/// A decoded recording.
#[derive(Debug, Clone, PartialEq)]
pub struct LeapRecording {
    /// The file it came from, for messages.
    pub source_name: String,
    /// The file's `metadata.formatVersion`: 0.1, 1 or 2.
    pub format_version: f64,
    /// Frames in file order.
    pub frames: Vec<TrackingFrame>,
}

fn err(
    source: &str,
    frame: Option<usize>,
    field: impl Into<String>,
    reason: impl Into<String>,
) -> InputError {
    InputError {
        source_name: source.to_string(),
        frame,
        field: field.into(),
        reason: reason.into(),
    }
}

/// Reads a `.json.lz` or `.json` recording from disk.
pub fn load(path: &Path) -> Result<LeapRecording, InputError> {
    let (name, text) = super::read_text(path, &crate::files::FileSystem)?;
    parse(&name, &text)
}

/// Decodes recording text: plain JSON if it starts with `{`, else LZ-String
/// base64.
pub fn parse(source: &str, text: &str) -> Result<LeapRecording, InputError> {
    let trimmed = text.trim();
    let json = if trimmed.starts_with('{') {
        trimmed.to_string()
    } else {
        let units = lz_str::decompress_from_base64(trimmed).ok_or_else(|| {
            err(source, None, "lz-string", "not valid LZ-String base64 data (corrupt or truncated)")
        })?;
        String::from_utf16(&units)
            .map_err(|_| err(source, None, "lz-string", "decompressed data is not valid text"))?
    };
    let root: Value = serde_json::from_str(&json).map_err(|e| {
        err(source, None, "json", format!("invalid JSON, {}", crate::file_error::json_reason(&e)))
    })?;
    from_json(source, &root)
}

/// Builds a recording from its parsed JSON.
pub fn from_json(source: &str, root: &Value) -> Result<LeapRecording, InputError> {
    let meta = root.get("metadata").ok_or_else(|| err(source, None, "metadata", "missing"))?;
    let version = meta
        .get("formatVersion")
        .and_then(Value::as_f64)
        .ok_or_else(|| err(source, None, "metadata.formatVersion", "missing or not a number"))?;
    let raw = root
        .get("frames")
        .and_then(Value::as_array)
        .ok_or_else(|| err(source, None, "frames", "missing or not an array"))?;
    let frames = match version {
        v if v == 0.1 || v == 1.0 => raw
            .iter()
            .enumerate()
            .map(|(i, f)| frame(source, i, f))
            .collect::<Result<Vec<_>, _>>()?,
        2.0 => {
            let header = raw
                .first()
                .ok_or_else(|| err(source, Some(0), "header", "format 2 needs a header frame"))?;
            raw.iter()
                .enumerate()
                .skip(1)
                .map(|(i, f)| unpack(source, i, header, f).and_then(|obj| frame(source, i, &obj)))
                .collect::<Result<Vec<_>, _>>()?
        }
        v => {
            return Err(err(
                source,
                None,
                "metadata.formatVersion",
                format!("unknown format version {v} (known: 0.1, 1, 2)"),
            ));
        }
    };
    if frames.is_empty() {
        return Err(err(source, None, "frames", "the recording has no frames"));
    }
    Ok(LeapRecording { source_name: source.to_string(), format_version: version, frames })
}

/// Format 2: turns a packed frame (arrays in header order) into the object
/// a format-1 frame would be. A header entry is a key, or `{name: [keys]}`
/// for one nested object, or `{name: [[keys]]}` for a list of them.
fn unpack(source: &str, index: usize, header: &Value, packed: &Value) -> Result<Value, InputError> {
    fn object(
        source: &str,
        index: usize,
        path: &str,
        keys: &[Value],
        values: &Value,
    ) -> Result<Value, InputError> {
        let values = values
            .as_array()
            .ok_or_else(|| err(source, Some(index), path, "packed value is not an array"))?;
        if values.len() != keys.len() {
            return Err(err(
                source,
                Some(index),
                path,
                format!(
                    "packed array has {} values but the header has {} keys",
                    values.len(),
                    keys.len()
                ),
            ));
        }
        let mut out = Map::new();
        for (key, value) in keys.iter().zip(values) {
            match key {
                Value::String(k) => {
                    out.insert(k.clone(), value.clone());
                }
                Value::Object(spec) => {
                    for (name, sub) in spec {
                        let sub_path = format!("{path}.{name}");
                        let sub = sub.as_array().ok_or_else(|| {
                            let why = format!("header entry must list keys, got {sub}");
                            err(source, Some(0), &sub_path, why)
                        })?;
                        let unpacked = match sub.as_slice() {
                            [Value::Array(item_keys)] => {
                                let items = value.as_array().ok_or_else(|| {
                                    err(
                                        source,
                                        Some(index),
                                        &sub_path,
                                        "packed list is not an array",
                                    )
                                })?;
                                Value::Array(
                                    items
                                        .iter()
                                        .enumerate()
                                        .map(|(j, item)| {
                                            object(
                                                source,
                                                index,
                                                &format!("{sub_path}[{j}]"),
                                                item_keys,
                                                item,
                                            )
                                        })
                                        .collect::<Result<_, _>>()?,
                                )
                            }
                            keys => object(source, index, &sub_path, keys, value)?,
                        };
                        out.insert(name.clone(), unpacked);
                    }
                }
                _ => {
                    return Err(err(
                        source,
                        Some(0),
                        path,
                        "header entries must be keys or objects",
                    ));
                }
            }
        }
        Ok(Value::Object(out))
    }
    let keys = header
        .as_array()
        .ok_or_else(|| err(source, Some(0), "header", "format 2 header is not an array"))?;
    object(source, index, "frame", keys, packed)
}

fn number(source: &str, index: usize, path: &str, v: Option<&Value>) -> Result<f32, InputError> {
    let v = v.ok_or_else(|| err(source, Some(index), path, "missing"))?;
    let x =
        v.as_f64().ok_or_else(|| err(source, Some(index), path, format!("not a number: {v}")))?;
    if !x.is_finite() || x.abs() > MAX_COORDINATE_MM as f64 {
        return Err(err(source, Some(index), path, format!("absurd value {x}")));
    }
    Ok(x as f32)
}

fn vec3(source: &str, index: usize, path: &str, v: Option<&Value>) -> Result<Vec3, InputError> {
    let v = v.ok_or_else(|| err(source, Some(index), path, "missing"))?;
    let a = v
        .as_array()
        .filter(|a| a.len() == 3)
        .ok_or_else(|| err(source, Some(index), path, format!("not a 3-vector: {v}")))?;
    let c = |i: usize| number(source, index, &format!("{path}[{i}]"), a.get(i));
    Ok(Vec3::new(c(0)?, c(1)?, c(2)?))
}

fn unit(source: &str, index: usize, path: &str, v: Option<&Value>) -> Result<Vec3, InputError> {
    vec3(source, index, path, v)?
        .try_normalize()
        .ok_or_else(|| err(source, Some(index), path, "zero-length direction"))
}

/// A grab or pinch strength, or a confidence: absent or null when the
/// tracker gives none, else a number in [0, 1] (Leap's scale); anything
/// else is refused, since the replay finds closings from the strengths.
fn strength(
    source: &str,
    index: usize,
    path: &str,
    v: Option<&Value>,
) -> Result<Option<f32>, InputError> {
    let Some(v) = v.filter(|v| !v.is_null()) else { return Ok(None) };
    let x =
        v.as_f64().ok_or_else(|| err(source, Some(index), path, format!("not a number: {v}")))?;
    if !(0.0..=1.0).contains(&x) {
        return Err(err(source, Some(index), path, format!("must be in [0, 1], got {x}")));
    }
    Ok(Some(x as f32))
}

/// One frame object (format 0.1/1, or unpacked format 2, or a live
/// protocol-v6 frame).
pub(crate) fn frame(source: &str, index: usize, f: &Value) -> Result<TrackingFrame, InputError> {
    let timestamp = f
        .get("timestamp")
        .and_then(Value::as_i64)
        .ok_or_else(|| err(source, Some(index), "timestamp", "missing or not an integer (µs)"))?;
    // The service counts µs from its start; a negative time would make
    // differences between frames overflow.
    if timestamp < 0 {
        let why = format!("must be ≥ 0 µs, got {timestamp}");
        return Err(err(source, Some(index), "timestamp", why));
    }
    let hands_json = f.get("hands").and_then(Value::as_array).map(Vec::as_slice).unwrap_or(&[]);
    let pointables =
        f.get("pointables").and_then(Value::as_array).map(Vec::as_slice).unwrap_or(&[]);
    let mut hands = Vec::with_capacity(hands_json.len());
    for (h, hand) in hands_json.iter().enumerate() {
        let path = |field: &str| format!("hands[{h}].{field}");
        let id = hand
            .get("id")
            .and_then(Value::as_i64)
            .ok_or_else(|| err(source, Some(index), path("id"), "missing or not an integer"))?;
        let side = match hand.get("type") {
            Some(Value::String(s)) if s == "left" => Side::Left,
            Some(Value::String(s)) if s == "right" => Side::Right,
            other => {
                let got = other.map_or("nothing".to_string(), Value::to_string);
                let why = format!("expected \"left\" or \"right\", got {got}");
                return Err(err(source, Some(index), path("type"), why));
            }
        };
        let mut joints = [[Vec3::ZERO; 4]; 5];
        let mut widths = DEFAULT_WIDTHS_MM;
        let mut carps: [Option<Vec3>; 4] = [None; 4];
        let mut seen = [false; 5];
        for (p, pointable) in pointables.iter().enumerate() {
            if pointable.get("handId").and_then(Value::as_i64) != Some(id)
                || pointable.get("tool").and_then(Value::as_bool) == Some(true)
            {
                continue;
            }
            let ppath = |field: &str| format!("pointables[{p}].{field}");
            // Finger type 0 (thumb) … 4 (pinky); format 2 drops `type`, but
            // Leap's pointable ids are `10 · handId + type`.
            let finger = match pointable.get("type").and_then(Value::as_i64) {
                Some(t) => t,
                None => pointable
                    .get("id")
                    .and_then(Value::as_i64)
                    .map(|i| i.rem_euclid(10))
                    .ok_or_else(|| {
                        err(source, Some(index), ppath("type"), "missing finger type and id")
                    })?,
            };
            let f = usize::try_from(finger).ok().filter(|&f| f < 5).ok_or_else(|| {
                err(source, Some(index), ppath("type"), format!("finger type {finger} is not 0..4"))
            })?;
            let tip_key = if pointable.get("btipPosition").is_some() {
                "btipPosition"
            } else {
                "tipPosition"
            };
            for (j, key) in
                ["mcpPosition", "pipPosition", "dipPosition", tip_key].iter().enumerate()
            {
                joints[f][j] = vec3(source, index, &ppath(key), pointable.get(*key))?;
            }
            if let (Some(carp), 1..) = (pointable.get("carpPosition"), f) {
                carps[f - 1] = Some(vec3(source, index, &ppath("carpPosition"), Some(carp))?);
            }
            if let Some(w) = pointable.get("width") {
                let w = number(source, index, &ppath("width"), Some(w))?;
                if w <= 0.0 {
                    return Err(err(
                        source,
                        Some(index),
                        ppath("width"),
                        format!("must be positive, got {w}"),
                    ));
                }
                widths[f] = w;
            }
            seen[f] = true;
        }
        if let Some(missing) = seen.iter().position(|s| !s) {
            return Err(err(
                source,
                Some(index),
                path("fingers"),
                format!("finger {missing} of hand {id} is missing"),
            ));
        }
        hands.push(TrackedHand {
            id,
            side,
            palm_position: vec3(source, index, &path("palmPosition"), hand.get("palmPosition"))?,
            palm_normal: unit(source, index, &path("palmNormal"), hand.get("palmNormal"))?,
            direction: unit(source, index, &path("direction"), hand.get("direction"))?,
            joints,
            // Only a complete set outlines the palm.
            carps: carps
                .iter()
                .copied()
                .collect::<Option<Vec<Vec3>>>()
                .and_then(|c| c.try_into().ok()),
            widths,
            grab: strength(source, index, &path("grabStrength"), hand.get("grabStrength"))?,
            pinch: strength(source, index, &path("pinchStrength"), hand.get("pinchStrength"))?,
            confidence: strength(source, index, &path("confidence"), hand.get("confidence"))?,
        });
    }
    Ok(TrackingFrame { timestamp_us: timestamp, hands })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hand_json() -> Value {
        serde_json::json!({
            "id": 7, "type": "right",
            "palmPosition": [0.0, 200.0, 0.0], "palmNormal": [0.0, -1.0, 0.0],
            "direction": [0.0, 0.0, -1.0],
            "grabStrength": 0.25, "pinchStrength": 1.0
        })
    }

    fn pointable(finger: i64) -> Value {
        let x = 20.0 * finger as f64 - 40.0;
        serde_json::json!({
            "handId": 7, "id": 70 + finger, "type": finger, "width": 18.0, "tool": false,
            "mcpPosition": [x, 200.0, -40.0], "pipPosition": [x, 200.0, -80.0],
            "dipPosition": [x, 200.0, -105.0], "tipPosition": [x, 200.0, -125.0]
        })
    }

    fn recording(version: f64) -> Value {
        serde_json::json!({
            "metadata": { "formatVersion": version },
            "frames": [{
                "timestamp": 1000, "hands": [hand_json()],
                "pointables": (0..5).map(pointable).collect::<Vec<_>>()
            }]
        })
    }

    #[test]
    fn reads_a_format_1_frame() {
        let rec = from_json("test", &recording(1.0)).unwrap();
        let hand = &rec.frames[0].hands[0];
        assert_eq!((hand.id, hand.side), (7, Side::Right));
        assert_eq!(hand.joints[4][3], Vec3::new(40.0, 200.0, -125.0));
        assert_eq!(hand.grab, Some(0.25));
    }

    #[test]
    fn strengths_out_of_range_are_refused_and_absent_ones_are_none() {
        for (value, why) in [
            (serde_json::json!(1.3), "must be in [0, 1], got 1.3"),
            (serde_json::json!(-0.05), "must be in [0, 1], got -0.05"),
            (serde_json::json!("NaN"), "not a number: \"NaN\""),
        ] {
            let mut bad = recording(1.0);
            bad["frames"][0]["hands"][0]["pinchStrength"] = value;
            let e = from_json("rec.json", &bad).unwrap_err().to_string();
            assert_eq!(e, format!("rec.json: frame 0: hands[0].pinchStrength: {why}"));
        }
        let mut none = recording(1.0);
        none["frames"][0]["hands"][0]["grabStrength"] = serde_json::Value::Null;
        none["frames"][0]["hands"][0].as_object_mut().unwrap().remove("pinchStrength");
        let hand = &from_json("rec.json", &none).unwrap().frames[0].hands[0];
        assert_eq!((hand.grab, hand.pinch), (None, None));
    }

    /// A Leap's per-hand confidence comes in as it is recorded; outside
    /// [0, 1] it is an error naming the file, the frame and the field.
    #[test]
    fn the_hands_confidence_is_read_and_checked() {
        let mut rec = recording(1.0);
        rec["frames"][0]["hands"][0]["confidence"] = serde_json::json!(0.17);
        let hand = &from_json("rec.json", &rec).unwrap().frames[0].hands[0];
        assert_eq!(hand.confidence, Some(0.17));
        assert_eq!(
            from_json("rec.json", &recording(1.0)).unwrap().frames[0].hands[0].confidence,
            None
        );
        rec["frames"][0]["hands"][0]["confidence"] = serde_json::json!(1.02);
        let e = from_json("rec.json", &rec).unwrap_err().to_string();
        assert_eq!(e, "rec.json: frame 0: hands[0].confidence: must be in [0, 1], got 1.02");
    }

    #[test]
    fn errors_name_the_file_frame_and_field() {
        let mut bad = recording(1.0);
        bad["frames"][0]["hands"][0]["palmPosition"] = serde_json::json!([0.0, "x", 0.0]);
        let e = from_json("rec.json", &bad).unwrap_err().to_string();
        assert_eq!(e, "rec.json: frame 0: hands[0].palmPosition[1]: not a number: \"x\"");

        let mut absurd = recording(1.0);
        absurd["frames"][0]["pointables"][2]["tipPosition"] = serde_json::json!([0.0, 1.0e12, 0.0]);
        let e = from_json("rec.json", &absurd).unwrap_err().to_string();
        assert!(
            e.contains("frame 0")
                && e.contains("pointables[2].tipPosition[1]")
                && e.contains("absurd"),
            "{e}"
        );

        let mut missing = recording(1.0);
        missing["frames"][0]["pointables"].as_array_mut().unwrap().remove(3);
        let e = from_json("rec.json", &missing).unwrap_err().to_string();
        assert!(e.contains("hands[0].fingers") && e.contains("finger 3"), "{e}");

        let e = from_json("rec.json", &recording(3.0)).unwrap_err().to_string();
        assert!(
            e.contains("metadata.formatVersion") && e.contains("unknown format version 3"),
            "{e}"
        );
    }

    #[test]
    fn corrupt_lz_and_json_are_errors_not_panics() {
        let e = parse("x.json.lz", "this is not base64 LZ data at all!").unwrap_err();
        assert!(e.field == "lz-string" || e.field == "json", "{e}");
        let e = parse("x.json", "{\"metadata\": ").unwrap_err();
        assert_eq!(e.field, "json");
        assert!(e.to_string().contains("line 1"), "{e}");
    }
}
