//! A skin patch's deviation springs ([`super`]): how far each sample's
//! point on the object has moved from its point on the skin, four samples
//! at a time, or eight in the AVX2 build (`wide8.rs`).

#[cfg(target_arch = "x86_64")]
mod wide8;

use super::{PatchScratch, PatchStep, Samples, damping_lag};
use crate::contact::ObjectView;
use crate::contact::lanes::{self, Chunk, LANES, Mat3Lanes};
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
/// which of them slip (all bits set in a lane that slips).
#[derive(Debug, Clone, Copy)]
pub(super) struct Head {
    pub rest: Chunk,
    pub e_n: f32x4,
    pub e_t: Chunk,
    pub slipping: f32x4,
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
    /// `ci` and valid lanes `valid`.
    #[inline(always)]
    fn head(&self, skin: Chunk, ci: Chunk, valid: f32x4) -> Head {
        let rest = lanes::add(self.c, lanes::mat_mul(&self.skin_rot, skin));
        let e = lanes::sub(ci, rest);
        let e_dot_n = lanes::dot(e, self.n);
        let e_n = if self.clamped { e_dot_n.fast_clamp(self.lower, self.limit) } else { e_dot_n };
        let e_t = lanes::sub(e, lanes::scale(e_dot_n, self.n));
        let slipping = lanes::dot(e_t, e_t).simd_gt(self.cone) & valid;
        Head { rest, e_n, e_t, slipping }
    }

    /// A chunk's deviations from its head (its slips done): the damping of
    /// their rates, and the rocking spring on the normal part.
    #[inline(always)]
    fn tail(&self, skin: Chunk, ci: Chunk, e_n: f32x4, e_t: Chunk) -> Chunk {
        let spin = lanes::cross(self.angvel, lanes::sub(ci, self.c));
        let e_rate = lanes::sub(spin, lanes::mat_mul(&self.skin_rate, skin));
        let rate_n = lanes::dot(e_rate, self.n);
        let rate_t = lanes::sub(e_rate, lanes::scale(rate_n, self.n));
        // Scaled so that γ/N times it is the rocking spring k/N on e_n.
        let rocking_stretch = self.rock * (e_n + self.rocking_lag * rate_n);
        let damped = lanes::add(e_t, lanes::scale(self.lag, rate_t));
        lanes::add(damped, lanes::scale(rocking_stretch, self.n))
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
/// same operations on each lane, so the same bits.
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
    head: Head,
) {
    let Head { rest, e_n, mut e_t, slipping } = head;
    let mut ci = scratch.points.chunks()[j];
    if slipping.any() {
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
