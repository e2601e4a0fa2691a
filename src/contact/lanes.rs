//! Vectors laid out for SIMD: a skin patch's samples, four to a register.
//!
//! Chunk `j` of a [`Vec3Lanes`] holds items `4j..4j + 4` as three `f32x4`
//! (their x, y and z), so one instruction does the same arithmetic for four
//! samples, and a dot product needs no shuffles. Each lane computes exactly
//! the expression the scalar code would (`a·b = (x·x' + y·y') + z·z'`, a
//! matrix times a vector column by column, no fused multiply-add), so a
//! lane's bits are those of the scalar `glam` code. Sums across samples are
//! taken lane by lane in sample order ([`Vec3Lanes::sum`]), as a scalar
//! loop would, so they too are the same bits.
//!
//! What the padding lanes of the last chunk hold is unspecified (zeros in a
//! new chunk, a buffer's earlier items in a reused one) and never read:
//! [`Vec3Lanes::sum`] and [`Vec3Lanes::copy_to`] stop at
//! [`Vec3Lanes::len`], [`Vec3Lanes::valid`] masks them out, and a caller
//! given whole chunks is given [`Vec3Lanes::used`] with each.

use glam::{Mat3, Vec3, Vec3A, Vec4};
use std::ops::{Add, BitAnd, Mul, Sub};
use wide::f32x4;

/// Items per chunk.
pub(crate) const LANES: usize = 4;

/// Four vectors: their x, y and z.
pub(crate) type Chunk = [f32x4; 3];

/// A sequence of vectors (units those of its items), in chunks of four.
#[derive(Debug, Clone, Default)]
pub(crate) struct Vec3Lanes {
    chunks: Vec<Chunk>,
    len: usize,
}

impl Vec3Lanes {
    /// The items of `items`, in order.
    pub fn from_items(items: impl IntoIterator<Item = Vec3>) -> Vec3Lanes {
        let mut lanes = Vec3Lanes::default();
        for v in items {
            lanes.push(v);
        }
        lanes
    }

    /// How many items (not lanes) there are.
    #[inline]
    pub fn len(&self) -> usize {
        self.len
    }

    /// `len` items, in a buffer kept from call to call, to be written
    /// chunk by chunk: what they hold before is left unspecified (zeros in
    /// new chunks, the last call's items in kept ones).
    #[inline]
    pub fn reset(&mut self, len: usize) {
        self.chunks.resize(len.div_ceil(LANES), [f32x4::ZERO; 3]);
        self.len = len;
    }

    /// Appends an item.
    pub fn push(&mut self, v: Vec3) {
        if self.len.is_multiple_of(LANES) {
            self.chunks.push([f32x4::ZERO; 3]);
        }
        self.len += 1;
        self.set(self.len - 1, v);
    }

    /// Item `i` (< [`Self::len`]).
    #[inline]
    pub fn get(&self, i: usize) -> Vec3 {
        lane(&self.chunks[i / LANES], i % LANES)
    }

    /// Sets item `i` (< [`Self::len`]).
    #[inline]
    pub fn set(&mut self, i: usize, v: Vec3) {
        set_lane(&mut self.chunks[i / LANES], i % LANES, v);
    }

