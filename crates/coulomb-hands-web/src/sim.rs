//! A world and what drives it, in plain Rust: what the page's `World` does,
//! with errors as the library's messages. The bindings ([`crate::World`])
//! only turn these into JavaScript values and exceptions, so everything
//! here also runs natively (the tests, `examples/reference.rs`).

use crate::arrays;
use coulomb_hands::files::NoFiles;
use coulomb_hands::hand::rig::HandRig;
use coulomb_hands::hand::{HandPose, HandSample};
use coulomb_hands::input::capture;
use coulomb_hands::input::layouts::{self, Layout};
use coulomb_hands::input::playback::{DEFAULT_GRACE, Playback};
use coulomb_hands::input::recording;
use coulomb_hands::run::capture::{CaptureOptions, capture_world};
use coulomb_hands::run::closing::Closings;
use coulomb_hands::run::demo::GraspLiftCarry;
use coulomb_hands::run::drive::{Driver, Observer, PoseFn};
use coulomb_hands::run::replay::{GraspObject, replay_world};
use coulomb_hands::run::sampled::FrameHands;
use coulomb_hands::run::scenario::check::{Check, History};
use coulomb_hands::run::scenario::{self, Scenario, ScenarioHand, ScenarioReport};
use coulomb_hands::scene::Scene;
use coulomb_hands::scene::mesh::TriangleMesh;
use coulomb_hands::scene::{MeshBody, MeshShape};
use coulomb_hands::{
    HandId, InteractionConfig, InteractionWorld, Material, ObjectDesc, ObjectId, Side, StaticDesc,
    WorldError,
};
use glam::{Quat, Vec3};
use std::path::Path;

/// An error as the page shows it: the library's message.
pub type Error = String;

/// What the library returns, its error as text.
fn text<T, E: std::fmt::Display>(result: Result<T, E>) -> Result<T, Error> {
    result.map_err(|e| e.to_string())
}

/// The scene the viewer opens on, a desk of objects for a hand to push,
/// grasp and lift: the viewer's own file.
pub const DESK: &str = include_str!("../../coulomb-hands-view/scenes/desk.json");

/// The object the bundled recording's closings get (the book's replay
/// example): a 4 cm, 50 g box.
pub const CLOSING_OBJECT: &str = coulomb_hands::run::held::GraspObject::DEFAULT;

/// What watches a world's run: nothing, a scenario's checks, or a recording's closings.
enum Script {
    /// Nothing: the hands are the caller's, or a script's without checks (the demo's).
    Free,
    /// A scenario, whose checks are judged on its history.
    Scenario { report: ReportInputs },
    /// A recording, with an object at each closing and its verdicts.
    Recording { closings: Option<Box<Closings>> },
    /// A hand–object capture's hand, with the captured object drawn as a ghost.
    Capture { ghost: Box<Ghost> },
}

/// The captured object of a hand–object capture: its mesh, and its pose
/// frame by frame, which the page draws beside the simulated object.
pub struct Ghost {
    /// The object's mesh in its own frame (m).
    mesh: TriangleMesh,
    /// Its captured pose per frame (world, m), at least two.
    poses: Vec<(Vec3, Quat)>,
    /// Frames a second.
    frame_rate_hz: f64,
}

impl Ghost {
    /// The captured pose at time `t` (s): between the two frames about
    /// `t`, the position linear and the rotation by slerp; before the first
    /// frame the first pose, after the last the last.
    pub fn pose_at(&self, t: f64) -> (Vec3, Quat) {
        capture::pose_at(&self.poses, self.frame_rate_hz, t)
    }

    /// Its mesh's triangles in its own frame, 9 numbers each, as the
    /// page's `objectMesh` gives an object's.
    pub fn triangles(&self) -> Vec<f32> {
        let corner = |i: &u32| self.mesh.vertices[*i as usize].to_array();
        self.mesh.triangles.iter().flatten().flat_map(corner).collect()
    }
}

/// A scenario's name, checks and the history they measure.
struct ReportInputs {
    name: String,
    checks: Vec<Check>,
    history: Box<History>,
}

