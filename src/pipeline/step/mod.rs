//! One step of the interaction layer, in order: start reading here.
//!
//! [`InteractionWorld::step`] is the whole step. Its first half,
//! [`InteractionWorld::apply_hand_forces`], turns the hand poses set before
//! it into forces on the objects, stage by stage, one file each:
//!
//! 0. `follow.rs`: the hands that act follow the tracked hands;
//! 1. `clear.rs`: last step's hand forces are cleared;
//! 2. `keep.rs`: existing contacts are kept or end;
//! 3. `find.rs`: new contacts begin, found by the collision driver among
//!    the objects rapier's broad phase puts near each hand (`near.rs`);
//! 4. `share.rs`: how each contact presses, and its share of its virtual
//!    finger's γ;
//! 5. `stability.rs`: each object's stability limit on γ and damping;
//! 6. `update.rs`: each contact evaluates the contact law;
//! 7. `apply.rs`: its forces go to rapier, and are added to its object's
//!    total for [`crate::ObjectState::hand_force`].
//!
//! 8. `grab.rs`: for the grab baselines only, a qualifying grasp moves
//!    its object with the hand.
//!
//! Stages 6 and 7 run contact by contact, in update order (`update.rs`).
//! Stages 2 to 7 are built twice, for the baseline and for AVX2
//! (`avx2.rs`), with the same bits out.
//!
//! Its second half, [`InteractionWorld::step_physics`], is rapier's step:
//! gravity, object–object contacts and integration, with as many substeps
//! as `substeps.rs` chooses for what the hands push and for the rest.

mod apply;
#[cfg(target_arch = "x86_64")]
mod avx2;
mod clear;
mod find;
mod follow;
mod grab;
mod implicit;
mod keep;
pub(super) mod near;
mod share;
pub(crate) mod stability;
mod substeps;
mod update;

#[cfg(all(test, target_arch = "x86_64"))]
pub(crate) use avx2::BASELINE_ONLY;
pub(crate) use grab::GrabSlot;
pub(crate) use implicit::ImplicitMemory;
pub(crate) use substeps::Raised;

use super::config::InteractionConfig;
use super::record::Call;
use super::{HandSlot, InteractionWorld, ObjectSlot};
use crate::contact::detect::{Detector, Proximity};
use crate::contact::patch::PatchScratch;
use crate::contact::{
    BoneMotion, Contact, ContactEvent, ContactEventKind, LawSettings, ObjectView, Press,
};
use crate::friction::{ForceCap, FrictionCoefficients};
use crate::hand::{Bone, HandId};
use crate::scene::ObjectId;
use apply::RunForces;
use rapier3d::prelude::{ColliderSet, RigidBodySet, SharedShape};
use stability::{StabilityScale, nominal_damping};

/// Stages 6 and 7's borrows of the world (their methods are in
/// `update.rs` and `apply.rs`, children of this module, which see its
/// fields): what they read (the colliders,
/// for the objects' shapes) apart from what they write (the bodies'
/// forces, the events), so that one object's view serves a run of its
/// contacts.
struct Stage<'w> {
    colliders: &'w ColliderSet,
    hand_shapes: &'w [Option<SharedShape>],
    config: &'w InteractionConfig,
    /// The hands, whose poses the contacts' bone motions borrow.
    hands: &'w [HandSlot],
    /// Per contact, in update order: its press and its share of its
    /// virtual finger's γ (stage 4).
    presses: &'w [Press],
    shares: &'w [f32],
    /// Per object, its stability limit (stage 5).
    limits: &'w [StabilityScale],
    settings: &'w LawSettings,
    detector: &'w mut Detector,
    objects: &'w mut [ObjectSlot],
    bodies: &'w mut RigidBodySet,
    forced: &'w mut Vec<u32>,
    events: &'w mut Vec<ContactEvent>,
    time: f64,
    patch: &'w mut PatchScratch,
    /// The last object's view under its stability limit, before any
    /// contact's share: applying forces changes none of what it holds.
    view: Option<ObjectView<'w>>,
    /// The forces of the last object's run of contacts, not yet written.
    run: Option<RunForces>,
}

impl InteractionWorld {
    /// One full step: hand forces, then the physics engine.
    pub fn step(&mut self) {
        // The hand poses were set before this call (`set_hand_pose`,
        // `clear_hand_pose`); from them come this step's contacts and forces.
        self.apply_hand_forces();
        // ── Hand forces are set; rapier has not moved anything yet. ──
        // As between MuJoCo's mj_step1 and mj_step2, a program may call the
        // two halves itself and add forces of its own here.
        self.step_physics();
    }

