//! Scripted hands: a few keyframes of palm pose and finger flexion, eased
//! between, on the parametric [`HandRig`].

use crate::hand::rig::{Articulation, HandRig};
use crate::hand::{HandPose, HandSample, MAX_COORDINATE, Side};
use crate::run::RunError;
use crate::run::drive::HandSource;
use glam::{EulerRot, Quat, Vec3};

/// Linear 0→1 ramp of `t` over `[t0, t1]`.
pub fn ramp(t0: f32, t1: f32, t: f32) -> f32 {
    ((t - t0) / (t1 - t0)).clamp(0.0, 1.0)
}

/// Smooth 0→1 ramp of `t` over `[t0, t1]` (zero slope at both ends).
pub fn smoothstep(t0: f32, t1: f32, t: f32) -> f32 {
    let x = ramp(t0, t1, t);
    x * x * (3.0 - 2.0 * x)
}

/// A bad keyframe: which key, which field, and why.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "keys{}: {reason}",
    match key { Some(k) => format!("[{k}].{field}"), None => String::new() }
)]
pub struct KeyError {
    /// The key's index, or `None` for the list as a whole.
    pub key: Option<usize>,
    /// The field, e.g. `t` or `curl`.
    pub field: &'static str,
    /// What is wrong with it.
    pub reason: String,
}

/// Flexion of each finger in [0, 1] (0 straight, 1 a fist), thumb first,
/// or one number for all five.
#[derive(Debug, Clone, Copy, PartialEq, serde::Deserialize)]
#[serde(untagged)]
pub enum Curl {
    /// One flexion for all five fingers.
    All(f32),
    /// One flexion per finger, thumb first.
    Each([f32; 5]),
}

impl Default for Curl {
    fn default() -> Self {
        Curl::All(0.0)
    }
}

impl Curl {
    fn each(self) -> [f32; 5] {
        match self {
            Curl::All(c) => [c; 5],
            Curl::Each(c) => c,
        }
    }

    /// The first flexion outside [0, 1], if any.
    fn outside_unit(self) -> Option<f32> {
        self.each().into_iter().find(|c| !(0.0..=1.0).contains(c))
    }
}

/// One keyframe.
#[derive(Debug, Clone, Copy, PartialEq, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Key {
    /// Time (s).
    pub t: f32,
    /// Palm centre (world, m).
    pub palm: Vec3,
    /// Palm orientation as rotations about the world x, y and z axes, in
    /// degrees, applied in that order. Zero: palm facing up (+y), fingers
    /// along +z, a right thumb towards −x.
    #[serde(default)]
    pub rotation_deg: Vec3,
    /// Finger flexion in [0, 1], one or five: every joint, or only the two
    /// outer joints when `knuckle` is given. Absent: straight fingers.
    #[serde(default)]
    pub curl: Curl,
    /// Flexion of each finger's base joint (knuckle; the thumb's
    /// metacarpal joint) in [0, 1], one or five, instead of `curl` there;
    /// `curl` then bends the two outer joints. Absent: the knuckle follows
    /// `curl`. Knuckle and finger flexion together draw a fingertip along a
    /// surface ([`Articulation`]).
    #[serde(default)]
    pub knuckle: Option<Curl>,
    /// Thumb opposition in [0, 1]: 0 abducted in the palm plane, 1 swung in
    /// front of the palm to meet the fingertips
    /// ([`HandRig::thumb_direction`]).
    #[serde(default)]
    pub opposition: f32,
    /// Abduction of index … pinky in the palm plane (degrees, positive
    /// towards the thumb, within ±30°): [`Articulation::spread_deg`].
    #[serde(default)]
    pub spread_deg: [f32; 4],
    /// How the hand moves from the previous key to this one.
    #[serde(default)]
    pub ease: Ease,
}

/// How a scripted hand moves between two keys.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Ease {
    /// A smoothstep: the segment starts and ends at rest.
    #[default]
    Smooth,
    /// At constant speed, as for a steady push; the speed changes at once
    /// at the keys, so a segment that starts in contact starts with a jerk.
    Linear,
}

impl Key {
    /// Flexion per finger and joint: the knuckle, then `curl` twice.
    fn flex(&self) -> [[f32; 3]; 5] {
        let (curl, knuckle) = (self.curl.each(), self.knuckle.unwrap_or(self.curl).each());
        std::array::from_fn(|f| [knuckle[f], curl[f], curl[f]])
    }

