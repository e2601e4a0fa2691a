//! Host-engine mode: a host engine (Unity's PhysX, Unreal's Chaos, Godot's
//! Jolt, or rapier run by a program) owns the rigid bodies and integrates
//! them; the library gives back what the hand does to each.
//!
//! Each step the host gives every object's state ([`HostBody`], through
//! [`InteractionWorld::set_host_body`]) and the hands' poses, then calls
//! [`InteractionWorld::host_step`]: stages 0 to 7 of the built-in step run
//! as they always do, and the step's forces come back as one
//! [`HandWrench`] per object (force and torque about its centre of mass,
//! for `AddForce`/`AddTorque`), with every contact's own force at its point
//! in [`InteractionWorld::contacts`] (for `AddForceAtPosition`, or to draw
//! them). The host applies them and integrates: gravity and object–object
//! contacts are its own.
//!
//! The library keeps of each object what its contacts need: its shape (for
//! the contact queries) and material, and the state the host last gave:
//! its pose and centre of mass in the object's slot, its velocities and
//! mass properties on the body it keeps for it, which rapier never steps
//! in this mode, and its collider where the pose puts it. The body's own
//! pose is left as it was (rapier's `set_position` recomputes the world
//! inertia, which no stage reads) until rapier steps the world again
//! ([`InteractionWorld::step_physics`] first writes it), or a program
//! takes it ([`InteractionWorld::physics_mut`]).
//!
//! [`InteractionWorld::step`] is the same stages followed by the
//! built-in host, rapier: stage 7 writes the wrenches straight into its
//! bodies, and [`InteractionWorld::step_physics`] integrates them.
//! [`InteractionWorld::integrate_wrenches`] is that built-in host offered to
//! another world: a program that steps rapier itself (and the test that
//! holds the two modes to the same bits) gives it the wrenches.

use super::InteractionWorld;
use super::error::WorldError;
use crate::scene::ObjectId;
use crate::scene::object::{finite_vec, unit_quat};
use glam::{Quat, Vec3};
use rapier3d::math::Pose;
use rapier3d::prelude::{MassProperties, RigidBody};

/// An object's state as the host has it at the start of a step (world
/// frame, metres, seconds, kilograms).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct HostBody {
    /// The body's origin (m).
    pub position: Vec3,
    /// Its orientation (unit quaternion).
    pub rotation: Quat,
    /// The linear velocity of its centre of mass (m/s).
    pub linvel: Vec3,
    /// Its angular velocity (rad/s).
    pub angvel: Vec3,
    /// Its mass (kg), above 0.
    pub mass: f32,
    /// Its centre of mass in its own frame (m).
    pub center_of_mass: Vec3,
    /// Its principal moments of inertia (kg·m²), each above 0.
    pub principal_inertia: Vec3,
    /// The rotation from the principal axes to the body's frame.
    pub inertia_rotation: Quat,
}

/// What the hands did to one object in a step: the sum of their contacts'
/// forces, as a force through its centre of mass and a torque about it.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct HandWrench {
    /// The object.
    pub object: ObjectId,
    /// The force (N).
    pub force: Vec3,
    /// The torque about the centre of mass (N·m).
    pub torque: Vec3,
    /// Whether a hand touched it this step (some contact, pressing or
    /// hovering within the offset): the built-in host gives such a body
    /// more substeps ([`crate::InteractionConfig::engine_substeps`]).
    pub touched: bool,
    /// Whether a hand pushed it: a force to apply, and a body to wake (the
    /// force and torque may sum to zero though it was pushed).
    pub pushed: bool,
}

impl HostBody {
    /// A rapier body's state, as a program that steps rapier itself gives
    /// it ([`InteractionWorld::set_host_body`]).
    pub fn of_rapier(body: &RigidBody) -> HostBody {
        let props = &body.mass_properties().local_mprops;
        HostBody {
            position: body.translation(),
            rotation: *body.rotation(),
            linvel: body.linvel(),
            angvel: body.angvel(),
            mass: props.mass(),
            center_of_mass: props.local_com,
            principal_inertia: props.principal_inertia(),
            inertia_rotation: props.principal_inertia_local_frame,
        }
    }
}

