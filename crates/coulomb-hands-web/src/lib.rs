//! coulomb-hands in the browser: a wasm-bindgen API over
//! [`InteractionWorld`](coulomb_hands::InteractionWorld), which the page in
//! `web/` draws with three.js and poses from WebXR hand tracking.
//!
//! One class, `World`: a world and what drives it. It is made empty
//! (`new World(configJson)`), or as the README's demo, a shipped scenario,
//! a scene, the viewer's desk, or a recording's bytes replayed with its
//! closings' verdicts. Objects are added as boxes, spheres, meshes from a
//! file's bytes, or scene text; hands are added and posed from WebXR's 25
//! joints with radii (the library's `webxr` layout), from the rig's hand
//! (the mouse-driven hand), or from a pose's numbers; `step(n)` runs `n`
//! steps of 1 ms (by default); states, contacts and events come back as
//! typed arrays whose layouts are in [`arrays`] (their strides:
//! `poseStride()`, `stateStride()`, `contactStride()`, `eventStride()`).
//! Every error is a JavaScript `Error` carrying the library's message, and
//! leaves the world as it was.
//!
//! Everything but the bindings is plain Rust ([`sim::Sim`]), which the
//! native tests and `examples/reference.rs` run: the page's numbers are the
//! native library's, bit for bit, with `enhanced-determinism`.

pub mod arrays;
pub mod shapes;
pub mod sim;

use coulomb_hands::ObjectId;
use sim::Sim;
use wasm_bindgen::prelude::*;

/// A panic (a bug: the library returns errors for bad input) is written to the browser's
/// console with its message before the module aborts, instead of a bare `unreachable`.
#[cfg(target_arch = "wasm32")]
#[wasm_bindgen(start)]
fn start() {
    #[wasm_bindgen]
    extern "C" {
        #[wasm_bindgen(js_namespace = console)]
        fn error(message: &str);
    }
    std::panic::set_hook(Box::new(|info| error(&format!("coulomb-hands-web: {info}"))));
}

/// The library's message as a JavaScript `Error`.
fn js<T>(result: Result<T, sim::Error>) -> Result<T, JsError> {
    result.map_err(|e| JsError::new(&e))
}

/// A world and what drives it.
#[wasm_bindgen]
pub struct World {
    sim: Sim,
}

/// The shipped scenarios' names, in the CLI's order.
#[wasm_bindgen(js_name = shippedScenarios)]
pub fn shipped_scenarios() -> Vec<String> {
    sim::shipped_names()
}

/// The object a recording's closings get by default (`box:0.04:0.05`).
#[wasm_bindgen(js_name = closingObject)]
pub fn closing_object() -> String {
    sim::CLOSING_OBJECT.into()
}

/// How many numbers a hand pose has ([`arrays::POSE`]).
#[wasm_bindgen(js_name = poseStride)]
pub fn pose_stride() -> usize {
    arrays::POSE
}

/// How many numbers each object state has ([`arrays::STATE`]).
#[wasm_bindgen(js_name = stateStride)]
pub fn state_stride() -> usize {
    arrays::STATE
}

/// How many numbers each contact has ([`arrays::CONTACT`]).
#[wasm_bindgen(js_name = contactStride)]
pub fn contact_stride() -> usize {
    arrays::CONTACT
}

/// How many numbers each event has ([`arrays::EVENT`]).
#[wasm_bindgen(js_name = eventStride)]
pub fn event_stride() -> usize {
    arrays::EVENT
}

#[wasm_bindgen]
impl World {
    /// An empty world; `config` is JSON of any config fields (the others
    /// their defaults), or empty.
    #[wasm_bindgen(constructor)]
    pub fn new(config: &str) -> Result<World, JsError> {
        Ok(World { sim: js(Sim::empty(js(sim::config(config))?))? })
    }

    /// The README's demo: a scripted hand grasps, lifts, carries and turns
    /// a cube, then opens.
    pub fn demo() -> Result<World, JsError> {
        Ok(World { sim: js(Sim::demo())? })
    }

    /// A shipped scenario by name, with its hands and checks.
    pub fn scenario(name: &str) -> Result<World, JsError> {
        Ok(World { sim: js(Sim::shipped_scenario(name))? })
    }

    /// A scenario file's text; `file` names it in errors.
    #[wasm_bindgen(js_name = scenarioText)]
    pub fn scenario_text(file: &str, json: &str) -> Result<World, JsError> {
        Ok(World { sim: js(Sim::scenario_text(file, json))? })
    }

    /// A scene file's text, with its gravity and no hands; `file` names it
    /// in errors.
    pub fn scene(file: &str, json: &str) -> Result<World, JsError> {
        Ok(World { sim: js(Sim::scene(file, json))? })
    }

    /// The viewer's desk: a cube, a ball, a block and a can on the ground.
    pub fn desk() -> Result<World, JsError> {
        Ok(World { sim: js(Sim::desk())? })
    }

