//! The Coulomb friction contact law of thesis §3.5.5–3.5.6, as pure math.
//!
//! Nothing here knows about rapier: every function takes and returns plain
//! [`glam::Vec3`]/`f32` values, so these files can be read beside the
//! thesis. Each equation, and each clause this crate adds to it, has
//! exactly one home, whose doc comment cites it:
//!
//! * [`law`]: the thesis's equations, Eq. 3.4–3.8 and Eq. 3.10;
//! * [`safeguards`]: what keeps the law sane on tracked hands (the
//!   penetration-speed limit, the force cap and its tangential cap, the
//!   damper);
//! * [`slip`]: where a slipping spring re-anchors, one rule for a whole
//!   contact and for each skin-patch sample;
//! * [`stribeck`]: how static friction fades to kinetic as skin slides
//!   faster (a departure from the thesis's sudden drop);
//! * [`gamma`]: the contact stiffness γ, Eq. 3.11;
//! * [`implicit`]: the springs stepped by backward Euler, for steps too
//!   long for explicit ones (a host engine's 90 Hz);
//! * [`grip`]: the whole grip: the two sides of one hand's grip press as
//!   equally stiff virtual fingers, and the pad's damper loses what a
//!   fingertip does.
//!
//! # Sign convention (used everywhere in the crate)
//! * `n` is the **outward** unit surface normal of the object at the contact
//!   point `C`.
//! * `p` is the tracked bone's point that pushes into the object.
//! * `f = γ(C − p)` (Eq. 3.4) is the force **on the bone** (the reaction).
//!   While the bone presses into the object, `C` lies outside `p` along `n`,
//!   so `f · n > 0`: that is the first clause of Eq. 3.7.
//! * The force **on the object** is the opposite, `−(f_n + f_T)`: it pushes
//!   the object the way the bone penetrates and drags it along with the bone.
//!
//! Units: lengths in metres, forces in newtons, γ in N/m, speeds in m/s.

pub mod gamma;
pub mod grip;
pub mod implicit;
pub mod law;
pub mod safeguards;
pub mod slip;
pub mod stribeck;

pub use gamma::{MAX_PENETRATION_FRACTION, auto_gamma};
pub use grip::{
    DepthSums, FINGERTIP_DISSIPATION, Sides, pad_damping_ratio, released_energy_fraction,
    settling_time, side_count, sides, virtual_finger_factor,
};
pub use law::{
    inside_friction_cone, resolve, split_normal_tangential, spring_force, tangential_friction,
    total_force,
};
pub use safeguards::{
    ForceCap, damped_spring_force, damping_coefficient, limited_relative_velocity,
    speed_limited_depth, spring_at_depth,
};
pub use slip::{kinetic_stretch, slipped_stretch, slips, static_stretch_squared};
pub use stribeck::kinetic_mu;

use glam::Vec3;

/// Static and dynamic friction coefficients between skin and a material.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FrictionCoefficients {
    /// μ_st: bounds the tangential force of a sticking contact (Eq. 3.7).
    pub static_mu: f32,
    /// μ_dyn: scales the tangential force of a slipping contact (Eq. 3.8).
    pub dynamic_mu: f32,
}

impl FrictionCoefficients {
    /// The larger of the two: no contact's friction exceeds this times its
    /// normal force.
    #[inline]
    pub fn max(&self) -> f32 {
        self.static_mu.max(self.dynamic_mu)
    }
}

/// How a slipping contact's tangential force is computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
pub enum KineticFriction {
    /// Eq. 3.8 as written in the thesis: `f_T = μ_dyn · f_t`. Its magnitude
    /// grows with the tangential spring stretch and is **not** bounded by
    /// `μ_dyn·|f_n|`, so a fast tangential hand motion can transmit more
    /// friction than Coulomb's law allows.
    Thesis,
    /// Coulomb's kinetic friction: `f_T = μ_dyn·|f_n|` along `f_t`'s
    /// direction. The default, because it is the law the thesis names and it
    /// makes the simulated slip threshold independent of how fast the hand
    /// moves (tested in `tests/physics`). It never exceeds the spring's own
    /// tangential force `|f_t|`, so a material whose measured μ_dyn is above
    /// its μ_st cannot make friction push harder than the skin is stretched.
    #[default]
    Coulomb,
}

/// Whether a contact sticks, slips, or does not press at all.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum FrictionState {
    /// Inside the friction cone: `C` stays fixed on the object.
    Static,
    /// Outside the cone: the contact slips and `C` moves along the surface.
    Dynamic,
    /// `f · n ≤ 0`: the bone does not press into the object. A contact cannot
    /// pull (no adhesion), so it transmits no force at all.
    Separated,
}

impl FrictionState {
    /// Every state, in the order of [`Self::code`]; the names bindings
    /// give them (Python's `FRICTION_STATES`).
    pub const NAMES: [&'static str; 3] = ["static", "dynamic", "separated"];

    /// The state as a number, for arrays across a binding (Python, the web
    /// page, C): its place in [`Self::NAMES`].
    pub fn code(self) -> u8 {
        match self {
            FrictionState::Static => 0,
            FrictionState::Dynamic => 1,
            FrictionState::Separated => 2,
        }
    }
}

/// The result of the contact law for one contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ResolvedForce {
    /// `f_n`, the normal part of the reaction on the bone (N).
    pub normal: Vec3,
    /// `f_T`, the tangential friction part of the reaction on the bone (N).
    pub tangential: Vec3,
    /// Which branch of Eq. 3.7/3.8 applied.
    pub state: FrictionState,
}

/// The whole per-contact law as this crate applies it, on the reaction
/// `f` (N) of a bone whose spring sees `seen_depth` (m): no force from a bone
/// short of the surface, whatever its damper says; the cone and kinetic
/// rule of [`resolve`]; and friction under the force cap, when there is one.
#[inline]
pub fn contact_law(
    f: Vec3,
    n: Vec3,
    seen_depth: f32,
    gamma: f32,
    mu: FrictionCoefficients,
    kinetic: KineticFriction,
    cap: Option<ForceCap>,
) -> ResolvedForce {
    let pressing = seen_depth > 0.0;
    let mut law = if pressing { resolve(f, n, mu, kinetic) } else { ResolvedForce::SEPARATED };
    if let Some(cap) = cap {
        law.tangential = cap.tangential(law.tangential, mu, gamma);
    }
    law
}

impl ResolvedForce {
    /// No force: a bone that does not press.
    pub const SEPARATED: ResolvedForce = ResolvedForce {
        normal: Vec3::ZERO,
        tangential: Vec3::ZERO,
        state: FrictionState::Separated,
    };

    /// The force applied to the object: the opposite of the reaction (N).
    #[inline]
    pub fn on_object(&self) -> Vec3 {
        -(self.normal + self.tangential)
    }
}
