//! Flight after a release: when a hand last pressed on an object, where it
//! lands, and where ballistic flight from its release predicts it lands,
//! for the `release_speed`, `landing_error` and `landing_distance` checks.

use super::check::History;
#[cfg(doc)]
use super::check::Measure;
use glam::Vec3;

impl History {
    /// The step of object `o`'s release in [`from`, `to`]: the last in which
    /// a hand contact pressed on it, if a step of the window follows it.
    pub(super) fn release(&self, o: usize, from: f32, to: Option<f32>) -> Option<usize> {
        let window = self.steps(from, to);
        let end = *window.end();
        window.rev().find(|&s| self.contacts[s][o] > 0).filter(|&s| s < end)
    }

    /// Where object `o`'s centre first comes down to `height` after step
    /// `after`, interpolated between steps.
    fn landing(&self, o: usize, after: usize, height: f32) -> Option<Vec3> {
        (after + 1..self.poses.len()).find_map(|s| {
            let (a, b) = (self.poses[s - 1][o].0, self.poses[s][o].0);
            let k = if a.y > b.y { ((a.y - height) / (a.y - b.y)).clamp(0.0, 1.0) } else { 1.0 };
            (b.y <= height).then(|| a.lerp(b, k))
        })
    }

    /// Where object `o`, released in [`from`, `to`] (as for
    /// [`Measure::ReleaseSpeed`]), lands at `height`, and where ballistic
    /// flight from its release predicts it would.
    pub(super) fn landed_and_predicted(
        &self,
        o: usize,
        (from, to): (f32, Option<f32>),
        height: f32,
    ) -> Option<(Vec3, Vec3)> {
        let s = self.release(o, from, to)?;
        let (p, v) = (self.poses[s][o].0, self.velocities[s][o]);
        Some((self.landing(o, s, height)?, ballistic_landing(p, v, self.gravity, height)?))
    }
}

/// Where a point thrown from `p` at `v` (m, m/s) under `gravity` (m/s²)
/// comes down to `height` (m): the later root of
/// `p.y + v.y t + g.y t²/2 = height`. `None` without downward gravity or if
/// it never gets there.
pub fn ballistic_landing(p: Vec3, v: Vec3, gravity: Vec3, height: f32) -> Option<Vec3> {
    let (a, b, c) = (0.5 * gravity.y, v.y, p.y - height);
    let discriminant = b * b - 4.0 * a * c;
    if a >= 0.0 || discriminant < 0.0 {
        return None;
    }
    let t = (-b - discriminant.sqrt()) / (2.0 * a);
    (t >= 0.0).then(|| p + v * t + 0.5 * gravity * t * t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Quat;

    #[test]
    fn ballistic_landing_solves_the_flight_to_the_height() {
        // Thrown level at 2 m/s from 1.25 m under g = 10: 0.5 s to fall
        // 1.25 m, 1 m ahead.
        let g = Vec3::new(0.0, -10.0, 0.0);
        let p = ballistic_landing(Vec3::new(0.0, 1.25, 0.0), Vec3::Z * 2.0, g, 0.0).unwrap();
        assert!(p.distance(Vec3::new(0.0, 0.0, 1.0)) < 1e-5, "{p}");
        assert!(ballistic_landing(Vec3::ZERO, Vec3::Y, Vec3::ZERO, -1.0).is_none(), "no gravity");
        assert!(ballistic_landing(Vec3::ZERO, Vec3::ZERO, g, 1.0).is_none(), "never that high");
    }

    #[test]
    fn release_is_the_last_pressing_step_and_landing_the_first_crossing() {
        // Held (a pressing contact) for two steps, then falling 0.1 m a step.
        let ys = [0.5, 0.5, 0.4, 0.3, 0.2, 0.1];
        let contacts = [1, 1, 0, 0, 0, 0];
        let h = History {
            dt: 0.1,
            names: vec!["ball".into()],
            poses: ys.iter().map(|&y| vec![(Vec3::new(0.0, y, 0.0), Quat::IDENTITY)]).collect(),
            velocities: ys.iter().map(|_| vec![Vec3::ZERO]).collect(),
            contacts: contacts.iter().map(|&c| vec![c]).collect(),
            hand_forces: ys.iter().map(|_| vec![Vec3::ZERO]).collect(),
            palms: ys.iter().map(|_| vec![None]).collect(),
            gravity: Vec3::ZERO,
        };
        assert_eq!(h.release(0, 0.0, None), Some(1));
        assert_eq!(h.release(0, 0.0, Some(0.2)), None, "still pressing at the window's end");
        let landed = h.landing(0, 1, 0.25).unwrap();
        assert!((landed.y - 0.25).abs() < 1e-6, "interpolated between steps: {landed}");
        assert!(h.landed_and_predicted(0, (0.0, None), 0.25).is_none(), "no gravity, no flight");
    }
}
