//! Host mode through C: the host gives its bodies' states, steps the
//! hands, and gets back each object's hand wrench to apply before it
//! integrates (the core's `pipeline/host.rs` states the contract).

use crate::args::{finite, out, out_slice, slice};
use crate::handles::{ChWorld, with_world};
use crate::status::{ChStatus, Failure, call};
use crate::world::refused;
use coulomb_hands::pipeline::frame::HostFrame;
use coulomb_hands::{HandWrench, HostBody, ObjectId};
use glam::{Quat, Vec3};

/// An object's state as the host has it at the start of a step, in the
/// world's frame and units (`ch_world_set_frame`; by default the library's:
/// right-handed, y up, m, s, kg).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChHostBody {
    /// The body's origin (m).
    pub position: [f32; 3],
    /// Its orientation, x, y, z, w (a unit quaternion).
    pub rotation: [f32; 4],
    /// Its centre of mass's velocity (m/s).
    pub linvel: [f32; 3],
    /// Its angular velocity (rad/s).
    pub angvel: [f32; 3],
    /// Its mass (kg), above 0.
    pub mass: f32,
    /// Its centre of mass in its own frame (m).
    pub center_of_mass: [f32; 3],
    /// Its principal moments of inertia (kg·m²), each above 0.
    pub principal_inertia: [f32; 3],
    /// The rotation from the principal axes to the body's frame, x, y, z, w.
    pub inertia_rotation: [f32; 4],
}

/// What the hands did to one object in a host step, in the world's frame
/// and units: apply `force` at its centre of mass and `torque` about it
/// (AddForce and AddTorque) for the step, then integrate.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChWrench {
    /// The object's id.
    pub object: u32,
    /// The force (N).
    pub force: [f32; 3],
    /// The torque about the centre of mass (N·m).
    pub torque: [f32; 3],
    /// 1 when a hand touched it this step (pressing, or hovering within the
    /// release offset): a host with substeps may give it more.
    pub touched: u8,
    /// 1 when a hand pushed it: apply the wrench and wake the body (it may
    /// sum to zero though it was pushed).
    pub pushed: u8,
}

impl ChHostBody {
    /// The core's state, every number checked finite (the core checks the
    /// rest: unit rotations, positive mass and inertia, range). `index` is
    /// its place in the batch: a message names `bodies[index].field[k]`,
    /// built only when there is one to give.
    fn host_body(&self, index: usize, f: &HostFrame) -> Result<HostBody, Failure> {
        let fields: [(&str, &[f32]); 8] = [
            ("position", &self.position),
            ("rotation", &self.rotation),
            ("linvel", &self.linvel),
            ("angvel", &self.angvel),
            ("mass", std::slice::from_ref(&self.mass)),
            ("center_of_mass", &self.center_of_mass),
            ("principal_inertia", &self.principal_inertia),
            ("inertia_rotation", &self.inertia_rotation),
        ];
        for (field, values) in fields {
            if values.iter().any(|v| !v.is_finite()) {
                finite(values, &format!("bodies[{index}].{field}"))?;
            }
        }
        Ok(HostBody {
            position: f.point_in(Vec3::from_array(self.position)),
            rotation: f.rotation_in(Quat::from_array(self.rotation)),
            linvel: f.point_in(Vec3::from_array(self.linvel)),
            angvel: f.angular_in(Vec3::from_array(self.angvel)),
            mass: self.mass,
            center_of_mass: f.point_in(Vec3::from_array(self.center_of_mass)),
            principal_inertia: f.inertia_in(Vec3::from_array(self.principal_inertia)),
            inertia_rotation: f.rotation_in(Quat::from_array(self.inertia_rotation)),
        })
    }
}

impl ChWrench {
    /// A wrench in the host's frame and units.
    fn of(w: &HandWrench, f: &HostFrame) -> ChWrench {
        ChWrench {
            object: w.object.0,
            force: f.force_out(w.force).to_array(),
            torque: f.torque_out(w.torque).to_array(),
            touched: u8::from(w.touched),
            pushed: u8::from(w.pushed),
        }
    }
}

/// Host mode: `count` objects' states as the host has them now, object
/// `ids[i]` in `bodies[i]`. All are checked before any is written: one bad
/// state or id leaves the world as it was, and the message names it.
///
/// # Safety
/// `ids` and `bodies` each point to `count` readable values (or are null
/// with `count` 0).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ch_world_set_host_bodies(
    world: ChWorld,
    ids: *const u32,
    bodies: *const ChHostBody,
    count: usize,
) -> ChStatus {
    call("ch_world_set_host_bodies", || {
        // SAFETY: the caller's contract, for both arrays.
        let (ids, bodies) = unsafe { (slice(ids, count, "ids")?, slice(bodies, count, "bodies")?) };
        with_world(world, |e| {
            let state = |(i, (&id, body)): (usize, (&u32, &ChHostBody))| {
                Ok((ObjectId(id), body.host_body(i, &e.frame)?))
            };
            let states =
                ids.iter().zip(bodies).enumerate().map(state).collect::<Result<Vec<_>, _>>()?;
            e.world.set_host_bodies(&states).map_err(refused)
        })
    })
}

/// Host mode: one step of the hands (no integration): each object's wrench
/// into `wrenches`, in id order, removed objects left out; `*written` is
/// set to how many. `len` must hold every object in the world
/// (`ch_world_object_count` bounds it), or nothing runs. The contacts'
/// own forces are in `ch_world_contacts` after it.
///
/// # Safety
/// `wrenches` points to `len` writable wrenches; `written` to a writable
/// `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ch_world_host_step(
    world: ChWorld,
    wrenches: *mut ChWrench,
    len: usize,
    written: *mut usize,
) -> ChStatus {
    call("ch_world_host_step", || {
        // SAFETY: the caller's contract.
        let written = unsafe { out(written, "written") }?;
        with_world(world, |e| {
            let count = e.world.object_ids().count();
            // SAFETY: the caller's contract; checked before the step runs.
            let dest = match unsafe { out_slice(wrenches, len, count, "wrenches") }? {
                Some(dest) => dest,
                None if count == 0 => &mut [],
                None => return Err(Failure::null("wrenches")),
            };
            // The hands posed for this step, once it is known to run.
            e.world.check_host_mode().map_err(refused)?;
            e.hands.begin(&e.world, 1);
            e.hands.pose(&mut e.world).map_err(refused)?;
            let computed = e.world.host_step().map_err(refused)?;
            for (slot, wrench) in dest.iter_mut().zip(&computed) {
                *slot = ChWrench::of(wrench, &e.frame);
            }
            *written = computed.len();
            Ok(())
        })
    })
}