    /// The items, in order.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = Vec3> + '_ {
        (0..self.len).map(|i| self.get(i))
    }

    /// Sets `out` to the items, in order, reusing its buffer.
    #[inline(always)]
    pub fn copy_to(&self, out: &mut Vec<Vec3>) {
        out.resize(self.len, Vec3::ZERO);
        for (items, chunk) in out.chunks_mut(LANES).zip(&self.chunks) {
            let vectors = f32x4::transpose([chunk[0], chunk[1], chunk[2], chunk[2]]);
            for (item, v) in items.iter_mut().zip(vectors) {
                let [x, y, z, _] = v.to_array();
                *item = Vec3::new(x, y, z);
            }
        }
    }

    /// How many lanes of chunk `j` hold items (0 to [`LANES`]).
    #[inline]
    pub fn used(&self, j: usize) -> usize {
        self.len.saturating_sub(j * LANES).min(LANES)
    }

    /// Which lanes of chunk `j` hold items, as a bitmask.
    #[inline]
    pub fn used_mask(&self, j: usize) -> u32 {
        (1 << self.used(j)) - 1
    }

    /// The chunks, the last one padded.
    #[inline]
    pub fn chunks(&self) -> &[Chunk] {
        &self.chunks
    }

    /// The chunks, to write.
    #[inline]
    pub fn chunks_mut(&mut self) -> &mut [Chunk] {
        &mut self.chunks
    }

    /// The sum of the items, added in order from zero, as glam's `Sum`: a
    /// whole chunk by one transpose ([`add_in_order`]), a padded one lane
    /// by lane.
    pub fn sum(&self) -> Vec3 {
        let mut sum = Vec3A::ZERO;
        for (j, chunk) in self.chunks.iter().enumerate() {
            match self.used(j) {
                LANES => add_in_order(&mut sum, chunk),
                used => (0..used).for_each(|k| sum += Vec3A::from(lane(chunk, k))),
            }
        }
        sum.into()
    }

    /// Which lanes of chunk `j` hold items: a mask of all ones for those.
    #[inline]
    pub fn valid(&self, j: usize) -> f32x4 {
        const ON: f32 = f32::from_bits(u32::MAX);
        /// The mask of `used` lanes, by `used`.
        const MASKS: [[f32; LANES]; LANES + 1] =
            [[0.0; LANES], [ON, 0.0, 0.0, 0.0], [ON, ON, 0.0, 0.0], [ON, ON, ON, 0.0], [ON; LANES]];
        f32x4::new(MASKS[self.used(j)])
    }
}

/// Lane `k` of `chunk` as a vector.
#[inline]
pub(crate) fn lane(chunk: &Chunk, k: usize) -> Vec3 {
    Vec3::new(chunk[0].as_array()[k], chunk[1].as_array()[k], chunk[2].as_array()[k])
}

/// Sets lane `k` of `chunk`.
#[inline]
pub(crate) fn set_lane(chunk: &mut Chunk, k: usize, v: Vec3) {
    chunk[0].as_mut_array()[k] = v.x;
    chunk[1].as_mut_array()[k] = v.y;
    chunk[2].as_mut_array()[k] = v.z;
}

/// `v` in every lane.
#[inline]
pub(crate) fn splat(v: Vec3) -> Chunk {
    [f32x4::splat(v.x), f32x4::splat(v.y), f32x4::splat(v.z)]
}

/// One register of `f32` lanes, as the contact kernels compute on it:
/// `f32x4` here, eight lanes in the AVX2 build
/// (`patch/deviation/wide8.rs`), and a plain `f32`, one lane, the scalar
/// reading that the kernels' tests compare with. A kernel written once on
/// a `Lane` does the same operations in the same order on each lane,
/// whatever the width: so the same bits.
pub(crate) trait Lane:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self>
{
    /// A comparison's result, lane by lane.
    type Mask: Copy + BitAnd<Output = Self::Mask>;

    /// A four-lane constant (the same value in each lane) in every lane.
    fn widen(v: f32x4) -> Self;

    /// Each lane held within `[lower, upper]`, as `f32x4::fast_clamp`: a
    /// NaN stays NaN, and a zero within bounds of zero keeps its sign.
    fn clamp(self, lower: Self, upper: Self) -> Self;

    /// Where `self > other`.
    fn gt(self, other: Self) -> Self::Mask;

    /// Whether any lane of `mask` is set.
    fn any(mask: Self::Mask) -> bool;
}

impl Lane for f32x4 {
    type Mask = f32x4;

    #[inline(always)]
    fn widen(v: f32x4) -> f32x4 {
        v
    }

    #[inline(always)]
    fn clamp(self, lower: f32x4, upper: f32x4) -> f32x4 {
        self.fast_clamp(lower, upper)
    }

    #[inline(always)]
    fn gt(self, other: f32x4) -> f32x4 {
        self.simd_gt(other)
    }

    #[inline(always)]
    fn any(mask: f32x4) -> bool {
        mask.any()
    }
}

impl Lane for f32 {
    type Mask = bool;

    #[inline(always)]
    fn widen(v: f32x4) -> f32 {
        v.as_array()[0]
    }

    #[inline(always)]
    fn clamp(self, lower: f32, upper: f32) -> f32 {
        if self < lower {
            lower
        } else if self > upper {
            upper
        } else {
            self
        }
    }

