//! A hand–object capture replayed open loop: the captured hand moves the
//! object through contacts alone, and every captured frame measures how far
//! the simulated object is from the captured one.
//!
//! The object starts at its first captured pose, on a static table whose
//! top is the mesh's lowest point in that pose, under gravity. The hand is
//! the skeletal hand fitted to the capture ([`crate::input::capture`]),
//! interpolated to the physics rate by the playback. After the first frame
//! nothing of the captured object is used: no feedback, no snapping, no
//! grab state.

use super::RunError;
use super::drive::{Observer, StepView};
use super::replay::replay;
use crate::input::capture::Capture;
use crate::scene::object::{HandSurface, MeshBody, MeshShape};
use crate::scene::{GammaMode, Material, ObjectDesc, ObjectId, StaticDesc};
use crate::{InteractionConfig, InteractionWorld, Method};
use glam::Quat;

/// V-HACD's concavity limit for the object: parts within 1 % of the
/// mesh's size of it, so a finger in a handle or a rim meets the object's
/// own shape, not its hull.
pub const CONCAVITY: f32 = 0.01;

/// The table's friction coefficient with the object (unknown in a
/// capture; a dry tabletop).
pub const TABLE_FRICTION: f32 = 0.5;

/// What a capture is replayed with; the capture gives neither the mass nor
/// the materials.
#[derive(Debug, Clone)]
pub struct CaptureOptions {
    /// How the hand moves the object.
    pub method: Method,
    /// Contact stiffness.
    pub gamma: GammaMode,
    /// The object's mass (kg).
    pub mass: f32,
    /// The skin–object material.
    pub material: Material,
    /// What the hand touches: `Exact`, the mesh's own surface wherever
    /// the mesh closes a volume (the default), or `Body`, the convex parts
    /// the engine moves (an ablation).
    pub hand_surface: HandSurface,
}

impl Default for CaptureOptions {
    fn default() -> Self {
        CaptureOptions {
            method: Method::default(),
            gamma: GammaMode::default(),
            mass: DEFAULT_MASS,
            material: Material::wood(),
            hand_surface: HandSurface::Exact,
        }
    }
}

/// The mass replayed when none is given (kg): the middle of the 0.1-0.6 kg
/// a hand-held household object weighs.
pub const DEFAULT_MASS: f32 = 0.3;

/// Replays of one capture over a grid of masses and materials, which a
/// capture does not give: the command line's `--mass` and `--material`,
/// and the Python package's `replay_capture`.
#[derive(Debug, Clone)]
pub struct CaptureGrid {
    /// How the hand moves the object.
    pub method: Method,
    /// Contact stiffness.
    pub gamma: GammaMode,
    /// Masses (kg), each positive.
    pub masses: Vec<f32>,
    /// Skin–object materials.
    pub materials: Vec<Material>,
    /// What the hand touches ([`CaptureOptions::hand_surface`]).
    pub hand_surface: HandSurface,
}

impl CaptureGrid {
    /// The grid of `masses` (kg; [`DEFAULT_MASS`] when `None`) and the
    /// materials named (wood when `None`), the hand touching the exact
    /// surface; a mass that is not positive, or an unknown material, is an
    /// error naming it.
    pub fn new(
        method: Method,
        gamma: GammaMode,
        masses: Option<Vec<f32>>,
        materials: Option<Vec<String>>,
    ) -> Result<CaptureGrid, RunError> {
        let masses = masses.unwrap_or_else(|| vec![DEFAULT_MASS]);
        if let Some(m) = masses.iter().find(|m| !(m.is_finite() && **m > 0.0)) {
            let reason = format!("{m} kg is not a positive mass");
            return Err(RunError::Study { field: "mass", reason });
        }
        let materials = match materials {
            None => vec![Material::wood()],
            Some(names) => names
                .iter()
                .map(|name| Material::by_name(name))
                .collect::<Result<_, _>>()
                .map_err(|reason| RunError::Study { field: "material", reason })?,
        };
        if masses.is_empty() || materials.is_empty() {
            let reason = "give at least one mass and one material".to_string();
            return Err(RunError::Study { field: "mass", reason });
        }
        Ok(CaptureGrid { method, gamma, masses, materials, hand_surface: HandSurface::Exact })
    }
}

/// A capture and its replays over a grid: `replay --json`'s data.
#[derive(Debug, Clone, serde::Serialize)]
pub struct CaptureReport {
    /// What was read from the capture.
    pub capture: CaptureInfo,
    /// One replay per material and mass, materials outermost.
    pub replays: Vec<CaptureReplay>,
}