    /// Finds, keeps, updates, begins and ends contacts, and sets this
    /// step's hand forces on the objects: the first half of [`Self::step`].
    pub fn apply_hand_forces(&mut self) {
        let mut step = std::mem::take(&mut self.scratch);
        if self.external || !self.unindexed.is_empty() {
            // Objects added, put down or moved by a program since the
            // last step: the kept broad-phase answers bound none of that.
            step.near.forget();
        }
        self.events.clear();
        self.follow_hands();
        self.clear_forces();
        contact_stages(self, &mut step);
        self.implicit_springs(&step);
        self.scratch = step;
        self.grab_objects();
    }

    /// Advances rapier by `dt` with the forces set by
    /// [`Self::apply_hand_forces`]: gravity and object–object contacts are
    /// the engine's. The poses of this step become the previous poses, for
    /// bone velocities.
    pub fn step_physics(&mut self) {
        self.record(|| Call::Step);
        self.unhost();
        self.set_substeps();
        self.physics.step();
        // rapier's broad phase has now seen every object where it was.
        self.unindexed.clear();
        self.end_step();
    }

    /// What ends a step whoever integrates it (rapier here, a host in
    /// [`Self::host_step`]): the clock, and this step's poses become the
    /// previous ones, for bone velocities.
    pub(in crate::pipeline) fn end_step(&mut self) {
        self.time += self.config.dt as f64;
        self.host_moved = 0.0;
        for hand in self.hands.iter_mut() {
            hand.prev = hand.pose.clone();
            hand.prev_mark = hand.pose_mark;
        }
    }

    /// The object as the contact law sees it this step, with its contact
    /// stiffness and damping scaled by the stability limit.
    #[inline(always)]
    fn object_view(&self, index: usize, limit: StabilityScale) -> ObjectView<'_> {
        let physics = &self.physics;
        view_of(
            index,
            &self.objects,
            &physics.bodies,
            &physics.colliders,
            &self.hand_shapes,
            &self.config,
            limit,
        )
    }

    /// A bone's shape now and one step ago, if its hand is tracked.
    #[inline(always)]
    fn motion(&self, hand: HandId, bone: Bone) -> Option<BoneMotion<'_>> {
        motion_of(&self.hands, hand, bone)
    }

    fn push_event(&mut self, kind: ContactEventKind, c: &Contact) {
        push_event(&mut self.events, self.time, kind, c);
    }
}

/// Stages 2 to 7, the contacts' work, in the build the CPU runs best: on
/// x86-64 with AVX2 (checked once, by `std`), the same code compiled for
/// AVX2 (`avx2.rs`), else for the target's baseline. The same IEEE
/// operations in either encoding and no fused multiply-add, so the same
/// bits (`run/scenario/builds.rs`); AVX2's three-operand forms spare the
/// register copies of the patch's lane arithmetic (the saving is in the
/// book's "Benchmarks").
fn contact_stages(world: &mut InteractionWorld, step: &mut StepScratch) {
    #[cfg(target_arch = "x86_64")]
    if avx2::enabled() {
        // SAFETY: this CPU has AVX2, the one feature the build enables.
        return unsafe { avx2::contact_stages(world, step) };
    }
    step.patch.avx2 = false;
    inlined_contact_stages(world, step);
}

/// Stages 2 to 7, inlined into each build of [`contact_stages`]: each
/// stage, and what it calls of the contact law and the patch, is
/// `#[inline(always)]`, since a function left out of line would keep the
/// baseline encoding.
#[inline(always)]
fn inlined_contact_stages(world: &mut InteractionWorld, step: &mut StepScratch) {
    world.keep_contacts(step);
    world.find_new_contacts(step);
    world.press_contacts(step);
    world.stability_limits(step);
    world.update_contacts(step);
}

/// Object `index`'s view ([`InteractionWorld::object_view`]), read from
/// the world's parts: it borrows only the colliders (for its shape), so
/// stages 6 and 7 keep one while they write the bodies' forces.
#[inline(always)]
fn view_of<'c>(
    index: usize,
    objects: &[ObjectSlot],
    bodies: &RigidBodySet,
    colliders: &'c ColliderSet,
    hand_shapes: &'c [Option<SharedShape>],
    config: &InteractionConfig,
    limit: StabilityScale,
) -> ObjectView<'c> {
    let slot = &objects[index];
    let body = &bodies[slot.body];
    let collider = &colliders[slot.collider];
    ObjectView {
        id: ObjectId(index as u32),
        pose: *collider.position(),
        shape: hand_shapes.get(index).and_then(|s| s.as_deref()).unwrap_or(collider.shape()),
        linvel: body.linvel(),
        angvel: body.angvel(),
        center_of_mass: slot.center_of_mass(body),
        inv_inertia: body.mass_properties().local_mprops.inv_principal_inertia.max_element(),
        sharing: limit.contacts.max(1) as f32,
        gamma: slot.gamma * limit.stiffness,
        damping: nominal_damping(config, slot) * limit.damping,
        cap: config.force_cap.then(|| ForceCap::for_diameter(slot.diameter)),
        mu: if config.hand_friction { slot.material.skin } else { NO_FRICTION },
    }
}

