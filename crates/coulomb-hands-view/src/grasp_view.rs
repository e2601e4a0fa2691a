//! The view that shows the grasp: of a few directions round the run's
//! volume, the one from which the most of the hands' pressing contacts are
//! in sight, not hidden behind a palm or the object itself. A hand grasps
//! from above, so the default view, from behind and above, often looks at
//! the back of the palm, with the object and the fingertips under it.
//!
//! The contacts are sampled while the camera's `Framing::of_run` plays
//! the run headlessly; each view is then scored by straight lines from its
//! eye to each sampled contact point. Only what hides a contact counts,
//! not how it looks: a view that sees them all from the default direction
//! keeps it.

use glam::{Quat, Vec3};
use rapier3d::math::Pose;
use rapier3d::parry::query::Ray;
use rapier3d::parry::shape::SharedShape;

use coulomb_hands::hand::{Bone, BoneShape, Capsule, HandId, HandPose, Palm};
use coulomb_hands::pipeline::InteractionWorld;

/// The directions tried: turns about the vertical (°), the default's first,
/// then every 30°.
const YAWS_DEG: [f32; 12] =
    [0.0, 30.0, -30.0, 60.0, -60.0, 90.0, -90.0, 120.0, -120.0, 150.0, -150.0, 180.0];
/// The elevation a camera starts at, unless a run's grasps or the user
/// say otherwise (rad, about 32°).
pub const DEFAULT_PITCH: f32 = 0.55;
/// Elevations tried (rad): the default's first, then 18° and 50°.
const PITCHES: [f32; 3] = [DEFAULT_PITCH, 0.314, 0.873];
/// The most contact points kept to score the views by: more are thinned
/// evenly over the run.
const MOST_SAMPLES: usize = 400;
/// How far short of a contact point a line of sight stops (m): the bone
/// pressing there, and the object's own surface, are that close.
const SHORT_OF: f32 = 0.003;

/// One pressing contact, with what could hide it at that moment.
#[derive(Clone)]
struct Sample {
    /// The contact point C (world, m).
    point: Vec3,
    /// The contact normal at C (world, unit), out of the object.
    normal: Vec3,
    /// Where its object's colliders were.
    object: Vec<(SharedShape, Pose)>,
    /// The palms of the hands tracked at that moment.
    palms: Vec<Palm>,
    /// Their fingers' bones, but the one pressing here.
    fingers: Vec<Capsule>,
}

/// Contact points gathered over a run.
#[derive(Default, Clone)]
pub struct GraspSamples(Vec<Sample>);

impl GraspSamples {
    /// Adds the contacts that press in `world` now.
    pub fn add(&mut self, world: &InteractionWorld) {
        let hands: Vec<(HandId, &HandPose)> = (0..world.hand_count())
            .filter_map(|i| world.hand_pose(HandId(i as u32)).map(|p| (HandId(i as u32), p)))
            .collect();
        for contact in world.contacts().iter().filter(|c| c.normal_force > 0.0) {
            let Some(body) = world.object_body(contact.object) else { continue };
            let Some(body) = world.physics().bodies.get(body) else { continue };
            let colliders =
                body.colliders().iter().filter_map(|h| world.physics().colliders.get(*h));
            let object = colliders.map(|c| (c.shared_shape().clone(), *c.position())).collect();
            let palms = hands.iter().map(|(_, p)| p.palm).collect();
            let pressing = |hand: HandId, bone: Bone| hand == contact.hand && bone == contact.bone;
            let fingers = hands
                .iter()
                .flat_map(|&(hand, pose)| {
                    Bone::all().filter(move |&b| !pressing(hand, b)).filter_map(|b| {
                        match pose.bone(b) {
                            BoneShape::Capsule(c) => Some(c),
                            BoneShape::Palm(_) => None,
                        }
                    })
                })
                .collect();
            let (point, normal) = (contact.point, contact.normal);
            self.0.push(Sample { point, normal, object, palms, fingers });
        }
    }

