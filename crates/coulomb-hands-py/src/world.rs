//! `World`: an `InteractionWorld`, its calls one for one.

use crate::arrays::{self, points_array, quats_array, values_array};
use crate::config::Config;
use crate::values;
use crate::{ArgumentError, LayoutError, SkeletonError, world_error};
use coulomb_hands::hand::{HandPose, HandSample};
use coulomb_hands::input::layouts::{self, JointsError, Layout};
use coulomb_hands::run::bench;
use coulomb_hands::run::sampled::FrameHands;
use coulomb_hands::scene::mesh::TriangleMesh;
use coulomb_hands::scene::{MeshBody, MeshShape, Scene};
use coulomb_hands::{
    GammaMode, HandId, InteractionConfig, InteractionWorld, Material, ObjectDesc, ObjectError,
    ObjectId, ObjectState, ShapeDesc, Side, StaticDesc, WorldError,
};
use glam::{Quat, Vec3};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

/// Steps from which `step(n)` lets other Python threads run meanwhile.
const DETACHED_STEPS: usize = 8;

/// A world: rapier objects, and hands that move them only through
/// Coulomb friction contact forces.
#[pyclass(module = "coulomb_hands")]
pub struct World {
    world: InteractionWorld,
    /// The hands' poses on their way to the newest set (the core's rule
    /// for a hand posed once for several steps).
    hands: FrameHands,
}

/// `left` or `right`.
pub fn side(name: &str) -> PyResult<Side> {
    name.parse().map_err(|e| ArgumentError::new_err(format!("side: {e}")))
}

/// A material of the library's table by name.
fn material(object: &str, name: &str) -> PyResult<Material> {
    Material::by_name(name).map_err(|reason| {
        world_error(ObjectError { object: object.into(), field: "material".into(), reason }.into())
    })
}

/// A rotation, x, y, z, w, or none (unturned).
fn rotation(value: Option<&Bound<'_, PyAny>>) -> PyResult<Quat> {
    value.map_or(Ok(Quat::IDENTITY), |q| arrays::quat(q, "rotation"))
}

