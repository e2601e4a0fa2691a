//! Side-by-side stereo (§3.8.2): two cameras a virtual camera distance
//! apart.

use bevy::prelude::*;

/// Side-by-side stereo, with this virtual camera distance.
#[derive(Resource, Debug, Clone, Copy, PartialEq)]
pub struct Stereo {
    /// Between the two cameras (m).
    pub vcd: f32,
}

/// The average adult interpupillary distance (m).
pub const HUMAN_IPD: f32 = 0.063;
/// The distance between a Leap Motion controller's two cameras (m), the
/// VCD its image pass-through needs.
pub const LEAP_ICD: f32 = 0.040;

impl std::str::FromStr for Stereo {
    type Err = String;
    /// `ipd` (63 mm), `leap` (40 mm) or a distance in millimetres.
    fn from_str(s: &str) -> Result<Stereo, String> {
        let vcd = match s {
            "ipd" => HUMAN_IPD,
            "leap" => LEAP_ICD,
            mm => match mm.parse::<f32>() {
                Ok(mm) if mm.is_finite() && mm > 0.0 && mm <= 1000.0 => mm / 1000.0,
                _ => {
                    let why = "expected ipd (63 mm), leap (40 mm) or millimetres in (0, 1000]";
                    return Err(format!("{why}, got {s:?}"));
                }
            },
        };
        Ok(Stereo { vcd })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stereo_takes_the_presets_or_millimetres_and_refuses_others() {
        assert_eq!("ipd".parse::<Stereo>(), Ok(Stereo { vcd: 0.063 }));
        assert_eq!("leap".parse::<Stereo>(), Ok(Stereo { vcd: 0.040 }));
        assert_eq!("55".parse::<Stereo>(), Ok(Stereo { vcd: 0.055 }));
        for bad in ["0", "-5", "NaN", "inf", "eyes", "2000"] {
            assert!(bad.parse::<Stereo>().unwrap_err().contains("ipd"), "{bad}");
        }
    }
}
