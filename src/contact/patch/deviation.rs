//! A skin patch's deviation springs ([`super`]): how far each sample's
//! point on the object has moved from its point on the skin.
//!
//! The kernel, [`Springs::head`] and [`Springs::tail`], is written once on
//! a [`Lane`]: it runs four samples at a time (`f32x4`), eight in the AVX2
//! build (`wide8.rs`), and one at a time on a plain `f32`, which reads as
//! the scalar arithmetic it is and which the tests compare with.

#[cfg(target_arch = "x86_64")]
mod wide8;

use super::{PatchScratch, PatchStep, Samples, damping_lag};
use crate::contact::ObjectView;
use crate::contact::lanes::{self, Chunk, LANES, Lane, Mat3Lanes, Vector};
use crate::contact::surface;
use crate::friction::{slipped_stretch, static_stretch_squared};
use wide::f32x4;

/// A patch's springs this step, each constant in every lane.
#[derive(Debug, Clone, Copy)]
pub(super) struct Springs {
    /// C and the normal there (world, m), and the object's spin (rad/s).
    pub c: Chunk,
    pub n: Chunk,
    pub angvel: Chunk,
    /// The skin frame's rotation, and its rate (per s).
    pub skin_rot: Mat3Lanes,
    pub skin_rate: Mat3Lanes,
    /// Whether the normal deviation is held within `±limit` (m).
    pub clamped: bool,
    pub lower: f32x4,
    pub limit: f32x4,
    /// The rocking spring over γ, and its damping as stretch per rate (s).
    pub rock: f32x4,
    pub rocking_lag: f32x4,
    /// The deviations' damping as stretch per rate (s).
    pub lag: f32x4,
    /// The squared tangential stretch a sample holds before it slips (m²).
    pub cone: f32x4,
}

/// A chunk's deviations as far as the slip test: the samples' skin points
/// on the object (`rest`), their normal and tangential deviations, and
/// which of them slip.
#[derive(Debug, Clone, Copy)]
pub(super) struct Head<W: Lane> {
    pub rest: Vector<W>,
    pub e_n: W,
    pub e_t: Vector<W>,
    pub slipping: W::Mask,
}

impl Springs {
    #[inline(always)]
    fn new(step: &PatchStep) -> Springs {
        let rocking = step.rocking;
        let limit = f32x4::splat(step.normal_force / rocking.stiffness);
        Springs {
            c: lanes::splat(step.center),
            n: lanes::splat(step.normal),
            angvel: lanes::splat(step.spin),
            skin_rot: lanes::splat_mat(&step.skin),
            skin_rate: lanes::splat_mat(&step.skin_rate),
            clamped: rocking.clamped,
            lower: -limit,
            limit,
            rock: f32x4::splat(rocking.stiffness / step.gamma),
            rocking_lag: f32x4::splat(rocking.lag),
            // Damping of the deviations, folded in as extra stretch c/γ · ė.
            lag: f32x4::splat(damping_lag(step.damping, step.gamma)),
            cone: f32x4::splat(static_stretch_squared(step.normal_force, step.mu, step.gamma)),
        }
    }

    /// The head of a chunk of samples with skin offsets `skin`, points
    /// `ci` and valid lanes `valid`: where each sample's skin point is on
    /// the object, how far its point has moved from there, normally (held
    /// within the rocking limit on a soft pad) and tangentially, and
    /// whether that is beyond its share of the friction cone.
    #[inline(always)]
    fn head<W: Lane>(&self, skin: Vector<W>, ci: Vector<W>, valid: W::Mask) -> Head<W> {
        let (c, n) = (lanes::widen(&self.c), lanes::widen(&self.n));
        let rest = lanes::add(c, lanes::mat_mul(&self.skin_rot, skin));
        let e = lanes::sub(ci, rest);
        let e_dot_n = lanes::dot(e, n);
        let e_n = if self.clamped {
            e_dot_n.clamp(W::widen(self.lower), W::widen(self.limit))
        } else {
            e_dot_n
        };
        let e_t = lanes::sub(e, lanes::scale(e_dot_n, n));
        let slipping = lanes::dot(e_t, e_t).gt(W::widen(self.cone)) & valid;
        Head { rest, e_n, e_t, slipping }
    }

