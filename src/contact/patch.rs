//! Skin patches (thesis §3.5.4): a contact's force is spread over N sample
//! points on the object's surface around C.
//!
//! Each sample carries `1/N` of the contact force. On top of that, each
//! sample is a small spring of stiffness `γ/N` between its point on the
//! object and its point on the skin. Those springs' mean is removed, so they
//! add **no net force** (the total equals the single-point force exactly)
//! but resist twisting and rocking of the object against the skin: the
//! stabilising effect the thesis reports for 9 samples over 1.

mod deviation;

use super::lanes::{self, Chunk, Vec3Lanes};
use super::surface;
use super::{LawSettings, ObjectView};
use crate::friction::FrictionCoefficients;
use glam::{Mat3, Vec3};
use wide::f32x4;

/// Patch sizes per skin class (§3.5.4: thumb and palm patches are wider).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PatchConfig {
    /// Samples per contact, ≥ 1. The thesis uses 8–9.
    pub samples: usize,
    /// Patch radius of index to pinky bones (m).
    pub finger_radius: f32,
    /// Patch radius of thumb bones (m).
    pub thumb_radius: f32,
    /// Patch radius of the palm (m).
    pub palm_radius: f32,
}

impl Default for PatchConfig {
    /// Finger pads make contact areas about 8–10 mm across; the thumb's is
    /// wider; the palm's, a few centimetres.
    fn default() -> Self {
        PatchConfig { samples: 9, finger_radius: 0.004, thumb_radius: 0.006, palm_radius: 0.03 }
    }
}

/// Offsets of the samples on the tangent plane of normal `n`: the centre,
/// then the others evenly on a circle of `radius`. Their mean is zero for
/// N ≠ 2, so the patch is centred on C.
pub fn sample_offsets(n: Vec3, samples: usize, radius: f32) -> Vec<Vec3> {
    let samples = samples.max(1);
    let (t1, t2) = n.any_orthonormal_pair();
    let ring = samples - 1;
    let mut out = Vec::with_capacity(samples);
    out.push(Vec3::ZERO);
    for k in 0..ring {
        let a = std::f32::consts::TAU * k as f32 / ring as f32;
        out.push(radius * (a.cos() * t1 + a.sin() * t2));
    }
    out
}

/// How many halvings of the search interval fit a patch's ring to its face:
/// to 1/64 of the configured radius.
const FIT_STEPS: usize = 6;

/// The largest ring radius, up to `radius` (m), whose samples all lie on the
/// face of C (normal `n`): a 3 cm palm ring on a 2 cm cube shrinks to the
/// cube's face, instead of wrapping its samples round the edges onto the
/// sides, where they would press sideways. Found by bisection; a ring that
/// fits nowhere leaves every sample at C. Also says whether the face is
/// planar under the ring (every sample's normal within 2.6° of C's): only
/// then may the patch hold the object as a rigid support ([`Rocking`]); a
/// ball or a pencil must still roll.
pub(crate) fn fit_to_face(
    object: &ObjectView,
    c: Vec3,
    n: Vec3,
    samples: usize,
    radius: f32,
) -> (f32, bool) {
    // The least cosine between n and a ring sample's normal, if the ring
    // of radius r fits the face.
    let fit = |r: f32| {
        let cos = |o: &Vec3| surface::face_cos(object.shape, &object.pose, c + *o, n, 0.6 * r);
        let ring = sample_offsets(n, samples, r);
        let least = ring.iter().skip(1).map(cos).try_fold(1.0f32, |l, c| Some(l.min(c?)));
        least.filter(|&l| l >= surface::SAME_FACE_COS)
    };
    let (mut fitting, mut least) = (radius, fit(radius));
    if least.is_none() {
        let mut too_big = radius;
        fitting = 0.0;
        for _ in 0..FIT_STEPS {
            let mid = 0.5 * (fitting + too_big);
            match fit(mid) {
                Some(l) => (fitting, least) = (mid, Some(l)),
                None => too_big = mid,
            }
        }
    }
    let planar = fitting > 0.0 && least.is_some_and(|l| l >= PLANAR_COS);
    (fitting, planar)
}

