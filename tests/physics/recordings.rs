//! The bundled real Leap Motion recordings: every format decodes, replays
//! stay finite, and broken files are errors, not panics.

use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::leap;
use coulomb_hands::input::playback::{DEFAULT_GRACE, Playback};
use coulomb_hands::replay::{replay, world_with_objects};
use coulomb_hands::{InteractionConfig, ObjectDesc, WorldError};
use glam::Vec3;
use std::path::PathBuf;

fn data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/leap").join(name)
}

#[test]
fn all_four_recordings_decode_with_their_formats_frames_and_hands() {
    for (name, version, frames, hands) in [
        ("grab.json.lz", 0.1, 374, 1),
        ("pinch.json.lz", 0.1, 307, 1),
        ("pinch-57fps.json.lz", 2.0, 133, 1),
        ("three-claps.json.lz", 0.1, 403, 2),
    ] {
        let rec = leap::load(&data(name)).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(rec.format_version, version, "{name}");
        assert_eq!(rec.frames.len(), frames, "{name}");
        let playback = Playback::new(name, &rec.frames, &Conversion::leap_desktop(Vec3::ZERO), DEFAULT_GRACE).unwrap();
        assert_eq!(playback.tracks.len(), hands, "{name}");
        // Desktop recordings: hands hover 5–40 cm above the device.
        let pose = playback.sample(0, 0.5 * playback.duration).expect("tracked mid-way");
        pose.pose.validate(0).unwrap();
        assert!((0.05..0.4).contains(&pose.pose.palm.center.y), "{name}: palm at {:?}", pose.pose.palm.center);
    }
}

#[test]
fn the_packed_format_matches_its_own_header() {
    // Format 2 drops finger types and widths: types come from pointable
    // ids, widths from the defaults, and the five fingers are all there.
    let rec = leap::load(&data("pinch-57fps.json.lz")).unwrap();
    let hand = &rec.frames[0].hands[0];
    assert_eq!(hand.widths, leap::DEFAULT_WIDTHS_MM);
    // Finger types were recovered: the middle finger reaches farther than the pinky.
    let span = |f: usize| hand.joints[f][0].distance(hand.joints[f][3]);
    assert!(span(2) > span(4), "middle finger longer than pinky");
}

#[test]
fn two_handed_and_packed_replays_stay_finite_with_an_object_in_the_way() {
    for name in ["three-claps.json.lz", "pinch-57fps.json.lz"] {
        let rec = leap::load(&data(name)).unwrap();
        let playback = Playback::new(name, &rec.frames, &Conversion::leap_desktop(Vec3::ZERO), DEFAULT_GRACE).unwrap();
        // A box where the hands are, so contacts actually happen.
        let centre = playback.sample(0, 0.5 * playback.duration).unwrap().pose.palm.center;
        let desc = ObjectDesc::cuboid("box", Vec3::splat(0.05), 0.05, centre);
        let (mut world, _) = world_with_objects(InteractionConfig::default(), &[desc]).unwrap();
        let mut lines = 0;
        let summary = replay::<WorldError>(name, &playback, &mut world, &[], |_, line| {
            lines += 1;
            assert!(line.objects.iter().all(|o| o.pos.iter().chain(&o.linvel).chain(&o.rot).all(|v| v.is_finite())));
            Ok(())
        })
        .unwrap();
        assert!(summary.all_finite, "{name}");
        assert_eq!(lines, summary.steps);
        assert!(summary.contacts_begun > 0, "{name}: the hands never touched the box");
    }
}

#[test]
fn a_truncated_recording_is_an_error_naming_the_file() {
    let text = std::fs::read_to_string(data("grab.json.lz")).unwrap();
    for cut in [text.len() / 2, 1000, 10] {
        let e = leap::parse("grab-cut.json.lz", &text[..cut]).unwrap_err();
        assert!(e.to_string().starts_with("grab-cut.json.lz: "), "{e}");
    }
    let e = leap::load(&data("missing.json.lz")).unwrap_err();
    assert_eq!(e.field, "file");
}
