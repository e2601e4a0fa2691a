//! A reduced positioning-accuracy study (thesis §5.2): every method runs
//! the same synthetic users' trials to the end.

use coulomb_hands::Method;
use coulomb_hands::eval::board::{SQUARE, SQUARES};
use coulomb_hands::eval::{AccuracyOptions, accuracy};

#[test]
fn every_method_completes_the_reduced_accuracy_study_with_errors_on_the_board() {
    let options = AccuracyOptions { users: 2, trials: 5, seed: 11, methods: Method::ALL.to_vec() };
    let report = accuracy(&options, &mut |_, _| {}).expect("the study runs");
    let board_diagonal_mm = (SQUARES as f64 * SQUARE as f64) * 2f64.sqrt() * 1e3;
    assert_eq!(report.methods.len(), 4);
    for m in &report.methods {
        assert_eq!(m.errors_mm.len() + m.failed, 10, "{}: every trial counted", m.method);
        for e in &m.errors_mm {
            assert!(e.is_finite() && *e >= 0.0 && *e < board_diagonal_mm, "{}: {e} mm", m.method);
        }
        assert!(m.mean_time_s.is_finite() && m.mean_mm.is_finite(), "{}", m.method);
        // A grip that holds a 40 g cube completes nearly every trial; the
        // thesis's law as written, an undamped spring, may not (README).
        if m.method != "thesis" {
            assert!(m.failed <= 2, "{}: {} of 10 trials failed", m.method, m.failed);
        }
    }
}
