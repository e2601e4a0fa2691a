"""What Python adds to the Rust library, on the benchmark's reference scene (not a test:
it times, and prints; run it with the package installed):

    python crates/coulomb-hands-py/bench/overhead.py

1. `World.step()` called once per step from Python, against the same steps run in one
   call (`World.step(n)`, the Rust loop over `InteractionWorld::step`): the difference
   per step is the cost of a call from Python. The issue's bound: 5 us.
2. Both hands' joints set from NumPy, (26, 3) OpenXR positions with radii, as a tracker
   loop would each frame, the 16-bone poses built and checked by the library. The
   issue's bound: 10 us.

Each figure is the median of several rounds, so that another process's burst on a
shared machine shows in one round, not in the figure.
"""

from __future__ import annotations

import json
import statistics
import time
from pathlib import Path

import numpy as np
import coulomb_hands as ch

ROUNDS = 15
STEPS = 400
REPO = Path(__file__).resolve().parents[3]


def per_step_us(world: ch.World, one_call: bool) -> float:
    start = time.perf_counter()
    if one_call:
        world.step(STEPS)
    else:
        step = world.step
        for _ in range(STEPS):
            step()
    return (time.perf_counter() - start) * 1e6 / STEPS


def step_overhead(world: ch.World) -> tuple[float, float, float]:
    """Per step: the Rust loop's time, Python's, and the median of their paired
    differences (rounds alternate, so a burst of other work hits both alike)."""
    world.step(200)  # the contacts begin and press in
    rust, python = [], []
    for _ in range(ROUNDS):
        rust.append(per_step_us(world, True))
        python.append(per_step_us(world, False))
    r, p = statistics.median(rust), statistics.median(python)
    overhead = statistics.median(b - a for a, b in zip(rust, python))
    return r, p, overhead


def joints_us() -> float:
    line = (REPO / "data" / "joints" / "pinch-57fps.jsonl").read_text().splitlines()[40]
    hand = json.loads(line)["hands"][0]
    joints = np.array(hand["joints"])
    radii = np.array(hand["radii"])
    world = ch.World()
    left, right = world.add_hand("left"), world.add_hand("right")
    mirrored = joints * [-1.0, 1.0, 1.0]
    n = 20000
    rounds = []
    for _ in range(ROUNDS):
        start = time.perf_counter()
        for _ in range(n):
            world.set_hand_joints(left, mirrored, "openxr", radii)
            world.set_hand_joints(right, joints, "openxr", radii)
        rounds.append((time.perf_counter() - start) * 1e6 / n)
    return statistics.median(rounds)


def main() -> None:
    scenes = [
        ("reference scene, awake (2 hands, 16 held boxes, the tower)", True, True),
        ("reference scene without the tower, awake", False, True),
        ("reference scene, asleep (the tower at rest)", True, False),
    ]
    for name, tower, awake in scenes:
        world = ch.World.reference_scene(tower=tower, awake=awake)
        rust, python, overhead = step_overhead(world)
        print(f"{name}, per step:")
        print(f"  Rust loop, World.step({STEPS}): {rust:8.2f} us")
        print(f"  World.step() from Python:    {python:8.2f} us")
        print(f"  Python's overhead:           {overhead:8.2f} us  (bound 5 us)")
    rust, python, overhead = step_overhead(ch.World())
    print(f"an empty world, per step: Rust {rust:.3f} us, Python {python:.3f} us, "
          f"overhead {overhead:.3f} us: the cost of the call itself")
    both = joints_us()
    print(f"both hands' joints from NumPy (OpenXR, 26 x 3, radii): {both:.2f} us  (bound 10 us)")


if __name__ == "__main__":
    main()
