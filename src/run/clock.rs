//! The wall clock that the timed runs read (the bench, the report's
//! scenario runs), passed in by their caller. Simulated time is the
//! driver's ([`super::drive::Driver`]); this is only how long the machine
//! took.
//!
//! Native programs pass a [`SystemClock`]. wasm32-unknown-unknown has no
//! clock in std (`Instant::now` panics there), so the library never reads
//! one itself on it: a web page passes its own, such as a closure over
//! `performance.now()`.

use std::time::Duration;

/// A monotonic wall clock: the time since some fixed instant of its own.
pub trait Clock {
    /// The time since the clock's origin; never less than an earlier
    /// reading.
    fn now(&self) -> Duration;
}

/// Any `Fn() -> Duration` is a clock.
impl<F: Fn() -> Duration> Clock for F {
    fn now(&self) -> Duration {
        self()
    }
}

/// std's monotonic clock ([`std::time::Instant`]), from when it was made.
/// Not on wasm32, which has none.
#[cfg(not(target_arch = "wasm32"))]
#[derive(Debug, Clone, Copy)]
pub struct SystemClock {
    origin: std::time::Instant,
}

#[cfg(not(target_arch = "wasm32"))]
impl SystemClock {
    /// A clock whose origin is now.
    pub fn new() -> Self {
        SystemClock { origin: std::time::Instant::now() }
    }
}

#[cfg(not(target_arch = "wasm32"))]
impl Default for SystemClock {
    fn default() -> Self {
        SystemClock::new()
    }
}

#[cfg(not(target_arch = "wasm32"))]
impl Clock for SystemClock {
    fn now(&self) -> Duration {
        self.origin.elapsed()
    }
}
