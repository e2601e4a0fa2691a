//! A scenario's checks: what is measured on the run's history, and the
//! bound it must meet.

pub use super::history::History;
use glam::{Quat, Vec3};

/// One check of a scenario file: a measure and its bound (`min`, `max` or
/// both), in the measure's unit.
#[derive(Debug, Clone, PartialEq, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Check {
    /// The check's name, for the report.
    pub name: String,
    /// What is measured.
    pub measure: Measure,
    /// Lower bound, if any.
    #[serde(default)]
    pub min: Option<f32>,
    /// Upper bound, if any.
    #[serde(default)]
    pub max: Option<f32>,
}

/// What a check measures. Times are seconds from the start; a missing `to`
/// is the end of the run. Objects are named as in the scene.
#[derive(Debug, Clone, PartialEq, serde::Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Measure {
    /// How far the object moved from `from` to `to` (m): along the unit
    /// `axis` if given (signed), else the distance.
    Displacement {
        /// The object's name in the scene.
        object: String,
        /// Start time (s).
        from: f32,
        /// End time (s); `None` is the end of the run.
        to: Option<f32>,
        /// Unit axis (world) to measure along, if any.
        axis: Option<Vec3>,
    },
    /// The object's height (y) at `at` (m).
    Height {
        /// The object's name in the scene.
        object: String,
        /// Time (s).
        at: f32,
    },
    /// The object's lowest height over [`from`, `to`] (m).
    MinHeight {
        /// The object's name in the scene.
        object: String,
        /// Start time (s).
        from: f32,
        /// End time (s); `None` is the end of the run.
        to: Option<f32>,
    },
    /// The largest distance of the object from where it was at `from`, in
    /// the palm frame of hand `hand` (index in the file), over
    /// [`from`, `to`] (m): how much it moved in the hand.
    DriftInHand {
        /// The object's name in the scene.
        object: String,
        /// Index of the hand in the scenario file.
        hand: usize,
        /// Start time (s).
        from: f32,
        /// End time (s); `None` is the end of the run.
        to: Option<f32>,
    },
    /// The largest angle by which the object turned in the palm frame of
    /// hand `hand` since `from`, over [`from`, `to`] (degrees).
    TurnInHand {
        /// The object's name in the scene.
        object: String,
        /// Index of the hand in the scenario file.
        hand: usize,
        /// Start time (s).
        from: f32,
        /// End time (s); `None` is the end of the run.
        to: Option<f32>,
    },
    /// The object's rotation from `from` to `to` (degrees): about the unit
    /// world `axis` if given (signed, right-handed), else the whole angle.
    Rotation {
        /// The object's name in the scene.
        object: String,
        /// Start time (s).
        from: f32,
        /// End time (s); `None` is the end of the run.
        to: Option<f32>,
        /// Unit axis (world) to measure the turn about, if any.
        axis: Option<Vec3>,
    },
    /// The angle between the object's local +y axis and world up at `at`
    /// (degrees).
    Tilt {
        /// The object's name in the scene.
        object: String,
        /// Time (s).
        at: f32,
    },
    /// The object's mean acceleration from `from` to `to` along the unit
    /// world `axis` (m/s²): its velocity's change along the axis over the
    /// time between, as Newton's second law reads it for a steady force
    /// (a ball rolling down a slope).
    Acceleration {
        /// The object's name in the scene.
        object: String,
        /// Start time (s).
        from: f32,
        /// End time (s); after `from`.
        to: f32,
        /// Unit axis (world) to measure along.
        axis: Vec3,
    },
    /// The object's speed at `at` (m/s).
    Speed {
        /// The object's name in the scene.
        object: String,
        /// Time (s).
        at: f32,
    },
    /// The largest displacement from `from` to `to` among the objects whose
    /// name starts with `prefix`, except those in `except` (m).
    GroupDisplacement {
        /// The start of the group's object names.
        prefix: String,
        /// Names of objects left out of the group.
        #[serde(default)]
        except: Vec<String>,
        /// Start time (s).
        from: f32,
        /// End time (s); `None` is the end of the run.
        to: Option<f32>,
    },
    /// The largest horizontal distance of the object's centre from the
    /// polyline through `path` ([x, z] points, m) over [`from`, `to`] (m).
    PathDeviation {
        /// The object's name in the scene.
        object: String,
        /// The polyline's points, `[x, z]` (world, m).
        path: Vec<[f32; 2]>,
        /// Start time (s).
        from: f32,
        /// End time (s); `None` is the end of the run.
        to: Option<f32>,
    },
    /// Hand contacts that press on the object at `at`: those whose normal
    /// force is positive, the first clause of Eq. 3.7 (`f · n > 0`; state
    /// static or dynamic, not separated). A bone within the contact offset
    /// that does not press has a contact but transmits no force, so it does
    /// not count: two pressing contacts can squeeze, two touching ones
    /// cannot. There is no threshold above zero: the spring has no dead band,
    /// so a pressing contact carries force (γ times its depth) however
    /// shallow; whether the forces are enough is what a scenario's other
    /// checks (lifted, drift in the hand) test.
    Contacts {
        /// The object's name in the scene.
        object: String,
        /// Time (s).
        at: f32,
    },
    /// The object's speed at its release (m/s): its state after the last
    /// step in [`from`, `to`] in which a hand contact pressed on it (as
    /// `contacts` counts them), when the last force from a hand acted. With
    /// no pressing contact in the window, or one still pressing at its end,
    /// it was not released: the value is not a number and the check fails.
    ReleaseSpeed {
        /// The object's name in the scene.
        object: String,
        /// Start time (s).
        from: f32,
        /// End time (s); `None` is the end of the run.
        to: Option<f32>,
    },
    /// How far from the prediction the released object lands (m): the
    /// distance between where its centre first comes down to `height`
    /// after the release (as `release_speed`) and where ballistic flight
    /// from its release position and velocity, under the config's gravity,
    /// comes down to the same height. Not released, or not landed by the
    /// end of the run: not a number, and the check fails.
    LandingError {
        /// The object's name in the scene.
        object: String,
        /// Start time (s) of the window in which it is released.
        from: f32,
        /// End time (s) of that window; `None` is the end of the run.
        to: Option<f32>,
        /// Height (world y, m) of its centre when it lands: the ground's
        /// height plus, e.g., a ball's radius.
        height: f32,
    },
    /// Horizontal (x–z) distance from `target` ([x, z], m) of where the
    /// released object lands, as for `landing_error` (m).
    LandingDistance {
        /// The object's name in the scene.
        object: String,
        /// Start time (s) of the window in which it is released.
        from: f32,
        /// End time (s) of that window; `None` is the end of the run.
        to: Option<f32>,
        /// Height (world y, m) of its centre when it lands.
        height: f32,
        /// The target, `[x, z]` (world, m).
        target: [f32; 2],
    },
    /// The mean, over the steps of [`from`, `to`], of the hand contacts'
    /// total force on the object (Eq. 3.10) along the unit world `axis`
    /// (N): what the hands push or pull it with, to set against what
    /// resists it, such as μ·m·g on the ground.
    HandForce {
        /// The object's name in the scene.
        object: String,
        /// Start time (s).
        from: f32,
        /// End time (s); `None` is the end of the run.
        to: Option<f32>,
        /// Unit axis (world) to measure along.
        axis: Vec3,
    },
}

