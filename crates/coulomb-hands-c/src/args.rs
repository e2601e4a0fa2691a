//! Arguments read from C and results written to it: every pointer checked
//! (null, alignment, length) and every number (finite) before anything is
//! used, each failure naming its argument. Results are written only once
//! the call has succeeded.

use crate::status::{ChStatus, Failure};
use std::ffi::{CStr, c_char};

/// Borrowed NUL-terminated UTF-8 text.
///
/// # Safety
/// `ptr` is null or a NUL-terminated string that outlives the call.
pub unsafe fn text<'a>(ptr: *const c_char, arg: &str) -> Result<&'a str, Failure> {
    // SAFETY: the caller's.
    unsafe { optional_text(ptr, arg) }?.ok_or_else(|| Failure::null(arg))
}

/// [`text`], where null means "none".
///
/// # Safety
/// As [`text`].
pub unsafe fn optional_text<'a>(ptr: *const c_char, arg: &str) -> Result<Option<&'a str>, Failure> {
    if ptr.is_null() {
        return Ok(None);
    }
    // SAFETY: not null, and NUL-terminated by the caller's contract.
    let text = unsafe { CStr::from_ptr(ptr) };
    text.to_str().map(Some).map_err(|e| Failure::invalid(arg, format!("not UTF-8 ({e})")))
}

/// `len` borrowed values at `ptr`, checked for null and alignment; none at
/// all may be null.
///
/// # Safety
/// `ptr` is null or points to `len` readable, initialised values.
pub unsafe fn slice<'a, T>(ptr: *const T, len: usize, arg: &str) -> Result<&'a [T], Failure> {
    if len == 0 {
        return Ok(&[]);
    }
    if ptr.is_null() {
        return Err(Failure::null(arg));
    }
    if !ptr.is_aligned() {
        return Err(Failure::invalid(arg, "misaligned"));
    }
    if len.checked_mul(size_of::<T>()).is_none_or(|bytes| bytes > isize::MAX as usize) {
        return Err(Failure::invalid(arg, format!("length {len} is too large")));
    }
    // SAFETY: not null, aligned, within isize::MAX bytes, and readable for
    // `len` values by the caller's contract.
    Ok(unsafe { std::slice::from_raw_parts(ptr, len) })
}

/// `len` finite floats at `ptr`, where `len` must be `want` (`unit` names
/// what each group of values is, for the message).
///
/// # Safety
/// As [`slice`].
pub unsafe fn floats<'a>(
    ptr: *const f32,
    len: usize,
    want: usize,
    arg: &str,
) -> Result<&'a [f32], Failure> {
    if len != want {
        return Err(Failure::invalid(arg, format!("{len} values, expected {want}")));
    }
    // SAFETY: the caller's.
    let values = unsafe { slice(ptr, len, arg) }?;
    finite(values, arg)?;
    Ok(values)
}

/// Every value finite, or an error naming the first that is not.
pub fn finite(values: &[f32], arg: &str) -> Result<(), Failure> {
    match values.iter().position(|v| !v.is_finite()) {
        Some(i) => {
            Err(Failure::invalid(&format!("{arg}[{i}]"), format!("{} is not finite", values[i])))
        }
        None => Ok(()),
    }
}

/// One finite number.
pub fn number(value: f32, arg: &str) -> Result<f32, Failure> {
    finite(&[value], arg).map(|()| value)
}

/// Where a single result goes, checked before the call does anything.
///
/// # Safety
/// `ptr` is null or points to a writable `T`.
pub unsafe fn out<'a, T>(ptr: *mut T, arg: &str) -> Result<&'a mut T, Failure> {
    if ptr.is_null() {
        return Err(Failure::null(arg));
    }
    if !ptr.is_aligned() {
        return Err(Failure::invalid(arg, "misaligned"));
    }
    // SAFETY: not null, aligned, writable by the caller's contract.
    Ok(unsafe { &mut *ptr })
}

/// An output array of `len` values at `ptr` that must hold `count`: the
/// size query (`ptr` null) is `None`; too short a buffer is an error.
///
/// # Safety
/// `ptr` is null or points to `len` writable values.
pub unsafe fn out_slice<'a, T>(
    ptr: *mut T,
    len: usize,
    count: usize,
    arg: &str,
) -> Result<Option<&'a mut [T]>, Failure> {
    if ptr.is_null() {
        return Ok(None);
    }
    if len < count {
        return Err(Failure::new(
            ChStatus::BufferTooSmall,
            format!("{arg}: room for {len}, {count} needed"),
        ));
    }
    if !ptr.is_aligned() {
        return Err(Failure::invalid(arg, "misaligned"));
    }
    // SAFETY: not null, aligned, writable for `len >= count` values by the
    // caller's contract.
    Ok(Some(unsafe { std::slice::from_raw_parts_mut(ptr, count) }))
}

/// An output of `count` values into `ptr` (room for `len`), with its size
/// in `*needed`: set whatever else happens, the one value a failed call
/// writes, so that a caller whose buffer was too short knows what to give.
/// A null `ptr` is the size query (`None`).
///
/// # Safety
/// `ptr` is null or points to `len` writable values.
pub unsafe fn output<'a, T>(
    ptr: *mut T,
    len: usize,
    count: usize,
    needed: &mut usize,
    arg: &str,
) -> Result<Option<&'a mut [T]>, Failure> {
    *needed = count;
    // SAFETY: the caller's contract.
    unsafe { out_slice(ptr, len, count, arg) }
}

/// Text written as NUL-terminated bytes into `buf` (`len` bytes), with
/// `*needed` set to the bytes it takes ([`output`]); a null `buf` is the
/// size query.
///
/// # Safety
/// `buf` is null or points to `len` writable bytes; `needed` is null or
/// points to a writable `size_t`.
pub unsafe fn write_text(
    text: &str,
    buf: *mut c_char,
    len: usize,
    needed: *mut usize,
) -> Result<(), Failure> {
    // SAFETY: `needed` is checked by `out`; `buf` by `out_slice`.
    let needed = unsafe { out(needed, "needed") }?;
    let bytes = text.as_bytes();
    let count = bytes.len() + 1;
    // SAFETY: the caller's contract (null or `len` writable bytes).
    if let Some(dest) = unsafe { output(buf.cast::<u8>(), len, count, needed, "buffer") }? {
        dest[..bytes.len()].copy_from_slice(bytes);
        dest[bytes.len()] = 0;
    }
    Ok(())
}