/// A world, the hands that drive it (a script's, a recording's, or none),
/// and what watches it.
pub struct Sim {
    driver: Driver<'static, InteractionWorld>,
    script: Script,
    /// How many steps its script runs, counted as the library's own run counts them
    /// (`GraspLiftCarry::run`, `Scenario::run`, `replay`), or `None`.
    script_steps: Option<usize>,
    /// A name for the page.
    name: String,
    /// The hands the page poses once per frame (the mouse's, the
    /// headset's): the frame's steps take each from where it was to its
    /// frame's pose, by the core's rule for a hand sampled at a display's
    /// rate ([`coulomb_hands::run::sampled`]), instead of holding it for
    /// the frame's steps and then jumping.
    posed: FrameHands,
}

/// A hand side by name.
pub fn side(name: &str) -> Result<Side, Error> {
    name.parse().map_err(|e| format!("side: {e}"))
}

/// The config from JSON text: any [`InteractionConfig`] fields, the others
/// their defaults; empty text is the default config.
pub fn config(json: &str) -> Result<InteractionConfig, Error> {
    if json.trim().is_empty() {
        return Ok(InteractionConfig::default());
    }
    let config: InteractionConfig =
        serde_json::from_str(json).map_err(|e| format!("config: {e}"))?;
    text(config.validate())?;
    Ok(config)
}

/// The shipped scenarios' names, in the CLI's order.
pub fn shipped_names() -> Vec<String> {
    scenario::shipped().iter().map(|(name, _)| (*name).to_string()).collect()
}

impl Sim {
    fn new(world: InteractionWorld, script: Script, steps: Option<usize>, name: &str) -> Sim {
        let driver = Driver::new(world);
        Sim { driver, script, script_steps: steps, name: name.into(), posed: FrameHands::default() }
    }

    /// An empty world with `config`.
    pub fn empty(config: InteractionConfig) -> Result<Sim, Error> {
        Ok(Sim::new(text(InteractionWorld::new(config))?, Script::Free, None, "world"))
    }

    /// The README's demo: a scripted right hand grasps a 5 cm cube, lifts,
    /// carries and turns it, then opens (`coulomb-hands demo`, the same
    /// world and hand).
    pub fn demo() -> Result<Sim, Error> {
        let demo = text(GraspLiftCarry::new(InteractionConfig::default()))?;
        let GraspLiftCarry { world, hand, half, .. } = demo;
        let steps = GraspLiftCarry::steps(world.config().dt);
        let mut sim = Sim::new(world, Script::Free, Some(steps), "demo");
        let script =
            PoseFn::new(Side::Right, move |t| Some(GraspLiftCarry::pose_at(half, t as f32)));
        text(sim.driver.drive(hand, script))?;
        Ok(sim)
    }

    /// A shipped scenario by name, with its hands and checks.
    pub fn shipped_scenario(name: &str) -> Result<Sim, Error> {
        if !scenario::shipped().iter().any(|(n, _)| *n == name) {
            let names = shipped_names().join(", ");
            return Err(format!("no shipped scenario {name:?} (shipped: {names})"));
        }
        Sim::of_scenario(text(Scenario::find(name))?)
    }

    /// A scenario file's text (`file` names it in errors); the files it
    /// names (recordings, meshes) cannot be read in a page.
    pub fn scenario_text(file: &str, json: &str) -> Result<Sim, Error> {
        Sim::of_scenario(text(Scenario::parse_with(file, json, Path::new(""), &NoFiles))?)
    }

    fn of_scenario(scenario: Scenario) -> Result<Sim, Error> {
        let mut world = text(InteractionWorld::new(scenario.config))?;
        text(world.add_scene(&scenario.scene))?;
        let history = Box::new(History::new(&world));
        let steps = scenario.steps();
        let report = ReportInputs { name: scenario.name.clone(), checks: scenario.checks, history };
        let mut sim = Sim::new(world, Script::Scenario { report }, Some(steps), &scenario.name);
        for hand in scenario.hands {
            sim.driver.add_hand(hand);
        }
        Ok(sim)
    }

