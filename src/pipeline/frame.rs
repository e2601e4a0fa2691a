//! A host engine's frame and units, and the library's: every number a
//! binding passes across, converted in one place.
//!
//! The library's frame is right-handed with y up, in metres, kilograms and
//! seconds. Unity's is left-handed with y up (z forward), in metres;
//! Unreal's is left-handed with z up (x forward, y right), in centimetres
//! (forces in kg·cm/s², torques in kg·cm²/s²). Godot's is the library's.
//!
//! A host frame is an orthogonal map `P` from the host's axes to the
//! library's, and a length scale `s` (metres per host unit). With `P`'s
//! determinant `d` (−1 for a mirror), points and velocities map by `s·P`,
//! directions by `P`, forces by `s·P` (a host's force unit is kg·unit/s²),
//! and the axial vectors (angular velocity by `d·P`, torque by `d·s²·P`): a
//! mirror turns a turn the other way. A rotation `R` becomes `P·R·Pᵀ`,
//! which is proper even for a mirror: as a quaternion, `q` turned by the
//! proper part `d·P`.

use glam::{Mat3, Quat, Vec3};

/// A host engine's frame and length unit ([`Self::LIBRARY`], [`Self::UNITY`],
/// [`Self::UNREAL`], or [`Self::by_name`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HostFrame {
    /// The host's axes in the library's frame: the columns are where the
    /// host's x, y and z point.
    axes: Mat3,
    /// Metres per host length unit.
    scale: f32,
    /// The determinant of `axes`: +1, or −1 for a mirror.
    handedness: f32,
}

impl HostFrame {
    /// The library's own frame (and Godot's): right-handed, y up, metres.
    pub const LIBRARY: HostFrame = HostFrame { axes: Mat3::IDENTITY, scale: 1.0, handedness: 1.0 };

    /// Unity's: left-handed, y up, z forward, metres. The mirror is z.
    pub const UNITY: HostFrame = HostFrame {
        axes: Mat3::from_cols(Vec3::X, Vec3::Y, Vec3::NEG_Z),
        scale: 1.0,
        handedness: -1.0,
    };

    /// Unreal's: left-handed, z up, x forward, y right, centimetres. Its x
    /// (forward) is the library's −z, its y (right) the library's x, its z
    /// (up) the library's y.
    pub const UNREAL: HostFrame = HostFrame {
        axes: Mat3::from_cols(Vec3::NEG_Z, Vec3::X, Vec3::Y),
        scale: 0.01,
        handedness: -1.0,
    };

    /// The frames by name, for bindings and messages.
    pub const NAMES: [&str; 3] = ["library", "unity", "unreal"];

    /// A frame by its name in [`Self::NAMES`].
    pub fn by_name(name: &str) -> Result<HostFrame, String> {
        match name {
            "library" | "godot" => Ok(Self::LIBRARY),
            "unity" => Ok(Self::UNITY),
            "unreal" => Ok(Self::UNREAL),
            _ => Err(format!("unknown frame {name:?} (known: {})", Self::NAMES.join(", "))),
        }
    }

    /// `axes · v`, exactly `v` in the library's frame (so a library-frame
    /// binding passes the library's bits through).
    fn library_axes(&self, v: Vec3) -> Vec3 {
        if self.axes == Mat3::IDENTITY { v } else { self.axes * v }
    }

    /// `axesᵀ · v`, exactly `v` in the library's frame.
    fn host_axes(&self, v: Vec3) -> Vec3 {
        if self.axes == Mat3::IDENTITY { v } else { self.axes.transpose() * v }
    }

    /// A position or a velocity the host gives (host units) in the
    /// library's (m, m/s).
    pub fn point_in(&self, p: Vec3) -> Vec3 {
        self.library_axes(p) * self.scale
    }

    /// A library position or velocity in the host's units.
    pub fn point_out(&self, p: Vec3) -> Vec3 {
        self.host_axes(p) / self.scale
    }

    /// A length (a size, a radius, a height) in metres.
    pub fn length_in(&self, l: f32) -> f32 {
        l * self.scale
    }

    /// A length in metres in the host's unit.
    pub fn length_out(&self, l: f32) -> f32 {
        l / self.scale
    }

    /// A box's full size along the host's axes, along the library's: the
    /// same three lengths, the axes permuted.
    pub fn size_in(&self, size: Vec3) -> Vec3 {
        self.permuted(size) * self.scale
    }

    /// `v`'s components along the library's axes, signs kept: the axes'
    /// signed permutation without its signs (so a negative size or moment
    /// stays negative, for the checks that refuse it).
    fn permuted(&self, v: Vec3) -> Vec3 {
        let a = self.axes;
        Mat3::from_cols(a.x_axis.abs(), a.y_axis.abs(), a.z_axis.abs()) * v
    }

    /// A unit direction (a surface normal) in the host's axes.
    pub fn direction_out(&self, n: Vec3) -> Vec3 {
        self.host_axes(n)
    }

    /// A force (N) in the host's unit (kg·unit/s²).
    pub fn force_out(&self, f: Vec3) -> Vec3 {
        self.point_out(f)
    }

    /// A force's magnitude (N) in the host's unit.
    pub fn force_magnitude_out(&self, f: f32) -> f32 {
        f / self.scale
    }

    /// An angular velocity the host gives (rad/s) in the library's frame.
    pub fn angular_in(&self, w: Vec3) -> Vec3 {
        self.library_axes(w) * self.handedness
    }

