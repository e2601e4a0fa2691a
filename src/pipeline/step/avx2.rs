//! The contact stages built for AVX2 ([`super::contact_stages`] runs it
//! where the CPU has it).

use super::{InteractionWorld, StepScratch};

/// Whether to run the AVX2 build: the CPU has AVX2, and (in this crate's
/// tests) the baseline build is not asked for.
#[inline]
pub(super) fn enabled() -> bool {
    #[cfg(test)]
    if BASELINE_ONLY.get() {
        return false;
    }
    std::arch::is_x86_feature_detected!("avx2")
}

/// Stages 2 to 7 ([`super::inlined_contact_stages`]), built with AVX2.
#[target_feature(enable = "avx2")]
pub(super) fn contact_stages(world: &mut InteractionWorld, step: &mut StepScratch) {
    // The patches' deviation springs may take eight samples at a time.
    step.patch.avx2 = true;
    super::inlined_contact_stages(world, step);
}

#[cfg(test)]
thread_local! {
    /// Set: this thread's steps run the baseline build, so a test can
    /// compare the two (`run/scenario/builds.rs`).
    pub(crate) static BASELINE_ONLY: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}
