//! Hand–object contacts: creation (§3.5.2), the per-step force of each
//! contact (§3.5.5, via [`crate::friction`]), slipping surface points
//! (§3.5.3) and skin patches (§3.5.4).
//!
//! # Lifecycle of a contact (one per (hand, bone, object))
//! * **Begins** when the bone's surface comes within
//!   [`crate::InteractionConfig::contact_offset`] of the object's surface.
//!   C is the closest (or, if penetrating, deepest-projection) point on the
//!   object's surface; n is the object's outward normal there.
//! * **Each step** it evaluates the contact law. While `f·n ≤ 0` (the bone
//!   hovers in the offset band or pulls away) it transmits no force and its
//!   anchors follow the bone ([`FrictionState::Separated`]).
//! * **Ends** when the bone's surface is farther than
//!   [`crate::InteractionConfig::release_offset`] from the object, or when
//!   the hand loses tracking.
//!
//! # Which bone point is `p`
//! The thesis uses the phalanx centroid, so a bone must sink by its own
//! radius before it pushes at all, and an object on a flat palm would sink
//! by half the palm's thickness. Here `p` is the bone's **deepest surface
//! point** towards the object: a point fixed on the bone's axis (its axial
//! parameter is frozen when the contact begins) pushed out by the radius
//! along `−n`; for the palm, the palm surface point fixed in the palm frame.
//! Because `p` is a material point of the bone, sliding the bone along its
//! own axis stretches the friction spring, as it should.

pub mod patch;
pub mod surface;

use crate::friction::{self, FrictionCoefficients, FrictionState, KineticFriction};
use crate::hand::{Bone, BoneShape, Palm};
use crate::object::ObjectId;
use crate::pipeline::HandId;
use glam::{Quat, Vec3};
use rapier3d::math::Pose;
use rapier3d::parry::shape::Shape;
use surface::SurfacePoint;

/// One active contact between a bone and an object, as of the last step.
#[derive(Debug, Clone)]
pub struct Contact {
    pub hand: HandId,
    pub bone: Bone,
    pub object: ObjectId,
    /// The contact point C on the object's surface (world, m).
    pub point: Vec3,
    /// The object's outward surface normal at C (world, unit).
    pub normal: Vec3,
    /// The bone's point p that pushes into the object (world, m).
    pub bone_point: Vec3,
    /// Penetration of p below C along n (m); negative while hovering.
    pub depth: f32,
    /// Force applied to the object by this contact in the last step (N).
    pub force: Vec3,
    /// Normal magnitude of that force (N), ≥ 0.
    pub normal_force: f32,
    /// The contact stiffness γ used in the last step (N/m): the object's γ,
    /// or less under the pipeline's stability limit.
    pub stiffness: f32,
    pub state: FrictionState,
    /// The skin patch's sample points on the object (world, m).
    pub samples: Vec<Vec3>,
    pub(crate) anchor: Anchor,
}

/// What a contact remembers between steps.
#[derive(Debug, Clone)]
pub(crate) struct Anchor {
    /// C and n in the object body's frame: static contacts move with it.
    c_local: Vec3,
    n_local: Vec3,
    bone: BoneAnchor,
    /// Per sample: its point in the object frame and its skin offset from p
    /// in the bone frame.
    samples: Vec<(Vec3, Vec3)>,
    /// The penetration depth the force saw last step (m), for the
    /// penetration-speed limit.
    limited_depth: f32,
}

/// The material point of the bone that the contact holds on to.
#[derive(Debug, Clone, Copy)]
enum BoneAnchor {
    /// Axial parameter of p on the capsule, and the bone's direction in the
    /// palm frame when the contact began (to carry the patch's skin offsets
    /// along as the finger bends).
    Capsule { s: f32, dir_in_palm: Vec3 },
    /// p in the palm frame.
    Palm { local: Vec3 },
}

