//! `live`: the physics on a live Leap Motion stream.

use coulomb_hands::{InteractionConfig, RunError};

pub fn live(url: &str, seconds: f64, device: glam::Vec3) -> Result<(), RunError> {
    use coulomb_hands::input::{convert::Conversion, playback::DEFAULT_GRACE};
    use coulomb_hands::run::{live::run_live, replay::replay_world};
    let mut world = replay_world(InteractionConfig::default(), false)?;
    let conversion = Conversion::leap_desktop(device);
    let s = run_live(url, &mut world, conversion, DEFAULT_GRACE, seconds, &mut [])?;
    println!(
        "live {url}: {} frames, {} skipped, {} hands seen, {:.2} s simulated, {} contacts begun",
        s.frames, s.skipped, s.hands_seen, s.simulated, s.contacts_begun
    );
    Ok(())
}
