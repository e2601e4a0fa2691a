//! Scene files: static scenery and objects for `replay --scene`, as JSON.
//!
//! ```json
//! {
//!   "statics": [{"name": "table", "shape": {"Box": {"half_extents": [0.4, 0.02, 0.3]}},
//!                "position": [0.0, 0.1, 0.0], "rotation": [0.0, 0.0, 0.0, 1.0], "friction": 0.5}],
//!   "objects": [{"name": "cube", "shape": {"Box": {"half_extents": [0.025, 0.025, 0.025]}},
//!                "mass": 0.05,
//!                "material": {"name": "wood", "skin": {"static_mu": 0.46, "dynamic_mu": 0.46},
//!                             "surface_friction": 0.5, "source": "table"},
//!                "position": [0.0, 0.2, 0.0], "rotation": [0.0, 0.0, 0.0, 1.0], "gamma": null}]
//! }
//! ```
//!
//! A mesh shape loads a file (OBJ, STL, glTF, GLB) relative to the scene file:
//! `{"Mesh": {"file": "../assets/meshes/pawn.obj", "scale": 1.0,
//! "body": {"Voxels": {"size": 0.004}}}}`, with body `{"ConvexParts": {"concavity": 0.01}}`
//! or, for statics only, `"TriMesh"`; `"hand_surface": "Exact"` has hands touch a closed
//! mesh's own triangles while the engine moves the body.
//!
//! Optional: `"ground": {"height": 0.0, "friction": 0.5}`, `"gravity": [0.0, -9.81, 0.0]`
//! and `"towers": [{"base": [x, y, z]}]` (54 blocks each, see
//! [`super::Tower`]).
//!
//! Shapes are `{"Box": {"half_extents": [x, y, z]}}`, `{"Sphere": {"radius": r}}`,
//! `{"Capsule": {"half_height": h, "radius": r}}`, `{"Cylinder": {"half_height": h, "radius": r}}`
//! or `{"Compound": [{"position": [..], "rotation": [..], "shape": {..}}, ..]}`, in metres.
//! A material may also be given by name alone: `"material": "wood"` (see
//! [`crate::Material::names`]). Unknown fields are errors.

use super::material::Material;
use super::object::{GammaMode, ObjectDesc, ShapeDesc, StaticDesc};
use super::tower::Tower;
use crate::files::{FileSystem, Files};
use glam::{Quat, Vec3};
use std::path::Path;

/// A material by table name, or in full.
#[derive(Debug, Clone, serde::Deserialize)]
#[serde(untagged)]
enum MaterialRef {
    Named(String),
    Full(Material),
}

#[derive(Debug, Clone, serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct ObjectEntry {
    name: String,
    shape: ShapeDesc,
    mass: f32,
    material: MaterialRef,
    position: Vec3,
    #[serde(default = "identity")]
    rotation: Quat,
    #[serde(default)]
    gamma: Option<GammaMode>,
    #[serde(default)]
    inertia: Option<Vec3>,
}

fn identity() -> Quat {
    Quat::IDENTITY
}

/// A flat ground whose top face is at `height` (m).
#[derive(Debug, Clone, Copy, PartialEq, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Ground {
    /// Height of its top face (m).
    pub height: f32,
    /// Object–ground friction coefficient.
    pub friction: f32,
}

#[derive(Debug, Clone, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct SceneEntry {
    #[serde(default)]
    ground: Option<Ground>,
    #[serde(default)]
    gravity: Option<Vec3>,
    #[serde(default)]
    statics: Vec<StaticDesc>,
    #[serde(default)]
    objects: Vec<ObjectEntry>,
    #[serde(default)]
    towers: Vec<Tower>,
}

/// A loaded scene; the default is an empty one (no ground, the world's
/// gravity).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Scene {
    /// A flat ground, if any.
    pub ground: Option<Ground>,
    /// Overrides the world's gravity (m/s²).
    pub gravity: Option<Vec3>,
    /// Static scenery.
    pub statics: Vec<StaticDesc>,
    /// Objects hands can touch.
    pub objects: Vec<ObjectDesc>,
    /// Towers of blocks named `block{level}-{slot}`, added after `objects`.
    pub towers: Vec<Tower>,
}

/// Why a scene file was rejected; names the file and where.
pub type SceneError = crate::file_error::FileError;