/// What is wrong with a check, found before a run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CheckError {
    /// Neither `min` nor `max`.
    #[error("needs a bound: min, max or both")]
    NoBound,
    /// A bound is NaN or infinite (a number too large for `f32`).
    #[error("{bound}: must be finite, got {value}")]
    BoundNotFinite {
        /// `min` or `max`.
        bound: &'static str,
        /// Its value.
        value: f32,
    },
    /// An axis that is not a unit vector.
    #[error("measure.axis: must be a unit vector, got {0:?}")]
    Axis(Vec3),
    /// A path of fewer than two finite points.
    #[error("measure.path: needs at least two finite [x, z] points")]
    Path,
    /// A window whose end is not after its start.
    #[error("measure.to: must be after measure.from ({from}), got {to}")]
    Window {
        /// Its start (s).
        from: f32,
        /// Its end (s).
        to: f32,
    },
    /// A landing height or target that is not finite.
    #[error("measure.{field}: must be finite, got {value}")]
    NotFinite {
        /// `height` or `target`.
        field: &'static str,
        /// The first value that is not.
        value: f32,
    },
}

/// The outcome of one check.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct CheckResult {
    /// The check's name.
    pub name: String,
    /// The measured value, in the measure's unit.
    pub value: f32,
    /// The bound as text, e.g. `>= 0.05` or `<= 0.01`.
    pub bound: String,
    /// Whether the value is finite and within the bound.
    pub passed: bool,
}