    /// A scene file's text (`file` names it in errors), or the desk's for
    /// `desk`, with its gravity, and no hands yet.
    pub fn scene(file: &str, json: &str) -> Result<Sim, Error> {
        let scene = text(Scene::parse_with(file, json, Path::new(""), &NoFiles))?;
        let config = InteractionConfig::default().with_scene(&scene);
        let mut world = text(InteractionWorld::new(config))?;
        text(world.add_scene(&scene))?;
        Ok(Sim::new(world, Script::Free, None, file))
    }

    /// The desk scene of the viewer.
    pub fn desk() -> Result<Sim, Error> {
        let mut sim = Sim::scene("scenes/desk.json", DESK)?;
        sim.name = "desk".into();
        Ok(sim)
    }

    /// A recording's bytes (Leap Motion `.json` or `.json.lz`, a joint
    /// recording `.jsonl`; `file` is its name, whose extension counts),
    /// replayed over a ground as `coulomb-hands replay` does, with an
    /// `object` (`box:SIDE:MASS` or `sphere:DIAMETER:MASS`) at each closing
    /// of a hand if given, whose verdicts [`Sim::verdicts_json`] gives.
    pub fn recording(file: &str, bytes: Vec<u8>, object: Option<&str>) -> Result<Sim, Error> {
        let recording = text(recording::from_bytes(file, bytes))?;
        let playback = text(recording.playback(Vec3::ZERO, DEFAULT_GRACE))?;
        let object: Option<GraspObject> =
            object.map(|o| o.parse().map_err(|e| format!("object: {e}"))).transpose()?;
        let world = text(replay_world(InteractionConfig::default(), false))?;
        let closings =
            object.map(|o| text(Closings::new(&playback, o)).map(Box::new)).transpose()?;
        let script = Script::Recording { closings };
        Ok(Sim::of_playback(world, playback, script, &recording.source_name))
    }

    /// A hand–object capture's text (`file` names it in errors) and the
    /// bytes of the mesh it names, replayed as `coulomb-hands replay` replays
    /// a capture: the object at its first captured pose on a table, moved
    /// by the captured hand through contacts alone. The captured object is
    /// [`Sim::ghost_pose`] and [`Sim::ghost_mesh`].
    pub fn capture(file: &str, json: &str, mesh_bytes: &[u8]) -> Result<Sim, Error> {
        let mesh =
            |name: &str| TriangleMesh::from_bytes(name, mesh_bytes).map_err(|e| e.to_string());
        let captured = text(capture::parse(file, json, &mesh))?;
        let playback = text(captured.playback())?;
        let (world, _) = text(capture_world(&captured, &CaptureOptions::default()))?;
        let capture::Capture { mesh, poses, frame_rate_hz, source_name, .. } = captured;
        let script = Script::Capture { ghost: Box::new(Ghost { mesh, poses, frame_rate_hz }) };
        Ok(Sim::of_playback(world, playback, script, &source_name))
    }

    /// `world` driven by every hand of `playback` for its whole duration and
    /// one step more, as the CLI's replay runs.
    fn of_playback(world: InteractionWorld, playback: Playback, script: Script, name: &str) -> Sim {
        let steps = playback.steps(world.config().dt);
        let mut sim = Sim::new(world, script, Some(steps), name);
        let playback = Box::new(playback);
        for track in 0..playback.tracks.len() {
            sim.driver.add_hand(ScenarioHand::Recording { playback: playback.clone(), track });
        }
        sim
    }

    /// A capture's captured object, or `None` for any other run.
    pub fn ghost(&self) -> Option<&Ghost> {
        match &self.script {
            Script::Capture { ghost } => Some(ghost),
            _ => None,
        }
    }

    /// The captured object's pose at the world's time: position (3 numbers,
    /// m) and rotation (x, y, z, w); empty for a run that is no capture.
    pub fn ghost_pose(&self) -> Vec<f32> {
        let Some(ghost) = self.ghost() else { return Vec::new() };
        let (position, rotation) = ghost.pose_at(self.world().time());
        position.to_array().into_iter().chain(rotation.to_array()).collect()
    }

    /// The captured object's triangles in its own frame (9 numbers each);
    /// empty for a run that is no capture.
    pub fn ghost_mesh(&self) -> Vec<f32> {
        self.ghost().map(Ghost::triangles).unwrap_or_default()
    }

