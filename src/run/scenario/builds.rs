//! Both builds of a step's contact stages (`pipeline/step/avx2.rs`) give
//! the same bits, on shipped scenarios.

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

/// A shipped scenario's bits, with the AVX2 build or the baseline.
fn run(name: &str, baseline: bool) -> Bits {
    BASELINE_ONLY.set(baseline);
    let mut bits = Bits::default();
    let report = Scenario::find(name).unwrap().run(&mut [&mut bits]);
    BASELINE_ONLY.set(false);
    assert!(report.unwrap().passed, "{name} failed");
    bits
}

/// Grasps, a slide down a slope, a spin and a handover: both builds give
/// every force and pose the same bits, step by step.
#[test]
fn avx2_and_baseline_builds_step_alike() {
    if !std::arch::is_x86_feature_detected!("avx2") {
        eprintln!("no AVX2 on this CPU: only the baseline build runs");
        return;
    }
    for name in ["slide-slippery", "spin-one-hand", "handover"] {
        let (avx2, baseline) = (run(name, false), run(name, true));
        assert!(avx2.bits.len() > 10_000 && avx2.slipping > 0, "{name}: {avx2:?}");
        assert!(avx2 == baseline, "{name}: the builds differ");
    }
}
