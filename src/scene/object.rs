//! Descriptions of the virtual objects hands can touch, and of static scenery.

pub use super::gamma::{GammaError, GammaMode};
use super::material::Material;
use glam::{Quat, Vec3};
use rapier3d::geometry::SharedShape;
use rapier3d::math::Pose;

/// Handle of an interactive object in an [`crate::InteractionWorld`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
pub struct ObjectId(pub u32);

impl std::fmt::Display for ObjectId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "object {}", self.0)
    }
}

/// A collision shape, in the object's local frame (metres).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub enum ShapeDesc {
    /// A box with the given half extents.
    Box {
        /// Half extents along local x, y and z (m).
        half_extents: Vec3,
    },
    /// A sphere about the local origin.
    Sphere {
        /// Radius (m).
        radius: f32,
    },
    /// A capsule along local y.
    Capsule {
        /// Half the length of the axis segment, without the caps (m).
        half_height: f32,
        /// Radius (m).
        radius: f32,
    },
    /// A cylinder along local y.
    Cylinder {
        /// Half the height (m).
        half_height: f32,
        /// Radius (m).
        radius: f32,
    },
    /// Several convex parts rigidly joined, e.g. an axe's handle and head.
    Compound(Vec<Part>),
    /// A triangle mesh from a file (§3.7), made into a body as `body` says.
    Mesh(MeshShape),
}

/// A mesh shape: the file, its scale, and how it becomes a collider.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeshShape {
    /// The OBJ, STL, glTF or GLB file, relative to the scene file.
    pub file: String,
    /// Multiplies the file's coordinates (e.g. 0.001 for millimetres).
    #[serde(default = "unit_scale")]
    pub scale: f32,
    /// How the mesh becomes a collider.
    pub body: MeshBody,
    /// What of it the hand touches: the body (the default) or the exact
    /// triangles.
    #[serde(default)]
    pub hand_surface: HandSurface,
    /// The file's triangles, filled in when a scene is loaded (and kept in
    /// session files, so a replay needs no mesh files).
    #[serde(default)]
    pub mesh: super::mesh::TriangleMesh,
}

fn unit_scale() -> f32 {
    1.0
}

/// How a mesh becomes a collider.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub enum MeshBody {
    /// Boxes of side `size` (m) filling the solid, as the thesis voxelizes
    /// concave objects; smaller voxels follow the shape more closely and
    /// cost more contacts queries.
    Voxels {
        /// Side of each voxel box (m).
        size: f32,
    },
    /// Convex parts by V-HACD; `concavity` (0..1, e.g. 0.01) is the
    /// largest deviation each part may have from the mesh.
    ConvexParts {
        /// V-HACD's concavity limit, in (0, 1].
        concavity: f32,
    },
    /// The exact triangles: only for static scenery, since a triangle mesh
    /// has no inside to give a dynamic body its mass.
    TriMesh,
}

/// What a hand's contacts query on a mesh object. The engine collides a
/// dynamic object as convex pieces (`body`), but a hand's contacts need
/// only closest points and ray casts, which parry answers exactly on the
/// triangles. Pieces overfill a concave mesh: V-HACD's parts of a dish
/// fill its rim's curl by up to 9 mm, where a fitted finger then presses
/// deep and pushes. So a replay of a real hand on a real object touches
/// the real surface.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum HandSurface {
    /// The body the engine moves, as the thesis's hand touched its
    /// colliders.
    #[default]
    Body,
    /// The file's own triangles ([`super::mesh::TriangleMesh::solid`]):
    /// the mesh must be closed and wound outwards. A `TriMesh` body is this
    /// already.
    Exact,
}

impl std::str::FromStr for HandSurface {
    type Err = String;
    fn from_str(s: &str) -> Result<HandSurface, String> {
        match s {
            "body" | "Body" => Ok(HandSurface::Body),
            "exact" | "Exact" => Ok(HandSurface::Exact),
            _ => Err(format!("expected \"body\" or \"exact\", got {s:?}")),
        }
    }
}

impl std::fmt::Display for HandSurface {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            HandSurface::Body => "body",
            HandSurface::Exact => "exact",
        })
    }
}

