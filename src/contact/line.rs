//! Line contacts: a finger bone lying along a face touches it along a
//! line, not at a point.
//!
//! A capsule pressed against a face at a steep angle touches it with its
//! round end, over a pad a few millimetres across: a ring patch
//! ([`super::patch::sample_offsets`]). Laid along the face, the same
//! capsule touches it along its length, as a real finger laid flat does,
//! and an object resting on it is held upright by where the pressure sits
//! along that line, as on a small flat support. So the patch of a bone
//! that lies along a flat face, within the contact offset of it from end
//! to end (the band in which a contact begins), is stretched along the
//! bone, clipped to where the face stays flat. Across the bone
//! it keeps the pad's width where the face is flat there too. A curved
//! face (a ball, a pen across the bone) falls away from a straight bone
//! within a pad's width, so it keeps the pad's ring.
//!
//! A fingertip is the exception ([`Pad::of`]). Its pulp is a rounded pad at
//! the end of the finger: pressed against a flat face, it presses hardest
//! in the middle of a patch a few millimetres across (an inverted
//! paraboloid: Pawluk & Howe 1999, "Dynamic contact of the human fingerpad
//! against a flat surface", J. Biomech. Eng. 121:605), not evenly along
//! the 2–3 cm of the distal bone's capsule. So a distal bone's line
//! reaches only a pad's radius from its middle: its patch is the pad's
//! ring, laid flat. It still holds an object upright as a flat support
//! does, but a fingertip pinch twists free at a fingertip's torsional
//! friction, μ·N times the ring's mean arm (8/9 of the pad's radius with
//! the default 9 samples), where a line along the whole bone held twice
//! that. The ring sits at the middle of the part of the bone on the face,
//! not at the bone's tip: the capsule does not say where its pulp is.

use super::ObjectView;
use super::patch::PLANAR_COS;
use super::surface;
use crate::hand::{Bone, Capsule, Phalanx};
use glam::Vec3;

/// The part of a bone that lies along a face, on the face's tangent plane
/// at C (world).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Line {
    /// The middle of the line (m), on C's tangent plane.
    pub middle: Vec3,
    /// Along the line (unit, tangent to the face).
    pub along: Vec3,
    /// Half the line's length (m).
    pub half: f32,
    /// Half its width (m): the pad's, or 0 where the face curves away
    /// across the bone.
    pub across: f32,
}

/// A bone's pad as a line sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Pad {
    /// The pad's radius (m): its ring's, and a line's half-width.
    pub radius: f32,
    /// How far (m) a line may reach from its middle along the bone.
    pub reach: f32,
}

impl Pad {
    /// The pad of `bone`, of radius `radius` (m): a fingertip's line
    /// reaches a pad's radius from its middle (its rounded pulp), the
    /// others' the whole bone (their pads lie flat along the phalanx).
    pub(crate) fn of(bone: Bone, radius: f32) -> Pad {
        let reach = match bone {
            Bone::Finger(_, Phalanx::Distal) => radius,
            _ => f32::INFINITY,
        };
        Pad { radius, reach }
    }
}

/// How many halvings fit each end of the line to its face: to 1/64 of
/// its reach from C.
const FIT_STEPS: usize = 6;

