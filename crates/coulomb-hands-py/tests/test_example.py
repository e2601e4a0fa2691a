"""The MediaPipe example runs as the book shows it: the hand closes on the cube, many
bones press it, and the plot is written (no window)."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

from conftest import REPO


def test_the_mediapipe_example_closes_the_hand_on_the_cube_and_plots(tmp_path: Path) -> None:
    out = tmp_path / "forces.png"
    script = REPO / "examples" / "python" / "mediapipe_to_physics.py"
    result = subprocess.run(
        [sys.executable, str(script), "--out", str(out)],
        capture_output=True,
        text=True,
        check=True,
    )
    pressing = re.search(r"(\d+) bones press the cube", result.stdout)
    assert pressing is not None, result.stdout
    assert int(pressing.group(1)) >= 6
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
