//! Rolling contacts: a contact follows the two surfaces as they roll on
//! each other, so a ball rolls down a palm.
//!
//! The thesis anchors C on the object while the contact sticks. For a
//! grip that holds, that is right. For an object that rolls, it is not:
//! C turns away with the object, the measured depth falls while the
//! object sinks into the skin, and the contact kicks when it slips and
//! finds its depth again.
//!
//! Two surfaces that roll without slipping touch at a point that moves on
//! both: by contact kinematics (Montana 1988, "The kinematics of contact
//! and grasp", IJRR 7(3)), on the object at the rate `(K_o + K_b)⁻¹ (n × ω)`
//! for their relative spin ω about the tangent axes, the contact normal n
//! and their curvatures K_o and K_b there ([`Anchor::roll`]). K_o is read
//! from the object's normals a millimetre either side of C, from closest
//! points, exact on every shape; K_b is the bone's where C touches it: a
//! capsule's side across its axis, of the radius ρ = R_b − d at which C
//! sits from the axis with the skin sunk d; nothing on the palm's flat
//! faces. Each step a static contact on a curved object is carried so, p
//! with it, keeping the tangential stretch of its friction spring: the
//! spring grows only by slip where the surfaces touch, as the tangential
//! spring of discrete-element contacts does (Cundall & Strack 1979;
//! Luding 2008, "Cohesive, frictional powders", Granular Matter 10). The
//! rate alone, integrated, would drift with every error of the curvature
//! read: one Newton step then brings C to where the surfaces truly touch,
//! where the object's normal faces the bone. So the depth is the true
//! depth every step.
//!
//! On a capsule's side p is not a material point of the bone across it:
//! it lies a radius from the axis against C's normal, so where C sits
//! across the bone is the spring's stretch. There the Newton step acts
//! along the axis only; across it, C is set where the stretch is the
//! spring's, whose slope against C's move is `I + ρ K_o`, and the stretch
//! does not count p's slide round the bone as the object turns, which is
//! no slip. (Set back to face the axis across it too, by a step along
//! K_o alone, C overshot 3.5 times for a 3 cm ball on a finger, and each
//! step put the spring back 2.4 times as stretched: a ball pinched
//! between two fingers spun up within 25 ms.)
//!
//! What does not roll:
//! - a flat face (a box's, a plate's), and a flat direction (a pen along
//!   its length): it pivots within the pad's patch, whose deviation springs
//!   hold it, as the thesis's pinned C does. An edge, sharper than the
//!   millimetre probe resolves, is not a bend;
//! - a fingertip pressing with its end cap: there C stays pinned. Rolled
//!   by the relative spin alone, a fingertip flexing into an object would
//!   carry C as if it turned about the contact, where it also slides; in
//!   a wrap grip round a mallet's handle that shook the grip loose.
//!
//! The patch moves with C, turned as the surface turns under it. The spin
//! a roll took up, and for a sliding contact on a curved object the spin
//! that turns the surface under its patch, is not seen by the patch's
//! dampers ([`Anchor::rolled`]), which would otherwise brake the roll, or
//! stall a sliding ball's spin.

use super::anchor::{Anchor, BoneAnchor, Site, palm_face_under};
use super::surface;
use super::{BoneMotion, ObjectView};
use crate::hand::{BoneShape, Palm};
use glam::{Quat, Vec3};

/// The least curvature (1/m) along which an object rolls: a
/// radius of 0.5 m. Flatter, the contact stays pinned.
const LEAST_CURVATURE: f32 = 2.0;

/// How far to either side of C (m) the object's normals are read for its
/// curvature: well inside a finger's pad, and short of a small object's
/// edges.
const CURVATURE_STEP: f32 = 0.001;

/// The least turn (rad per step) that rolls a contact. Below it nothing is
/// computed: a still grip costs only this test.
const LEAST_TURN: f32 = 1.0e-6;

/// Newton steps that set a capsule-side contact's stretch (`roll`).
const HELD_STEPS: usize = 2;

/// A surface's curvature at C in a tangent basis `(t1, t2)` (1/m):
/// symmetric.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
struct Curvature {
    xx: f32,
    xy: f32,
    yy: f32,
}

impl std::ops::Add for Curvature {
    type Output = Curvature;
    fn add(self, o: Curvature) -> Curvature {
        Curvature { xx: self.xx + o.xx, xy: self.xy + o.xy, yy: self.yy + o.yy }
    }
}

