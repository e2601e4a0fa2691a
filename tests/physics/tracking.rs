//! Tracking glitches in a real recording: the fist of `grab.json.lz` holds
//! a 4.5 cm, 50 g box while its frames vanish, repeat, jitter, go
//! backwards, swap sides, duplicate ids, collapse a finger or arrive in a
//! 10 kHz burst. Each run must stay finite, never fling the box, and begin
//! and end contacts only with their events ([`ContactBook`]).

use super::glitch::ContactBook;
use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::playback::{DEFAULT_GRACE, Playback};
use coulomb_hands::input::{TrackedHand, TrackingFrame, leap};
use coulomb_hands::run::drive::StepView;
use coulomb_hands::run::grasp::GraspSite;
use coulomb_hands::run::replay::{place_at_grasp, replay, world_with_objects};
use coulomb_hands::{GammaMode, InteractionConfig, Side};
use glam::Vec3;
use std::path::PathBuf;

/// What a glitched replay did.
struct Outcome {
    /// The box's top speed (m/s).
    top_speed: f32,
    /// Its largest drift in the palm frame over the closing, outside
    /// `glitch` (m).
    drift: f32,
    /// The most contacts on it while the hand was lost (after the grace).
    contacts_while_lost: usize,
    /// Contacts that ended during the glitch.
    ended_in_glitch: usize,
    book: ContactBook,
    skipped: Vec<String>,
}

fn frames() -> Vec<TrackingFrame> {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/leap/grab.json.lz");
    leap::load(&path).unwrap().frames
}

fn playback(frames: &[TrackingFrame]) -> Playback {
    let conversion = Conversion::leap_desktop(Vec3::ZERO);
    Playback::new("grab.json.lz", frames, &conversion, DEFAULT_GRACE).unwrap()
}

/// The first closing of the clean recording.
fn closing() -> GraspSite {
    let config = InteractionConfig { gamma: GammaMode::Auto, ..InteractionConfig::default() };
    let (mut world, _) = world_with_objects(config, &[]).unwrap();
    place_at_grasp(&mut world, &playback(&frames()), "box:0.045:0.05".parse().unwrap(), 0)
        .unwrap()
        .1
}

/// Replays `frames` (edited from the recording) with the box placed in the
/// clean recording's first closing; `glitch` is the edited span (s), left
/// out of the drift, and `lost` a span in which the hand is untracked.
fn replay_glitched(frames: &[TrackingFrame], glitch: (f64, f64), lost: (f64, f64)) -> Outcome {
    let config = InteractionConfig { gamma: GammaMode::Auto, ..InteractionConfig::default() };
    let (mut world, _) = world_with_objects(config, &[]).unwrap();
    let clean = playback(&self::frames());
    let (fixture, site) =
        place_at_grasp(&mut world, &clean, "box:0.045:0.05".parse().unwrap(), 0).unwrap();
    let edited = playback(frames);
    let id = fixture.object;
    let mut out = Outcome {
        top_speed: 0.0,
        drift: 0.0,
        contacts_while_lost: 0,
        ended_in_glitch: 0,
        book: ContactBook::default(),
        skipped: edited.skipped.iter().map(ToString::to_string).collect(),
    };
    let mut reference = None;
    let mut each = |step: &StepView| {
        let (w, t) = (step.world, step.t);
        out.book.check(w, t as f32);
        let state = w.object_state(id).unwrap();
        out.top_speed = out.top_speed.max(state.linvel.length());
        if t > lost.0 + DEFAULT_GRACE && t < lost.1 {
            out.contacts_while_lost = out.contacts_while_lost.max(w.contacts().len());
        }
        // From the last frame before the glitch (at most a frame earlier).
        let in_glitch = t >= glitch.0 - 0.02 && t <= glitch.1 + 0.05;
        if in_glitch {
            let ended = coulomb_hands::ContactEventKind::Ended;
            out.ended_in_glitch += w.events().iter().filter(|e| e.kind == ended).count();
        }
        if t >= site.closed_at && t < site.opening_at && !in_glitch {
            let Some(hand) = clean.sample(site.track, t) else { return Ok(()) };
            let local = hand.pose.palm.to_local(state.position);
            let r = *reference.get_or_insert(local);
            out.drift = out.drift.max(local.distance(r));
        }
        Ok(())
    };
    replay("glitched", &edited, &mut world, &[fixture], &mut [&mut each]).unwrap();
    out
}

