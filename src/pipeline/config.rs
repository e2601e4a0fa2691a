//! The interaction layer's settings, their validation, and the rapier
//! parameters they imply.

use crate::contact::patch::PatchConfig;
use crate::friction::{FINGERTIP_DISSIPATION, KineticFriction};
use crate::grab::GrabMethod;
use crate::hand::acting::TrackingFilter;
use crate::scene::{GammaMode, Scene};
use glam::Vec3;
use rapier3d::dynamics::{FrictionModel, IntegrationParameters};

/// The longest step (s) at which rapier makes its speculative contacts
/// [`SPECULATIVE_SPEED`] times the step ahead; longer steps keep rapier's
/// own 2 cm, made for 60 Hz.
///
/// At 1 kHz, each step moves bodies 16 times less than at 60 Hz, and a 2 cm
/// margin makes rapier's solver carry contacts between tower blocks that are
/// nowhere near touching. The solver study of the book's "Benchmarks" found
/// that a 5 mm margin keeps every scenario's checks (the tool knocking the
/// tower, both Jenga pulls, the handover), the recordings' verdicts and the
/// held boxes, with fewer of rapier's instructions on the awake reference
/// scene (the figures are in the book's table). Fewer solver iterations
/// saved more but left a box in an opened hand of the grab recording, so
/// the objects the hands push keep rapier's 4 ([`HAND_SUBSTEPS`]).
pub const HAPTIC_STEP: f32 = 0.002;
/// The approach speed (m/s) rapier's speculative contacts cover in one step
/// at the haptic rate: 5 mm at 1 ms. A faster body may sink into another
/// for a step before their contact is made.
pub const SPECULATIVE_SPEED: f32 = 5.0;
/// rapier's substeps per step for an object the hands push, and everything
/// in contact with it: rapier's default 4, whatever the step.
///
/// rapier adds a body's user force to its velocity substep by substep, so
/// over N substeps a step's constant hand force `f` moves the body by
/// `v·dt + (N+1)/(2N)·(f/m)·dt²`. The hand's springs and dampers, explicit
/// forces, were tuned and checked at N = 4 (5/8): with 1 or 2 substeps for
/// every body, a fist of the grab recording still held its box when it
/// opened. So they keep 4 whatever [`InteractionConfig::engine_substeps`].
pub const HAND_SUBSTEPS: usize = 4;
/// [`InteractionConfig::engine_substeps`]'s default: rapier's substeps per
/// step for the bodies no hand pushes. In the book's substeps study, with
/// the pushed objects at [`HAND_SUBSTEPS`], every bundled scene kept its
/// outcome at 2 and at 1. 2 takes a fifth off rapier's awake step and
/// keeps stacks no hand touches standing as 4 does; with 1, a pyramid of
/// blocks creeps apart 4 mm in 5 s (`tests/physics/stacks.rs`).
pub const ENGINE_SUBSTEPS: usize = 2;
/// The most substeps [`InteractionConfig::engine_substeps`] may ask for:
/// each costs about a solver pass over every awake contact.
const MAX_SUBSTEPS: usize = 64;

