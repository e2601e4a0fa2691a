//! What a contact holds on to between steps: its point C on the object, the
//! bone's material point p that presses there, and its skin patch's
//! samples. Static contacts keep them; slipping ones move them
//! (§3.5.3).

use super::surface::{self, SurfacePoint};
use super::{BoneMotion, LawSettings, ObjectView, line, patch};
use crate::friction::FrictionCoefficients;
use crate::hand::{Bone, BoneShape, Palm, SkinClass};
use glam::{Mat3, Quat, Vec3};

/// A contact's anchors.
#[derive(Debug, Clone)]
pub(crate) struct Anchor {
    /// C and n in the object body's frame: static contacts move with it.
    pub c_local: Vec3,
    pub n_local: Vec3,
    pub bone: BoneAnchor,
    /// Per sample: its point in the object frame and its skin offset from p
    /// in the bone frame.
    pub samples: patch::Samples,
    /// The patch's radius on the object (m); a line's, half its length.
    pub radius: f32,
    /// The bone's pad radius (m): the ring a line falls back to when it
    /// slides off its flat face ([`Self::slide`]).
    pub pad: f32,
    /// Whether the patch holds the object as a rigid support: a planar
    /// face of the object on the interior of a palm face, or along a
    /// finger bone that lies on it (a line contact).
    pub rigid: bool,
    /// The penetration depth the force saw last step (m), for the
    /// penetration-speed limit.
    pub limited_depth: f32,
    /// The skin frame's rotation this anchor was last spread with, as a
    /// matrix, and the mark of the hand pose it came from
    /// ([`super::BoneMotion::marks`]).
    pub skin: Option<(u64, Mat3)>,
    /// The object's spin (rad/s, world) that this step's roll took up
    /// ([`Self::roll`], `roll.rs`): it moved the patch with C, so the
    /// patch's dampers must not resist it. Zero when nothing rolled.
    pub rolled: Vec3,
}

/// The material point of the bone that the contact holds on to.
#[derive(Debug, Clone, Copy)]
pub(crate) enum BoneAnchor {
    /// Axial parameter of p on the capsule, and the bone's direction in the
    /// palm frame when the contact began (to carry the patch's skin offsets
    /// along as the finger bends).
    Capsule { s: f32, dir_in_palm: Vec3 },
    /// p in the palm frame, and the outward normal (palm frame) of the
    /// palm face p lies on, when the contact presses on that face's
    /// interior (see [`palm_face_under`]).
    Palm { local: Vec3, face: Option<Vec3> },
}

/// Where a contact's anchors are this step (world).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Site {
    /// The contact point C on the object's surface (m).
    pub c: Vec3,
    /// The contact normal: the object's outward normal at C, or, on the
    /// interior of a palm face, that face's inward normal (unit).
    pub n: Vec3,
    /// The object's outward surface normal at C (unit).
    pub surface_n: Vec3,
    /// The bone's point p now and one step ago (m).
    pub p: Vec3,
    pub p_prev: Vec3,
}

impl BoneAnchor {
    /// The bone's material point that presses at C (normal `n`).
    pub(super) fn at(bone: &BoneShape, palm: &Palm, c: Vec3, n: Vec3) -> BoneAnchor {
        match bone {
            BoneShape::Capsule(cap) => {
                let dir = palm.rotation.inverse() * (cap.b - cap.a).normalize_or_zero();
                BoneAnchor::Capsule { s: cap.closest_parameter(c), dir_in_palm: dir }
            }
            BoneShape::Palm(p) => {
                let local = p.to_local(palm_point_under(p, c, n));
                BoneAnchor::Palm { local, face: palm_face_under(p, local, n) }
            }
        }
    }

    /// Whether p presses on the interior of a flat palm face.
    #[inline]
    pub fn is_flat(self) -> bool {
        matches!(self, BoneAnchor::Palm { face: Some(_), .. })
    }

