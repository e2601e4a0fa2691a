//! Hand–object contacts: creation (§3.5.2), the per-step force of each
//! contact (§3.5.5, via [`crate::friction`]), slipping surface points
//! (§3.5.3) and skin patches (§3.5.4).
//!
//! * `detect.rs`: the collision driver, which finds bones near objects;
//! * `anchor.rs`: what a contact holds on to (C, p, its patch's samples);
//! * `line.rs`: line and area contacts, a patch laid along a bone that
//!   lies on a face, or over the palm on a plate;
//! * `roll.rs`: rolling contacts, C and p carried as the surfaces roll;
//! * [`patch`]: spreading a contact's force over its skin patch, with its
//!   deviation springs' kernel (`patch/deviation.rs`, written once on a
//!   lane type, and its eight-lane AVX2 type beneath it,
//!   `patch/deviation/wide8.rs`);
//! * `lanes.rs`: four vectors at a time, the patch's SIMD arithmetic, and
//!   the `Lane` trait that kernels are written on (`f32x4`, or one `f32`);
//! * [`surface`]: moving C along the surface by inverse ray casts;
//! * [`event`]: begin/end events.
//!
//! # Lifecycle of a contact (one per (hand, bone, object))
//! * **Begins** when the bone's surface comes within
//!   [`crate::InteractionConfig::contact_offset`] of the object's surface.
//!   C is the closest (or, if penetrating, deepest-projection) point on the
//!   object's surface; n is the object's outward normal there.
//! * **Each step** it evaluates the contact law (`Contact::update`). While
//!   `f·n ≤ 0` (the bone hovers in the offset band or pulls away) it
//!   transmits no force and its anchors follow the bone
//!   ([`FrictionState::Separated`]).
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

pub(crate) mod anchor;
pub(crate) mod detect;
pub mod event;
pub(crate) mod lanes;
mod line;
pub mod patch;
mod roll;
pub mod surface;

pub use event::{ContactEvent, ContactEventKind};

use crate::friction::{self, ForceCap, FrictionCoefficients, FrictionState, KineticFriction};
use crate::hand::{Bone, BoneShape, HandId, HandPose, Palm};
use crate::scene::ObjectId;
use anchor::{Anchor, Site};
use detect::{Detector, Proximity};
use glam::{Mat3, Vec3};
use rapier3d::math::Pose;
use rapier3d::parry::shape::Shape;
use surface::SurfacePoint;

/// One active contact between a bone and an object, as of the last step.
#[derive(Debug, Clone)]
pub struct Contact {
    /// The hand whose bone touches.
    pub hand: HandId,
    /// The bone that touches.
    pub bone: Bone,
    /// The object touched.
    pub object: ObjectId,
    /// The contact point C on the object's surface (world, m).
    pub point: Vec3,
    /// The contact normal at C (world, unit): the object's outward surface
    /// normal there, or for a press on the interior of a palm face, that
    /// face's inward normal (the plane the object rests on).
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
    /// Whether it stuck, slipped or did not press in the last step.
    pub state: FrictionState,
    /// The skin patch's sample points on the object (world, m).
    pub samples: Vec<Vec3>,
    pub(crate) anchor: Anchor,
    /// The velocity of p over the last step (m/s), its speed into the
    /// object limited as the law limits it: where a step-aware spring
    /// expects the bone to go on (`pipeline/step/implicit.rs`).
    pub(crate) bone_velocity: Vec3,
}

/// A bone as seen by one step: its hand's pose now and one step ago (the
/// same pose on the hand's first tracked step). It borrows the poses, so
/// each stage looks it up afresh: cheaper than carrying two shapes and two
/// palms from stage to stage.
#[derive(Debug, Clone, Copy)]
pub(crate) struct BoneMotion<'h> {
    pub bone: Bone,
    pub pose: &'h HandPose,
    pub prev_pose: &'h HandPose,
    /// Which poses they are (`HandSlot`'s marks): what was computed from
    /// one pose holds for another of the same mark.
    pub marks: [u64; 2],
}