/// Settings of the interaction layer. Units: s, m, N, m/s. In files, a
/// missing field takes its default and an unknown one is an error.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct InteractionConfig {
    /// Physics time step (s); default 1 ms, the haptic rate. Contact springs
    /// are explicit forces; at a longer step (a host engine's 1/90 s), an
    /// object too light for them steps its springs by backward Euler
    /// ([`Self::step_aware`]), or is softened without it.
    pub dt: f32,
    /// Gravity (m/s²).
    pub gravity: Vec3,
    /// A contact begins when a bone's surface comes within this distance of
    /// an object (m): the thesis's Default Contact Offset.
    pub contact_offset: f32,
    /// A contact ends when the bone's surface is farther than this (m).
    /// Larger than `contact_offset`, so tracking jitter at the threshold does
    /// not flicker begin/end events.
    pub release_offset: f32,
    /// Contact stiffness γ for objects without their own (§3.5.6).
    pub gamma: GammaMode,
    /// Eq. 3.8 as written, or Coulomb's kinetic friction (default).
    pub kinetic: KineticFriction,
    /// Skin patch sampling (§3.5.4).
    pub patch: PatchConfig,
    /// Damping ratio ζ of each contact spring, or `None` for the thesis's
    /// pure spring. The damper acts on the bone-vs-object velocity at the
    /// contact with `c = 2ζ√(γ m)` (times the contact's share of its
    /// virtual finger). The default, 0.76, is the ζ at which a pad that
    /// pushes an object away from rest gives back 19 % of the energy that
    /// loaded it, as a fingertip does (81 % dissipated:
    /// [`crate::friction::grip`]).
    pub damping_ratio: Option<f32>,
    /// The contacts of one hand that press one object from the same side
    /// share one γ, as one virtual finger (default), so that a thumb
    /// balances any number of fingers and a still hand that opens lets go
    /// of its object without pushing it ([`crate::friction::grip`]). Off,
    /// each contact has the whole γ, as in the thesis.
    pub virtual_fingers: bool,
    /// Cap each contact's spring at the thesis's assumed 20 % maximum
    /// penetration of the object's bounding diameter d: its normal spring
    /// force stays ≤ `γ·0.2·d` however deep a bone is
    /// ([`crate::friction::ForceCap`]).
    pub force_cap: bool,
    /// The penetration depth a contact's spring sees may grow by at most
    /// this speed (m/s), or `None` for no limit. Real fingers press slower;
    /// a bone that teleports deep inside is a tracking glitch.
    pub max_penetration_speed: Option<f32>,
    /// How far above the surface the inverse rays of slipping contacts
    /// start (m).
    pub probe_offset: f32,
    /// Natural frequency of rapier's soft object–object and object–ground
    /// contacts (Hz). Stiffer than the step rate collapses stacks, so the
    /// world uses at most `1/dt`. rapier's 30 Hz default
    /// lets a 54-block tower sink 28 mm in 2 s; 240 Hz at a 1 ms step,
    /// 0.6 mm.
    pub contact_frequency: f32,
    /// rapier's friction between objects and with the ground: its
    /// manifold-centred model (default), whose sliding friction is
    /// Coulomb's μ·N, or one cone per contact point, which falls short of
    /// it ([`ObjectFriction`]).
    pub object_friction: ObjectFriction,
    /// rapier's substeps per step (its solver iterations) for the bodies no
    /// hand pushes. The objects the hands push, and what touches them, run
    /// at least [`HAND_SUBSTEPS`] (`pipeline::step`'s `substeps.rs`). The
    /// default, 2, takes a fifth off rapier's step on an awake tower, and
    /// every scenario, recording verdict, held box and standing tower keeps
    /// its outcome (the book's "Benchmarks"); 4 is rapier's own for every
    /// body, which a program with joints or long chains of its own may
    /// want.
    pub engine_substeps: usize,
    /// The patch's deviation springs against twisting and rocking
    /// (default); off, each sample carries `f/N`, as in the thesis.
    pub deviation_springs: bool,
    /// A slipping contact re-centres under the bone before its C moves
    /// (default); off, C moves from where it is, as in the thesis.
    pub slip_recentre: bool,
    /// A finger bone lying along a flat face touches it along a line
    /// (default): its patch is stretched along the bone (a fingertip's only
    /// to its pad's radius: its pulp touches) and holds the object upright
    /// as a small flat support does (`contact/line.rs`).
    /// Off, every finger patch is the pad's ring, as in the thesis.
    pub line_contacts: bool,
    /// A contact on a curved object follows the two surfaces as they roll
    /// on each other (default; `contact/roll.rs`), so a ball rolls down a
    /// palm with its true depth at every step, and static friction holds
    /// only the slip where they touch. Off (the thesis's), C stays pinned
    /// to the object while it sticks, and a ball rolling on the skin sinks
    /// into it and kicks (the book's "Rolling contacts").
    pub rolling: bool,
    /// Static friction fades to kinetic as skin slides faster, over this
    /// speed (m/s), as measured skin friction does
    /// ([`crate::friction::stribeck`]): skin that creeps holds with μ_st,
    /// skin that slides a few times faster than this with μ_dyn. The
    /// default, 30 mm/s, lies in the band (20–50 mm/s) in which every
    /// tested plate on a flat hand starts to slide within 0.5° of atan μ_st:
    /// far above the creep of a contact under an object that stays put,
    /// below the centimetres a second of a real slide and the tracked
    /// hand's jitter. Slower, the falling friction outweighs the pads'
    /// dampers and a nudged plate stick-slips (the book's "Static friction
    /// that fades with speed"). `None` drops a contact to μ_dyn the instant
    /// it leaves the cone, as in the thesis.
    pub stribeck_speed: Option<f32>,
    /// Each object's stability limit on γ and damping (default): see
    /// `pipeline/stability.rs`. Off, as in the thesis.
    pub stability_limit: bool,
    /// Under the stability limit, an object whose springs an explicit step
    /// could not keep stable, and any touched object at a step longer than
    /// [`HAPTIC_STEP`], keeps their full γ and damping, stepped by backward
    /// Euler (`friction/implicit.rs`, default), rather than softened: a grip
    /// then holds at a host engine's 90 Hz as at 1 kHz.
    pub step_aware: bool,
    /// A grab baseline instead of friction hands (`None`, the default):
    /// [`crate::grab`].
    pub grab: Option<GrabMethod>,
    /// Skin friction on hand contacts (default). Without it a bone pushes
    /// with the law's normal force only, as the grab baselines' hands do.
    pub hand_friction: bool,
    /// How the hand that acts follows the tracked hand: the tracker's
    /// jitter taken out ([`crate::hand::acting`], default), or `None` for
    /// the tracked hand as it is, as in the thesis.
    pub tracking: Option<TrackingFilter>,
}

