#!/usr/bin/env bash
# Builds the core (the coulomb-hands library, without its `live` feature) for
# wasm32-unknown-unknown, in release:
#
#   scripts/wasm-core.sh [more cargo build options, e.g. --features enhanced-determinism]
#
# (scripts/web.sh adds `-p coulomb-hands-web`, the page's crate, whose cdylib is the .wasm.)
#
# Two routes, by what the machine has:
# - the ordinary one, `cargo build --target wasm32-unknown-unknown`, when the active toolchain
#   has the target installed (`rustup target list --installed` lists it, or, without rustup,
#   its sysroot holds it);
# - else Debian's web toolchain, rustc 1.96 with the standard library's source, which builds
#   std for the target (`-Zbuild-std`, through RUSTC_BOOTSTRAP) and links with lld-22
#   (Debian's `lld`, version 14, is too old). Install it once:
#     sudo apt-get update && sudo apt-get install -y rustc-web cargo-web rust-web-src lld-22
#   Its cargo is /usr/bin/cargo, called by its full path: rustup's stays first on PATH. Std's
#   own dependencies come from the crate registry.
# The library is built as an .rlib under ${CARGO_TARGET_DIR:-target}/wasm32-unknown-unknown/
# release/; a .wasm is linked by a cdylib crate that depends on it. Measured by the Debian
# route on 2 busy cores: 4 min 36 s cold (std, the dependencies and the core), 1 min after a
# change to the core, and 3 min more for `--features enhanced-determinism` (parry and rapier
# again).
set -euo pipefail
cd "$(dirname "$0")/.."
target=wasm32-unknown-unknown
args=(build --release --locked --target "$target" -p coulomb-hands --no-default-features --lib)
installed() {
  if command -v rustup > /dev/null 2>&1; then
    rustup target list --installed 2>/dev/null | grep -qx "$target"
  else
    [[ -d "$(rustc --print sysroot)/lib/rustlib/$target" ]]
  fi
}
if installed; then
  echo "wasm-core: the active toolchain's $target target" >&2
  exec cargo "${args[@]}" "$@"
fi
for tool in /usr/bin/cargo /usr/bin/rustc; do
  if [[ ! -x $tool ]]; then
    echo "wasm-core: no $target target in the active toolchain, and no $tool: install" \
      "Debian's web toolchain (rustc-web cargo-web rust-web-src lld-22), or a toolchain" \
      "with the target (rustup target add $target)" >&2
    exit 1
  fi
done
echo "wasm-core: Debian's web toolchain, building std for $target" >&2
export RUSTC=/usr/bin/rustc RUSTC_BOOTSTRAP=1
exec /usr/bin/cargo "${args[@]}" -Zbuild-std=std,panic_abort "$@"