impl BoneMotion<'_> {
    /// The bone's shape now.
    #[inline(always)]
    pub fn now(&self) -> BoneShape {
        self.pose.bone(self.bone)
    }

    /// The bone's shape one step ago.
    #[inline(always)]
    pub fn prev(&self) -> BoneShape {
        self.prev_pose.bone(self.bone)
    }

    /// The palm now, whose frame a finger's skin frame rolls with.
    #[inline(always)]
    pub fn palm_now(&self) -> &Palm {
        &self.pose.palm
    }

    /// The palm one step ago.
    #[inline(always)]
    pub fn palm_prev(&self) -> &Palm {
        &self.prev_pose.palm
    }
}

/// The object as seen by one step.
#[derive(Clone, Copy)]
pub(crate) struct ObjectView<'a> {
    pub id: ObjectId,
    pub pose: Pose,
    pub shape: &'a dyn Shape,
    pub linvel: Vec3,
    pub angvel: Vec3,
    pub center_of_mass: Vec3,
    /// The largest principal 1/inertia (1/(kg·m²)).
    pub inv_inertia: f32,
    /// How many hand contacts share the object this step (≥ 1).
    pub sharing: f32,
    /// Contact stiffness γ (N/m) and damping (N·s/m), under the stability
    /// limit.
    pub gamma: f32,
    pub damping: f32,
    /// The force cap, if on.
    pub cap: Option<ForceCap>,
    pub mu: FrictionCoefficients,
}

impl ObjectView<'_> {
    #[inline]
    fn velocity_at(&self, q: Vec3) -> Vec3 {
        self.linvel + self.angvel.cross(q - self.center_of_mass)
    }

    /// The object as one contact sees it: with `share` (0 to 1) of its γ
    /// and damping, the contact's share of its virtual finger's.
    #[inline]
    pub fn shared(self, share: f32) -> Self {
        ObjectView { gamma: self.gamma * share, damping: self.damping * share, ..self }
    }
}

/// Step-wide settings of the contact law.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct LawSettings {
    pub dt: f32,
    pub kinetic: KineticFriction,
    pub max_penetration_speed: Option<f32>,
    pub probe_offset: f32,
    pub patch: patch::PatchConfig,
    /// The contact dampers' damping ratio ζ (0 without dampers).
    pub damping_ratio: f32,
    /// The patch's deviation springs; without them each sample carries
    /// `f/N`, as in the thesis.
    pub deviation_springs: bool,
    /// A slipping contact re-centres under the bone before C moves.
    pub recentre: bool,
    /// How near a face (m) a bone lying along it touches it, for line
    /// contacts (`line.rs`): the contact offset; `None` without them.
    pub line_band: Option<f32>,
    /// Contacts follow the surfaces as they roll (`roll.rs`).
    pub rolling: bool,
    /// The sliding speed over which static friction fades to kinetic (m/s),
    /// or `None` for the thesis's sudden drop ([`friction::stribeck`]).
    pub stribeck_speed: Option<f32>,
}

/// How a contact presses this step, before any force: where its anchors
/// are, and how deep its spring sees the bone. Found for every contact
/// before any is updated, since contacts of one hand share γ by how deep
/// each presses ([`crate::friction::grip`]).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Press {
    site: Site,
    /// How deep p is below C along n (m); negative while hovering.
    pub depth: f32,
    /// The depth after the penetration-speed limit, before the cap (m).
    limited: f32,
    /// The depth the spring sees: the speed limit, then the cap (m).
    pub seen: f32,
    /// The bone's and the object's velocities at the contact (m/s).
    bone_velocity: Vec3,
    object_velocity: Vec3,
}

impl Press {
    /// The contact normal (world, unit): see [`Contact::normal`].
    #[inline]
    pub fn normal(&self) -> Vec3 {
        self.site.n
    }