impl Curvature {
    /// `(1/r)·(I − â âᵀ)` on the tangent plane, for the unit tangent `â`
    /// (or `1/r` every way for `â` zero): a cylinder's side, or a sphere.
    fn round(radius: f32, along: Vec3, t1: Vec3, t2: Vec3) -> Curvature {
        let k = 1.0 / radius;
        let (a1, a2) = (along.dot(t1), along.dot(t2));
        Curvature { xx: k * (1.0 - a1 * a1), xy: -k * a1 * a2, yy: k * (1.0 - a2 * a2) }
    }

    /// `I + ρ·K`: how a capsule-side contact's stretch changes as C moves
    /// on a surface of this curvature, C at `rho` from the axis (`roll`).
    fn stretch_slope(self, rho: f32) -> Curvature {
        Curvature { xx: 1.0 + rho * self.xx, xy: rho * self.xy, yy: 1.0 + rho * self.yy }
    }

    /// `M⁻¹·r` for this matrix taken as any symmetric one (not only a
    /// curvature): `r` itself where it is singular.
    fn inverse_times(self, r: [f32; 2]) -> [f32; 2] {
        let det = self.xx * self.yy - self.xy * self.xy;
        // Not a number is not invertible either.
        let invertible = det.abs() > f32::EPSILON * (self.xx * self.xx + self.yy * self.yy);
        if !invertible {
            return r;
        }
        [(self.yy * r[0] - self.xy * r[1]) / det, (self.xx * r[1] - self.xy * r[0]) / det]
    }

    /// Whether it is curved enough to roll along some direction.
    fn curved(self) -> bool {
        self.largest() >= LEAST_CURVATURE
    }

    /// Its larger eigenvalue: the sharpest bend at C (1/m).
    fn largest(self) -> f32 {
        let spread = (0.25 * (self.xx - self.yy) * (self.xx - self.yy) + self.xy * self.xy).sqrt();
        0.5 * (self.xx + self.yy) + spread
    }

    /// `K·v` for a tangent vector `v` given in the basis.
    fn times(self, v: [f32; 2]) -> [f32; 2] {
        [self.xx * v[0] + self.xy * v[1], self.xy * v[0] + self.yy * v[1]]
    }

    /// `K⁺·r` for the tangent rate `r` given in the basis: along the
    /// eigen-directions whose curvature is at least [`LEAST_CURVATURE`]
    /// (the pseudo-inverse); nothing along a flat one.
    fn solve(self, r: [f32; 2]) -> [f32; 2] {
        let Curvature { xx, xy, yy } = self;
        let mean = 0.5 * (xx + yy);
        let spread = (0.25 * (xx - yy) * (xx - yy) + xy * xy).sqrt();
        if spread <= 1e-6 * mean.abs() {
            // The same every way (a sphere, or flat).
            return if mean >= LEAST_CURVATURE { r.map(|v| v / mean) } else { [0.0; 2] };
        }
        // An eigenvector for the larger eigenvalue, from whichever row of
        // K − λI is the larger; the other is at right angles to it.
        let high = mean + spread;
        let (a, b) = ([xy, high - xx], [high - yy, xy]);
        // √(x² + y²), not `hypot`: the same IEEE operations on every target.
        let length = |v: [f32; 2]| (v[0] * v[0] + v[1] * v[1]).sqrt();
        let e = if length(a) >= length(b) { a } else { b };
        let len = length(e);
        let e1 = [e[0] / len, e[1] / len];
        let e2 = [-e1[1], e1[0]];
        let mut moved = [0.0; 2];
        for (lambda, e) in [(high, e1), (mean - spread, e2)] {
            if lambda >= LEAST_CURVATURE {
                let part = e[0] * r[0] + e[1] * r[1];
                for i in 0..2 {
                    moved[i] += part / lambda * e[i];
                }
            }
        }
        moved
    }
}