impl InteractionWorld {
    /// Host mode: object `id` as the host has it now. The state is checked
    /// (finite, within range, a unit rotation, a positive mass and
    /// inertia) before anything is written; a rejected state leaves the
    /// world as it was.
    pub fn set_host_body(&mut self, id: ObjectId, state: &HostBody) -> Result<(), WorldError> {
        let new_mass = self.check_host_body(id, state)?;
        self.write_host_body(id, state, new_mass);
        Ok(())
    }

    /// Writes a state [`Self::check_host_body`] passed; `new_mass` is
    /// what it said of the mass properties.
    fn write_host_body(&mut self, id: ObjectId, state: &HostBody, new_mass: bool) {
        let slot = &mut self.objects[id.0 as usize];
        let (body, collider, reach) = (slot.body, slot.collider, slot.reach);
        if new_mass {
            let mass = MassState::of(state);
            (slot.mass, slot.host_mass) = (state.mass, Some(mass));
            let physics = &mut self.physics;
            // Compared as `HostBody::of_rapier` reads them, so mass
            // properties the host read from rapier and gives back are left
            // to the bit.
            if MassState::of(&HostBody::of_rapier(&physics.bodies[body])) != mass {
                let props = MassProperties::with_principal_inertia_frame(
                    state.center_of_mass,
                    state.mass,
                    state.principal_inertia,
                    unit(state.inertia_rotation),
                );
                physics.colliders[collider].set_mass_properties(props);
                physics.bodies[body].recompute_mass_properties_from_colliders(&physics.colliders);
            }
        }
        let physics = &mut self.physics;
        let slot = &self.objects[id.0 as usize];
        let (from, to) =
            (slot.pose(&physics.bodies), Pose::from_parts(state.position, unit(state.rotation)));
        // Turned about its origin by at most π·|Δq| (rad), either sign of
        // q (no trigonometry), so no point moved farther than this.
        let (a, b) = (from.rotation, to.rotation);
        let chord = (a - b).length().min((a + b).length());
        let turned = std::f32::consts::PI * chord;
        let moved = from.translation.distance(to.translation) + turned * reach;
        self.host_moved = self.host_moved.max(moved);
        let rigid = &mut physics.bodies[body];
        rigid.set_linvel(state.linvel, false);
        rigid.set_angvel(state.angvel, false);
        let com = to.transform_point(rigid.mass_properties().local_mprops.local_com);
        // Its collider where rapier's step would put it (rapier's own
        // propagation visits every body changed since its last step, which
        // in this mode is every body, every call).
        let c = &mut physics.colliders[collider];
        let local = c.position_wrt_parent().copied().unwrap_or_default();
        c.set_position(to * local);
        // rapier's broad phase never sees it move in this mode: the contact
        // search takes its exact box (`step/near.rs`), and asks afresh the
        // step it is first hosted.
        let slot = &mut self.objects[id.0 as usize];
        (slot.host_pose, slot.host_com) = (to, com);
        if !slot.hosted {
            slot.hosted = true;
            self.hosted.push(id.0);
            self.unindexed.push(id.0);
        }
        self.record(|| super::Call::SetHostBody(id.0, *state));
    }

    /// Host mode: many objects' states at once, as [`Self::set_host_body`]
    /// sets one, all checked before any is written: a rejected state (or
    /// id) leaves the world as it was. An id given twice takes its last
    /// state. What a binding's batched call does.
    pub fn set_host_bodies(&mut self, bodies: &[(ObjectId, HostBody)]) -> Result<(), WorldError> {
        for (id, state) in bodies {
            self.check_host_body(*id, state)?;
        }
        for (id, state) in bodies {
            // Asked again: an id given twice has its mass properties new
            // only the first time.
            let new_mass = self.objects[id.0 as usize].host_mass != Some(MassState::of(state));
            self.write_host_body(*id, state, new_mass);
        }
        Ok(())
    }