    /// A chunk's deviations from its head (its slips done): the damping of
    /// their rates, and the rocking spring on the normal part.
    #[inline(always)]
    fn tail<W: Lane>(&self, skin: Vector<W>, ci: Vector<W>, e_n: W, e_t: Vector<W>) -> Vector<W> {
        let (c, n) = (lanes::widen(&self.c), lanes::widen(&self.n));
        let spin = lanes::cross(lanes::widen(&self.angvel), lanes::sub(ci, c));
        let e_rate = lanes::sub(spin, lanes::mat_mul(&self.skin_rate, skin));
        let rate_n = lanes::dot(e_rate, n);
        let rate_t = lanes::sub(e_rate, lanes::scale(rate_n, n));
        // Scaled so that γ/N times it is the rocking spring k/N on e_n.
        let rocking_stretch = W::widen(self.rock) * (e_n + W::widen(self.rocking_lag) * rate_n);
        let damped = lanes::add(e_t, lanes::scale(W::widen(self.lag), rate_t));
        lanes::add(damped, lanes::scale(rocking_stretch, n))
    }
}

/// Each sample's deviation `e_i` (m) from its skin point, relative to C:
/// tangentially, slipped back to its own share of the cone where it is
/// beyond it (its object point moves along the surface); plus the damping
/// of its rate, folded in as extra stretch; normally, scaled to the
/// [`super::Rocking`] spring. Samples that slip move their points in
/// `scratch.points` and `samples.object`.
///
/// In the AVX2 build ([`PatchScratch::avx2`]), two chunks at a time: the
/// same kernel on each lane, so the same bits.
#[inline(always)]
pub(super) fn deviate(
    step: &PatchStep,
    samples: &mut Samples,
    object: &ObjectView,
    scratch: &mut PatchScratch,
) {
    let springs = Springs::new(step);
    let chunks = samples.object.chunks().len();
    let mut j = 0;
    #[cfg(target_arch = "x86_64")]
    if scratch.avx2 {
        while j + 2 <= chunks {
            // SAFETY: `avx2` is set only by the AVX2 build of the contact
            // stages, which runs only where the CPU has AVX2.
            let slipping = unsafe { wide8::deviate_two(&springs, samples, scratch, j) };
            if let Some(heads) = slipping {
                for (k, head) in heads.into_iter().enumerate() {
                    finish(step, &springs, samples, object, scratch, j + k, head);
                }
            }
            j += 2;
        }
    }
    while j < chunks {
        let (skin, ci) = (samples.skin.chunks()[j], scratch.points.chunks()[j]);
        let head = springs.head(skin, ci, samples.object.valid(j));
        finish(step, &springs, samples, object, scratch, j, head);
        j += 1;
    }
}

