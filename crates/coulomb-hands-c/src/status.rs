//! What every call returns, the thread's last error, and the one wrapper
//! every entry point runs its body in.

use std::cell::RefCell;
use std::panic::{AssertUnwindSafe, catch_unwind};

/// A call's outcome. Anything but `CH_STATUS_OK` leaves a message for
/// `ch_last_error`, and the call changed nothing.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChStatus {
    /// Done.
    Ok = 0,
    /// A pointer that must not be null was.
    NullPointer = 1,
    /// An argument was refused: a wrong length, a number that is not finite
    /// or out of range, a misaligned array, text that is not UTF-8, an
    /// unknown name.
    InvalidArgument = 2,
    /// An output buffer is too short; query its size with a null buffer.
    BufferTooSmall = 3,
    /// The world handle is not a live world's (freed, or never made).
    StaleHandle = 4,
    /// A config, scene or recording was refused: its JSON, a field, or a
    /// value (the message names it).
    InvalidInput = 5,
    /// The world refused the call: an unknown object or hand id, a state it
    /// cannot take (the message says why).
    Refused = 6,
    /// The header is not this library's ABI version.
    AbiMismatch = 7,
    /// A fault inside the library (a caught panic); the world it happened
    /// in is unusable and should be freed.
    Internal = 8,
}

/// Why a call failed: its status and message.
#[derive(Debug)]
pub(crate) struct Failure {
    pub status: ChStatus,
    pub message: String,
}

impl Failure {
    pub fn new(status: ChStatus, message: impl Into<String>) -> Failure {
        Failure { status, message: message.into() }
    }

    pub fn null(arg: &str) -> Failure {
        Failure::new(ChStatus::NullPointer, format!("{arg} is null"))
    }

    pub fn invalid(arg: &str, why: impl std::fmt::Display) -> Failure {
        Failure::new(ChStatus::InvalidArgument, format!("{arg}: {why}"))
    }

    pub fn refused(why: impl std::fmt::Display) -> Failure {
        Failure::new(ChStatus::Refused, why.to_string())
    }

    pub fn input(why: impl std::fmt::Display) -> Failure {
        Failure::new(ChStatus::InvalidInput, why.to_string())
    }
}

thread_local! {
    static LAST_ERROR: RefCell<String> = const { RefCell::new(String::new()) };
}

/// Runs an entry point's body: its failure or panic becomes a status and
/// the thread's last error, prefixed with the call's name.
pub(crate) fn call(name: &str, body: impl FnOnce() -> Result<(), Failure>) -> ChStatus {
    let (status, message) = match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => return ChStatus::Ok,
        Ok(Err(failure)) => (failure.status, failure.message),
        Err(panic) => {
            let what = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            (ChStatus::Internal, format!("internal error (caught): {what}"))
        }
    };
    LAST_ERROR.with(|last| *last.borrow_mut() = format!("{name}: {message}"));
    status
}

/// This thread's last failure's message ("" before any).
pub(crate) fn last_error() -> String {
    LAST_ERROR.with(|last| last.borrow().clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_panic_is_a_status_and_a_message_not_an_unwind_across_the_boundary() {
        let status = call("ch_example", || panic!("a fault inside"));
        assert_eq!(status, ChStatus::Internal);
        let message = LAST_ERROR.with(|last| last.borrow().clone());
        assert_eq!(message, "ch_example: internal error (caught): a fault inside");
        // A success leaves the last failure's message.
        assert_eq!(call("ch_other", || Ok(())), ChStatus::Ok);
        assert!(LAST_ERROR.with(|last| last.borrow().starts_with("ch_example")));
    }
}
