"""Types of coulomb-hands' extension module; `coulomb_hands` re-exports all of it.

Units: metres, seconds, kilograms, newtons; the world is right-handed with y up.
Arrays in may be anything `numpy.asarray` takes; arrays out are float64 (the library's
f32 values, exactly) or integer ids.
"""

from os import PathLike
from typing import Any, Optional, Sequence, TypedDict, Union

import numpy as np
import numpy.typing as npt

ArrayLike = npt.ArrayLike
FloatArray = npt.NDArray[np.float64]
Path = Union[str, PathLike[str]]
Gamma = Union[float, str]

BONES: list[str]
"""The 16 bones' names by index: "palm", then "thumb proximal" ... "little distal"."""
FRICTION_STATES: list[str]
"""The codes of `World.contacts()["state"]`: "static", "dynamic", "separated"."""
EVENT_KINDS: list[str]
"""The codes of `World.events()["kind"]`: "began", "ended"."""

class HandPose(TypedDict):
    """A hand's 16 bones: the palm box and 15 finger capsules, thumb first, proximal
    first (`BONES[1:]`)."""

    palm_center: FloatArray
    """(3,) the palm box's centre."""
    palm_rotation: FloatArray
    """(4,) its orientation, x, y, z, w: +y out of the palm, +z towards the fingers."""
    palm_half_extents: FloatArray
    """(3,) half width, half thickness, half length."""
    capsule_a: FloatArray
    """(15, 3) each capsule's end nearer the palm."""
    capsule_b: FloatArray
    """(15, 3) each capsule's end nearer the fingertip."""
    capsule_radius: FloatArray
    """(15,) each capsule's radius."""

class ObjectStates(TypedDict):
    """Every object's state, row i for object id i."""

    position: FloatArray
    """(n, 3) body origin."""
    rotation: FloatArray
    """(n, 4) orientation, x, y, z, w."""
    linvel: FloatArray
    """(n, 3) linear velocity (m/s)."""
    angvel: FloatArray
    """(n, 3) angular velocity (rad/s)."""
    hand_force: FloatArray
    """(n, 3) the hand contacts' total force in the last step (N), thesis Eq. 3.10."""
    sleeping: npt.NDArray[np.bool_]
    """(n,) whether rapier put it to sleep."""
    present: npt.NDArray[np.bool_]
    """(n,) False for a removed object, whose row is NaN."""

class Contacts(TypedDict):
    """The active contacts, one row each, ordered by (object, hand, bone)."""

    object: npt.NDArray[np.uint32]
    hand: npt.NDArray[np.uint32]
    bone: npt.NDArray[np.uint32]
    """(n,) the bone, an index into `BONES`."""
    point: FloatArray
    """(n, 3) the contact point C on the object's surface."""
    normal: FloatArray
    """(n, 3) the contact normal at C."""
    bone_point: FloatArray
    """(n, 3) the bone's point p that pushes into the object."""
    depth: FloatArray
    """(n,) penetration of p below C (m); negative while hovering."""
    force: FloatArray
    """(n, 3) the force on the object in the last step (N)."""
    normal_force: FloatArray
    """(n,) its normal magnitude (N)."""
    stiffness: FloatArray
    """(n,) the contact stiffness gamma used (N/m)."""
    state: npt.NDArray[np.uint8]
    """(n,) an index into `FRICTION_STATES`."""

class Events(TypedDict):
    """The contact events of the last step, one row each."""

    kind: npt.NDArray[np.uint8]
    """(n,) an index into `EVENT_KINDS`."""
    object: npt.NDArray[np.uint32]
    hand: npt.NDArray[np.uint32]
    bone: npt.NDArray[np.uint32]
    point: FloatArray
    """(n, 3) the contact point C at that moment."""
    time: FloatArray
    """(n,) simulation time of the step (s)."""

