"""Error paths: each bad input raises its own exception, naming the problem, and a
world that refused a call goes on as if it had never been made."""

from __future__ import annotations

import math
from typing import Any, Callable

import numpy as np
import pytest
import coulomb_hands as ch
from conftest import REPO, far_hand


def raises(kind: type[Exception], call: Callable[[], Any], *words: str) -> None:
    with pytest.raises(kind) as error:
        call()
    for word in words:
        assert word in str(error.value), (word, str(error.value))


def test_wrong_shapes_raise_shape_errors_naming_the_argument() -> None:
    world = ch.World()
    hand = world.add_hand("left")
    raises(ch.ShapeError, lambda: world.set_hand_joints(hand, np.zeros((25, 3))), "joints", "(26, 3)", "(25, 3)")
    raises(ch.ShapeError, lambda: world.set_hand_joints(hand, np.zeros(63), "mediapipe"), "(21, 3)", "(63,)")
    raises(ch.ShapeError, lambda: world.set_hand_joints(hand, np.zeros((21, 3)), "mediapipe", radii=np.zeros(20)), "radii")
    raises(ch.ShapeError, lambda: world.set_hand_joints(hand, [["a", "b", "c"]] * 26), "joints", "numbers")
    raises(ch.ShapeError, lambda: world.add_box("b", [0.1, 0.1], 1.0, [0, 0, 0]), "size", "(3,)")
    pose = far_hand()
    pose["capsule_a"] = pose["capsule_a"][:14]
    raises(ch.ShapeError, lambda: world.set_hand_pose(hand, pose), "capsule_a", "(15, 3)")


def test_a_rotation_is_made_a_unit_quaternion_as_every_binding_makes_it() -> None:
    world = ch.World()
    half_turn = math.sqrt(0.5)
    # 3 times a quarter turn about y: taken as the quarter turn, as C and the page take it.
    box = world.add_box("b", [0.1, 0.2, 0.3], 1.0, [0, 1, 0], rotation=[0, 3 * half_turn, 0, 3 * half_turn])
    turned = world.object_states()["rotation"][box]
    assert np.allclose(turned, [0, half_turn, 0, half_turn], atol=1e-6), turned
    raises(ch.ShapeError, lambda: world.add_box("z", [0.1] * 3, 1.0, [0, 1, 0], rotation=[0, 0, 0, 0]),
           "rotation", "zero-length")
    assert world.object_names() == ["b"]


def test_nan_is_named_where_it_is() -> None:
    world = ch.World()
    hand = world.add_hand("right")
    joints = np.zeros((26, 3))
    joints[11, 2] = np.nan
    raises(ch.LayoutError, lambda: world.set_hand_joints(hand, joints), "openxr joint 11", "not finite")
    pose = far_hand()
    pose["capsule_b"][7, 0] = np.inf
    raises(ch.PoseError, lambda: world.set_hand_pose(hand, pose), "middle")
    raises(ch.ObjectError, lambda: world.add_box("crate", [0.1, np.nan, 0.1], 1.0, [0, 1, 0]), "crate", "half_extents")
    odd = [1e-4, 1e-4, 3e-4]  # no body has a moment above the other two together
    raises(ch.ObjectError, lambda: world.add_sphere("ball", 0.05, 0.2, [0, 1, 0], inertia=odd), "ball", "inertia")
    raises(ch.ShapeError, lambda: world.add_box("b", [0.1] * 3, 1.0, [0, 1, 0], inertia=[1e-4] * 2), "inertia", "(3,)")
    raises(ch.ConfigError, lambda: ch.Config(contact_offset=float("nan")), "contact_offset")
    config = ch.Config()
    raises(ch.ConfigError, lambda: setattr(config, "dt", -0.001), "dt")
    assert config.dt == 0.001  # the rejected change left it as it was
    raises(ch.ConfigError, lambda: ch.Config(gama=400), "gama")


