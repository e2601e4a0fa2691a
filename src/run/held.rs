//! The object a run puts where a hand closes ([`GraspObject`], placed by
//! [`ObjectPlace`]), and whether a hand holds an object ([`is_squeezed`],
//! [`is_gripped`]): what a replay's fixtures and a closing's verdict share.

use super::grasp::GraspSite;
use crate::hand::MAX_COORDINATE;
use crate::pipeline::InteractionWorld;
use crate::scene::{ObjectDesc, ObjectId};
use glam::Vec3;

/// An object to put where the recorded hand grasps: `SHAPE:SIZE_M:MASS_KG`
/// with SHAPE `box` (SIZE the side) or `sphere` (SIZE the diameter).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GraspObject {
    /// A sphere, else a box.
    pub sphere: bool,
    /// Side or diameter (m).
    pub size: f32,
    /// Mass (kg).
    pub mass: f32,
}

impl GraspObject {
    /// The object a recording's closings get unless one is asked for: a
    /// 4 cm, 50 g wooden box, a small thing a hand pinches or grasps. The
    /// command line, the viewer and the web page take it from here.
    pub const DEFAULT: &'static str = "box:0.04:0.05";

    /// This object named `name`, sitting in the grasp at `site`
    /// ([`GraspSite::rotation`]).
    pub fn at(self, site: &GraspSite, name: &str) -> ObjectDesc {
        ObjectDesc { rotation: site.rotation, ..self.desc(name, site.point) }
    }

    /// The object, named `name`, centred at `at` (m), unturned: wood, as
    /// [`ObjectDesc::cuboid`] makes it.
    pub fn desc(&self, name: &str, at: Vec3) -> ObjectDesc {
        if self.sphere {
            ObjectDesc::sphere(name, 0.5 * self.size, self.mass, at)
        } else {
            ObjectDesc::cuboid(name, Vec3::splat(self.size), self.mass, at)
        }
    }
}

/// Why a `SHAPE:SIZE_M:MASS_KG` text is not a [`GraspObject`].
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GraspObjectError {
    /// Not three `:`-separated parts.
    #[error("expected SHAPE:SIZE_M:MASS_KG, e.g. box:0.045:0.05, got \"{0}\"")]
    Form(String),
    /// The shape is neither `box` nor `sphere`.
    #[error("unknown shape \"{0}\" (box or sphere)")]
    Shape(String),
    /// A size or mass that is not a positive number.
    #[error("{part} must be a positive number, got \"{text}\"")]
    Number {
        /// `SIZE_M` or `MASS_KG`.
        part: &'static str,
        /// What was given.
        text: String,
    },
}

impl std::str::FromStr for GraspObject {
    type Err = GraspObjectError;
    fn from_str(s: &str) -> Result<Self, GraspObjectError> {
        let parts: Vec<&str> = s.split(':').collect();
        let [shape, size, mass] = parts.as_slice() else {
            return Err(GraspObjectError::Form(s.to_string()));
        };
        let sphere = match *shape {
            "box" => false,
            "sphere" => true,
            other => return Err(GraspObjectError::Shape(other.to_string())),
        };
        let number = |part: &'static str, v: &str| {
            v.parse::<f32>()
                .ok()
                .filter(|x| x.is_finite() && *x > 0.0)
                .ok_or_else(|| GraspObjectError::Number { part, text: v.to_string() })
        };
        Ok(GraspObject { sphere, size: number("SIZE_M", size)?, mass: number("MASS_KG", mass)? })
    }
}

/// Where a run puts its [`GraspObject`]: `grasp`, at every closing of a
/// hand (held until the hand grips it, [`super::replay::replay_closings`]), or `x,y,z`, once
/// with its centre there (m). The CLI's `--object-at`, for `replay`, `live`
/// and the viewer alike.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ObjectPlace {
    /// At every closing of a hand.
    Grasp,
    /// Once, centred here (world, m).
    At(Vec3),
}

/// Why a text is not an [`ObjectPlace`].
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("expected \"grasp\" or x,y,z in metres, e.g. 0,0.02,0.1, got \"{0}\"")]
pub struct ObjectPlaceError(pub String);

impl std::str::FromStr for ObjectPlace {
    type Err = ObjectPlaceError;
    fn from_str(s: &str) -> Result<Self, ObjectPlaceError> {
        if s == "grasp" {
            return Ok(ObjectPlace::Grasp);
        }
        let numbers: Vec<f32> = (s.split(',').map(|v| v.trim().parse::<f32>()))
            .collect::<Result<_, _>>()
            .map_err(|_| ObjectPlaceError(s.to_string()))?;
        match numbers.as_slice() {
            [x, y, z] if numbers.iter().all(|v| v.is_finite() && v.abs() <= MAX_COORDINATE) => {
                Ok(ObjectPlace::At(Vec3::new(*x, *y, *z)))
            }
            _ => Err(ObjectPlaceError(s.to_string())),
        }
    }
}

/// Whether the hand contacts on an object could hold it up, without
/// flinging it: it is squeezed ([`is_squeezed`]), the static friction,
/// μ_st·Σ f_n, exceeds the object's weight, and the hand force plus
/// gravity would accelerate it by less than g.
pub fn is_gripped(world: &InteractionWorld, id: ObjectId) -> bool {
    let (Some(mass), Some(material), Ok(state)) =
        (world.object_mass(id), world.object_material(id), world.object_state(id))
    else {
        return false;
    };
    let normal: f32 = world.contacts_on(id).iter().map(|c| c.normal_force.max(0.0)).sum();
    let opposed = is_squeezed(world, id);
    let gravity = world.config().gravity;
    let weight = mass * gravity.length();
    let net = state.hand_force + mass * gravity;
    opposed && normal * material.skin.static_mu > weight && net.length() < weight
}

/// Whether hands squeeze the object: some two of its contacts press on it
/// from roughly opposite sides (normals more than 120° apart). Friction
/// can only hold an object up against gravity from more than one side
/// (an object resting on an open palm is not squeezed).
pub fn is_squeezed(world: &InteractionWorld, id: ObjectId) -> bool {
    let pressing: Vec<_> = world.contacts_on(id).iter().filter(|c| c.normal_force > 0.0).collect();
    pressing
        .iter()
        .enumerate()
        .any(|(i, a)| pressing[i + 1..].iter().any(|b| a.normal.dot(b.normal) < -0.5))
}
