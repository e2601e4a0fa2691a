//! A synthetic user: a closed-loop controller of one tracked right hand
//! that moves the cube of the placement task (thesis §5.2) to its target
//! square, by either of the two ways the thesis's users placed it (§5.4):
//!
//! * [`Strategy::Lift`]: it reaches over the cube, descends, closes its
//!   grip, lifts, carries, lowers until the cube rests, opens and
//!   withdraws;
//! * [`Strategy::Slide`]: it grips the cube where it rests and slides it
//!   over the board between its fingers, then opens and withdraws.
//!
//! Then it looks: if the cube is farther from the target than the user's
//! tolerance, it corrects (at most [`MAX_CORRECTIONS`] times): a cube
//! nearly in place ([`NUDGE_BELOW`]) it nudges with its open hand's thumb,
//! one farther away it moves again the same way.
//!
//! It knows the cube only from glances ([`super::perception`]), never
//! contacts, forces or grabs, and drives every method the same way. Its
//! tracked hand is what a tracker reports: the intended hand `latency`
//! late, with real tracking noise on every joint and the dropouts of real
//! tracking ([`super::noise`]).
use super::board::CUBE_HALF;
use super::grip::grip;
use super::noise::{NoiseStream, Tracked};
use super::perception::Perception;
use crate::hand::{HandPose, HandSample, Side};
use crate::run::RunError;
use crate::run::drive::{HandSource, Observer, StepView};
use crate::scene::ObjectId;
use glam::{Quat, Vec3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::VecDeque;
use std::sync::{Arc, Mutex, PoisonError};

/// Re-grips after the first placement, at most.
pub const MAX_CORRECTIONS: usize = 3;
/// Hover height of the open hand over the cube before descending (m).
const HOVER: f32 = 0.06;
/// How high the cube is carried (m above resting).
const CARRY: f32 = 0.05;
/// A cube this far from the grip's centre has left the hand (m).
const DROPPED: f32 = 0.025;
/// How fast a slide moves, as a share of the user's speed.
const SLIDE_SPEED: f32 = 0.4;
/// A cube nearer its target than this is nudged, not picked up again: by
/// less than its half size it is nearly in place (m).
pub const NUDGE_BELOW: f32 = CUBE_HALF;
/// The longest a nudge pushes (s).
const PUSH_FOR: f64 = 4.0;

/// How a user moves the cube (thesis §5.4).
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Hash, Default, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "lowercase")]
pub enum Strategy {
    /// Lift it, carry it, lower it onto the target.
    #[default]
    Lift,
    /// Slide it over the board between the fingers.
    Slide,
}

impl Strategy {
    /// Both, in the order reports list them.
    pub const ALL: [Strategy; 2] = [Strategy::Lift, Strategy::Slide];

    /// Its name on the command line and in reports.
    pub fn name(self) -> &'static str {
        match self {
            Strategy::Lift => "lift",
            Strategy::Slide => "slide",
        }
    }
}

impl std::fmt::Display for Strategy {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for Strategy {
    type Err = String;

    fn from_str(s: &str) -> Result<Strategy, String> {
        Strategy::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| format!("unknown strategy \"{s}\": expected lift or slide"))
    }
}

/// One user's own parameters, drawn per user.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct UserParams {
    /// Tracking latency (s).
    pub latency: f64,
    /// Hand speed when far from a goal (m/s).
    pub speed: f32,
    /// How fast the hand closes on a goal (1/s): speed = gain × distance
    /// near it.
    pub gain: f32,
    /// The placement error the user accepts, as they see it (m).
    pub tolerance: f32,
    /// How deep the closed grip sinks the pads into the cube (m).
    pub squeeze: f32,
}

impl UserParams {
    /// A user drawn from `rng`.
    pub fn draw(rng: &mut ChaCha8Rng) -> UserParams {
        UserParams {
            latency: rng.random_range(0.015..=0.045),
            speed: rng.random_range(0.2..=0.4),
            gain: rng.random_range(4.0..=6.0),
            tolerance: rng.random_range(0.002..=0.005),
            squeeze: rng.random_range(0.003..=0.006),
        }
    }
}

/// What a user sees: the cube's pose after the last step, shared by the
/// [`Eyes`] that write it and the [`User`] (a hand source, so `Send`) that
/// reads it.
#[derive(Debug, Clone, Default)]
pub struct Sight(Arc<Mutex<Option<(Vec3, Quat)>>>);

