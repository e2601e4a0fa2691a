//! The whole grip, beyond each contact: how stiffly the contacts of one
//! hand press together, and how much energy a pad gives back when it
//! unloads.
//!
//! Tracked bones are rigid and pass through virtual objects, so a bone's
//! depth is not a pad's compression but how hard the person grips. In a
//! real hand the squeeze balances inside the hand: the thumb's normal
//! force equals the sum of the opposing fingers' (Zatsiorsky & Latash 2008,
//! "Multifinger prehension: an overview", J Mot Behav 40(5)), which act as
//! one *virtual finger* (Arbib, Iberall & Lyons 1985; Iberall 1987). With
//! one γ per contact, n fingers against a thumb press n times as stiffly,
//! so the only thing free to balance them, the object, moves
//! `(n−1)/(n+1)` of the depth towards the thumb, and springs back across
//! the hand as the grip opens. Here the contacts of one hand that press an
//! object from opposite sides make two virtual fingers of equal stiffness,
//! the squeeze the one-γ-per-contact grip reached once the object had
//! moved ([`side_count`], [`virtual_finger_factor`]).
//!
//! A real pad also returns little of the work that loaded it: the
//! fingertip dissipates 81 % of it over a tap (Jindrich, Zhou, Becker &
//! Dennerlein 2003, J Biomech 36(4)), and skin loaded sideways loses 80 %
//! to hysteresis (Wang & Hayward 2007, J Biomech 40(4)). The contact's
//! damper is set to lose as much ([`pad_damping_ratio`]).

use glam::Vec3;

/// The fraction of the work that loaded it which a fingertip pad
/// dissipates as it unloads: 81 %, averaged over fast and normal taps
/// (varying < 3 % across them; Jindrich et al. 2003).
pub const FINGERTIP_DISSIPATION: f32 = 0.81;

/// Depth sums of a set of pressing contacts, each weighted (m, m²).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct DepthSums {
    /// `Σ k_j s_j`: the weighted depths.
    pub depths: f32,
    /// `Σ k_j s_j²`.
    pub squares: f32,
}

impl DepthSums {
    /// How many contacts press, each counted by its depth:
    /// `(Σ k s)² / Σ k s²`. It is n for n contacts at one depth, falls
    /// smoothly as one of them backs out, and is 0 for none.
    #[inline]
    pub fn count(&self) -> f32 {
        if self.squares > 0.0 { self.depths * self.depths / self.squares } else { 0.0 }
    }
}

/// The two sides of a grip as one contact, of normal `n`, sees them.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Sides {
    /// Its own side: each pressing contact weighted by `max(0, n·n_j)`,
    /// the part of its press along `n` (this contact included, at 1).
    pub own: DepthSums,
    /// The opposing side: each weighted by `max(0, −n·n_j)`.
    pub opposing: DepthSums,
}

/// The [`Sides`] of a contact of normal `n` (unit) among a hand's
/// `pressing` contacts on one object, as (normal, depth) pairs (this
/// contact included). Contacts on the same face count whole on one side,
/// those on the opposite face on the other, those at right angles on
/// neither.
pub fn sides(n: Vec3, pressing: impl IntoIterator<Item = (Vec3, f32)>) -> Sides {
    let mut out = Sides::default();
    for (n_j, s_j) in pressing {
        let (along, s) = (n.dot(n_j), s_j.max(0.0));
        let side = if along >= 0.0 { &mut out.own } else { &mut out.opposing };
        let k = along.abs();
        side.depths += k * s;
        side.squares += k * s * s;
    }
    out
}

/// How many contacts' stiffness each side of a grip presses with, for a
/// side of `own` contacts against `opposing` ones (depth-weighted
/// [`DepthSums::count`]s): their harmonic mean `2CD/(C+D)`.
///
/// With one γ per contact, the two sides are springs Cγ and Dγ with the
/// object between them, in series: at equal sinks s the grip squeezes
/// with `γ·s·2CD/(C+D)`, but only once the object has moved off-centre to
/// balance them. Giving both sides that stiffness keeps the squeeze and
/// drops the offset. A side that nothing opposes counts its opposition as
/// one contact (what pushes back, the object's support or inertia, has no
/// digits to count), so the count does not jump when the first opposing
/// contact begins to press: a lone pad keeps γ, and n pads on one face
/// press like `2n/(n+1)` of them.
#[inline]
pub fn side_count(own: f32, opposing: f32) -> f32 {
    let opposing = opposing.max(1.0);
    if own <= 0.0 { 0.0 } else { 2.0 * own * opposing / (own + opposing) }
}

/// A contact's factor on γ (and on its damper): its part of its side,
/// `s / Σs`, times its [`side_count`].
///
/// So the two sides of a grip press equally stiffly however many digits
/// each has: a thumb against n fingers presses like `2n/(n+1)` contacts,
/// and each finger like `2/(n+1)` of one. Equal sinks then balance, and
/// stay balanced while every pad backs out together; a side sunk deeper
/// than the other still pushes. Deeper pads of a side carry more of it,
/// and a pad joining at depth 0 adds nothing to its side's force.
#[inline]
pub fn virtual_finger_factor(depth: f32, sides: &Sides) -> f32 {
    let own = sides.own;
    if depth <= 0.0 || own.depths <= 0.0 {
        return 1.0;
    }
    depth / own.depths * side_count(own.count(), sides.opposing.count())
}