/// The object's curvature at C (outward normal `n`), from its normals a
/// [`CURVATURE_STEP`] either side along `t1` and `t2`; `None` at an edge
/// or where the surface is not found.
fn object_curvature(
    object: &ObjectView,
    c: Vec3,
    n: Vec3,
    t1: Vec3,
    t2: Vec3,
) -> Option<Curvature> {
    let h = CURVATURE_STEP;
    // A point of a smooth surface lies under its probe: one pulled aside
    // by more than half the step found an edge, not the surface's bend.
    let at = |q: Vec3| {
        let (point, normal) = surface_near(object, q, n)?;
        let aside = (point - q) - (point - q).dot(n) * n;
        let smooth = normal.dot(n) >= surface::SAME_FACE_COS && aside.length() <= 0.5 * h;
        smooth.then_some((point, normal))
    };
    let (_, n_c) = at(c)?;
    // The normal's change over the surface points' own spacing along t.
    let rate = |t: Vec3| {
        let ((p_plus, n_plus), (p_minus, n_minus)) = (at(c + h * t)?, at(c - h * t)?);
        let span = (p_plus - p_minus).dot(t);
        // A smooth surface bends alike either side of C; an edge within
        // the step bends one side only.
        let lopsided = 0.5 * (n_plus + n_minus) - n_c;
        let lopsided = (lopsided - lopsided.dot(n_c) * n_c).length();
        let even = lopsided <= 0.25 * 0.5 * (n_plus - n_minus).length() + 1e-3;
        (span > 0.5 * h && even).then(|| (n_plus - n_minus) / span)
    };
    let (d1, d2) = (rate(t1)?, rate(t2)?);
    let xy = 0.5 * (d1.dot(t2) + d2.dot(t1));
    let k = Curvature { xx: d1.dot(t1), xy, yy: d2.dot(t2) };
    // Sharper than the step can resolve is an edge, which closest points
    // round off over the step: a box's edge does not roll.
    let finite = [k.xx, k.xy, k.yy].iter().all(|v| v.is_finite());
    (finite && k.largest() <= 0.5 / h).then_some(k)
}

/// The object's surface point nearest `q`, a point near C (outward normal
/// `n` there), and its outward normal, from closest points, which parry
/// finds exactly on every shape, where a ray's normal on a round
/// support-mapped shape (a cylinder) can be tens of degrees off: the
/// closest point to a point a [`CURVATURE_STEP`] outside along `n`, then
/// to one as far outside along the normal found there.
fn surface_near(object: &ObjectView, q: Vec3, n: Vec3) -> Option<(Vec3, Vec3)> {
    let (shape, pose) = (object.shape, &object.pose);
    let (mut on, mut normal) = (q, n);
    for _ in 0..2 {
        let out = on + CURVATURE_STEP * normal;
        on = surface::project_to_surface(shape, pose, out);
        normal = (out - on).try_normalize()?;
    }
    Some((on, normal))
}

/// The object's outward normal at its surface nearest `q` ([`surface_near`]).
fn normal_near(object: &ObjectView, q: Vec3, n: Vec3) -> Option<Vec3> {
    surface_near(object, q, n).map(|(_, normal)| normal)
}

/// A contact's relative spin over a step, where the object is curved
/// enough at C to roll ([`Anchor::turning`]).
struct Turning {
    site: Site,
    /// The object's outward normal at C.
    n: Vec3,
    /// The object's spin less the skin's, along the tangent plane (rad/s).
    turning: Vec3,
    /// A tangent basis at C, and the object's curvature in it.
    t1: Vec3,
    t2: Vec3,
    k_object: Curvature,
}

impl Anchor {
    /// The object's spin against the skin's over `dt` (s), along C's
    /// tangent plane, where the object is curved at C; `None` on a flat
    /// face, at an edge, for a rigid patch, or for a turn too small to
    /// count.
    fn turning(&self, motion: &BoneMotion, object: &ObjectView, dt: f32) -> Option<Turning> {
        // Also a step of no length, or not a number.
        if self.rigid || dt.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        let site = self.site(object, motion);
        let n = site.surface_n;
        // The skin's spin: the bone's frame, now against one step ago.
        let skin_now = self.bone.rotation(motion.now(), motion.palm_now());
        let skin_before = self.bone.rotation(motion.prev(), motion.palm_prev());
        let turn = (skin_now * skin_before.inverse()).normalize();
        let turn = if turn.w < 0.0 { -turn } else { turn };
        let relative = object.angvel - rotation_vector(turn) / dt;
        let turning = relative - relative.dot(n) * n;
        let turn = turning.length() * dt;
        if turn.is_nan() || turn < LEAST_TURN {
            return None;
        }
        let (t1, t2) = n.any_orthonormal_pair();
        let k_object = object_curvature(object, site.c, n, t1, t2)?;
        // A flat face pivots within the pad's patch, whose deviation
        // springs hold it: nothing rolls.
        k_object.curved().then_some(Turning { site, n, turning, t1, t2, k_object })
    }