/// What was read from a capture.
#[derive(Debug, Clone, serde::Serialize)]
pub struct CaptureInfo {
    /// The capture file.
    pub source: String,
    /// Captured frames.
    pub frames: usize,
    /// Frames a second.
    pub frame_rate_hz: f64,
    /// `surface` (778 points) or `keypoints` (21).
    pub hand: &'static str,
    /// The side as the capture labels it.
    pub side: crate::hand::Side,
    /// The side its points have the shape of, which the hand is built as.
    pub shape: crate::hand::Side,
    /// Finger widths (mm), thumb first.
    pub finger_widths_mm: [f32; 5],
    /// How far the palm's skin lies before its knuckles' axes (mm).
    pub palm_depth_mm: f32,
    /// What of the object the hand touches.
    pub touched: String,
}

impl CaptureInfo {
    /// What `capture` holds, and what of its object a hand asked to touch
    /// `surface` touches.
    pub fn of(c: &Capture, surface: HandSurface) -> CaptureInfo {
        CaptureInfo {
            source: c.source_name.clone(),
            frames: c.poses.len(),
            frame_rate_hz: c.frame_rate_hz,
            hand: if c.from_surface { "surface" } else { "keypoints" },
            side: c.side,
            shape: c.hand.shape,
            finger_widths_mm: c.hand.widths.map(|w| w * 1e3),
            palm_depth_mm: c.hand.palm_depth * 1e3,
            touched: touched(c, surface).1,
        }
    }
}

/// Replays `capture` once for every material and mass of `grid`.
pub fn replay_grid(capture: &Capture, grid: &CaptureGrid) -> Result<CaptureReport, RunError> {
    let mut replays = Vec::new();
    for material in &grid.materials {
        for &mass in &grid.masses {
            let options = CaptureOptions {
                method: grid.method,
                gamma: grid.gamma,
                mass,
                material: material.clone(),
                hand_surface: grid.hand_surface,
            };
            replays.push(replay_capture(capture, &options)?);
        }
    }
    let capture = CaptureInfo::of(capture, grid.hand_surface);
    Ok(CaptureReport { capture, replays })
}

/// One replay of a capture: what it was run with, its score, and every
/// captured frame.
#[derive(Debug, Clone, serde::Serialize)]
pub struct CaptureReplay {
    /// The capture file.
    pub source: String,
    /// The method's name.
    pub method: String,
    /// The object's mass (kg).
    pub mass_kg: f32,
    /// The skin–object material's name.
    pub material: String,
    /// How far it followed the capture.
    pub score: CaptureScore,
    /// Every captured frame, the first (the start) included.
    pub frames: Vec<FrameResult>,
}

/// How far a replay's object followed the captured one.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct CaptureScore {
    /// Mean translation error over the frames after the first (mm).
    pub translation_mean_mm: f32,
    /// Largest translation error (mm).
    pub translation_max_mm: f32,
    /// Mean rotation error over the frames after the first (°).
    pub rotation_mean_deg: f32,
    /// Largest rotation error (°).
    pub rotation_max_deg: f32,
    /// The captured object's highest rise above its first pose (mm).
    pub captured_lift_mm: f32,
    /// The simulated object's highest rise above its first pose (mm).
    pub simulated_lift_mm: f32,
    /// Where the simulated object ends against the captured one.
    pub set_down: SetDown,
    /// Every number of the replay was finite.
    pub all_finite: bool,
}

/// Where the object ends, at the capture's last frame.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SetDown {
    /// Horizontal distance from the captured object (mm).
    pub distance_mm: f32,
    /// The simulated object's height above its first pose (mm).
    pub height_mm: f32,
    /// The captured object's height above its first pose (mm).
    pub captured_height_mm: f32,
}

impl CaptureScore {
    /// The simulated object rose at least half as high as the captured one.
    pub fn lifted(&self) -> bool {
        self.simulated_lift_mm >= 0.5 * self.captured_lift_mm
    }

    /// It ends within 1 cm of the height the captured object ends at.
    pub fn landed(&self) -> bool {
        (self.set_down.height_mm - self.set_down.captured_height_mm).abs() <= 10.0
    }