/// A bone's shape now and one step ago ([`BoneMotion`]), if its hand is
/// tracked.
#[inline(always)]
fn motion_of(hands: &[HandSlot], hand: HandId, bone: Bone) -> Option<BoneMotion<'_>> {
    let slot = hands.get(hand.0 as usize)?;
    let pose = slot.pose.as_ref()?;
    let (prev_pose, prev_mark) = match &slot.prev {
        Some(prev) => (prev, slot.prev_mark),
        None => (pose, slot.pose_mark),
    };
    let marks = [slot.pose_mark, prev_mark];
    Some(BoneMotion { bone, pose, prev_pose, marks })
}

/// Records a contact's event at `time` (s).
fn push_event(events: &mut Vec<ContactEvent>, time: f64, kind: ContactEventKind, c: &Contact) {
    let (hand, bone, object, point) = (c.hand, c.bone, c.object, c.point);
    events.push(ContactEvent { kind, hand, bone, object, point, time });
}

/// Skin friction of a baseline's hand, which pushes but does not hold.
const NO_FRICTION: FrictionCoefficients = FrictionCoefficients { static_mu: 0.0, dynamic_mu: 0.0 };

/// A contact found this step, on its way to begin.
#[derive(Debug)]
pub(super) struct Candidate {
    pub contact: Contact,
    /// The closest features, if a stage has queried them this step.
    pub proximity: Option<Proximity>,
}

/// A contact `keep_contacts` kept: its closest features, if it queried
/// them. Its hand is tracked; stages 4 and 6 look up its bone's motion
/// ([`motion_of`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct Kept {
    pub proximity: Option<Proximity>,
}

/// The order of [`InteractionWorld::contacts`]: by object, then hand, then
/// bone, so each object's contacts are one run.
fn contact_key(c: &Contact) -> (ObjectId, HandId, usize) {
    (c.object, c.hand, c.bone.index())
}

/// Buffers kept from step to step, so a warm step allocates little.
#[derive(Debug, Default)]
pub(crate) struct StepScratch {
    /// Per kept contact (in [`InteractionWorld::contacts`]' order): what
    /// `keep_contacts` found of it.
    pub(super) kept: Vec<Kept>,
    /// The contacts found this step.
    pub(super) found: Vec<Candidate>,
    pub(super) detector: Detector,
    /// The objects near the hand being searched, and their boxes.
    pub(super) near: near::Nearby,
    /// Per object, its stability limit this step; read only for objects
    /// with contacts, the `touched` ones.
    pub(super) limits: Vec<StabilityScale>,
    pub(super) touched: Vec<usize>,
    pub(super) patch: PatchScratch,
    /// The contact law's settings, from the world's config.
    pub(super) settings: LawSettings,
    /// Per contact (the kept ones in order, then the new ones): how it
    /// presses this step, whose virtual fingers it belongs to, and its
    /// share of their γ.
    pub(super) presses: Vec<Press>,
    pub(super) sides: Vec<share::SideKey>,
    pub(super) shares: Vec<f32>,
    /// The pressing contacts' indices, grouped by side key.
    pub(super) order: Vec<usize>,
    /// The objects stage 8 visits: touched or held, ascending.
    pub(super) grab_visits: Vec<u32>,
}

impl StepScratch {
    pub(super) fn new(config: &InteractionConfig) -> StepScratch {
        let detector = Detector::new(config.contact_offset, config.release_offset);
        let settings = LawSettings {
            dt: config.dt,
            kinetic: config.kinetic,
            max_penetration_speed: config.max_penetration_speed,
            probe_offset: config.probe_offset,
            patch: config.patch,
            damping_ratio: config.damping_ratio.unwrap_or(0.0),
            deviation_springs: config.deviation_springs,
            recentre: config.slip_recentre,
            line_band: config.line_contacts.then_some(config.contact_offset),
            rolling: config.rolling,
            stribeck_speed: config.stribeck_speed,
        };
        StepScratch { detector, settings, ..StepScratch::default() }
    }
}
