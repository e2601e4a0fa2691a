//! The measures on small hand-made histories, and the checks' validation.

use super::*;

fn history(positions: &[Vec3], rotations: &[Quat]) -> History {
    History {
        dt: 0.5,
        names: vec!["box".into()],
        poses: positions.iter().zip(rotations).map(|(p, r)| vec![(*p, *r)]).collect(),
        velocities: positions.iter().map(|_| vec![Vec3::ZERO]).collect(),
        contacts: positions.iter().map(|_| vec![0]).collect(),
        hand_forces: positions.iter().map(|p| vec![Vec3::new(p.x, -1.0, 0.0)]).collect(),
        palms: positions.iter().map(|_| vec![Some((Vec3::ZERO, Quat::IDENTITY))]).collect(),
        gravity: Vec3::new(0.0, -9.81, 0.0),
    }
}

fn check(measure: Measure, min: Option<f32>, max: Option<f32>) -> Check {
    Check { name: "c".into(), measure, min, max }
}

#[test]
fn hand_force_is_the_mean_over_the_window_along_the_axis() {
    let h = history(
        &[Vec3::ZERO, Vec3::new(0.1, 0.0, 0.0), Vec3::new(0.2, 0.0, 0.0)],
        &[Quat::IDENTITY; 3],
    );
    let along = |axis, from| Measure::HandForce { object: "box".into(), from, to: None, axis };
    let r = check(along(Vec3::X, 0.5), Some(0.09), Some(0.11)).evaluate(&h);
    assert!((r.value - 0.1).abs() < 1e-6 && r.passed, "{r:?}");
    let r = check(along(Vec3::X, 1.0), None, Some(0.1)).evaluate(&h);
    assert!((r.value - 0.15).abs() < 1e-6 && !r.passed, "the last two steps: {r:?}");
    let r = check(along(-Vec3::Y, 0.5), Some(1.0), None).evaluate(&h);
    assert!((r.value - 1.0).abs() < 1e-6 && r.passed, "{r:?}");
    let slanted = check(along(Vec3::new(1.0, 1.0, 0.0), 0.5), Some(0.0), None);
    assert!(matches!(slanted.validate(), Err(CheckError::Axis(_))));
}

#[test]
fn acceleration_is_the_velocity_change_over_the_window_along_the_axis() {
    let mut h = history(&[Vec3::ZERO; 4], &[Quat::IDENTITY; 4]);
    h.velocities = [0.0, 0.3, 0.9, 1.2].iter().map(|&v| vec![Vec3::new(v, -v, 0.0)]).collect();
    let along = |axis, from, to| Measure::Acceleration { object: "box".into(), from, to, axis };
    // Steps 1 to 4 are at 0.5 … 2.0 s: from 0.5 to 1.5 s, 0.9 m/s in 1 s.
    let r = check(along(Vec3::X, 0.5, 1.5), Some(0.85), Some(0.95)).evaluate(&h);
    assert!((r.value - 0.9).abs() < 1e-6 && r.passed, "{r:?}");
    let r = check(along(-Vec3::Y, 1.0, 2.0), None, Some(0.5)).evaluate(&h);
    assert!((r.value - 0.9).abs() < 1e-6 && !r.passed, "{r:?}");
    // A window past the run's end has no time in it: not a number.
    let r = check(along(Vec3::X, 3.0, 4.0), Some(0.0), None).evaluate(&h);
    assert!(r.value.is_nan() && !r.passed, "{r:?}");
    let backwards = check(along(Vec3::X, 1.5, 0.5), Some(0.0), None).validate();
    assert_eq!(backwards, Err(CheckError::Window { from: 1.5, to: 0.5 }));
    let e = check(along(Vec3::new(1.0, 1.0, 0.0), 0.5, 1.5), Some(0.0), None).validate();
    assert!(matches!(e, Err(CheckError::Axis(_))), "{e:?}");
}

#[test]
fn displacement_rotation_and_path_measures() {
    let q90 = Quat::from_rotation_y(90f32.to_radians());
    let h = history(
        &[Vec3::ZERO, Vec3::new(0.1, 0.0, 0.0), Vec3::new(0.2, 0.0, 0.1)],
        &[Quat::IDENTITY, Quat::IDENTITY, q90],
    );
    let d = check(
        Measure::Displacement { object: "box".into(), from: 0.5, to: None, axis: Some(Vec3::X) },
        Some(0.15),
        None,
    );
    let r = d.evaluate(&h);
    assert!((r.value - 0.2).abs() < 1e-6 && r.passed && r.bound == ">= 0.15", "{r:?}");
    let spin = check(
        Measure::Rotation { object: "box".into(), from: 0.5, to: None, axis: Some(-Vec3::Y) },
        None,
        Some(-80.0),
    );
    let r = spin.evaluate(&h);
    assert!((r.value + 90.0).abs() < 0.01 && r.passed, "{r:?}");
    let path = check(
        Measure::PathDeviation {
            object: "box".into(),
            path: vec![[0.0, 0.0], [0.2, 0.0]],
            from: 0.5,
            to: None,
        },
        None,
        Some(0.05),
    );
    let r = path.evaluate(&h);
    assert!((r.value - 0.1).abs() < 1e-6 && !r.passed, "{r:?}");
}

#[test]
fn checks_without_a_bound_or_with_a_bad_axis_are_rejected() {
    let m = Measure::Height { object: "box".into(), at: 1.0 };
    assert!(check(m.clone(), None, None).validate().is_err());
    assert!(check(m, Some(0.0), None).validate().is_ok());
    let d = Measure::Displacement {
        object: "box".into(),
        from: 0.0,
        to: None,
        axis: Some(Vec3::new(1.0, 1.0, 0.0)),
    };
    assert!(check(d, Some(0.0), None).validate().unwrap_err().to_string().contains("unit"));
    let (object, to) = ("box".to_string(), None);
    let far =
        Measure::LandingDistance { object, from: 0.0, to, height: 0.0, target: [0.0, f32::NAN] };
    let e = check(far, None, Some(0.2)).validate().unwrap_err().to_string();
    assert!(e.starts_with("measure.target"), "{e}");
}
