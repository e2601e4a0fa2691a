//! The threaded live reader ([`LiveFeed`]) against a loopback service the
//! test paces frame by frame: it never waits, plays the stream a little
//! behind its newest frame on the host's clock, reports a broken stream,
//! and ends its thread when dropped.

use super::live::{close, pinch_frames, pinch_path, service, within_a_minute};
use coulomb_hands::hand::HandSample;
use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::leap;
use coulomb_hands::input::playback::{DEFAULT_GRACE, Playback};
use coulomb_hands::run::drive::{Driver, HandSource};
use coulomb_hands::run::live::{LiveFeed, PLAYOUT_DELAY};
use coulomb_hands::run::replay::world_with_objects;
use coulomb_hands::{InteractionConfig, ObjectDesc, ObjectId, Side};
use glam::Vec3;
use std::sync::mpsc;
use std::thread::JoinHandle;
use tungstenite::Message;

/// A loopback service that sends what the test hands it: `Some(frame)` is
/// sent, `None` closes the stream cleanly, and dropping the sender drops
/// the connection with no close. Returns the URL.
fn paced() -> (String, mpsc::Sender<Option<String>>, JoinHandle<()>) {
    let (tx, rx) = mpsc::channel::<Option<String>>();
    let (url, server) = service(move |ws| {
        while let Ok(next) = rx.recv() {
            match next {
                Some(frame) => ws.send(Message::text(frame)).unwrap(),
                None => return close(ws),
            }
        }
    });
    (url, tx, server)
}

/// Waits until `feed` has received `frames` frames.
fn received(feed: &LiveFeed, frames: usize) {
    while feed.stats().frames < frames {
        std::thread::sleep(std::time::Duration::from_millis(1));
    }
}

/// The farthest any bone end or the palm's centre lies from its place in
/// `b` (m).
fn apart(a: &HandSample, b: &HandSample) -> f32 {
    let ends = |s: &HandSample| {
        let bones = s.pose.fingers.iter().flatten().flat_map(|c| [c.a, c.b]);
        bones.chain([s.pose.palm.center]).collect::<Vec<Vec3>>()
    };
    ends(a).iter().zip(ends(b)).map(|(x, y)| x.distance(y)).fold(0.0, f32::max)
}

/// The first `frames` frames of the real pinch as a replay plays them.
fn replay_of(frames: usize) -> Playback {
    let recorded = leap::load(&pinch_path()).unwrap();
    let conversion = Conversion::leap_desktop(Vec3::ZERO);
    Playback::new("pinch", &recorded.frames[..frames], &conversion, DEFAULT_GRACE).unwrap()
}

#[test]
fn a_live_feed_never_waits_and_plays_the_stream_a_little_behind_its_newest_frame() {
    let frames: Vec<String> = pinch_frames()[..130].iter().map(|f| f.to_string()).collect();
    let replay = replay_of(130);
    let (url, tx, server) = paced();
    within_a_minute(move || {
        let conversion = Conversion::leap_desktop(Vec3::ZERO);
        let feed = LiveFeed::connect(&url, conversion, DEFAULT_GRACE).unwrap();
        let mut hand = feed.hand(Side::Right);
        // Nothing sent yet: untracked, and no wait for the service.
        assert_eq!(hand.sample(7.25).unwrap(), None);
        assert!(!hand.finished());
        frames[..70].iter().for_each(|f| tx.send(Some(f.clone())).unwrap());
        received(&feed, 70);
        // The host's 7.25 s is tied to the newest frame less the delay;
        // its clock then plays the stream on, between frames.
        let newest = feed.stats().newest.unwrap();
        for later in [0.0, 0.0037, 0.0121] {
            let live = hand.sample(7.25 + later).unwrap().unwrap();
            let want = replay.sample(0, newest - PLAYOUT_DELAY + later).unwrap();
            assert!(apart(&live, &want) < 1e-5, "{} m off at +{later} s", apart(&live, &want));
        }
        // Sixty more frames arrive at once (the host stalled): it jumps to
        // the newest rather than play half a second late.
        frames[70..].iter().for_each(|f| tx.send(Some(f.clone())).unwrap());
        received(&feed, 130);
        let newest = feed.stats().newest.unwrap();
        let live = hand.sample(7.27).unwrap().unwrap();
        let want = replay.sample(0, newest - PLAYOUT_DELAY).unwrap();
        assert!(apart(&live, &want) < 1e-5, "{} m off after the stall", apart(&live, &want));
        // The service closes: finished once the last frame is played.
        tx.send(None).unwrap();
        while !feed.stats().closed {
            std::thread::sleep(std::time::Duration::from_millis(1));
        }
        assert!(!hand.finished(), "{} s of the stream still to play", PLAYOUT_DELAY);
        let live = hand.sample(7.27 + PLAYOUT_DELAY + 0.002).unwrap().unwrap();
        assert!(apart(&live, &replay.sample(0, newest).unwrap()) < 1e-5);
        assert!(hand.finished());
        let stats = feed.stats();
        assert_eq!((stats.frames, stats.skipped, stats.dropped, stats.hands_seen), (130, 0, 0, 1));
        assert_eq!(stats.error, None);
    });
    server.join().unwrap();
}

