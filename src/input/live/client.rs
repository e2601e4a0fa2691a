//! The Leap Motion service's WebSocket client (feature `live`).

use super::parse_message;
use crate::input::{InputError, TrackingFrame};
use std::io::ErrorKind;
use std::net::TcpStream;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;
use tungstenite::stream::MaybeTlsStream;
use tungstenite::{Message, WebSocket};

/// How often a reader stopped by a flag looks at it while no message comes.
pub const STOP_POLL: Duration = Duration::from_millis(100);

/// A live connection to a Leap Motion service.
pub struct LiveLeap {
    url: String,
    socket: WebSocket<MaybeTlsStream<TcpStream>>,
    /// Frames received and parsed.
    pub frames: usize,
    /// Messages that were not valid frames, skipped.
    pub skipped: usize,
    /// The last skipped message's error, for diagnostics.
    pub last_error: Option<InputError>,
}

impl LiveLeap {
    /// Connects and asks for frames even when the app is in the background.
    pub fn connect(url: &str) -> Result<LiveLeap, InputError> {
        let fail = |reason: String| InputError {
            source_name: url.to_string(),
            frame: None,
            field: "connection".into(),
            reason,
        };
        let (mut socket, _) = tungstenite::connect(url).map_err(|e| fail(e.to_string()))?;
        socket.send(Message::text(r#"{"background": true}"#)).map_err(|e| fail(e.to_string()))?;
        Ok(LiveLeap { url: url.to_string(), socket, frames: 0, skipped: 0, last_error: None })
    }

    /// Blocks for the next frame. Messages that are not frames (the
    /// service's version greeting, events) are passed over; malformed
    /// frames are skipped and counted. `Ok(None)` when the stream closes.
    pub fn next_frame(&mut self) -> Result<Option<TrackingFrame>, InputError> {
        self.wait_at_most(None)?;
        self.read_frame(None)
    }

    /// [`Self::next_frame`], but `Ok(None)` too once `stop` is set: while no
    /// message comes, a reader on a thread of its own looks at it every
    /// [`STOP_POLL`], so the thread can end while the service sends
    /// nothing. Only a plain `ws://` stream can be waited on so; any other
    /// is an error rather than a wait that could not be stopped.
    pub fn next_frame_unless(
        &mut self,
        stop: &AtomicBool,
    ) -> Result<Option<TrackingFrame>, InputError> {
        if !self.wait_at_most(Some(STOP_POLL))? {
            return Err(self.fail("only a plain ws:// stream can be read on a thread".into()));
        }
        self.read_frame(Some(stop))
    }

    /// Sets how long a read waits for a message (`None`: for as long as it
    /// takes). `false` for a stream that is not a plain socket, which keeps
    /// waiting for as long as it takes.
    fn wait_at_most(&self, timeout: Option<Duration>) -> Result<bool, InputError> {
        match self.socket.get_ref() {
            MaybeTlsStream::Plain(tcp) => {
                tcp.set_read_timeout(timeout).map_err(|e| self.fail(e.to_string()))?;
                Ok(true)
            }
            _ => Ok(false),
        }
    }

    fn fail(&self, reason: String) -> InputError {
        InputError {
            source_name: self.url.clone(),
            frame: Some(self.frames + self.skipped),
            field: "connection".into(),
            reason,
        }
    }

    fn read_frame(
        &mut self,
        stop: Option<&AtomicBool>,
    ) -> Result<Option<TrackingFrame>, InputError> {
        loop {
            if stop.is_some_and(|stop| stop.load(Ordering::Relaxed)) {
                return Ok(None);
            }
            let message = match self.socket.read() {
                Ok(m) => m,
                Err(tungstenite::Error::ConnectionClosed | tungstenite::Error::AlreadyClosed) => {
                    return Ok(None);
                }
                // The read timeout of `next_frame_unless`: nothing yet.
                Err(tungstenite::Error::Io(e))
                    if stop.is_some()
                        && matches!(e.kind(), ErrorKind::WouldBlock | ErrorKind::TimedOut) =>
                {
                    continue;
                }
                Err(e) => return Err(self.fail(e.to_string())),
            };
            let text = match message {
                Message::Text(t) => t,
                Message::Close(_) => {
                    // Send the queued close reply so the service sees a clean close.
                    let _ = self.socket.flush();
                    return Ok(None);
                }
                _ => continue,
            };
            let index = self.frames + self.skipped;
            let parsed = parse_message(&self.url, index, text.as_str());
            match parsed {
                Ok(Some(frame)) => {
                    self.frames += 1;
                    return Ok(Some(frame));
                }
                Ok(None) => continue,
                Err(e) => {
                    self.skipped += 1;
                    self.last_error = Some(e);
                }
            }
        }
    }
}
