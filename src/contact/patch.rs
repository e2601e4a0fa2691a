//! Skin patches (thesis §3.5.4): a contact's force is spread over N sample
//! points on the object's surface around C.
//!
//! Each sample carries `1/N` of the contact force. On top of that, each
//! sample is a small spring of stiffness `γ/N` between its point on the
//! object and its point on the skin. Those springs' mean is removed, so they
//! add **no net force** (the total equals the single-point force exactly)
//! but resist twisting and rocking of the object against the skin: the
//! stabilising effect the thesis reports for 9 samples over 1.

use super::ObjectView;
use super::anchor::Anchor;
use super::surface;
use crate::friction::{FrictionCoefficients, slipped_stretch, slips};
use glam::{Mat3, Vec3};

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

/// The per-sample forces on the object.
///
/// * `total`: the contact's force on the object (N).
/// * `deviations[i]`: `e_i = (C_i − C) − (p_i − p)`, how far sample i's
///   object point has moved from its skin point, relative to the patch
///   centre (m); already limited by the caller's torsional friction.
/// * `stiffness`: γ (N/m), split as γ/N per sample.
#[inline]
pub fn sample_forces(total: Vec3, deviations: &[Vec3], stiffness: f32, out: &mut Vec<Vec3>) {
    out.clear();
    let n = deviations.len().max(1) as f32;
    let mean = deviations.iter().copied().sum::<Vec3>() / n;
    out.extend(deviations.iter().map(|e| total / n - stiffness / n * (*e - mean)));
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
}

/// Buffers reused from step to step.
#[derive(Debug, Default)]
pub(crate) struct PatchScratch {
    deviations: Vec<Vec3>,
    sample_forces: Vec<Vec3>,
    /// `(force on the object, point)` per sample: each spread appends its
    /// contact's.
    pub applied: Vec<(Vec3, Vec3)>,
}

/// Spreads a contact's force over its skin patch: each sample keeps its
/// share of the force plus its deviation spring, limited by its own share
/// of the friction cone (a sample beyond it slips by the slip rule, which
/// is how a patch slips in torsion). Writes the samples' world points to
/// `points` and appends `(force on the object, point)` per sample to
/// `scratch.applied`.
pub(crate) fn spread(
    step: &PatchStep,
    anchor: &mut Anchor,
    object: &ObjectView,
    scratch: &mut PatchScratch,
    points: &mut Vec<Vec3>,
) {
    let pose = &object.pose;
    let (c, n) = (step.center, step.normal);
    // Rotations as matrices: each is applied to every sample.
    let object_rot = Mat3::from_quat(pose.rotation);
    // Damping of the deviations, folded in as extra stretch c/γ · ė.
    let lag = if step.gamma > 0.0 { step.damping / step.gamma } else { 0.0 };
    let normal_limit = step.normal_force / step.gamma;
    scratch.deviations.clear();
    points.clear();
    for (ci_local, skin) in anchor.samples.iter_mut() {
        let mut ci = pose.translation + object_rot * *ci_local;
        let rest = c + step.skin * *skin;
        let e = ci - rest;
        let e_n = e.dot(n).clamp(-normal_limit, normal_limit);
        let mut e_t = e - e.dot(n) * n;
        if slips(e_t, step.normal_force, step.mu, step.gamma) {
            // This sample slips: its object point moves along the surface.
            e_t = slipped_stretch(e_t, step.normal_force, step.mu, step.gamma);
            ci = surface::project_to_surface(object.shape, pose, rest + e_t + e_n * n);
            *ci_local = pose.inverse_transform_point(ci);
        }
        let e_rate = object.angvel.cross(ci - c) - step.skin_rate * *skin;
        scratch.deviations.push(e_t + e_n * n + lag * e_rate);
        points.push(ci);
    }
    sample_forces(step.force, &scratch.deviations, step.gamma, &mut scratch.sample_forces);
    let forces = scratch.sample_forces.iter().copied();
    scratch.applied.extend(forces.zip(points.iter().copied()));
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