/// A bone as seen by one step: its shape now and one step ago.
#[derive(Debug, Clone, Copy)]
pub(crate) struct BoneMotion {
    pub now: BoneShape,
    pub prev: BoneShape,
    pub palm_now: Palm,
    pub palm_prev: Palm,
}

/// The object as seen by one step.
pub(crate) struct ObjectView<'a> {
    pub id: ObjectId,
    pub pose: Pose,
    pub shape: &'a dyn Shape,
    pub linvel: Vec3,
    pub angvel: Vec3,
    pub center_of_mass: Vec3,
    pub gamma: f32,
    pub damping: f32,
    /// The deepest penetration the spring sees (m): 20 % of the object's
    /// bounding diameter (the force cap), or `None`.
    pub max_depth: Option<f32>,
    pub mu: FrictionCoefficients,
}

impl ObjectView<'_> {
    fn velocity_at(&self, q: Vec3) -> Vec3 {
        self.linvel + self.angvel.cross(q - self.center_of_mass)
    }
}

/// Step-wide settings of the contact law.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LawSettings {
    pub dt: f32,
    pub kinetic: KineticFriction,
    pub max_penetration_speed: Option<f32>,
    pub probe_offset: f32,
    pub patch: patch::PatchConfig,
}

/// Closest-feature geometry between a bone and an object (world).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Proximity {
    /// On the bone's surface.
    pub bone_point: Vec3,
    /// On the object's surface.
    pub object_point: Vec3,
    /// The object's outward normal at `object_point`.
    pub object_normal: Vec3,
    /// Signed surface distance, negative when penetrating (m).
    pub distance: f32,
}

fn bone_rotation(anchor: BoneAnchor, bone: BoneShape, palm: &Palm) -> Quat {
    match (anchor, bone) {
        (BoneAnchor::Capsule { dir_in_palm, .. }, BoneShape::Capsule(c)) => {
            let now = palm.rotation.inverse() * (c.b - c.a).normalize_or_zero();
            palm.rotation * Quat::from_rotation_arc(dir_in_palm, now)
        }
        _ => palm.rotation,
    }
}

fn bone_point(anchor: BoneAnchor, bone: BoneShape, n: Vec3) -> Vec3 {
    match (anchor, bone) {
        (BoneAnchor::Capsule { s, .. }, BoneShape::Capsule(c)) => c.axis_point(s) - c.radius * n,
        (BoneAnchor::Palm { local }, BoneShape::Palm(p)) => p.to_world(local),
        // A bone never changes kind; keep a harmless answer for the type system.
        (_, BoneShape::Capsule(c)) => c.centroid(),
        (_, BoneShape::Palm(p)) => p.center,
    }
}

/// The contact site on the face found by the closest-feature query, under
/// the bone's point nearest the object's centre: the middle of the overlap
/// of a flat bone and a flat face, wherever either has slid.
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

/// The bone's material point that presses at C (normal `n`).
fn anchor_on_bone(bone: &BoneShape, palm: &Palm, c: Vec3, n: Vec3) -> BoneAnchor {
    match bone {
        BoneShape::Capsule(cap) => {
            let dir = palm.rotation.inverse() * (cap.b - cap.a).normalize_or_zero();
            BoneAnchor::Capsule { s: cap.closest_parameter(c), dir_in_palm: dir }
        }
        BoneShape::Palm(p) => {
            // The palm surface point under C: where a ray from C along −n
            // leaves the palm box while C is inside it, else the palm's
            // closest point to C.
            let local = p.to_local(c);
            let under = if local.abs().cmple(p.half_extents).all() {
                let dir = p.rotation.inverse() * -n;
                let exit = (0..3)
                    .filter(|&i| dir[i].abs() > 1e-6)
                    .map(|i| (p.half_extents[i].copysign(dir[i]) - local[i]) / dir[i])
                    .fold(f32::INFINITY, f32::min);
                if exit.is_finite() { c - n * exit } else { c }
            } else {
                p.to_world(local.clamp(-p.half_extents, p.half_extents))
            };
            BoneAnchor::Palm { local: p.to_local(under) }
        }
    }
}