/// The recording's frames with those in `span` (s from the first) edited.
fn edit(span: (f64, f64), mut f: impl FnMut(usize, &mut Vec<TrackingFrame>)) -> Vec<TrackingFrame> {
    let frames = frames();
    let start = frames[0].timestamp_us;
    let mut out = Vec::new();
    for (i, frame) in frames.into_iter().enumerate() {
        let t = (frame.timestamp_us - start) as f64 * 1e-6;
        let mut group = vec![frame];
        if t >= span.0 && t <= span.1 {
            f(i, &mut group);
        }
        out.extend(group);
    }
    out
}

/// The middle of the first closing's hold (from its most closed instant
/// until it begins to open), and a span of `length` s around it.
fn mid_closing(length: f64) -> (f64, f64) {
    let site = closing();
    let mid = 0.5 * (site.closed_at + site.opening_at);
    (mid - length / 2.0, mid + length / 2.0)
}

const NEVER: (f64, f64) = (f64::INFINITY, f64::INFINITY);

fn assert_calm(name: &str, out: &Outcome) {
    assert!(out.top_speed <= 2.0, "{name}: the box reached {:.2} m/s", out.top_speed);
    assert!(out.book.began > 0, "{name}: no contact ever began");
}

fn assert_held(name: &str, out: &Outcome) {
    assert_calm(name, out);
    assert!(out.drift < 0.02, "{name}: the box moved {:.1} mm in the fist", out.drift * 1e3);
}

#[test]
fn the_clean_recording_holds_the_box() {
    let out = replay_glitched(&frames(), NEVER, NEVER);
    assert_held("clean", &out);
    assert!(out.skipped.is_empty(), "{:?}", out.skipped);
}

#[test]
fn a_50_ms_dropout_is_bridged_and_a_2_s_one_lets_go() {
    let short = mid_closing(0.05);
    let out = replay_glitched(&edit(short, |_, g| g.clear()), short, NEVER);
    assert_held("50 ms dropout", &out);
    // A closed fist's contacts come and go as its fingers shift on the box;
    // the bridged dropout must not end more of them than the clean
    // recording does over the same 50 ms.
    let clean = replay_glitched(&frames(), short, NEVER);
    assert!(
        out.ended_in_glitch <= clean.ended_in_glitch,
        "a bridged dropout ended {} contacts, the clean recording {}",
        out.ended_in_glitch,
        clean.ended_in_glitch
    );

    // From mid-closing on, 2 s of nothing; the hand comes back for the
    // last 0.4 s of the recording.
    let long = (mid_closing(0.0).0, mid_closing(0.0).0 + 2.0);
    assert!(playback(&frames()).duration > long.1 + 0.3);
    let out = replay_glitched(&edit(long, |_, g| g.clear()), long, long);
    assert_calm("2 s dropout", &out);
    assert_eq!(out.contacts_while_lost, 0, "contacts stayed while the hand was lost");
    assert!(out.ended_in_glitch > 0, "the lost hand's contacts never ended");
}

