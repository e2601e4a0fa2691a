"""The stub is what the package is: `mypy --strict` passes on a program using every
call (typed_api.py, which then runs), on the example and on the benchmark."""

from __future__ import annotations

import subprocess
import sys

from conftest import REPO
import typed_api

PACKAGE = REPO / "crates" / "coulomb-hands-py"


def test_mypy_strict_accepts_the_typed_uses_of_the_package() -> None:
    files = [
        PACKAGE / "tests" / "typed_api.py",
        REPO / "examples" / "python" / "mediapipe_to_physics.py",
        PACKAGE / "bench" / "overhead.py",
    ]
    result = subprocess.run(
        [sys.executable, "-m", "mypy", "--strict", "--no-incremental", *map(str, files)],
        capture_output=True,
        text=True,
        cwd=PACKAGE / "tests",
    )
    assert result.returncode == 0, result.stdout + result.stderr


def test_the_typed_program_runs() -> None:
    assert abs(typed_api.run() - 0.006) < 1e-9