impl MeshBody {
    /// The body a mesh gets where none is asked for (the Python package's
    /// `add_mesh`, a mesh dropped on the web page): 5 mm voxels, the
    /// thesis's way, fine enough for a hand-sized object's hollows (the
    /// fingers are 12-23 mm thick).
    pub const DEFAULT: MeshBody = MeshBody::Voxels { size: 0.005 };
}

/// At most this many boxes make a voxelized mesh.
pub const MAX_VOXEL_BOXES: usize = 4096;

impl MeshShape {
    /// A mesh made into `body`, touched as its body is
    /// ([`HandSurface::Body`]).
    pub fn new(
        file: impl Into<String>,
        scale: f32,
        body: MeshBody,
        mesh: super::mesh::TriangleMesh,
    ) -> Self {
        MeshShape { file: file.into(), scale, body, hand_surface: HandSurface::Body, mesh }
    }

    /// The shape a hand's contacts query instead of the body's, if it
    /// touches the exact triangles of a body made of pieces.
    fn hand_shape(&self, object: &str, field: &str) -> Result<Option<SharedShape>, ObjectError> {
        if self.hand_surface == HandSurface::Body || self.body == MeshBody::TriMesh {
            return Ok(None);
        }
        let solid = self.mesh.scaled(self.scale).solid().map_err(|e| {
            ObjectError::new(object, format!("{field}.Mesh.hand_surface"), format!("Exact: {e}"))
        })?;
        Ok(Some(SharedShape::new(solid)))
    }

    fn build(&self, object: &str, field: &str) -> Result<SharedShape, ObjectError> {
        let f = |sub: &str| format!("{field}.Mesh.{sub}");
        positive(object, &f("scale"), self.scale)?;
        self.mesh.check().map_err(|e| {
            let why = if self.mesh.triangles.is_empty() {
                format!("'{}' is not loaded (load the scene with Scene::load)", self.file)
            } else {
                e.to_string()
            };
            ObjectError::new(object, f("file"), why)
        })?;
        let mesh = self.mesh.scaled(self.scale);
        // Scaling can overflow to infinity or shrink the mesh to nothing.
        let (lo, hi) = mesh.bounds();
        let extent = lo.abs().max(hi.abs()).max_element();
        if !(extent <= crate::hand::MAX_COORDINATE && mesh.check().is_ok()) {
            let why = format!(
                "{} scales the mesh to {extent} m from its origin: it must stay within {} m and \
                 keep a volume",
                self.scale,
                crate::hand::MAX_COORDINATE
            );
            return Err(ObjectError::new(object, f("scale"), why));
        }
        Ok(match self.body {
            MeshBody::Voxels { size } => {
                positive(object, &f("body.Voxels.size"), size)?;
                let boxes = mesh
                    .voxel_boxes(size, MAX_VOXEL_BOXES)
                    .map_err(|e| ObjectError::new(object, f("body.Voxels.size"), e.to_string()))?;
                SharedShape::compound(
                    boxes
                        .into_iter()
                        .map(|(c, h)| {
                            (Pose::from_translation(c), SharedShape::cuboid(h.x, h.y, h.z))
                        })
                        .collect(),
                )
            }
            MeshBody::ConvexParts { concavity } => {
                if !(concavity.is_finite() && concavity > 0.0 && concavity <= 1.0) {
                    return Err(ObjectError::new(
                        object,
                        f("body.ConvexParts.concavity"),
                        format!("must be in (0, 1], got {concavity}"),
                    ));
                }
                let params = rapier3d::parry::transformation::vhacd::VHACDParameters {
                    concavity,
                    ..Default::default()
                };
                convex_parts(&mesh, &params).ok_or_else(|| {
                    let why = "V-HACD found no convex part (the mesh is too small or degenerate)";
                    ObjectError::new(object, f("body.ConvexParts"), why)
                })?
            }
            MeshBody::TriMesh => {
                SharedShape::trimesh(mesh.vertices, mesh.triangles).map_err(|e| {
                    ObjectError::new(object, f("file"), format!("not a usable triangle mesh: {e}"))
                })?
            }
        })
    }
}

