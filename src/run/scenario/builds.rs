//! Both builds of a step's contact stages (`pipeline/step/avx2.rs`) give
//! the same bits, on shipped scenarios; and so do skin frames kept from
//! step to step (`contact/anchor.rs`, `Anchor::skin`) and computed anew.

use crate::contact::anchor::FRAMES_ANEW;
use crate::friction::FrictionState;
use crate::pipeline::InteractionWorld;
use crate::pipeline::step::BASELINE_ONLY;
use crate::run::RunError;
use crate::run::drive::{Observer, StepView};
use crate::run::scenario::Scenario;

/// A run's every contact force and sample point, and every object's pose
/// and velocity, step by step, as bits; and how many contact steps slipped.
#[derive(Default, PartialEq, Debug)]
struct Bits {
    bits: Vec<u32>,
    slipping: usize,
}

impl Observer for Bits {
    fn after_hand_forces(&mut self, world: &mut InteractionWorld) -> Result<(), RunError> {
        for c in world.contacts() {
            let sampled = c.samples.iter().flat_map(|p| p.to_array());
            let forces = c.force.to_array().into_iter().chain([c.normal_force]);
            self.bits.extend(forces.chain(sampled).map(f32::to_bits));
            self.slipping += usize::from(c.state == FrictionState::Dynamic);
        }
        Ok(())
    }

    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        for id in step.world.object_ids() {
            let state = step.world.object_state(id)?;
            let pose = [state.position.to_array(), state.linvel.to_array()];
            let turn = state.rotation.to_array();
            self.bits.extend(pose.into_iter().flatten().chain(turn).map(f32::to_bits));
        }
        Ok(())
    }
}

/// How a run is built.
#[derive(Clone, Copy)]
enum Build {
    /// As shipped: the AVX2 build where the CPU has it.
    Shipped,
    /// The baseline build.
    Baseline,
    /// Every skin frame computed anew.
    FramesAnew,
}

/// A shipped scenario's bits, as `build` builds it.
fn run(name: &str, build: Build) -> Bits {
    BASELINE_ONLY.set(matches!(build, Build::Baseline));
    FRAMES_ANEW.set(matches!(build, Build::FramesAnew));
    let mut bits = Bits::default();
    let report = Scenario::find(name).unwrap().run(&mut [&mut bits]);
    BASELINE_ONLY.set(false);
    FRAMES_ANEW.set(false);
    assert!(report.unwrap().passed, "{name} failed");
    bits
}

/// Grasps, a slide down a slope, a spin and a handover.
const SCENARIOS: [&str; 3] = ["slide-slippery", "spin-one-hand", "handover"];

/// Grasps, a slide down a slope, a spin and a handover: both builds give
/// every force and pose the same bits, step by step.
#[test]
fn avx2_and_baseline_builds_step_alike() {
    if !std::arch::is_x86_feature_detected!("avx2") {
        eprintln!("no AVX2 on this CPU: only the baseline build runs");
        return;
    }
    for name in SCENARIOS {
        let (avx2, baseline) = (run(name, Build::Shipped), run(name, Build::Baseline));
        assert!(avx2.bits.len() > 10_000 && avx2.slipping > 0, "{name}: {avx2:?}");
        assert!(avx2 == baseline, "{name}: the builds differ");
    }
}

/// The same scenarios, their hands moving, holding still and slipping
/// (which re-anchors a contact's skin frame): skin frames kept from step
/// to step give every force and pose the same bits as frames computed anew.
#[test]
fn kept_skin_frames_step_alike_with_frames_computed_anew() {
    for name in SCENARIOS {
        let (kept, anew) = (run(name, Build::Shipped), run(name, Build::FramesAnew));
        assert!(kept.bits.len() > 10_000 && kept.slipping > 0, "{name}: {kept:?}");
        assert!(kept == anew, "{name}: kept frames differ");
    }
}
