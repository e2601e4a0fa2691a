//! The interaction methods a world can run, as the evaluation compares
//! them (thesis Ch. 5): this crate's friction hands, the thesis's law as
//! written, and the two grab baselines. A method is a config; the grab
//! baselines add the step's grab stage.

use super::config::InteractionConfig;
use crate::friction::KineticFriction;
use crate::grab::GrabMethod;

/// How hands move objects.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// Coulomb friction contacts with this crate's safeguards (default).
    #[default]
    Coulomb,
    /// The thesis's law as written (§3.5–3.7), without the safeguards.
    Thesis,
    /// \[23\]'s kinematic grasp (§3.9): [`crate::grab::kinematic`].
    Kinematic,
    /// A grab helper like Ultraleap's Physical Hands:
    /// [`crate::grab::heuristic`].
    Heuristic,
}

impl Method {
    /// Every method, in the order reports list them.
    pub const ALL: [Method; 4] =
        [Method::Coulomb, Method::Thesis, Method::Kinematic, Method::Heuristic];

    /// The method's name on the command line and in reports.
    pub fn name(self) -> &'static str {
        match self {
            Method::Coulomb => "coulomb",
            Method::Thesis => "thesis",
            Method::Kinematic => "kinematic",
            Method::Heuristic => "heuristic",
        }
    }

    /// `base` set up for this method; its step, gravity, γ and patch sizes
    /// are kept.
    ///
    /// The thesis's law as written: the kinetic rule as written, a pure spring
    /// (no damper, force cap or penetration-speed limit), one contact
    /// offset, no stability limit, the patch's samples carrying `f/N` each
    /// (no deviation springs), slipping C moved from where it is rather
    /// than re-centred under the bone, every finger patch the pad's ring (no
    /// line contacts), C pinned to the object while it sticks (no rolling),
    /// a contact that leaves the cone dropping at once to μ_dyn (no
    /// Stribeck fade),
    /// and the tracked hand acting as it is
    /// tracked, jitter and all. One difference remains: `p`
    /// is the bone's surface point, not the phalanx centroid (see
    /// `contact/mod.rs`, "Which bone point is p"): with the centroid, the
    /// law's "no pulling force" rule would leave every bone pushing only
    /// once sunk by its own radius (8–10 mm), and without that rule a bone
    /// within the offset would pull the object towards it.
    pub fn config(self, base: InteractionConfig) -> InteractionConfig {
        match self {
            Method::Coulomb => base,
            Method::Thesis => InteractionConfig {
                kinetic: KineticFriction::Thesis,
                damping_ratio: None,
                force_cap: false,
                max_penetration_speed: None,
                release_offset: base.contact_offset,
                stability_limit: false,
                step_aware: false,
                virtual_fingers: false,
                deviation_springs: false,
                slip_recentre: false,
                line_contacts: false,
                rolling: false,
                stribeck_speed: None,
                tracking: None,
                ..base
            },
            Method::Kinematic => Self::grab(base, GrabMethod::Kinematic),
            Method::Heuristic => Self::grab(base, GrabMethod::Heuristic),
        }
    }

    fn grab(base: InteractionConfig, method: GrabMethod) -> InteractionConfig {
        InteractionConfig { grab: Some(method), hand_friction: false, ..base }
    }
}

impl std::fmt::Display for Method {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// An unknown method name.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown method \"{0}\": expected one of coulomb, thesis, kinematic, heuristic")]
pub struct UnknownMethod(pub String);

impl std::str::FromStr for Method {
    type Err = UnknownMethod;

    fn from_str(s: &str) -> Result<Method, UnknownMethod> {
        Method::ALL.into_iter().find(|m| m.name() == s).ok_or_else(|| UnknownMethod(s.into()))
    }
}
