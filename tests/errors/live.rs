//! The live stream's errors (InputError): a service that is not there, a
//! stream that breaks, and messages that are not frames, against a local
//! WebSocket server on loopback.

use crate::{frame, leap_hand, names};
use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::live::LiveLeap;
use coulomb_hands::run::live::run_live;
use coulomb_hands::run::replay::replay_world;
use coulomb_hands::{InteractionConfig, RunError};
use glam::Vec3;
use std::net::TcpListener;
use tungstenite::Message;

/// Serves `messages` to the first client after the service's greeting;
/// then closes properly (`close`) or just drops the connection.
fn serve(messages: Vec<String>, close: bool) -> (String, std::thread::JoinHandle<()>) {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let url = format!("ws://{}/v6.json", listener.local_addr().unwrap());
    let server = std::thread::spawn(move || {
        let (stream, _) = listener.accept().unwrap();
        let mut ws = tungstenite::accept(stream).unwrap();
        ws.send(Message::text(r#"{"serviceVersion":"2.3.1","version":6}"#)).unwrap();
        for m in messages {
            ws.send(Message::text(m)).unwrap();
        }
        if close {
            ws.close(None).unwrap();
            while ws.read().is_ok() {}
        } else {
            // Read what the client sent, so dropping the socket is a plain
            // end of stream, not a reset that could discard the messages.
            ws.read().unwrap();
        }
    });
    (url, server)
}

fn free_url() -> String {
    let port = TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port();
    format!("ws://127.0.0.1:{port}/v6.json")
}

#[test]
fn connecting_to_nothing_names_the_url() {
    let url = free_url();
    let e = LiveLeap::connect(&url).err().expect("nothing listens");
    assert_eq!((e.field.as_str(), e.frame), ("connection", None));
    names(e, &[&format!("{url}: connection: ")]);
    let mut world = replay_world(InteractionConfig::default(), false).unwrap();
    let conversion = Conversion::leap_desktop(Vec3::ZERO);
    let e = run_live(&url, &mut world, conversion, 0.1, 0.01, &mut []).unwrap_err();
    assert!(matches!(e, RunError::Input(_)), "{e:?}");
    names(e, &[&format!("{url}: connection: ")]);
}

#[test]
fn malformed_messages_are_skipped_and_the_last_one_named() {
    let mut bad = frame(2000, &[leap_hand(7)]);
    bad["hands"][0]["palmNormal"] = serde_json::json!([0, 0, 0]);
    let messages = vec![frame(1000, &[]).to_string(), "{not json".into(), bad.to_string()];
    let (url, server) = serve(messages, true);
    let mut live = LiveLeap::connect(&url).unwrap();
    assert!(live.next_frame().unwrap().is_some());
    let e = live.last_error.clone();
    assert!(e.is_none(), "{e:?}");
    assert!(live.next_frame().unwrap().is_none(), "the stream closed");
    server.join().unwrap();
    assert_eq!((live.frames, live.skipped), (1, 2));
    let e = live.last_error.unwrap();
    assert_eq!(e.frame, Some(2));
    names(e, &[&url, ": frame 2: hands[0].palmNormal: zero-length direction"]);
}

#[test]
fn json_errors_of_the_stream_give_the_frame_line_and_column() {
    let (url, server) = serve(vec!["{not json".into()], true);
    let mut live = LiveLeap::connect(&url).unwrap();
    assert!(live.next_frame().unwrap().is_none());
    server.join().unwrap();
    let e = live.last_error.unwrap();
    names(e, &[&url, ": frame 0: json: line 1 column 2: key must be a string"]);
}

#[test]
fn a_stream_that_breaks_names_the_frame_it_broke_at() {
    let (url, server) = serve(vec![frame(1000, &[]).to_string(), "[]".into()], false);
    let mut live = LiveLeap::connect(&url).unwrap();
    assert!(live.next_frame().unwrap().is_some());
    server.join().unwrap();
    let e = live.next_frame().unwrap_err();
    assert_eq!((e.field.as_str(), e.frame), ("connection", Some(2)));
    names(e, &[&url, ": frame 2: connection: "]);
}

#[test]
fn timestamps_too_far_apart_to_subtract_drop_the_frame_instead_of_panicking() {
    let frames = [frame(i64::MIN, &[leap_hand(7)]), frame(i64::MAX, &[leap_hand(7)])];
    let (url, server) = serve(frames.iter().map(|f| f.to_string()).collect(), true);
    let mut world = replay_world(InteractionConfig::default(), false).unwrap();
    let conversion = Conversion::leap_desktop(Vec3::ZERO);
    let summary = run_live(&url, &mut world, conversion, 0.1, 0.01, &mut []).unwrap();
    server.join().unwrap();
    // The first is refused as malformed (a negative timestamp); the second
    // is the clock's zero.
    assert_eq!((summary.frames, summary.skipped, summary.dropped), (1, 1, 0), "{summary:?}");
}
