//! The Leap Motion service's WebSocket JSON stream (protocol v6 frame
//! objects), feeding the same pipeline as recordings: its messages
//! ([`parse_message`]), and, with the `live` feature (on by default), a
//! client that reads them from the service (`LiveLeap`). The parser needs
//! no network, so a program that gets the messages itself (a web page's own
//! WebSocket) can use it without the feature.

use super::{InputError, TrackingFrame, leap};
use serde_json::Value;

#[cfg(feature = "live")]
mod client;

#[cfg(feature = "live")]
pub use client::{LiveLeap, STOP_POLL};

/// Where the Leap Motion service listens by default.
pub const DEFAULT_URL: &str = "ws://127.0.0.1:6437/v6.json";

/// Parses one text message of the service's stream: `Ok(Some(frame))` for a
/// protocol-v6 frame, `Ok(None)` for a message that is not a frame (the
/// version greeting, an event), and an error naming `source`, message
/// `index` and the field for a malformed frame.
pub fn parse_message(
    source: &str,
    index: usize,
    text: &str,
) -> Result<Option<TrackingFrame>, InputError> {
    let v = serde_json::from_str::<Value>(text).map_err(|e| InputError {
        source_name: source.to_string(),
        frame: Some(index),
        field: "json".into(),
        reason: crate::file_error::json_reason(&e),
    })?;
    if v.get("timestamp").is_none() && (v.get("version").is_some() || v.get("event").is_some()) {
        Ok(None)
    } else {
        leap::frame(source, index, &v).map(Some)
    }
}