def test_unknown_names_raise_their_own_errors() -> None:
    world = ch.World()
    hand = world.add_hand("left")
    raises(ch.LayoutError, lambda: world.set_hand_joints(hand, np.zeros((21, 3)), "leap"), "unknown layout", "leap")
    raises(ch.ArgumentError, lambda: world.add_hand("middle"), "side")
    raises(ch.ObjectError, lambda: world.add_box("b", [0.1] * 3, 1.0, [0, 0, 0], material="cheese"), "cheese")
    raises(ch.UnknownMethodError, lambda: ch.run_scenario("push", method="magnet"), "magnet")
    raises(ch.NoSuchHandError, lambda: world.set_hand_joints(7, np.zeros((26, 3))), "7")
    raises(ch.NoSuchObjectError, lambda: world.object_mass(3), "3")


def test_missing_files_raise_errors_naming_them(tmp_path: Any) -> None:
    missing = tmp_path / "nowhere.json"
    world = ch.World()
    raises(ch.InputError, lambda: ch.replay(missing), "nowhere.json")
    raises(ch.InputError, lambda: ch.load_recording(missing), "nowhere.json")
    raises(ch.FileError, lambda: world.add_scene(missing), "nowhere.json")
    raises(ch.FileError, lambda: world.add_mesh("m", tmp_path / "m.obj", 0.1, [0, 0, 0]), "m.obj")
    raises(ch.FileError, lambda: ch.run_scenario(str(missing)), "nowhere.json")
    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"format":"coulomb-hands-joints","version":1}\n{"t": 0, "hands": 3}\n')
    raises(ch.InputError, lambda: ch.replay(bad), "bad.jsonl", "frame 0", "hands")


def test_a_capture_replay_names_a_missing_file_a_bad_mass_and_an_unknown_material(tmp_path: Any) -> None:
    capture = REPO / "data" / "taco" / "taco_20231104_017.json"
    missing = tmp_path / "nowhere.json"
    raises(ch.InputError, lambda: ch.replay_capture(missing), str(missing))
    raises(ch.StudyError, lambda: ch.replay_capture(capture, mass=-1), "mass", "-1 kg")
    raises(ch.StudyError, lambda: ch.replay_capture(capture, mass=[0.3, 0.0]), "mass", "0 kg")
    raises(ch.StudyError, lambda: ch.replay_capture(capture, material="unobtainium"), "unobtainium", "known", "wood", "rubber")
    raises(ch.ShapeError, lambda: ch.replay_capture(capture, mass="heavy"), "mass")
    raises(ch.ArgumentError, lambda: ch.replay_capture(capture, material=["wood", 3]), "material")
    raises(ch.ArgumentError, lambda: ch.replay_capture(capture, hand_surface="skin"), "hand_surface", "exact", "body", "skin")


def test_a_world_goes_on_after_an_error_as_if_it_had_not_been() -> None:
    def world() -> tuple[ch.World, int]:
        w = ch.World()
        w.add_ground()
        w.add_box("cube", [0.036] * 3, 0.061, [0.0, 0.03, 0.0])
        return w, w.add_hand("right")

    fist = ch.load_mediapipe(REPO / "data" / "mediapipe" / "fist_landmarks.pbtxt", "mirrored")
    landmarks = fist["joints"] + [0.0, 0.09, 0.0]  # the fist just above the cube
    clean, hand = world()
    failed, hand = world()
    bad = landmarks.copy()
    bad[4, 0] = np.nan
    for w in (clean, failed):
        w.set_hand_joints(hand, landmarks, "mediapipe")
        w.step(50)
    raises(ch.LayoutError, lambda: failed.set_hand_joints(hand, bad, "mediapipe"))
    raises(ch.ShapeError, lambda: failed.set_hand_joints(hand, landmarks[:20], "mediapipe"))
    raises(ch.ObjectError, lambda: failed.add_box("x", [0.1, 0.1, -0.1], 1.0, [0, 1, 0]))
    for w in (clean, failed):
        w.set_hand_joints(hand, landmarks, "mediapipe")
        w.step(250)
    a, b = clean.object_states(), failed.object_states()
    assert failed.object_names() == ["cube"]
    for key in ("position", "rotation", "linvel"):
        assert np.array_equal(a[key], b[key]), key
    assert np.array_equal(clean.contacts()["force"], failed.contacts()["force"])
    # The fist came down on the cube and pushed it aside, in both worlds alike.
    assert np.linalg.norm(b["position"][0] - [0.0, 0.03, 0.0]) > 0.02