    /// The widest patch, up to `radius` (m), that stays on the palm face p
    /// presses: a ring must not hold an object up beyond the palm's edge.
    fn room_on_face(self, palm: &Palm, radius: f32) -> f32 {
        let BoneAnchor::Palm { local, face: Some(face) } = self else { return radius };
        let h = palm.half_extents;
        (0..3)
            .filter(|&j| face[j] == 0.0)
            .map(|j| h[j] - local[j].abs())
            .fold(radius, f32::min)
            .max(0.0)
    }

    /// The contact normal for an object surface normal `n` (see [`Site::n`]).
    #[inline]
    pub fn normal(self, palm: &Palm, n: Vec3) -> Vec3 {
        match self {
            BoneAnchor::Palm { face: Some(face), .. } => -(palm.rotation * face),
            _ => n,
        }
    }

    /// The anchored point p on the bone's surface, for a contact normal `n`.
    #[inline]
    pub(super) fn point(self, bone: BoneShape, n: Vec3) -> Vec3 {
        match (self, bone) {
            (BoneAnchor::Capsule { s, .. }, BoneShape::Capsule(c)) => {
                c.axis_point(s) - c.radius * n
            }
            (BoneAnchor::Palm { local, .. }, BoneShape::Palm(p)) => p.to_world(local),
            // A bone never changes kind; keep a harmless answer for the type system.
            (_, BoneShape::Capsule(c)) => c.centroid(),
            (_, BoneShape::Palm(p)) => p.center,
        }
    }

    /// The skin frame's rotation (world): the palm's, turned for a finger
    /// bone by how the bone has swung in the palm since it was anchored.
    #[inline]
    pub fn rotation(self, bone: BoneShape, palm: &Palm) -> Quat {
        match (self, bone) {
            (BoneAnchor::Capsule { dir_in_palm, .. }, BoneShape::Capsule(c)) => {
                let now = palm.rotation.inverse() * (c.b - c.a).normalize_or_zero();
                palm.rotation * rotation_arc(dir_in_palm, now)
            }
            _ => palm.rotation,
        }
    }
}

/// Whether every skin frame is computed anew, none kept ([`Anchor::skin`]):
/// only where a test asks for it (`run/scenario/builds.rs`), which
/// compares the two.
#[inline(always)]
pub(crate) fn computing_frames_anew() -> bool {
    #[cfg(test)]
    return FRAMES_ANEW.get();
    #[cfg(not(test))]
    false
}