    /// The (yaw, pitch) (rad) that shows the sampled contacts best from
    /// `distance` (m) off `center`: by the sum, over the contacts in sight,
    /// of how far across each contact's normal the line of sight runs
    /// (1 − |cos| of their angle). From its side a contact shows the bone
    /// and the object both; along its normal, the bone covers it. The first
    /// best of the tried directions, so the default's when it does as well
    /// as any. `None` with no contact.
    pub fn view(&self, center: Vec3, distance: f32) -> Option<(f32, f32)> {
        if self.0.is_empty() {
            return None;
        }
        let every = self.0.len().div_ceil(MOST_SAMPLES);
        let samples: Vec<&Sample> = self.0.iter().step_by(every).collect();
        let mut best: Option<((f32, f32), f32)> = None;
        for pitch in PITCHES {
            for yaw in YAWS_DEG.map(f32::to_radians) {
                let eye = center + back(yaw, pitch) * distance;
                let score: f32 = samples.iter().filter_map(|s| shown(eye, s)).sum();
                if best.is_none_or(|(_, most)| score > most + 1e-3) {
                    best = Some(((yaw, pitch), score));
                }
            }
        }
        best.map(|(view, _)| view)
    }

    /// How many contacts were sampled.
    pub fn len(&self) -> usize {
        self.0.len()
    }

    /// Whether none was.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// The share of the sampled contacts in sight from the view at `yaw`
    /// and `pitch` (rad), `distance` (m) off `center`.
    pub fn share_in_sight(&self, center: Vec3, distance: f32, yaw: f32, pitch: f32) -> f32 {
        let eye = center + back(yaw, pitch) * distance;
        let seen = self.0.iter().filter(|s| in_sight(eye, s)).count();
        seen as f32 / self.0.len().max(1) as f32
    }
}

/// How far across its normal the line of sight from `eye` to a contact
/// runs (1 − |cos|), or `None` if something hides it.
fn shown(eye: Vec3, sample: &Sample) -> Option<f32> {
    let dir = (sample.point - eye).try_normalize()?;
    in_sight(eye, sample).then(|| 1.0 - dir.dot(sample.normal).abs())
}

/// The direction from the focus to the eye of a view at `yaw` and `pitch`
/// (rad), as the orbit camera places its eye.
pub fn back(yaw: f32, pitch: f32) -> Vec3 {
    Quat::from_euler(glam::EulerRot::YXZ, yaw, pitch, 0.0) * Vec3::NEG_Z
}

/// Whether the straight line from `eye` to the sample's contact point
/// misses every palm and its object's colliders, up to a few millimetres
/// short of the point.
fn in_sight(eye: Vec3, sample: &Sample) -> bool {
    let to = sample.point - eye;
    let length = to.length() - SHORT_OF;
    let Some(dir) = to.try_normalize() else { return true };
    if length <= 0.0 {
        return true;
    }
    let hidden_by_palm = sample.palms.iter().any(|p| segment_hits_box(eye, dir, length, p));
    let end = eye + dir * length;
    let hidden_by_finger = sample.fingers.iter().any(|c| segment_meets_capsule(eye, end, c));
    if hidden_by_palm || hidden_by_finger {
        return false;
    }
    let ray = Ray::new(eye, dir);
    let hidden_by_object = sample
        .object
        .iter()
        .any(|(shape, pose)| shape.cast_ray(pose, &ray, length, true).is_some());
    !(hidden_by_palm || hidden_by_object)
}

/// Whether the segment from `origin` along the unit `dir` for `length` (m)
/// meets the palm's box (the slab test in the box's own frame).
fn segment_hits_box(origin: Vec3, dir: Vec3, length: f32, palm: &Palm) -> bool {
    let inverse = palm.rotation.inverse();
    let (o, d) = (inverse * (origin - palm.center), inverse * dir);
    let (mut near, mut far) = (0.0f32, length);
    for axis in 0..3 {
        let h = palm.half_extents[axis];
        if d[axis].abs() < 1e-9 {
            if o[axis].abs() > h {
                return false;
            }
            continue;
        }
        let (a, b) = ((-h - o[axis]) / d[axis], (h - o[axis]) / d[axis]);
        near = near.max(a.min(b));
        far = far.min(a.max(b));
        if near > far {
            return false;
        }
    }
    true
}

