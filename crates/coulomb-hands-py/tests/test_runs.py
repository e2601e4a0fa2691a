"""The library's loaders and runs through the package: a joint recording's OpenXR
joints pose the hand the Rust loader poses, and a replay's data serialises to the CLI's
--json text byte for byte."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path
from typing import Callable, TypeVar

import numpy as np
import pytest
import coulomb_hands as ch
from conftest import REPO

RECORDING = REPO / "data" / "joints" / "pinch-57fps.jsonl"
T = TypeVar("T")


def test_openxr_joints_of_a_recording_pose_the_hand_the_rust_loader_poses() -> None:
    loaded = ch.load_recording(RECORDING)
    lines = RECORDING.read_text().splitlines()[1:]
    assert len(loaded) == len(lines) == 133
    world = ch.World()
    hands: dict[str, int] = {}
    compared = 0
    for line, frame in zip(lines, loaded):
        tracked = json.loads(line)["hands"]
        assert len(tracked) == len(frame["hands"])
        for hand, expected in zip(tracked, frame["hands"]):
            assert hand["layout"] == "openxr"
            side = hand["side"]
            if side not in hands:
                hands[side] = world.add_hand(side)
            world.set_hand_joints(
                hands[side],
                np.array(hand["joints"]),
                "openxr",
                radii=np.array(hand["radii"]),
                orientations=np.array(hand["orientations"]),
            )
            # Posed before a single step, the hand is given to it as set.
            world.step()
            pose = world.tracked_pose(hands[side])
            assert pose is not None
            for key, value in expected["pose"].items():
                assert np.array_equal(pose[key], value), key  # type: ignore[literal-required]
            compared += 1
    assert compared == 133
    # The hand pinches: its thumb and index tips close to within 3 cm at some frame.
    tips = [f["hands"][0]["pose"] for f in loaded if f["hands"]]
    gaps = [np.linalg.norm(p["capsule_b"][2] - p["capsule_b"][5]) for p in tips]
    assert min(gaps) < 0.03 < max(gaps)


def cli() -> Path:
    """The CLI the workspace built: $COULOMB_HANDS_BIN, or target/debug's or
    target/release's."""
    given = os.environ.get("COULOMB_HANDS_BIN")
    candidates = [Path(given)] if given else []
    candidates += [REPO / "target" / p / "coulomb-hands" for p in ("debug", "release")]
    for path in candidates:
        if path.is_file():
            return path
    pytest.fail("no coulomb-hands binary: build it with `cargo build` or set COULOMB_HANDS_BIN")


def cli_json(*args: str) -> str:
    """The binary's `--json` output for `args`, run in the repository."""
    command = [str(cli()), *args, "--json"]
    return subprocess.run(command, cwd=REPO, capture_output=True, text=True, check=True).stdout


def in_repo(call: Callable[[], T]) -> T:
    """`call()` with the repository as the working directory, as the CLI runs."""
    cwd = os.getcwd()
    os.chdir(REPO)
    try:
        return call()
    finally:
        os.chdir(cwd)


def test_a_replay_from_python_is_the_cli_json_byte_for_byte() -> None:
    recording = "data/leap/pinch.json.lz"
    args = ["--object-at-grasp", "box:0.038:0.045", "--gamma", "330", "--grace", "0.12"]
    out = cli_json("replay", recording, *args)
    data = in_repo(
        lambda: ch.replay(recording, object_at_grasp="box:0.038:0.045", gamma=330.0, grace=0.12)
    )
    assert json.dumps(data, indent=2, ensure_ascii=False) + "\n" == out
    # And the run did something: the box put at the closing settled in the grip with
    # under 2 cm of drift, then fell when the hand opened.
    (closing,) = data["closings"]
    assert closing["settled_at"] is not None and closing["slipped_at"] is None
    assert closing["drift"] < 0.02 and closing["released"]
    assert data["all_finite"]


