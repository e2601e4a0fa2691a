//! Value parsers for the command line: each error says what was expected.

/// A finite number > 0.
pub fn positive(s: &str) -> Result<f64, String> {
    let v: f64 = s.trim().parse().map_err(|e| format!("expected a number, got {s:?} ({e})"))?;
    if v.is_finite() && v > 0.0 && (v as f32) > 0.0 {
        Ok(v)
    } else {
        Err(format!("must be a finite number > 0, got {s}"))
    }
}

/// A finite number ≥ 0.
pub fn at_least_zero(s: &str) -> Result<f64, String> {
    let v: f64 = s.trim().parse().map_err(|e| format!("expected a number, got {s:?} ({e})"))?;
    if v.is_finite() && v >= 0.0 {
        Ok(v)
    } else {
        Err(format!("must be a finite number ≥ 0, got {s}"))
    }
}

pub fn parse_vec3(s: &str) -> Result<glam::Vec3, String> {
    let v: Vec<f32> = s
        .split(',')
        .map(|p| p.trim().parse::<f32>())
        .collect::<Result<_, _>>()
        .map_err(|e| format!("expected three finite numbers \"x,y,z\", got \"{s}\" ({e})"))?;
    match v.as_slice() {
        [x, y, z] if v.iter().all(|c| c.is_finite()) => Ok(glam::Vec3::new(*x, *y, *z)),
        _ => Err(format!("expected three finite numbers \"x,y,z\", got \"{s}\"")),
    }
}

/// A count of at least one (users, trials), up to 65535: clap names the
/// range when it is not.
pub fn count() -> impl clap::builder::TypedValueParser<Value = usize> {
    use clap::builder::TypedValueParser;
    clap::value_parser!(u16).range(1..).map(usize::from)
}