    /// Its name: the scenario's, the recording's, `demo`, `desk`.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// How long its script runs (s); `None` for a world the caller drives.
    pub fn duration(&self) -> Option<f64> {
        let dt = f64::from(self.world().config().dt);
        self.script_steps.map(|n| n as f64 * dt)
    }

    /// The world.
    pub fn world(&self) -> &InteractionWorld {
        self.driver.world()
    }

    fn world_mut(&mut self) -> &mut InteractionWorld {
        self.driver.world_mut()
    }

    /// Steps run so far.
    pub fn steps(&self) -> usize {
        self.driver.steps()
    }

    /// Up to `n` steps, each its hands posed (the script's, and the
    /// page's on their way to the poses it set since the last steps,
    /// reached at the last of these `n`), the hand forces, rapier's step; a script
    /// stops at its end. Returns the steps run.
    pub fn step(&mut self, n: usize) -> Result<usize, Error> {
        let left = self.script_steps.map_or(n, |total| total.saturating_sub(self.steps()));
        let n = n.min(left);
        self.posed.begin(self.driver.world(), n);
        let mut run = 0;
        for _ in 0..n {
            text(self.posed.pose(self.driver.world_mut()))?;
            let mut observers: Vec<&mut dyn Observer> = match &mut self.script {
                Script::Free | Script::Recording { closings: None } | Script::Capture { .. } => {
                    Vec::new()
                }
                Script::Scenario { report } => vec![&mut *report.history],
                Script::Recording { closings: Some(c) } => vec![&mut **c],
            };
            if !text(self.driver.step(&mut observers))? {
                break;
            }
            run += 1;
        }
        Ok(run)
    }

    /// Whether its script has run to its end (never, without one).
    pub fn finished(&self) -> bool {
        self.script_steps.is_some_and(|total| self.steps() >= total)
    }

    /// A scenario's checks judged on the run so far, as `scenario --json`
    /// gives one scenario's report; `None` for anything else.
    pub fn report(&self) -> Option<ScenarioReport> {
        let Script::Scenario { report } = &self.script else { return None };
        let checks: Vec<_> = report.checks.iter().map(|c| c.evaluate(&report.history)).collect();
        let passed = checks.iter().all(|c| c.passed);
        Some(ScenarioReport { name: report.name.clone(), passed, checks })
    }

    /// [`Sim::report`] as JSON, or `null`.
    pub fn report_json(&self) -> String {
        serde_json::to_string(&self.report()).unwrap_or_else(|_| "null".into())
    }

    /// A recording's closings' verdicts so far as a JSON array (as in
    /// `replay --json`'s `closings`), or `null` without closings.
    pub fn verdicts_json(&self) -> String {
        let verdicts = match &self.script {
            Script::Recording { closings: Some(c) } => Some(c.verdicts()),
            _ => None,
        };
        serde_json::to_string(&verdicts).unwrap_or_else(|_| "null".into())
    }

    /// A recording's closings' verdicts so far, one line each as `coulomb-hands replay`
    /// prints them; empty without closings.
    pub fn verdict_lines(&self) -> Vec<String> {
        match &self.script {
            Script::Recording { closings: Some(c) } => {
                c.verdicts().iter().map(ToString::to_string).collect()
            }
            _ => Vec::new(),
        }
    }

    fn hand(&self, hand: u32) -> Result<Side, Error> {
        let id = HandId(hand);
        self.world().hand_side(id).ok_or_else(|| WorldError::NoSuchHand(id).to_string())
    }

    /// A hand, untracked until it is posed; returns its id.
    pub fn add_hand(&mut self, side: Side) -> u32 {
        self.world_mut().add_hand(side).0
    }

    /// Hand `hand` posed by `sample` at the next steps (lost for `None`),
    /// reached at the last of them; a bad hand or pose changes nothing.
    fn pose(&mut self, hand: u32, sample: Option<HandSample>) -> Result<(), Error> {
        text(self.posed.set(self.driver.world_mut(), HandId(hand), sample))
    }

    /// [`Sim::pose`] of a pose with no tracker strengths.
    fn pose_bones(&mut self, hand: u32, pose: HandPose) -> Result<(), Error> {
        self.pose(hand, Some(HandSample::from_pose(pose)))
    }

