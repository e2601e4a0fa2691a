//! MediaPipe hand landmarker results in protobuf text format (`.pbtxt`),
//! as MediaPipe's own test data stores them: `classifications` (the
//! handedness), `landmarks` (21 normalised image landmarks) and
//! `world_landmarks` (21 landmarks in metres), each a list of
//! `landmark { x: .. y: .. z: .. }` blocks.
//!
//! Only the world landmarks make a hand: they are metres with the origin at
//! the hand's approximate geometric centre, on the image's axes (x right,
//! y down, z away from the camera), so a rotation by 180° about x
//! ([`super::layouts::mediapipe_to_y_up`]) makes them right-handed and
//! y up. The normalised landmarks are fractions of the image's width and
//! height, with a depth of about the same scale as x; turning them into
//! metres would need the camera's intrinsics, so they are read but not used.
//!
//! The handedness label needs care ([`Label`]): MediaPipe's Tasks API
//! documents it as the subject's own hand ("Left and Right handedness
//! correspond to the subject's hands, not the viewer"), but the legacy
//! Hands solution, and older versions of the Tasks API, labelled hands as
//! if the image were mirrored (a selfie camera), and said to swap the label
//! otherwise. MediaPipe's own `fist_landmarks.pbtxt` is of the second kind:
//! labelled `"Left"`, its landmarks on the image's right-handed axes are a
//! right hand (its fingers curl towards the palm only when read as one;
//! `tests/physics/trackers.rs`).

use super::convert::Conversion;
use super::layouts::{self, mediapipe};
use super::{InputError, TrackedHand};
use crate::hand::Side;
use glam::Vec3;

/// One hand of a hand landmarker result.
#[derive(Debug, Clone, PartialEq)]
pub struct HandLandmarks {
    /// The classified hand, if the file has a `"Left"` or `"Right"` label.
    pub handedness: Option<Side>,
    /// Normalised image landmarks (fractions of the image; z relative).
    pub landmarks: Option<[Vec3; mediapipe::COUNT]>,
    /// World landmarks (m), MediaPipe's axes (y down).
    pub world_landmarks: Option<[Vec3; mediapipe::COUNT]>,
    /// The least `visibility` or `presence` of any landmark, when the
    /// file gives them: how sure the tracker is of the hand's least seen
    /// joint, in [0, 1] (MediaPipe's likelihoods that a landmark is
    /// unoccluded and in the image).
    pub confidence: Option<f32>,
}

/// What a file's handedness label means.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Label {
    /// The subject's own hand (MediaPipe Tasks, recent versions).
    Subject,
    /// The hand as if the image were mirrored (MediaPipe Hands, older
    /// Tasks versions, MediaPipe's own test data): swapped.
    Mirrored,
}

impl HandLandmarks {
    /// The hand as a tracker reports it, in metres, y up, centred where
    /// MediaPipe centres it, its side read from the label as `label` says;
    /// `source` names the file in errors.
    pub fn tracked_hand(
        &self,
        source: &str,
        id: i64,
        label: Label,
    ) -> Result<TrackedHand, InputError> {
        let fail = |field: &str, reason: String| InputError {
            source_name: source.to_string(),
            frame: None,
            field: field.to_string(),
            reason,
        };
        let world = self
            .world_landmarks
            .ok_or_else(|| fail("world_landmarks", "missing: only they are in metres".into()))?;
        let side = self
            .handedness
            .ok_or_else(|| fail("classifications", "no \"Left\" or \"Right\" label".into()))?;
        let side = match (label, side) {
            (Label::Subject, side) => side,
            (Label::Mirrored, Side::Left) => Side::Right,
            (Label::Mirrored, Side::Right) => Side::Left,
        };
        let up: Conversion = layouts::mediapipe_to_y_up();
        let landmarks = world.map(|p| up.point(p));
        let hand = layouts::from_mediapipe(id, side, &landmarks)
            .map_err(|e| fail(&format!("world_landmarks.landmark[{}]", e.joint), e.reason))?;
        Ok(TrackedHand { confidence: self.confidence, ..hand })
    }
}