#[test]
fn a_live_feed_paced_by_its_service_drives_a_hand_into_a_cube() {
    // The real pinch sent frame by frame at its own timestamps while the
    // driver steps up to each: the hand sweeps through a weightless 3 cm
    // cube floating where the index fingertip is 40 % of the way in.
    let frames = 180;
    let replay = replay_of(frames);
    let tip = replay.sample(0, 0.4 * replay.duration).unwrap().pose.fingers[1][2].b;
    let cube = ObjectDesc::cuboid("cube", Vec3::splat(0.03), 0.05, tip);
    let messages: Vec<String> = pinch_frames()[..frames].iter().map(|f| f.to_string()).collect();
    let recorded = leap::load(&pinch_path()).unwrap();
    let start = recorded.frames[0].timestamp_us;
    let times: Vec<f64> =
        recorded.frames[..frames].iter().map(|f| (f.timestamp_us - start) as f64 * 1e-6).collect();
    let (url, tx, server) = paced();
    let (moved, touched, worst) = within_a_minute(move || {
        let weightless = InteractionConfig { gravity: Vec3::ZERO, ..InteractionConfig::default() };
        let dt = f64::from(weightless.dt);
        let (mut world, _) = world_with_objects(weightless, &[cube]).unwrap();
        let before = world.object_state(ObjectId(0)).unwrap().position;
        let conversion = Conversion::leap_desktop(Vec3::ZERO);
        let feed = LiveFeed::connect(&url, conversion, DEFAULT_GRACE).unwrap();
        let mut driver = Driver::new(&mut world);
        driver.add_hand(feed.hand(Side::Right));
        let (mut touched, mut worst, mut tie) = (false, 0.0f32, None);
        for (k, frame) in messages.into_iter().enumerate() {
            tx.send(Some(frame)).unwrap();
            received(&feed, k + 1);
            // The host's clock (the driver's) runs up to this frame's time;
            // its first step ties it to the newest frame less the delay.
            while (driver.steps() + 1) as f64 * dt <= times[k] {
                let t = driver.steps() as f64 * dt;
                let tie = *tie.get_or_insert(times[k] - t - PLAYOUT_DELAY);
                driver.step(&mut []).unwrap();
                let live = driver.hands()[0].sample.clone();
                let want = replay.sample(0, t + tie);
                if let (Some(live), Some(want)) = (&live, &want) {
                    worst = worst.max(apart(live, want));
                }
                assert_eq!(live.is_some(), want.is_some(), "tracked at {t} s");
                touched |= !driver.world().contacts().is_empty();
            }
        }
        let after = driver.world().object_state(ObjectId(0)).unwrap().position;
        (after.distance(before), touched, worst)
    });
    server.join().unwrap();
    assert!(worst < 1e-5, "the live hand strayed {worst} m from the recording");
    assert!(touched, "the hand never touched the cube");
    assert!(moved > 0.001, "the cube moved {moved} m");
}

#[test]
fn a_live_feed_whose_connection_drops_reports_it() {
    let (url, tx, server) = paced();
    let frames: Vec<String> = pinch_frames()[..12].iter().map(|f| f.to_string()).collect();
    within_a_minute(move || {
        let feed = LiveFeed::connect(&url, Conversion::leap_desktop(Vec3::ZERO), 0.1).unwrap();
        let mut hand = feed.hand(Side::Right);
        frames.into_iter().for_each(|f| tx.send(Some(f)).unwrap());
        received(&feed, 12);
        assert!(hand.sample(0.0).unwrap().is_some());
        drop(tx); // the service goes without closing the stream
        while !feed.stats().closed {
            std::thread::sleep(std::time::Duration::from_millis(1));
        }
        let error = hand.sample(0.001).unwrap_err().to_string();
        assert!(error.contains(&url) && error.contains("connection"), "{error}");
        assert!(!hand.finished(), "a failed stream is not a finished one");
        assert_eq!(feed.stats().frames, 12);
    });
    server.join().unwrap();
}

#[test]
fn dropping_a_live_feed_ends_its_reader_while_the_service_is_silent() {
    // The service greets and then sends nothing; the reader thread holds
    // the connection, so the service sees it close only when the thread
    // has ended.
    let (url, server) = service(|ws| while ws.read().is_ok() {});
    within_a_minute(move || {
        let feed = LiveFeed::connect(&url, Conversion::leap_desktop(Vec3::ZERO), 0.1).unwrap();
        let mut hand = feed.hand(Side::Left);
        assert_eq!(hand.sample(0.5).unwrap(), None);
        drop(feed);
        drop(hand);
        server.join().unwrap();
    });
}
