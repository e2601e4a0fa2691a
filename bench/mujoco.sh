#!/usr/bin/env bash
# MuJoCo side by side with coulomb-hands (the book's "Benchmarks"): makes a
# virtualenv with pip's mujoco, then runs `coulomb-hands bench --mujoco` with
# it, so that both figures come from one run.
#
#   bench/mujoco.sh [--venv DIR] [bench arguments...]
#
# DIR defaults to target/mujoco-venv. Extra arguments go to `bench`
# (e.g. --json, --steps 2000). Needs python3 with its venv module.
set -euo pipefail
cd "$(dirname "$0")/.."
venv=target/mujoco-venv
if [[ "${1:-}" == "--venv" ]]; then
    venv="${2:?--venv needs a directory}"
    shift 2
fi
if ! command -v python3 >/dev/null; then
    echo "error: python3 not found: install Python 3 (with its venv module)" >&2
    exit 1
fi
if [[ ! -x "$venv/bin/python" ]]; then
    python3 -m venv "$venv" || {
        echo "error: python3 -m venv failed: install Python's venv module (python3-venv)" >&2
        exit 1
    }
fi
if ! "$venv/bin/python" -c "import mujoco" 2>/dev/null; then
    "$venv/bin/python" -m pip install --quiet mujoco
fi
cargo run --release --quiet -- bench --mujoco --python "$venv/bin/python" "$@"