    /// A sliding contact on a curved object: [`Anchor::slide`] carries its
    /// patch with C, so the spin that turns the curved surface under the
    /// patch moves none of its samples against the skin. That spin is
    /// taken out of the patch's dampers ([`Anchor::rolled`]), which would
    /// otherwise brake a ball that slides and spins up, as a rocking
    /// patch's do. What turns the surface along a flat direction stays.
    pub fn slide_spin(&mut self, motion: &BoneMotion, object: &ObjectView, dt: f32) {
        self.rolled = Vec3::ZERO;
        if self.on_end_cap() {
            return;
        }
        let Some(Turning { n, turning, t1, t2, k_object, .. }) = self.turning(motion, object, dt)
        else {
            return;
        };
        let rate = n.cross(turning);
        let [r1, r2] = k_object.times(k_object.solve([rate.dot(t1), rate.dot(t2)]));
        self.rolled = (r1 * t1 + r2 * t2).cross(n);
    }

    /// Whether the contact is on a capsule's end cap, a fingertip pressing:
    /// there the contact keeps the thesis's anchored C (module doc).
    fn on_end_cap(&self) -> bool {
        matches!(self.bone, BoneAnchor::Capsule { s, .. } if !(s > 0.0 && s < 1.0))
    }

    /// The direction the object's outward normal at C has where the two
    /// surfaces touch: against a palm face, the face's inward normal; on a
    /// capsule's side, towards its axis. `None` off a palm face.
    fn facing(&self, bone: BoneShape, palm: &Palm, c: Vec3) -> Option<Vec3> {
        match (self.bone, bone) {
            (BoneAnchor::Palm { face: Some(face), .. }, _) => Some(-(palm.rotation * face)),
            (BoneAnchor::Capsule { .. }, BoneShape::Capsule(cap)) => {
                (cap.axis_point(cap.closest_parameter(c)) - c).try_normalize()
            }
            _ => None,
        }
    }

    /// For a contact on a capsule's side: how far C is from the axis (m),
    /// and the axis's direction. `None` on the palm.
    fn axis_from(&self, bone: BoneShape, c: Vec3) -> Option<(f32, Vec3)> {
        match (self.bone, bone) {
            (BoneAnchor::Capsule { .. }, BoneShape::Capsule(cap)) => {
                let rho = (cap.axis_point(cap.closest_parameter(c)) - c).length();
                (rho > 0.0).then(|| (rho, (cap.b - cap.a).normalize_or_zero()))
            }
            _ => None,
        }
    }