    /// A recording's bytes replayed over a ground, as `coulomb-hands
    /// replay` does; `file` is its name (its extension counts), and
    /// `object` (`box:SIDE:MASS` or `sphere:DIAMETER:MASS`), if given, is
    /// put at each closing of a hand and judged (`verdicts()`).
    pub fn recording(file: &str, bytes: Vec<u8>, object: Option<String>) -> Result<World, JsError> {
        Ok(World { sim: js(Sim::recording(file, bytes, object.as_deref()))? })
    }

    /// A hand–object capture's JSON text (`file` names it in errors) and
    /// the bytes of the mesh it names, replayed as `coulomb-hands replay`
    /// replays one: the captured hand moves the object through contacts;
    /// the captured object is `ghostPose()` and `ghostMesh()`.
    pub fn capture(file: &str, json: &str, mesh: &[u8]) -> Result<World, JsError> {
        Ok(World { sim: js(Sim::capture(file, json, mesh))? })
    }

    /// A capture's captured object at the world's time: position (3, m)
    /// and rotation (4, x, y, z, w); empty for any other run.
    #[wasm_bindgen(js_name = ghostPose)]
    pub fn ghost_pose(&self) -> Vec<f32> {
        self.sim.ghost_pose()
    }

    /// A capture's captured object's triangles in its own frame (9 numbers
    /// each); empty for any other run.
    #[wasm_bindgen(js_name = ghostMesh)]
    pub fn ghost_mesh(&self) -> Vec<f32> {
        self.sim.ghost_mesh()
    }

    /// Its name: the scenario's, the recording's, `demo`, `desk`.
    #[wasm_bindgen(getter)]
    pub fn name(&self) -> String {
        self.sim.name().into()
    }

    /// How long its script runs (s), or undefined for a world the page
    /// drives.
    #[wasm_bindgen(getter)]
    pub fn duration(&self) -> Option<f64> {
        self.sim.duration()
    }

    /// The step (s).
    #[wasm_bindgen(getter)]
    pub fn dt(&self) -> f32 {
        self.sim.world().config().dt
    }

    /// Simulated time (s).
    #[wasm_bindgen(getter)]
    pub fn time(&self) -> f64 {
        self.sim.world().time()
    }

    /// Steps run so far.
    #[wasm_bindgen(getter)]
    pub fn steps(&self) -> usize {
        self.sim.steps()
    }

    /// Whether its script has run to its end.
    #[wasm_bindgen(getter)]
    pub fn finished(&self) -> bool {
        self.sim.finished()
    }

    /// Up to `n` steps (a script stops at its end); returns the steps run.
    pub fn step(&mut self, n: usize) -> Result<usize, JsError> {
        js(self.sim.step(n))
    }

    /// A scenario's report (JSON, as `scenario --json` gives one), or
    /// `null`.
    pub fn report(&self) -> String {
        self.sim.report_json()
    }

    /// A recording's closings' verdicts (a JSON array), or `null`.
    pub fn verdicts(&self) -> String {
        self.sim.verdicts_json()
    }

    /// A recording's closings' verdicts, one line each as `coulomb-hands replay` prints them.
    #[wasm_bindgen(js_name = verdictLines)]
    pub fn verdict_lines(&self) -> Vec<String> {
        self.sim.verdict_lines()
    }

    /// A hand, `left` or `right`, untracked until posed; returns its id.
    #[wasm_bindgen(js_name = addHand)]
    pub fn add_hand(&mut self, side: &str) -> Result<u32, JsError> {
        Ok(self.sim.add_hand(js(sim::side(side))?))
    }

    /// How many hands the world has (a script's, then the page's).
    #[wasm_bindgen(js_name = handCount)]
    pub fn hand_count(&self) -> usize {
        self.sim.world().hand_count()
    }

    /// Poses a hand from WebXR's 25 joints, wrist first: positions (75
    /// numbers, m), radii (25) and, if given, orientations (100, x, y, z, w).
    #[wasm_bindgen(js_name = setHandWebxr)]
    pub fn set_hand_webxr(
        &mut self,
        hand: u32,
        positions: &[f32],
        radii: &[f32],
        orientations: Option<Vec<f32>>,
    ) -> Result<(), JsError> {
        js(self.sim.set_hand_webxr(hand, positions, radii, orientations.as_deref()))
    }

    /// Poses a hand's 16 bones from `poseStride()` numbers.
    #[wasm_bindgen(js_name = setHandPose)]
    pub fn set_hand_pose(&mut self, hand: u32, pose: &[f32]) -> Result<(), JsError> {
        js(self.sim.set_hand_pose(hand, pose))
    }

    /// Poses a hand as the rig's adult hand: palm centre (3), rotation (4),
    /// curl per finger (5, thumb first, 0 to 1), thumb opposition (0 to 1).
    #[wasm_bindgen(js_name = setHandRig)]
    pub fn set_hand_rig(
        &mut self,
        hand: u32,
        palm: &[f32],
        rotation: &[f32],
        curl: &[f32],
        opposition: f32,
    ) -> Result<(), JsError> {
        js(self.sim.set_hand_rig(hand, palm, rotation, curl, opposition))
    }