    /// The friction coefficients of skin sliding over the object as fast as
    /// the bone moves along its surface here ([`friction::stribeck`]).
    #[inline(always)]
    fn friction(&self, mu: FrictionCoefficients, settings: &LawSettings) -> FrictionCoefficients {
        let Some(v_s) = settings.stribeck_speed else { return mu };
        if mu.static_mu == mu.dynamic_mu {
            // Nothing to fade (most materials): skip the speed and the exp.
            return mu;
        }
        let relative = self.bone_velocity - self.object_velocity;
        let sliding = relative - relative.dot(self.site.n) * self.site.n;
        mu.sliding_at(sliding.length(), v_s)
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
        let near = SurfacePoint { point: prox.object_point, normal: prox.object_normal };
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
            anchor: Anchor::new(near, bone, motion, object, settings),
            bone_velocity: Vec3::ZERO,
        }
    }

    /// How this contact presses this step ([`Press`]): its anchors' site,
    /// and the depth its spring sees under the penetration-speed limit and
    /// the force cap. Changes nothing: [`Self::update`] keeps the limited
    /// depth for the next step.
    #[inline(always)]
    pub(crate) fn press(
        &self,
        object: &ObjectView,
        motion: &BoneMotion,
        settings: &LawSettings,
    ) -> Press {
        let site = self.anchor.site(object, motion);
        let depth = (site.c - site.p).dot(site.n);
        let object_velocity = object.velocity_at(site.c);
        let bone_velocity = (site.p - site.p_prev) / settings.dt;
        let limited = match settings.max_penetration_speed {
            Some(v) => {
                let approach = object_velocity.dot(site.n);
                let bone_speed = -bone_velocity.dot(site.n);
                let previous = self.anchor.limited_depth;
                friction::speed_limited_depth(depth, previous, approach, bone_speed, v, settings.dt)
            }
            None => depth,
        };
        let seen = object.cap.map_or(limited, |cap| cap.depth(limited));
        Press { site, depth, limited, seen, bone_velocity, object_velocity }
    }

    /// Evaluates the contact law for this step and updates the anchors:
    /// reaction → resolve → slip → spread over the patch. Leaves the
    /// sample forces on the object, with their points, in `scratch`
    /// ([`patch::PatchScratch::applied`]; none if it applies
    /// none: the caller clears it first). `press` is this
    /// step's [`Self::press`]; `object` carries the contact's own γ and
    /// damping (its share of its virtual finger's, under the stability
    /// limit).
    ///
    /// `proximity` is the bone–object closest-feature query, if the caller
    /// has run it; `detector` runs it when the contact needs it. A contact
    /// that stays static never does: its bone point is pressed in below C,
    /// inside the friction cone. Returns `false` when the contact has ended.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(crate) fn update(
        &mut self,
        press: &Press,
        proximity: Option<Proximity>,
        detector: &mut Detector,
        motion: &BoneMotion,
        object: &ObjectView,
        settings: &LawSettings,
        scratch: &mut patch::PatchScratch,
    ) -> bool {
        let at = press.site;
        self.anchor.limited_depth = press.limited.max(0.0);
        let relative = Self::relative_velocity(press, settings);
        let reaction = Self::reaction(press, object, relative);
        let (gamma, mu) = (object.gamma, press.friction(object.mu, settings));
        let law = friction::contact_law(
            reaction,
            at.n,
            press.seen,
            gamma,
            mu,
            settings.kinetic,
            object.cap,
        );
        self.stiffness = gamma;
        self.bone_point = at.p;
        self.bone_velocity = press.object_velocity + relative;
        self.depth = press.depth;
        self.state = law.state;
        self.normal_force = law.normal.length();
        self.force = law.on_object();

        let mut touching = || proximity.or_else(|| detector.still_touching(&motion.now(), object));
        match law.state {
            FrictionState::Separated if press.depth > 0.0 => {
                // Still inside, but the damper says the surfaces part faster
                // than the spring pushes: no force this step, anchors kept.
                self.samples.clear();
                return true;
            }
            FrictionState::Separated => {
                // Not pressing: no force, and the contact re-anchors at the
                // current closest features so the next press starts fresh.
                let Some(prox) = touching() else { return false };
                let near = SurfacePoint { point: prox.object_point, normal: prox.object_normal };
                self.anchor = Anchor::new(near, self.bone, motion, object, settings);
                self.point = prox.object_point;
                self.normal = prox.object_normal;
                self.samples.clear();
                self.force = Vec3::ZERO;
                return true;
            }
            FrictionState::Dynamic => {
                if touching().is_none() {
                    return false;
                }
                let kinetic = (settings.kinetic == KineticFriction::Coulomb).then_some(mu);
                let slip = anchor::Slip {
                    normal_force: self.normal_force,
                    kinetic,
                    probe_offset: settings.probe_offset,
                    recentre: settings.recentre,
                };
                self.anchor.slide(&at, &slip, motion, object);
            }
            FrictionState::Static => {}
        }
        // A static contact's anchors have not moved since `press` placed
        // its site: the patch is spread there.
        let site = (law.state == FrictionState::Static).then_some(at);
        self.spread(site, motion, object, settings, scratch);
        true
    }

    /// The damped spring on the bone (N), at the depth the safeguards let
    /// the spring see ([`Press::seen`]), with the bone's speed into the
    /// object, relative to it, limited for the damper too.
    #[inline(always)]
    fn reaction(press: &Press, object: &ObjectView, relative_velocity: Vec3) -> Vec3 {
        let at = &press.site;
        let spring = friction::spring_at_depth(object.gamma, at.c, at.p, at.n, press.seen);
        friction::damped_spring_force(spring, object.damping, relative_velocity)
    }

    /// The bone's velocity relative to the object at the contact, its speed
    /// into the object limited as the spring's depth is.
    #[inline(always)]
    fn relative_velocity(press: &Press, settings: &LawSettings) -> Vec3 {
        let (bone, object_velocity) = (press.bone_velocity, press.object_velocity);
        match settings.max_penetration_speed {
            Some(v) => friction::limited_relative_velocity(bone, object_velocity, press.site.n, v),
            None => bone - object_velocity,
        }
    }

    /// Spreads this step's force over the skin patch (§3.5.4), at `site`
    /// if the anchors are still where it was found, else where they are.
    #[inline(always)]
    fn spread(
        &mut self,
        site: Option<Site>,
        motion: &BoneMotion,
        object: &ObjectView,
        settings: &LawSettings,
        scratch: &mut patch::PatchScratch,
    ) {
        let anchor = &self.anchor;
        let site = site.unwrap_or_else(|| anchor.site(object, motion));
        let rocking = if anchor.rigid {
            patch::Rocking::rigid(object, anchor.samples.len(), anchor.radius, settings)
        } else {
            patch::Rocking::soft(object)
        };
        // The skin frame kept from the last spread serves for a pose of its
        // mark: the pose one step ago after a step, or now while the hand
        // holds its pose.
        let [now, before] = motion.marks;
        let frame = |mark: u64, shape, palm| match anchor.skin {
            Some((kept, frame)) if kept == mark && !anchor::computing_frames_anew() => frame,
            _ => Mat3::from_quat(anchor.bone.rotation(shape, palm)),
        };
        let skin = frame(now, motion.now(), motion.palm_now());
        let skin_before = frame(before, motion.prev(), motion.palm_prev());
        let step = patch::PatchStep {
            center: site.c,
            normal: site.surface_n,
            skin,
            skin_rate: (skin - skin_before) * (1.0 / settings.dt),
            force: self.force,
            normal_force: self.normal_force,
            gamma: object.gamma,
            damping: object.damping,
            mu: object.mu,
            rocking,
            deviation_springs: settings.deviation_springs,
            spin: object.angvel - anchor.rolled,
        };
        self.anchor.skin = Some((now, skin));
        patch::spread(&step, &mut self.anchor.samples, object, scratch, &mut self.samples);
        self.point = site.c;
        self.normal = site.n;
    }
}
