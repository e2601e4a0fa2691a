//! World handles: numbers from a registry, never pointers, so that a freed
//! or made-up handle is an error and not undefined behaviour. A number is
//! never given twice.

use crate::status::{ChStatus, Failure};
use coulomb_hands::InteractionWorld;
use coulomb_hands::pipeline::frame::HostFrame;
use coulomb_hands::run::sampled::FrameHands;
use std::collections::BTreeMap;
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};

/// An opaque handle on a world, from `ch_world_new` until `ch_world_free`;
/// 0 is never a world. A world may be used from any thread, one call at a
/// time (calls on one world from two threads wait for each other).
pub type ChWorld = usize;

/// A world, the frame its caller speaks in (`ch_world_set_frame`), and
/// its hands' poses on their way to the caller's newest (the core's rule
/// for a hand posed once for several steps).
pub struct Entry {
    pub world: InteractionWorld,
    pub frame: HostFrame,
    pub hands: FrameHands,
}

/// One world, locked while a call uses it.
type Shared = Arc<Mutex<Entry>>;

struct Registry {
    next: ChWorld,
    live: BTreeMap<ChWorld, Shared>,
}

static WORLDS: Mutex<Registry> = Mutex::new(Registry { next: 1, live: BTreeMap::new() });

/// The registry, whoever panicked while holding it (it holds no invariant
/// a panic could break: a map insert or removal either happened or not).
fn registry() -> MutexGuard<'static, Registry> {
    WORLDS.lock().unwrap_or_else(PoisonError::into_inner)
}

/// A new world's handle.
pub fn insert(world: InteractionWorld) -> Result<ChWorld, Failure> {
    let mut registry = registry();
    let handle = registry.next;
    registry.next = handle
        .checked_add(1)
        .ok_or_else(|| Failure::new(ChStatus::Internal, "world handles exhausted"))?;
    let entry = Entry { world, frame: HostFrame::LIBRARY, hands: FrameHands::default() };
    registry.live.insert(handle, Arc::new(Mutex::new(entry)));
    Ok(handle)
}

/// Forgets a world; it is dropped once no call uses it.
pub fn remove(handle: ChWorld) -> Result<(), Failure> {
    registry().live.remove(&handle).map(drop).ok_or_else(|| stale(handle))
}

/// Runs `f` on the world `handle` names, locked for the call.
pub fn with_world<T>(
    handle: ChWorld,
    f: impl FnOnce(&mut Entry) -> Result<T, Failure>,
) -> Result<T, Failure> {
    let shared = registry().live.get(&handle).cloned().ok_or_else(|| stale(handle))?;
    let mut world = shared.lock().map_err(|_| {
        Failure::new(
            ChStatus::Internal,
            format!("world {handle} failed inside an earlier call; free it"),
        )
    })?;
    f(&mut world)
}

fn stale(handle: ChWorld) -> Failure {
    Failure::new(ChStatus::StaleHandle, format!("world: {handle} is not a live world's handle"))
}