/// The fraction of its stored energy that a Kelvin–Voigt pad of damping
/// ratio `zeta` gives back to a free object it pushes away from rest.
///
/// The pad, compressed by `x₀` and let go, follows
/// `x = x₀e^{−ζωt}(cos ω_d t + ζ/√(1−ζ²)·sin ω_d t)` and lets go of the
/// object when its force `k·x + c·ẋ` falls to zero: at `ω_d t = acos ζ`,
/// with the speed `ω x₀ exp(−ζ acos ζ / √(1−ζ²))`. So the fraction is
/// `exp(−2ζ·acos ζ / √(1−ζ²))`: 1 for a pure spring, 0.30 at ζ = 0.5,
/// `e^{−2}` at ζ = 1 (the limit of both forms), and `acosh` in place of
/// `acos` above it.
pub fn released_energy_fraction(zeta: f32) -> f32 {
    let z = f64::from(zeta.max(0.0));
    let angle_per_sine = if (z - 1.0).abs() < 1e-6 {
        1.0
    } else if z < 1.0 {
        z.acos() / (1.0 - z * z).sqrt()
    } else {
        z.acosh() / (z * z - 1.0).sqrt()
    };
    (-2.0 * z * angle_per_sine).exp() as f32
}

/// The damping ratio ζ at which a pad released from rest gives back
/// `1 − dissipation` of the energy that loaded it
/// ([`released_energy_fraction`], which falls with ζ), found by bisection:
/// 0.76 for the fingertip's 81 %. `dissipation` is a fraction in [0, 1);
/// outside it there is no such ζ, and the answer is `None`.
pub fn pad_damping_ratio(dissipation: f32) -> Option<f32> {
    if !(0.0..1.0).contains(&dissipation) {
        return None;
    }
    let returned = 1.0 - dissipation;
    let (mut low, mut high) = (0.0f32, 64.0f32);
    for _ in 0..48 {
        let mid = 0.5 * (low + high);
        if released_energy_fraction(mid) > returned {
            low = mid;
        } else {
            high = mid;
        }
    }
    Some(0.5 * (low + high))
}