/// How rapier solves friction between objects (not hand contacts, which
/// are always the thesis's model).
///
/// A sliding box must meet μ·N. With one cone per contact point, rapier
/// meets 0.90–0.94 of it, whatever the step, substeps or speed: it solves
/// each point's two tangent rows together, `Δλ = −K⁻¹·v`, and then caps
/// the impulse's length at μ·λ_n. Where the point's effective mass `K`
/// is anisotropic, as at a box's corner (its lever arm has parts along
/// both tangents), the capped impulse points along `K⁻¹·v`, not against
/// the slip `v`: Coulomb's (maximum-dissipation) friction would cap it
/// in `K`'s metric. For a cube's corner, `K ∝ [[4, −1.5], [−1.5, 4]]`,
/// and the friction along the slip is `4/√18.25 = 0.936` of μ·N, as
/// measured. The manifold-centred model puts one cone at the centre of
/// the contact points, under the centre of mass for a body resting on a
/// face, where `K` is isotropic: μ·N exactly (tests/physics/
/// object_friction.rs), and it is faster (the book's "Benchmarks").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
pub enum ObjectFriction {
    /// rapier's one cone per contact point: 6–10 % short of μ·N where a
    /// point's lever arm has parts along both tangents.
    Coulomb,
    /// rapier's one cone per manifold, at the centre of its points, plus a
    /// twist constraint (its `FrictionModel::Simplified`): μ·N.
    #[default]
    Simplified,
}

impl Default for InteractionConfig {
    fn default() -> Self {
        InteractionConfig {
            dt: 1.0 / 1000.0,
            gravity: Vec3::new(0.0, -9.81, 0.0),
            contact_offset: 0.004,
            release_offset: 0.008,
            gamma: GammaMode::default(),
            kinetic: KineticFriction::Coulomb,
            patch: PatchConfig::default(),
            damping_ratio: crate::friction::pad_damping_ratio(FINGERTIP_DISSIPATION),
            force_cap: true,
            max_penetration_speed: Some(1.0),
            probe_offset: 0.004,
            contact_frequency: 240.0,
            object_friction: ObjectFriction::Simplified,
            engine_substeps: ENGINE_SUBSTEPS,
            deviation_springs: true,
            slip_recentre: true,
            line_contacts: true,
            rolling: true,
            stribeck_speed: Some(0.03),
            stability_limit: true,
            step_aware: true,
            virtual_fingers: true,
            grab: None,
            hand_friction: true,
            tracking: Some(TrackingFilter::default()),
        }
    }
}

/// Why a configuration was rejected.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("config: {field}: {reason}")]
pub struct ConfigError {
    /// The field, as named in files.
    pub field: &'static str,
    /// What is wrong with its value.
    pub reason: String,
}