class Config:
    """A world's settings: `InteractionConfig`'s fields with the names and values of
    config files (the book's config page), e.g. `Config(dt=0.002, gamma="auto")` or
    `Config(gamma=300.0, patch={"samples": 5, ...})`; `gamma` is spelled as everywhere in
    the package, "auto" or a number of N/m (a config file's "Auto" and {"Fixed": 300.0} are
    read too). Checked as the library
    checks them: a bad, mistyped or unknown field raises `ConfigError` naming it, and a
    rejected change leaves the config as it was."""

    dt: float
    gravity: list[float]
    contact_offset: float
    release_offset: float
    gamma: Gamma
    kinetic: str
    patch: dict[str, Any]
    damping_ratio: Optional[float]
    virtual_fingers: bool
    force_cap: bool
    max_penetration_speed: Optional[float]
    probe_offset: float
    contact_frequency: float
    object_friction: str
    engine_substeps: int
    deviation_springs: bool
    slip_recentre: bool
    line_contacts: bool
    rolling: bool
    stribeck_speed: Optional[float]
    stability_limit: bool
    step_aware: bool
    grab: Optional[str]
    hand_friction: bool
    tracking: Optional[dict[str, Any]]
    def __init__(self, **fields: Any) -> None:
        """The default config with `fields` changed."""
    @staticmethod
    def for_method(method: str) -> Config:
        """A method's config: "coulomb" (the default), "thesis", "kinematic" or
        "heuristic"."""
    def to_dict(self) -> dict[str, Any]:
        """Every field and its value, as in a config file."""
    def replace(self, **fields: Any) -> Config:
        """A copy with `fields` changed."""

class World:
    """A rapier world whose objects tracked hands move only through Coulomb friction
    contact forces. Ids of objects and hands are ints from 0, in the order added."""

    def __init__(self, config: Optional[Config] = None) -> None:
        """An empty world with `config`, or the default config."""
    @staticmethod
    def reference_scene(boxes: int = 16, tower: bool = True, awake: bool = True) -> World:
        """The benchmark's reference scene (`coulomb-hands bench`): a ground, the 54-block
        tower unless `tower` is False, and `boxes` (1 to 16) 3 cm, 20 g boxes held
        mid-air, box k squeezed between bone k of the left hand (id 0) and of the right
        hand (id 1). With `awake`, rapier's sleeping is off, as under a moving hand."""
    @property
    def config(self) -> Config:
        """The settings the world was made with."""
    @property
    def time(self) -> float:
        """Simulated time (s)."""
    def add_ground(self, height: float = 0.0, friction: float = 0.5) -> None:
        """A ground slab whose top face is at `height`."""
    def add_static_box(
        self,
        name: str,
        size: ArrayLike,
        position: ArrayLike,
        rotation: Optional[ArrayLike] = None,
        friction: float = 0.5,
    ) -> None:
        """A static box of full `size` (3,) centred at `position` (3,): scenery that
        objects rest on and hands pass through."""
    def add_box(
        self,
        name: str,
        size: ArrayLike,
        mass: float,
        position: ArrayLike,
        rotation: Optional[ArrayLike] = None,
        material: str = "wood",
        gamma: Optional[Gamma] = None,
        inertia: Optional[ArrayLike] = None,
    ) -> int:
        """A box of full `size` (3,) and `mass` at `position` (3,), turned by
        `rotation` (4,) x, y, z, w, of a material of the library's table, with its own
        contact stiffness `gamma` (N/m, or "auto") if given, and its own principal
        moments of inertia `inertia` (3,) about its centre, along its axes (kg·m²), if
        its mass is not spread evenly; returns its id."""
    def add_sphere(
        self,
        name: str,
        radius: float,
        mass: float,
        position: ArrayLike,
        material: str = "wood",
        gamma: Optional[Gamma] = None,
        inertia: Optional[ArrayLike] = None,
    ) -> int:
        """A sphere of `radius` and `mass` centred at `position` (3,), with its own
        principal moments of inertia `inertia` (3,) if not solid (a hollow ball's
        2/3·m·r² each); returns its id."""
    def add_mesh(
        self,
        name: str,
        path: Path,
        mass: float,
        position: ArrayLike,
        rotation: Optional[ArrayLike] = None,
        scale: float = 1.0,
        voxel_size: Optional[float] = None,
        concavity: Optional[float] = None,
        material: str = "wood",
        gamma: Optional[Gamma] = None,
    ) -> int:
        """A mesh from an OBJ, STL, glTF or GLB file, its coordinates times `scale`,
        filled with boxes of side `voxel_size` (default 5 mm), or else split into convex
        parts within `concavity`; returns its id. A bad file raises `FileError`."""
    def add_scene(self, path: Path) -> list[int]:
        """A scene file's ground, statics, objects and towers; returns the ids of the
        objects added. Its gravity belongs to the config."""
    def add_hand(self, side: str) -> int:
        """A hand, "left" or "right", untracked until posed; returns its id."""
    def set_hand_joints(
        self,
        hand: int,
        joints: ArrayLike,
        layout: str = "openxr",
        radii: Optional[ArrayLike] = None,
        orientations: Optional[ArrayLike] = None,
    ) -> None:
        """Poses a hand from tracked joints: (N, 3) positions in metres, y up, in
        `layout`'s order ("openxr" 26 joints, "webxr" 25, "mediapipe" 21 world
        landmarks, already turned y up), with each joint's radius (N,) and orientation
        (N, 4), x, y, z, w, when the tracker gives them (not for MediaPipe). As a joint
        recording's hand is posed. A wrong shape raises `ShapeError`; a joint that is not
        finite, or an unknown layout, `LayoutError`; the world is left as it was."""
    def set_hand_pose(self, hand: int, pose: HandPose) -> None:
        """Poses a hand's 16 bones directly. A bad pose raises `PoseError` naming the
        bone, and changes nothing."""
    def hand_pose(self, hand: int) -> Optional[HandPose]:
        """The hand that acts, or None while untracked: the pose its contacts saw in the
        last step (the pose set, for a hand tracked since), the tracked hand with the
        tracker's jitter taken out by `config.tracking`."""
    def tracked_pose(self, hand: int) -> Optional[HandPose]:
        """The hand as the tracker gave it to the last step, or None while untracked."""
    def hand_jitter(self, hand: int) -> Optional[float]:
        """The jitter measured on the hand (m, rms per axis, the hand's own tremor of
        about 30 µm included; 0 until measured), or None when `config.tracking` is None."""
    def clear_hand(self, hand: int) -> None:
        """Marks a hand untracked: its contacts end at the next step."""
    def step(self, n: int = 1) -> None:
        """`n` steps of `config.dt`, each the hands' forces then rapier's step. A hand
        posed since the last steps goes there in a straight line over these, from where
        it was, and is there at the last of them (posed before each single step, or
        first seen, it is there at once). Other Python threads run meanwhile when `n` is
        8 or more."""
    def apply_hand_forces(self) -> None:
        """A step's first half: the hands posed, contacts found and updated, their forces
        given to rapier, nothing moved yet."""
    def step_physics(self) -> None:
        """A step's second half: rapier's step."""
    def object_names(self) -> list[Optional[str]]:
        """The objects' names, by id (item i is object i's); a removed object's is None."""
    def object_mass(self, id: int) -> float:
        """An object's mass (kg)."""
    def object_material(self, id: int) -> dict[str, Any]:
        """An object's material: name, static_mu and dynamic_mu against skin,
        surface_friction against other objects."""
    def remove_object(self, id: int) -> None:
        """Removes an object: what rested on it falls, its contacts end at the next step,
        and its id is not given again; its row of `object_states()` is then NaN."""
    def set_object_locked(self, id: int, locked: bool) -> None:
        """Holds an object fixed in place (True) or lets it move again."""
    def place_object(
        self, id: int, position: ArrayLike, rotation: Optional[ArrayLike] = None
    ) -> None:
        """Puts an object at `position`, turned by `rotation`, at rest."""
    def object_states(self) -> ObjectStates:
        """Every object's state, as arrays."""
    def contacts(self) -> Contacts:
        """The active contacts after the last step, as arrays."""
    def events(self) -> Events:
        """The contact events of the last step, as arrays."""

