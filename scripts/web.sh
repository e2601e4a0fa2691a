#!/usr/bin/env bash
# Builds the page in web/ and, with --serve [PORT], serves it at http://localhost:PORT (8000):
#
#   scripts/web.sh --serve
#
# What it builds, into web/ (which is then a plain folder any static host can serve):
# - pkg/: crates/coulomb-hands-web for wasm32-unknown-unknown, in release with
#   `enhanced-determinism` (the native library's bits), SIMD128 and fat LTO, by
#   scripts/wasm-core.sh's two routes, then wasm-bindgen's JavaScript module (`wasm-bindgen
#   --target web`);
# - vendor/: three.js, from web/node_modules (`npm ci` there, run here when it is missing);
# - data/: the recording and the hand–object capture the page replays (data/leap/grab.json.lz,
#   data/taco/taco_20231104_017.json and the .obj mesh it names).
# It needs wasm-bindgen-cli at the lock file's wasm-bindgen version:
#   cargo install wasm-bindgen-cli --version "$(scripts/web.sh --wasm-bindgen-version)"
# and Node.js with npm, and, for the Debian route, what scripts/wasm-core.sh says.
set -euo pipefail
cd "$(dirname "$0")/.."
# The lock file's wasm-bindgen, which the CLI must match.
version=$(grep -A1 '^name = "wasm-bindgen"$' Cargo.lock | sed -n 's/^version = "\(.*\)"$/\1/p')
if [[ ${1:-} == --wasm-bindgen-version ]]; then
  echo "$version"
  exit 0
fi
bindgen="${CARGO_HOME:-$HOME/.cargo}/bin/wasm-bindgen"
command -v wasm-bindgen > /dev/null 2>&1 && bindgen=$(command -v wasm-bindgen)
if [[ "$("$bindgen" --version 2>/dev/null)" != "wasm-bindgen $version" ]]; then
  echo "web: wasm-bindgen $version is needed (the lock file's): cargo install" \
    "wasm-bindgen-cli --version $version" >&2
  exit 1
fi
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-target/wasm}
# WebAssembly's 128-bit SIMD (every browser with WebXR has it), and the whole program optimised
# as one (fat LTO, one codegen unit): the demo's step 24 % faster than without them, and the
# same bits (SIMD128's lanes are IEEE operations, no fused multiply-add). The flags make the
# build its own: std and the dependencies are compiled again, not shared with the core's.
export CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="-C target-feature=+simd128"
export CARGO_PROFILE_RELEASE_LTO=fat CARGO_PROFILE_RELEASE_CODEGEN_UNITS=1
scripts/wasm-core.sh -p coulomb-hands-web --features coulomb-hands-web/enhanced-determinism
wasm=$CARGO_TARGET_DIR/wasm32-unknown-unknown/release/coulomb_hands_web.wasm
rm -rf web/pkg
"$bindgen" --target web --out-dir web/pkg "$wasm"
[[ -d web/node_modules/three ]] || (cd web && npm ci --no-audit --no-fund)
rm -rf web/vendor web/data
mkdir -p web/vendor/three/controls web/data
cp web/node_modules/three/build/three.module.js web/node_modules/three/build/three.core.js \
  web/vendor/three/
cp web/node_modules/three/examples/jsm/controls/OrbitControls.js web/vendor/three/controls/
cp web/node_modules/three/LICENSE web/vendor/three/
cp data/leap/grab.json.lz data/taco/taco_20231104_017.json data/taco/taco_20231104_017.obj \
  web/data/
echo "web: built web/ ($(du -h web/pkg/coulomb_hands_web_bg.wasm | cut -f1) of wasm)" >&2
if [[ ${1:-} == --serve ]]; then
  port=${2:-8000}
  echo "web: serving web/ at http://localhost:$port (Ctrl-C ends it)" >&2
  exec python3 -m http.server "$port" --bind 127.0.0.1 --directory web
fi
