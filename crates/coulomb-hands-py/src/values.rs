//! Python values to and from the library's own: a method's name, a γ
//! argument, and any serialisable result as JSON's Python objects. Every
//! module takes them from here, so none imports another for them.

use crate::{ArgumentError, UnknownMethodError};
use coulomb_hands::{GammaMode, Method};
use pyo3::prelude::*;

/// A method by name.
pub fn method(name: &str) -> PyResult<Method> {
    name.parse().map_err(|e: coulomb_hands::pipeline::method::UnknownMethod| {
        UnknownMethodError::new_err(e.to_string())
    })
}

/// `value` as JSON's Python objects.
pub fn to_python<'py>(
    py: Python<'py>,
    value: &impl serde::Serialize,
) -> PyResult<Bound<'py, PyAny>> {
    let text = serde_json::to_string(value)
        .map_err(|e| crate::OutputError::new_err(format!("output: {e}")))?;
    py.import("json")?.call_method1("loads", (text,))
}

/// A γ argument: a number (N/m) or `"auto"`, as the command line's
/// `--gamma` takes it; a number the world checks where it uses it.
pub fn gamma(value: &Bound<'_, PyAny>) -> PyResult<GammaMode> {
    match value.extract::<String>() {
        Ok(text) => text.parse().map_err(|e| ArgumentError::new_err(format!("gamma: {e}"))),
        Err(_) => Ok(GammaMode::Fixed(value.extract::<f32>()?)),
    }
}
