//! Coordinate conversions from tracker space to the world (thesis §3.3.2,
//! §3.8.1), as composable affine transforms.
//!
//! The world is rapier's: metres, right-handed, y up. The thesis writes its
//! matrices with a `1` in the last column of every row; read literally that
//! is a translation by (1, 1, 1), an evident typesetting slip, so the
//! rotations here have no translation part.

use glam::{Affine3A, Mat3, Quat, Vec3};

/// An affine map from tracker space to world space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Conversion {
    affine: Affine3A,
}

/// Where the tracker sits on a head-mounted display (§3.3.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MountPreset {
    /// Leap Motion on the front plate of an Oculus Rift DK2: (0, 0, 0.08) m.
    OculusDk2,
    /// Leap Motion on top of a HoloLens: (0, 0.07, 0.05) m.
    HoloLens,
}

impl MountPreset {
    /// The mount translation `V` of §3.3.2 as the thesis writes it (m), in
    /// Unity's left-handed frame, where +z is forward.
    pub fn thesis_translation(self) -> Vec3 {
        match self {
            MountPreset::OculusDk2 => Vec3::new(0.0, 0.0, 0.08),
            MountPreset::HoloLens => Vec3::new(0.0, 0.07, 0.05),
        }
    }

    /// The mount translation in this right-handed world, where forward is
    /// −z: the thesis's `V` with z negated, so the tracker sits in front of
    /// the eyes (m).
    pub fn translation(self) -> Vec3 {
        Conversion::right_to_left_handed().point(self.thesis_translation())
    }
}

impl Default for Conversion {
    fn default() -> Self {
        Self::identity()
    }
}

impl Conversion {
    /// The conversion that changes nothing.
    pub fn identity() -> Self {
        Conversion { affine: Affine3A::IDENTITY }
    }

    /// `S_mm→m`: Leap Motion reports millimetres.
    pub fn mm_to_m() -> Self {
        Conversion { affine: Affine3A::from_scale(Vec3::splat(0.001)) }
    }

    /// `M_Desktop→HMD` without the mount (§3.8.1): a 90° rotation about x
    /// and a 180° rotation about z, taking the up-facing (desktop) device
    /// frame to the forward-facing (head-mounted) one:
    /// x → −x, y → −z, z → −y.
    pub fn desktop_to_hmd() -> Self {
        let m = Mat3::from_cols(
            Vec3::new(-1.0, 0.0, 0.0),
            Vec3::new(0.0, 0.0, -1.0),
            Vec3::new(0.0, -1.0, 0.0),
        );
        Conversion { affine: Affine3A::from_mat3(m) }
    }

    /// `T_Mount`: the translation of the tracker on the headset (m).
    pub fn mount_translation(t: Vec3) -> Self {
        Conversion { affine: Affine3A::from_translation(t) }
    }

    /// `R_Mount = R_x(α) · R_y(β) · R_z(γ)` for a tilted mount (radians).
    pub fn mount_rotation(alpha: f32, beta: f32, gamma: f32) -> Self {
        let r = Mat3::from_rotation_x(alpha)
            * Mat3::from_rotation_y(beta)
            * Mat3::from_rotation_z(gamma);
        Conversion { affine: Affine3A::from_mat3(r) }
    }

    /// `S_righthand→lefthand`: negates z, for left-handed engines.
    pub fn right_to_left_handed() -> Self {
        Conversion { affine: Affine3A::from_scale(Vec3::new(1.0, 1.0, -1.0)) }
    }

    /// Attaches tracker space to a moving head: the head's world rotation
    /// and position (the thesis's camera–controller parenting, Fig. 3.26).
    pub fn head_pose(rotation: Quat, position: Vec3) -> Self {
        Conversion { affine: Affine3A::from_rotation_translation(rotation, position) }
    }

    /// A plain translation, e.g. where a desktop device sits in the world (m).
    pub fn translation(t: Vec3) -> Self {
        Self::mount_translation(t)
    }

    /// `self`, then `next`.
    pub fn then(self, next: Conversion) -> Self {
        Conversion { affine: next.affine * self.affine }
    }

    /// A desktop (up-facing) Leap Motion whose origin sits at `device` in
    /// the world: millimetres to metres, then that offset. Leap's desktop
    /// axes are already right-handed with y up.
    pub fn leap_desktop(device: Vec3) -> Self {
        Self::mm_to_m().then(Self::translation(device))
    }

    /// A head-mounted Leap Motion (§3.8.1): desktop→HMD, mm→m, the mount's
    /// rotation then translation (in metres, after the unit change), then
    /// the head pose.
    pub fn leap_head_mounted(
        mount: Vec3,
        mount_rotation: (f32, f32, f32),
        head: (Quat, Vec3),
    ) -> Self {
        Self::desktop_to_hmd()
            .then(Self::mm_to_m())
            .then(Self::mount_rotation(mount_rotation.0, mount_rotation.1, mount_rotation.2))
            .then(Self::mount_translation(mount))
            .then(Self::head_pose(head.0, head.1))
    }