/// The mesh's convex parts by V-HACD, as
/// `SharedShape::convex_decomposition_with_params` makes them, or `None`
/// when there are none (parry would panic on the empty compound).
fn convex_parts(
    mesh: &super::mesh::TriangleMesh,
    params: &rapier3d::parry::transformation::vhacd::VHACDParameters,
) -> Option<SharedShape> {
    use rapier3d::parry::transformation::vhacd::VHACD;
    let decomposition = VHACD::decompose(params, &mesh.vertices, &mesh.triangles, true);
    let parts: Vec<(Pose, SharedShape)> = decomposition
        .compute_exact_convex_hulls(&mesh.vertices, &mesh.triangles)
        .into_iter()
        .filter_map(|(vertices, indices)| SharedShape::convex_mesh(vertices, &indices))
        .map(|part| (Pose::IDENTITY, part))
        .collect();
    (!parts.is_empty()).then(|| SharedShape::compound(parts))
}

/// One part of a compound shape.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Part {
    /// The part's position in the object's local frame (m).
    pub position: Vec3,
    /// The part's orientation in the object's local frame (unit quaternion).
    pub rotation: Quat,
    /// The part's shape, a primitive in its own frame.
    pub shape: ShapeDesc,
}

/// Everything needed to add a dynamic object.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ObjectDesc {
    /// A name for messages and outputs.
    pub name: String,
    /// Collision shape, in the object's local frame.
    pub shape: ShapeDesc,
    /// Mass in kg.
    pub mass: f32,
    /// Surface material: friction against skin and other objects.
    pub material: Material,
    /// World position of the body origin (m).
    pub position: Vec3,
    /// World orientation (unit quaternion).
    pub rotation: Quat,
    /// Overrides the world's γ mode for this object.
    pub gamma: Option<GammaMode>,
    /// Its principal moments of inertia about its centre of mass, along
    /// its own axes (kg·m²), where its mass is not spread evenly through
    /// its shape: a hollow ball's `2/3·m·r²` each, say. `None`: the
    /// shape's own at this mass, of uniform density.
    #[serde(default)]
    pub inertia: Option<Vec3>,
}

impl ObjectDesc {
    /// A wooden box of the given full size (m) and mass (kg).
    pub fn cuboid(name: &str, size: Vec3, mass: f32, position: Vec3) -> ObjectDesc {
        ObjectDesc {
            name: name.to_string(),
            shape: ShapeDesc::Box { half_extents: size * 0.5 },
            mass,
            material: Material::wood(),
            position,
            rotation: Quat::IDENTITY,
            gamma: None,
            inertia: None,
        }
    }

    /// A wooden ball of the given radius (m) and mass (kg), centred at
    /// `position`.
    pub fn sphere(name: &str, radius: f32, mass: f32, position: Vec3) -> ObjectDesc {
        ObjectDesc {
            shape: ShapeDesc::Sphere { radius },
            ..ObjectDesc::cuboid(name, Vec3::splat(2.0 * radius), mass, position)
        }
    }

    /// A wooden object of a mesh's shape (`mesh`, its body and what the
    /// hand touches) and the given mass (kg), at `position`, unturned.
    pub fn mesh(name: &str, mesh: MeshShape, mass: f32, position: Vec3) -> ObjectDesc {
        ObjectDesc {
            shape: ShapeDesc::Mesh(mesh),
            ..ObjectDesc::cuboid(name, Vec3::ONE, mass, position)
        }
    }

    /// The same object with another material.
    pub fn with_material(mut self, material: Material) -> ObjectDesc {
        self.material = material;
        self
    }

    /// The same object with its own principal moments of inertia
    /// (kg·m², [`Self::inertia`]).
    pub fn with_inertia(mut self, inertia: Vec3) -> ObjectDesc {
        self.inertia = Some(inertia);
        self
    }

    /// The same object with its own γ mode.
    pub fn with_gamma(mut self, gamma: GammaMode) -> ObjectDesc {
        self.gamma = Some(gamma);
        self
    }
}

/// Why an object or scenery description was rejected.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("object '{object}': {field}: {reason}")]
pub struct ObjectError {
    /// The object's or scenery's name.
    pub object: String,
    /// The field, e.g. `mass` or `shape.radius`.
    pub field: String,
    /// What is wrong with it.
    pub reason: String,
}

