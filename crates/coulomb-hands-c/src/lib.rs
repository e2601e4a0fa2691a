//! The C ABI of coulomb-hands: hands that move objects only through Coulomb
//! friction contact forces, for engines and languages that call C (Unity
//! through P/Invoke, Unreal, Godot's GDExtension, C and C++).
//!
//! It serves both of the library's modes:
//! - the **built-in world**: the library steps its own rapier world
//!   (`ch_world_step`) and gives the objects' states back
//!   (`ch_world_object_states`);
//! - the **host mode**: the host engine owns the bodies, gives their states
//!   (`ch_world_set_host_bodies`), and gets back the hands' force and torque
//!   on each (`ch_world_host_step`) to apply before it integrates.
//!
//! The conventions are those of C APIs written in Rust (rustls-ffi,
//! wgpu-native):
//! - every call returns a [`ChStatus`]; on failure, `ch_last_error` gives a
//!   message naming the call and the argument (thread-local, kept until the
//!   thread's next failure);
//! - a failed call changes nothing, and writes nothing but an output's size;
//! - no panic crosses the boundary (one is caught and is
//!   `CH_STATUS_INTERNAL`; the world it happened in refuses further calls);
//! - worlds are opaque handles ([`ChWorld`]) from a registry, so a freed or
//!   made-up handle is `CH_STATUS_STALE_HANDLE`, never undefined behaviour;
//! - arrays are borrowed with their lengths; an output's size is queried
//!   with a null buffer, and a too-short buffer is `CH_STATUS_BUFFER_TOO_SMALL`
//!   with the size written (the one value a failed call writes);
//! - `ch_check_abi(CH_ABI_VERSION)` tells a header from another release;
//! - configs and scenes are the JSON the command-line tool reads, and
//!   recordings its files.
//!
//! The header, `include/coulomb_hands.h`, is generated from this crate by
//! cbindgen and checked in; a test fails when it is stale.

mod abi;
mod args;
mod handles;
mod host;
mod replay;
mod status;
mod world;

// Every entry point and type, for Rust callers (the benchmarks) as for C.
pub use abi::*;
pub use handles::ChWorld;
pub use host::*;
pub use replay::*;
pub use status::*;
pub use world::*;
