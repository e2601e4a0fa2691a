//! How the replay's settings fare on every closing of every bundled
//! recording: γ fixed or automatic (Eq. 3.11), and the skin patch, each
//! with four objects put at every closing. The replay's defaults were
//! chosen from this table. Only judged closings count (those held long
//! enough, pressing the object, and settled: [`Hold::Judged`]).
//!
//! `cargo run --release --example replay_defaults`

use coulomb_hands::contact::patch::PatchConfig;
use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::{leap, playback::DEFAULT_GRACE, playback::Playback};
use coulomb_hands::run::closing::Hold;
use coulomb_hands::run::replay::{replay_closings, world_with_objects};
use coulomb_hands::{GammaMode, InteractionConfig};

const RECORDINGS: [&str; 4] =
    ["pinch.json.lz", "pinch-57fps.json.lz", "grab.json.lz", "three-claps.json.lz"];

/// Objects from a small pinched box to a fist-sized one.
const OBJECTS: [&str; 4] = ["box:0.02:0.01", "box:0.03:0.03", "sphere:0.04:0.04", "box:0.045:0.05"];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data/leap");
    let conversion = Conversion::leap_desktop(glam::Vec3::ZERO);
    let mut playbacks = Vec::new();
    for name in RECORDINGS {
        let recording = leap::load(&dir.join(name))?;
        playbacks.push(Playback::new(name, &recording.frames, &conversion, DEFAULT_GRACE)?);
    }
    let wide = PatchConfig {
        finger_radius: 0.008,
        thumb_radius: 0.012,
        palm_radius: 0.06,
        ..PatchConfig::default()
    };
    let patches = [
        ("1 sample", PatchConfig { samples: 1, ..PatchConfig::default() }),
        ("default", PatchConfig::default()),
        ("radii x2", wide),
    ];
    let gammas = [200.0, 400.0, 800.0].map(GammaMode::Fixed).into_iter().chain([GammaMode::Auto]);
    println!("| γ | patch | judged closings held | released after opening | not judged |");
    println!("|---|---|---|---|---|");
    for gamma in gammas {
        for (patch_name, patch) in &patches {
            let (mut judged, mut held, mut released, mut not) = (0, 0, 0, 0);
            for (playback, name) in playbacks.iter().zip(RECORDINGS) {
                for object in OBJECTS {
                    let config = InteractionConfig { gamma, patch: *patch, ..Default::default() };
                    let (mut world, _) = world_with_objects(config, &[])?;
                    let summary =
                        replay_closings(name, playback, &mut world, object.parse()?, &mut [])?;
                    let (ok, rest): (Vec<_>, Vec<_>) =
                        summary.closings.iter().partition(|c| c.hold == Hold::Judged);
                    (judged, not) = (judged + ok.len(), not + rest.len());
                    held += summary.closings.iter().filter(|c| c.held()).count();
                    released +=
                        summary.closings.iter().filter(|c| c.released == Some(true)).count();
                }
            }
            let gamma = match gamma {
                GammaMode::Auto => "auto".to_string(),
                GammaMode::Fixed(g) => format!("{g} N/m"),
            };
            println!("| {gamma} | {patch_name} | {held} of {judged} | {released} | {not} |");
        }
    }
    Ok(())
}