/// Reads a `.pbtxt` hand landmarker result from disk.
pub fn load(path: &std::path::Path) -> Result<HandLandmarks, InputError> {
    let (name, text) = super::read_text(path, &crate::files::FileSystem)?;
    parse(&name, &text)
}

/// A text-format field: a scalar's text, or a message's fields.
#[derive(Debug, Clone, PartialEq)]
enum Node {
    Scalar(String),
    Message(Vec<(String, usize, Node)>),
}

/// The tokens of protobuf text format, each with its line.
fn tokens(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let mut rest = line.trim_start();
        while let Some(c) = rest.chars().next() {
            let len = match c {
                '#' => break,
                '{' | '}' | ':' => 1,
                '"' => rest[1..].find('"').map_or(rest.len(), |i| i + 2),
                _ => rest
                    .find(|c: char| c.is_whitespace() || "{}:#".contains(c))
                    .unwrap_or(rest.len()),
            };
            out.push((n + 1, rest[..len].to_string()));
            rest = rest[len..].trim_start();
        }
    }
    out
}

/// Parses fields until a `}` (or the end, at the top level).
fn message(
    source: &str,
    tokens: &mut std::iter::Peekable<std::vec::IntoIter<(usize, String)>>,
    top: bool,
) -> Result<Vec<(String, usize, Node)>, InputError> {
    let fail = |line: usize, reason: String| InputError {
        source_name: source.to_string(),
        frame: None,
        field: format!("line {line}"),
        reason,
    };
    let mut fields = Vec::new();
    while let Some((line, name)) = tokens.next() {
        if name == "}" {
            return if top { Err(fail(line, "unmatched '}'".into())) } else { Ok(fields) };
        }
        if !name.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_') {
            return Err(fail(line, format!("expected a field name, got '{name}'")));
        }
        if tokens.peek().is_some_and(|t| t.1 == ":") {
            tokens.next();
        }
        match tokens.next() {
            Some((_, open)) if open == "{" => {
                fields.push((name, line, Node::Message(message(source, tokens, false)?)));
            }
            Some((_, value)) if value != "}" && value != ":" => {
                fields.push((name, line, Node::Scalar(value)));
            }
            _ => return Err(fail(line, format!("field '{name}' has no value"))),
        }
    }
    if top { Ok(fields) } else { Err(fail(0, "unclosed '{' at the end of the file".into())) }
}