    fn rotation(&self) -> Quat {
        let r = self.rotation_deg * (std::f32::consts::PI / 180.0);
        // About x first, then y, then z, all world axes: R = Rz·Ry·Rx.
        Quat::from_euler(EulerRot::ZYX, r.z, r.y, r.x)
    }
}

/// A scripted hand: keyframes eased with a smoothstep between each pair,
/// so the hand starts and stops each segment at rest, or at constant speed
/// into a key whose `ease` is [`Ease::Linear`]. Before the first key
/// and after the last, the hand holds still.
#[derive(Debug, Clone, PartialEq)]
pub struct Script {
    /// The hand that is posed.
    pub rig: HandRig,
    /// The keyframes, in increasing time.
    pub keys: Vec<Key>,
}

impl Script {
    /// Checks the keys: at least one, times finite, non-negative and
    /// increasing, positions finite and within [`MAX_COORDINATE`], angles
    /// finite, flexion and opposition in [0, 1]. The error names the key
    /// and the field.
    pub fn new(side: Side, keys: Vec<Key>) -> Result<Script, KeyError> {
        Self::with_rig(HandRig::adult(side), keys)
    }

    /// As [`Self::new`] with a given hand.
    pub fn with_rig(rig: HandRig, keys: Vec<Key>) -> Result<Script, KeyError> {
        if keys.is_empty() {
            let reason = "at least one keyframe is needed".to_string();
            return Err(KeyError { key: None, field: "", reason });
        }
        let mut previous = f32::NEG_INFINITY;
        for (i, k) in keys.iter().enumerate() {
            let at = |field, reason| Err(KeyError { key: Some(i), field, reason });
            if !(k.t.is_finite() && k.t >= 0.0) {
                return at("t", format!("must be a finite time ≥ 0 s, got {}", k.t));
            }
            if k.t <= previous {
                return at("t", format!("times must increase, got {} after {previous}", k.t));
            }
            previous = k.t;
            if !(k.palm.is_finite() && k.palm.abs().max_element() <= MAX_COORDINATE) {
                let why =
                    format!("must be finite and within ±{MAX_COORDINATE} m, got {:?}", k.palm);
                return at("palm", why);
            }
            if !k.rotation_deg.is_finite() {
                return at("rotation_deg", format!("must be finite, got {:?}", k.rotation_deg));
            }
            if let Some(c) = k.curl.outside_unit() {
                return at("curl", format!("each flexion must be in [0, 1], got {c}"));
            }
            if let Some(c) = k.knuckle.and_then(Curl::outside_unit) {
                return at("knuckle", format!("each flexion must be in [0, 1], got {c}"));
            }
            if !(0.0..=1.0).contains(&k.opposition) {
                return at("opposition", format!("must be in [0, 1], got {}", k.opposition));
            }
            if let Some(a) = k.spread_deg.iter().find(|a| !(-30.0..=30.0).contains(*a)) {
                return at("spread_deg", format!("each must be within ±30°, got {a}"));
            }
        }
        Ok(Script { rig, keys })
    }

    /// The hand pose at time `t` (s).
    pub fn pose(&self, t: f32) -> HandPose {
        let next = self.keys.partition_point(|k| k.t <= t);
        let (a, b, s) = match next {
            0 => (&self.keys[0], &self.keys[0], 0.0),
            n if n == self.keys.len() => (&self.keys[n - 1], &self.keys[n - 1], 0.0),
            n => {
                let (a, b) = (&self.keys[n - 1], &self.keys[n]);
                let s = match b.ease {
                    Ease::Smooth => smoothstep(a.t, b.t, t),
                    Ease::Linear => ramp(a.t, b.t, t),
                };
                (a, b, s)
            }
        };
        let lerp = |x: f32, y: f32| x + (y - x) * s;
        let (fa, fb) = (a.flex(), b.flex());
        let joints = Articulation {
            flex: std::array::from_fn(|f| std::array::from_fn(|j| lerp(fa[f][j], fb[f][j]))),
            opposition: lerp(a.opposition, b.opposition),
            spread_deg: std::array::from_fn(|f| lerp(a.spread_deg[f], b.spread_deg[f])),
        };
        self.rig.pose_articulated(
            a.palm.lerp(b.palm, s),
            a.rotation().slerp(b.rotation(), s).normalize(),
            &joints,
        )
    }

    /// When the last key is reached (s).
    pub fn end(&self) -> f32 {
        self.keys.last().map_or(0.0, |k| k.t)
    }
}