    #[inline(always)]
    fn gt(self, other: f32) -> bool {
        self > other
    }

    #[inline(always)]
    fn any(mask: bool) -> bool {
        mask
    }
}

/// Vectors in lanes: their x, y and z, each a [`Lane`].
pub(crate) type Vector<W> = [W; 3];

/// `a + b`, lane by lane.
#[inline(always)]
pub(crate) fn add<W: Lane>(a: Vector<W>, b: Vector<W>) -> Vector<W> {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a − b`, lane by lane.
#[inline(always)]
pub(crate) fn sub<W: Lane>(a: Vector<W>, b: Vector<W>) -> Vector<W> {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `s·a`, lane by lane.
#[inline(always)]
pub(crate) fn scale<W: Lane>(s: W, a: Vector<W>) -> Vector<W> {
    [s * a[0], s * a[1], s * a[2]]
}

/// `a·b = (a.x·b.x + a.y·b.y) + a.z·b.z`, lane by lane.
#[inline(always)]
pub(crate) fn dot<W: Lane>(a: Vector<W>, b: Vector<W>) -> W {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a × b`, lane by lane.
#[inline(always)]
pub(crate) fn cross<W: Lane>(a: Vector<W>, b: Vector<W>) -> Vector<W> {
    [a[1] * b[2] - b[1] * a[2], a[2] * b[0] - b[2] * a[0], a[0] * b[1] - b[0] * a[1]]
}

/// A four-lane constant vector ([`splat`]) in every lane of `W`.
#[inline(always)]
pub(crate) fn widen<W: Lane>(v: &Chunk) -> Vector<W> {
    v.map(W::widen)
}

/// Which lanes of `c` hold a vector other than zero, as a bitmask (`-0.0`
/// is zero, as in `glam`'s `!=`).
#[inline]
pub(crate) fn nonzero(c: &Chunk) -> u32 {
    let zero = f32x4::ZERO;
    !(c[0].simd_eq(zero) & c[1].simd_eq(zero) & c[2].simd_eq(zero)).to_bitmask() & 0b1111
}

/// `c`'s lanes whose bit `mask` has, `-0.0` in the others. `x + (-0.0)` is
/// `x` for every `x`, zeros' signs included, so a sum that adds a lane left
/// out has the bits of one that skips it ([`add_in_order`]).
#[inline]
pub(crate) fn keep(c: &Chunk, mask: u32) -> Chunk {
    let kept = f32x4::new(LANE_MASKS[(mask & 0b1111) as usize]);
    c.map(|x| kept.bitselect(x, f32x4::splat(-0.0)))
}

/// Per bitmask of lanes, a mask with all of a lane's bits set where it has
/// the lane's bit.
const LANE_MASKS: [[f32; LANES]; 1 << LANES] = {
    let mut masks = [[0.0; LANES]; 1 << LANES];
    let mut mask = 0;
    while mask < 1 << LANES {
        let mut k = 0;
        while k < LANES {
            if mask & (1 << k) != 0 {
                masks[mask][k] = f32::from_bits(u32::MAX);
            }
            k += 1;
        }
        mask += 1;
    }
    masks
};

/// The four vectors of `c`, in lane order, by one transpose.
#[inline]
pub(crate) fn vectors(c: &Chunk) -> [Vec3A; LANES] {
    // The fourth lane of each, z again, is never read.
    f32x4::transpose([c[0], c[1], c[2], c[2]])
        .map(|v| Vec3A::from_vec4(Vec4::from_array(v.to_array())))
}

/// Adds the four vectors of `c` to `sum` one after another, in lane order:
/// the sums, and so the bits, of a loop over them.
#[inline]
pub(crate) fn add_in_order(sum: &mut Vec3A, c: &Chunk) {
    for v in vectors(c) {
        *sum += v;
    }
}

/// A matrix's columns, each in every lane: splat once, multiply many.
pub(crate) type Mat3Lanes = [Chunk; 3];

/// `m`'s columns in every lane.
#[inline]
pub(crate) fn splat_mat(m: &Mat3) -> Mat3Lanes {
    [splat(m.x_axis), splat(m.y_axis), splat(m.z_axis)]
}

/// `m·v`, column by column as glam's `Mat3 * Vec3`: `(x·v.x + y·v.y) + z·v.z`.
#[inline(always)]
pub(crate) fn mat_mul<W: Lane>(m: &Mat3Lanes, v: Vector<W>) -> Vector<W> {
    let [x, y, z] = m;
    let row = |i: usize| W::widen(x[i]) * v[0] + W::widen(y[i]) * v[1] + W::widen(z[i]) * v[2];
    [row(0), row(1), row(2)]
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Quat;

    /// Five vectors with no simple bits: the lanes must give the scalar
    /// code's results exactly, not nearly.
    fn items() -> Vec<Vec3> {
        (0..5)
            .map(|i| {
                let t = i as f32 + 0.37;
                Vec3::new(t.sin() * 0.013, (1.7 * t).cos() * 0.021, (0.3 * t).tan() * 0.007)
            })
            .collect()
    }

    #[test]
    fn items_round_trip_and_padding_is_masked() {
        let lanes = Vec3Lanes::from_items(items());
        assert_eq!(lanes.len(), 5);
        assert_eq!(lanes.chunks().len(), 2);
        assert_eq!(lanes.iter().collect::<Vec<_>>(), items());
        assert_eq!(lanes.valid(0).to_bitmask(), 0b1111);
        assert_eq!(lanes.valid(1).to_bitmask(), 0b0001);
        assert_eq!(lanes.sum(), items().into_iter().sum::<Vec3>());
        // Copied over a longer buffer and a shorter one alike.
        for before in [vec![Vec3::ONE; 7], vec![Vec3::NEG_ONE; 2]] {
            let mut out = before;
            lanes.copy_to(&mut out);
            assert_eq!(out, items());
        }
    }

    #[test]
    fn nonzero_lanes_are_those_glam_calls_nonzero() {
        let items = [Vec3::new(0.0, -0.0, 0.0), Vec3::new(0.0, 0.0, 1e-42), Vec3::ZERO, -Vec3::Y];
        let chunk = Vec3Lanes::from_items(items).chunks()[0];
        let glam = items.iter().enumerate().filter(|(_, v)| **v != Vec3::ZERO);
        assert_eq!(nonzero(&chunk), glam.fold(0, |mask, (k, _)| mask | 1 << k));
        assert_eq!(nonzero(&chunk), 0b1010);
    }

    #[test]
    fn lanes_left_out_of_a_sum_leave_the_bits_of_skipping_them() {
        // Signed zeros in both the items and the sums: adding +0.0 instead
        // of -0.0 would turn a -0.0 sum into +0.0.
        let items = [Vec3::new(-0.0, 0.25, -0.0), Vec3::new(1e-3, -0.0, 0.0), -Vec3::Z, Vec3::NAN];
        let chunk = Vec3Lanes::from_items(items).chunks()[0];
        for start in [Vec3::new(-0.0, -0.0, 0.0), Vec3::new(3.5, -0.0, -7e-4)] {
            for mask in 0..1 << LANES {
                let mut lanes = Vec3A::from(start);
                add_in_order(&mut lanes, &keep(&chunk, mask));
                let kept = items.iter().enumerate().filter(|(k, _)| mask & 1 << k != 0);
                let skipped = kept.fold(start, |sum, (_, v)| sum + *v);
                let bits = |v: Vec3| v.to_array().map(f32::to_bits);
                assert_eq!(bits(lanes.into()), bits(skipped), "mask {mask:04b} from {start}");
            }
        }
    }

    #[test]
    fn lane_arithmetic_has_the_scalar_bits() {
        let (a, b) =
            (Vec3Lanes::from_items(items()), Vec3Lanes::from_items(items().into_iter().rev()));
        let m = Mat3::from_quat(Quat::from_euler(glam::EulerRot::XYZ, 0.3, -1.1, 2.4));
        let (ca, cb) = (a.chunks()[0], b.chunks()[0]);
        for k in 0..LANES {
            let (x, y) = (a.get(k), b.get(k));
            assert_eq!(lane(&cross(ca, cb), k), x.cross(y));
            assert_eq!(dot(ca, cb).as_array()[k], x.dot(y));
            assert_eq!(lane(&mat_mul(&splat_mat(&m), ca), k), m * x);
            assert_eq!(lane(&sub(add(ca, cb), scale(f32x4::splat(0.7), cb)), k), x + y - 0.7 * y);
        }
    }
}
