//! A recording replayed through C, as the CLI's `replay FILE --json`.

use crate::args::{text, write_text};
use crate::status::{ChStatus, Failure, call};
use coulomb_hands::run::replay::{ReplayOptions, replay_file};
use std::ffi::c_char;
use std::path::Path;

/// Replays a recording (any format the CLI's `replay` reads: Leap JSON or
/// `.json.lz`, joint recordings, session files) with the CLI's defaults,
/// and writes what `coulomb-hands replay FILE --json` prints, as
/// NUL-terminated JSON, into `json` (`len` bytes). `*needed` is set to
/// the bytes it takes, NUL included. With `json` null, or too short (then
/// `CH_STATUS_BUFFER_TOO_SMALL` and nothing written), call again: the
/// replay runs again, to the same bytes.
///
/// # Safety
/// `path` is NUL-terminated; `json` is null or points to `len` writable
/// bytes; `needed` points to a writable `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ch_replay(
    path: *const c_char,
    json: *mut c_char,
    len: usize,
    needed: *mut usize,
) -> ChStatus {
    call("ch_replay", || {
        // SAFETY: the caller's contract.
        let path = unsafe { text(path, "path") }?;
        if needed.is_null() {
            return Err(Failure::null("needed"));
        }
        let replayed = replay_file(Path::new(path), &ReplayOptions::default())
            .map_err(|e| Failure::input(format!("path: {e}")))?;
        let text = serde_json::to_string_pretty(&replayed)
            .map_err(|e| Failure::new(ChStatus::Internal, e.to_string()))?;
        // SAFETY: the caller's contract, as `write_text` states it.
        unsafe { write_text(&text, json, len, needed) }
    })
}