impl Sight {
    /// Shows the cube at this pose (m).
    pub fn set(&self, pose: Option<(Vec3, Quat)>) {
        *self.0.lock().unwrap_or_else(PoisonError::into_inner) = pose;
    }

    /// The pose last shown, if any.
    pub fn get(&self) -> Option<(Vec3, Quat)> {
        *self.0.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

/// The observer that shows the cube's pose to a user.
pub struct Eyes {
    /// The cube.
    pub cube: ObjectId,
    /// Shared with the user.
    pub sight: Sight,
}

impl Observer for Eyes {
    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        let s = step.world.object_state(self.cube)?;
        self.sight.set(Some((s.position, s.rotation)));
        Ok(())
    }
}

/// Where the user is in the task.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Phase {
    Approach,
    Descend,
    Close {
        since: f64,
    },
    Lift,
    Carry,
    Lower {
        since: f64,
    },
    /// Sliding the gripped cube over the board.
    Slide,
    Release,
    /// Nudging the cube with the open hand's thumb towards the target.
    Push {
        since: f64,
    },
    Withdraw,
    Judge {
        since: f64,
    },
    Done,
}

/// The intended hand: the grip's centre (m), its yaw (rad) and closure.
#[derive(Debug, Clone, Copy)]
struct Intent {
    t: f64,
    at: Vec3,
    yaw: f32,
    closure: f32,
}

/// A synthetic user doing one trial: a [`HandSource`].
pub struct User<'a> {
    params: UserParams,
    strategy: Strategy,
    target: Vec3,
    sight: Sight,
    perception: Perception,
    /// The tracker's noise and dropouts, if any.
    tracking: Option<NoiseStream<'a>>,
    phase: Phase,
    intent: Intent,
    /// Recent intents, for the latency.
    history: VecDeque<Intent>,
    /// The tracker's last report, held through a short dropout.
    reported: Option<HandPose>,
    rng: ChaCha8Rng,
    corrections: usize,
    /// This correction nudges the cube instead of picking it up.
    nudge: bool,
    /// The nudge's yaw (rad), aimed at the first glance of the approach
    /// and kept: a person aims a nudge once, and a cube a few millimetres
    /// from its target, seen again at every glance, would point it anew
    /// each time within the glances' errors, so that the hand never came
    /// to rest behind it.
    aim: Option<f32>,
    /// Drops while the cube was lifted, carried or slid.
    pub drops: usize,
    /// When the user finished (s).
    pub done_at: Option<f64>,
    /// Where the cube truly was in the grip's frame (x from the thumb to
    /// the fingers, y up; m) when the hand first began to open on it, to
    /// set it down: what the grip does to it while held shows here.
    pub held_at: Option<Vec3>,
    last_t: f64,
}

