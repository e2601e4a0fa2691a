//! The deviation springs ([`super`]) eight samples at a time, for the
//! AVX2 build: two chunks of [`crate::contact::lanes`] side by side in 256-bit
//! registers. Each lane does `lanes.rs`'s operations in the same order,
//! with no fused multiply-add, so the same bits as four at a time.

use super::{Head, Springs};
use crate::contact::lanes::{Chunk, Mat3Lanes};
use crate::contact::patch::{PatchScratch, Samples};
use std::arch::x86_64::{
    __m256, _CMP_GT_OS, _mm256_add_ps, _mm256_and_ps, _mm256_castps256_ps128, _mm256_cmp_ps,
    _mm256_extractf128_ps, _mm256_max_ps, _mm256_min_ps, _mm256_movemask_ps, _mm256_mul_ps,
    _mm256_set_m128, _mm256_sub_ps,
};
use wide::f32x4;

/// Eight vectors: their x, y and z.
type Chunk8 = [__m256; 3];

/// `lo` in the low four lanes, `hi` in the high four.
#[target_feature(enable = "avx2")]
#[inline]
fn join(lo: f32x4, hi: f32x4) -> __m256 {
    _mm256_set_m128(hi.into(), lo.into())
}

/// The low four lanes and the high four.
#[target_feature(enable = "avx2")]
#[inline]
fn split(v: __m256) -> (f32x4, f32x4) {
    (_mm256_castps256_ps128(v).into(), _mm256_extractf128_ps::<1>(v).into())
}

#[target_feature(enable = "avx2")]
#[inline]
fn join3(lo: &Chunk, hi: &Chunk) -> Chunk8 {
    [join(lo[0], hi[0]), join(lo[1], hi[1]), join(lo[2], hi[2])]
}

#[target_feature(enable = "avx2")]
#[inline]
fn split3(v: Chunk8) -> (Chunk, Chunk) {
    let [(x0, x1), (y0, y1), (z0, z1)] = [split(v[0]), split(v[1]), split(v[2])];
    ([x0, y0, z0], [x1, y1, z1])
}

/// A constant, in all eight lanes.
#[target_feature(enable = "avx2")]
#[inline]
fn wide(v: f32x4) -> __m256 {
    join(v, v)
}

#[target_feature(enable = "avx2")]
#[inline]
fn wide3(v: &Chunk) -> Chunk8 {
    join3(v, v)
}

#[target_feature(enable = "avx2")]
#[inline]
fn add(a: Chunk8, b: Chunk8) -> Chunk8 {
    [_mm256_add_ps(a[0], b[0]), _mm256_add_ps(a[1], b[1]), _mm256_add_ps(a[2], b[2])]
}

#[target_feature(enable = "avx2")]
#[inline]
fn sub(a: Chunk8, b: Chunk8) -> Chunk8 {
    [_mm256_sub_ps(a[0], b[0]), _mm256_sub_ps(a[1], b[1]), _mm256_sub_ps(a[2], b[2])]
}

#[target_feature(enable = "avx2")]
#[inline]
fn scale(s: __m256, a: Chunk8) -> Chunk8 {
    [_mm256_mul_ps(s, a[0]), _mm256_mul_ps(s, a[1]), _mm256_mul_ps(s, a[2])]
}

/// `(a.x·b.x + a.y·b.y) + a.z·b.z`, as `lanes::dot`.
#[target_feature(enable = "avx2")]
#[inline]
fn dot(a: Chunk8, b: Chunk8) -> __m256 {
    let xy = _mm256_add_ps(_mm256_mul_ps(a[0], b[0]), _mm256_mul_ps(a[1], b[1]));
    _mm256_add_ps(xy, _mm256_mul_ps(a[2], b[2]))
}

/// `a × b`, as `lanes::cross`.
#[target_feature(enable = "avx2")]
#[inline]
fn cross(a: Chunk8, b: Chunk8) -> Chunk8 {
    let term =
        |i: usize, j: usize| _mm256_sub_ps(_mm256_mul_ps(a[i], b[j]), _mm256_mul_ps(b[i], a[j]));
    [term(1, 2), term(2, 0), term(0, 1)]
}

/// `m·v`, column by column, as `lanes::mat_mul`.
#[target_feature(enable = "avx2")]
#[inline]
fn mat_mul(m: &Mat3Lanes, v: Chunk8) -> Chunk8 {
    let [x, y, z] = m;
    let row = |i: usize| {
        let xy = _mm256_add_ps(_mm256_mul_ps(wide(x[i]), v[0]), _mm256_mul_ps(wide(y[i]), v[1]));
        _mm256_add_ps(xy, _mm256_mul_ps(wide(z[i]), v[2]))
    };
    [row(0), row(1), row(2)]
}

/// Chunks `j` and `j + 1` of the deviations ([`super::deviate`]),
/// eight samples at once. If any of them slips, nothing is written, and
/// the two chunks' heads are returned for the four-lane slip and tail.
#[target_feature(enable = "avx2")]
pub(super) fn deviate_two(
    s: &Springs,
    samples: &Samples,
    scratch: &mut PatchScratch,
    j: usize,
) -> Option<[Head; 2]> {
    let (skin, points) = (samples.skin.chunks(), scratch.points.chunks());
    let skin = join3(&skin[j], &skin[j + 1]);
    let ci = join3(&points[j], &points[j + 1]);
    let (c, n) = (wide3(&s.c), wide3(&s.n));
    let rest = add(c, mat_mul(&s.skin_rot, skin));
    let e = sub(ci, rest);
    let e_dot_n = dot(e, n);
    // `f32x4::fast_clamp`'s operand order: NaN gives the bound.
    let e_n = if s.clamped {
        _mm256_max_ps(wide(s.lower), _mm256_min_ps(wide(s.limit), e_dot_n))
    } else {
        e_dot_n
    };
    let e_t = sub(e, scale(e_dot_n, n));
    let beyond = _mm256_cmp_ps::<_CMP_GT_OS>(dot(e_t, e_t), wide(s.cone));
    let valid = join(samples.object.valid(j), samples.object.valid(j + 1));
    let slipping = _mm256_and_ps(beyond, valid);
    if _mm256_movemask_ps(slipping) != 0 {
        let [(rest0, rest1), (t0, t1)] = [split3(rest), split3(e_t)];
        let [(n0, n1), (slip0, slip1)] = [split(e_n), split(slipping)];
        let head0 = Head { rest: rest0, e_n: n0, e_t: t0, slipping: slip0 };
        return Some([head0, Head { rest: rest1, e_n: n1, e_t: t1, slipping: slip1 }]);
    }
    let spin = cross(wide3(&s.angvel), sub(ci, c));
    let e_rate = sub(spin, mat_mul(&s.skin_rate, skin));
    let rate_n = dot(e_rate, n);
    let rate_t = sub(e_rate, scale(rate_n, n));
    let lagged = _mm256_add_ps(e_n, _mm256_mul_ps(wide(s.rocking_lag), rate_n));
    let rocking_stretch = _mm256_mul_ps(wide(s.rock), lagged);
    let damped = add(e_t, scale(wide(s.lag), rate_t));
    let (d0, d1) = split3(add(damped, scale(rocking_stretch, n)));
    let deviations = scratch.deviations.chunks_mut();
    (deviations[j], deviations[j + 1]) = (d0, d1);
    None
}