impl Check {
    /// The objects and hands the check refers to, for validation before a
    /// run: object names, group prefix, and the hand index.
    pub(crate) fn references(&self) -> (Vec<&str>, Option<usize>) {
        match &self.measure {
            Measure::Displacement { object, .. }
            | Measure::Height { object, .. }
            | Measure::MinHeight { object, .. }
            | Measure::Rotation { object, .. }
            | Measure::Tilt { object, .. }
            | Measure::Speed { object, .. }
            | Measure::Acceleration { object, .. }
            | Measure::PathDeviation { object, .. }
            | Measure::Contacts { object, .. }
            | Measure::ReleaseSpeed { object, .. }
            | Measure::LandingError { object, .. }
            | Measure::LandingDistance { object, .. }
            | Measure::HandForce { object, .. } => (vec![object.as_str()], None),
            Measure::DriftInHand { object, hand, .. }
            | Measure::TurnInHand { object, hand, .. } => (vec![object.as_str()], Some(*hand)),
            Measure::GroupDisplacement { except, .. } => {
                (except.iter().map(String::as_str).collect(), None)
            }
        }
    }

    /// Checks what can be checked without a run: a bound, finite numbers
    /// (bounds, landing heights and targets), unit axes, a path of at least
    /// two points.
    pub(crate) fn validate(&self) -> Result<(), CheckError> {
        if self.min.is_none() && self.max.is_none() {
            return Err(CheckError::NoBound);
        }
        for (bound, value) in [("min", self.min), ("max", self.max)] {
            if let Some(value) = value.filter(|v| !v.is_finite()) {
                return Err(CheckError::BoundNotFinite { bound, value });
            }
        }
        let landing = match &self.measure {
            Measure::LandingError { height, .. } => vec![("height", *height)],
            Measure::LandingDistance { height, target, .. } => {
                vec![("height", *height), ("target", target[0]), ("target", target[1])]
            }
            _ => vec![],
        };
        if let Some((field, value)) = landing.into_iter().find(|(_, v)| !v.is_finite()) {
            return Err(CheckError::NotFinite { field, value });
        }
        if let Measure::Acceleration { from, to, .. } = &self.measure
            && to <= from
        {
            return Err(CheckError::Window { from: *from, to: *to });
        }
        let axis = match &self.measure {
            Measure::Displacement { axis, .. } | Measure::Rotation { axis, .. } => *axis,
            Measure::HandForce { axis, .. } | Measure::Acceleration { axis, .. } => Some(*axis),
            Measure::PathDeviation { path, .. }
                if path.len() < 2 || path.iter().flatten().any(|v| !v.is_finite()) =>
            {
                return Err(CheckError::Path);
            }
            _ => None,
        };
        match axis {
            Some(a) if !(a.is_finite() && (a.length() - 1.0).abs() < 1e-3) => {
                Err(CheckError::Axis(a))
            }
            _ => Ok(()),
        }
    }

