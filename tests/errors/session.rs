//! Session files (SessionError): reading, writing and replaying them; each
//! error names the file, or the call that failed.

use crate::{Scratch, cli_error, names};
use coulomb_hands::hand::rig::HandRig;
use coulomb_hands::output::{Session, SessionError};
use coulomb_hands::pipeline::Call;
use coulomb_hands::{InteractionConfig, ObjectDesc, Side};
use glam::{Quat, Vec3};

const SESSION: &str = r#"{"format": "coulomb-hands-session/1", "config": {}, "calls": CALLS}"#;

fn session_text(calls: &str) -> String {
    SESSION.replace("CALLS", calls)
}

#[test]
fn unreadable_session_files_are_named() {
    let dir = Scratch::new("session-files");
    let e = Session::load(&dir.path("gone.json")).unwrap_err();
    assert!(matches!(e, SessionError::File { .. }), "{e:?}");
    names(e, &[&dir.text("gone.json"), "No such file"]);
    let broken = dir.file("broken.json", session_text(r#"["step", {"set_hand_pose": [0, {}]}]"#));
    let e = Session::load(&broken).unwrap_err().to_string();
    names(e.clone(), &[&dir.text("broken.json"), ": line 1 column ", "missing field `palm`"]);
    assert_eq!(e.matches("line").count(), 1, "the place is said once: {e}");
    let future = session_text("[]").replace("session/1\"", "session/2\", \"note\": \"session/1\"");
    let e = Session::load(&dir.file("future.json", future)).unwrap_err();
    let expected = "expected \"coulomb-hands-session/1\"";
    names(e, &["future.json: format is \"coulomb-hands-session/2\", ", expected]);
    let fast = session_text("[]").replace("{}", r#"{"dt": 5}"#);
    let e = Session::load(&dir.file("fast.json", fast)).unwrap_err();
    names(e, &["fast.json: config: dt: must be in (0, 0.1] s, got 5"]);
    let e = Session::new(InteractionConfig::default()).save(&dir.path("")).unwrap_err();
    names(e, &[&dir.text(""), "directory"]);
}

fn replay_error(config: InteractionConfig, calls: Vec<Call>) -> String {
    let session = Session { calls, ..Session::new(config) };
    session.replay(|_| {}).err().expect("the replay fails").to_string()
}

#[test]
fn replays_name_the_call_that_failed() {
    let config = InteractionConfig::default();
    let bad = InteractionConfig { dt: 0.0, ..config };
    names(replay_error(bad, vec![]), &["session config: dt: ", "got 0"]);
    let pose = HandRig::adult(Side::Left).pose(Vec3::Y, Quat::IDENTITY, [0.0; 5]);
    let calls = vec![Call::AddHand(Side::Left), Call::Step, Call::SetHandPose(1, Box::new(pose))];
    names(replay_error(config, calls), &["session call 2: hand 1 does not exist"]);
    let mut thin = HandRig::adult(Side::Left).pose(Vec3::Y, Quat::IDENTITY, [0.0; 5]);
    thin.fingers[1][2].radius = 0.0;
    let calls = vec![Call::AddHand(Side::Left), Call::SetHandPose(0, Box::new(thin))];
    let e = replay_error(config, calls);
    names(e, &["session call 1: hand 0: bone index-distal: radius 0 m must be positive"]);
    let light = ObjectDesc::cuboid("feather", Vec3::splat(0.02), 0.0, Vec3::Y);
    let e = replay_error(config, vec![Call::Step, Call::AddObject(light)]);
    names(e, &["session call 1: object 'feather': mass: ", "got 0"]);
    names(replay_error(config, vec![Call::ClearHandPose(4)]), &["session call 0: hand 4"]);
    let e = replay_error(config, vec![Call::SetObjectLocked(2, true)]);
    names(e, &["session call 0: object 2 does not exist"]);
    let e = replay_error(config, vec![Call::Step, Call::ReseatContacts(0)]);
    names(e, &["session call 1: object 0 does not exist"]);
}

#[test]
fn the_cli_names_the_session_file_of_a_failed_replay() {
    let dir = Scratch::new("session-cli");
    let file = dir.file("s.json", session_text(r#"["step", {"clear_hand_pose": 3}]"#));
    let e = cli_error(&["replay", &file.display().to_string()]);
    assert_eq!(e, format!("{}: session call 1: hand 3 does not exist", dir.text("s.json")));
    let file = dir.file("c.json", session_text("[]").replace("{}", r#"{"gravity": [0, 1e39, 0]}"#));
    let e = cli_error(&["replay", &file.display().to_string()]);
    names(e, &[&dir.text("c.json"), ": config: gravity: must be finite", "inf"]);
}

#[test]
fn a_session_s_bytes_replay_as_its_file_does_and_name_it() {
    use coulomb_hands::run::replay::{ReplayOptions, Replayed, replay_bytes, replay_file};
    let dir = Scratch::new("session-bytes");
    let cube = ObjectDesc::cuboid("cube", Vec3::splat(0.04), 0.05, Vec3::Y);
    let calls = vec![Call::AddObject(cube), Call::Step, Call::Step];
    let file = dir.path("s.json");
    Session { calls, ..Session::new(InteractionConfig::default()) }.save(&file).unwrap();
    let (name, bytes) = (dir.text("s.json"), std::fs::read(&file).unwrap());
    let options = ReplayOptions::default();
    let json = |r: Replayed| serde_json::to_string(&r).unwrap();
    let from_bytes = replay_bytes(&name, bytes, &options).unwrap();
    assert_eq!(json(from_bytes), json(replay_file(&file, &options).unwrap()));
    let bad = session_text(r#"["step", {"clear_hand_pose": 3}]"#).into_bytes();
    let e = replay_bytes("s.json", bad, &options).unwrap_err();
    names(e, &["s.json: session call 1: hand 3 does not exist"]);
}