    /// Whether `state` may be set on object `id` (mass properties a host
    /// gave last are checked already), and whether its mass properties
    /// are new.
    fn check_host_body(&self, id: ObjectId, state: &HostBody) -> Result<bool, WorldError> {
        let slot = self.slot(id)?;
        if !usual_motion(state) {
            check_motion(&slot.name, state)?;
        }
        let new_mass = slot.host_mass != Some(MassState::of(state));
        if new_mass {
            check_mass(&slot.name, state)?;
        }
        Ok(new_mass)
    }

    /// Host mode: one step without the engine. Stages 0 to 7 run as in
    /// [`Self::step`], then the step ends as rapier's would (the time, the
    /// poses of this step become the previous ones) with nothing
    /// integrated. Returns each object's wrench, in id order (a removed
    /// object's is left out). The grab baselines move objects themselves,
    /// which a host's bodies cannot be made to do from here: they are an
    /// error, before anything runs.
    pub fn host_step(&mut self) -> Result<Vec<HandWrench>, WorldError> {
        self.check_host_mode()?;
        self.apply_hand_forces();
        self.host_forces()
    }

    /// Host mode's second half, after [`Self::apply_hand_forces`], as
    /// [`Self::step_physics`] is the built-in step's: the wrenches, then the
    /// step ends with nothing integrated.
    pub fn host_forces(&mut self) -> Result<Vec<HandWrench>, WorldError> {
        self.check_host_mode()?;
        let wrenches = self.wrenches();
        self.record(|| super::Call::HostStep);
        // The hosted objects' first step is done: from now on their exact
        // boxes and `host_moved` bound the search.
        let objects = &self.objects;
        self.unindexed.retain(|&o| !objects[o as usize].hosted);
        self.end_step();
        Ok(wrenches)
    }

    /// Before rapier steps the world itself: each object a host set since
    /// rapier's last step gets the host's pose on its body, and is rapier's
    /// again until a host sets it.
    pub(in crate::pipeline) fn unhost(&mut self) {
        for o in self.hosted.drain(..) {
            let slot = &mut self.objects[o as usize];
            slot.hosted = false;
            if let Some(body) = self.physics.bodies.get_mut(slot.body) {
                body.set_position(slot.host_pose, false);
            }
        }
    }

    /// Whether this world's method can run in host mode (the grab
    /// baselines cannot): what [`Self::host_step`] checks before it runs,
    /// for a binding that prepares the step first.
    pub fn check_host_mode(&self) -> Result<(), WorldError> {
        match self.config.grab {
            Some(grab) => Err(WorldError::HostGrab(grab)),
            None => Ok(()),
        }
    }

    /// The hands' wrench on each object this step, as stage 7 left them on
    /// the bodies.
    fn wrenches(&self) -> Vec<HandWrench> {
        let live = self.objects.iter().enumerate().filter(|(_, o)| !o.removed);
        live.map(|(i, slot)| {
            let (force, torque) = if slot.pushed {
                let body = &self.physics.bodies[slot.body];
                (body.user_force(), body.user_torque())
            } else {
                (Vec3::ZERO, Vec3::ZERO)
            };
            let (touched, pushed) = (slot.forced, slot.pushed);
            HandWrench { object: ObjectId(i as u32), force, torque, touched, pushed }
        })
        .collect()
    }

