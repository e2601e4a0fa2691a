//! Headless replay of a hand-tracking recording through the interaction
//! world, with a per-step trace and a summary.

use crate::input::grasp::{GraspSite, find_grasps};
use crate::input::playback::Playback;
use crate::object::ShapeDesc;
use crate::object::{ObjectDesc, ObjectId, StaticDesc};
use crate::pipeline::{HandId, InteractionConfig, InteractionWorld, WorldError};
use crate::{ContactEventKind, Side};
use glam::Vec3;
use std::io::Write;

/// One line of `--trace` output (JSON Lines), in world metres.
#[derive(Debug, Clone, serde::Serialize)]
pub struct TraceLine {
    /// Simulated time (s).
    pub t: f64,
    pub hands: Vec<TraceHand>,
    pub objects: Vec<TraceObject>,
    /// Active hand–object contacts.
    pub contacts: usize,
}

impl TraceLine {
    /// The line for `world` after a step, with the given hands.
    pub fn of(world: &InteractionWorld, hands: Vec<TraceHand>) -> TraceLine {
        let objects = (0..world.object_count() as u32)
            .filter_map(|o| {
                let id = ObjectId(o);
                let s = world.object_state(id).ok()?;
                Some(TraceObject {
                    name: world.object_name(id).unwrap_or("").to_string(),
                    pos: s.position.to_array(),
                    rot: s.rotation.to_array(),
                    linvel: s.linvel.to_array(),
                })
            })
            .collect();
        TraceLine { t: world.time(), hands, objects, contacts: world.contacts().len() }
    }

    /// Whether every number on the line is finite.
    pub fn is_finite(&self) -> bool {
        self.hands.iter().all(|h| h.palm.iter().all(|v| v.is_finite()))
            && self.objects.iter().all(|o| o.pos.iter().chain(&o.rot).chain(&o.linvel).all(|v| v.is_finite()))
    }
}

#[derive(Debug, Clone, serde::Serialize)]
pub struct TraceHand {
    pub id: i64,
    pub side: Side,
    pub palm: [f32; 3],
    /// The tracker's grab strength (0..1), if it reports one.
    pub grab: Option<f32>,
    /// The tracker's pinch strength (0..1), if it reports one.
    pub pinch: Option<f32>,
}

#[derive(Debug, Clone, serde::Serialize)]
pub struct TraceObject {
    pub name: String,
    pub pos: [f32; 3],
    /// Unit quaternion, x y z w.
    pub rot: [f32; 4],
    pub linvel: [f32; 3],
}

/// What happened to one object.
#[derive(Debug, Clone, serde::Serialize)]
pub struct ObjectSummary {
    pub name: String,
    /// Start-to-end displacement (m).
    pub displacement: f32,
    /// Largest speed during the replay (m/s).
    pub max_speed: f32,
    pub start: [f32; 3],
    pub end: [f32; 3],
}

/// The replay's numbers; `--json` prints exactly this.
#[derive(Debug, Clone, serde::Serialize)]
pub struct ReplaySummary {
    pub source: String,
    pub frames: usize,
    /// Distinct tracked hands.
    pub hands: usize,
    /// Recording length (s).
    pub duration: f64,
    pub steps: usize,
    pub contacts_begun: usize,
    pub objects: Vec<ObjectSummary>,
    /// True when every traced number was finite.
    pub all_finite: bool,
}

/// A world to replay into, recording its session if `record`: ground at
/// y = 0.
pub fn replay_world(config: InteractionConfig, record: bool) -> Result<InteractionWorld, WorldError> {
    let mut world = if record { InteractionWorld::new_recording(config)? } else { InteractionWorld::new(config)? };
    world.add_static(&StaticDesc::ground(0.0, 0.5))?;
    Ok(world)
}

/// A world to replay into: ground at y = 0 plus the given objects.
pub fn world_with_objects(config: InteractionConfig, objects: &[ObjectDesc]) -> Result<(InteractionWorld, Vec<ObjectId>), WorldError> {
    let mut world = replay_world(config, false)?;
    let ids = objects.iter().map(|o| world.add_object(o)).collect::<Result<Vec<_>, _>>()?;
    Ok((world, ids))
}

/// An object to put where the recorded hand grasps: `SHAPE:SIZE_M:MASS_KG`
/// with SHAPE `box` (SIZE the side) or `sphere` (SIZE the diameter).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GraspObject {
    pub sphere: bool,
    /// Side or diameter (m).
    pub size: f32,
    /// Mass (kg).
    pub mass: f32,
}

impl std::str::FromStr for GraspObject {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        let parts: Vec<&str> = s.split(':').collect();
        let [shape, size, mass] = parts.as_slice() else {
            return Err(format!("expected SHAPE:SIZE_M:MASS_KG, e.g. box:0.045:0.05, got \"{s}\""));
        };
        let sphere = match *shape {
            "box" => false,
            "sphere" => true,
            other => return Err(format!("unknown shape \"{other}\" (box or sphere)")),
        };
        let number = |what: &str, v: &str| -> Result<f32, String> {
            v.parse::<f32>()
                .ok()
                .filter(|x| x.is_finite() && *x > 0.0)
                .ok_or_else(|| format!("{what} must be a positive number, got \"{v}\""))
        };
        Ok(GraspObject { sphere, size: number("SIZE_M", size)?, mass: number("MASS_KG", mass)? })
    }
}