    /// Within the targets: lifted and set down, translation error
    /// at most 10 mm on average and 30 mm at worst, rotation error at most
    /// 5° and 15°.
    pub fn on_target(&self) -> bool {
        self.lifted()
            && self.landed()
            && self.translation_mean_mm <= 10.0
            && self.translation_max_mm <= 30.0
            && self.rotation_mean_deg <= 5.0
            && self.rotation_max_deg <= 15.0
    }
}

/// One captured frame of a replay.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FrameResult {
    /// The frame's index in the capture.
    pub frame: usize,
    /// Its time (s).
    pub time_s: f64,
    /// Distance between the simulated and captured object's origins (mm).
    pub translation_error_mm: f32,
    /// The translation error's horizontal part (mm).
    pub horizontal_error_mm: f32,
    /// Angle of the rotation between them (°).
    pub rotation_error_deg: f32,
    /// The captured object's height above its first pose (mm).
    pub captured_height_mm: f32,
    /// The simulated object's height above its first pose (mm).
    pub simulated_height_mm: f32,
    /// The hand's contacts with the object, bone by bone.
    pub contacts: Vec<FrameContact>,
    /// The sum of their normal forces (N).
    pub normal_force_n: f32,
    /// The simulated object's position, in the capture's frame and units.
    pub position: [f32; 3],
    /// Its rotation (world-from-object) in the capture's frame, as a unit
    /// quaternion `[x, y, z, w]`.
    pub rotation: [f32; 4],
}

/// One contact of the hand with the object at a captured frame: what a
/// trace of the replay reads contact by contact.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FrameContact {
    /// The bone (`palm`, `index-distal`, …).
    pub bone: String,
    /// How deep the bone presses below the contact point (mm; negative
    /// while it hovers within the offset).
    pub depth_mm: f32,
    /// The force's normal part (N).
    pub normal_force_n: f32,
    /// Its tangential part, friction (N).
    pub friction_n: f32,
    /// Whether it sticks, slips or does not press.
    pub state: crate::friction::FrictionState,
    /// The contact point C, in the capture's frame and units.
    pub point: [f32; 3],
}

/// Replays `capture` with `options`.
pub fn replay_capture(
    capture: &Capture,
    options: &CaptureOptions,
) -> Result<CaptureReplay, RunError> {
    let (mut world, object) = capture_world(capture, options)?;
    let playback = capture.playback()?;
    let mut frames = Vec::with_capacity(capture.poses.len());
    frames.push(measure(capture, &world, object, 0)?);
    let dt = f64::from(world.config().dt);
    let mut recorder = FrameRecorder { capture, object, dt, frames: &mut frames, failed: None };
    let summary = replay(&capture.source_name, &playback, &mut world, &[], &mut [&mut recorder])?;
    if let Some(e) = recorder.failed {
        return Err(e);
    }
    // The last frame falls on the playback's last instant; should rounding
    // leave it unstepped, it is measured at the world's last step.
    while frames.len() < capture.poses.len() {
        frames.push(measure(capture, &world, object, frames.len())?);
    }
    let score = score(&frames, summary.all_finite);
    Ok(CaptureReplay {
        source: capture.source_name.clone(),
        method: options.method.to_string(),
        mass_kg: options.mass,
        material: options.material.name.clone(),
        score,
        frames,
    })
}

/// The world a capture is replayed in: the table and the object at its
/// first captured pose.
pub fn capture_world(
    capture: &Capture,
    options: &CaptureOptions,
) -> Result<(InteractionWorld, ObjectId), RunError> {
    let base = InteractionConfig { gamma: options.gamma, ..InteractionConfig::default() };
    capture.check()?;
    let mut world = InteractionWorld::new(options.method.config(base))?;
    let (position, rotation) = capture.poses[0];
    let table = capture.mesh.vertices.iter().map(|v| (rotation * *v + position).y);
    world.add_static(&StaticDesc::ground(table.fold(f32::INFINITY, f32::min), TABLE_FRICTION))?;
    let body = MeshBody::ConvexParts { concavity: CONCAVITY };
    let shape = MeshShape {
        hand_surface: touched(capture, options.hand_surface).0,
        ..MeshShape::new(&capture.mesh_file, 1.0, body, capture.mesh.clone())
    };
    let desc = ObjectDesc {
        rotation,
        material: options.material.clone(),
        ..ObjectDesc::mesh("object", shape, options.mass, position)
    };
    let object = world.add_object(&desc)?;
    Ok((world, object))
}