    /// The built-in host, for a world whose objects a program steps itself
    /// with rapier: each object's hand wrench (from another world's
    /// [`Self::host_step`], object for object) set on its body, then
    /// [`Self::step_physics`], as [`Self::step`] does after stage 7. Its own
    /// hands take no part.
    pub fn integrate_wrenches(&mut self, wrenches: &[HandWrench]) -> Result<(), WorldError> {
        for w in wrenches {
            let slot = self.slot(w.object)?;
            finite(&slot.name, "force", w.force)?;
            finite(&slot.name, "torque", w.torque)?;
        }
        self.clear_forces();
        // As stage 7 leaves them (`step/apply.rs`).
        for w in wrenches.iter().filter(|w| w.touched || w.pushed) {
            let slot = &mut self.objects[w.object.0 as usize];
            (slot.forced, slot.pushed) = (true, w.pushed);
            self.forced.push(w.object.0);
            if w.pushed {
                push(&mut self.physics.bodies[slot.body], w.force, w.torque);
            }
        }
        self.step_physics();
        Ok(())
    }
}

/// `q` as the host gave it where it is a unit quaternion to f32's
/// precision, so that its bits are the host's; else normalised.
fn unit(q: Quat) -> Quat {
    if (q.length_squared() - 1.0).abs() <= 4.0 * f32::EPSILON { q } else { q.normalize() }
}

/// A host body's mass properties, as given: what tells a change.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct MassState(f32, Vec3, Vec3, Quat);

impl MassState {
    fn of(s: &HostBody) -> MassState {
        MassState(s.mass, s.center_of_mass, s.principal_inertia, s.inertia_rotation)
    }
}

/// Whether a host's pose and velocities pass [`check_motion`], told in one
/// test without naming a field: the usual case, on every call.
#[inline(always)]
fn usual_motion(s: &HostBody) -> bool {
    let all_finite = s.linvel.is_finite() & s.angvel.is_finite() & s.position.is_finite();
    // (`max_element` passes NaN over, hence the test above.)
    let placed = s.position.abs().max_element() <= crate::hand::MAX_COORDINATE;
    // |q|² within 1e-3 of 1 is |q| within 5e-4 of it, inside `unit_quat`.
    let turned = (s.rotation.length_squared() - 1.0).abs() <= 1.0e-3;
    all_finite & placed & turned
}

/// A host's pose and velocities of object `name`, before any is written,
/// the field at fault named.
#[cold]
fn check_motion(name: &str, s: &HostBody) -> Result<(), WorldError> {
    finite(name, "linvel", s.linvel)?;
    finite(name, "angvel", s.angvel)?;
    finite_vec(name, "position", s.position)?;
    unit_quat(name, "rotation", s.rotation)?;
    Ok(())
}

/// A velocity, force or torque of object `name`: finite, of any size (a
/// position's bound in metres is no bound on these).
fn finite(name: &str, field: &str, v: Vec3) -> Result<(), WorldError> {
    if v.is_finite() {
        return Ok(());
    }
    let why = format!("must be finite, got {v:?}");
    Err(crate::scene::ObjectError::new(name, field, why).into())
}

/// A host's mass properties of object `name`, before any is written.
fn check_mass(name: &str, s: &HostBody) -> Result<(), WorldError> {
    finite_vec(name, "center_of_mass", s.center_of_mass)?;
    unit_quat(name, "inertia_rotation", s.inertia_rotation)?;
    crate::scene::object::positive(name, "mass", s.mass)?;
    let axes = ["principal_inertia.x", "principal_inertia.y", "principal_inertia.z"];
    for (field, v) in axes.iter().zip(s.principal_inertia.to_array()) {
        crate::scene::object::positive(name, field, v)?;
    }
    Ok(())
}

/// Sets a body's hand force and torque (about its centre of mass) for
/// rapier's step, and wakes it: what a pushed object gets, in stage 7
/// (`step/apply.rs`) and from another world's wrenches
/// (`integrate_wrenches`). It lives here because `record` imports this
/// module, and the step's modules import `record`.
#[inline(always)]
pub(in crate::pipeline) fn push(body: &mut RigidBody, force: Vec3, torque: Vec3) {
    body.reset_forces(false);
    body.reset_torques(false);
    body.add_force(force, false);
    body.add_torque(torque, false);
    body.wake_up(true);
}