    /// An angular velocity (rad/s) in the host's frame.
    pub fn angular_out(&self, w: Vec3) -> Vec3 {
        self.host_axes(w) * self.handedness
    }

    /// A torque (N·m) in the host's unit (kg·unit²/s²).
    pub fn torque_out(&self, t: Vec3) -> Vec3 {
        self.host_axes(t) * (self.handedness / (self.scale * self.scale))
    }

    /// Principal moments of inertia (kg·unit²) about the host's principal
    /// axes, in kg·m² about the library's: the frames' axes are signed
    /// permutations of each other, so the moments are permuted as a box's
    /// size is.
    pub fn inertia_in(&self, i: Vec3) -> Vec3 {
        self.permuted(i) * (self.scale * self.scale)
    }

    /// The proper rotation of the map: `d·P`.
    fn turn(&self) -> Quat {
        Quat::from_mat3(&(self.axes * self.handedness))
    }

    /// An orientation the host gives in the library's frame: `P·R·Pᵀ`.
    pub fn rotation_in(&self, q: Quat) -> Quat {
        if self.axes == Mat3::IDENTITY {
            return q;
        }
        let t = self.turn();
        t * q * t.conjugate()
    }

    /// A library orientation in the host's frame.
    pub fn rotation_out(&self, q: Quat) -> Quat {
        if self.axes == Mat3::IDENTITY {
            return q;
        }
        let t = self.turn();
        t.conjugate() * q * t
    }
}

impl Default for HostFrame {
    fn default() -> Self {
        Self::LIBRARY
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Equal to f32's precision, relative to the larger.
    fn close(a: Vec3, b: Vec3) -> bool {
        a.distance(b) <= 1e-5 * a.length().max(b.length()).max(1.0)
    }

    fn same_turn(a: Quat, b: Quat) -> bool {
        (a.dot(b).abs() - 1.0).abs() < 1e-5
    }

    #[test]
    fn unity_is_the_library_mirrored_in_z() {
        let unity = HostFrame::UNITY;
        assert!(close(unity.point_in(Vec3::new(0.3, 1.2, 0.7)), Vec3::new(0.3, 1.2, -0.7)));
        // A rotation maps as the points it moves: turning then mapping is
        // mapping then turning.
        let q = Quat::from_axis_angle(Vec3::Y, 0.9);
        let p = Vec3::new(0.2, -0.1, 0.4);
        let rotated_then_mapped = unity.point_in(q * p);
        let mapped_then_rotated = unity.rotation_in(q) * unity.point_in(p);
        assert!(close(rotated_then_mapped, mapped_then_rotated));
        // An angular velocity maps as the rotation it integrates to.
        let w = Vec3::new(0.4, -1.3, 2.1);
        let dt = 1e-3;
        let turned = Quat::from_scaled_axis(w * dt);
        let expected = unity.rotation_in(turned).to_scaled_axis() / dt;
        assert!(close(unity.angular_in(w), expected), "{} {}", unity.angular_in(w), expected);
    }

    #[test]
    fn every_frame_maps_back_to_what_it_was_given() {
        let p = Vec3::new(12.0, -3.5, 40.0);
        let q = Quat::from_euler(glam::EulerRot::XYZ, 0.3, -1.1, 2.0);
        let w = Vec3::new(-0.7, 0.2, 1.9);
        for name in HostFrame::NAMES {
            let f = HostFrame::by_name(name).unwrap();
            assert!(close(f.point_out(f.point_in(p)), p), "{name}");
            assert!(close(f.angular_out(f.angular_in(w)), w), "{name}");
            assert!(same_turn(f.rotation_out(f.rotation_in(q)), q), "{name}");
            // Rotations and points agree in every frame.
            let v = Vec3::new(0.05, 0.3, -0.2);
            assert!(close(f.point_in(q * v), f.rotation_in(q) * f.point_in(v)), "{name}");
        }
        assert!(HostFrame::by_name("blender").unwrap_err().contains("unity"));
        // A negative size or moment stays negative, for the checks to refuse.
        for f in [HostFrame::UNITY, HostFrame::UNREAL] {
            assert!(f.size_in(Vec3::new(1.0, -2.0, 3.0)).min_element() < 0.0);
            assert!(f.inertia_in(Vec3::new(1.0, 2.0, -3.0)).min_element() < 0.0);
        }
    }

    #[test]
    fn unreal_is_z_up_in_centimetres() {
        let ue = HostFrame::UNREAL;
        // 150 cm up is 1.5 m up; 100 cm forward is 1 m along the library's −z.
        assert!(close(ue.point_in(Vec3::new(0.0, 0.0, 150.0)), Vec3::new(0.0, 1.5, 0.0)));
        assert!(close(ue.point_in(Vec3::new(100.0, 0.0, 0.0)), Vec3::new(0.0, 0.0, -1.0)));
        // Gravity's 9.81 N on 1 kg is 981 kg·cm/s² down its z.
        assert!(close(ue.force_out(Vec3::new(0.0, -9.81, 0.0)), Vec3::new(0.0, 0.0, -981.0)));
        // A torque of 1 N·m is 10⁴ kg·cm²/s².
        let t = ue.torque_out(Vec3::new(0.0, 1.0, 0.0));
        assert!((t.length() - 1e4).abs() < 1e-1, "{t}");
    }
}