impl Anchor {
    /// Anchors a contact at the current closest features.
    fn new(
        prox: &Proximity,
        bone: Bone,
        motion: &BoneMotion,
        object: &ObjectView,
        patch: &patch::PatchConfig,
    ) -> Anchor {
        let near = SurfacePoint { point: prox.object_point, normal: prox.object_normal };
        let site = site_under_bone(&motion.now, object, near);
        let (c, n) = (site.point, site.normal);
        let bone_anchor = anchor_on_bone(&motion.now, &motion.palm_now, c, n);
        let radius = match bone.skin_class() {
            crate::hand::SkinClass::Finger => patch.finger_radius,
            crate::hand::SkinClass::Thumb => patch.thumb_radius,
            crate::hand::SkinClass::Palm => patch.palm_radius,
        };
        let rot_inv = bone_rotation(bone_anchor, motion.now, &motion.palm_now).inverse();
        let samples = patch::sample_offsets(n, patch.samples, radius)
            .into_iter()
            .map(|o| {
                let ci = surface::project_to_surface(object.shape, &object.pose, c + o);
                (object.pose.inverse_transform_point(ci), rot_inv * (ci - c))
            })
            .collect();
        Anchor {
            c_local: object.pose.inverse_transform_point(c),
            n_local: object.pose.rotation.inverse() * n,
            bone: bone_anchor,
            samples,
            limited_depth: 0.0,
        }
    }
}

impl Contact {
    /// Creates a contact at the current closest features.
    pub(crate) fn begin(
        hand: HandId,
        bone: Bone,
        prox: &Proximity,
        motion: &BoneMotion,
        object: &ObjectView,
        settings: &LawSettings,
    ) -> Contact {
        let anchor = Anchor::new(prox, bone, motion, object, &settings.patch);
        Contact {
            hand,
            bone,
            object: object.id,
            point: prox.object_point,
            normal: prox.object_normal,
            bone_point: prox.bone_point,
            depth: -prox.distance,
            force: Vec3::ZERO,
            normal_force: 0.0,
            stiffness: object.gamma,
            state: FrictionState::Separated,
            samples: Vec::new(),
            anchor,
        }
    }