#[cfg(test)]
thread_local! {
    /// Set: this thread's contacts compute every skin frame anew.
    pub(crate) static FRAMES_ANEW: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// glam's `Quat::from_rotation_arc`, step for step, so the same bits (a
/// unit test compares them): glam's is not `#[inline]`, so each call left
/// the AVX2 build of the contact stages for the baseline one.
#[inline(always)]
fn rotation_arc(from: Vec3, to: Vec3) -> Quat {
    const ONE_MINUS_EPS: f32 = 1.0 - 2.0 * f32::EPSILON;
    let dot = from.dot(to);
    if dot > ONE_MINUS_EPS {
        Quat::IDENTITY
    } else if dot < -ONE_MINUS_EPS {
        Quat::from_axis_angle(from.any_orthonormal_vector(), std::f32::consts::PI)
    } else {
        let c = from.cross(to);
        Quat::from_xyzw(c.x, c.y, c.z, 1.0 + dot).normalize()
    }
}

/// The palm surface point under C: while C is inside the palm box, along
/// −n from C, else the palm's closest point to C. Inside, a ray from C
/// along −n finds the palm's face where the object's normal says it is,
/// so that a ball sunk into the palm is pushed straight out. But an
/// object's normal can lie along the palm (a box's side face, its edge
/// tipped into the palm's face), and its ray then grazes under the face,
/// or runs along the palm to its far end, and reads centimetres of depth
/// for a C a millimetre in. So the ray is taken to the first face it
/// meets that is turned within 60° of −n (as for [`palm_face_under`]),
/// past any edge it merely grazes, when that face is no further from C
/// than the palm is thick; otherwise the nearest face's point is under C.
fn palm_point_under(p: &Palm, c: Vec3, n: Vec3) -> Vec3 {
    let local = p.to_local(c);
    let h = p.half_extents;
    if !local.abs().cmple(h).all() {
        return p.to_world(local.clamp(-h, h));
    }
    let dir = p.rotation.inverse() * -n;
    let thick = 2.0 * h.min_element();
    let facing_exit = (0..3)
        .filter(|&i| dir[i].abs() >= FACING_COS)
        .map(|i| (h[i] - local[i] * dir[i].signum(), dir[i].abs()))
        .filter(|&(distance, _)| distance <= thick)
        .map(|(distance, along)| distance / along)
        .fold(f32::INFINITY, f32::min);
    if facing_exit.is_finite() {
        // Past a grazed edge the face's plane lies beyond the palm: its
        // point under C is on the palm's edge.
        let under = local + dir * facing_exit;
        let on_palm = under.abs().cmple(h + Vec3::splat(1e-6)).all();
        return if on_palm { c - n * facing_exit } else { p.to_world(under.clamp(-h, h)) };
    }
    let nearest = (h - local.abs()).min_position();
    let mut on_face = local;
    on_face[nearest] = h[nearest].copysign(local[nearest]);
    p.to_world(on_face)
}

/// cos 60°: a palm face turned further than this from an object's normal
/// does not press along it (its normal is not the contact's, and a ray
/// along the object's normal only grazes it).
const FACING_COS: f32 = 0.5;

/// How far inside a palm face's edges (m) a contact must press for the
/// face's normal to be the contact normal. At the edge itself the palm has
/// no normal, and the object's is the contact's.
const PALM_EDGE_MARGIN: f32 = 0.002;

/// The outward normal (palm frame) of the palm face whose interior the palm
/// point `local` (palm frame) lies on, if the object's normal `n` (world)
/// faces it. A flat palm under a flat face, an edge or a corner is a plane:
/// its normal is the contact's, however the object rocks on the soft
/// contact, just as a real box on a real palm slides at atan μ_st whatever
/// its height. Near a palm edge, or for a face turned away by more than
/// 60°, the object's normal stays the contact's.
pub(super) fn palm_face_under(palm: &Palm, local: Vec3, n: Vec3) -> Option<Vec3> {
    let h = palm.half_extents;
    let axis = (local / h).abs().max_position();
    let face = Vec3::AXES[axis] * local[axis].signum();
    let interior = (0..3).all(|j| j == axis || local[j].abs() <= h[j] - PALM_EDGE_MARGIN);
    let facing = -(palm.rotation * face).dot(n) >= FACING_COS;
    (interior && facing && (local[axis].abs() - h[axis]).abs() <= PALM_EDGE_MARGIN).then_some(face)
}

/// The contact site on the face found by the closest-feature query, under
/// the bone's point nearest the object's centre: the middle of the overlap
/// of a flat bone and a flat face, wherever either has slid. This is the
/// thesis's ray towards the collider's centre (§3.7).
fn site_under_bone(bone: &BoneShape, object: &ObjectView, near: SurfacePoint) -> SurfacePoint {
    let centre = object.center_of_mass;
    let (bone_centre, reach) = match bone {
        BoneShape::Capsule(cap) => (cap.axis_point(cap.closest_parameter(centre)), cap.radius),
        BoneShape::Palm(p) => {
            let local = p.to_local(centre).clamp(-p.half_extents, p.half_extents);
            (p.to_world(local), p.half_extents.min_element())
        }
    };
    surface::locate_contact(object.shape, &object.pose, near, bone_centre, reach + 0.01)
}

/// How a slipping contact moves its anchors ([`Anchor::slide`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Slip {
    /// This step's normal force (N).
    pub normal_force: f32,
    /// Coulomb's kinetic friction, or `None` for the thesis's rule.
    pub kinetic: Option<FrictionCoefficients>,
    /// How far above the surface the inverse rays start (m).
    pub probe_offset: f32,
    /// Re-centre under the bone first (this crate), or slide from C (the
    /// thesis).
    pub recentre: bool,
}