def test_a_capture_replay_from_python_is_the_cli_json() -> None:
    capture = "data/taco/taco_20231104_017.json"
    args = ["--mass", "0.1,0.6", "--material", "wood"]
    out = cli_json("replay", capture, *args)
    data = in_repo(lambda: ch.replay_capture(capture, mass=[0.1, 0.6], material="wood"))
    # The same data; not the same text, as Python writes 4.5e-05 where serde_json
    # writes 0.000045.
    assert json.loads(json.dumps(data)) == json.loads(out)
    assert data["capture"]["frames"] == 146
    replays = data["replays"]
    assert [(r["material"], round(r["mass_kg"], 6)) for r in replays] == [("wood", 0.1), ("wood", 0.6)]
    assert [len(r["frames"]) for r in replays] == [146, 146]
    # Each starts at the first captured pose (row-major 4x4: its translation is
    # elements 3, 7 and 11), in the capture's own frame and units.
    pose = json.loads((REPO / capture).read_text())["object"]["poses"][0]
    for r in replays:
        assert np.allclose(r["frames"][0]["position"], [pose[3], pose[7], pose[11]], rtol=0, atol=1e-5)
        assert r["score"]["all_finite"]


def accuracy_json(args: list[str]) -> str:
    """What `coulomb-hands eval accuracy --json ARGS` prints."""
    return subprocess.run(
        [str(cli()), "eval", "accuracy", "--json", *args],
        cwd=REPO,
        capture_output=True,
        text=True,
        check=True,
    ).stdout


def test_the_accuracy_study_from_python_is_the_cli_json_byte_for_byte() -> None:
    args = ["--users", "1", "--trials", "2", "--seed", "17", "--method", "coulomb,thesis"]
    args += ["--strategy", "slide", "--noise-mm", "0.45"]
    out = accuracy_json(args)
    data = ch.eval_accuracy(
        users=1,
        trials=2,
        seed=17,
        methods=["coulomb", "thesis"],
        strategies=["slide"],
        noise_mm=0.45,
    )
    assert json.dumps(data, indent=2, ensure_ascii=False) + "\n" == out
    assert [m["method"] for m in data["methods"]] == ["coulomb", "thesis"]
    assert abs(data["noise_rms_mm"] - 0.45) < 1e-6


def test_the_accuracy_study_takes_white_noise_as_the_cli_does() -> None:
    args = ["--users", "1", "--trials", "1", "--seed", "4", "--method", "coulomb"]
    args += ["--strategy", "lift", "--noise-mm", "1.7", "--noise-white", "45"]
    out = accuracy_json(args)
    data = ch.eval_accuracy(
        users=1,
        trials=1,
        seed=4,
        methods=["coulomb"],
        strategies=["lift"],
        noise_mm=1.7,
        noise_white=45.0,
    )
    assert json.dumps(data, indent=2, ensure_ascii=False) + "\n" == out
    with pytest.raises(ch.StudyError, match="noise-white: a tracker's frame rate in 10–1000 Hz"):
        ch.eval_accuracy(users=1, trials=1, noise_white=2000.0)


def test_a_scenario_runs_and_passes_its_checks() -> None:
    data = ch.run_scenario("push")
    (report,) = data["scenarios"]
    assert report["name"] == "push" and report["passed"]
    assert all(c["passed"] for c in report["checks"])


def test_the_bench_times_cluttered_scenes_with_the_same_bones_pressing() -> None:
    data = ch.bench(steps=20, boxes=3, tower=False, objects=[30, 75])
    assert [p["objects"] for p in data["objects"]] == [30, 75]
    assert all(p["bones_pressing"] == 32 and p["interaction_us"] > 0 for p in data["objects"])
    assert data["reference"]["bones_pressing"] == 6
    with pytest.raises(ch.ArgumentError, match="objects: each in 16..=4000, got 9"):
        ch.bench(steps=20, objects=[30, 9])
