"""coulomb-hands from Python: tracked hands move virtual objects only through Coulomb
friction contact forces, on rapier3d. NumPy arrays in and out; every call is the Rust
library's own (see the book's "From Python" page)."""

from typing import TYPE_CHECKING

from ._coulomb_hands import (
    BONES,
    EVENT_KINDS,
    FRICTION_STATES,
    ArgumentError,
    BenchError,
    Config,
    ConfigError,
    CoulombHandsError,
    FileError,
    GraspObjectError,
    InputError,
    LayoutError,
    NoGraspError,
    NoSuchHandError,
    NoSuchObjectError,
    ObjectError,
    OutputError,
    PoseError,
    SessionError,
    ShapeError,
    SkeletonError,
    StudyError,
    UnknownMethodError,
    World,
    bench,
    eval_accuracy,
    load_mediapipe,
    load_recording,
    mediapipe_to_y_up,
    replay,
    replay_capture,
    run_scenario,
)

if TYPE_CHECKING:  # the arrays' dicts, typed in the stub only
    from ._coulomb_hands import Contacts as Contacts
    from ._coulomb_hands import Events as Events
    from ._coulomb_hands import HandPose as HandPose
    from ._coulomb_hands import ObjectStates as ObjectStates

__all__ = [
    "BONES",
    "EVENT_KINDS",
    "FRICTION_STATES",
    "ArgumentError",
    "BenchError",
    "Config",
    "ConfigError",
    "CoulombHandsError",
    "FileError",
    "GraspObjectError",
    "InputError",
    "LayoutError",
    "NoGraspError",
    "NoSuchHandError",
    "NoSuchObjectError",
    "ObjectError",
    "OutputError",
    "PoseError",
    "SessionError",
    "ShapeError",
    "SkeletonError",
    "StudyError",
    "UnknownMethodError",
    "World",
    "bench",
    "eval_accuracy",
    "load_mediapipe",
    "load_recording",
    "mediapipe_to_y_up",
    "replay",
    "replay_capture",
    "run_scenario",
]