    /// Marks a hand untracked: its contacts end at the next step.
    #[wasm_bindgen(js_name = clearHand)]
    pub fn clear_hand(&mut self, hand: u32) -> Result<(), JsError> {
        js(self.sim.clear_hand(hand))
    }

    /// The hand that acts, as `poseStride()` numbers, or empty while
    /// untracked.
    #[wasm_bindgen(js_name = handPose)]
    pub fn hand_pose(&self, hand: u32) -> Result<Vec<f32>, JsError> {
        js(self.sim.hand_pose(hand))
    }

    /// A ground slab whose top is at `height` (m).
    #[wasm_bindgen(js_name = addGround)]
    pub fn add_ground(&mut self, height: f32, friction: f32) -> Result<(), JsError> {
        js(self.sim.add_ground(height, friction))
    }

    /// A box of full `size` (3, m) and `mass` (kg) at `position` (3),
    /// turned by `rotation` (4, or empty), of a material of the library's
    /// table (`wood`, `rubber` …); returns its id.
    #[wasm_bindgen(js_name = addBox)]
    pub fn add_box(
        &mut self,
        name: &str,
        size: &[f32],
        mass: f32,
        position: &[f32],
        rotation: &[f32],
        material: &str,
    ) -> Result<u32, JsError> {
        js(self.sim.add_box(name, size, mass, position, rotation, material))
    }

    /// A sphere of `radius` (m) and `mass` (kg) at `position`; returns its id.
    #[wasm_bindgen(js_name = addSphere)]
    pub fn add_sphere(
        &mut self,
        name: &str,
        radius: f32,
        mass: f32,
        position: &[f32],
        material: &str,
    ) -> Result<u32, JsError> {
        js(self.sim.add_sphere(name, radius, mass, position, material))
    }

    /// A mesh from an OBJ, STL, glTF or GLB file's bytes (`file` its name),
    /// scaled, filled with boxes of side `voxelSize` (m; undefined, the
    /// library's default, 5 mm); returns its id.
    #[wasm_bindgen(js_name = addMesh)]
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
    ) -> Result<u32, JsError> {
        let sim = &mut self.sim;
        js(sim.add_mesh(name, file, bytes, scale, voxel_size, mass, position, rotation, material))
    }

    /// A scene file's text added (ground, statics, objects, towers);
    /// returns the ids of the objects it added.
    #[wasm_bindgen(js_name = addScene)]
    pub fn add_scene(&mut self, file: &str, json: &str) -> Result<Vec<u32>, JsError> {
        js(self.sim.add_scene(file, json))
    }

    /// Puts an object at `position` and `rotation` (4, or empty), at rest.
    #[wasm_bindgen(js_name = placeObject)]
    pub fn place_object(
        &mut self,
        id: u32,
        position: &[f32],
        rotation: &[f32],
    ) -> Result<(), JsError> {
        js(self.sim.place_object(id, position, rotation))
    }

    /// Removes an object: what rested on it falls, its contacts end at the
    /// next step, and its id is not given again; its row of
    /// `objectStates()` is then NaN and its name empty.
    #[wasm_bindgen(js_name = removeObject)]
    pub fn remove_object(&mut self, id: u32) -> Result<(), JsError> {
        js(self.sim.remove_object(id))
    }

    /// How many objects were added, removed ones included; their ids are
    /// 0 to this.
    #[wasm_bindgen(js_name = objectCount)]
    pub fn object_count(&self) -> usize {
        self.sim.world().object_count()
    }

    /// The objects' names, by id; a removed object's is empty.
    #[wasm_bindgen(js_name = objectNames)]
    pub fn object_names(&self) -> Vec<String> {
        let world = self.sim.world();
        let name = |(id, _)| world.object_name(id).unwrap_or_default().to_string();
        world.object_slots().map(name).collect()
    }

    /// Every object's state, by id, `stateStride()` numbers each; a
    /// removed object's are NaN.
    #[wasm_bindgen(js_name = objectStates)]
    pub fn object_states(&self) -> Vec<f32> {
        arrays::states(self.sim.world().object_slots().map(|(_, state)| state))
    }

    /// An object's triangles in its own frame (9 numbers each).
    #[wasm_bindgen(js_name = objectMesh)]
    pub fn object_mesh(&self, id: u32) -> Result<Vec<f32>, JsError> {
        let found = shapes::object(self.sim.world(), ObjectId(id));
        js(found.ok_or_else(|| coulomb_hands::WorldError::NoSuchObject(ObjectId(id)).to_string()))
    }

    /// The static scenery's triangles in the world's frame (9 numbers each).
    #[wasm_bindgen(js_name = staticMesh)]
    pub fn static_mesh(&self) -> Vec<f32> {
        shapes::statics(self.sim.world())
    }

    /// The active contacts after the last step, `contactStride()` numbers
    /// each, ordered by (object, hand, bone).
    pub fn contacts(&self) -> Vec<f32> {
        arrays::contacts(self.sim.world().contacts())
    }

    /// The last step's contact events, `eventStride()` numbers each.
    pub fn events(&self) -> Vec<f64> {
        arrays::events(self.sim.world().events())
    }
}