/// What the hand touches of a capture's object, asked for `asked`: its
/// exact surface, which the real hand touched, when the mesh closes a
/// volume; else the convex parts the engine moves, and why.
fn touched(capture: &Capture, asked: HandSurface) -> (HandSurface, String) {
    match asked {
        HandSurface::Body => (HandSurface::Body, "the mesh's convex parts, as asked".to_string()),
        HandSurface::Exact => match capture.mesh.solid() {
            Ok(_) => (HandSurface::Exact, "the mesh's exact surface".to_string()),
            Err(e) => (HandSurface::Body, format!("the mesh's convex parts ({e})")),
        },
    }
}

/// Measures the object at every captured frame's time: at the physics step
/// nearest to it.
struct FrameRecorder<'a> {
    capture: &'a Capture,
    object: ObjectId,
    dt: f64,
    frames: &'a mut Vec<FrameResult>,
    failed: Option<RunError>,
}

impl Observer for FrameRecorder<'_> {
    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        let next = self.frames.len();
        if next < self.capture.poses.len() && step.t + 0.5 * self.dt > self.capture.time(next) {
            match measure(self.capture, step.world, self.object, next) {
                Ok(frame) => self.frames.push(frame),
                Err(e) => self.failed = Some(e),
            }
        }
        Ok(())
    }
}

/// Frame `i`'s measure of the simulated object against the captured one.
fn measure(
    capture: &Capture,
    world: &InteractionWorld,
    object: ObjectId,
    i: usize,
) -> Result<FrameResult, RunError> {
    let state = world.object_state(object)?;
    let (captured, captured_rotation) = capture.poses[i];
    let start = capture.poses[0].0.y;
    let contacts = world.contacts_on(object);
    let (position, rotation) = capture.frame.pose_back(state.position, state.rotation);
    Ok(FrameResult {
        frame: i,
        time_s: capture.time(i),
        translation_error_mm: (state.position - captured).length() * 1e3,
        horizontal_error_mm: (state.position - captured).with_y(0.0).length() * 1e3,
        rotation_error_deg: rotation_between(state.rotation, captured_rotation),
        captured_height_mm: (captured.y - start) * 1e3,
        simulated_height_mm: (state.position.y - start) * 1e3,
        contacts: contacts.iter().map(|c| contact_of(capture, c)).collect(),
        normal_force_n: contacts.iter().map(|c| c.normal_force).sum(),
        position: position.to_array(),
        rotation: rotation.to_array(),
    })
}

/// A contact as a frame reports it.
fn contact_of(capture: &Capture, c: &crate::contact::Contact) -> FrameContact {
    let friction = c.force - c.normal * c.force.dot(c.normal);
    let point = capture.frame.point_back(c.point);
    FrameContact {
        bone: c.bone.to_string(),
        depth_mm: c.depth * 1e3,
        normal_force_n: c.normal_force,
        friction_n: friction.length(),
        state: c.state,
        point: point.to_array(),
    }
}

/// The angle of the rotation taking `a` to `b` (°), in [0, 180].
fn rotation_between(a: Quat, b: Quat) -> f32 {
    let dot = a.normalize().dot(b.normalize()).abs().min(1.0);
    (2.0 * dot.acos()).to_degrees()
}

/// The score of a replay's frames.
fn score(frames: &[FrameResult], finite: bool) -> CaptureScore {
    let after = &frames[1.min(frames.len())..];
    let mean =
        |f: fn(&FrameResult) -> f32| after.iter().map(f).sum::<f32>() / after.len().max(1) as f32;
    let max = |f: fn(&FrameResult) -> f32| after.iter().map(f).fold(0.0, f32::max);
    let last = frames.last();
    let all = [mean(|f| f.translation_error_mm), mean(|f| f.rotation_error_deg)];
    CaptureScore {
        translation_mean_mm: all[0],
        translation_max_mm: max(|f| f.translation_error_mm),
        rotation_mean_deg: all[1],
        rotation_max_deg: max(|f| f.rotation_error_deg),
        captured_lift_mm: max(|f| f.captured_height_mm),
        simulated_lift_mm: max(|f| f.simulated_height_mm),
        set_down: SetDown {
            distance_mm: last.map_or(0.0, |l| l.horizontal_error_mm),
            height_mm: last.map_or(0.0, |l| l.simulated_height_mm),
            captured_height_mm: last.map_or(0.0, |l| l.captured_height_mm),
        },
        all_finite: finite && all.iter().all(|x| x.is_finite()),
    }
}