    /// Measures the check on a run's history. Objects were validated, so
    /// lookups by name succeed. An empty history (no step) fails the check.
    pub fn evaluate(&self, h: &History) -> CheckResult {
        if h.poses.is_empty() {
            return self.result(f32::NAN);
        }
        let index = |name: &str| h.names.iter().position(|n| n == name).unwrap_or(0);
        let pose = |o: usize, t: f32| h.poses[h.step(t)][o];
        let value = match &self.measure {
            Measure::Displacement { object, from, to, axis } => {
                let o = index(object);
                let d = pose(o, to.unwrap_or(h.end())).0 - pose(o, *from).0;
                axis.map_or(d.length(), |a| d.dot(a))
            }
            Measure::Height { object, at } => pose(index(object), *at).0.y,
            Measure::MinHeight { object, from, to } => {
                let o = index(object);
                h.steps(*from, *to).map(|s| h.poses[s][o].0.y).fold(f32::INFINITY, f32::min)
            }
            Measure::DriftInHand { object, hand, from, to } => {
                let o = index(object);
                let local =
                    |s: usize| h.palms[s][*hand].map(|(c, r)| r.inverse() * (h.poses[s][o].0 - c));
                let reference = local(h.step(*from));
                h.steps(*from, *to)
                    .map(|s| match (reference, local(s)) {
                        (Some(a), Some(b)) => a.distance(b),
                        _ => f32::INFINITY, // the hand was not tracked
                    })
                    .fold(0.0, f32::max)
            }
            Measure::TurnInHand { object, hand, from, to } => {
                let o = index(object);
                let local =
                    |s: usize| h.palms[s][*hand].map(|(_, r)| r.inverse() * h.poses[s][o].1);
                let reference = local(h.step(*from));
                h.steps(*from, *to)
                    .map(|s| match (reference, local(s)) {
                        (Some(a), Some(b)) => a.angle_between(b).to_degrees(),
                        _ => f32::INFINITY,
                    })
                    .fold(0.0, f32::max)
            }
            Measure::Rotation { object, from, to, axis } => {
                let o = index(object);
                let (a, b) = (pose(o, *from).1, pose(o, to.unwrap_or(h.end())).1);
                let delta = b * a.inverse();
                match axis {
                    None => delta.angle_between(Quat::IDENTITY).to_degrees(),
                    Some(axis) => {
                        // Twist about `axis` (swing–twist decomposition).
                        let v = Vec3::new(delta.x, delta.y, delta.z);
                        let p = axis * v.dot(*axis);
                        let twist = Quat::from_xyzw(p.x, p.y, p.z, delta.w).normalize();
                        let (ax, angle) = twist.to_axis_angle();
                        let signed = if ax.dot(*axis) < 0.0 { -angle } else { angle };
                        let wrapped = (signed + std::f32::consts::PI)
                            .rem_euclid(std::f32::consts::TAU)
                            - std::f32::consts::PI;
                        wrapped.to_degrees()
                    }
                }
            }
            Measure::Tilt { object, at } => {
                (pose(index(object), *at).1 * Vec3::Y).angle_between(Vec3::Y).to_degrees()
            }
            Measure::Speed { object, at } => h.velocities[h.step(*at)][index(object)].length(),
            Measure::Acceleration { object, from, to, axis } => {
                let (o, a, b) = (index(object), h.step(*from), h.step(*to));
                let dv = (h.velocities[b][o] - h.velocities[a][o]).dot(*axis);
                // A run that ended before `from`: no time between.
                if b > a { dv / ((b - a) as f32 * h.dt) } else { f32::NAN }
            }
            Measure::GroupDisplacement { prefix, except, from, to } => {
                let (a, b) = (h.step(*from), h.step(to.unwrap_or(h.end())));
                h.names
                    .iter()
                    .enumerate()
                    .filter(|(_, n)| n.starts_with(prefix.as_str()) && !except.contains(n))
                    .map(|(o, _)| h.poses[a][o].0.distance(h.poses[b][o].0))
                    .fold(0.0, f32::max)
            }
            Measure::PathDeviation { object, path, from, to } => {
                let o = index(object);
                h.steps(*from, *to)
                    .map(|s| distance_to_path(h.poses[s][o].0, path))
                    .fold(0.0, f32::max)
            }
            Measure::Contacts { object, at } => h.contacts[h.step(*at)][index(object)] as f32,
            Measure::HandForce { object, from, to, axis } => {
                let o = index(object);
                let steps = h.steps(*from, *to);
                let n = steps.clone().count() as f32;
                steps.map(|s| h.hand_forces[s][o].dot(*axis)).sum::<f32>() / n
            }
            Measure::ReleaseSpeed { object, from, to } => {
                let o = index(object);
                h.release(o, *from, *to).map_or(f32::NAN, |s| h.velocities[s][o].length())
            }
            Measure::LandingError { object, from, to, height } => h
                .landed_and_predicted(index(object), (*from, *to), *height)
                .map_or(f32::NAN, |(landed, predicted)| landed.distance(predicted)),
            Measure::LandingDistance { object, from, to, height, target } => h
                .landed_and_predicted(index(object), (*from, *to), *height)
                .map_or(f32::NAN, |(landed, _)| {
                    glam::Vec2::new(landed.x, landed.z).distance(glam::Vec2::from(*target))
                }),
        };
        self.result(value)
    }

    /// The check's outcome for a measured `value`.
    fn result(&self, value: f32) -> CheckResult {
        let (min_ok, max_ok) =
            (self.min.is_none_or(|m| value >= m), self.max.is_none_or(|m| value <= m));
        let bound = match (self.min, self.max) {
            (Some(a), Some(b)) => format!("{a} ..= {b}"),
            (Some(a), None) => format!(">= {a}"),
            (None, Some(b)) => format!("<= {b}"),
            (None, None) => String::new(),
        };
        CheckResult {
            name: self.name.clone(),
            value,
            bound,
            passed: value.is_finite() && min_ok && max_ok,
        }
    }
}

/// Horizontal (x–z) distance from `p` to the polyline through `path`.
fn distance_to_path(p: Vec3, path: &[[f32; 2]]) -> f32 {
    let q = glam::Vec2::new(p.x, p.z);
    path.windows(2)
        .map(|w| {
            let (a, b) = (glam::Vec2::from(w[0]), glam::Vec2::from(w[1]));
            let ab = b - a;
            let s = ((q - a).dot(ab) / ab.length_squared().max(f32::MIN_POSITIVE)).clamp(0.0, 1.0);
            q.distance(a + ab * s)
        })
        .fold(f32::INFINITY, f32::min)
}

#[cfg(test)]
mod tests;
