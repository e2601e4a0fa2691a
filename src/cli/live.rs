//! `live`: the physics on a live Leap Motion stream, with a scene and an
//! object to touch, optionally recorded.

use super::args::positive;
use super::options::{JsonOutput, SessionArgs};
use super::{Outcome, print_objects};
use coulomb_hands::InteractionConfig;
use coulomb_hands::input::live::DEFAULT_URL;

/// The default tracking time to run for (s).
pub const SECONDS: f64 = 10.0;

/// Run the physics on a live Leap Motion service's WebSocket stream.
#[derive(clap::Args)]
pub struct LiveArgs {
    /// The service's WebSocket URL.
    #[arg(long, default_value = DEFAULT_URL)]
    url: String,
    /// Stop after this many seconds of tracking time.
    #[arg(long, default_value_t = SECONDS, value_parser = positive)]
    seconds: f64,
    #[command(flatten)]
    session: SessionArgs,
    #[command(flatten)]
    output: JsonOutput,
}

impl LiveArgs {
    /// Runs the stream for `--seconds`, then prints what the hands did.
    pub fn run(self) -> Outcome {
        use coulomb_hands::input::convert::Conversion;
        use coulomb_hands::run::live::run_live;
        if self.session.grasp_object().is_some() {
            return Err("--object-at grasp needs a hand's closings, which a live stream does not \
                        give: put the object at x,y,z"
                .into());
        }
        let scene = self.session.load_scene()?;
        let mut world = self.session.world(InteractionConfig::default(), scene.as_ref())?;
        let conversion = Conversion::leap_desktop(self.session.device);
        let (url, grace, seconds) = (&self.url, self.session.grace, self.seconds);
        let s = run_live(url, &mut world, conversion, grace, seconds, &mut [])?;
        self.session.save(&mut world)?;
        self.output.print(&s, |s| {
            println!(
                "live {url}: {} frames, {} skipped, {} hands seen, {:.2} s simulated, \
                 {} contacts begun",
                s.frames, s.skipped, s.hands_seen, s.simulated, s.contacts_begun
            );
            print_objects(&s.objects);
        })?;
        Ok(())
    }
}
