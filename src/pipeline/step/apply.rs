//! Stage 7: a contact's forces go to rapier.

use super::Stage;
use crate::contact::lanes;
use crate::friction::total_force;
use crate::pipeline::{firewall, host};
use crate::scene::ObjectId;
use glam::{Vec3, Vec3A};

/// The hand forces of one object's run of contacts, summed as they are
/// applied and written to rapier once, when the run ends ([`Stage::flush`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct RunForces {
    object: ObjectId,
    /// The body's user force (N) and torque (N·m), this run's samples
    /// added to what it had.
    force: Vec3A,
    torque: Vec3A,
    /// The object's total hand force (N), Eq. 3.10.
    total: Vec3A,
    /// Whether any sample pushed the body: then they are written.
    pushed: bool,
    /// Whether rapier moves the body, and its centre of mass (world, m),
    /// which the torques are taken about.
    dynamic: bool,
    /// Whether the total is the force, bit for bit, at the end of the run
    /// ([`sums_alike`]): then it is not summed apart.
    alike: bool,
    center_of_mass: Vec3,
}

impl Stage<'_> {
    /// Applies the sample forces of the contact just updated (in
    /// `self.patch`) to its object, as rapier's `add_force_at_point` would
    /// one by one, skipping any that is not finite ([`firewall::forces`]),
    /// and adds them to the object's total hand force
    /// ([`crate::friction::total_force`]: the samples of a contact share
    /// its force exactly, so their sum is the contacts' sum).
    ///
    /// The body's force and torque are summed here, over the object's run
    /// of contacts, and written back once ([`Self::flush`]): the same sums,
    /// in the same order, as `add_force_at_point` per sample, without its
    /// per-sample checks and wake-ups. Written once a contact, they would
    /// differ at most in the sign of a zero partial sum, which the write
    /// (`0 + sum`) makes +0 either way: so the same bits.
    #[inline(always)]
    pub(super) fn apply_forces(&mut self, object: ObjectId) {
        let run = match self.run {
            Some(run) if run.object == object => run,
            _ => {
                self.flush();
                self.start_run(object)
            }
        };
        let RunForces { mut force, mut torque, mut total, mut pushed, dynamic, alike, .. } = run;
        if let Some((forces, points)) = self.patch.applied() {
            let origin = lanes::splat(run.center_of_mass);
            for (j, (f, q)) in forces.chunks().iter().zip(points.chunks()).enumerate() {
                // Bitmasks of lanes, four samples at once: those the
                // firewall passes, and of them, those pushing a dynamic
                // body. The others add -0.0: the bits of skipping them.
                let finite = firewall::forces(f, q) & forces.used_mask(j);
                // Eq. 3.10 over the forces the firewall passed.
                if !alike {
                    total = total_force(total, lanes::vectors(&lanes::keep(f, finite)));
                }
                let pushing = if dynamic { finite & lanes::nonzero(f) } else { 0 };
                if pushing != 0 {
                    let torques = lanes::cross(lanes::sub(*q, origin), *f);
                    // The same sum, on the body: the zero samples skipped.
                    force = total_force(force, lanes::vectors(&lanes::keep(f, pushing)));
                    lanes::add_in_order(&mut torque, &lanes::keep(&torques, pushing));
                    pushed = true;
                }
            }
        }
        if alike {
            total = force;
        }
        self.run = Some(RunForces { force, torque, total, pushed, ..run });
    }

    /// Starts summing `object`'s forces: from its body's user force and
    /// torque and its total so far. It will be cleared next step.
    #[inline(always)]
    fn start_run(&mut self, object: ObjectId) -> RunForces {
        let slot = &mut self.objects[object.0 as usize];
        if !slot.forced {
            slot.forced = true;
            self.forced.push(object.0);
        }
        let body = &self.bodies[slot.body];
        let (force, total, dynamic) = (body.user_force(), slot.hand_force, body.is_dynamic());
        RunForces {
            object,
            force: force.into(),
            torque: body.user_torque().into(),
            total: total.into(),
            pushed: false,
            dynamic,
            alike: dynamic && sums_alike(force, total),
            center_of_mass: slot.center_of_mass(body),
        }
    }

    /// Writes the run of forces summed so far to its object's body and
    /// total, if there is one: at the end of each run of contacts on an
    /// object, and of the stage.
    #[inline(always)]
    pub(super) fn flush(&mut self) {
        let Some(run) = self.run.take() else { return };
        let slot = &mut self.objects[run.object.0 as usize];
        slot.hand_force = run.total.into();
        slot.pushed |= run.pushed;
        if run.pushed {
            host::push(&mut self.bodies[slot.body], run.force.into(), run.torque.into());
        }
    }
}

/// Whether a run's total (every finite sample) and force (the finite
/// samples that are not zero, on a dynamic body) end with the same bits,
/// starting from `force` and `total`: when they start with the same bits,
/// none of them −0. Then no partial sum is ever −0 (in round-to-nearest,
/// `x + y` is −0 only for `x` and `y` both −0), and adding a zero vector to
/// a sum that is not −0 changes none of its bits: so skipping the zero
/// samples, as the force does, changes nothing.
fn sums_alike(force: Vec3, total: Vec3) -> bool {
    let (force, total) = (force.to_array().map(f32::to_bits), total.to_array().map(f32::to_bits));
    force == total && !force.contains(&(-0.0f32).to_bits())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sums_that_start_alike_end_alike_with_the_zero_samples_skipped() {
        // Forces with zero vectors among them, signed zeros included, and
        // components that cancel exactly.
        let forces = [
            Vec3::new(0.25, -0.0, 1e-3),
            Vec3::new(-0.0, -0.0, -0.0),
            Vec3::new(-0.25, 0.0, -1e-3),
            Vec3::new(0.0, -0.0, 0.0),
            Vec3::new(3e-7, -2.5, -0.0),
        ];
        for start in [Vec3::ZERO, Vec3::new(0.5, 0.0, -7e-3)] {
            assert!(sums_alike(start, start));
            let total = forces.iter().fold(start, |sum, f| sum + *f);
            let pushing = forces.iter().filter(|f| **f != Vec3::ZERO);
            let force = pushing.fold(start, |sum, f| sum + *f);
            let bits = |v: Vec3| v.to_array().map(f32::to_bits);
            assert_eq!(bits(total), bits(force), "from {start}");
        }
        // A −0 start could end otherwise (−0 + 0 is +0), so it is not alike.
        let negative = Vec3::new(-0.0, 1.0, 0.0);
        assert!(!sums_alike(negative, negative));
        assert!(!sums_alike(Vec3::ZERO, Vec3::new(0.0, 0.0, 1e-9)));
    }
}