    /// Poses a hand from WebXR Hand Input's 25 joints, wrist first:
    /// positions (75 numbers, m, y up), radii (25, m), and orientations
    /// (100: x, y, z, w each) if given.
    pub fn set_hand_webxr(
        &mut self,
        hand: u32,
        positions: &[f32],
        radii: &[f32],
        orientations: Option<&[f32]>,
    ) -> Result<(), Error> {
        let side = self.hand(hand)?;
        let count = Layout::WebXr.count();
        let positions = arrays::vec3s(positions, "positions", count)?;
        let quats = orientations.map(|q| arrays::quats(q, "orientations", count)).transpose()?;
        if radii.len() != count {
            return Err(format!("radii: expected {count} numbers (webxr), got {}", radii.len()));
        }
        let webxr = Layout::WebXr;
        let given = (Some(radii), quats.as_deref());
        let pose =
            text(layouts::hand_pose_from_joints(webxr, hand, side, &positions, given.0, given.1))?;
        self.pose_bones(hand, pose)
    }

    /// Poses a hand's 16 bones from [`arrays::POSE`] numbers.
    pub fn set_hand_pose(&mut self, hand: u32, pose: &[f32]) -> Result<(), Error> {
        self.hand(hand)?;
        let pose = arrays::pose_from(pose)?;
        self.pose_bones(hand, pose)
    }

    /// Poses a hand as the rig's adult hand of its side: the palm's centre
    /// (3 numbers, m), its rotation (x, y, z, w), each finger's curl (5, 0
    /// straight to 1 a fist, thumb first) and the thumb's opposition (0 to
    /// 1): the viewer's mouse-driven hand.
    pub fn set_hand_rig(
        &mut self,
        hand: u32,
        palm: &[f32],
        rotation: &[f32],
        curl: &[f32],
        opposition: f32,
    ) -> Result<(), Error> {
        let side = self.hand(hand)?;
        let palm = arrays::vec3s(palm, "palm", 1)?[0];
        let rotation = arrays::quats(rotation, "rotation", 1)?[0];
        let curl: [f32; 5] =
            curl.try_into().map_err(|_| format!("curl: expected 5 numbers, got {}", curl.len()))?;
        if !curl.iter().chain([&opposition]).all(|c| (0.0..=1.0).contains(c)) {
            return Err(format!(
                "curl and opposition: each from 0 to 1, got {curl:?}, {opposition}"
            ));
        }
        let pose = HandRig::adult(side).pose_opposed(palm, rotation, curl, opposition);
        self.pose_bones(hand, pose)
    }

    /// Marks a hand untracked: its contacts end at the next step.
    pub fn clear_hand(&mut self, hand: u32) -> Result<(), Error> {
        self.pose(hand, None)
    }

    /// A hand's acting pose as [`arrays::POSE`] numbers, or empty while it
    /// is untracked.
    pub fn hand_pose(&self, hand: u32) -> Result<Vec<f32>, Error> {
        self.hand(hand)?;
        Ok(self.world().hand_pose(HandId(hand)).map(arrays::pose).unwrap_or_default())
    }

    /// A ground slab whose top is at `height` (m).
    pub fn add_ground(&mut self, height: f32, friction: f32) -> Result<(), Error> {
        text(self.world_mut().add_static(&StaticDesc::ground(height, friction)).map(|_| ()))
    }

    /// Adds `desc` with a material of the library's table by name.
    fn add(&mut self, desc: ObjectDesc, material: &str) -> Result<u32, Error> {
        let found = Material::by_name(material).map_err(|why| format!("{}: {why}", desc.name))?;
        Ok(text(self.world_mut().add_object(&desc.with_material(found)))?.0)
    }

    /// A box of full `size` (3 numbers, m) and `mass` (kg) at `position`,
    /// turned by `rotation` (x, y, z, w, or empty); returns its id.
    pub fn add_box(
        &mut self,
        name: &str,
        size: &[f32],
        mass: f32,
        position: &[f32],
        rotation: &[f32],
        material: &str,
    ) -> Result<u32, Error> {
        let size = arrays::vec3s(size, "size", 1)?[0];
        let at = arrays::vec3s(position, "position", 1)?[0];
        let rotation = arrays::rotation(rotation)?;
        self.add(ObjectDesc { rotation, ..ObjectDesc::cuboid(name, size, mass, at) }, material)
    }

