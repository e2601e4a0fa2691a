//! What a synthetic user sees of the cube: glances, each with an error
//! from the display it is seen on, not the exact pose every millisecond.
//!
//! The thesis's users wore an Oculus Rift DK2 (§3.3): 960 × 1080 pixels per
//! eye over about 100° across, so a pixel spans θ = 100°/960 ≈ 6.3 arcmin.
//! Where a thing is across the line of sight is read from its image, to
//! within about half a pixel: `σ_lateral = d·θ/2`, 0.46 mm at d = 0.5 m.
//! How far away it is comes from binocular disparity, whose half-pixel
//! step is a depth step of `σ_depth = d²·θ/(2a)` (the stereo relation
//! `Δd = d²·Δγ/a`, Howard & Rogers 1995, "Binocular Vision and
//! Stereopsis"), with a = 63 mm, the mean adult interpupillary distance
//! (Dodgson 2004, "Variation and extrema of human interpupillary
//! distance"): 3.6 mm at 0.5 m, eight times worse. The cube and its target
//! square are seen at the same distance, so only these random errors
//! matter, not a bias in judged distance.
//!
//! A user looks again every quarter second, the mean fixation of scene
//! viewing (Rayner 1998, "Eye movements in reading and information
//! processing", 225–330 ms), and between glances takes a cube it carries
//! to move with its hand.

use glam::{Quat, Vec3};
use rand::Rng;
use rand_distr::{Distribution, StandardNormal};

/// The angle one display pixel spans (rad): 100° over 960 pixels.
pub const PIXEL: f32 = 100.0 / 960.0 * std::f32::consts::PI / 180.0;
/// The interpupillary distance (m).
pub const EYES_APART: f32 = 0.063;
/// How often the user looks again (s).
pub const GLANCE: f64 = 0.25;
/// Where the eyes are, from the board's centre (m): seated at a desk,
/// 0.5 m from it, looking down at it at 53°.
pub const EYE: Vec3 = Vec3::new(0.0, 0.4, -0.3);

/// The error of one glance at a point `at`, from the eyes at `eye` (m):
/// `σ_depth` along the line of sight, `σ_lateral` across it, scaled by
/// `scale` (0 sees exactly).
pub fn glance_error(eye: Vec3, at: Vec3, scale: f32, rng: &mut impl Rng) -> Vec3 {
    let sight = at - eye;
    let d = sight.length();
    let Some(along) = sight.try_normalize() else { return Vec3::ZERO };
    let (across, up) = along.any_orthonormal_pair();
    let lateral = d * PIXEL / 2.0;
    let depth = d * d * PIXEL / (2.0 * EYES_APART);
    let mut normal = || -> f32 { StandardNormal.sample(rng) };
    scale * (along * depth * normal() + across * lateral * normal() + up * lateral * normal())
}

/// One user's view of the cube.
#[derive(Debug, Clone)]
pub struct Perception {
    /// Where the eyes are (world, m).
    pub eye: Vec3,
    /// How strong the glance errors are (1: the DK2's; 0: exact).
    pub scale: f32,
    /// The last glance: when, what was seen, and where the hand was.
    last: Option<(f64, Vec3, Quat, Vec3)>,
}

impl Perception {
    /// Eyes at `eye` with errors `scale` times the display's.
    pub fn new(eye: Vec3, scale: f32) -> Perception {
        Perception { eye, scale, last: None }
    }

    /// Where the user takes the cube to be at `t` (s), its true pose being
    /// `truth` and the hand's grip centre `hand`: a new glance every
    /// [`GLANCE`], in between the last one, moved with the hand if the user
    /// is `carrying` it.
    pub fn sees(
        &mut self,
        t: f64,
        truth: (Vec3, Quat),
        hand: Vec3,
        carrying: bool,
        rng: &mut impl Rng,
    ) -> (Vec3, Quat) {
        let due = self.last.is_none_or(|(at, ..)| t - at >= GLANCE - 1e-9);
        if due {
            let error = glance_error(self.eye, truth.0, self.scale, rng);
            self.last = Some((t, truth.0 + error, truth.1, hand));
        }
        let (_, seen, turn, hand_then) = self.last.expect("a glance was taken");
        if carrying { (seen + (hand - hand_then), turn) } else { (seen, turn) }
    }

    /// Forgets the last glance, so the next call looks again: after a
    /// hand lets go, a user looks where the cube came to rest.
    pub fn look_again(&mut self) {
        self.last = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn depth_is_judged_eight_times_worse_than_direction_at_half_a_metre() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let eye = Vec3::new(0.1, 0.3, -0.4);
        let at = eye + Vec3::new(0.3, -0.3, 0.2).normalize() * 0.5;
        let along = (at - eye).normalize();
        let (mut depth, mut lateral, n) = (0.0f64, 0.0f64, 20_000);
        for _ in 0..n {
            let e = glance_error(eye, at, 1.0, &mut rng);
            let d = e.dot(along);
            depth += f64::from(d * d);
            lateral += f64::from((e - d * along).length_squared()) / 2.0;
        }
        let (depth, lateral) = ((depth / n as f64).sqrt(), (lateral / n as f64).sqrt());
        assert!((depth - 3.61e-3).abs() < 0.1e-3, "{depth}");
        assert!((lateral - 0.455e-3).abs() < 0.02e-3, "{lateral}");
        assert_eq!(glance_error(eye, at, 0.0, &mut rng), Vec3::ZERO);
    }

    #[test]
    fn between_glances_a_carried_cube_moves_with_the_hand() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let mut p = Perception::new(Vec3::new(0.0, 0.4, -0.3), 0.0);
        let cube = (Vec3::new(0.05, 0.02, 0.0), Quat::IDENTITY);
        let hand = Vec3::new(0.05, 0.06, 0.0);
        assert_eq!(p.sees(0.0, cube, hand, true, &mut rng).0, cube.0);
        // 0.1 s later the cube has moved 1 cm; the user still sees the old
        // glance, carried along by its hand's 2 cm.
        let moved = (cube.0 + Vec3::X * 0.01, cube.1);
        let seen = p.sees(0.1, moved, hand + Vec3::X * 0.02, true, &mut rng).0;
        assert!((seen - (cube.0 + Vec3::X * 0.02)).length() < 1e-6);
        // Not carrying it, the glance stands; a new glance sees it anew.
        assert_eq!(p.sees(0.2, moved, hand, false, &mut rng).0, cube.0);
        assert_eq!(p.sees(0.25, moved, hand, false, &mut rng).0, moved.0);
    }
}
