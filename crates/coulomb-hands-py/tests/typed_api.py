"""The package used as a typed program would use it: `test_types.py` checks this file,
the example and the benchmark with `mypy --strict` against the stub, and runs it."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import numpy as np
import numpy.typing as npt
import coulomb_hands as ch

REPO = Path(__file__).resolve().parents[3]


def tracked_fist(world: ch.World, hand: int) -> npt.NDArray[np.float64]:
    fist = ch.load_mediapipe(REPO / "data" / "mediapipe" / "fist_landmarks.pbtxt", "mirrored")
    joints: npt.NDArray[np.float64] = fist["joints"] + np.array([0.0, 0.2, 0.0])
    world.set_hand_joints(hand, joints, layout="mediapipe")
    return joints


def run() -> float:
    config: ch.Config = ch.Config(dt=0.001, gamma=380.0).replace(force_cap=True)
    assert config.to_dict()["gamma"] == 380.0 and config.gamma == 380.0
    assert ch.Config(gamma={"Fixed": 380.0}).gamma == 380.0
    assert ch.Config(gamma="Auto").gamma == ch.Config(gamma="auto").gamma == "auto"
    assert ch.Config.for_method("thesis").kinetic == "Thesis"
    world = ch.World(config)
    world.add_ground(0.0, 0.5)
    world.add_static_box("shelf", [0.3, 0.02, 0.2], [0.5, 0.1, 0.0])
    cube: int = world.add_box("cube", [0.05, 0.05, 0.05], 0.05, [0.0, 0.025, 0.0])
    ball = world.add_sphere("ball", 0.02, 0.03, [0.1, 0.02, 0.0], material="rubber")
    hand = world.add_hand("right")
    tracked_fist(world, hand)
    pose: Optional[ch.HandPose] = world.hand_pose(hand)
    assert pose is not None
    tracked: Optional[ch.HandPose] = world.tracked_pose(hand)
    assert tracked is not None
    jitter: Optional[float] = world.hand_jitter(hand)
    assert jitter == 0.0
    world.set_hand_pose(hand, pose)
    world.step(5)
    world.apply_hand_forces()
    world.step_physics()
    world.clear_hand(hand)
    states: ch.ObjectStates = world.object_states()
    contacts: ch.Contacts = world.contacts()
    events: ch.Events = world.events()
    assert states["position"].shape == (2, 3) and contacts["point"].shape[1] == 3
    assert events["kind"].dtype == np.uint8
    assert world.object_names() == ["cube", "ball"] and ball == 1
    assert ch.BONES[0] == "palm" and ch.FRICTION_STATES[0] == "static"
    try:
        world.set_hand_joints(hand, np.zeros((3, 3)))
    except ch.ShapeError as e:
        assert "joints" in str(e)
    world.place_object(cube, [0.0, 0.1, 0.0])
    world.set_object_locked(cube, False)
    world.remove_object(ball)
    names: list[Optional[str]] = world.object_names()
    assert names == ["cube", None] and not world.object_states()["present"][ball]
    return world.time
