"""What the package's tests share: the checkout's files, and hand poses built by hand."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

REPO = Path(__file__).resolve().parents[3]
"""The checkout's root: its data/ and target/ are the tests' inputs."""

THUMB_DISTAL = 3
INDEX_DISTAL = 6


def far_hand(y: float = 1.0) -> dict[str, Any]:
    """A flat hand whose bones all lie at height `y`, far from anything in a test: each
    capsule 24 mm long, 8 mm in radius, the fingers side by side."""
    a = np.zeros((15, 3))
    b = np.zeros((15, 3))
    for i in range(15):
        finger, phalanx = divmod(i, 3)
        a[i] = [0.03 * finger - 0.06, y, 0.05 + 0.025 * phalanx]
        b[i] = a[i] + [0.0, 0.0, 0.024]
    return {
        "palm_center": np.array([0.0, y, 0.0]),
        "palm_rotation": np.array([0.0, 0.0, 0.0, 1.0]),
        "palm_half_extents": np.array([0.045, 0.01, 0.045]),
        "capsule_a": a,
        "capsule_b": b,
        "capsule_radius": np.full(15, 0.008),
    }


def pinch(centre: np.ndarray, half_width: float, depth: float) -> dict[str, Any]:
    """`far_hand` with its thumb and index fingertips moved to pinch a box of half
    width `half_width` centred at `centre` along x: each fingertip capsule runs along z
    beside a face, pressed `depth` into it; everything else is a metre away."""
    pose = far_hand()
    radius = 0.008
    for bone, sign in [(THUMB_DISTAL, -1.0), (INDEX_DISTAL, 1.0)]:
        x = centre[0] + sign * (half_width + radius - depth)
        pose["capsule_a"][bone - 1] = [x, centre[1], centre[2] - 0.011]
        pose["capsule_b"][bone - 1] = [x, centre[1], centre[2] + 0.011]
        pose["capsule_radius"][bone - 1] = radius
    return pose