impl Scene {
    /// Reads and checks a scene file: JSON syntax, known fields, material
    /// names, and every object's and static's values, before anything is
    /// simulated.
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        let text = SceneError::read(path)?;
        Self::parse_in(&path.display().to_string(), &text, path.parent().unwrap_or(Path::new(".")))
    }

    /// Parses scene text; mesh files are looked up from the working directory.
    pub fn parse(file: &str, text: &str) -> Result<Scene, SceneError> {
        Self::parse_in(file, text, Path::new("."))
    }

    /// Parses scene text whose mesh file paths are relative to `dir`.
    pub fn parse_in(file: &str, text: &str, dir: &Path) -> Result<Scene, SceneError> {
        Self::parse_with(file, text, dir, &FileSystem)
    }

    /// [`Self::parse_in`], the mesh files read from `files` ([`crate::files`]).
    pub fn parse_with(
        file: &str,
        text: &str,
        dir: &Path,
        files: &dyn Files,
    ) -> Result<Scene, SceneError> {
        Self::from_entry(file, SceneError::json(file, text)?, dir, files)
    }

    /// Checks a parsed scene and loads its mesh files (`file` names it in
    /// errors; mesh paths are relative to `dir`, read from `files`).
    pub(crate) fn from_entry(
        file: &str,
        mut entry: SceneEntry,
        dir: &Path,
        files: &dyn Files,
    ) -> Result<Scene, SceneError> {
        let fail = |reason: String| SceneError::new(file, reason);
        let shapes = entry.objects.iter_mut().map(|o| (o.name.clone(), &mut o.shape));
        let static_shapes = entry.statics.iter_mut().map(|s| (s.name.clone(), &mut s.shape));
        for (name, shape) in shapes.chain(static_shapes) {
            if let ShapeDesc::Mesh(m) = shape
                && m.mesh.triangles.is_empty()
            {
                m.mesh = super::mesh::TriangleMesh::load_from(&dir.join(&m.file), files)
                    .map_err(|e| fail(format!("object '{name}': shape.Mesh.file: {e}")))?;
            }
        }
        let objects = entry
            .objects
            .into_iter()
            .map(|o| {
                let material = match o.material {
                    MaterialRef::Full(m) => m,
                    MaterialRef::Named(n) => Material::named(&n).ok_or_else(|| {
                        fail(format!(
                            "object '{}': material: unknown name '{n}' (known: {})",
                            o.name,
                            Material::names().collect::<Vec<_>>().join(", ")
                        ))
                    })?,
                };
                Ok(ObjectDesc {
                    name: o.name,
                    shape: o.shape,
                    mass: o.mass,
                    material,
                    position: o.position,
                    rotation: o.rotation,
                    gamma: o.gamma,
                    inertia: o.inertia,
                })
            })
            .collect::<Result<Vec<_>, SceneError>>()?;
        let scene = Scene {
            ground: entry.ground,
            gravity: entry.gravity,
            statics: entry.statics,
            objects,
            towers: entry.towers,
        };
        let limit = crate::hand::MAX_COORDINATE;
        if let Some(g) = scene.ground {
            if !(g.height.is_finite() && g.height.abs() <= limit) {
                let why = format!("must be finite and within ±{limit} m, got {}", g.height);
                return Err(fail(format!("ground.height: {why}")));
            }
            if !(g.friction.is_finite() && g.friction >= 0.0) {
                let why = format!("must be finite and ≥ 0, got {}", g.friction);
                return Err(fail(format!("ground.friction: {why}")));
            }
        }
        if let Some(g) = scene.gravity.filter(|g| !g.is_finite()) {
            return Err(fail(format!("gravity: must be finite, got {g:?}")));
        }
        for (i, t) in scene.towers.iter().enumerate() {
            if !(t.base.is_finite() && t.base.abs().max_element() <= limit) {
                let why = format!("must be finite and within ±{limit} m, got {:?}", t.base);
                return Err(fail(format!("towers[{i}].base: {why}")));
            }
        }
        for o in &scene.objects {
            o.validate().map_err(|e| fail(e.to_string()))?;
        }
        for s in &scene.statics {
            s.validate().map_err(|e| fail(e.to_string()))?;
        }
        Ok(scene)
    }

    /// The names of every object the scene adds, towers' blocks included.
    pub fn object_names(&self) -> Vec<String> {
        let mut names: Vec<String> = self.objects.iter().map(|o| o.name.clone()).collect();
        for _ in &self.towers {
            names.extend(Tower::block_names());
        }
        names
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_a_scene_with_a_named_material() {
        let scene = Scene::parse(
            "s.json",
            r#"{"objects": [{"name": "cube", "shape": {"Box": {"half_extents": [0.02, 0.02, 0.02]}},
                 "mass": 0.05, "material": "rubber", "position": [0.0, 0.2, 0.0]}]}"#,
        )
        .unwrap();
        assert_eq!(scene.objects[0].material.skin.static_mu, 0.9);
        assert_eq!(scene.objects[0].rotation, Quat::IDENTITY);
        assert_eq!(scene.objects[0].inertia, None, "uniform density unless given");
    }

    #[test]
    fn reads_an_object_s_own_inertia() {
        let scene = Scene::parse(
            "s.json",
            r#"{"objects": [{"name": "shell", "shape": {"Sphere": {"radius": 0.03}},
                 "mass": 0.06, "material": "rubber", "position": [0.0, 0.2, 0.0],
                 "inertia": [3.6e-5, 3.6e-5, 3.6e-5]}]}"#,
        )
        .unwrap();
        assert_eq!(scene.objects[0].inertia, Some(Vec3::splat(3.6e-5)));
    }

    #[test]
    fn errors_name_the_file_and_the_problem() {
        let unknown =
            Scene::parse("s.json", r#"{"objects": [], "lights": []}"#).unwrap_err().to_string();
        assert!(unknown.starts_with("s.json: line 1") && unknown.contains("lights"), "{unknown}");
        let bad_mass = Scene::parse(
            "s.json",
            r#"{"objects": [{"name": "cube", "shape": {"Sphere": {"radius": 0.02}}, "mass": -1,
                 "material": "wood", "position": [0.0, 0.2, 0.0]}]}"#,
        )
        .unwrap_err()
        .to_string();
        assert!(
            bad_mass.contains("s.json") && bad_mass.contains("'cube'") && bad_mass.contains("mass"),
            "{bad_mass}"
        );
        let material = Scene::parse(
            "s.json",
            r#"{"objects": [{"name": "cube", "shape": {"Sphere": {"radius": 0.02}}, "mass": 1,
                 "material": "cheese", "position": [0.0, 0.2, 0.0]}]}"#,
        )
        .unwrap_err()
        .to_string();
        assert!(material.contains("unknown name 'cheese'"), "{material}");
    }

    #[test]
    fn mesh_files_may_come_as_bytes() {
        let text = r#"{"objects": [{"name": "pawn", "mass": 0.03, "material": "wood",
            "position": [0, 0, 0], "shape": {"Mesh": {"file": "../assets/meshes/pawn.obj",
            "body": {"Voxels": {"size": 0.003}}}}}]}"#;
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
        let on_disk = Scene::parse_in("s.json", text, &dir).unwrap();
        let pawn = std::fs::read(dir.join("../assets/meshes/pawn.obj")).unwrap();
        let files = std::collections::BTreeMap::from([("../assets/meshes/pawn.obj".into(), pawn)]);
        assert_eq!(Scene::parse_with("s.json", text, Path::new(""), &files).unwrap(), on_disk);
        let none = crate::files::NoFiles;
        let e = Scene::parse_with("s.json", text, Path::new(""), &none).unwrap_err().to_string();
        let why = "../assets/meshes/pawn.obj: not among the files given";
        assert_eq!(e, format!("s.json: object 'pawn': shape.Mesh.file: {why}"));
    }

    #[test]
    fn mesh_files_load_relative_to_the_scene_and_bad_ones_name_the_object() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
        let scene = |file: &str, body: &str| {
            Scene::parse_in(
                "s.json",
                &format!(
                    concat!(
                        r#"{{"objects": [{{"name": "pawn", "mass": 0.03, "material": "wood", "#,
                        r#""position": [0, 0, 0],
                        "shape": {{"Mesh": {{"file": "{file}", "body": {body}}}}}}}]}}"#
                    ),
                    file = file,
                    body = body
                ),
                &dir,
            )
        };
        let ok = scene("../assets/meshes/pawn.obj", r#"{"Voxels": {"size": 0.003}}"#).unwrap();
        let ShapeDesc::Mesh(m) = &ok.objects[0].shape else { panic!() };
        assert!(m.mesh.triangles.len() > 100);
        let missing = scene("../assets/meshes/rook.obj", r#"{"Voxels": {"size": 0.003}}"#)
            .unwrap_err()
            .to_string();
        assert!(
            missing.starts_with("s.json: object 'pawn': shape.Mesh.file: ")
                && missing.contains("rook.obj"),
            "{missing}"
        );
        let tiny = scene("../assets/meshes/pawn.obj", r#"{"Voxels": {"size": 0.00001}}"#)
            .unwrap_err()
            .to_string();
        assert!(tiny.contains("'pawn'") && tiny.contains("Voxels.size"), "{tiny}");
        let unknown =
            scene("../assets/meshes/pawn.obj", r#"{"Voxels": {"size": 0.003, "fill": 1}}"#)
                .unwrap_err()
                .to_string();
        assert!(unknown.contains("line") && unknown.contains("fill"), "{unknown}");
    }
}
