//! The built-in world through C: made from the CLI's config JSON, filled
//! with scenes, objects and hands, stepped, and read back.

use crate::args::{self, floats, number, optional_text, out, output, text};
use crate::handles::{self, ChWorld, with_world};
use crate::status::{ChStatus, Failure, call};
use coulomb_hands::hand::HandSample;
use coulomb_hands::input::layouts::{self, Layout};
use coulomb_hands::pipeline::frame::HostFrame;
use coulomb_hands::scene::Scene;
use coulomb_hands::{
    HandId, InteractionConfig, InteractionWorld, Material, Method, ObjectDesc, ObjectState, Side,
    StaticDesc,
};
use glam::{Quat, Vec3};
use std::ffi::c_char;
use std::path::Path;

/// An object's state after a step, in the world's frame and units
/// (`ch_world_set_frame`; by default right-handed, y up, m, s, N).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChObjectState {
    /// Its origin (m).
    pub position: [f32; 3],
    /// Its orientation, x, y, z, w.
    pub rotation: [f32; 4],
    /// Its centre of mass's velocity (m/s).
    pub linvel: [f32; 3],
    /// Its angular velocity (rad/s).
    pub angvel: [f32; 3],
    /// The hands' force on it in the last step (N; thesis Eq. 3.10).
    pub hand_force: [f32; 3],
    /// 1 while the object is in the world, 0 once removed (its numbers are
    /// then NaN).
    pub present: u8,
    /// 1 while rapier has it asleep.
    pub sleeping: u8,
}

/// One contact of a hand on an object after the last step.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChContact {
    /// The object's id.
    pub object: u32,
    /// The hand's id.
    pub hand: u32,
    /// The bone: 0 the palm, then 1 + 3 × finger + phalanx (thumb first;
    /// proximal, middle, distal).
    pub bone: u32,
    /// Its friction state: 0 static, 1 dynamic (sliding), 2 separated (hovering
    /// within the release offset; the library's `FrictionState::code`).
    pub state: u32,
    /// C, the contact's anchor on the object's surface (m).
    pub point: [f32; 3],
    /// The surface's outward normal there.
    pub normal: [f32; 3],
    /// p, the bone's point the spring pulls towards C (m).
    pub bone_point: [f32; 3],
    /// The force on the object (N), applied over the contact's skin patch
    /// around `point`: what to draw, or to apply at `point` for
    /// AddForceAtPosition.
    pub force: [f32; 3],
    /// How far p is pressed in below C along the normal (m).
    pub depth: f32,
    /// The normal part of the force (N).
    pub normal_force: f32,
    /// The spring's stiffness γ (N/m).
    pub stiffness: f32,
}

/// Three numbers by value: a position (m), a size (m).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChVec3 {
    pub x: f32,
    pub y: f32,
    pub z: f32,
}

/// A rotation by value, x, y, z, w: `{0, 0, 0, 1}` turns nothing.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChQuat {
    pub x: f32,
    pub y: f32,
    pub z: f32,
    pub w: f32,
}

impl ChVec3 {
    /// Its numbers, each finite, or an error naming `arg`.
    fn checked(self, arg: &str) -> Result<Vec3, Failure> {
        let v = [self.x, self.y, self.z];
        args::finite(&v, arg)?;
        Ok(Vec3::from_array(v))
    }
}

impl ChQuat {
    /// A unit rotation, or an error naming `arg`.
    fn checked(self, arg: &str) -> Result<Quat, Failure> {
        let q = [self.x, self.y, self.z, self.w];
        args::finite(&q, arg)?;
        layouts::rotation(q).ok_or_else(|| Failure::invalid(arg, "zero-length rotation"))
    }
}

/// The world's refusal as a status.
pub(crate) fn refused(e: coulomb_hands::WorldError) -> Failure {
    Failure::refused(e)
}

