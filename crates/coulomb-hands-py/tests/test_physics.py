"""Physical outcomes through the package: a pinch holds a box by friction, and lets one
heavier than mu * sum(f_n) / g slip; two worlds on two threads step as one after the
other does."""

from __future__ import annotations

import threading

import numpy as np
import coulomb_hands as ch
from conftest import pinch

CENTRE = np.array([0.0, 0.31, 0.0])
SIDE = 0.042
GAMMA = 350.0


def pinched_world(mass: float) -> tuple[ch.World, int]:
    """A 42 mm wooden box between a still thumb and index tip, each pressed 2.5 mm in,
    no ground under it."""
    world = ch.World(ch.Config(gamma={"Fixed": GAMMA}))
    box = world.add_box("box", [SIDE] * 3, mass, CENTRE)
    hand = world.add_hand("right")
    world.set_hand_pose(hand, pinch(CENTRE, SIDE / 2, 0.0025))
    return world, box


def test_a_pinch_holds_a_light_box_and_a_box_beyond_its_friction_slips() -> None:
    light, box = pinched_world(0.03)
    light.step(600)
    contacts = light.contacts()
    assert len(contacts["object"]) == 2
    assert set(contacts["bone"].tolist()) == {3, 6}
    normal = float(contacts["normal_force"].sum())
    mu = light.object_material(box)["static_mu"]
    g = 9.81
    limit = mu * normal / g  # the heaviest box this grip can hold (kg)
    assert limit > 0.03
    drop = CENTRE[1] - light.object_states()["position"][box, 1]
    assert drop < 0.002, f"the light box sank {drop * 1000:.2f} mm"
    # Just under the limit it still holds; a quarter over it, friction cannot carry it.
    for factor, held in [(0.8, True), (1.25, False)]:
        world, box = pinched_world(factor * limit)
        world.step(600)
        drop = CENTRE[1] - world.object_states()["position"][box, 1]
        if held:
            assert drop < 0.002, f"{factor} x the limit sank {drop * 1000:.2f} mm"
        else:
            assert drop > 0.05, f"{factor} x the limit sank only {drop * 1000:.1f} mm"
            assert len(world.contacts()["object"]) == 0


def falling_world(x: float) -> ch.World:
    """A sphere dropped from 0.27 m beside a pinched box, on a ground."""
    world, _ = pinched_world(0.02)
    world.add_ground(0.0, 0.7)
    world.add_sphere("ball", 0.019, 0.07, [x, 0.27, 0.05])
    return world


def test_two_worlds_on_two_threads_step_as_one_after_the_other() -> None:
    sequential = [falling_world(x) for x in (0.1, -0.1)]
    for w in sequential:
        w.step(700)
    threaded = [falling_world(x) for x in (0.1, -0.1)]
    threads = [threading.Thread(target=w.step, args=(700,)) for w in threaded]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for a, b in zip(sequential, threaded):
        sa, sb = a.object_states(), b.object_states()
        for key in ("position", "rotation", "linvel", "angvel", "hand_force"):
            assert np.array_equal(sa[key], sb[key]), key
    # The ball landed: it rests on the ground, the box is still held.
    states = sequential[0].object_states()
    assert abs(states["position"][1, 1] - 0.019) < 0.002
    assert states["position"][0, 1] > 0.3
