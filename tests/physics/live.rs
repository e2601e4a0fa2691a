//! The live Leap Motion WebSocket client against a local server on
//! loopback that streams a real recording's frames.

use coulomb_hands::input::leap;
use coulomb_hands::input::live::LiveLeap;
use std::net::TcpListener;
use tungstenite::Message;

#[test]
fn streams_a_recording_over_a_local_websocket_and_skips_malformed_frames() {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/leap/pinch.json.lz");
    let text = std::fs::read_to_string(&path).unwrap();
    let json = String::from_utf16(&lz_str::decompress_from_base64(text.trim()).unwrap()).unwrap();
    let root: serde_json::Value = serde_json::from_str(&json).unwrap();
    let frames: Vec<String> =
        root["frames"].as_array().unwrap()[..100].iter().map(|f| f.to_string()).collect();
    let mut broken = root["frames"][100].clone();
    broken["hands"][0].as_object_mut().unwrap().remove("palmPosition");

    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let url = format!("ws://{}/v6.json", listener.local_addr().unwrap());
    let server = std::thread::spawn(move || {
        let (stream, _) = listener.accept().unwrap();
        let mut ws = tungstenite::accept(stream).unwrap();
        ws.send(Message::text(r#"{"serviceVersion":"2.3.1","version":6}"#)).unwrap();
        for (i, f) in frames.iter().enumerate() {
            if i == 50 {
                ws.send(Message::text("{not json")).unwrap();
                ws.send(Message::text(broken.to_string())).unwrap();
            }
            ws.send(Message::text(f.clone())).unwrap();
        }
        ws.close(None).unwrap();
        // Drain until the client acknowledges the close.
        while ws.read().is_ok() {}
    });

    // The client runs on its own thread so a hang fails the test instead
    // of stalling the suite.
    let (done, result) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let mut live = LiveLeap::connect(&url).unwrap();
        let mut received = Vec::new();
        while let Some(frame) = live.next_frame().unwrap() {
            received.push(frame);
        }
        done.send((live, received)).ok();
    });
    let (live, received) = result
        .recv_timeout(std::time::Duration::from_secs(60))
        .expect("the stream finished within 60 s");
    server.join().unwrap();
    assert_eq!(live.frames, 100);
    assert_eq!(live.skipped, 2, "the bad JSON and the frame without a palm");
    let e = live.last_error.unwrap().to_string();
    assert!(e.contains("palmPosition") && e.contains("missing"), "{e}");
    // The same frames a recording gives: the same pipeline downstream.
    let recorded = leap::load(&path).unwrap();
    assert_eq!(received, recorded.frames[..100]);
}