/// A new, empty world for `method` (`coulomb`, `thesis`, `kinematic` or
/// `heuristic`; null for `coulomb`) with the config `config_json` (an
/// `InteractionConfig` as JSON, as a session file holds it: a missing field
/// takes its default; null for all defaults), into `*world`.
///
/// # Safety
/// `method` and `config_json` are null or NUL-terminated; `world` points to
/// a writable `ChWorld`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ch_world_new(
    method: *const c_char,
    config_json: *const c_char,
    world: *mut ChWorld,
) -> ChStatus {
    call("ch_world_new", || {
        // SAFETY: the caller's contract, for each pointer.
        let (method, json, world) = unsafe {
            (
                optional_text(method, "method")?,
                optional_text(config_json, "config_json")?,
                out(world, "world")?,
            )
        };
        let method: Method = match method {
            Some(name) => name.parse().map_err(|e| Failure::invalid("method", e))?,
            None => Method::default(),
        };
        let config = match json {
            Some(json) => serde_json::from_str::<InteractionConfig>(json)
                .map_err(|e| Failure::input(format!("config_json: {e}")))?,
            None => InteractionConfig::default(),
        };
        config.validate().map_err(|e| Failure::input(format!("config_json: {e}")))?;
        let made = InteractionWorld::new(method.config(config))
            .map_err(|e| Failure::input(format!("config_json: {e}")))?;
        *world = handles::insert(made)?;
        Ok(())
    })
}

/// Frees a world; its handle is stale from now on.
#[unsafe(no_mangle)]
pub extern "C" fn ch_world_free(world: ChWorld) -> ChStatus {
    call("ch_world_free", || handles::remove(world))
}

/// The frame and units every later call on this world speaks in:
/// `"library"` (right-handed, y up, metres; the default, and Godot's),
/// `"unity"` (left-handed, y up, z forward, metres) or `"unreal"`
/// (left-handed, z up, centimetres, forces in kg·cm/s²). Positions,
/// sizes, rotations, velocities, forces and torques in and out are then the
/// host's; configs, scenes and recordings stay the library's. Set it before
/// anything is added.
///
/// # Safety
/// `frame` is null or NUL-terminated.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ch_world_set_frame(world: ChWorld, frame: *const c_char) -> ChStatus {
    call("ch_world_set_frame", || {
        // SAFETY: the caller's contract.
        let name = unsafe { text(frame, "frame") }?;
        let frame = HostFrame::by_name(name).map_err(|e| Failure::invalid("frame", e))?;
        with_world(world, |e| {
            e.frame = frame;
            Ok(())
        })
    })
}

/// A static ground slab whose top face is at `height` (m), with the
/// friction coefficient `friction` against objects.
#[unsafe(no_mangle)]
pub extern "C" fn ch_world_add_ground(world: ChWorld, height: f32, friction: f32) -> ChStatus {
    call("ch_world_add_ground", || {
        let (height, friction) = (number(height, "height")?, number(friction, "friction")?);
        with_world(world, |e| {
            let desc = StaticDesc::ground(e.frame.length_in(height), friction);
            e.world.add_static(&desc).map(drop).map_err(refused)
        })
    })
}

/// A box of full `size` (m) and `mass` (kg) at `position` (m), turned by
/// `rotation`, of the named skin–object `material` (null for `wood`), into
/// `*id`. With [`ch_world_add_sphere`], what a host's box and sphere
/// colliders become; other shapes come in a scene.
///
/// # Safety
/// The texts are null or NUL-terminated; `id` points to a writable
/// `uint32_t`.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ch_world_add_box(
    world: ChWorld,
    name: *const c_char,
    size: ChVec3,
    mass: f32,
    position: ChVec3,
    rotation: ChQuat,
    material: *const c_char,
    id: *mut u32,
) -> ChStatus {
    call("ch_world_add_box", || {
        let (size, at, turn) =
            (size.checked("size")?, position.checked("position")?, rotation.checked("rotation")?);
        // SAFETY: the caller's contract, for each pointer.
        let (name, material, id) =
            unsafe { (text(name, "name")?, material_of(material)?, out(id, "id")?) };
        let mass = number(mass, "mass")?;
        *id = with_world(world, |e| {
            let f = e.frame;
            let desc = ObjectDesc {
                rotation: f.rotation_in(turn),
                ..ObjectDesc::cuboid(name, f.size_in(size), mass, f.point_in(at))
            };
            e.world.add_object(&desc.with_material(material)).map_err(refused)
        })?
        .0;
        Ok(())
    })
}