/// The line along which capsule `bone` touches the face of C (outward
/// normal `n`), if the bone lies along it: its surface within `band` (m)
/// of C's tangent plane at both ends, and as parallel to the plane as the
/// face must be flat (2.6°), so that its depth is the same along it. The
/// line is its axis projected onto that plane, each end drawn in until the
/// face under it is as flat as at C, then to the pad's reach from its
/// middle ([`Pad::of`]). `None` when the bone presses with one end, or
/// when the line is shorter than the pad is wide, two of its radii (the
/// face curves away under it): its patch is then the pad's ring.
pub(crate) fn along_face(
    bone: &Capsule,
    object: &ObjectView,
    c: Vec3,
    n: Vec3,
    band: f32,
    pad: Pad,
    samples: usize,
) -> Option<Line> {
    let Pad { radius: pad, reach } = pad;
    // The bone's surface above the plane at each end of its axis: both
    // within the band, and level, or the bone is not lying along the face
    // but pressing it with one end (a fingertip, however flat its pad).
    let height = |q: Vec3| (q - c).dot(n) - bone.radius;
    let (h0, h1) = (height(bone.a), height(bone.b));
    let level = (1.0 - PLANAR_COS * PLANAR_COS).sqrt() / PLANAR_COS;
    let lying = pad > 0.0
        && h0 <= band
        && h1 <= band
        && (h0 - h1).abs() <= level * (bone.b - bone.a).length();
    if !lying {
        return None;
    }
    let on_plane = |q: Vec3| q - (q - c).dot(n) * n;
    let (mut from, mut to) = (on_plane(bone.a), on_plane(bone.b));
    let along = (to - from).normalize_or_zero();
    if along == Vec3::ZERO || (to - from).length() < 2.0 * pad {
        return None;
    }
    // Each end drawn towards the other until the face under it is flat: a
    // bone longer than the face must not hold the object beyond its edge.
    let on_face = |q: Vec3| flat_under(object, q, n, pad);
    let anchor_point = on_plane(bone.axis_point(bone.closest_parameter(c)));
    if !on_face(anchor_point) {
        return None;
    }
    for end in [&mut from, &mut to] {
        if on_face(*end) {
            continue;
        }
        let (mut inside, mut outside) = (anchor_point, *end);
        for _ in 0..FIT_STEPS {
            let mid = 0.5 * (inside + outside);
            if on_face(mid) { inside = mid } else { outside = mid }
        }
        *end = inside;
    }
    let half = 0.5 * (to - from).dot(along);
    if half.is_nan() || half < pad {
        return None;
    }
    // Only the pad's own reach touches: a fingertip's pulp, not its bone.
    let half = half.min(reach);
    // The pad's width across it, where every sample of the ellipse lies on
    // the flat face; else none (a face narrower than the pad: a knife edge).
    let mut line = Line { middle: 0.5 * (from + to), along, half, across: pad };
    let fits = sample_offsets(n, &line, samples).iter().all(|o| on_face(line.middle + *o));
    if !fits {
        line.across = 0.0;
    }
    Some(line)
}

/// Whether the object's surface under `q`, a point of C's tangent plane
/// (normal `n`), is there within `depth` (m) and as flat as at C (2.6°): where
/// a line may lie.
pub(crate) fn flat_under(object: &ObjectView, q: Vec3, n: Vec3, depth: f32) -> bool {
    surface::face_cos(object.shape, &object.pose, q, n, depth).is_some_and(|cos| cos >= PLANAR_COS)
}