impl ObjectError {
    pub(crate) fn new(object: &str, field: impl Into<String>, reason: impl Into<String>) -> Self {
        ObjectError { object: object.to_string(), field: field.into(), reason: reason.into() }
    }
}

pub(crate) fn positive(object: &str, field: &str, v: f32) -> Result<(), ObjectError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(ObjectError::new(object, field, format!("must be a positive finite number, got {v}")))
    }
}

/// A length (m): positive, finite and at most [`crate::hand::MAX_COORDINATE`];
/// larger shapes only make the contact queries fail (parry's EPA panics on a
/// 1e20 m capsule).
fn size(object: &str, field: &str, v: f32) -> Result<(), ObjectError> {
    if v.is_finite() && v > 0.0 && v <= crate::hand::MAX_COORDINATE {
        Ok(())
    } else {
        let max = crate::hand::MAX_COORDINATE;
        Err(ObjectError::new(
            object,
            field,
            format!("must be positive and at most {max} m, got {v}"),
        ))
    }
}

pub(crate) fn finite_vec(object: &str, field: &str, v: Vec3) -> Result<(), ObjectError> {
    if v.is_finite() && v.abs().max_element() <= crate::hand::MAX_COORDINATE {
        Ok(())
    } else {
        Err(ObjectError::new(
            object,
            field,
            format!("must be finite and within ±{} m, got {v:?}", crate::hand::MAX_COORDINATE),
        ))
    }
}

pub(crate) fn unit_quat(object: &str, field: &str, q: Quat) -> Result<(), ObjectError> {
    if q.is_finite() && (q.length() - 1.0).abs() <= 1.0e-3 {
        Ok(())
    } else {
        Err(ObjectError::new(object, field, format!("must be a unit quaternion, got {q:?}")))
    }
}

impl ShapeDesc {
    /// Checks sizes and builds rapier's shape.
    pub(crate) fn build(&self, object: &str, field: &str) -> Result<SharedShape, ObjectError> {
        Ok(match self {
            ShapeDesc::Box { half_extents: h } => {
                finite_vec(object, &format!("{field}.half_extents"), *h)?;
                for (axis, v) in ["x", "y", "z"].iter().zip(h.to_array()) {
                    positive(object, &format!("{field}.half_extents.{axis}"), v)?;
                }
                SharedShape::cuboid(h.x, h.y, h.z)
            }
            ShapeDesc::Sphere { radius } => {
                size(object, &format!("{field}.radius"), *radius)?;
                SharedShape::ball(*radius)
            }
            ShapeDesc::Capsule { half_height, radius } => {
                size(object, &format!("{field}.half_height"), *half_height)?;
                size(object, &format!("{field}.radius"), *radius)?;
                SharedShape::capsule_y(*half_height, *radius)
            }
            ShapeDesc::Cylinder { half_height, radius } => {
                size(object, &format!("{field}.half_height"), *half_height)?;
                size(object, &format!("{field}.radius"), *radius)?;
                SharedShape::cylinder(*half_height, *radius)
            }
            ShapeDesc::Compound(parts) => {
                if parts.is_empty() {
                    return Err(ObjectError::new(
                        object,
                        field,
                        "a compound needs at least one part",
                    ));
                }
                let mut built = Vec::with_capacity(parts.len());
                for (i, part) in parts.iter().enumerate() {
                    let f = format!("{field}.parts[{i}]");
                    if matches!(part.shape, ShapeDesc::Compound(_) | ShapeDesc::Mesh(_)) {
                        return Err(ObjectError::new(
                            object,
                            &f,
                            "a compound's parts are primitives, not compounds or meshes",
                        ));
                    }
                    finite_vec(object, &format!("{f}.position"), part.position)?;
                    unit_quat(object, &format!("{f}.rotation"), part.rotation)?;
                    let shape = part.shape.build(object, &format!("{f}.shape"))?;
                    built.push((Pose::from_parts(part.position, part.rotation), shape));
                }
                SharedShape::compound(built)
            }
            ShapeDesc::Mesh(mesh) => mesh.build(object, field)?,
        })
    }
}

