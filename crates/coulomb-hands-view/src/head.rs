//! Hands attached to the head (§3.8.1). A recording made with the Leap
//! Motion worn on a headset is in the worn device's frame. It is mapped with
//! the thesis's chain (desktop→HMD, mm→m, the mount's tilt and offset, then
//! the head's pose), and the camera sits at the eyes, so the hands are seen
//! where the wearer saw them.
//!
//! A recording has no head tracking, so the head holds still at one pose.
//! It is the thesis's camera–controller parenting (Fig. 3.26) frozen in time.

use coulomb_hands::input::InputError;
use coulomb_hands::input::convert::{Conversion, MountPreset};
use coulomb_hands::input::recording::Recording;
use glam::{EulerRot, Quat, Vec3};

/// Where the tracker sits on the headset, by name: `dk2` (on the front plate of
/// an Oculus Rift DK2, 8 cm ahead of the eyes) or `hololens` (on top of a
/// HoloLens, 7 cm up and 5 cm ahead).
pub fn parse_mount(s: &str) -> Result<MountPreset, String> {
    match s {
        "dk2" => Ok(MountPreset::OculusDk2),
        "hololens" => Ok(MountPreset::HoloLens),
        _ => Err(format!("expected dk2 or hololens, got {s:?}")),
    }
}

/// Where the head is: the eyes' centre and which way they look.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeadPose {
    /// The eyes' centre (world, m).
    pub position: Vec3,
    /// Turn about the vertical (°); 0 looks along −z, 90 along −x.
    pub yaw_deg: f32,
    /// Elevation above the horizontal (°); negative looks down.
    pub pitch_deg: f32,
}

impl Default for HeadPose {
    /// Eyes 50 cm above the replay's ground, 35 cm back from its origin,
    /// looking 30° down. Hands held 30–40 cm ahead then land where a desktop
    /// recording's hands do, about 20 cm over the ground near the origin, so
    /// the same scenes and objects suit both.
    fn default() -> Self {
        HeadPose { position: Vec3::new(0.0, 0.5, 0.35), yaw_deg: 0.0, pitch_deg: -30.0 }
    }
}

impl HeadPose {
    /// The head's orientation: yaw about +y, then pitch about the turned x.
    pub fn rotation(&self) -> Quat {
        Quat::from_euler(EulerRot::YXZ, self.yaw_deg.to_radians(), self.pitch_deg.to_radians(), 0.0)
    }
}

impl std::str::FromStr for HeadPose {
    type Err = String;
    /// `X,Y,Z,YAW,PITCH`: metres, then degrees.
    fn from_str(s: &str) -> Result<HeadPose, String> {
        let parts: Vec<f32> = s.split(',').map(|p| p.trim().parse().unwrap_or(f32::NAN)).collect();
        match parts[..] {
            [x, y, z, yaw_deg, pitch_deg]
                if parts.iter().all(|p| p.is_finite())
                    && pitch_deg.abs() <= 89.0
                    && Vec3::new(x, y, z).abs().max_element() <= 100.0 =>
            {
                Ok(HeadPose { position: Vec3::new(x, y, z), yaw_deg, pitch_deg })
            }
            _ => Err(format!(
                "expected X,Y,Z,YAW_DEG,PITCH_DEG with coordinates within ±100 m and pitch \
                 within ±89°, got {s:?}"
            )),
        }
    }
}

/// A head-mounted tracker: its mount, and the head it is on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeadMount {
    /// Where the tracker sits relative to the eyes.
    pub mount: MountPreset,
    /// Where the head is.
    pub head: HeadPose,
}

impl HeadMount {
    /// The map from the worn tracker's frame into the world; an error for a
    /// recording that is not in a tracker's frame (a joint recording).
    pub fn conversion(&self, recording: &Recording) -> Result<Conversion, InputError> {
        let head = (self.head.rotation(), self.head.position);
        recording.head_mounted_conversion(self.mount.translation(), (0.0, 0.0, 0.0), head)
    }

    /// Where the eyes are and which way they look (world, m).
    pub fn eyes(&self) -> (Vec3, Quat) {
        (self.head.position, self.head.rotation())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_head_pose_is_position_then_yaw_and_pitch_within_limits() {
        let h: HeadPose = "0.1,1.6,-0.2,90,-20".parse().expect("a head pose");
        assert_eq!(h.position, Vec3::new(0.1, 1.6, -0.2));
        // Yaw 90° turns the forward −z to −x; pitch −20° tips it down.
        let (forward, down) = (h.rotation() * Vec3::NEG_Z, 20f32.to_radians());
        assert!((forward - Vec3::new(-down.cos(), -down.sin(), 0.0)).length() < 1e-6);
        for bad in ["0,1,0", "0,1,0,0,90", "0,1,0,0,NaN", "a,1,0,0,0", "0,1,0,0,0,0", "150,0,0,0,0"]
        {
            assert!(bad.parse::<HeadPose>().is_err(), "{bad}");
        }
        assert_eq!(parse_mount("dk2"), Ok(MountPreset::OculusDk2));
        assert!(parse_mount("rift").unwrap_err().contains("dk2 or hololens"));
    }
}
