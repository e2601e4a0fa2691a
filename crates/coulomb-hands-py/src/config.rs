//! `Config`: `InteractionConfig` with the field names and values of the
//! config files (the book's config page), checked as the library checks
//! them.

use crate::ConfigError;
use coulomb_hands::{GammaMode, InteractionConfig, Method};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use pythonize::depythonize;

/// The settings of a world: `InteractionConfig`'s fields, as in config files.
#[pyclass(module = "coulomb_hands", eq, from_py_object)]
#[derive(Clone, PartialEq)]
pub struct Config {
    inner: InteractionConfig,
    /// `inner`'s fields as a config file has them, kept beside it so that
    /// reading one is a lookup, not the whole config written and parsed.
    fields: serde_json::Map<String, serde_json::Value>,
}

impl Config {
    /// `config`, which the library has checked.
    pub fn new_checked(config: InteractionConfig) -> PyResult<Config> {
        // Through JSON's text, as `as_dict`, so that 0.001 s reads 0.001.
        let text = serde_json::to_string(&config);
        let fields = text.and_then(|t| serde_json::from_str(&t));
        let mut fields: serde_json::Map<String, serde_json::Value> =
            fields.map_err(|e| crate::OutputError::new_err(format!("config: {e}")))?;
        fields.insert("gamma".into(), gamma(config.gamma));
        Ok(Config { inner: config, fields })
    }

    /// The library's config.
    pub fn inner(&self) -> &InteractionConfig {
        &self.inner
    }
}

/// `config`'s fields as a dict, in the library's order, as a config file
/// has them (through JSON, so that 0.001 s reads 0.001, not its f32's
/// digits), but γ as the package spells it everywhere ([`gamma`]).
fn as_dict<'py>(py: Python<'py>, config: &InteractionConfig) -> PyResult<Bound<'py, PyDict>> {
    let dict = crate::values::to_python(py, config)?.cast_into::<PyDict>()?;
    dict.set_item("gamma", pythonize::pythonize(py, &gamma(config.gamma))?)?;
    Ok(dict)
}

/// γ as the package spells it, for objects, replays and configs alike:
/// `"auto"`, or a number of N/m (a config file's `"Auto"` and
/// `{"Fixed": n}` are read too).
fn gamma(mode: GammaMode) -> serde_json::Value {
    match mode {
        GammaMode::Auto => "auto".into(),
        // Through its shortest text, as the rest: 380 reads 380.0.
        GammaMode::Fixed(n) => {
            n.to_string().parse::<f64>().map_or(serde_json::Value::Null, |n| n.into())
        }
    }
}

/// The config of `dict`'s fields, checked: a field of the wrong type or an
/// unknown one is a `ConfigError` naming it, as is a bad value.
fn from_dict(dict: &Bound<'_, PyDict>) -> PyResult<InteractionConfig> {
    let config: InteractionConfig =
        depythonize(dict.as_any()).map_err(|e| ConfigError::new_err(format!("config: {e}")))?;
    config.validate().map_err(|e| ConfigError::new_err(e.to_string()))?;
    Ok(config)
}

#[pymethods]
impl Config {
    /// The default config with the given fields changed.
    #[new]
    #[pyo3(signature = (**fields))]
    fn new(py: Python<'_>, fields: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let dict = as_dict(py, &InteractionConfig::default())?;
        if let Some(fields) = fields {
            for (key, value) in fields.iter() {
                dict.set_item(key, value)?;
            }
        }
        Config::new_checked(from_dict(&dict)?)
    }

    /// A method's config (`coulomb`, `thesis`, `kinematic`, `heuristic`).
    #[staticmethod]
    fn for_method(method: &str) -> PyResult<Self> {
        let method: Method = crate::values::method(method)?;
        Config::new_checked(method.config(InteractionConfig::default()))
    }

    /// Every field and its value, as in a config file.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        as_dict(py, &self.inner)
    }

    /// A copy with the given fields changed.
    #[pyo3(signature = (**fields))]
    fn replace(&self, py: Python<'_>, fields: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let dict = as_dict(py, &self.inner)?;
        if let Some(fields) = fields {
            for (key, value) in fields.iter() {
                dict.set_item(key, value)?;
            }
        }
        Config::new_checked(from_dict(&dict)?)
    }

    fn __getattr__<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        let value = self.fields.get(name).ok_or_else(|| {
            pyo3::exceptions::PyAttributeError::new_err(format!("Config has no field {name}"))
        })?;
        Ok(pythonize::pythonize(py, value)?)
    }

    fn __setattr__(
        &mut self,
        name: &Bound<'_, PyString>,
        value: &Bound<'_, PyAny>,
    ) -> PyResult<()> {
        let dict = as_dict(name.py(), &self.inner)?;
        dict.set_item(name, value)?;
        *self = Config::new_checked(from_dict(&dict)?)?;
        Ok(())
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let fields: Vec<String> = as_dict(py, &self.inner)?
            .iter()
            .map(|(k, v)| Ok(format!("{k}={}", v.repr()?)))
            .collect::<PyResult<_>>()?;
        Ok(format!("Config({})", fields.join(", ")))
    }
}
