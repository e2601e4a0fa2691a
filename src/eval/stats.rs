//! Summary statistics with 95 % confidence intervals, for the study's
//! tables and plots.

pub use crate::output::report::Estimate;

/// The standard normal's 97.5 % quantile.
const Z: f64 = 1.959_964;

/// Student's t 97.5 % quantiles for 1 to 30 degrees of freedom (the
/// standard table).
const T975: [f64; 30] = [
    12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160,
    2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056,
    2.052, 2.048, 2.045, 2.042,
];

/// Student's t 97.5 % quantile for `df` degrees of freedom: the table to
/// 30, above it the Cornish–Fisher expansion about the normal (within
/// 0.01 % there, exact at ∞).
pub fn t975(df: usize) -> f64 {
    if df == 0 {
        return f64::NAN;
    }
    if let Some(t) = T975.get(df - 1) {
        return *t;
    }
    let d = df as f64;
    let (z3, z5) = (Z.powi(3), Z.powi(5));
    Z + (z3 + Z) / (4.0 * d)
        + (5.0 * z5 + 16.0 * z3 + 3.0 * Z) / (96.0 * d * d)
        + (3.0 * Z.powi(7) + 19.0 * z5 + 17.0 * z3 - 15.0 * Z) / (384.0 * d.powi(3))
}

/// Mean, sample standard deviation and median of `v` (not numbers for
/// none: a method that completed no trial has no error, not a zero one).
pub fn describe(v: &[f64]) -> (f64, f64, f64) {
    if v.is_empty() {
        return (f64::NAN, f64::NAN, f64::NAN);
    }
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
    let mut sorted = v.to_vec();
    sorted.sort_by(f64::total_cmp);
    let mid = sorted.len() / 2;
    let median = if sorted.len().is_multiple_of(2) {
        (sorted[mid - 1] + sorted[mid]) / 2.0
    } else {
        sorted[mid]
    };
    (mean, var.sqrt(), median)
}

/// The mean of `v` with its 95 % t interval (a single value has none).
pub fn mean_ci(v: &[f64]) -> Estimate {
    let (mean, sd, _) = describe(v);
    if v.is_empty() {
        return Estimate::NONE;
    }
    let half = t975(v.len() - 1) * sd / (v.len() as f64).sqrt();
    let half = if half.is_finite() { half } else { f64::NAN };
    Estimate { value: mean, low: mean - half, high: mean + half }
}

/// The mean of quantities `v` that are never negative (counts, distances)
/// with its 95 % t interval, whose lower end is held at 0.
pub fn nonnegative_ci(v: &[f64]) -> Estimate {
    let e = mean_ci(v);
    Estimate { low: e.low.max(0.0), ..e }
}

/// The proportion `k` of `n` with its 95 % Wilson score interval, which
/// stays inside [0, 1] and is not empty at 0 of n.
pub fn proportion_ci(k: usize, n: usize) -> Estimate {
    if n == 0 {
        return Estimate::NONE;
    }
    let (k, n) = (k as f64, n as f64);
    let p = k / n;
    let z2 = Z * Z;
    let centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
    let half = Z / (1.0 + z2 / n) * (p * (1.0 - p) / n + z2 / (4.0 * n * n)).sqrt();
    Estimate { value: p, low: (centre - half).max(0.0), high: (centre + half).min(1.0) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn t_quantiles_match_the_table() {
        for (df, table) in [(3, 3.182), (14, 2.145), (40, 2.021), (60, 2.000), (120, 1.980)] {
            assert!((t975(df) - table).abs() / table < 0.001, "df {df}: {}", t975(df));
        }
        // The expansion joins the table smoothly.
        assert!((t975(31) - 2.040).abs() < 0.001, "{}", t975(31));
    }

    #[test]
    fn a_mean_interval_covers_the_mean_by_t_times_the_standard_error() {
        let e = mean_ci(&[2.0, 4.0, 6.0, 8.0]);
        // sd = 2.582, se = 1.291, t(3) = 3.182.
        assert!((e.value - 5.0).abs() < 1e-12);
        assert!((e.high - 5.0 - 3.182 * 1.2910).abs() < 0.01, "{e:?}");
        assert!(mean_ci(&[]).value.is_nan());
        assert!(mean_ci(&[3.0]).low.is_nan());
    }

    #[test]
    fn wilson_intervals_stay_in_the_unit_range() {
        let none = proportion_ci(0, 20);
        assert_eq!((none.value, none.low), (0.0, 0.0));
        assert!((none.high - 0.161).abs() < 0.001, "{none:?}");
        let half = proportion_ci(10, 20);
        assert!((half.low - 0.299).abs() < 0.001 && (half.high - 0.701).abs() < 0.001);
        assert_eq!(proportion_ci(20, 20).high, 1.0);
    }
}