/// Parses a hand landmarker result in protobuf text format.
pub fn parse(source: &str, text: &str) -> Result<HandLandmarks, InputError> {
    let fields = message(source, &mut tokens(text).into_iter().peekable(), true)?;
    let fail = |field: String, reason: String| InputError {
        source_name: source.to_string(),
        frame: None,
        field,
        reason,
    };
    let children = |node: &Node| match node {
        Node::Message(f) => f.clone(),
        Node::Scalar(_) => Vec::new(),
    };
    let mut out = HandLandmarks {
        handedness: None,
        landmarks: None,
        world_landmarks: None,
        confidence: None,
    };
    for (name, line, node) in &fields {
        match name.as_str() {
            "classifications" => {
                let labels = children(node).into_iter().filter(|f| f.0 == "classification");
                for (_, _, c) in labels {
                    let label = children(&c).into_iter().find(|f| f.0 == "label");
                    out.handedness = match label.map(|f| f.2) {
                        Some(Node::Scalar(s)) if s == "\"Left\"" => Some(Side::Left),
                        Some(Node::Scalar(s)) if s == "\"Right\"" => Some(Side::Right),
                        _ => out.handedness,
                    };
                }
            }
            "landmarks" | "world_landmarks" => {
                let points = children(node)
                    .into_iter()
                    .filter(|f| f.0 == "landmark")
                    .enumerate()
                    .map(|(i, (_, line, l))| {
                        let at = |axis: &str| format!("{name}.landmark[{i}].{axis}");
                        let axis = |axis: &str| {
                            let value = children(&l).into_iter().find(|f| f.0 == axis);
                            let Some((_, _, Node::Scalar(v))) = value else {
                                return Err(fail(at(axis), format!("missing (line {line})")));
                            };
                            v.parse::<f32>().ok().filter(|x| x.is_finite()).ok_or_else(|| {
                                let why = format!("not a finite number: {v} (line {line})");
                                fail(at(axis), why)
                            })
                        };
                        for key in ["visibility", "presence"] {
                            if children(&l).iter().any(|f| f.0 == key) {
                                let p = axis(key)?;
                                if !(0.0..=1.0).contains(&p) {
                                    let why = format!("must be in [0, 1], got {p} (line {line})");
                                    return Err(fail(at(key), why));
                                }
                                out.confidence = Some(out.confidence.map_or(p, |c| c.min(p)));
                            }
                        }
                        Ok(Vec3::new(axis("x")?, axis("y")?, axis("z")?))
                    })
                    .collect::<Result<Vec<_>, _>>()?;
                let n = points.len();
                let points: [Vec3; mediapipe::COUNT] = points.try_into().map_err(|_| {
                    let why =
                        format!("{n} landmarks, a hand has {} (line {line})", mediapipe::COUNT);
                    fail(name.clone(), why)
                })?;
                if name == "landmarks" {
                    out.landmarks = Some(points);
                } else {
                    out.world_landmarks = Some(points);
                }
            }
            _ => {}
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nested_blocks_comments_and_errors() {
        let one = "landmark { x: 1 y: 2.5 z: -3e-2 } # a comment\n";
        let text = format!(
            "classifications {{ classification {{ label: \"Right\" }} }}\n\
                            world_landmarks {{\n{}}}\n",
            one.repeat(21)
        );
        let h = parse("t.pbtxt", &text).unwrap();
        assert_eq!(h.handedness, Some(Side::Right));
        assert_eq!(h.world_landmarks.unwrap()[20], Vec3::new(1.0, 2.5, -0.03));
        assert!(h.landmarks.is_none() && h.confidence.is_none());
        let e = parse("t.pbtxt", "world_landmarks { landmark { x: 1 y: 2 } }").unwrap_err();
        assert_eq!(e.to_string(), "t.pbtxt: world_landmarks.landmark[0].z: missing (line 1)");
        let e = parse("t.pbtxt", "landmarks {\n landmark { x: nan y: 0 z: 0 }\n}").unwrap_err();
        assert_eq!(e.field, "landmarks.landmark[0].x");
        assert!(parse("t.pbtxt", "landmarks { landmark {").is_err());
        assert!(parse("t.pbtxt", "}").is_err());
    }

    /// Landmarks' visibility and presence come in as the hand's least;
    /// out of [0, 1], they are an error naming the landmark.
    #[test]
    fn the_least_visibility_or_presence_is_the_hands_confidence() {
        let seen = "landmark { x: 0 y: 0 z: 0 visibility: 0.9 presence: 0.97 }\n";
        let hidden = "landmark { x: 0 y: 0 z: 0 visibility: 0.35 }\n";
        let text = format!("landmarks {{\n{}{}}}\n", seen.repeat(20), hidden);
        assert_eq!(parse("t.pbtxt", &text).unwrap().confidence, Some(0.35));
        let text = "landmarks { landmark { x: 0 y: 0 z: 0 presence: 1.4 } }";
        let e = parse("t.pbtxt", text).unwrap_err().to_string();
        assert_eq!(
            e,
            "t.pbtxt: landmarks.landmark[0].presence: must be in [0, 1], got 1.4 (line 1)"
        );
    }
}
