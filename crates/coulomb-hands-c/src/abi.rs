//! The calls about the ABI itself: its version, and the last error.

use crate::status::{ChStatus, Failure, call, last_error};
use std::ffi::c_char;

/// The ABI's version: a program built against one header calls
/// `ch_check_abi(CH_ABI_VERSION)` to refuse a library of another.
pub const CH_ABI_VERSION: u32 = 1;

/// The message of this thread's last failed call, as NUL-terminated UTF-8,
/// into `message` (`len` bytes). `*needed` is always set to the bytes it
/// takes, NUL included (1 if no call failed yet): with `message` null, that
/// is all the call does. Too short a buffer is `CH_STATUS_BUFFER_TOO_SMALL`,
/// with nothing written to it. Never changes the last error itself, and
/// never unwinds (a panic inside is `CH_STATUS_INTERNAL`).
///
/// # Safety
/// `message` is null or points to `len` writable bytes; `needed` points to
/// a writable `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ch_last_error(
    message: *mut c_char,
    len: usize,
    needed: *mut usize,
) -> ChStatus {
    // Not in `call`: its own failure is reported as its status only, so
    // that the message it was asked for stays the last error.
    let written = std::panic::catch_unwind(|| {
        // SAFETY: the caller's contract, as `write_text` states it.
        unsafe { crate::args::write_text(&last_error(), message, len, needed) }
    });
    match written {
        Ok(Ok(())) => ChStatus::Ok,
        Ok(Err(failure)) => failure.status,
        Err(_) => ChStatus::Internal,
    }
}

/// This library's ABI version ([`CH_ABI_VERSION`] when it was built).
#[unsafe(no_mangle)]
pub extern "C" fn ch_abi_version() -> u32 {
    CH_ABI_VERSION
}

/// `CH_STATUS_OK` when `version` (the header's `CH_ABI_VERSION`) is this
/// library's, else `CH_STATUS_ABI_MISMATCH`: call it once before any other.
#[unsafe(no_mangle)]
pub extern "C" fn ch_check_abi(version: u32) -> ChStatus {
    call("ch_check_abi", || {
        if version == CH_ABI_VERSION {
            Ok(())
        } else {
            Err(Failure::new(
                ChStatus::AbiMismatch,
                format!("the header is ABI version {version}, this library {}", CH_ABI_VERSION),
            ))
        }
    })
}