    /// Rolls the contact over `dt` (s): carries C on the object, and p on
    /// the bone, to where the surfaces touch after their relative spin,
    /// keeping the friction spring's tangential stretch; the patch moves
    /// with C. Records the spin it took up in [`Anchor::rolled`] (zero if
    /// nothing rolled).
    pub fn roll(&mut self, motion: &BoneMotion, object: &ObjectView, dt: f32) {
        self.rolled = Vec3::ZERO;
        if self.on_end_cap() {
            return;
        }
        let Some(Turning { site, n, turning, t1, t2, k_object }) = self.turning(motion, object, dt)
        else {
            return;
        };
        // Montana's rate: the two curvatures add. The bone's is the one C
        // touches: on a capsule's side, the skin sunk d round the axis,
        // a cylinder of ρ = R_b − d through C, not the bone's radius.
        let side = self.axis_from(motion.now(), site.c);
        let k_bone =
            side.map_or(Curvature::default(), |(rho, axis)| Curvature::round(rho, axis, t1, t2));
        let k = k_object + k_bone;
        let rate = n.cross(turning);
        let moved = k.solve([rate.dot(t1), rate.dot(t2)]);
        let shift = (moved[0] * t1 + moved[1] * t2) * dt;
        if shift == Vec3::ZERO || !shift.is_finite() {
            return;
        }
        let (shape, pose) = (object.shape, &object.pose);
        let c = surface::project_to_surface(shape, pose, site.c + shift);
        let normal = normal_near(object, c, n).unwrap_or(n);
        // The roll integrated open-loop drifts with every error of the
        // curvature read: C is brought back to where the surfaces truly
        // touch, where the object's normal faces the bone (a palm face's
        // own normal, or a capsule's axis), by one Newton step. As C moves,
        // the object's normal turns by its curvature, and the direction to
        // a capsule's axis turns the other way, by 1/ρ across it: the
        // step's slope is K_o + K_bone. On a capsule, only along its axis:
        // across it, p lies under C's normal, so where C sits is the
        // spring's stretch, which the roll keeps (below); C faces the axis
        // there only for a slack spring. Set back across too, C lost its
        // stretch every step and had it put back from afar.
        let facing = self.facing(motion.now(), motion.palm_now(), c).unwrap_or(normal);
        let miss = facing - normal;
        let back = k.solve([miss.dot(t1), miss.dot(t2)]);
        let back = match side {
            Some((_, axis)) => {
                let along = (axis - axis.dot(n) * n).normalize_or_zero();
                let (a1, a2) = (along.dot(t1), along.dot(t2));
                let part = back[0] * a1 + back[1] * a2;
                [part * a1, part * a2]
            }
            None => back,
        };
        let (c, normal) = if back == [0.0; 2] {
            (c, normal)
        } else {
            let c = surface::project_to_surface(shape, pose, c + back[0] * t1 + back[1] * t2);
            (c, normal_near(object, c, normal).unwrap_or(normal))
        };
        // The spring's tangential stretch, kept: p goes under C less it.
        // On a palm face p is a material point of the palm, and C's offset
        // from it is the spring's. On a capsule's side p is not: it lies a
        // radius from the axis against C's normal, so as the object turns
        // on the skin by θ = (ω − ω_skin)·dt, p slid round the bone by
        // R_b·θ, and the depth d along the normal turned into the tangent
        // plane by d·θ. Neither is a slip of the surfaces: the spring grows
        // by their relative velocity at C (Cundall & Strack; Luding 2008),
        // so both come off, ρ·θ × n for C at ρ = R_b − d from the axis.
        let d = site.c - site.p;
        let stretch = d - d.dot(site.n) * site.n;
        let stretch = match side {
            Some((rho, _)) => stretch - rho * dt * turning.cross(n),
            None => stretch,
        };
        let foot = c - stretch;
        self.bone = match (self.bone, motion.now()) {
            // Along the bone as far as its axis runs along the surface: a
            // bone that points into the object (a fingertip pressing) keeps
            // its depth, where the axis point nearest the foot would pull p
            // back along the bone by as much as it is sunk.
            (BoneAnchor::Capsule { s, dir_in_palm }, BoneShape::Capsule(cap)) => {
                let axis = cap.b - cap.a;
                let along = axis - axis.dot(normal) * normal;
                let shift = foot - site.p;
                let shift = shift - shift.dot(normal) * normal;
                let len2 = along.length_squared();
                let ds = if len2 > 1e-12 { shift.dot(along) / len2 } else { 0.0 };
                BoneAnchor::Capsule { s: (s + ds).clamp(0.0, 1.0), dir_in_palm }
            }
            (BoneAnchor::Capsule { .. }, BoneShape::Palm(_)) => self.bone,
            // On a palm face, p slides along the face by the same shift:
            // found again from the foot along the object's normal, it would
            // land a depth × the normals' angle away, and each step's error
            // would stretch the spring further.
            // Rolled past the face's edge, p is found as a new contact's
            // is: clamped to the palm, at its edge, where the palm has no
            // normal of its own. The palm ends there; the face does not.
            (BoneAnchor::Palm { local, face: Some(face) }, BoneShape::Palm(palm)) => {
                let on_face = face * face.dot(local);
                let shift = foot - site.p;
                let moved = palm.to_local(site.p + shift - shift.dot(site.n) * site.n);
                let local = moved - face * face.dot(moved) + on_face;
                if palm_face_under(&palm, local, normal) == Some(face) {
                    BoneAnchor::Palm { local, face: Some(face) }
                } else {
                    BoneAnchor::at(&motion.now(), motion.palm_now(), foot, normal)
                }
            }
            (BoneAnchor::Palm { .. }, _) => {
                BoneAnchor::at(&motion.now(), motion.palm_now(), foot, normal)
            }
        };
        // A capsule's p is where its surface is deepest along n: across the
        // bone, the stretch is C's offset from it. Kept by moving C. Moving
        // C by δ turns its normal by K_o·δ, which moves p the other way and
        // turns the depth into the tangent plane: the stretch changes by
        // (I + ρ·K_o)·δ, the slope of these Newton steps. Started where the
        // roll took C, close to it, the second closes what the first's
        // normal, read a little towards the last one, left.
        // On a palm face, the face's normal: the stretch's own, and p is
        // under C less the stretch already.
        let (mut c, mut normal) = (c, normal);
        for _ in 0..side.map_or(1, |_| HELD_STEPS) {
            let contact_n = self.bone.normal(motion.palm_now(), normal);
            let p = self.bone.point(motion.now(), contact_n);
            let held = c - p - (c - p).dot(contact_n) * contact_n;
            let to = match self.axis_from(motion.now(), c) {
                Some((rho, _)) => {
                    let miss = stretch - held;
                    let slope = k_object.stretch_slope(rho);
                    let [a, b] = slope.inverse_times([miss.dot(t1), miss.dot(t2)]);
                    c + a * t1 + b * t2
                }
                None => c + stretch - held,
            };
            c = surface::project_to_surface(shape, pose, to);
            // The normal where C came to rest: set across a capsule by the
            // stretch, it is not where the roll alone would have taken it.
            normal = normal_near(object, c, normal).unwrap_or(normal);
        }
        self.c_local = pose.inverse_transform_point(c);
        self.n_local = pose.rotation.inverse() * normal;
        // The patch moves with C, turned as the surface turns under it: on
        // a ball, a turn about its centre, so the ring stays centred on C.
        let turn = Quat::from_rotation_arc(n, normal);
        let samples = &mut self.samples;
        for i in 0..samples.len() {
            let offset = pose.transform_point(samples.object.get(i)) - site.c;
            let moved = surface::project_to_surface(shape, pose, c + turn * offset);
            samples.object.set(i, pose.inverse_transform_point(moved));
        }
        // The spin taken up is what C truly rolled on the object, K·ΔC/dt:
        // what C moved to keep the stretch did not roll, so the patch's
        // dampers must still see that spin.
        let delta = c - site.c;
        let [r1, r2] = k.times([delta.dot(t1), delta.dot(t2)]);
        let rolled = (r1 * t1 + r2 * t2) / dt;
        self.rolled = rolled.cross(n);
    }
}

