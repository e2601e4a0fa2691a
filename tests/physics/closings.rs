//! Closings of a synthetic tracked hand, as a replay finds and judges them:
//! by the tracker's grab strength where it reports one, by the fingers'
//! curl and the aperture from the joints always. A hand that starts half
//! closed still closes; one continuous fist is one closing however its
//! aperture flickers; a twitch is listed but not judged; the held window
//! spans the whole hold.

use coulomb_hands::friction::settling_time;
use coulomb_hands::hand::rig::HandRig;
use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::playback::{DEFAULT_GRACE, Playback};
use coulomb_hands::input::{TrackedHand, TrackingFrame};
use coulomb_hands::run::closing::{ClosingVerdict, Hold};
use coulomb_hands::run::grasp::spans::Signal;
use coulomb_hands::run::grasp::{GraspSite, MIN_HOLD, SAMPLE_STEP, find_grasps};
use coulomb_hands::run::replay::{ReplaySummary, replay_closings, world_with_objects};
use coulomb_hands::{HandPose, InteractionConfig, Side};
use glam::{Quat, Vec3};

/// What the synthetic tracker reports at one instant: the four fingers'
/// curl, the thumb's opposition, and a grab strength if it gives one.
#[derive(Clone, Copy)]
struct Reported {
    curl: f32,
    opposition: f32,
    grab: Option<f32>,
}

/// The joints a tracker would report for a rig pose (metres).
fn tracked(pose: &HandPose, grab: Option<f32>) -> TrackedHand {
    TrackedHand {
        id: 5,
        side: Side::Right,
        palm_position: pose.palm_surface(),
        palm_normal: pose.palm.normal(),
        direction: pose.palm.rotation * Vec3::Z,
        joints: pose.fingers.map(|f| [f[0].a, f[0].b, f[1].b, f[2].b]),
        carps: None,
        widths: pose.fingers.map(|f| 2.0 * f[0].radius),
        grab,
        pinch: None,
        confidence: None,
    }
}

/// A right hand, palm turned to the left (its normal −x), 25 cm up,
/// reported at `rate` Hz for `duration` s as `at(t)` says.
fn recording(duration: f64, rate: f64, at: impl Fn(f64) -> Reported) -> Playback {
    let rig = HandRig::adult(Side::Right);
    let palm = Quat::from_rotation_z(std::f32::consts::FRAC_PI_2);
    let frames: Vec<TrackingFrame> = (0..=(duration * rate).round() as i64)
        .map(|i| {
            let t = i as f64 / rate;
            let r = at(t);
            let curl = [0.35, r.curl, r.curl, r.curl, r.curl];
            let pose = rig.pose_opposed(Vec3::new(0.0, 0.25, 0.0), palm, curl, r.opposition);
            let timestamp_us = (t * 1e6).round() as i64;
            TrackingFrame { timestamp_us, hands: vec![tracked(&pose, r.grab)] }
        })
        .collect();
    Playback::new("synthetic", &frames, &Conversion::identity(), DEFAULT_GRACE).unwrap()
}

/// `from` until `t0`, then linearly to `to` by `t1`.
fn ramp(t: f64, (t0, from): (f64, f32), (t1, to): (f64, f32)) -> f32 {
    let s = ((t - t0) / (t1 - t0)).clamp(0.0, 1.0) as f32;
    from + (to - from) * s
}

/// A hand that starts half closed (curl 0.45), makes a fist (curl 1.0)
/// from 0.3 to 0.5 s, holds it until 1.1 s and opens back by 1.3 s.
fn half_closed_to_fist(t: f64) -> f32 {
    if t < 0.8 { ramp(t, (0.3, 0.45), (0.5, 1.0)) } else { ramp(t, (1.1, 1.0), (1.3, 0.45)) }
}

fn replayed(playback: &Playback, object: &str) -> ReplaySummary {
    let (mut world, _) = world_with_objects(InteractionConfig::default(), &[]).unwrap();
    replay_closings("synthetic", playback, &mut world, object.parse().unwrap(), &mut []).unwrap()
}

fn near(a: f64, b: f64, within: f64) -> bool {
    (a - b).abs() <= within
}

fn one(sites: &[GraspSite]) -> &GraspSite {
    assert_eq!(sites.len(), 1, "{sites:#?}");
    &sites[0]
}

#[test]
fn a_hand_that_starts_half_closed_and_makes_a_fist_closes_by_its_curl() {
    // No strengths: the joints alone. The curl rises 0.55 from where it
    // started; three quarters of the way, 0.86, it passes at 0.45 s on the
    // way in and 1.15 s on the way out.
    let at = |t| Reported { curl: half_closed_to_fist(t), opposition: 0.3, grab: None };
    let playback = recording(1.6, 90.0, at);
    let site = *one(&find_grasps(&playback, SAMPLE_STEP));
    assert!(site.signals.contains(Signal::Curl) && !site.signals.contains(Signal::Grab));
    assert!(site.sustained);
    assert!(near(site.closing_at, 0.45, 0.015), "{site:?}");
    assert!(near(site.opening_at, 1.15, 0.015), "{site:?}");
}

