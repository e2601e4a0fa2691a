//! Converts a Leap Motion recording into a joint recording (JSON lines,
//! OpenXR layout, metres, y up; `coulomb_hands::input::joints`):
//!
//! ```text
//! cargo run --example leap_to_joints -- \
//!     data/leap/pinch-57fps.json.lz data/joints/pinch-57fps.jsonl
//! ```
//!
//! The device's origin becomes the joint recording's origin, so replaying
//! either with the same `--device` puts the hand in the same place.

use coulomb_hands::input::{convert::Conversion, joints, leap};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [input, output] = args.as_slice() else {
        return Err("usage: leap_to_joints LEAP_RECORDING OUT.jsonl".into());
    };
    let recording = leap::load(std::path::Path::new(input))?;
    let text = joints::openxr_recording(&recording.frames, &Conversion::mm_to_m());
    std::fs::write(output, text)?;
    println!("{input}: {} frames -> {output}", recording.frames.len());
    Ok(())
}