/// Chunk `j`'s deviations from its head: the samples that slip move their
/// object points along the surface, then [`Springs::tail`].
#[inline(always)]
fn finish(
    step: &PatchStep,
    springs: &Springs,
    samples: &mut Samples,
    object: &ObjectView,
    scratch: &mut PatchScratch,
    j: usize,
    head: Head<f32x4>,
) {
    let Head { rest, e_n, mut e_t, slipping } = head;
    let mut ci = scratch.points.chunks()[j];
    if <f32x4 as Lane>::any(slipping) {
        let pose = &object.pose;
        let mask = slipping.to_bitmask();
        for k in (0..LANES).filter(|k| mask & (1 << k) != 0) {
            let slipped =
                slipped_stretch(lanes::lane(&e_t, k), step.normal_force, step.mu, step.gamma);
            let e_n_k = e_n.as_array()[k];
            let target = lanes::lane(&rest, k) + slipped + e_n_k * step.normal;
            let moved = surface::project_to_surface(object.shape, pose, target);
            samples.object.set(j * LANES + k, pose.inverse_transform_point(moved));
            lanes::set_lane(&mut ci, k, moved);
            lanes::set_lane(&mut e_t, k, slipped);
        }
        scratch.points.chunks_mut()[j] = ci;
    }
    let skin = samples.skin.chunks()[j];
    scratch.deviations.chunks_mut()[j] = springs.tail(skin, ci, e_n, e_t);
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use glam::{Mat3, Vec3};

    /// The skin frame's rotation of [`springs`].
    fn skin_rotation() -> Mat3 {
        Mat3::from_euler(glam::EulerRot::XYZ, 0.31, -0.17, 0.53)
    }

    /// A patch's springs, clamped or not, on a tilted normal, with a skin
    /// frame turned and turning and an object that spins.
    pub fn springs(clamped: bool) -> Springs {
        let rot = skin_rotation();
        let rate = Mat3::from_cols(
            Vec3::new(0.0, 1.3, -0.4),
            Vec3::new(-1.3, 0.0, 0.9),
            Vec3::new(0.4, -0.9, 0.0),
        );
        Springs {
            c: lanes::splat(Vec3::new(0.012, 0.31, -0.007)),
            n: lanes::splat(Vec3::new(0.2, 0.9, -0.3).normalize()),
            angvel: lanes::splat(Vec3::new(0.7, -2.1, 0.4)),
            skin_rot: lanes::splat_mat(&rot),
            skin_rate: lanes::splat_mat(&rate),
            clamped,
            lower: f32x4::splat(-3e-4),
            limit: f32x4::splat(3e-4),
            rock: f32x4::splat(1.7),
            rocking_lag: f32x4::splat(2.3e-3),
            lag: f32x4::splat(1.1e-3),
            cone: f32x4::splat(1.0e-6),
        }
    }

    /// Eight samples round C: skin offsets, and object points that have
    /// moved from them by up to about 1.6 mm, so that some slip (beyond
    /// the cone's 1 mm) and some do not.
    pub fn samples(springs: &Springs) -> Samples {
        let c = lanes::lane(&springs.c, 0);
        Samples::from_pairs((0..8).map(|i| {
            let a = i as f32 * 0.83;
            let skin = Vec3::new(a.cos(), 0.3 * a.sin(), a.sin()) * 0.004;
            let moved = Vec3::new((2.1 * a).sin(), (1.3 * a).cos(), (0.7 * a).sin()) * 9e-4;
            (c + skin_rotation() * skin + moved, skin)
        }))
    }

    fn bits<const N: usize>(v: [f32; N]) -> [u32; N] {
        v.map(f32::to_bits)
    }

    #[test]
    fn the_kernel_four_at_a_time_has_the_bits_of_its_scalar_reading() {
        for clamped in [false, true] {
            let springs = springs(clamped);
            let samples = samples(&springs);
            let mut slipped = 0;
            for j in 0..2 {
                let (skin, ci) = (samples.skin.chunks()[j], samples.object.chunks()[j]);
                let four = springs.head(skin, ci, samples.object.valid(j));
                let tail = springs.tail(skin, ci, four.e_n, four.e_t);
                for k in 0..LANES {
                    let one = |c: &Chunk| lanes::lane(c, k).to_array();
                    let scalar = springs.head::<f32>(one(&skin), one(&ci), true);
                    assert_eq!(bits(one(&four.rest)), bits(scalar.rest));
                    assert_eq!(bits(one(&four.e_t)), bits(scalar.e_t));
                    assert_eq!(four.e_n.as_array()[k].to_bits(), scalar.e_n.to_bits());
                    let four_slips = four.slipping.to_bitmask() & (1 << k) != 0;
                    assert_eq!(four_slips, scalar.slipping, "sample {}", 4 * j + k);
                    slipped += usize::from(scalar.slipping);
                    let one_tail = springs.tail(one(&skin), one(&ci), scalar.e_n, scalar.e_t);
                    assert_eq!(bits(one(&tail)), bits(one_tail));
                }
            }
            assert!(slipped > 0 && slipped < 8, "{slipped} of 8 slip");
        }
    }
}