    /// Evaluates the contact law for this step and updates the anchors.
    /// Writes the sample forces into `out` (cleared first).
    ///
    /// `proximity` is the bone–object closest-feature query, or `None` if
    /// the caller skipped it; `query` runs it (returning `None` beyond the
    /// release offset). A contact that stays static never needs it: its bone
    /// point is pressed in below C, inside the friction cone. Returns
    /// `false` when the contact has ended.
    pub(crate) fn update(
        &mut self,
        proximity: Option<Proximity>,
        query: &mut dyn FnMut() -> Option<Proximity>,
        motion: &BoneMotion,
        object: &ObjectView,
        settings: &LawSettings,
        scratch: &mut Scratch,
    ) -> bool {
        scratch.forces.clear();
        let pose = &object.pose;
        let a = &mut self.anchor;
        let n = (pose.rotation * a.n_local).normalize_or_zero();
        let c = pose.transform_point(a.c_local);
        let p = bone_point(a.bone, motion.now, n);
        let p_prev = bone_point(a.bone, motion.prev, n);
        let gamma = object.gamma;
        self.stiffness = gamma;

        // Eq. 3.4 with the penetration-speed limit: the depth the spring
        // sees may grow by at most v_max·dt per step beyond what the
        // object's own approach adds, so a bone that teleports deep inside
        // (a tracking glitch) ramps in like a finger pressing at v_max
        // instead of releasing the whole spring at once, while an object
        // falling onto a hand meets the full spring.
        let d = c - p;
        let depth = d.dot(n);
        let object_velocity = object.velocity_at(c);
        let mut seen_depth = match settings.max_penetration_speed {
            Some(v) => {
                let approach = object_velocity.dot(n).max(0.0);
                depth.min(a.limited_depth + (v + approach) * settings.dt)
            }
            None => depth,
        };
        a.limited_depth = seen_depth.max(0.0);
        // The force cap: the spring never sees more than the thesis's 20 %
        // penetration, so its normal force stays ≤ γ·0.2·d.
        if let Some(max) = object.max_depth {
            seen_depth = seen_depth.min(max);
        }
        let spring = friction::spring_force(gamma, c, p) + gamma * (seen_depth - depth) * n;
        // The bone's velocity, with its speed into the object held to the
        // same limit, so a teleporting bone cannot kick through the damper.
        let mut bone_velocity = (p - p_prev) / settings.dt;
        if let Some(v) = settings.max_penetration_speed {
            let into = -bone_velocity.dot(n);
            if into > v {
                bone_velocity += (into - v) * n;
            }
        }
        let relative_velocity = bone_velocity - object_velocity;
        let f = friction::damped_spring_force(spring, object.damping, relative_velocity);

        // A bone that has not reached the surface pushes nothing, whatever
        // its speed: the damper only acts on a penetrating bone.
        let mut law = if seen_depth <= 0.0 {
            friction::resolve(Vec3::ZERO, n, object.mu, settings.kinetic)
        } else {
            friction::resolve(f, n, object.mu, settings.kinetic)
        };
        if let Some(max) = object.max_depth {
            // Eq. 3.8 as written scales an unbounded stretch: bound it too.
            let ft_cap = object.mu.static_mu.max(object.mu.dynamic_mu) * gamma * max;
            let ft_mag = law.tangential.length();
            if ft_mag > ft_cap {
                law.tangential *= ft_cap / ft_mag;
            }
        }

        self.bone_point = p;
        self.depth = depth;
        self.state = law.state;
        self.normal_force = law.normal.length();
        self.force = law.on_object();

        match law.state {
            FrictionState::Separated if depth > 0.0 => {
                // Still inside, but the damper says the surfaces part faster
                // than the spring pushes: no force this step, anchors kept.
                self.samples.clear();
                return true;
            }
            FrictionState::Separated => {
                // Not pressing: no force, and the contact re-anchors at the
                // current closest features so the next press starts fresh.
                let Some(prox) = proximity.or_else(query) else { return false };
                *a = Anchor::new(&prox, self.bone, motion, object, &settings.patch);
                self.point = prox.object_point;
                self.normal = prox.object_normal;
                self.samples.clear();
                self.force = Vec3::ZERO;
                return true;
            }
            FrictionState::Dynamic => {
                if proximity.or_else(query).is_none() {
                    return false;
                }
                // Slipping: skin and surface slide over each other, so both
                // anchors move. The site re-centres under the bone (the
                // overlap follows whichever of bone and face is smaller),
                // then C moves along the surface (§3.5.3) so the spring
                // keeps the kinetic stretch (Coulomb) or none (thesis).
                let site = site_under_bone(&motion.now, object, SurfacePoint { point: c, normal: n });
                let bone_anchor = anchor_on_bone(&motion.now, &motion.palm_now, site.point, site.normal);
                let p_new = bone_point(bone_anchor, motion.now, site.normal);
                let target = match settings.kinetic {
                    KineticFriction::Coulomb => {
                        let slip = (d - depth * n).normalize_or_zero();
                        let keep = friction::kinetic_stretch(self.normal_force, object.mu, gamma);
                        Some(site.point + slip * keep)
                    }
                    KineticFriction::Thesis => None,
                };
                if let Some(moved) =
                    surface::slide(object.shape, pose, site, target, p_new, settings.probe_offset)
                {
                    let shift = moved.point - c;
                    a.c_local = pose.inverse_transform_point(moved.point);
                    a.n_local = pose.rotation.inverse() * moved.normal;
                    // The skin offsets live in the bone frame, which the new
                    // anchor redefines: carry them over.
                    let carry = bone_rotation(bone_anchor, motion.now, &motion.palm_now).inverse()
                        * bone_rotation(a.bone, motion.now, &motion.palm_now);
                    for (_, skin) in a.samples.iter_mut() {
                        *skin = carry * *skin;
                    }
                    a.bone = bone_anchor;
                    for (ci_local, _) in a.samples.iter_mut() {
                        let ci = pose.transform_point(*ci_local) + shift;
                        *ci_local = pose.inverse_transform_point(surface::project_to_surface(
                            object.shape,
                            pose,
                            ci,
                        ));
                    }
                }
            }
            FrictionState::Static => {}
        }

        // Skin patch: per-sample deviation springs, each limited by its own
        // share of the friction cone (torsional slip), mean removed.
        let c_now = pose.transform_point(a.c_local);
        let n_now = (pose.rotation * a.n_local).normalize_or_zero();
        // Rotations as matrices: each is applied to every sample.
        let object_rot = glam::Mat3::from_quat(pose.rotation);
        let rot = glam::Mat3::from_quat(bone_rotation(a.bone, motion.now, &motion.palm_now));
        let rot_rate = (rot - glam::Mat3::from_quat(bone_rotation(a.bone, motion.prev, &motion.palm_prev)))
            * (1.0 / settings.dt);
        // Damping of the deviations, folded in as extra stretch c/γ · ė.
        let lag = if gamma > 0.0 { object.damping / gamma } else { 0.0 };
        let fn_mag = self.normal_force;
        let static_limit = object.mu.static_mu * fn_mag / gamma;
        let kinetic_limit = object.mu.dynamic_mu * fn_mag / gamma;
        let normal_limit = fn_mag / gamma;
        let deviations = &mut scratch.deviations;
        deviations.clear();
        self.samples.clear();
        for (ci_local, skin) in a.samples.iter_mut() {
            let mut ci = pose.translation + object_rot * *ci_local;
            let rest = c_now + rot * *skin;
            let e = ci - rest;
            let e_n = e.dot(n_now).clamp(-normal_limit, normal_limit);
            let mut e_t = e - e.dot(n_now) * n_now;
            if e_t.length_squared() > static_limit * static_limit {
                // This sample slips: it keeps the kinetic stretch and its
                // object point moves along the surface.
                e_t = e_t.normalize_or_zero() * kinetic_limit;
                ci = surface::project_to_surface(object.shape, pose, rest + e_t + e_n * n_now);
                *ci_local = pose.inverse_transform_point(ci);
            }
            let e_rate = object.angvel.cross(ci - c_now) - rot_rate * *skin;
            deviations.push(e_t + e_n * n_now + lag * e_rate);
            self.samples.push(ci);
        }
        let mut forces = std::mem::take(&mut scratch.sample_forces);
        patch::sample_forces(self.force, deviations, gamma, &mut forces);
        self.point = c_now;
        self.normal = n_now;
        scratch.forces.extend(forces.iter().copied().zip(self.samples.iter().copied()));
        scratch.sample_forces = forces;
        true
    }
}

/// Buffers reused from step to step, so updating a contact allocates nothing.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    deviations: Vec<Vec3>,
    sample_forces: Vec<Vec3>,
    /// `(force on the object, world point)` per sample of the last update.
    pub forces: Vec<(Vec3, Vec3)>,
}

/// Contact begin/end notifications, for visuals and sound.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub enum ContactEventKind {
    Began,
    Ended,
}

/// A contact began or ended during a step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactEvent {
    pub kind: ContactEventKind,
    pub hand: HandId,
    pub bone: Bone,
    pub object: ObjectId,
    /// The contact point C at that moment (world, m).
    pub point: Vec3,
    /// Simulation time of the step (s).
    pub time: f64,
}
