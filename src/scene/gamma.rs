//! How an object's contact stiffness γ is chosen, and how it is spelled:
//! in files `"Auto"` or `{"Fixed": 400.0}`, on the command line and in the
//! bindings `auto` or a number.

/// How an object's contact stiffness γ (N/m) is chosen (§3.5.6).
///
/// Written to files as `"Auto"` or `{"Fixed": 400.0}`; read from those, or
/// as the command line and the bindings spell it, `"auto"` or a number.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub enum GammaMode {
    /// The same γ for every object; the thesis uses 400 N/m.
    Fixed(f32),
    /// Eq. 3.11 per object: `γ = m g / (μ_st · 0.2 · d)`.
    Auto,
}

impl Default for GammaMode {
    fn default() -> Self {
        GammaMode::Fixed(400.0)
    }
}

/// As the command line takes it: `auto`, or γ in N/m.
impl std::fmt::Display for GammaMode {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            GammaMode::Fixed(gamma) => write!(f, "{gamma}"),
            GammaMode::Auto => f.write_str("auto"),
        }
    }
}

impl<'de> serde::Deserialize<'de> for GammaMode {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<GammaMode, D::Error> {
        d.deserialize_any(GammaSpelling)
    }
}

/// The spellings [`GammaMode`] is read from. The number is checked where
/// γ is used (a config's, an object's), as a file's `{"Fixed": n}` is.
struct GammaSpelling;

impl<'de> serde::de::Visitor<'de> for GammaSpelling {
    type Value = GammaMode;

    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(r#""auto", a number of N/m, or {"Fixed": N/m}"#)
    }

    fn visit_str<E: serde::de::Error>(self, s: &str) -> Result<GammaMode, E> {
        match s {
            "auto" | "Auto" => Ok(GammaMode::Auto),
            _ => Err(E::invalid_value(serde::de::Unexpected::Str(s), &self)),
        }
    }

    fn visit_f64<E: serde::de::Error>(self, gamma: f64) -> Result<GammaMode, E> {
        Ok(GammaMode::Fixed(gamma as f32))
    }

    fn visit_i64<E: serde::de::Error>(self, gamma: i64) -> Result<GammaMode, E> {
        Ok(GammaMode::Fixed(gamma as f32))
    }

    fn visit_u64<E: serde::de::Error>(self, gamma: u64) -> Result<GammaMode, E> {
        Ok(GammaMode::Fixed(gamma as f32))
    }

    fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<GammaMode, A::Error> {
        use serde::de::Error;
        let mode = match map.next_key::<String>()?.as_deref() {
            Some("Fixed") => GammaMode::Fixed(map.next_value()?),
            Some("Auto") => {
                map.next_value::<serde::de::IgnoredAny>()?;
                GammaMode::Auto
            }
            Some(other) => return Err(A::Error::unknown_variant(other, &["Fixed", "Auto"])),
            None => return Err(A::Error::invalid_length(0, &self)),
        };
        match map.next_key::<serde::de::IgnoredAny>()? {
            Some(_) => Err(A::Error::invalid_length(2, &self)),
            None => Ok(mode),
        }
    }
}

/// `auto`, or γ as a positive, finite number of N/m: the spelling of the
/// command line's `--gamma`, and of the Python and web bindings' `gamma`.
impl std::str::FromStr for GammaMode {
    type Err = GammaError;
    fn from_str(s: &str) -> Result<GammaMode, GammaError> {
        if s == "auto" {
            return Ok(GammaMode::Auto);
        }
        match s.parse::<f32>() {
            Ok(gamma) if gamma.is_finite() && gamma > 0.0 => Ok(GammaMode::Fixed(gamma)),
            _ => Err(GammaError(s.to_string())),
        }
    }
}

/// A γ that is neither `auto` nor a positive, finite number of N/m.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("expected \"auto\" or a positive number of N/m, got {0:?}")]
pub struct GammaError(pub String);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gamma_is_read_as_files_and_as_the_command_line_spell_it() {
        let read = |json: &str| serde_json::from_str::<GammaMode>(json).map_err(|e| e.to_string());
        for json in [r#""Auto""#, r#""auto""#, r#"{"Auto": null}"#] {
            assert_eq!(read(json), Ok(GammaMode::Auto), "{json}");
        }
        for json in ["350", "350.0", r#"{"Fixed": 350}"#, r#"{"Fixed": 350.0}"#] {
            assert_eq!(read(json), Ok(GammaMode::Fixed(350.0)), "{json}");
        }
        for json in [r#""stiff""#, "true", r#"{"Soft": 1}"#, r#"{"Fixed": 1, "Auto": null}"#] {
            let e = read(json).unwrap_err();
            assert!(
                e.contains(r#""auto", a number of N/m, or {"Fixed": N/m}"#)
                    || e.contains("unknown variant"),
                "{json}: {e}"
            );
        }
        // Written as files always had it.
        assert_eq!(serde_json::to_string(&GammaMode::Fixed(350.0)).unwrap(), r#"{"Fixed":350.0}"#);
        assert_eq!(serde_json::to_string(&GammaMode::Auto).unwrap(), r#""Auto""#);
        // The command line's: `auto` or a positive, finite number.
        assert_eq!("auto".parse(), Ok(GammaMode::Auto));
        assert_eq!("420".parse(), Ok(GammaMode::Fixed(420.0)));
        for bad in ["Auto", "-1", "0", "inf", "NaN", ""] {
            let e = bad.parse::<GammaMode>().unwrap_err().to_string();
            assert_eq!(e, format!(r#"expected "auto" or a positive number of N/m, got {bad:?}"#));
        }
    }
}