def replay(
    path: Path,
    *,
    device: Optional[ArrayLike] = None,
    grace: Optional[float] = None,
    scene: Optional[Path] = None,
    gamma: Optional[Gamma] = None,
    method: str = "coulomb",
    object_at_grasp: Optional[str] = None,
) -> dict[str, Any]:
    """Replays a recording (Leap Motion, or a joint recording) or a recorded session
    headlessly, as `coulomb-hands replay FILE --json` does with the same options
    (`object_at_grasp` as "box:0.045:0.05"); returns its JSON's data."""

def replay_capture(
    path: Path,
    *,
    method: str = "coulomb",
    mass: Optional[Union[float, Sequence[float]]] = None,
    material: Optional[Union[str, Sequence[str]]] = None,
    gamma: Optional[Gamma] = None,
    hand_surface: str = "exact",
) -> dict[str, Any]:
    """Replays a hand-object capture (its object at its first captured pose, moved by the
    captured hand through contacts alone) once for every material and mass (kg) given, 0.3
    kg and wood when None, as `coulomb-hands replay CAPTURE --mass ... --material ...
    --hand-surface ... --json` does; returns its JSON's data, {"capture": {...}, "replays":
    [...]}, materials outermost. The hand touches the mesh's own surface where the mesh is
    closed ("exact"), or the convex parts the engine moves ("body"). A mass that is not
    positive or an unknown material raises `StudyError`; a surface neither "exact" nor
    "body" raises `ArgumentError`."""