impl Anchor {
    /// Anchors a contact at `near`, the closest features on the object.
    pub fn new(
        near: SurfacePoint,
        bone: Bone,
        motion: &BoneMotion,
        object: &ObjectView,
        settings: &LawSettings,
    ) -> Anchor {
        let patch = &settings.patch;
        let site = site_under_bone(&motion.now(), object, near);
        let (mut c, n) = (site.point, site.normal);
        // A finger's pad is soft and round: pressed near an edge, it wraps
        // round it. Laid along a flat face, it touches it along a line,
        // which holds the object as a flat support does, and the contact
        // sits at the line's middle, so that its patch is centred on C. The
        // palm's wide flat ring must fit the face it is on.
        let pad = match bone.skin_class() {
            SkinClass::Finger => patch.finger_radius,
            SkinClass::Thumb => patch.thumb_radius,
            SkinClass::Palm => patch.palm_radius,
        };
        let line = match (motion.now(), settings.line_band) {
            (BoneShape::Capsule(cap), Some(band)) => {
                line::along_face(&cap, object, c, n, band, line::Pad::of(bone, pad), patch.samples)
            }
            _ => None,
        };
        if let Some(line) = &line {
            c = surface::project_to_surface(object.shape, &object.pose, line.middle);
        }
        let bone_anchor = BoneAnchor::at(&motion.now(), motion.palm_now(), c, n);
        let (radius, rigid, offsets) = match (line, bone.skin_class()) {
            (Some(line), _) => (line.half, true, line::sample_offsets(n, &line, patch.samples)),
            (None, SkinClass::Palm) => {
                let room = bone_anchor.room_on_face(motion.palm_now(), pad);
                let (radius, planar) = patch::fit_to_face(object, c, n, patch.samples, room);
                let rigid = planar && bone_anchor.is_flat();
                (radius, rigid, patch::sample_offsets(n, patch.samples, radius))
            }
            (None, _) => (pad, false, patch::sample_offsets(n, patch.samples, pad)),
        };
        let samples =
            lay_samples(offsets, c, bone_anchor.rotation(motion.now(), motion.palm_now()), object);
        Anchor {
            c_local: object.pose.inverse_transform_point(c),
            n_local: object.pose.rotation.inverse() * n,
            bone: bone_anchor,
            samples,
            radius,
            pad,
            rigid,
            limited_depth: 0.0,
            skin: None,
            rolled: Vec3::ZERO,
        }
    }

    /// Where the anchors are this step.
    #[inline(always)]
    pub fn site(&self, object: &ObjectView, motion: &BoneMotion) -> Site {
        let pose = &object.pose;
        let surface_n = (pose.rotation * self.n_local).normalize_or_zero();
        let n = self.bone.normal(motion.palm_now(), surface_n);
        Site {
            c: pose.transform_point(self.c_local),
            n,
            surface_n,
            p: self.bone.point(motion.now(), n),
            p_prev: self.bone.point(motion.prev(), n),
        }
    }