impl ObjectDesc {
    /// The shape its hand contacts query, if not its collider's: a mesh's
    /// exact triangles ([`HandSurface::Exact`]).
    pub(crate) fn hand_shape(&self) -> Result<Option<SharedShape>, ObjectError> {
        match &self.shape {
            ShapeDesc::Mesh(mesh) => mesh.hand_shape(&self.name, "shape"),
            _ => Ok(None),
        }
    }

    pub(crate) fn validate(&self) -> Result<SharedShape, ObjectError> {
        let name = self.name.as_str();
        positive(name, "mass", self.mass)?;
        finite_vec(name, "position", self.position)?;
        unit_quat(name, "rotation", self.rotation)?;
        if let Err((field, v)) = self.material.validate() {
            let why = format!("must be finite and ≥ 0, got {v}");
            return Err(ObjectError::new(name, format!("material.{field}"), why));
        }
        if let Some(GammaMode::Fixed(g)) = self.gamma {
            positive(name, "gamma", g)?;
        }
        if let ShapeDesc::Mesh(MeshShape { body: MeshBody::TriMesh, .. }) = self.shape {
            return Err(ObjectError::new(
                name,
                "shape.Mesh.body",
                "a triangle mesh has no inside, so it can only be static scenery: use \
                 Voxels or ConvexParts",
            ));
        }
        self.shape.build(name, "shape")
    }
}

/// Static scenery: collides with objects through rapier, never with hands.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StaticDesc {
    /// A name for messages and outputs.
    pub name: String,
    /// Collision shape, in the scenery's local frame.
    pub shape: ShapeDesc,
    /// World position of the body origin (m).
    pub position: Vec3,
    /// World orientation (unit quaternion).
    pub rotation: Quat,
    /// Object–object friction coefficient for rapier.
    pub friction: f32,
}

impl StaticDesc {
    /// A large flat ground slab whose top face is at height `y` (m).
    pub fn ground(y: f32, friction: f32) -> StaticDesc {
        StaticDesc {
            name: "ground".to_string(),
            shape: ShapeDesc::Box { half_extents: Vec3::new(5.0, 0.5, 5.0) },
            position: Vec3::new(0.0, y - 0.5, 0.0),
            rotation: Quat::IDENTITY,
            friction,
        }
    }

    pub(crate) fn validate(&self) -> Result<SharedShape, ObjectError> {
        let name = self.name.as_str();
        finite_vec(name, "position", self.position)?;
        unit_quat(name, "rotation", self.rotation)?;
        if !(self.friction.is_finite() && self.friction >= 0.0) {
            return Err(ObjectError::new(
                name,
                "friction",
                format!("must be finite and ≥ 0, got {}", self.friction),
            ));
        }
        self.shape.build(name, "shape")
    }
}

/// Checks an object's own principal moments of inertia `i` (kg·m²) against
/// its `mass` (kg) and its bounding radius `reach` (m), the farthest any
/// of its mass can be from its centre: each moment finite and positive,
/// none more than the other two together (every real body's, since
/// `I_x + I_y − I_z = 2∫z²dm ≥ 0`), and none above `m·reach²`.
pub(crate) fn check_inertia(
    object: &str,
    i: Vec3,
    mass: f32,
    reach: f32,
) -> Result<(), ObjectError> {
    if !(i.is_finite() && i.min_element() > 0.0) {
        let why = format!("each principal moment must be a positive finite number, got {i:?}");
        return Err(ObjectError::new(object, "inertia", why));
    }
    if (0..3).any(|k| i[k] > i[(k + 1) % 3] + i[(k + 2) % 3]) {
        let why =
            format!("no body has these moments: one exceeds the other two together, got {i:?}");
        return Err(ObjectError::new(object, "inertia", why));
    }
    let most = mass * reach * reach;
    if i.max_element() > most {
        let why = format!(
            "at most m·r² = {most} kg·m², all its mass at its shape's farthest reach, got {i:?}"
        );
        return Err(ObjectError::new(object, "inertia", why));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sphere_is_a_ball_of_its_radius() {
        let ball = ObjectDesc::sphere("ball", 0.03, 0.05, Vec3::Y);
        assert_eq!(ball.shape, ShapeDesc::Sphere { radius: 0.03 });
        assert_eq!((ball.mass, ball.position, ball.name.as_str()), (0.05, Vec3::Y, "ball"));
    }
}