/// A ball of `radius` (m) and `mass` (kg) centred at `position` (m), of the
/// named `material` (null for `wood`), into `*id`.
///
/// # Safety
/// `name` and `material` are null or NUL-terminated; `id` points to a
/// writable `uint32_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ch_world_add_sphere(
    world: ChWorld,
    name: *const c_char,
    radius: f32,
    mass: f32,
    position: ChVec3,
    material: *const c_char,
    id: *mut u32,
) -> ChStatus {
    call("ch_world_add_sphere", || {
        let at = position.checked("position")?;
        let (radius, mass) = (number(radius, "radius")?, number(mass, "mass")?);
        // SAFETY: the caller's contract, for each pointer.
        let (name, material, id) =
            unsafe { (text(name, "name")?, material_of(material)?, out(id, "id")?) };
        *id = with_world(world, |e| {
            let f = e.frame;
            let desc = ObjectDesc::sphere(name, f.length_in(radius), mass, f.point_in(at));
            e.world.add_object(&desc.with_material(material)).map_err(refused)
        })?
        .0;
        Ok(())
    })
}

/// A material of the library's table by name (null for `wood`).
///
/// # Safety
/// `name` is null or NUL-terminated.
unsafe fn material_of(name: *const c_char) -> Result<Material, Failure> {
    // SAFETY: the caller's.
    let name = unsafe { optional_text(name, "material") }?.unwrap_or("wood");
    Material::by_name(name).map_err(|e| Failure::invalid("material", e))
}

/// A scene, as the CLI's `--scene` file holds it (JSON: ground, statics,
/// objects, towers), added to the world; mesh files are looked up from
/// `dir` (null for the working directory). `*first` is the first object's
/// id and `*count` how many it added (ids `first..first + count`).
///
/// # Safety
/// The texts are null or NUL-terminated; `first` and `count` point to
/// writable `uint32_t`s.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ch_world_add_scene(
    world: ChWorld,
    scene_json: *const c_char,
    dir: *const c_char,
    first: *mut u32,
    count: *mut u32,
) -> ChStatus {
    call("ch_world_add_scene", || {
        // SAFETY: the caller's contract, for each pointer.
        let (json, dir, first, count) = unsafe {
            (
                text(scene_json, "scene_json")?,
                optional_text(dir, "dir")?.unwrap_or("."),
                out(first, "first")?,
                out(count, "count")?,
            )
        };
        let scene = Scene::parse_in("scene_json", json, Path::new(dir)).map_err(Failure::input)?;
        let (from, to) = with_world(world, |e| {
            let from = e.world.object_count() as u32;
            e.world.add_scene(&scene).map_err(refused)?;
            Ok((from, e.world.object_count() as u32))
        })?;
        (*first, *count) = (from, to - from);
        Ok(())
    })
}

/// A hand, `"left"` or `"right"`, untracked until posed, into `*hand`.
///
/// # Safety
/// `side` is null or NUL-terminated; `hand` points to a writable
/// `uint32_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ch_world_add_hand(
    world: ChWorld,
    side: *const c_char,
    hand: *mut u32,
) -> ChStatus {
    call("ch_world_add_hand", || {
        // SAFETY: the caller's contract, for each pointer.
        let (side, hand) = unsafe { (text(side, "side")?, out(hand, "hand")?) };
        let side: Side = side.parse().map_err(|e| Failure::invalid("side", e))?;
        *hand = with_world(world, |e| Ok(e.world.add_hand(side).0))?;
        Ok(())
    })
}