/// How long a grip of stiffness `stiffness` (N/m) and damping ratio `zeta`
/// takes to come to rest about where it holds a `mass` kg object (s): its
/// 2 % settling time, 4 over its slowest decay rate (`ζω`, or
/// `ω(ζ − √(ζ² − 1))` overdamped, with `ω = √(k/m)`; e.g. Ogata, *Modern
/// Control Engineering*, §5.3), but at most one period `2π/ω`: a grip
/// damped too little to settle rings, and its ringing is part of what it
/// does with the object. `None` unless stiffness and mass are positive and
/// finite.
pub fn settling_time(stiffness: f32, mass: f32, zeta: f32) -> Option<f32> {
    let valid = |x: f32| x.is_finite() && x > 0.0;
    if !(valid(stiffness) && valid(mass)) {
        return None;
    }
    let omega = (stiffness / mass).sqrt();
    let z = zeta.max(0.0);
    let decay = if z < 1.0 { z * omega } else { omega * (z - (z * z - 1.0).sqrt()) };
    let period = std::f32::consts::TAU / omega;
    Some(if decay > 0.0 { (4.0 / decay).min(period) } else { period })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each contact's factor in a hand of (normal, depth) contacts.
    fn factors(contacts: &[(Vec3, f32)]) -> Vec<f32> {
        let all = contacts.iter().copied();
        contacts.iter().map(|&(n, s)| virtual_finger_factor(s, &sides(n, all.clone()))).collect()
    }

    #[test]
    fn a_thumb_and_the_three_fingers_it_opposes_press_equally_stiffly() {
        let mut hand = vec![(-Vec3::X, 0.0026)];
        hand.extend([(Vec3::X, 0.0026); 3]);
        let f = factors(&hand);
        // In series, γ and 3γ squeeze like 1.5γ: each side now has it.
        assert!((f[0] - 1.5).abs() < 1e-5, "{f:?}");
        for finger in &f[1..] {
            assert!((finger - 0.5).abs() < 1e-5, "{f:?}");
        }
        assert!((f[0] - f[1..].iter().sum::<f32>()).abs() < 1e-5);
    }

    #[test]
    fn a_lone_pad_keeps_gamma_and_a_newcomer_adds_no_jump() {
        assert_eq!(factors(&[(Vec3::Y, 0.004)]), vec![1.0]);
        // Two unopposed pads press like 4/3 of one.
        let pair = factors(&[(Vec3::Y, 0.004); 2]);
        assert!(pair.iter().all(|f| (f - 2.0 / 3.0).abs() < 1e-6), "{pair:?}");
        let gamma = 310.0;
        let side_force = |hand: &[(Vec3, f32)]| {
            let f = factors(hand);
            hand.iter().zip(f).filter(|(c, _)| c.0 == Vec3::Y).map(|(c, k)| gamma * k * c.1).sum()
        };
        // Two fingers on +y against a thumb; a third finger touches at 0.
        let (a, b) = ((Vec3::Y, 0.004), (-Vec3::Y, 0.004));
        let before: f32 = side_force(&[a, a, b]);
        let after: f32 = side_force(&[a, a, b, (Vec3::Y, 0.0)]);
        assert_eq!(before, after);
        // The first opposing pad to press changes nothing either.
        let alone: f32 = side_force(&[a, a]);
        assert!((side_force(&[a, a, (-Vec3::Y, 1e-7)]) - alone).abs() < 1e-6 * alone);
        // And the thumb only presses as deep as it is.
        let thumb = |s: f32| factors(&[a, a, (-Vec3::Y, s)])[2] * gamma * s;
        assert!(thumb(1e-7) < 1e-3 * thumb(0.004));
    }

    #[test]
    fn a_deeper_side_still_pushes() {
        // Thumb 3 mm deep, two fingers 2 mm: both sides press like 4/3 of
        // a contact, so the thumb's pushes by 4/3·γ·(3 − 2) mm.
        let hand = [(-Vec3::X, 0.003), (Vec3::X, 0.002), (Vec3::X, 0.002)];
        let f = factors(&hand);
        let net = f[0] * 0.003 - f[1] * 0.002 - f[2] * 0.002;
        assert!((net - 4.0 / 3.0 * 0.001).abs() < 1e-7, "{f:?}");
    }

    #[test]
    fn pads_at_right_angles_do_not_count() {
        let s = sides(Vec3::X, [(Vec3::X, 0.003), (Vec3::Z, 0.003)]);
        assert!((s.own.count() - 1.0).abs() < 1e-6);
        assert_eq!(s.opposing.count(), 0.0);
        // Tilted 60°: half of the neighbour counts.
        let tilted = Vec3::new(0.5, 3f32.sqrt() / 2.0, 0.0);
        let s = sides(Vec3::X, [(Vec3::X, 0.002), (tilted, 0.002)]);
        assert!((s.own.count() - 1.5).abs() < 1e-5);
    }

    #[test]
    fn the_released_fraction_matches_a_stepped_pad() {
        // Step a mass off a Kelvin–Voigt pad until the pad's force is zero.
        for zeta in [0.0f32, 0.3, 0.5, 0.76, 1.0, 1.7] {
            let (w, dt) = (1.0f64, 1e-6f64);
            let (mut x, mut v) = (1.0f64, 0.0f64);
            while w * w * x + 2.0 * f64::from(zeta) * w * v > 0.0 {
                v -= (w * w * x + 2.0 * f64::from(zeta) * w * v) * dt;
                x += v * dt;
            }
            let stepped = (v * v) as f32;
            let exact = released_energy_fraction(zeta);
            assert!((stepped - exact).abs() < 1e-3, "ζ {zeta}: {stepped} vs {exact}");
        }
        assert!((released_energy_fraction(0.5) - 0.2984).abs() < 1e-3);
    }

    #[test]
    fn the_fingertips_dissipation_gives_its_damping_ratio() {
        let zeta = pad_damping_ratio(FINGERTIP_DISSIPATION).unwrap();
        assert!((zeta - 0.762).abs() < 0.005, "{zeta}");
        assert!((released_energy_fraction(zeta) - 0.19).abs() < 1e-4);
        assert!(pad_damping_ratio(0.0).unwrap() < 1e-6);
        assert_eq!(pad_damping_ratio(1.0), None);
        assert_eq!(pad_damping_ratio(-0.1), None);
        assert_eq!(pad_damping_ratio(f32::NAN), None);
    }

    #[test]
    fn a_grip_settles_in_four_decay_times_or_rings_for_a_period() {
        // 35 g in a 260 N/m grip: ω = 86.2 rad/s.
        let omega = (260.0f32 / 0.035).sqrt();
        let t = settling_time(260.0, 0.035, 0.76).unwrap();
        assert!((t - 4.0 / (0.76 * omega)).abs() < 1e-6, "{t}");
        // Underdamped below ζ = 2/π: a period.
        let period = std::f32::consts::TAU / omega;
        for zeta in [0.0, 0.3, 0.6] {
            assert!((settling_time(260.0, 0.035, zeta).unwrap() - period).abs() < 1e-6);
        }
        // Overdamped: the slow pole; much overdamped, a period again.
        let slow = omega * (1.05 - (1.05f32 * 1.05 - 1.0).sqrt());
        assert!((settling_time(260.0, 0.035, 1.05).unwrap() - 4.0 / slow).abs() < 1e-5);
        assert!((settling_time(260.0, 0.035, 9.0).unwrap() - period).abs() < 1e-6);
        for (k, m) in [(0.0, 0.1), (100.0, 0.0), (f32::NAN, 0.1), (100.0, f32::INFINITY)] {
            assert_eq!(settling_time(k, m, 0.5), None);
        }
    }
}