/// A unit quaternion's rotation vector (its axis times its angle, rad), as
/// glam's `to_scaled_axis`, but with libm's `atan2`: the same bits on
/// every target, so that a rolling run in WebAssembly is the native one.
fn rotation_vector(q: Quat) -> Vec3 {
    let v = Vec3::new(q.x, q.y, q.z);
    let length = v.length();
    if length >= 1.0e-8 { v / length * (2.0 * libm::atan2f(length, q.w)) } else { Vec3::ZERO }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sphere_rolls_every_way_a_cylinder_across_and_a_face_not_at_all() {
        let (t1, t2) = (Vec3::X, Vec3::Z);
        let r = [0.3, -0.2];
        // A 2 cm ball on a flat palm: the contact moves R·rate on it.
        let ball = Curvature::round(0.02, Vec3::ZERO, t1, t2);
        let moved = ball.solve(r);
        assert!((moved[0] - 0.006).abs() < 1e-7 && (moved[1] + 0.004).abs() < 1e-7, "{moved:?}");
        assert!(ball.curved());
        // A 1 cm cylinder lying along x: it rolls across its axis only.
        let pen = Curvature::round(0.01, Vec3::X, t1, t2);
        let moved = pen.solve(r);
        assert!(moved[0].abs() < 1e-9 && (moved[1] + 0.002).abs() < 1e-7, "{moved:?}");
        // A 2 cm ball on a capsule's side of 1 cm across x: the curvatures
        // add across the capsule, the ball's alone along it.
        let moved = (ball + pen).solve(r);
        assert!((moved[0] - 0.006).abs() < 1e-6, "{moved:?}");
        assert!((moved[1] + 0.2 / 150.0).abs() < 1e-7, "{moved:?}");
        // K·(K⁺·r) gives back r where it rolls.
        let back = (ball + pen).times(moved);
        assert!((back[0] - r[0]).abs() < 1e-6 && (back[1] - r[1]).abs() < 1e-6, "{back:?}");
        // A flat face: nothing rolls.
        assert_eq!(Curvature::default().solve(r), [0.0; 2]);
        assert!(!Curvature::default().curved());
    }

    #[test]
    fn the_rotation_vector_is_glam_s_scaled_axis() {
        for (axis, angle) in [(Vec3::Y, 0.3), (Vec3::new(1.0, -2.0, 0.5), 2.9), (Vec3::Z, 1e-5)] {
            let q = Quat::from_axis_angle(axis.normalize(), angle);
            let (ours, glam) = (rotation_vector(q), q.to_scaled_axis());
            assert!((ours - glam).length() <= 1e-6 * angle.max(1e-3), "{ours} vs {glam}");
        }
        assert_eq!(rotation_vector(Quat::IDENTITY), Vec3::ZERO);
    }
}