impl HandSource for &Script {
    fn side(&self) -> Side {
        self.rig.side
    }

    /// Keys are timed in f32 seconds.
    fn sample(&mut self, t: f64) -> Result<Option<HandSample>, RunError> {
        Ok(Some(HandSample::from_pose(self.pose(t as f32))))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(t: f32, y: f32, curl: f32) -> Key {
        Key {
            t,
            palm: Vec3::new(0.0, y, 0.0),
            rotation_deg: Vec3::ZERO,
            curl: Curl::All(curl),
            knuckle: None,
            opposition: 0.0,
            spread_deg: [0.0; 4],
            ease: Ease::Smooth,
        }
    }

    #[test]
    fn a_linear_key_is_reached_at_constant_speed() {
        let linear = Key { ease: Ease::Linear, ..key(3.0, 0.5, 0.0) };
        let s = Script::new(Side::Right, vec![key(1.0, 0.1, 0.0), linear]).unwrap();
        for (t, y) in [(1.0, 0.1), (1.5, 0.2), (2.25, 0.35), (3.0, 0.5)] {
            assert!((s.pose(t).palm.center.y - y).abs() < 1e-6, "at {t} s");
        }
        let key: Key =
            serde_json::from_str(r#"{"t": 1, "palm": [0, 0, 0], "ease": "linear"}"#).unwrap();
        assert_eq!(key.ease, Ease::Linear);
        let bad = r#"{"t": 1, "palm": [0, 0, 0], "ease": "bouncy"}"#;
        let err = serde_json::from_str::<Key>(bad).unwrap_err().to_string();
        assert!(err.contains("bouncy") && err.contains("linear"), "{err}");
    }

    #[test]
    fn eases_between_keys_and_holds_outside_them() {
        let s = Script::new(Side::Right, vec![key(1.0, 0.1, 0.0), key(2.0, 0.3, 1.0)]).unwrap();
        assert_eq!(s.pose(0.0).palm.center.y, 0.1);
        assert!((s.pose(1.5).palm.center.y - 0.2).abs() < 1e-6, "halfway by symmetry");
        assert!(s.pose(1.1).palm.center.y - 0.1 < 0.2 * 0.1 * 0.5, "slow start (ease in)");
        assert_eq!(s.pose(3.0).palm.center.y, 0.3);
        assert_eq!(s.pose(3.0), s.rig.pose(Vec3::new(0.0, 0.3, 0.0), Quat::IDENTITY, [1.0; 5]));
    }

    #[test]
    fn knuckle_keys_ease_the_knuckle_apart_from_the_curl() {
        let bent = Key { knuckle: Some(Curl::All(1.0)), ..key(1.0, 0.0, 0.0) };
        let s = Script::new(Side::Right, vec![key(0.0, 0.0, 0.0), bent]).unwrap();
        let joints = Articulation { flex: [[0.5, 0.0, 0.0]; 5], ..Articulation::default() };
        assert_eq!(s.pose(0.5), s.rig.pose_articulated(Vec3::ZERO, Quat::IDENTITY, &joints));
    }

    #[test]
    fn rotations_are_about_world_x_then_y_then_z() {
        let k = Key { rotation_deg: Vec3::new(90.0, 90.0, 0.0), ..key(0.0, 0.0, 0.0) };
        // +y (palm normal) → +z by Rx(90°) → +x by Ry(90°).
        assert!((k.rotation() * Vec3::Y - Vec3::X).length() < 1e-6);
    }

    #[test]
    fn bad_keys_name_the_key_and_field() {
        let e = Script::new(Side::Left, vec![key(0.0, 0.1, 0.0), key(0.0, 0.2, 0.0)])
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("keys[1].t"), "{e}");
        let e = Script::new(Side::Left, vec![key(0.0, f32::NAN, 0.0)]).unwrap_err().to_string();
        assert!(e.starts_with("keys[0].palm"), "{e}");
        let e = Script::new(Side::Left, vec![key(0.0, 0.1, 1.5)]).unwrap_err().to_string();
        assert!(e.starts_with("keys[0].curl"), "{e}");
        let e = Script::new(
            Side::Left,
            vec![Key {
                knuckle: Some(Curl::Each([0.0, 0.5, -0.1, 0.0, 0.0])),
                ..key(0.0, 0.1, 0.0)
            }],
        )
        .unwrap_err()
        .to_string();
        assert!(e.starts_with("keys[0].knuckle"), "{e}");
        assert!(Script::new(Side::Left, vec![]).is_err());
    }
}