/// The least cosine between sample normals for a face to count as planar.
pub(crate) const PLANAR_COS: f32 = 0.999;

/// The per-sample forces on the object.
///
/// * `total`: the contact's force on the object (N).
/// * `deviations[i]`: `e_i = (C_i − C) − (p_i − p)`, how far sample i's
///   object point has moved from its skin point, relative to the patch
///   centre (m); already limited by the caller's torsional friction.
/// * `stiffness`: γ (N/m), split as γ/N per sample.
pub fn sample_forces(total: Vec3, deviations: &[Vec3], stiffness: f32, out: &mut Vec<Vec3>) {
    let mut forces = Vec3Lanes::default();
    lane_forces(total, &Vec3Lanes::from_items(deviations.iter().copied()), stiffness, &mut forces);
    out.clear();
    out.extend(forces.iter());
}

/// [`sample_forces`] on lanes: `f_i = f/N − γ/N·(e_i − ē)`, so the
/// deviation springs add no net force.
#[inline]
fn lane_forces(total: Vec3, deviations: &Vec3Lanes, stiffness: f32, out: &mut Vec3Lanes) {
    let n = deviations.len().max(1) as f32;
    let mean = lanes::splat(deviations.sum() / n);
    let share = lanes::splat(total / n);
    let k = f32x4::splat(stiffness / n);
    out.reset(deviations.len());
    for (f, e) in out.chunks_mut().iter_mut().zip(deviations.chunks()) {
        *f = lanes::sub(share, lanes::scale(k, lanes::sub(*e, mean)));
    }
}

/// `dt²·K/I` of the rocking springs of all patches on one object together,
/// for a rotational stiffness K: 1/16 of the explicit integrator's bound
/// (`dt²·K/I < 4`), leaving room for the contact springs and dampers.
const ROCKING_SHARE: f32 = 0.25;

/// How a patch resists rocking: the normal parts of its deviation springs.
///
/// A flat face on a flat bone (a box on the palm) is held upright by
/// where the pressure sits under it, not by how soft the skin is. With the
/// deviation springs at γ/N, a box on a palm of γ 400 N/m rocks by degrees
/// and a 5 cm tall one topples long before it would slide. So on a flat
/// bone ([`Rocking::rigid`]) the normal deviations get the stiffest spring
/// the explicit integrator carries stably, whatever γ: the patch acts as a
/// rigid support, and [`push_only`] keeps every sample's push ≥ 0, so the
/// pressure can move only within the patch, as on a real face. So does a
/// line along a finger bone lying on a flat face (`line.rs`). A finger's
/// pad pressed with its round end is round, and an object rolls on it:
/// its patch stays soft ([`Rocking::soft`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Rocking {
    /// The patch's total normal stiffness against rocking (N/m), k/N per
    /// sample; at least γ.
    pub stiffness: f32,
    /// The damping of that motion, as stretch per unit rate (s).
    pub lag: f32,
    /// Whether each sample's normal deviation is held to `f_n/k`, so that
    /// its push stays within [0, 2f_n/N] (soft pads).
    pub clamped: bool,
}

impl Rocking {
    /// The deviation springs of a soft pad: γ/N, damped as the contact.
    pub fn soft(object: &ObjectView) -> Rocking {
        let lag = damping_lag(object.damping, object.gamma);
        Rocking { stiffness: object.gamma, lag, clamped: true }
    }

    /// The rocking springs of a patch of `samples` on a ring of `radius`
    /// (m). Their mean is removed, so they only turn the object: about a
    /// tangent axis they make a rotational stiffness `K = (k/N)·Σx²`, with
    /// `Σx² = (N − 1)·r²/2` over the ring. K is set to
    /// `ROCKING_SHARE · I_min / dt²` shared by the object's contacts, and
    /// damped at the contacts' damping ratio.
    pub fn rigid(
        object: &ObjectView,
        samples: usize,
        radius: f32,
        settings: &LawSettings,
    ) -> Rocking {
        let ring = samples.saturating_sub(1) as f32 * radius * radius / 2.0;
        let dt2 = settings.dt * settings.dt;
        let turning = ROCKING_SHARE / (object.sharing * dt2 * object.inv_inertia);
        let rigid = samples as f32 * turning / ring;
        if !(rigid.is_finite() && rigid > object.gamma) {
            return Rocking::soft(object);
        }
        // Critical damping of K on I is 2√(K·I); ζ of it, per unit of K.
        let share = ROCKING_SHARE / object.sharing;
        let lag = 2.0 * settings.damping_ratio * settings.dt / share.sqrt();
        Rocking { stiffness: rigid, lag, clamped: false }
    }
}