    /// Slipping (§3.5.3): skin and surface slide over each other, so both
    /// anchors move. The site re-centres under the bone (the overlap follows
    /// whichever of bone and face is smaller); then C moves along the
    /// surface by inverse ray casts, to keep the slip rule's stretch
    /// (`kinetic`, Coulomb) or, with `kinetic` `None` (the thesis's rule),
    /// along the thesis's ray towards the bone. The patch moves with C.
    pub fn slide(&mut self, at: &Site, slip: &Slip, motion: &BoneMotion, object: &ObjectView) {
        let Slip { normal_force, kinetic, probe_offset, recentre } = *slip;
        let pose = &object.pose;
        let here = SurfacePoint { point: at.c, normal: at.surface_n };
        let site = if recentre { site_under_bone(&motion.now(), object, here) } else { here };
        let bone_anchor = BoneAnchor::at(&motion.now(), motion.palm_now(), site.point, site.normal);
        let p_new = bone_anchor.point(motion.now(), site.normal);
        // The kinetic stretch is kept from the point of the site's tangent
        // plane under the bone: the re-centred site, or, where none was
        // found (a bone crossing a curved face askew, or no re-centring),
        // p's foot on C's tangent plane. Kept from C itself, it would carry
        // C one stretch further from the bone every step, round a curved
        // face and ever deeper below it.
        let under = if site == here {
            p_new + (site.point - p_new).dot(site.normal) * site.normal
        } else {
            site.point
        };
        let target = kinetic.map(|mu| {
            let d = at.c - at.p;
            let stretch_t = d - d.dot(at.n) * at.n;
            under + crate::friction::slipped_stretch(stretch_t, normal_force, mu, object.gamma)
        });
        let Some(moved) = surface::slide(object.shape, pose, site, target, p_new, probe_offset)
        else {
            return;
        };
        let shift = moved.point - at.c;
        self.c_local = pose.inverse_transform_point(moved.point);
        self.n_local = pose.rotation.inverse() * moved.normal;
        // The skin offsets live in the bone frame, which the new anchor
        // redefines: carry them over.
        let carry = bone_anchor.rotation(motion.now(), motion.palm_now()).inverse()
            * self.bone.rotation(motion.now(), motion.palm_now());
        let samples = &mut self.samples;
        for i in 0..samples.len() {
            samples.skin.set(i, carry * samples.skin.get(i));
        }
        self.bone = bone_anchor;
        // A frame computed for the old anchor does not serve the new one.
        self.skin = None;
        for i in 0..samples.len() {
            let ci = pose.transform_point(samples.object.get(i)) + shift;
            let on_surface = surface::project_to_surface(object.shape, pose, ci);
            samples.object.set(i, pose.inverse_transform_point(on_surface));
        }
        if self.is_line() && !self.lies_flat(moved.point, moved.normal, object) {
            self.lay_ring(moved.point, moved.normal, motion, object);
        }
    }

    /// Whether the patch is a line along a finger bone (`line.rs`).
    fn is_line(&self) -> bool {
        self.rigid && matches!(self.bone, BoneAnchor::Capsule { .. })
    }

    /// Whether every sample lies on the flat face of C (normal `n`), as a
    /// line's must.
    fn lies_flat(&self, c: Vec3, n: Vec3, object: &ObjectView) -> bool {
        (0..self.samples.len()).all(|i| {
            let q = object.pose.transform_point(self.samples.object.get(i));
            line::flat_under(object, q - (q - c).dot(n) * n, n, self.pad)
        })
    }

    /// Lays the pad's ring round C (normal `n`): what a line that slid off
    /// its flat face becomes, since the face no longer holds it along the
    /// bone.
    fn lay_ring(&mut self, c: Vec3, n: Vec3, motion: &BoneMotion, object: &ObjectView) {
        let ring = patch::sample_offsets(n, self.samples.len(), self.pad);
        let skin = self.bone.rotation(motion.now(), motion.palm_now());
        self.samples = lay_samples(ring, c, skin, object);
        self.radius = self.pad;
        self.rigid = false;
    }
}