impl<'a> User<'a> {
    /// A user with `params` who will move the cube to `target` (a square's
    /// centre, m) by `strategy`, seeing it through `perception`; its hand
    /// starts open at `start` (m), tracked with `tracking` noise if any.
    /// `seed` draws its glances and dropouts.
    pub fn new(
        params: UserParams,
        strategy: Strategy,
        target: Vec3,
        start: Vec3,
        (sight, perception): (Sight, Perception),
        tracking: Option<NoiseStream<'a>>,
        seed: u64,
    ) -> User<'a> {
        let intent = Intent { t: 0.0, at: start, yaw: 0.0, closure: 0.0 };
        User {
            params,
            strategy,
            target,
            sight,
            perception,
            tracking,
            phase: Phase::Approach,
            intent,
            history: VecDeque::new(),
            reported: None,
            rng: ChaCha8Rng::seed_from_u64(seed),
            corrections: 0,
            nudge: false,
            aim: None,
            drops: 0,
            done_at: None,
            held_at: None,
            last_t: 0.0,
        }
    }

    /// This user's first move is a nudge, as a correction of a cube
    /// nearly in place would be: it pushes instead of gripping.
    pub fn nudging(mut self) -> User<'a> {
        self.nudge = true;
        self
    }

    /// Moves the intended grip towards `goal` at the user's speed, slowing
    /// near it; returns the distance left (m).
    fn reach(&mut self, goal: Vec3, speed_share: f32, dt: f32) -> f32 {
        let gap = goal - self.intent.at;
        let speed = (self.params.speed * speed_share).min(self.params.gain * gap.length() + 0.002);
        self.intent.at += gap.clamp_length_max(speed * dt);
        (goal - self.intent.at).length()
    }

    /// Turns the intended yaw towards `yaw` at 2 rad/s; returns what is left.
    fn turn(&mut self, yaw: f32, dt: f32) -> f32 {
        let gap = yaw - self.intent.yaw;
        self.intent.yaw += gap.clamp(-2.0 * dt, 2.0 * dt);
        (yaw - self.intent.yaw).abs()
    }

    /// One control step at `t` (s), the cube truly at `truth`.
    fn control(&mut self, t: f64, dt: f32, truth: (Vec3, Quat)) {
        let carried =
            matches!(self.phase, Phase::Lift | Phase::Carry | Phase::Lower { .. } | Phase::Slide);
        let (cube, rotation) =
            self.perception.sees(t, truth, self.intent.at, carried, &mut self.rng);
        let to_target = (self.target - cube) * Vec3::new(1.0, 0.0, 1.0);
        let off = cube - self.intent.at;
        let lost = match self.phase {
            Phase::Slide => (off * Vec3::new(1.0, 0.0, 1.0)).length() > DROPPED,
            _ => off.y < -DROPPED,
        };
        if carried && lost {
            self.drops += 1;
            self.phase = Phase::Release;
        }
        let tolerance = self.params.tolerance;
        self.phase = match self.phase {
            Phase::Approach => {
                self.intent.closure = (self.intent.closure - dt / 0.3).max(0.0);
                let left = self.reach(cube + Vec3::Y * HOVER, 1.0, dt);
                // A nudge turns the thumb behind the cube, the fingers ahead.
                let yaw = if self.nudge {
                    *self.aim.get_or_insert_with(|| (-to_target.z).atan2(to_target.x))
                } else {
                    grip_yaw(rotation, self.intent.yaw)
                };
                let turn = self.turn(yaw, dt);
                if left < 0.002 && turn < 0.02 { Phase::Descend } else { Phase::Approach }
            }
            Phase::Descend => {
                let left = self.reach(cube, 0.5, dt);
                match (left < 0.0015, self.nudge) {
                    (false, _) => Phase::Descend,
                    (true, false) => Phase::Close { since: t },
                    (true, true) => Phase::Push { since: t },
                }
            }
            Phase::Close { since } if t - since <= 0.5 => {
                self.intent.closure = (self.intent.closure + dt / 0.35).min(1.0);
                Phase::Close { since }
            }
            Phase::Close { .. } => match self.strategy {
                Strategy::Lift => Phase::Lift,
                Strategy::Slide => Phase::Slide,
            },
            Phase::Lift => {
                let goal = Vec3::new(self.intent.at.x, CUBE_HALF + CARRY, self.intent.at.z);
                if self.reach(goal, 0.5, dt) < 0.001 { Phase::Carry } else { Phase::Lift }
            }
            Phase::Carry => {
                let goal = self.intent.at + to_target;
                let goal = Vec3::new(goal.x, CUBE_HALF + CARRY, goal.z);
                self.reach(goal, 1.0, dt);
                if to_target.length() < tolerance {
                    Phase::Lower { since: t }
                } else {
                    Phase::Carry
                }
            }
            Phase::Slide => {
                // The hand keeps its height, so the cube stays on the board.
                self.reach(self.intent.at + to_target, SLIDE_SPEED, dt);
                if to_target.length() < tolerance {
                    self.let_go(truth.0);
                    Phase::Release
                } else {
                    Phase::Slide
                }
            }
            Phase::Lower { since } => {
                let above = cube.y - CUBE_HALF;
                let goal = self.intent.at + to_target - Vec3::Y * above;
                self.reach(goal, 0.25, dt);
                let rests = above < 0.001 || t - since > 3.0;
                if rests {
                    self.let_go(truth.0);
                    Phase::Release
                } else {
                    Phase::Lower { since }
                }
            }
            Phase::Release => {
                self.intent.closure = (self.intent.closure - dt / 0.3).max(0.0);
                if self.intent.closure == 0.0 { Phase::Withdraw } else { Phase::Release }
            }
            Phase::Push { since } => {
                // Closed loop on the cube: push while it is short of the
                // target, keeping the hand's height.
                let goal = self.intent.at + to_target;
                self.reach(goal, 0.25, dt);
                let there = to_target.length() < 0.5 * tolerance;
                if there || t - since > PUSH_FOR {
                    self.nudge = false;
                    Phase::Withdraw
                } else {
                    Phase::Push { since }
                }
            }
            Phase::Withdraw => {
                let goal = Vec3::new(self.intent.at.x, cube.y + HOVER, self.intent.at.z);
                if self.reach(goal, 0.5, dt) < 0.002 {
                    Phase::Judge { since: t }
                } else {
                    Phase::Withdraw
                }
            }
            Phase::Judge { since } if t - since < 0.3 => Phase::Judge { since },
            Phase::Judge { .. } => {
                if to_target.length() <= tolerance || self.corrections >= MAX_CORRECTIONS {
                    self.done_at = Some(t);
                    Phase::Done
                } else {
                    self.corrections += 1;
                    self.nudge = to_target.length() < NUDGE_BELOW;
                    self.aim = None;
                    Phase::Approach
                }
            }
            Phase::Done => Phase::Done,
        };
    }

    /// Notes where the cube, truly at `cube`, sits in the grip as the hand
    /// first begins to open on it.
    fn let_go(&mut self, cube: Vec3) {
        let local = Quat::from_rotation_y(-self.intent.yaw) * (cube - self.intent.at);
        self.held_at.get_or_insert(local);
    }

    /// The intent the tracker reports at `t`: the one `latency` ago.
    fn delayed(&mut self, t: f64) -> Intent {
        let then = t - self.params.latency;
        while self.history.len() > 1 && self.history[1].t <= then {
            self.history.pop_front();
        }
        self.history.front().copied().unwrap_or(self.intent)
    }
}