/// Skin pushes and never pulls: each sample's push along `−n` (`n` the
/// object's outward normal) is held to ≥ 0, and the pushes are rescaled to
/// keep their sum, so the patch still transmits exactly the contact's
/// force. A box rocking over the patch's edge then rests on its downhill
/// samples alone, its pressure up to 0.8 of the ring's radius from C, as a
/// real face's moves towards its edge; a sample that would pull is let go.
pub fn push_only(forces: &mut [Vec3], n: Vec3) {
    let mut lanes = Vec3Lanes::from_items(forces.iter().copied());
    lane_push_only(&mut lanes, n);
    for (f, pushed) in forces.iter_mut().zip(lanes.iter()) {
        *f = pushed;
    }
}

/// [`push_only`] on lanes; the sums are taken in sample order.
#[inline]
fn lane_push_only(forces: &mut Vec3Lanes, n: Vec3) {
    let normal = lanes::splat(n);
    let push = |f: &Chunk| -lanes::dot(*f, normal);
    let (mut total, mut pressing) = (0.0f32, 0.0f32);
    for (j, f) in forces.chunks().iter().enumerate() {
        for &p in push(f).as_array().iter().take(forces.used(j)) {
            total += p;
            pressing += p.max(0.0);
        }
    }
    if total <= 0.0 || pressing <= total {
        return; // nothing pulls, or nothing presses
    }
    let scale = f32x4::splat(total / pressing);
    for f in forces.chunks_mut() {
        let p = push(f);
        let kept = p.max(f32x4::ZERO) * scale - p;
        *f = lanes::sub(*f, lanes::scale(kept, normal));
    }
}

/// A damper `damping` (N·s/m) on a spring `gamma` (N/m) folded into the
/// spring as extra stretch per unit rate, `c/γ` (s).
#[inline]
pub(super) fn damping_lag(damping: f32, gamma: f32) -> f32 {
    if gamma > 0.0 { damping / gamma } else { 0.0 }
}

/// A contact's patch as one step sees it (world).
#[derive(Debug, Clone, Copy)]
pub(crate) struct PatchStep {
    /// The contact point C and the normal there.
    pub center: Vec3,
    pub normal: Vec3,
    /// The skin frame's rotation now, and its rate (per s).
    pub skin: Mat3,
    pub skin_rate: Mat3,
    /// The contact's force on the object (N) and its normal magnitude.
    pub force: Vec3,
    pub normal_force: f32,
    /// The contact's stiffness γ (N/m) and damping (N·s/m).
    pub gamma: f32,
    pub damping: f32,
    pub mu: FrictionCoefficients,
    pub rocking: Rocking,
    /// Whether the samples' deviation springs act (off: `f/N` each).
    pub deviation_springs: bool,
    /// The object's spin that moves the samples against the skin (rad/s):
    /// its angular velocity, less what a roll took up (`Anchor::rolled`).
    pub spin: Vec3,
}

/// Buffers reused from step to step.
#[derive(Debug, Default)]
pub(crate) struct PatchScratch {
    pub(super) deviations: Vec3Lanes,
    /// The last spread contact's forces on the object (N), per sample.
    forces: Vec3Lanes,
    /// Its samples' points (world, m).
    pub(super) points: Vec3Lanes,
    /// Whether `forces` and `points` are the last contact's: cleared
    /// without emptying the buffers, so the next patch of the same size
    /// reuses them as they are.
    applied: bool,
    /// Whether the contact stages run in their AVX2 build, set by it
    /// alone: then the deviation springs take eight samples at a time.
    pub(crate) avx2: bool,
}

impl PatchScratch {
    /// Forgets the last contact's forces: a contact that applies none.
    #[inline]
    pub fn clear(&mut self) {
        self.applied = false;
    }