/// The patch's sample offsets from the line's middle, where its contact
/// sits (normal `n`): the middle, then the others evenly round an ellipse
/// of half-axes `line.half` along the line and `line.across` across it.
/// Their mean is the middle, where a line pressed evenly carries its load.
pub(crate) fn sample_offsets(n: Vec3, line: &Line, samples: usize) -> Vec<Vec3> {
    let samples = samples.max(1);
    let across = n.cross(line.along);
    let ring = samples - 1;
    let mut out = Vec::with_capacity(samples);
    out.push(Vec3::ZERO);
    for k in 0..ring {
        let a = std::f32::consts::TAU * k as f32 / ring as f32;
        out.push(line.half * a.cos() * line.along + line.across * a.sin() * across);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::friction::FrictionCoefficients;
    use crate::scene::ObjectId;
    use rapier3d::math::Pose;
    use rapier3d::parry::shape::{Ball, Cuboid, Shape};

    fn view(shape: &dyn Shape) -> ObjectView<'_> {
        ObjectView {
            id: ObjectId(0),
            pose: Pose::IDENTITY,
            shape,
            linvel: Vec3::ZERO,
            angvel: Vec3::ZERO,
            center_of_mass: Vec3::ZERO,
            inv_inertia: 1.0,
            sharing: 1.0,
            gamma: 300.0,
            damping: 1.0,
            cap: None,
            mu: FrictionCoefficients { static_mu: 0.8, dynamic_mu: 0.6 },
        }
    }

    /// A 4 mm pad whose line may reach the whole bone.
    const PAD: Pad = Pad { radius: 0.004, reach: f32::INFINITY };

    /// A bone of radius 7 mm whose axis runs from `a` to `b`.
    fn bone(a: Vec3, b: Vec3) -> Capsule {
        Capsule { a, b, radius: 0.007 }
    }

    #[test]
    fn a_bone_laid_along_a_face_touches_it_along_its_length() {
        // A 6 cm box's top face; a 3.1 cm bone lying on it, 1 mm above.
        let cube = Cuboid::new(Vec3::splat(0.03));
        let y = 0.03 + 0.007 + 0.001;
        let laid = bone(Vec3::new(-0.017, y, 0.004), Vec3::new(0.014, y, 0.004));
        let c = Vec3::new(0.0, 0.03, 0.004);
        let line = along_face(&laid, &view(&cube), c, Vec3::Y, 0.004, PAD, 9).unwrap();
        assert!((line.half - 0.0155).abs() < 1e-5, "{line:?}");
        assert!((line.middle - Vec3::new(-0.0015, 0.03, 0.004)).length() < 1e-5);
        assert!((line.along - Vec3::X).length() < 1e-5);
        assert_eq!(line.across, 0.004);
    }

    #[test]
    fn a_fingertip_laid_along_a_face_touches_it_with_its_pulp_alone() {
        // A 2.8 cm distal bone on a 6 cm box's top face: its line is the
        // pad's 5 mm either side of the middle of the part that lies on the
        // face; any other finger bone's reaches its ends.
        let cube = Cuboid::new(Vec3::splat(0.03));
        let y = 0.03 + 0.007 + 0.0005;
        let laid = bone(Vec3::new(-0.02, y, -0.006), Vec3::new(0.008, y, -0.006));
        let c = Vec3::new(0.0, 0.03, -0.006);
        let index = |p| Bone::Finger(crate::hand::Finger::Index, p);
        let pulp = Pad::of(index(Phalanx::Distal), 0.005);
        let tip = along_face(&laid, &view(&cube), c, Vec3::Y, 0.004, pulp, 9).unwrap();
        let whole = Pad::of(index(Phalanx::Intermediate), 0.005);
        let bone_line = along_face(&laid, &view(&cube), c, Vec3::Y, 0.004, whole, 9).unwrap();
        assert_eq!(tip.half, 0.005, "{tip:?}");
        assert!((bone_line.half - 0.014).abs() < 1e-6, "{bone_line:?}");
        assert_eq!((tip.middle, tip.along, tip.across), (bone_line.middle, bone_line.along, 0.005));
    }

    #[test]
    fn a_line_stops_at_the_face_s_edge_and_a_steep_bone_has_none() {
        let cube = Cuboid::new(Vec3::splat(0.02));
        let y = 0.02 + 0.007;
        // From 1 cm inside the face's edge to 2 cm beyond it.
        let over = bone(Vec3::new(0.01, y, 0.0), Vec3::new(0.04, y, 0.0));
        let c = Vec3::new(0.015, 0.02, 0.0);
        let line = along_face(&over, &view(&cube), c, Vec3::Y, 0.004, PAD, 9).unwrap();
        let end = line.middle.x + line.half;
        assert!(end <= 0.02 && end > 0.0195, "{line:?}");
        // A fingertip pressing at 20°: only its end is within the band.
        let steep = bone(Vec3::new(-0.02, y + 0.0073, 0.0), Vec3::new(0.0, y, 0.0));
        let c = Vec3::new(0.0, 0.02, 0.0);
        assert_eq!(along_face(&steep, &view(&cube), c, Vec3::Y, 0.004, PAD, 9), None);
        // At 4°, within the band from end to end, but its depth would differ
        // by 1.4 mm along it: not lying along the face. At 2° it does.
        for (deg, lies) in [(4.0f32, false), (2.0, true)] {
            let rise = 0.02 * deg.to_radians().tan();
            let tilted = bone(Vec3::new(-0.02, y + rise, 0.0), Vec3::new(0.0, y, 0.0));
            let line = along_face(&tilted, &view(&cube), c, Vec3::Y, 0.004, PAD, 9);
            assert_eq!(line.is_some(), lies, "{deg}°: {line:?}");
        }
        // A face 6 mm wide: a line along it, but no pad's width across it.
        let strip = Cuboid::new(Vec3::new(0.02, 0.02, 0.003));
        let line =
            along_face(&over, &view(&strip), Vec3::new(0.015, 0.02, 0.0), Vec3::Y, 0.004, PAD, 9);
        assert_eq!(line.map(|l| l.across), Some(0.0));
    }

    #[test]
    fn a_ball_s_curve_leaves_a_bone_along_it_no_line() {
        // A 3 cm ball under a bone lying on it: its surface stays within
        // the band for 1.5 cm on either side, but turns away by 2.6°
        // within 1.4 mm, less than a pad's width.
        let ball = Ball::new(0.03);
        let y = 0.03 + 0.007;
        let laid = bone(Vec3::new(-0.015, y, 0.0), Vec3::new(0.015, y, 0.0));
        let c = Vec3::new(0.0, 0.03, 0.0);
        assert_eq!(along_face(&laid, &view(&ball), c, Vec3::Y, 0.004, PAD, 9), None);
    }

    #[test]
    fn the_samples_lie_round_the_line_s_middle() {
        let middle = Vec3::new(0.01, 0.0, 0.0);
        let line = Line { middle, along: Vec3::X, half: 0.02, across: 0.004 };
        let offs = sample_offsets(Vec3::Y, &line, 9);
        assert!((offs.iter().sum::<Vec3>() / 9.0).length() < 1e-6);
        let reach = offs.iter().map(|o| o.x.abs()).fold(0.0, f32::max);
        assert!((reach - 0.02).abs() < 1e-6);
        assert!(offs.iter().all(|o| o.y == 0.0 && o.z.abs() <= 0.004 + 1e-7));
    }
}