/// Poses a hand from a tracker's joints in `layout`'s order (`"openxr"`,
/// 26 joints; `"webxr"`, 25; `"mediapipe"`, 21): `positions` (3 floats a
/// joint), `radii` (1 a joint; null for an average hand's) and
/// `orientations` (4 a joint, x, y, z, w, the layout's joint frames; null
/// when the tracker gives none), in the world's frame and units
/// (`ch_world_set_frame`). The lengths count floats.
///
/// # Safety
/// Each array is null or holds its length's floats; `layout` is null or
/// NUL-terminated.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ch_world_set_hand_joints(
    world: ChWorld,
    hand: u32,
    layout: *const c_char,
    positions: *const f32,
    positions_len: usize,
    radii: *const f32,
    radii_len: usize,
    orientations: *const f32,
    orientations_len: usize,
) -> ChStatus {
    call("ch_world_set_hand_joints", || {
        // SAFETY: the caller's contract, for `layout`.
        let layout: Layout = unsafe { text(layout, "layout") }?
            .parse()
            .map_err(|e| Failure::invalid("layout", e))?;
        let n = layout.count();
        // SAFETY: the caller's contract, for each array.
        let (positions, radii, orientations) = unsafe {
            let optional = |ptr: *const f32, len, per, arg| {
                (!ptr.is_null()).then(|| floats(ptr, len, per * n, arg)).transpose()
            };
            (
                floats(positions, positions_len, 3 * n, "positions")?,
                optional(radii, radii_len, 1, "radii")?,
                optional(orientations, orientations_len, 4, "orientations")?,
            )
        };
        let orientations = orientations
            .map(|q| {
                let xyzw: Vec<[f32; 4]> =
                    q.chunks_exact(4).map(|c| [c[0], c[1], c[2], c[3]]).collect();
                layouts::orientations(layout, &xyzw)
                    .map_err(|e| Failure::invalid("orientations", e))
            })
            .transpose()?;
        with_world(world, |e| {
            let f = e.frame;
            let positions: Vec<Vec3> =
                positions.chunks_exact(3).map(|p| f.point_in(Vec3::from_slice(p))).collect();
            let radii: Option<Vec<f32>> =
                radii.map(|r| r.iter().map(|&r| f.length_in(r)).collect());
            let orientations: Option<Vec<_>> =
                orientations.map(|qs| qs.into_iter().map(|q| f.rotation_in(q)).collect());
            let side = e
                .world
                .hand_side(HandId(hand))
                .ok_or_else(|| refused(coulomb_hands::WorldError::NoSuchHand(HandId(hand))))?;
            let pose = layouts::hand_pose_from_joints(
                layout,
                hand,
                side,
                &positions,
                radii.as_deref(),
                orientations.as_deref(),
            )
            .map_err(|e| Failure::invalid("positions", e))?;
            let sample = Some(HandSample::from_pose(pose));
            e.hands.set(&mut e.world, HandId(hand), sample).map_err(refused)
        })
    })
}

/// The hand is no longer tracked: its contacts end at the next step.
#[unsafe(no_mangle)]
pub extern "C" fn ch_world_clear_hand(world: ChWorld, hand: u32) -> ChStatus {
    call("ch_world_clear_hand", || {
        with_world(world, |e| e.hands.set(&mut e.world, HandId(hand), None).map_err(refused))
    })
}

/// `steps` steps of the built-in world (each the config's `dt`): the
/// hands' contact forces, then rapier. A hand posed since the last steps
/// goes there in a straight line over these, from where it was, and is
/// there at the last of them (posed before each single step, it is there
/// at once); a hand first seen is there at once.
#[unsafe(no_mangle)]
pub extern "C" fn ch_world_step(world: ChWorld, steps: u32) -> ChStatus {
    call("ch_world_step", || {
        with_world(world, |e| e.hands.step(&mut e.world, steps as usize).map_err(refused))
    })
}

