//! Object materials: skin-vs-material friction from published measurements.
//!
//! The hand's friction with an object comes from this table (thesis §3.5.5
//! uses experimental skin data). Object–object friction is rapier's and uses
//! [`Material::surface_friction`].

use crate::friction::FrictionCoefficients;

/// A surface material of a virtual object.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Material {
    /// A short name, e.g. `"wood"`.
    pub name: String,
    /// Skin-on-material friction used by the hand contact law.
    pub skin: FrictionCoefficients,
    /// Friction of this material against other objects, for rapier's own
    /// contacts (rapier averages the two colliders' values).
    pub surface_friction: f32,
    /// Where the skin values come from.
    pub source: String,
}

/// One row of the built-in table.
struct Row {
    name: &'static str,
    static_mu: f32,
    dynamic_mu: f32,
    surface_friction: f32,
    source: &'static str,
}

/// Skin-vs-material friction. Where a source gives only one of μ_st and
/// μ_dyn, the other is set equal to it and the source says so.
const TABLE: &[Row] = &[
    Row {
        name: "aluminium",
        static_mu: 0.38,
        dynamic_mu: 0.6,
        surface_friction: 0.4,
        source: "μ_st 0.38±0.13: two-finger pinch at slip, Buchholz, Frederick & Armstrong 1988, \
                 Ergonomics 31(3):317-325; μ_dyn 0.6: finger pad sliding, Seo et al. 2009, \
                 Ergonomics 52(5):609-616",
    },
    Row {
        name: "rubber",
        static_mu: 0.9,
        dynamic_mu: 0.9,
        surface_friction: 0.9,
        source: "0.9: finger pad sliding on rubber hoses, Seo et al. 2009, \
                 Ergonomics 52(5):609-616 (sliding only; static set equal)",
    },
    Row {
        name: "vinyl",
        static_mu: 0.53,
        dynamic_mu: 0.53,
        surface_friction: 0.4,
        source: "0.53±0.18: smooth vinyl, pinch at slip, Buchholz, Frederick & Armstrong 1988 \
                 (static only; dynamic set equal)",
    },
    Row {
        name: "paper",
        static_mu: 0.27,
        dynamic_mu: 0.27,
        surface_friction: 0.3,
        source: "0.27: dry paper, pinch at slip, Buchholz, Frederick & Armstrong 1988 \
                 (static only; dynamic set equal)",
    },
    Row {
        name: "paper-moist",
        static_mu: 0.42,
        dynamic_mu: 0.42,
        surface_friction: 0.3,
        source: "0.42±0.07: moist paper, pinch at slip, Buchholz, Frederick & Armstrong 1988 \
                 (static only; dynamic set equal)",
    },
    Row {
        name: "wood",
        static_mu: 0.46,
        dynamic_mu: 0.46,
        surface_friction: 0.5,
        source: "0.46: lowest value (raw wood) of the finger-on-wood range 0.46-4.80, Gott & Byrne \
                 2013, 'Measuring the Haptic Characteristics of Various Wood Finishes', a student \
                 research journal, vol. 3 issue 1 (weak source); dynamic set equal",
    },
    Row {
        name: "nylon",
        static_mu: 0.37,
        dynamic_mu: 0.37,
        surface_friction: 0.3,
        source: "0.37±0.09: nylon averaged over six body sites, Zhang & Mak 1999, Prosthetics and \
                 Orthotics International 23(2):135-141 (static only; dynamic set equal)",
    },
    Row {
        name: "glass",
        static_mu: 0.5,
        dynamic_mu: 0.5,
        surface_friction: 0.4,
        source: "≈0.5: typical dry skin on smooth hard surfaces, Derler & Gerhardt 2012, \
                 Tribology Letters 45:1-27 (review; one value for both)",
    },
];

impl Material {
    /// Looks a material up in the built-in table by name.
    pub fn named(name: &str) -> Option<Material> {
        TABLE.iter().find(|r| r.name == name).map(|r| Material {
            name: r.name.to_string(),
            skin: FrictionCoefficients { static_mu: r.static_mu, dynamic_mu: r.dynamic_mu },
            surface_friction: r.surface_friction,
            source: r.source.to_string(),
        })
    }

    /// The names in the built-in table.
    pub fn names() -> impl Iterator<Item = &'static str> {
        TABLE.iter().map(|r| r.name)
    }

    /// A material with explicit coefficients, e.g. for experiments.
    pub fn custom(name: &str, static_mu: f32, dynamic_mu: f32, surface_friction: f32) -> Material {
        Material {
            name: name.to_string(),
            skin: FrictionCoefficients { static_mu, dynamic_mu },
            surface_friction,
            source: "user-defined".to_string(),
        }
    }

    /// The material called `name`, or an error listing the known names.
    pub fn by_name(name: &str) -> Result<Material, String> {
        Self::named(name).ok_or_else(|| {
            let known: Vec<_> = Self::names().collect();
            format!("unknown material {name:?} (known: {})", known.join(", "))
        })
    }

    /// Wood, the default material of the demo scenes.
    pub fn wood() -> Material {
        Self::named("wood").unwrap_or_else(|| Self::custom("wood", 0.46, 0.46, 0.5))
    }

    /// The first coefficient that is not finite and ≥ 0: its field and
    /// value.
    pub(crate) fn validate(&self) -> Result<(), (&'static str, f32)> {
        [
            ("skin.static_mu", self.skin.static_mu),
            ("skin.dynamic_mu", self.skin.dynamic_mu),
            ("surface_friction", self.surface_friction),
        ]
        .into_iter()
        .find(|(_, v)| !(v.is_finite() && *v >= 0.0))
        .map_or(Ok(()), Err)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_row_is_valid_and_sourced() {
        for name in Material::names() {
            let m = Material::named(name).unwrap();
            m.validate().unwrap();
            assert!(m.skin.static_mu > 0.0 && m.skin.dynamic_mu > 0.0);
            assert!(m.source.len() > 20, "{name} needs a source");
        }
        assert_eq!(Material::named("aluminium").unwrap().skin.static_mu, 0.38);
        assert!(Material::named("unobtainium").is_none());
    }
}