#[test]
fn a_tracker_that_reports_a_fist_finds_it_and_says_when_it_opened() {
    // The same hand with a grab strength of 0.17 except 0.3–0.9 s, where
    // the tracker reports a fist (1.0). Its grab opens first: the held
    // window ends there, not when the curl drops at 1.15 s.
    let grab = |t: f64| if (0.3..0.9).contains(&t) { 1.0 } else { 0.17 };
    let at = |t| Reported { curl: half_closed_to_fist(t), opposition: 0.3, grab: Some(grab(t)) };
    let playback = recording(1.6, 120.0, at);
    let site = *one(&find_grasps(&playback, SAMPLE_STEP));
    assert!(site.signals.contains(Signal::Grab) && site.signals.contains(Signal::Curl), "{site:?}");
    assert!(near(site.closing_at, 0.30, 0.015) && near(site.opening_at, 0.89, 0.015), "{site:?}");
    // Judged over that whole window, with a 4 cm box in the fist.
    let summary = replayed(&playback, "box:0.04:0.05");
    let v: &ClosingVerdict = &summary.closings[0];
    assert_eq!(v.hold, Hold::Judged, "{v}");
    assert_eq!((v.closing_at, v.opening_at), (site.closing_at, site.opening_at));
    assert!(near(v.hold_s, 0.59, 0.03), "{v}");
    // The drift is measured once the grip has settled after the fixture let
    // go: γ 400 N/m on 50 g at the default damping.
    let zeta = InteractionConfig::default().damping_ratio.unwrap();
    let settle = f64::from(settling_time(400.0, 0.05, zeta).unwrap());
    let let_go = v.gripped_at.unwrap_or(v.closed_at);
    let settled = v.settled_at.unwrap();
    assert!(near(settled - let_go, settle, 1e-6), "{v:?}");
    assert!(settled < v.opening_at, "{v:?}");
}

#[test]
fn a_continuous_fist_whose_aperture_flickers_is_one_closing() {
    // The fingers stay curled from 0.3 to 1.3 s while the thumb swings
    // in and out every 40 ms, as a tracker's thumb does when it loses it
    // behind the fingers: the aperture opens and closes many times.
    let at = |t: f64| {
        let fist = (0.3..1.3).contains(&t);
        let flick = fist && (t * 25.0).floor() as i64 % 2 == 0;
        Reported {
            curl: if fist { 0.95 } else { 0.15 },
            opposition: if flick { 0.9 } else { 0.2 },
            grab: None,
        }
    };
    let playback = recording(1.7, 100.0, at);
    let site = *one(&find_grasps(&playback, SAMPLE_STEP));
    assert!(site.sustained && site.signals.contains(Signal::Curl), "{site:?}");
    assert!(near(site.closing_at, 0.3, 0.015) && near(site.opening_at, 1.29, 0.02), "{site:?}");
}

#[test]
fn a_thirty_millisecond_twitch_is_listed_but_not_judged() {
    // The fingers jerk from curl 0.1 to 0.7 and back within 30 ms.
    let at = |t: f64| {
        let curl = if t < 0.51 {
            ramp(t, (0.5, 0.1), (0.51, 0.7))
        } else {
            ramp(t, (0.52, 0.7), (0.53, 0.1))
        };
        Reported { curl, opposition: 0.2, grab: None }
    };
    let playback = recording(1.0, 200.0, at);
    let site = *one(&find_grasps(&playback, SAMPLE_STEP));
    assert!(!site.sustained && site.hold() < 0.03, "{site:?}");
    let summary = replayed(&playback, "box:0.03:0.02");
    let v = &summary.closings[0];
    assert_eq!(v.hold, Hold::TooShort);
    assert!(v.hold_s < MIN_HOLD && !v.held() && v.released.is_none(), "{v:?}");
    assert!(v.to_string().contains("too short to judge"), "{v}");
    assert!(summary.objects.is_empty(), "no object for a twitch");
}

#[test]
fn a_hand_closing_a_little_beside_a_bead_never_presses_it_and_is_not_judged() {
    // A flat hand curls to 0.45 (a rise well above the curl's threshold,
    // far short of a fist) with its thumb abducted, around a 1 cm bead
    // put between thumb and fingers: nothing touches it, and it falls.
    let at =
        |t: f64| Reported { curl: ramp(t, (0.3, 0.0), (0.6, 0.45)), opposition: 0.0, grab: None };
    let playback = recording(1.5, 90.0, at);
    let site = *one(&find_grasps(&playback, SAMPLE_STEP));
    assert!(site.sustained, "{site:?}");
    let summary = replayed(&playback, "box:0.01:0.002");
    let v = &summary.closings[0];
    assert_eq!(v.hold, Hold::NeverPressed, "{v}");
    assert!(v.to_string().contains("never pressed"), "{v}");
    assert!(summary.objects[0].displacement > 0.05, "it fell: {:?}", summary.objects[0]);
}