/// The world's simulated time (s), into `*time`.
///
/// # Safety
/// `time` points to a writable `double`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ch_world_time(world: ChWorld, time: *mut f64) -> ChStatus {
    call("ch_world_time", || {
        // SAFETY: the caller's contract.
        let time = unsafe { out(time, "time") }?;
        *time = with_world(world, |e| Ok(e.world.time()))?;
        Ok(())
    })
}

/// How many objects were ever added, removed ones included: the ids are
/// `0..count`, and `ch_world_object_states` gives one state each.
///
/// # Safety
/// `count` points to a writable `uint32_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ch_world_object_count(world: ChWorld, count: *mut u32) -> ChStatus {
    call("ch_world_object_count", || {
        // SAFETY: the caller's contract.
        let count = unsafe { out(count, "count") }?;
        *count = with_world(world, |e| Ok(e.world.object_count() as u32))?;
        Ok(())
    })
}

/// Every object's state, by id, into `states` (room for `len`); `*needed`
/// is set to how many there are, even when `len` is too few. With `states`
/// null, that is all it does.
///
/// # Safety
/// `states` is null or points to `len` writable states; `needed` points to
/// a writable `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ch_world_object_states(
    world: ChWorld,
    states: *mut ChObjectState,
    len: usize,
    needed: *mut usize,
) -> ChStatus {
    call("ch_world_object_states", || {
        // SAFETY: the caller's contract.
        let needed = unsafe { out(needed, "needed") }?;
        with_world(world, |e| {
            let count = e.world.object_count();
            // SAFETY: the caller's contract.
            if let Some(dest) = unsafe { output(states, len, count, needed, "states") }? {
                for (slot, (_, state)) in dest.iter_mut().zip(e.world.object_slots()) {
                    *slot = object_state(state, &e.frame);
                }
            }
            Ok(())
        })
    })
}

fn object_state(state: Option<ObjectState>, f: &HostFrame) -> ChObjectState {
    let s = state.unwrap_or(ObjectState::REMOVED);
    ChObjectState {
        position: f.point_out(s.position).to_array(),
        rotation: f.rotation_out(s.rotation).to_array(),
        linvel: f.point_out(s.linvel).to_array(),
        angvel: f.angular_out(s.angvel).to_array(),
        hand_force: f.force_out(s.hand_force).to_array(),
        present: u8::from(state.is_some()),
        sleeping: u8::from(s.sleeping),
    }
}

/// The contacts after the last step, ordered by object, hand and bone, into
/// `contacts` (room for `len`); `*needed` is set to how many there are,
/// even when `len` is too few. With `contacts` null, that is all it does.
///
/// # Safety
/// `contacts` is null or points to `len` writable contacts; `needed` points
/// to a writable `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ch_world_contacts(
    world: ChWorld,
    contacts: *mut ChContact,
    len: usize,
    needed: *mut usize,
) -> ChStatus {
    call("ch_world_contacts", || {
        // SAFETY: the caller's contract.
        let needed = unsafe { out(needed, "needed") }?;
        with_world(world, |e| {
            let (all, f) = (e.world.contacts(), e.frame);
            // SAFETY: the caller's contract.
            if let Some(dest) = unsafe { output(contacts, len, all.len(), needed, "contacts") }? {
                for (slot, c) in dest.iter_mut().zip(all) {
                    *slot = ChContact {
                        object: c.object.0,
                        hand: c.hand.0,
                        bone: c.bone.index() as u32,
                        state: u32::from(c.state.code()),
                        point: f.point_out(c.point).to_array(),
                        normal: f.direction_out(c.normal).to_array(),
                        bone_point: f.point_out(c.bone_point).to_array(),
                        force: f.force_out(c.force).to_array(),
                        depth: f.length_out(c.depth),
                        normal_force: f.force_magnitude_out(c.normal_force),
                        stiffness: c.stiffness,
                    };
                }
            }
            Ok(())
        })
    })
}