impl InteractionConfig {
    /// The thesis's law as written, as far as it runs:
    /// [`super::Method::Thesis`] on the default config.
    pub fn thesis() -> Self {
        super::Method::Thesis.config(Self::default())
    }

    /// This config with the scene's gravity, if the scene sets one.
    pub fn with_scene(self, scene: &Scene) -> Self {
        InteractionConfig { gravity: scene.gravity.unwrap_or(self.gravity), ..self }
    }

    /// Checks every field; the error names the first bad one.
    pub fn validate(&self) -> Result<(), ConfigError> {
        let err = |field, reason: String| Err(ConfigError { field, reason });
        let pos = |v: f32| v.is_finite() && v > 0.0;
        if !pos(self.dt) || self.dt > 0.1 {
            return err("dt", format!("must be in (0, 0.1] s, got {}", self.dt));
        }
        if !pos(self.contact_frequency) {
            let f = self.contact_frequency;
            return err("contact_frequency", format!("must be a positive number of Hz, got {f}"));
        }
        if !(1..=MAX_SUBSTEPS).contains(&self.engine_substeps) {
            let n = self.engine_substeps;
            return err("engine_substeps", format!("must be in 1..={MAX_SUBSTEPS}, got {n}"));
        }
        if !self.gravity.is_finite() {
            return err("gravity", format!("must be finite, got {:?}", self.gravity));
        }
        if !pos(self.contact_offset) {
            return err("contact_offset", format!("must be positive, got {}", self.contact_offset));
        }
        if !(self.release_offset.is_finite() && self.release_offset >= self.contact_offset) {
            let r = self.release_offset;
            return err("release_offset", format!("must be ≥ contact_offset, got {r}"));
        }
        if let GammaMode::Fixed(g) = self.gamma
            && !pos(g)
        {
            return err("gamma", format!("must be positive, got {g}"));
        }
        if self.patch.samples == 0 || self.patch.samples == 2 || self.patch.samples > 64 {
            // Two samples cannot be centred on C (one sits on it).
            let n = self.patch.samples;
            return err("patch.samples", format!("must be 1 or 3..=64, got {n}"));
        }
        for (field, v) in [
            ("patch.finger_radius", self.patch.finger_radius),
            ("patch.thumb_radius", self.patch.thumb_radius),
            ("patch.palm_radius", self.patch.palm_radius),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return err(field, format!("must be finite and ≥ 0, got {v}"));
            }
        }
        if let Some(z) = self.damping_ratio
            && !(z.is_finite() && z >= 0.0)
        {
            return err("damping_ratio", format!("must be finite and ≥ 0, got {z}"));
        }
        if let Some(v) = self.max_penetration_speed
            && !pos(v)
        {
            return err("max_penetration_speed", format!("must be positive, got {v}"));
        }
        if let Some(v) = self.stribeck_speed
            && !pos(v)
        {
            return err("stribeck_speed", format!("must be positive, got {v}"));
        }
        if !pos(self.probe_offset) {
            return err("probe_offset", format!("must be positive, got {}", self.probe_offset));
        }
        if let Some(Err((field, reason))) = self.tracking.map(|t| t.validate()) {
            return err(field, reason);
        }
        Ok(())
    }

    /// Sets rapier's step, friction model, contact stiffness and, at the
    /// haptic rate, its speculative margin from this config. Its substeps
    /// are set step by step (`pipeline::step`'s `substeps.rs`).
    pub(crate) fn set_rapier_parameters(&self, p: &mut IntegrationParameters) {
        p.dt = self.dt;
        if self.dt <= HAPTIC_STEP {
            p.normalized_prediction_distance = SPECULATIVE_SPEED * self.dt / p.length_unit;
        }
        p.friction_model = match self.object_friction {
            ObjectFriction::Coulomb => FrictionModel::Coulomb,
            ObjectFriction::Simplified => FrictionModel::Simplified,
        };
        let frequency = self.contact_frequency.min(1.0 / self.dt);
        p.contact_softness.natural_frequency = frequency;
        let static_frequency = p.static_contact_softness.natural_frequency;
        p.static_contact_softness.natural_frequency = static_frequency.max(frequency);
    }
}
