//! The deviation springs ([`super`]) eight samples at a time, for the
//! AVX2 build: [`super::Springs`]'s kernel on [`F32x8`], two chunks of
//! [`crate::contact::lanes`] side by side in one 256-bit register. Each lane
//! does the kernel's operations in the same order, with no fused
//! multiply-add, so the same bits as four at a time.

use super::{Head, Springs};
use crate::contact::lanes::{Chunk, Lane, Vector};
use crate::contact::patch::{PatchScratch, Samples};
use std::arch::x86_64::{
    __m256, _CMP_GT_OS, _mm256_add_ps, _mm256_and_ps, _mm256_castps256_ps128, _mm256_cmp_ps,
    _mm256_extractf128_ps, _mm256_max_ps, _mm256_min_ps, _mm256_movemask_ps, _mm256_mul_ps,
    _mm256_set_m128, _mm256_sub_ps,
};
use std::ops::{Add, BitAnd, Mul, Sub};
use wide::f32x4;

/// Eight `f32` lanes in one AVX register.
///
/// Made only by [`deviate_two`], which runs only where the CPU has AVX2:
/// so every value of this type is on such a CPU, and its operations'
/// intrinsics may run. They are inlined into `deviate_two`'s AVX2 code.
#[derive(Debug, Clone, Copy)]
pub(super) struct F32x8(__m256);

/// Calls an AVX intrinsic on [`F32x8`]s, which exist only where AVX2 does.
macro_rules! avx {
    ($e:expr) => {
        // SAFETY: an `F32x8` exists only on a CPU with AVX2 (its doc).
        unsafe { $e }
    };
}

/// An operator on [`F32x8`]s, lane by lane, by its AVX intrinsic.
macro_rules! lanewise {
    ($($op:ident, $method:ident, $intrinsic:ident;)*) => {$(
        impl $op for F32x8 {
            type Output = F32x8;
            #[inline(always)]
            fn $method(self, b: F32x8) -> F32x8 {
                F32x8(avx!($intrinsic(self.0, b.0)))
            }
        }
    )*};
}

lanewise! {
    Add, add, _mm256_add_ps;
    Sub, sub, _mm256_sub_ps;
    Mul, mul, _mm256_mul_ps;
    BitAnd, bitand, _mm256_and_ps;
}

impl Lane for F32x8 {
    type Mask = F32x8;

    #[inline(always)]
    fn widen(v: f32x4) -> F32x8 {
        F32x8::join(v, v)
    }

    #[inline(always)]
    fn clamp(self, lower: F32x8, upper: F32x8) -> F32x8 {
        // `f32x4::fast_clamp`'s operand order: a NaN lane stays NaN.
        F32x8(avx!(_mm256_max_ps(lower.0, _mm256_min_ps(upper.0, self.0))))
    }

    #[inline(always)]
    fn gt(self, other: F32x8) -> F32x8 {
        F32x8(avx!(_mm256_cmp_ps::<_CMP_GT_OS>(self.0, other.0)))
    }

    #[inline(always)]
    fn any(mask: F32x8) -> bool {
        avx!(_mm256_movemask_ps(mask.0)) != 0
    }
}

impl F32x8 {
    /// `lo` in the low four lanes, `hi` in the high four.
    #[inline(always)]
    fn join(lo: f32x4, hi: f32x4) -> F32x8 {
        F32x8(avx!(_mm256_set_m128(hi.into(), lo.into())))
    }

    /// The low four lanes and the high four.
    #[inline(always)]
    fn split(self) -> (f32x4, f32x4) {
        avx!((_mm256_castps256_ps128(self.0).into(), _mm256_extractf128_ps::<1>(self.0).into()))
    }
}

#[inline(always)]
fn join3(lo: &Chunk, hi: &Chunk) -> Vector<F32x8> {
    [F32x8::join(lo[0], hi[0]), F32x8::join(lo[1], hi[1]), F32x8::join(lo[2], hi[2])]
}

#[inline(always)]
fn split3(v: Vector<F32x8>) -> (Chunk, Chunk) {
    let [(x0, x1), (y0, y1), (z0, z1)] = v.map(F32x8::split);
    ([x0, y0, z0], [x1, y1, z1])
}