/// A patch's samples at `offsets` from C (world), each on the object's
/// surface, with its skin offset in the skin frame `skin`.
fn lay_samples(offsets: Vec<Vec3>, c: Vec3, skin: Quat, object: &ObjectView) -> patch::Samples {
    let rot_inv = skin.inverse();
    patch::Samples::from_pairs(offsets.into_iter().map(|o| {
        let ci = surface::project_to_surface(object.shape, &object.pose, c + o);
        (object.pose.inverse_transform_point(ci), rot_inv * (ci - c))
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A palm turned 40° about its length, its face's outward normal
    /// `up`, its length `along` and its width `across` (world).
    fn turned_palm() -> (Palm, Vec3, Vec3, Vec3) {
        let rotation = Quat::from_rotation_z(0.7);
        let palm = Palm {
            center: Vec3::new(0.13, 0.91, -0.27),
            rotation,
            half_extents: Vec3::new(0.037, 0.011, 0.048),
        };
        (palm, rotation * Vec3::Y, rotation * Vec3::Z, rotation * Vec3::X)
    }

    #[test]
    fn an_object_sunk_into_the_palm_face_is_under_c_along_its_normal() {
        let (palm, up, along, across) = turned_palm();
        let face = palm.center + up * 0.011;
        // A ball's C, 3 mm into the face, its outward normal into the palm.
        let c = face - up * 0.003 + across * 0.01;
        let p = palm_point_under(&palm, c, -up);
        assert!((p - (c + up * 0.003)).length() < 1e-6, "{p} for {c}");
        // The normal tilted 35° along the palm: the ray through the face.
        let n = -(up * 35f32.to_radians().cos() + along * 35f32.to_radians().sin());
        let p = palm_point_under(&palm, c, n);
        let t = 0.003 / 35f32.to_radians().cos();
        assert!((p - (c - n * t)).length() < 1e-6, "{p} for {c}");
        // Sunk past the palm's middle, it is still pushed back out by the
        // face it came through, not through the palm.
        let c = face - up * 0.015;
        assert!((palm_point_under(&palm, c, -up) - (c + up * 0.015)).length() < 1e-6);
    }

    #[test]
    fn a_normal_along_the_palm_reads_the_depth_of_c_and_a_grazed_edge_is_passed() {
        // A box's edge, 2.3 mm into the palm's face, with its side face's
        // outward normal (the one the closest-feature query gave) along
        // the palm's length: a ray along −n would run along the palm to its
        // far end, 7 cm. The palm's face is 2.3 mm away.
        let (palm, up, along, across) = turned_palm();
        let c = palm.center + up * 0.0087 + along * 0.0217 + across * 0.0067;
        let n = (along + across * 0.08 - up * 0.01).normalize();
        let p = palm_point_under(&palm, c, n);
        assert!((p - (c + up * 0.0023)).length() < 1e-6, "{p} for {c}");
        // An edge 0.3 mm in, its normal along the palm's length and tipped
        // a hair towards the face: the ray would graze under the face for
        // 3 cm before it left through it.
        let c = palm.center + up * 0.0107 - across * 0.004;
        let n = (along * 0.995 - up * 0.01).normalize();
        let p = palm_point_under(&palm, c, n);
        assert!((p - (c + up * 0.0003)).length() < 1e-6, "{p} for {c}");
        // A handle across the palm's edge: C 20 µm inside the edge, 1.3 mm
        // under the face, its normal into the face but for a hair towards
        // the edge, which the ray leaves by at once. The face is 1.3 mm
        // along it, on the palm's edge.
        let c = palm.center + up * 0.0097 + across * 0.03698 + along * 0.024;
        let n = -(up + across * 0.02).normalize();
        let p = palm_point_under(&palm, c, n);
        let on_edge = palm.center + up * 0.011 + across * 0.037 + along * 0.024;
        assert!((p - on_edge).length() < 1e-5, "{p} for {c}");
        // C outside the palm: its closest point, as before.
        let out = palm.center + up * 0.02 + across * 0.05;
        let p = palm_point_under(&palm, out, n);
        assert!((p - (palm.center + up * 0.011 + across * 0.037)).length() < 1e-6);
    }

    #[test]
    fn the_inlined_rotation_arc_has_glam_s_bits() {
        // Directions all round, and pairs within a hair of parallel and of
        // opposite, where glam's two special cases begin.
        let dir = |i: u32| {
            let (a, b) = (i as f32 * 0.7131, i as f32 * 1.3177 + 0.29);
            Vec3::new(a.cos() * b.sin(), a.sin() * b.sin(), b.cos()).normalize()
        };
        let mut pairs = Vec::new();
        for i in 0..300 {
            let (from, to) = (dir(i), dir(i * 7 + 3));
            let tilt = (to - from.dot(to) * from).normalize_or_zero();
            for t in [0.0, 1e-4, 3e-4, 1e-3, 0.05] {
                pairs.push((from, to));
                pairs.push((from, (from + t * tilt).normalize()));
                pairs.push((from, (-from + t * tilt).normalize()));
            }
        }
        let bits = |q: Quat| q.to_array().map(f32::to_bits);
        for (from, to) in pairs {
            let glam = Quat::from_rotation_arc(from, to);
            assert_eq!(bits(rotation_arc(from, to)), bits(glam), "{from} to {to}");
        }
    }
}