/// The grip's yaw for a cube turned by `rotation`: the cube's yaw, taken
/// to the face nearest the hand's current yaw (a cube has four sides).
fn grip_yaw(rotation: Quat, current: f32) -> f32 {
    let x = rotation * Vec3::X;
    let yaw = (-x.z).atan2(x.x);
    let quarter = std::f32::consts::FRAC_PI_2;
    yaw + ((current - yaw) / quarter).round() * quarter
}

impl HandSource for User<'_> {
    fn side(&self) -> Side {
        Side::Right
    }

    fn sample(&mut self, t: f64) -> Result<Option<HandSample>, RunError> {
        let dt = (t - self.last_t).max(0.0) as f32;
        self.last_t = t;
        if let Some(truth) = self.sight.get()
            && self.phase != Phase::Done
        {
            self.control(t, dt, truth);
        }
        self.intent.t = t;
        self.history.push_back(self.intent);
        let seen = self.delayed(t);
        let pose = grip(CUBE_HALF, seen.closure, self.params.squeeze).transformed(
            Vec3::ZERO,
            Quat::from_rotation_y(seen.yaw),
            seen.at,
        );
        let reported = match self.tracking.as_mut().map(|s| s.at(t, &mut self.rng)) {
            None => Some(pose),
            Some(Tracked::Hand(noise)) => Some(noise.apply(&pose)),
            Some(Tracked::Held) => self.reported.clone(),
            Some(Tracked::Lost) => None,
        };
        self.reported.clone_from(&reported);
        Ok(reported.map(HandSample::from_pose))
    }

    fn finished(&self) -> bool {
        self.phase == Phase::Done
    }
}

#[cfg(test)]
mod tests {
    use super::super::perception::EYE;
    use super::*;

    #[test]
    fn a_nudge_is_aimed_once_so_the_hand_comes_to_rest_behind_the_cube() {
        // A cube 3.5 mm short of its target along −x, seen through the
        // headset's glance errors, which are as large: the direction to
        // the target changes from glance to glance, here across ±π. A hand
        // that turned to each would keep turning, and never settle behind
        // the cube to push it (a trial of the noise sweep ran out of time
        // so).
        let params =
            UserParams { latency: 0.03, speed: 0.3, gain: 5.0, tolerance: 0.003, squeeze: 0.004 };
        let cube = Vec3::new(0.03, CUBE_HALF, 0.075);
        let target = cube + Vec3::new(-0.0035, 0.0, 0.0004);
        let start = cube + Vec3::new(-0.1, 0.15, 0.0);
        for seed in [2, 5, 11, 17, 23] {
            let eyes = (Sight::default(), Perception::new(EYE, 1.0));
            let mut user =
                User::new(params, Strategy::Lift, target, start, eyes, None, seed).nudging();
            let (dt, mut t) = (0.001, 0.0);
            while user.phase == Phase::Approach && t < 5.0 {
                user.control(t, dt, (cube, Quat::IDENTITY));
                t += f64::from(dt);
            }
            // 15 cm at 0.3 m/s while turning half a turn at 2 rad/s: about
            // 1.5 s. Aimed at every glance, most seeds were still
            // approaching at 5 s.
            assert!(t < 2.5, "seed {seed}: still approaching after {t:.1} s");
        }
    }
}