    /// Maps a point.
    pub fn point(&self, p: Vec3) -> Vec3 {
        self.affine.transform_point3(p)
    }

    /// Maps a direction (unit in, unit out; zero stays zero).
    pub fn direction(&self, v: Vec3) -> Vec3 {
        self.affine.transform_vector3(v).normalize_or_zero()
    }

    /// Maps a length, such as a finger width, by the mean scale.
    pub fn length(&self, l: f32) -> f32 {
        l * self.affine.matrix3.determinant().abs().cbrt()
    }

    /// Whether the map mirrors space (an odd number of handedness flips).
    pub fn mirrors(&self) -> bool {
        self.affine.matrix3.determinant() < 0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Vec3, b: Vec3) -> bool {
        (a - b).length() < 1e-5
    }

    #[test]
    fn desktop_to_hmd_matches_the_thesis_matrix() {
        // Rows [-1 0 0; 0 0 -1; 0 -1 0] applied to (1, 2, 3) give (-1, -3, -2).
        let c = Conversion::desktop_to_hmd();
        assert!(close(c.point(Vec3::new(1.0, 2.0, 3.0)), Vec3::new(-1.0, -3.0, -2.0)));
        // A hand 200 mm above an up-facing device is 200 mm in front (−z) of a worn one.
        assert!(close(c.point(Vec3::new(0.0, 200.0, 0.0)), Vec3::new(0.0, 0.0, -200.0)));
        assert!(!c.mirrors(), "a rotation, not a reflection");
    }

    #[test]
    fn mount_presets_and_units() {
        assert_eq!(MountPreset::OculusDk2.thesis_translation(), Vec3::new(0.0, 0.0, 0.08));
        assert_eq!(MountPreset::HoloLens.thesis_translation(), Vec3::new(0.0, 0.07, 0.05));
        // Forward is −z here: the trackers sit in front of the eyes.
        assert_eq!(MountPreset::OculusDk2.translation(), Vec3::new(0.0, 0.0, -0.08));
        assert_eq!(MountPreset::HoloLens.translation(), Vec3::new(0.0, 0.07, -0.05));
        let c = Conversion::mm_to_m()
            .then(Conversion::mount_translation(MountPreset::HoloLens.translation()));
        assert!(close(c.point(Vec3::new(100.0, 0.0, -50.0)), Vec3::new(0.1, 0.07, -0.1)));
        assert!((c.length(18.0) - 0.018).abs() < 1e-7);
    }

    #[test]
    fn mount_rotation_is_rx_ry_rz() {
        // R_x(90°)·R_y(90°)·R_z(90°) applied to x: R_z takes x to y, R_y keeps
        // y, R_x takes y to z.
        let h = std::f32::consts::FRAC_PI_2;
        let c = Conversion::mount_rotation(h, h, h);
        assert!(close(c.point(Vec3::X), Vec3::Z));
        // And applied to z: R_z keeps z, R_y takes z to x, R_x keeps x.
        assert!(close(c.point(Vec3::Z), Vec3::X));
    }

    #[test]
    fn handedness_flip_negates_z_and_mirrors() {
        let c = Conversion::right_to_left_handed();
        assert!(close(c.point(Vec3::new(1.0, 2.0, 3.0)), Vec3::new(1.0, 2.0, -3.0)));
        assert!(c.mirrors());
    }

    #[test]
    fn head_mounted_chain_by_hand() {
        // A point 300 mm above the device (desktop frame) on a DK2 worn at
        // (0, 1.6, 0) turned 90° left (about +y).
        let head = (Quat::from_rotation_y(std::f32::consts::FRAC_PI_2), Vec3::new(0.0, 1.6, 0.0));
        let c = Conversion::leap_head_mounted(
            MountPreset::OculusDk2.translation(),
            (0.0, 0.0, 0.0),
            head,
        );
        // desktop→HMD: (0, 0, -300) mm; → (0, 0, -0.3) m; + the mount 8 cm in front of
        // the eyes: (0, 0, -0.38); head yaw +90° takes -z to -x: (-0.38, 0, 0);
        // + head: (-0.38, 1.6, 0).
        assert!(close(c.point(Vec3::new(0.0, 300.0, 0.0)), Vec3::new(-0.38, 1.6, 0.0)));
        // Directions are rotated, not translated or scaled.
        assert!(close(c.direction(Vec3::Y), Vec3::new(-1.0, 0.0, 0.0)));
    }

    #[test]
    fn leap_desktop_places_the_device() {
        let c = Conversion::leap_desktop(Vec3::new(0.0, 0.75, 0.0));
        assert!(close(c.point(Vec3::new(10.0, 200.0, -30.0)), Vec3::new(0.01, 0.95, -0.03)));
    }
}