    /// A sphere of `radius` (m) and `mass` (kg) at `position`; returns its id.
    pub fn add_sphere(
        &mut self,
        name: &str,
        radius: f32,
        mass: f32,
        position: &[f32],
        material: &str,
    ) -> Result<u32, Error> {
        let at = arrays::vec3s(position, "position", 1)?[0];
        self.add(ObjectDesc::sphere(name, radius, mass, at), material)
    }

    /// A mesh from an OBJ, STL, glTF or GLB file's bytes (`file` is its
    /// name, whose extension says its format), scaled by `scale`, filled
    /// with boxes of side `voxel_size` (m; `None`, the library's
    /// [`MeshBody::DEFAULT`]); returns its id.
    #[allow(clippy::too_many_arguments)]
    pub fn add_mesh(
        &mut self,
        name: &str,
        file: &str,
        bytes: &[u8],
        scale: f32,
        voxel_size: Option<f32>,
        mass: f32,
        position: &[f32],
        rotation: &[f32],
        material: &str,
    ) -> Result<u32, Error> {
        let mesh = text(TriangleMesh::from_bytes(file, bytes))?;
        let body = voxel_size.map_or(MeshBody::DEFAULT, |size| MeshBody::Voxels { size });
        let at = arrays::vec3s(position, "position", 1)?[0];
        let rotation = arrays::rotation(rotation)?;
        let shape = MeshShape::new(file, scale, body, mesh);
        let desc = ObjectDesc { rotation, ..ObjectDesc::mesh(name, shape, mass, at) };
        self.add(desc, material)
    }

    /// A scene file's text added: its ground, statics, objects and towers
    /// (its gravity belongs to the config). Returns the ids it added.
    pub fn add_scene(&mut self, file: &str, json: &str) -> Result<Vec<u32>, Error> {
        let scene = text(Scene::parse_with(file, json, Path::new(""), &NoFiles))?;
        let first = self.world().object_count() as u32;
        text(self.world_mut().add_scene(&scene))?;
        Ok((first..self.world().object_count() as u32).collect())
    }

    /// Removes an object: what rested on it falls, its contacts end at the
    /// next step, and its id is not given again.
    pub fn remove_object(&mut self, id: u32) -> Result<(), Error> {
        text(self.world_mut().remove_object(ObjectId(id)))
    }

    /// Puts an object at `position` and `rotation` (x, y, z, w, or empty),
    /// at rest.
    pub fn place_object(
        &mut self,
        id: u32,
        position: &[f32],
        rotation: &[f32],
    ) -> Result<(), Error> {
        let at = arrays::vec3s(position, "position", 1)?[0];
        let rotation = arrays::rotation(rotation)?;
        text(self.world_mut().place_object(ObjectId(id), at, rotation))
    }
}

/// Numbers' bits as hexadecimal, 8 digits each: how the browser test
/// compares the page's numbers with the native library's.
pub fn hex(values: &[f32]) -> String {
    values.iter().map(|v| format!("{:08x}", v.to_bits())).collect()
}

/// A run's trace, which the page writes as it steps (`web/trace.js`) and
/// `examples/reference.rs` natively: after every `every` steps, and at the
/// end, the objects' states and the contacts as [`hex`] bits, joined by
/// `|`; the run is stepped to its script's end.
pub fn trace(sim: &mut Sim, every: usize) -> Result<Vec<String>, Error> {
    if sim.duration().is_none() {
        return Err("trace: a world without a script runs without end".into());
    }
    let mut rows = Vec::new();
    loop {
        let run = sim.step(every - sim.steps() % every)?;
        let world = sim.world();
        let states = arrays::states(world.object_slots().map(|(_, state)| state));
        let contacts = arrays::contacts(world.contacts());
        rows.push(format!("{}|{}", hex(&states), hex(&contacts)));
        if run == 0 || sim.finished() {
            return Ok(rows);
        }
    }
}