#[test]
fn a_duplicate_hand_id_is_left_out_and_swapped_sides_are_another_hand() {
    // A second copy of the hand, 6 cm to its side, with the same id.
    let span = mid_closing(0.4);
    let doubled = edit(span, |_, group| {
        let mut copy: TrackedHand = group[0].hands[0].clone();
        copy.palm_position.x += 60.0;
        copy.joints = copy.joints.map(|f| f.map(|j| j + Vec3::X * 60.0));
        group[0].hands.push(copy);
    });
    let out = replay_glitched(&doubled, NEVER, NEVER);
    assert_held("duplicate id", &out);
    assert!(!out.skipped.is_empty() && out.skipped[0].contains("another"), "{:?}", out.skipped);

    // For 0.3 s the tracker calls the right hand left: the right hand is
    // lost (its contacts end) and a left one appears where it was.
    let span = mid_closing(0.3);
    let swapped = edit(span, |_, group| {
        for hand in &mut group[0].hands {
            hand.side = Side::Left;
        }
    });
    let out = replay_glitched(&swapped, span, span);
    assert_calm("left and right swapped", &out);
    assert!(out.ended_in_glitch > 0, "the right hand's contacts never ended");
}

#[test]
fn jittered_repeated_and_backward_timestamps_keep_the_hold() {
    let span = mid_closing(1.0);
    let mut stale = 0;
    let jittered = edit(span, |i, group| {
        // ±50 % of a ~9 ms frame interval, deterministic.
        let jitter = ((i * 7919) % 11) as i64 - 5;
        group[0].timestamp_us += jitter * 900;
        match i % 12 {
            0 => group.push(group[0].clone()), // repeated timestamp
            6 => {
                let mut old = group[0].clone();
                old.timestamp_us -= 40_000; // a stale frame, 40 ms late
                group.push(old);
                stale += 1;
            }
            _ => {}
        }
    });
    let out = replay_glitched(&jittered, span, NEVER);
    assert_held("jittered timestamps", &out);
    assert_eq!(out.skipped.len(), stale, "{:?}", out.skipped);
    assert!(out.skipped.iter().all(|s| s.contains("backwards")), "{:?}", out.skipped);
}

#[test]
fn a_collapsed_finger_is_bridged_when_brief_and_a_loss_when_long() {
    let collapse = |_: usize, group: &mut Vec<TrackingFrame>| {
        let joints = &mut group[0].hands[0].joints[1];
        *joints = [joints[0]; 4];
    };
    let brief = mid_closing(0.04);
    let out = replay_glitched(&edit(brief, collapse), brief, NEVER);
    assert_held("40 ms collapsed finger", &out);
    assert!(out.skipped.iter().all(|s| s.contains("zero-length")), "{:?}", out.skipped);
    assert!(!out.skipped.is_empty());

    let long = mid_closing(0.5);
    let out = replay_glitched(&edit(long, collapse), long, long);
    assert_calm("500 ms collapsed finger", &out);
    assert_eq!(out.contacts_while_lost, 0, "contacts stayed while the hand was lost");
}

#[test]
fn a_10_khz_burst_of_frames_keeps_the_hold() {
    // Over 0.3 s, nine frames between each pair, 100 µs apart, each a copy
    // of the frame before with its hand moved a tenth of the way on.
    let span = mid_closing(0.3);
    let all = frames();
    let burst = edit(span, |i, group| {
        let (a, b) = (&all[i], &all[(i + 1).min(all.len() - 1)]);
        for k in 1..10 {
            let w = k as f32 / 10.0;
            let mut f = a.clone();
            f.timestamp_us += k * 100;
            let (ha, hb) = (&a.hands[0], &b.hands[0]);
            let h = &mut f.hands[0];
            h.palm_position = ha.palm_position.lerp(hb.palm_position, w);
            for (fi, finger) in h.joints.iter_mut().enumerate() {
                for (ji, j) in finger.iter_mut().enumerate() {
                    *j = ha.joints[fi][ji].lerp(hb.joints[fi][ji], w);
                }
            }
            group.push(f);
        }
    });
    assert!(burst.len() > frames().len() + 200, "a real burst");
    let out = replay_glitched(&burst, span, NEVER);
    assert_held("10 kHz burst", &out);
    assert!(out.skipped.is_empty(), "{:?}", out.skipped);
}