    /// The last spread contact's samples, if it applies any: their forces
    /// on the object (N) and their points (world, m), four to a chunk.
    /// A loop over them is the caller's, written out: a closure called
    /// from here would be left out of line, in the baseline build.
    #[inline(always)]
    pub fn applied(&self) -> Option<(&Vec3Lanes, &Vec3Lanes)> {
        self.applied.then_some((&self.forces, &self.points))
    }
}

/// Spreads a contact's force over its skin patch: each sample keeps its
/// share of the force plus its deviation spring (tangential γ/N, normal
/// [`Rocking`]), limited by its own share of the friction cone (a sample
/// beyond it slips by the slip rule, which is how a patch slips in
/// torsion). No sample pulls ([`push_only`]). Writes the samples' world
/// points to `points` and leaves `(force on the object, point)` per
/// sample in `scratch` ([`PatchScratch::applied`]).
///
/// Four samples at a time ([`super::lanes`]): the same arithmetic, in the
/// same order, as one sample at a time, so the same bits.
#[inline(always)]
pub(crate) fn spread(
    step: &PatchStep,
    samples: &mut Samples,
    object: &ObjectView,
    scratch: &mut PatchScratch,
    points: &mut Vec<Vec3>,
) {
    let pose = &object.pose;
    let object_rot = lanes::splat_mat(&Mat3::from_quat(pose.rotation));
    let origin = lanes::splat(pose.translation);
    let len = samples.object.len();
    scratch.deviations.reset(len);
    scratch.points.reset(len);
    for j in 0..samples.object.chunks().len() {
        let ci = lanes::add(origin, lanes::mat_mul(&object_rot, samples.object.chunks()[j]));
        scratch.points.chunks_mut()[j] = ci;
    }
    if step.deviation_springs {
        deviation::deviate(step, samples, object, scratch);
    } else {
        // The thesis's patch: each sample carries f/N where it lies.
        scratch.deviations.chunks_mut().fill([f32x4::ZERO; 3]);
    }
    scratch.points.copy_to(points);
    lane_forces(step.force, &scratch.deviations, step.gamma, &mut scratch.forces);
    lane_push_only(&mut scratch.forces, step.normal);
    scratch.applied = true;
}

/// A patch's samples: per sample, its point in the object frame (m) and
/// its skin offset from p in the bone frame (m).
#[derive(Debug, Clone, Default)]
pub(crate) struct Samples {
    pub object: Vec3Lanes,
    pub skin: Vec3Lanes,
}

impl Samples {
    /// Samples from `(object point, skin offset)` pairs.
    pub fn from_pairs(pairs: impl IntoIterator<Item = (Vec3, Vec3)>) -> Samples {
        let mut samples = Samples::default();
        for (object, skin) in pairs {
            samples.object.push(object);
            samples.skin.push(skin);
        }
        samples
    }

    /// How many there are.
    #[inline]
    pub fn len(&self) -> usize {
        self.object.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_are_tangent_centred_and_on_the_circle() {
        let n = Vec3::new(0.3, 0.9, -0.2).normalize();
        let offs = sample_offsets(n, 9, 0.01);
        assert_eq!(offs.len(), 9);
        let mean: Vec3 = offs.iter().copied().sum::<Vec3>() / 9.0;
        assert!(mean.length() < 1e-6);
        for o in &offs[1..] {
            assert!(o.dot(n).abs() < 1e-6);
            assert!((o.length() - 0.01).abs() < 1e-6);
        }
        assert_eq!(sample_offsets(n, 1, 0.01), vec![Vec3::ZERO]);
    }

    #[test]
    fn sample_forces_sum_to_the_contact_force_whatever_the_deviation() {
        let total = Vec3::new(0.1, -2.0, 0.3);
        let devs: Vec<Vec3> =
            (0..9).map(|i| Vec3::new(i as f32 * 1e-3, 0.0, -(i as f32) * 2e-4)).collect();
        let mut out = Vec::new();
        sample_forces(total, &devs, 400.0, &mut out);
        let sum: Vec3 = out.iter().copied().sum();
        assert!((sum - total).length() < 1e-5);
    }
}