/// Chunks `j` and `j + 1` of the deviations ([`super::deviate`]),
/// eight samples at once. If any of them slips, nothing is written, and
/// the two chunks' heads are returned for the four-lane slip and tail.
///
/// # Safety
/// The CPU must have AVX2.
#[target_feature(enable = "avx2")]
pub(super) unsafe fn deviate_two(
    springs: &Springs,
    samples: &Samples,
    scratch: &mut PatchScratch,
    j: usize,
) -> Option<[Head<f32x4>; 2]> {
    let (skin, points) = (samples.skin.chunks(), scratch.points.chunks());
    let skin = join3(&skin[j], &skin[j + 1]);
    let ci = join3(&points[j], &points[j + 1]);
    let valid = F32x8::join(samples.object.valid(j), samples.object.valid(j + 1));
    let Head { rest, e_n, e_t, slipping } = springs.head(skin, ci, valid);
    if F32x8::any(slipping) {
        let [(rest0, rest1), (t0, t1)] = [split3(rest), split3(e_t)];
        let [(n0, n1), (slip0, slip1)] = [e_n.split(), slipping.split()];
        let head0 = Head { rest: rest0, e_n: n0, e_t: t0, slipping: slip0 };
        return Some([head0, Head { rest: rest1, e_n: n1, e_t: t1, slipping: slip1 }]);
    }
    let (d0, d1) = split3(springs.tail(skin, ci, e_n, e_t));
    let deviations = scratch.deviations.chunks_mut();
    (deviations[j], deviations[j + 1]) = (d0, d1);
    None
}

#[cfg(test)]
mod tests {
    use super::super::tests::{samples, springs};
    use super::*;
    use crate::contact::lanes;

    #[test]
    fn eight_at_a_time_has_the_bits_of_four_at_a_time() {
        if !std::arch::is_x86_feature_detected!("avx2") {
            return;
        }
        let bits = |c: &Chunk| c.map(|x| x.to_array().map(f32::to_bits));
        for clamped in [false, true] {
            let springs = springs(clamped);
            let mut samples = samples(&springs);
            let heads: Vec<Head<f32x4>> = (0..2)
                .map(|j| {
                    let (skin, ci) = (samples.skin.chunks()[j], samples.object.chunks()[j]);
                    springs.head(skin, ci, samples.object.valid(j))
                })
                .collect();
            // Some slip: the two chunks' heads come back as four at a time.
            let (points, deviations) = (samples.object.clone(), samples.object.clone());
            let mut scratch = PatchScratch { points, deviations, ..PatchScratch::default() };
            // SAFETY: the CPU has AVX2 (checked above).
            let eight = unsafe { deviate_two(&springs, &samples, &mut scratch, 0) };
            let eight = eight.expect("some of the samples slip");
            for (four, eight) in heads.iter().zip(&eight) {
                assert_eq!(bits(&four.rest), bits(&eight.rest));
                assert_eq!(bits(&four.e_t), bits(&eight.e_t));
                assert_eq!(
                    four.e_n.to_array().map(f32::to_bits),
                    eight.e_n.to_array().map(f32::to_bits)
                );
                assert_eq!(four.slipping.to_bitmask(), eight.slipping.to_bitmask());
            }
            // None slips (the points on their skin points, pressed in):
            // the tails are written, as four at a time would.
            let rest: Vec<_> = heads
                .iter()
                .map(|h| lanes::add(h.rest, lanes::scale(f32x4::splat(2e-4), springs.n)))
                .collect();
            samples.object.chunks_mut().copy_from_slice(&rest);
            scratch.points = samples.object.clone();
            // SAFETY: as above.
            assert!(unsafe { deviate_two(&springs, &samples, &mut scratch, 0) }.is_none());
            for j in 0..2 {
                let (skin, ci) = (samples.skin.chunks()[j], samples.object.chunks()[j]);
                let head = springs.head(skin, ci, samples.object.valid(j));
                assert!(!head.slipping.any());
                let four = springs.tail(skin, ci, head.e_n, head.e_t);
                assert_eq!(bits(&four), bits(&scratch.deviations.chunks()[j]));
            }
        }
    }
}