/// An object's own principal moments of inertia (kg·m²), if given; the
/// world checks them ([`ObjectDesc::inertia`]).
fn inertia(value: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Vec3>> {
    value.map(|i| arrays::vec3(i, "inertia")).transpose()
}

impl World {
    fn add(
        &mut self,
        desc: ObjectDesc,
        material_name: &str,
        own_gamma: Option<GammaMode>,
    ) -> PyResult<u32> {
        let material = material(&desc.name, material_name)?;
        let desc = ObjectDesc { gamma: own_gamma, ..desc.with_material(material) };
        Ok(self.world.add_object(&desc).map_err(world_error)?.0)
    }

    /// Hand `hand` posed at the next step or steps (lost for `None`); a
    /// bad hand or pose changes nothing.
    fn pose(&mut self, hand: u32, pose: Option<HandPose>) -> PyResult<()> {
        let sample = pose.map(HandSample::from_pose);
        self.hands.set(&mut self.world, HandId(hand), sample).map_err(world_error)
    }

    fn hand(&self, hand: u32) -> PyResult<Side> {
        self.world
            .hand_side(HandId(hand))
            .ok_or_else(|| world_error(WorldError::NoSuchHand(HandId(hand))))
    }
}

#[pymethods]
impl World {
    /// An empty world with `config` (the default config if none).
    #[new]
    #[pyo3(signature = (config = None))]
    fn new(config: Option<Config>) -> PyResult<Self> {
        let config = config.map_or_else(InteractionConfig::default, |c| *c.inner());
        let world = InteractionWorld::new(config).map_err(world_error)?;
        Ok(World { world, hands: FrameHands::default() })
    }

    /// The benchmark's reference scene (the CLI's `bench`): a ground, the
    /// 54-block tower unless `tower` is False, and `boxes` (1 to 16) 3 cm,
    /// 20 g boxes held mid-air, box k squeezed between bone k of the left
    /// hand (id 0) and of the right hand (id 1), both posed. With `awake`,
    /// rapier's sleeping is off, as under a moving hand.
    #[staticmethod]
    #[pyo3(signature = (boxes = 16, tower = true, awake = true))]
    fn reference_scene(boxes: usize, tower: bool, awake: bool) -> PyResult<Self> {
        let (mut world, _) =
            bench::held_boxes_scene(bench::bench_config(), boxes, tower).map_err(world_error)?;
        if awake {
            bench::keep_awake(&mut world);
        }
        Ok(World { world, hands: FrameHands::default() })
    }

    /// The settings the world was made with.
    #[getter]
    fn config(&self) -> PyResult<Config> {
        Config::new_checked(*self.world.config())
    }

    /// Simulated time (s).
    #[getter]
    fn time(&self) -> f64 {
        self.world.time()
    }

    /// A ground slab whose top face is at `height` (m).
    #[pyo3(signature = (height = 0.0, friction = 0.5))]
    fn add_ground(&mut self, height: f32, friction: f32) -> PyResult<()> {
        self.world.add_static(&StaticDesc::ground(height, friction)).map_err(world_error)?;
        Ok(())
    }

    /// A static box of full `size` (m) centred at `position` (m): scenery
    /// that objects rest on and hands pass through.
    #[pyo3(signature = (name, size, position, rotation = None, friction = 0.5))]
    fn add_static_box(
        &mut self,
        name: &str,
        size: &Bound<'_, PyAny>,
        position: &Bound<'_, PyAny>,
        rotation: Option<&Bound<'_, PyAny>>,
        friction: f32,
    ) -> PyResult<()> {
        let desc = StaticDesc {
            name: name.into(),
            shape: ShapeDesc::Box { half_extents: 0.5 * arrays::vec3(size, "size")? },
            position: arrays::vec3(position, "position")?,
            rotation: self::rotation(rotation)?,
            friction,
        };
        self.world.add_static(&desc).map_err(world_error)?;
        Ok(())
    }

    /// A box of full `size` (m) and `mass` (kg); returns its id.
    #[pyo3(signature = (
        name,
        size,
        mass,
        position,
        rotation = None,
        material = "wood",
        gamma = None,
        inertia = None,
    ))]
    #[allow(clippy::too_many_arguments)]
    fn add_box(
        &mut self,
        name: &str,
        size: &Bound<'_, PyAny>,
        mass: f32,
        position: &Bound<'_, PyAny>,
        rotation: Option<&Bound<'_, PyAny>>,
        material: &str,
        gamma: Option<&Bound<'_, PyAny>>,
        inertia: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<u32> {
        let size = arrays::vec3(size, "size")?;
        let desc = ObjectDesc {
            rotation: self::rotation(rotation)?,
            inertia: self::inertia(inertia)?,
            ..ObjectDesc::cuboid(name, size, mass, arrays::vec3(position, "position")?)
        };
        self.add(desc, material, gamma.map(values::gamma).transpose()?)
    }

    /// A sphere of `radius` (m) and `mass` (kg); returns its id.
    #[pyo3(signature = (
        name, radius, mass, position, material = "wood", gamma = None, inertia = None
    ))]
    #[allow(clippy::too_many_arguments)]
    fn add_sphere(
        &mut self,
        name: &str,
        radius: f32,
        mass: f32,
        position: &Bound<'_, PyAny>,
        material: &str,
        gamma: Option<&Bound<'_, PyAny>>,
        inertia: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<u32> {
        let at = arrays::vec3(position, "position")?;
        let desc = ObjectDesc {
            inertia: self::inertia(inertia)?,
            ..ObjectDesc::sphere(name, radius, mass, at)
        };
        self.add(desc, material, gamma.map(values::gamma).transpose()?)
    }

    /// A mesh from an OBJ, STL, glTF or GLB file, filled with boxes of side
    /// `voxel_size` (m), or else split into convex parts within
    /// `concavity`; returns its id.
    #[pyo3(signature = (
        name,
        path,
        mass,
        position,
        rotation = None,
        scale = 1.0,
        voxel_size = None,
        concavity = None,
        material = "wood",
        gamma = None,
    ))]
    #[allow(clippy::too_many_arguments)]
    fn add_mesh(
        &mut self,
        py: Python<'_>,
        name: &str,
        path: PathBuf,
        mass: f32,
        position: &Bound<'_, PyAny>,
        rotation: Option<&Bound<'_, PyAny>>,
        scale: f32,
        voxel_size: Option<f32>,
        concavity: Option<f32>,
        material: &str,
        gamma: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<u32> {
        let body = match (voxel_size, concavity) {
            (Some(size), None) => MeshBody::Voxels { size },
            (None, Some(concavity)) => MeshBody::ConvexParts { concavity },
            (None, None) => MeshBody::DEFAULT,
            (Some(_), Some(_)) => {
                return Err(ArgumentError::new_err("give voxel_size or concavity, not both"));
            }
        };
        let mesh = py
            .detach(|| TriangleMesh::load(&path))
            .map_err(|e| crate::FileError::new_err(e.to_string()))?;
        let file = path.display().to_string();
        let shape = MeshShape::new(file, scale, body, mesh);
        let at = arrays::vec3(position, "position")?;
        let rotation = self::rotation(rotation)?;
        let desc = ObjectDesc { rotation, ..ObjectDesc::mesh(name, shape, mass, at) };
        self.add(desc, material, gamma.map(values::gamma).transpose()?)
    }

    /// A scene file's ground, statics, objects and towers; returns the ids
    /// of the objects it added. (Its gravity belongs to the config:
    /// `Config(gravity=...)`.)
    fn add_scene(&mut self, py: Python<'_>, path: PathBuf) -> PyResult<Vec<u32>> {
        let scene = py
            .detach(|| Scene::load(&path))
            .map_err(|e| crate::FileError::new_err(e.to_string()))?;
        let first = self.world.object_count() as u32;
        self.world.add_scene(&scene).map_err(world_error)?;
        Ok((first..self.world.object_count() as u32).collect())
    }

    /// A hand, `left` or `right`, untracked until it is posed; returns its id.
    fn add_hand(&mut self, side: &str) -> PyResult<u32> {
        Ok(self.world.add_hand(self::side(side)?).0)
    }

    /// Poses a hand from tracked joints: an (N, 3) array in metres, y up,
    /// in `layout`'s order (openxr 26, webxr 25, mediapipe 21), with each
    /// joint's radius (N,) and orientation (N, 4), x, y, z, w, when the
    /// tracker gives them.
    #[pyo3(signature = (hand, joints, layout = "openxr", radii = None, orientations = None))]
    fn set_hand_joints(
        &mut self,
        hand: u32,
        joints: &Bound<'_, PyAny>,
        layout: &str,
        radii: Option<&Bound<'_, PyAny>>,
        orientations: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<()> {
        let side = self.hand(hand)?;
        let layout: Layout = layout
            .parse()
            .map_err(|e: layouts::UnknownLayout| LayoutError::new_err(e.to_string()))?;
        let n = Some(layout.count());
        let what = |arg: &str| format!("{arg} ({} layout)", layout.name());
        let positions: Vec<Vec3> = arrays::rows::<3>(joints, &what("joints"), n)?
            .into_iter()
            .map(Vec3::from_array)
            .collect();
        let radii = radii.map(|r| arrays::column(r, &what("radii"), n)).transpose()?;
        let orientations = orientations
            .map(|q| arrays::rows::<4>(q, &what("orientations"), n))
            .transpose()?
            .map(|qs| layouts::orientations(layout, &qs))
            .transpose()
            .map_err(|e| LayoutError::new_err(e.to_string()))?;
        let given = (radii.as_deref(), orientations.as_deref());
        let pose = layouts::hand_pose_from_joints(layout, hand, side, &positions, given.0, given.1)
            .map_err(|e| match e {
                JointsError::Layout(e) => LayoutError::new_err(e.to_string()),
                JointsError::Skeleton(e) => SkeletonError::new_err(e.to_string()),
                JointsError::Pose(e) => world_error(e.into()),
            })?;
        self.pose(hand, Some(pose))
    }

    /// Poses a hand's 16 bones directly: a dict of arrays as `hand_pose`
    /// returns.
    fn set_hand_pose(&mut self, hand: u32, pose: &Bound<'_, PyAny>) -> PyResult<()> {
        let pose = arrays::pose_from_dict(pose)?;
        self.pose(hand, Some(pose))
    }

    /// The hand that acts as a dict of arrays, or None if untracked: the
    /// pose its contacts saw in the last step, the tracked hand with the
    /// tracker's jitter taken out.
    fn hand_pose<'py>(&self, py: Python<'py>, hand: u32) -> PyResult<Option<Bound<'py, PyDict>>> {
        self.hand(hand)?;
        self.world.hand_pose(HandId(hand)).map(|p| arrays::pose_dict(py, p)).transpose()
    }

    /// The hand as the tracker gave it to the last step, or None if
    /// untracked.
    fn tracked_pose<'py>(
        &self,
        py: Python<'py>,
        hand: u32,
    ) -> PyResult<Option<Bound<'py, PyDict>>> {
        self.hand(hand)?;
        self.world.tracked_pose(HandId(hand)).map(|p| arrays::pose_dict(py, p)).transpose()
    }

    /// The tracker's jitter measured on the hand (m, rms per axis), or None
    /// without the config's tracking filter.
    fn hand_jitter(&self, hand: u32) -> PyResult<Option<f32>> {
        self.hand(hand)?;
        Ok(self.world.hand_jitter(HandId(hand)))
    }

    /// Marks a hand untracked: its contacts end at the next step.
    fn clear_hand(&mut self, hand: u32) -> PyResult<()> {
        self.hands.set(&mut self.world, HandId(hand), None).map_err(world_error)
    }

    /// `n` steps: each the hands' forces, then rapier's step. A hand posed
    /// since the last steps goes there in a straight line over these, from
    /// where it was, and is there at the last of them (posed before each
    /// single step, it is there at once; first seen, it is there at once).
    /// Long runs let other Python threads run meanwhile.
    #[pyo3(signature = (n = 1))]
    fn step(&mut self, py: Python<'_>, n: usize) -> PyResult<()> {
        let (world, hands) = (&mut self.world, &mut self.hands);
        let run = if n < DETACHED_STEPS {
            hands.step(world, n)
        } else {
            py.detach(|| hands.step(world, n))
        };
        run.map_err(world_error)
    }

    /// A step's first half: the hands posed, contacts found and updated,
    /// their forces given to rapier. Nothing has moved yet; add forces,
    /// then `step_physics()`.
    fn apply_hand_forces(&mut self) -> PyResult<()> {
        self.hands.begin(&self.world, 1);
        self.hands.pose(&mut self.world).map_err(world_error)?;
        self.world.apply_hand_forces();
        Ok(())
    }

    /// A step's second half: rapier's step.
    fn step_physics(&mut self) {
        self.world.step_physics();
    }

    /// The objects' names, by id (item i is object i's); a removed
    /// object's is None.
    fn object_names(&self) -> Vec<Option<String>> {
        let name = |(id, _)| self.world.object_name(id).map(String::from);
        self.world.object_slots().map(name).collect()
    }

    /// An object's mass (kg).
    fn object_mass(&self, id: u32) -> PyResult<f32> {
        self.world
            .object_mass(ObjectId(id))
            .ok_or_else(|| world_error(WorldError::NoSuchObject(ObjectId(id))))
    }

    /// An object's material: name, static_mu and dynamic_mu against skin,
    /// surface_friction against other objects.
    fn object_material<'py>(&self, py: Python<'py>, id: u32) -> PyResult<Bound<'py, PyDict>> {
        let m = self
            .world
            .object_material(ObjectId(id))
            .ok_or_else(|| world_error(WorldError::NoSuchObject(ObjectId(id))))?;
        let dict = PyDict::new(py);
        dict.set_item("name", &m.name)?;
        dict.set_item("static_mu", m.skin.static_mu)?;
        dict.set_item("dynamic_mu", m.skin.dynamic_mu)?;
        dict.set_item("surface_friction", m.surface_friction)?;
        Ok(dict)
    }

    /// Removes an object: what rested on it falls, its contacts end at the
    /// next step, and its id is not given again. Its row of
    /// [`Self::object_states`] is then NaN, its `present` False.
    fn remove_object(&mut self, id: u32) -> PyResult<()> {
        self.world.remove_object(ObjectId(id)).map_err(world_error)
    }

    /// Holds an object fixed (True) or lets it move again.
    fn set_object_locked(&mut self, id: u32, locked: bool) -> PyResult<()> {
        self.world.set_object_locked(ObjectId(id), locked).map_err(world_error)
    }

    /// Puts an object at `position` (m) and `rotation`, at rest.
    #[pyo3(signature = (id, position, rotation = None))]
    fn place_object(
        &mut self,
        id: u32,
        position: &Bound<'_, PyAny>,
        rotation: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<()> {
        let at = arrays::vec3(position, "position")?;
        self.world.place_object(ObjectId(id), at, self::rotation(rotation)?).map_err(world_error)
    }

    /// Every object's state, by id (row i is object i's), as arrays:
    /// `position` (n, 3) m, `rotation` (n, 4) x, y, z, w, `linvel` (n, 3)
    /// m/s, `angvel` (n, 3) rad/s, `hand_force` (n, 3) N (thesis
    /// Eq. 3.10), `sleeping` (n,), and `present` (n,): False for a removed
    /// object, whose row is NaN (and not sleeping).
    fn object_states<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let slots: Vec<Option<ObjectState>> = self.world.object_slots().map(|(_, s)| s).collect();
        let states: Vec<ObjectState> =
            slots.iter().map(|s| s.unwrap_or(ObjectState::REMOVED)).collect();
        let present = slots.iter().map(Option::is_some);
        let dict = PyDict::new(py);
        dict.set_item("position", points_array(py, states.iter().map(|s| s.position))?)?;
        dict.set_item("rotation", quats_array(py, states.iter().map(|s| s.rotation))?)?;
        dict.set_item("linvel", points_array(py, states.iter().map(|s| s.linvel))?)?;
        dict.set_item("angvel", points_array(py, states.iter().map(|s| s.angvel))?)?;
        dict.set_item("hand_force", points_array(py, states.iter().map(|s| s.hand_force))?)?;
        dict.set_item("sleeping", values_array(py, states.iter().map(|s| s.sleeping)))?;
        dict.set_item("present", values_array(py, present))?;
        Ok(dict)
    }

    /// The active contacts after the last step, ordered by (object, hand,
    /// bone), as arrays: `object`, `hand`, `bone` (n,) ids (`BONES` names a
    /// bone), `point` (n, 3) C on the surface, `normal` (n, 3),
    /// `bone_point` (n, 3) p, `depth` (n,) m, `force` (n, 3) N,
    /// `normal_force` (n,) N, `stiffness` (n,) N/m, `state` (n,) codes of
    /// `FRICTION_STATES`.
    fn contacts<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let c = self.world.contacts();
        let dict = PyDict::new(py);
        dict.set_item("object", values_array(py, c.iter().map(|c| c.object.0)))?;
        dict.set_item("hand", values_array(py, c.iter().map(|c| c.hand.0)))?;
        dict.set_item("bone", values_array(py, c.iter().map(|c| c.bone.index() as u32)))?;
        dict.set_item("point", points_array(py, c.iter().map(|c| c.point))?)?;
        dict.set_item("normal", points_array(py, c.iter().map(|c| c.normal))?)?;
        dict.set_item("bone_point", points_array(py, c.iter().map(|c| c.bone_point))?)?;
        dict.set_item("depth", values_array(py, c.iter().map(|c| f64::from(c.depth))))?;
        dict.set_item("force", points_array(py, c.iter().map(|c| c.force))?)?;
        dict.set_item(
            "normal_force",
            values_array(py, c.iter().map(|c| f64::from(c.normal_force))),
        )?;
        dict.set_item("stiffness", values_array(py, c.iter().map(|c| f64::from(c.stiffness))))?;
        dict.set_item("state", values_array(py, c.iter().map(|c| c.state.code())))?;
        Ok(dict)
    }

    /// The contact events of the last step, as arrays: `kind` (n,) codes of
    /// `EVENT_KINDS`, `object`, `hand`, `bone` (n,), `point` (n, 3) C,
    /// `time` (n,) s.
    fn events<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let e = self.world.events();
        let dict = PyDict::new(py);
        dict.set_item("kind", values_array(py, e.iter().map(|e| e.kind.code())))?;
        dict.set_item("object", values_array(py, e.iter().map(|e| e.object.0)))?;
        dict.set_item("hand", values_array(py, e.iter().map(|e| e.hand.0)))?;
        dict.set_item("bone", values_array(py, e.iter().map(|e| e.bone.index() as u32)))?;
        dict.set_item("point", points_array(py, e.iter().map(|e| e.point))?)?;
        dict.set_item("time", values_array(py, e.iter().map(|e| e.time)))?;
        Ok(dict)
    }
}