/// Whether the segment `p`–`q` comes within the capsule's radius of its
/// axis (closest points of two segments).
fn segment_meets_capsule(p: Vec3, q: Vec3, capsule: &Capsule) -> bool {
    let (d1, d2) = (q - p, capsule.b - capsule.a);
    let r = p - capsule.a;
    let (a, e, f) = (d1.length_squared(), d2.length_squared(), d2.dot(r));
    let (c, b) = (d1.dot(r), d1.dot(d2));
    let (s, t) = if a <= f32::EPSILON {
        (0.0, if e > f32::EPSILON { (f / e).clamp(0.0, 1.0) } else { 0.0 })
    } else if e <= f32::EPSILON {
        ((-c / a).clamp(0.0, 1.0), 0.0)
    } else {
        let denom = a * e - b * b;
        let s = if denom > f32::EPSILON { ((b * f - c * e) / denom).clamp(0.0, 1.0) } else { 0.0 };
        let t = (b * s + f) / e;
        if t < 0.0 {
            ((-c / a).clamp(0.0, 1.0), 0.0)
        } else if t > 1.0 {
            (((b - c) / a).clamp(0.0, 1.0), 1.0)
        } else {
            (s, t)
        }
    };
    (p + d1 * s).distance(capsule.a + d2 * t) <= capsule.radius
}

#[cfg(test)]
mod tests {
    use super::*;

    fn palm_above() -> Palm {
        Palm {
            center: Vec3::new(0.0, 0.1, 0.0),
            rotation: Quat::IDENTITY,
            half_extents: Vec3::new(0.04, 0.01, 0.045),
        }
    }

    #[test]
    fn a_segment_meets_a_box_only_when_it_passes_through_it() {
        let palm = palm_above();
        let down = Vec3::NEG_Y;
        assert!(segment_hits_box(Vec3::new(0.0, 0.5, 0.0), down, 0.45, &palm));
        // Stopping short of it, or passing beside it.
        assert!(!segment_hits_box(Vec3::new(0.0, 0.5, 0.0), down, 0.3, &palm));
        assert!(!segment_hits_box(Vec3::new(0.05, 0.5, 0.0), down, 1.0, &palm));
        // Turned 90° about y, the box is 9 cm wide along x.
        let turned = Palm { rotation: Quat::from_rotation_y(std::f32::consts::FRAC_PI_2), ..palm };
        assert!(segment_hits_box(Vec3::new(0.043, 0.5, 0.0), down, 1.0, &turned));
    }

    #[test]
    fn a_point_under_a_palm_is_seen_from_the_side_not_from_above() {
        // A contact on the side of a cube under the palm, as a pinch from
        // above holds it, and the cube itself.
        let cube = SharedShape::cuboid(0.016, 0.016, 0.016);
        let pose = Pose::from_translation(Vec3::new(0.0, 0.07, 0.0));
        let sample = Sample {
            point: Vec3::new(0.0, 0.07, -0.016),
            normal: Vec3::NEG_Z,
            object: vec![(cube, pose)],
            palms: vec![palm_above()],
            fingers: vec![],
        };
        let samples = GraspSamples(vec![sample.clone()]);
        let from = |yaw: f32, pitch: f32| Vec3::new(0.0, 0.07, 0.0) + back(yaw, pitch) * 0.5;
        // Straight above: the palm hides it; from the far side, the cube.
        assert!(!in_sight(from(0.0, 1.5), &sample));
        assert!(!in_sight(from(std::f32::consts::PI, 0.3), &sample));
        // From its side (−z, the default's yaw), low, it is in sight.
        assert!(in_sight(from(0.0, 0.3), &sample));
        // Seen along its normal it shows least: the chosen view looks at
        // it from a side, where it is in sight.
        let (yaw, pitch) = samples.view(Vec3::new(0.0, 0.07, 0.0), 0.5).expect("a view");
        assert!(in_sight(from(yaw, pitch), &sample), "yaw {yaw} pitch {pitch}");
        assert!(back(yaw, pitch).dot(Vec3::NEG_Z).abs() < 0.9, "yaw {yaw} pitch {pitch}");
        // A finger across the line of sight hides it.
        let finger = Capsule {
            a: Vec3::new(-0.05, 0.07, -0.1),
            b: Vec3::new(0.05, 0.07, -0.1),
            radius: 0.008,
        };
        assert!(!in_sight(from(0.0, 0.0), &Sample { fingers: vec![finger], ..sample }));
        assert_eq!(GraspSamples::default().view(Vec3::ZERO, 0.5), None);
    }
}