/// An object held in place at a grasp site until the hand grips it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fixture {
    pub object: ObjectId,
    /// Released when the hand grips it, or at the grasp's most closed
    /// instant at the latest (s).
    pub release_by: f64,
}

/// Places `object` at the site of the recording's `index`-th grasp (in
/// time order), held fixed in place (as if on a support) until the hand
/// grips it. The recorded hand grasped nothing, so without the fixture a
/// finger arriving early would knock the object away before the others
/// close on it.
pub fn place_at_grasp(
    world: &mut InteractionWorld,
    playback: &Playback,
    object: GraspObject,
    index: usize,
) -> Result<(Fixture, GraspSite), WorldError> {
    let grasps = find_grasps(playback, 0.005);
    let site = *grasps.get(index).ok_or_else(|| {
        WorldError::Object(crate::ObjectError::new(
            "grasp object",
            "site",
            format!("the recording has {} grasps, not {}", grasps.len(), index + 1),
        ))
    })?;
    let half = 0.5 * object.size;
    let shape = if object.sphere { ShapeDesc::Sphere { radius: half } } else { ShapeDesc::Box { half_extents: Vec3::splat(half) } };
    let desc = ObjectDesc { shape, ..ObjectDesc::cuboid("grasped", Vec3::splat(object.size), object.mass, site.point) };
    let id = world.add_object(&desc)?;
    world.set_object_locked(id, true)?;
    Ok((Fixture { object: id, release_by: site.closed_at }, site))
}

/// Replays `playback` into `world` for its whole duration, releasing each
/// fixture when its object is gripped, or at its deadline with its contacts
/// re-seated ([`InteractionWorld::reseat_contacts`]). Calls `each` after every step with
/// the step's trace line; its error stops the run.
pub fn replay<E: From<WorldError>>(
    source: &str,
    playback: &Playback,
    world: &mut InteractionWorld,
    fixtures: &[Fixture],
    mut each: impl FnMut(&InteractionWorld, &TraceLine) -> Result<(), E>,
) -> Result<ReplaySummary, E> {
    let mut fixtures = fixtures.to_vec();
    let hands: Vec<HandId> = playback.tracks.iter().map(|tr| world.add_hand(tr.side)).collect();
    let dt = world.config().dt as f64;
    let steps = (playback.duration / dt).floor() as usize + 1;
    let objects: Vec<ObjectId> = (0..world.object_count() as u32).map(ObjectId).collect();
    let start: Vec<Vec3> = objects.iter().map(|&o| world.object_state(o).map(|s| s.position)).collect::<Result<_, _>>()?;
    let mut max_speed = vec![0.0f32; objects.len()];
    let (mut begun, mut all_finite) = (0, true);
    for i in 0..steps {
        let t = i as f64 * dt;
        for f in std::mem::take(&mut fixtures) {
            let gripped = world.is_gripped(f.object);
            if gripped || f.release_by <= t {
                world.set_object_locked(f.object, false)?;
                if !gripped {
                    world.reseat_contacts(f.object)?;
                }
            } else {
                fixtures.push(f);
            }
        }
        let mut trace_hands = Vec::new();
        for (k, hand) in hands.iter().enumerate() {
            match playback.sample(k, t) {
                Some(s) => {
                    world.set_hand_pose(*hand, &s.pose)?;
                    trace_hands.push(TraceHand {
                        id: playback.tracks[k].id,
                        side: playback.tracks[k].side,
                        palm: s.pose.palm.to_world(Vec3::Y * s.pose.palm.half_extents.y).to_array(),
                        grab: s.grab,
                        pinch: s.pinch,
                    });
                }
                None => world.clear_hand_pose(*hand)?,
            }
        }
        world.step();
        begun += world.events().iter().filter(|e| e.kind == ContactEventKind::Began).count();
        let line = TraceLine::of(world, trace_hands);
        for (k, o) in line.objects.iter().enumerate() {
            max_speed[k] = max_speed[k].max(Vec3::from(o.linvel).length());
        }
        all_finite &= line.is_finite();
        each(world, &line)?;
    }
    let objects = objects
        .iter()
        .enumerate()
        .map(|(k, &o)| {
            let end = world.object_state(o)?.position;
            Ok(ObjectSummary {
                name: world.object_name(o).unwrap_or("").to_string(),
                displacement: (end - start[k]).length(),
                max_speed: max_speed[k],
                start: start[k].to_array(),
                end: end.to_array(),
            })
        })
        .collect::<Result<Vec<_>, WorldError>>()?;
    Ok(ReplaySummary {
        source: source.to_string(),
        frames: playback.frames,
        hands: playback.tracks.len(),
        duration: playback.duration,
        steps,
        contacts_begun: begun,
        objects,
        all_finite,
    })
}

/// Writes one trace line as JSON Lines.
pub fn write_trace_line(out: &mut impl Write, line: &TraceLine) -> std::io::Result<()> {
    serde_json::to_writer(&mut *out, line).map_err(std::io::Error::other)?;
    out.write_all(b"\n")
}