def run_scenario(name_or_path: str, method: str = "coulomb") -> dict[str, Any]:
    """Runs a shipped scenario by name (e.g. "push") or a scenario file; returns
    `coulomb-hands scenario NAME --json`'s data, {"scenarios": [report]}."""

def eval_accuracy(
    *,
    users: int = 6,
    trials: int = 20,
    seed: int = 1,
    methods: Optional[Sequence[str]] = None,
    strategies: Optional[Sequence[str]] = None,
    noise: float = 1.0,
    noise_mm: Optional[float] = None,
    perception: float = 1.0,
    noise_from: Optional[Sequence[Path]] = None,
    noise_white: Optional[float] = None,
    threads: Optional[int] = None,
) -> dict[str, Any]:
    """The positioning-accuracy study (thesis 5.2); returns `coulomb-hands eval
    accuracy --json`'s data. `noise` scales the recordings' tracking noise;
    `noise_mm`, instead, sets its rms per joint and axis (mm). `noise_white`, a
    tracker's frame rate (Hz), draws white noise instead of the recordings'."""

def bench(
    *,
    steps: int = 5000,
    boxes: int = 16,
    tower: bool = True,
    mujoco: Optional[Path] = None,
    objects: Sequence[int] = (70, 250, 500, 1000, 2000),
) -> dict[str, Any]:
    """The performance analysis (thesis 5.3); returns `coulomb-hands bench --json`'s
    data. With `mujoco`, the Python with pip's mujoco that times MuJoCo's step;
    `objects`, the cluttered scenes' object counts (16 to 4000 each; empty for none)."""

def load_recording(path: Path, device: Optional[ArrayLike] = None) -> list[dict[str, Any]]:
    """A recording's frames as the library loads them, its origin at `device`: a list of
    {"t": s, "hands": [{"id", "side", "pose"}]}, each pose a `HandPose`."""

def load_mediapipe(path: Path, label: str = "subject") -> dict[str, Any]:
    """A MediaPipe hand landmarker result (.pbtxt) as the library reads it: "side", from
    its label read as `label` says ("subject": the subject's own hand; "mirrored": as
    MediaPipe Hands and MediaPipe's test data label hands), and "joints", its 21 world
    landmarks (21, 3) in metres turned y up, for `World.set_hand_joints(..., "mediapipe")`."""

def mediapipe_to_y_up(landmarks: ArrayLike) -> FloatArray:
    """MediaPipe world landmarks (n, 3), whose y points down, turned y up (180 degrees
    about x), as the library turns them."""

class CoulombHandsError(Exception):
    """Any error of coulomb-hands; each library error kind is a subclass, with the
    library's message."""

class ConfigError(CoulombHandsError):
    """A config field was rejected."""

class PoseError(CoulombHandsError):
    """A hand pose was rejected; names the hand and the bone."""

class ObjectError(CoulombHandsError):
    """An object or static description was rejected; names the object and the field."""

class NoSuchHandError(CoulombHandsError):
    """No hand has this id."""

class NoSuchObjectError(CoulombHandsError):
    """No object has this id."""

class InputError(CoulombHandsError):
    """Tracking input was bad or unreadable; names the file, the frame and the field."""

class LayoutError(CoulombHandsError):
    """A joint set could not become a hand: an unknown layout, a joint not finite."""

class SkeletonError(CoulombHandsError):
    """Tracked joints could not become the 16-bone hand."""

class FileError(CoulombHandsError):
    """A scene, scenario or mesh file was bad or unreadable; names the file."""

class SessionError(CoulombHandsError):
    """A session file could not be read, written or replayed."""

class OutputError(CoulombHandsError):
    """Writing an output failed."""

class StudyError(CoulombHandsError):
    """A study's option is out of range."""

class NoGraspError(CoulombHandsError):
    """An object was asked for at a grasp the recording does not have."""

class GraspObjectError(CoulombHandsError):
    """An object_at_grasp text is not SHAPE:SIZE_M:MASS_KG."""

class UnknownMethodError(CoulombHandsError):
    """A method name is not coulomb, thesis, kinematic or heuristic."""

class BenchError(CoulombHandsError):
    """A bench run failed."""

class ShapeError(CoulombHandsError):
    """An array argument has the wrong shape or is not numbers; names the argument."""

class ArgumentError(CoulombHandsError):
    """An argument is not one the call knows (a side, a material, a strategy)."""
