//! The world's own errors: ConfigError, PoseError, ObjectError and
//! WorldError's missing hands and objects, through InteractionWorld calls.

use crate::names;
use coulomb_hands::contact::patch::PatchConfig;
use coulomb_hands::hand::acting::TrackingFilter;
use coulomb_hands::hand::rig::HandRig;
use coulomb_hands::run::drive::{Driver, PoseFn};
use coulomb_hands::scene::{Part, mesh::TriangleMesh};
use coulomb_hands::{
    GammaMode, HandId, HandPose, HandSurface, InteractionConfig, InteractionWorld, Material,
    MeshBody, MeshShape, ObjectDesc, ObjectId, ShapeDesc, Side, StaticDesc, WorldError,
};
use glam::{Quat, Vec3};

fn config_error(change: impl FnOnce(&mut InteractionConfig)) -> String {
    let mut config = InteractionConfig::default();
    change(&mut config);
    let e = InteractionWorld::new(config).err().expect("the config is rejected");
    assert!(matches!(e, WorldError::Config(_)), "{e:?}");
    e.to_string()
}

#[test]
fn every_config_field_is_checked_by_name_with_its_value() {
    names(config_error(|c| c.dt = 0.0), &["config: dt: ", "(0, 0.1]", "got 0"]);
    names(config_error(|c| c.dt = 0.5), &["config: dt: ", "got 0.5"]);
    names(config_error(|c| c.dt = f32::NAN), &["config: dt: ", "got NaN"]);
    names(config_error(|c| c.contact_frequency = -1.0), &["contact_frequency: ", "Hz, got -1"]);
    for substeps in [0, 65] {
        let e = config_error(|c| c.engine_substeps = substeps);
        names(e, &["config: engine_substeps: ", "1..=64", &format!("got {substeps}")]);
    }
    names(config_error(|c| c.gravity.y = f32::INFINITY), &["config: gravity: ", "inf"]);
    names(config_error(|c| c.contact_offset = 0.0), &["config: contact_offset: ", "got 0"]);
    let release = config_error(|c| c.release_offset = 0.001);
    names(release, &["config: release_offset: ", "≥ contact_offset", "got 0.001"]);
    names(config_error(|c| c.gamma = GammaMode::Fixed(-400.0)), &["config: gamma: ", "got -400"]);
    for samples in [0, 2, 65] {
        let e = config_error(|c| c.patch = PatchConfig { samples, ..PatchConfig::default() });
        names(e, &["config: patch.samples: ", "1 or 3..=64", &format!("got {samples}")]);
    }
    let finger = config_error(|c| c.patch.finger_radius = -0.001);
    names(finger, &["config: patch.finger_radius: ", "got -0.001"]);
    let thumb = config_error(|c| c.patch.thumb_radius = f32::NAN);
    names(thumb, &["config: patch.thumb_radius: ", "got NaN"]);
    names(config_error(|c| c.patch.palm_radius = -1.0), &["config: patch.palm_radius: ", "-1"]);
    let damping = config_error(|c| c.damping_ratio = Some(-0.5));
    names(damping, &["config: damping_ratio: ", "got -0.5"]);
    let speed = config_error(|c| c.max_penetration_speed = Some(0.0));
    names(speed, &["config: max_penetration_speed: ", "got 0"]);
    let fade = config_error(|c| c.stribeck_speed = Some(-0.02));
    names(fade, &["config: stribeck_speed: ", "got -0.02"]);
    let endless = config_error(|c| c.stribeck_speed = Some(f32::INFINITY));
    names(endless, &["config: stribeck_speed: ", "got inf"]);
    names(config_error(|c| c.probe_offset = -0.004), &["config: probe_offset: ", "got -0.004"]);
    let filter = |change: fn(&mut TrackingFilter)| {
        config_error(move |c| {
            let mut f = TrackingFilter::default();
            change(&mut f);
            c.tracking = Some(f);
        })
    };
    let beta = filter(|f| f.shape.beta = -0.002);
    names(beta, &["config: tracking.shape.beta: ", "finite and ≥ 0", "got -0.002"]);
    let cutoff = filter(|f| f.gross.min_cutoff = f32::INFINITY);
    names(cutoff, &["config: tracking.gross.min_cutoff: ", "Hz, got inf"]);
    let derivative = filter(|f| f.shape.derivative_cutoff = 0.0);
    names(derivative, &["config: tracking.shape.derivative_cutoff: ", "got 0"]);
    let least = filter(|f| f.shape.least_cutoff = -0.5);
    names(least, &["config: tracking.shape.least_cutoff: ", "finite and ≥ 0", "got -0.5"]);
    let white = filter(|f| f.gross.white_cutoff = f32::NEG_INFINITY);
    names(white, &["config: tracking.gross.white_cutoff: ", "finite and ≥ 0", "got -inf"]);
    let window = filter(|f| f.jitter_window = f32::NAN);
    names(window, &["config: tracking.jitter_window: ", "got NaN"]);
    names(filter(|f| f.jitter_window = 90.0), &["tracking.jitter_window: ", "(0, 60] s, got 90"]);
}

fn pose() -> HandPose {
    HandRig::adult(Side::Right).pose(Vec3::new(0.0, 0.3, 0.0), Quat::IDENTITY, [0.0; 5])
}

/// The error of posing hand 1 (of two) with a changed pose; the world
/// keeps no pose for it.
fn pose_error(change: impl FnOnce(&mut HandPose)) -> String {
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    world.add_hand(Side::Left);
    let hand = world.add_hand(Side::Right);
    let mut bad = pose();
    change(&mut bad);
    let e = world.set_hand_pose(hand, &bad).unwrap_err();
    assert!(matches!(e, WorldError::Pose(_)), "{e:?}");
    assert!(world.hand_pose(hand).is_none(), "a rejected pose leaves the world untouched");
    e.to_string()
}

#[test]
fn every_pose_error_names_the_hand_the_bone_and_the_field() {
    let e = pose_error(|p| p.palm.center.x = f32::NAN);
    names(e, &["hand 1: bone palm: center is not finite"]);
    let e = pose_error(|p| p.palm.center.y = 2.0e4);
    names(e, &["hand 1: bone palm: center is 20000 m from the origin", "limit 10000 m"]);
    let e = pose_error(|p| p.palm.half_extents.z = f32::INFINITY);
    names(e, &["hand 1: bone palm: half_extents is not finite"]);
    let e = pose_error(|p| p.palm.half_extents.y = 0.0);
    names(e, &["hand 1: bone palm: half extents", "must all be positive"]);
    let e = pose_error(|p| p.palm.rotation = Quat::from_xyzw(f32::NAN, 0.0, 0.0, 1.0));
    names(e, &["hand 1: bone palm: rotation is not finite"]);
    let e = pose_error(|p| p.palm.rotation = Quat::from_xyzw(0.0, 0.0, 0.0, 2.0));
    names(e, &["hand 1: bone palm: rotation", "is not a unit quaternion"]);
    let e = pose_error(|p| p.fingers[1][0].a.z = f32::NEG_INFINITY);
    names(e, &["hand 1: bone index-proximal: a is not finite"]);
    let e = pose_error(|p| p.fingers[4][2].b.x = -5.0e4);
    names(e, &["hand 1: bone pinky-distal: b is 50000 m from the origin"]);
    let e = pose_error(|p| p.fingers[0][1].radius = f32::NAN);
    names(e, &["hand 1: bone thumb-intermediate: radius is not finite"]);
    let e = pose_error(|p| p.fingers[2][1].radius = -0.008);
    names(e, &["hand 1: bone middle-intermediate: radius -0.008 m must be positive"]);
    let e = pose_error(|p| p.fingers[3][0].b = p.fingers[3][0].a);
    names(e, &["hand 1: bone ring-proximal: zero-length bone (joints coincide at"]);
}

fn world() -> InteractionWorld {
    InteractionWorld::new(InteractionConfig::default()).unwrap()
}

fn cube() -> ObjectDesc {
    ObjectDesc::cuboid("crate", Vec3::splat(0.05), 0.1, Vec3::new(0.0, 0.1, 0.0))
}

/// The error of adding a changed cube named "crate"; nothing is added.
fn object_error(change: impl FnOnce(&mut ObjectDesc)) -> String {
    let mut world = world();
    let mut desc = cube();
    change(&mut desc);
    let e = world.add_object(&desc).unwrap_err();
    assert!(matches!(e, WorldError::Object(_)), "{e:?}");
    assert_eq!(world.object_count(), 0, "nothing is added");
    e.to_string()
}

fn shape(s: ShapeDesc) -> impl FnOnce(&mut ObjectDesc) {
    move |d| d.shape = s
}

#[test]
fn object_errors_name_the_object_the_field_and_the_value() {
    names(object_error(|d| d.mass = 0.0), &["object 'crate': mass: ", "got 0"]);
    names(object_error(|d| d.mass = f32::NAN), &["object 'crate': mass: ", "got NaN"]);
    let e = object_error(|d| d.position.y = 1.0e5);
    names(e, &["object 'crate': position: ", "within ±10000 m", "100000"]);
    let e = object_error(|d| d.rotation = Quat::from_xyzw(0.0, 0.0, 0.0, 0.5));
    names(e, &["object 'crate': rotation: must be a unit quaternion"]);
    let e = object_error(|d| d.material.skin.static_mu = -0.1);
    names(e, &["object 'crate': material.skin.static_mu: ", "got -0.1"]);
    let e = object_error(|d| d.material.skin.dynamic_mu = f32::NAN);
    names(e, &["object 'crate': material.skin.dynamic_mu: ", "got NaN"]);
    let e = object_error(|d| d.material.surface_friction = f32::INFINITY);
    names(e, &["object 'crate': material.surface_friction: ", "got inf"]);
    let e = object_error(|d| d.gamma = Some(GammaMode::Fixed(0.0)));
    names(e, &["object 'crate': gamma: ", "got 0"]);
    let e = object_error(|d| {
        d.material = Material::custom("ice", 0.0, 0.0, 0.1);
        d.gamma = Some(GammaMode::Auto);
    });
    names(e, &["object 'crate': gamma: ", "automatic γ is inf"]);
}

#[test]
fn an_object_s_own_inertia_must_be_a_real_body_s() {
    // The 5 cm, 100 g crate: its corners 4.3 cm from its centre, so no
    // moment can exceed 0.1 · 0.0433² = 1.875e-4 kg·m².
    let e = object_error(|d| d.inertia = Some(Vec3::new(4.0e-5, f32::NAN, 4.0e-5)));
    names(e, &["object 'crate': inertia: ", "positive finite", "NaN"]);
    let e = object_error(|d| d.inertia = Some(Vec3::new(4.0e-5, 0.0, 4.0e-5)));
    names(e, &["object 'crate': inertia: ", "positive finite"]);
    let e = object_error(|d| d.inertia = Some(Vec3::new(1.0e-5, 1.0e-5, 3.0e-5)));
    names(e, &["object 'crate': inertia: ", "exceeds the other two together"]);
    let e = object_error(|d| d.inertia = Some(Vec3::splat(2.0e-4)));
    names(e, &["object 'crate': inertia: ", "at most m·r² = 0.0001875"]);
    // A crate with its mass in its walls: more than a solid one's 4.2e-5.
    let mut world = world();
    let id = world.add_object(&cube().with_inertia(Vec3::splat(6.0e-5))).unwrap();
    let body = world.object_body(id).unwrap();
    let own = world.physics().bodies[body].mass_properties().local_mprops.principal_inertia();
    assert!((own - Vec3::splat(6.0e-5)).abs().max_element() < 1.0e-9, "{own}");
}

#[test]
fn the_automatic_gamma_needs_gravity() {
    let config = InteractionConfig { gravity: Vec3::ZERO, ..InteractionConfig::default() };
    let mut world = InteractionWorld::new(config).unwrap();
    let e = world.add_object(&cube().with_gamma(GammaMode::Auto)).unwrap_err();
    names(e, &["object 'crate': gamma: automatic γ is 0", "needs gravity"]);
}

#[test]
fn shape_errors_name_the_shape_field() {
    let boxed = |h: Vec3| ShapeDesc::Box { half_extents: h };
    let e = object_error(shape(boxed(Vec3::new(0.02, f32::NAN, 0.02))));
    names(e, &["object 'crate': shape.half_extents: must be finite"]);
    let e = object_error(shape(boxed(Vec3::new(0.02, 0.02, 0.0))));
    names(e, &["object 'crate': shape.half_extents.z: ", "got 0"]);
    let e = object_error(shape(ShapeDesc::Sphere { radius: -0.02 }));
    names(e, &["object 'crate': shape.radius: ", "got -0.02"]);
    let e = object_error(shape(ShapeDesc::Capsule { half_height: 0.0, radius: 0.01 }));
    names(e, &["object 'crate': shape.half_height: ", "got 0"]);
    let e = object_error(shape(ShapeDesc::Capsule { half_height: 0.02, radius: f32::NAN }));
    names(e, &["object 'crate': shape.radius: ", "got NaN"]);
    let e = object_error(shape(ShapeDesc::Cylinder { half_height: -1.0, radius: 0.01 }));
    names(e, &["object 'crate': shape.half_height: ", "got -1"]);
    let e = object_error(shape(ShapeDesc::Cylinder { half_height: 0.02, radius: 0.0 }));
    names(e, &["object 'crate': shape.radius: ", "got 0"]);
}

#[test]
fn compound_errors_name_the_part() {
    let part =
        |position: Vec3, rotation: Quat, shape: ShapeDesc| Part { position, rotation, shape };
    let ball = ShapeDesc::Sphere { radius: 0.01 };
    let ok = part(Vec3::ZERO, Quat::IDENTITY, ball.clone());
    let e = object_error(shape(ShapeDesc::Compound(vec![])));
    names(e, &["object 'crate': shape: a compound needs at least one part"]);
    let nested = part(Vec3::ZERO, Quat::IDENTITY, ShapeDesc::Compound(vec![ok.clone()]));
    let e = object_error(shape(ShapeDesc::Compound(vec![ok.clone(), nested])));
    names(e, &["object 'crate': shape.parts[1]: ", "not compounds or meshes"]);
    let far = part(Vec3::new(0.0, f32::NAN, 0.0), Quat::IDENTITY, ball.clone());
    let e = object_error(shape(ShapeDesc::Compound(vec![far])));
    names(e, &["object 'crate': shape.parts[0].position: must be finite"]);
    let turned = part(Vec3::ZERO, Quat::from_xyzw(1.0, 1.0, 0.0, 0.0), ball);
    let e = object_error(shape(ShapeDesc::Compound(vec![ok.clone(), turned])));
    names(e, &["object 'crate': shape.parts[1].rotation: must be a unit quaternion"]);
    let flat = part(Vec3::ZERO, Quat::IDENTITY, ShapeDesc::Sphere { radius: 0.0 });
    let e = object_error(shape(ShapeDesc::Compound(vec![ok, flat])));
    names(e, &["object 'crate': shape.parts[1].shape.radius: ", "got 0"]);
}

/// A unit tetrahedron (m).
pub fn tetrahedron() -> TriangleMesh {
    TriangleMesh {
        vertices: vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z],
        triangles: vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
    }
}

fn mesh(mesh: TriangleMesh, scale: f32, body: MeshBody) -> ShapeDesc {
    ShapeDesc::Mesh(MeshShape::new("tet.obj", scale, body, mesh))
}

#[test]
fn mesh_shape_errors_name_the_mesh_field() {
    let voxels = MeshBody::Voxels { size: 0.1 };
    let e = object_error(shape(mesh(tetrahedron(), 0.0, voxels)));
    names(e, &["object 'crate': shape.Mesh.scale: ", "got 0"]);
    let e = object_error(shape(mesh(TriangleMesh::default(), 1.0, voxels)));
    names(e, &["object 'crate': shape.Mesh.file: 'tet.obj' is not loaded"]);
    let mut nan = tetrahedron();
    nan.vertices[2].y = f32::NAN;
    let e = object_error(shape(mesh(nan, 1.0, voxels)));
    names(e, &["object 'crate': shape.Mesh.file: vertex 2 is not finite"]);
    let mut beyond = tetrahedron();
    beyond.triangles[3] = [1, 2, 4];
    let e = object_error(shape(mesh(beyond, 1.0, voxels)));
    names(e, &["shape.Mesh.file: triangle 3 refers to a vertex beyond the 4 there are"]);
    let e = object_error(shape(mesh(tetrahedron(), 1.0, MeshBody::Voxels { size: -0.1 })));
    names(e, &["object 'crate': shape.Mesh.body.Voxels.size: ", "got -0.1"]);
    let e = object_error(shape(mesh(tetrahedron(), 1.0, MeshBody::Voxels { size: 1.0e-6 })));
    names(e, &["shape.Mesh.body.Voxels.size: voxel size 0.000001 m", "too small"]);
    let e = object_error(shape(mesh(tetrahedron(), 1.0, MeshBody::Voxels { size: 5.0 })));
    names(e, &["shape.Mesh.body.Voxels.size: voxel size 5 m", "too large"]);
    let convex = MeshBody::ConvexParts { concavity: 1.5 };
    let e = object_error(shape(mesh(tetrahedron(), 1.0, convex)));
    names(e, &["object 'crate': shape.Mesh.body.ConvexParts.concavity: ", "got 1.5"]);
    let e = object_error(shape(mesh(tetrahedron(), 1.0, MeshBody::TriMesh)));
    names(e, &["object 'crate': shape.Mesh.body: ", "can only be static scenery"]);
}

/// A box from the origin to `size` (m), faces outward.
pub fn cuboid(size: Vec3) -> TriangleMesh {
    let corner = |i: u32| Vec3::new((i & 1) as f32, (i >> 1 & 1) as f32, (i >> 2 & 1) as f32);
    let quads =
        [[0, 4, 6, 2], [1, 3, 7, 5], [0, 1, 5, 4], [2, 6, 7, 3], [0, 2, 3, 1], [4, 5, 7, 6]];
    TriangleMesh {
        vertices: (0..8).map(|i| corner(i) * size).collect(),
        triangles: quads.iter().flat_map(|[a, b, c, d]| [[*a, *b, *c], [*a, *c, *d]]).collect(),
    }
}

#[test]
fn too_many_voxels_is_an_error_naming_the_count() {
    let e = tetrahedron().voxel_boxes(0.05, 10).unwrap_err();
    names(e, &["voxel size 0.05 m gives ", "boxes, more than 10: use larger voxels"]);
    // In a world the limit is MAX_VOXEL_BOXES (4096) rows along x: a slab
    // 1 cm thin in x, 50 cm square, in 5 mm voxels has 10 000.
    let slab = cuboid(Vec3::new(0.01, 0.5, 0.5));
    let e = object_error(shape(mesh(slab, 1.0, MeshBody::Voxels { size: 0.005 })));
    names(e, &["object 'crate': shape.Mesh.body.Voxels.size: ", "more than 4096"]);
}

/// `mesh` made into convex parts and touched on its exact surface.
fn touched_exactly(mesh: TriangleMesh) -> ShapeDesc {
    let body = MeshBody::ConvexParts { concavity: 0.01 };
    ShapeDesc::Mesh(MeshShape {
        hand_surface: HandSurface::Exact,
        ..MeshShape::new("box.obj", 1.0, body, mesh)
    })
}

#[test]
fn an_exact_surface_must_close_a_volume_wound_outwards() {
    // A hand touches the exact triangles by telling inside from outside:
    // a hole, a flipped triangle or inward winding leaves no inside.
    let closed = cuboid(Vec3::new(0.04, 0.03, 0.02));
    let mut world = world();
    world.add_object(&ObjectDesc { shape: touched_exactly(closed.clone()), ..cube() }).unwrap();
    let mut holed = closed.clone();
    holed.triangles.pop();
    let e = object_error(shape(touched_exactly(holed)));
    names(
        e,
        &["object 'crate': shape.Mesh.hand_surface: Exact: the mesh is not closed: 3 of its edges"],
    );
    let mut flipped = closed.clone();
    flipped.triangles[4].swap(1, 2);
    let e = object_error(shape(touched_exactly(flipped)));
    names(e, &["shape.Mesh.hand_surface: Exact: the mesh is not closed: ", "a flipped triangle"]);
    let mut inward = closed.clone();
    inward.triangles.iter_mut().for_each(|t| t.swap(1, 2));
    let e = object_error(shape(touched_exactly(inward)));
    names(e, &["shape.Mesh.hand_surface: Exact: the mesh's triangles wind inwards", "flip them"]);
    // An STL's triangles share no vertices; corners at the same place are
    // one, so it closes.
    let stl = TriangleMesh {
        vertices: closed
            .triangles
            .iter()
            .flat_map(|t| t.map(|k| closed.vertices[k as usize]))
            .collect(),
        triangles: (0..closed.triangles.len() as u32)
            .map(|i| [3 * i, 3 * i + 1, 3 * i + 2])
            .collect(),
    };
    assert_eq!(stl.open_edges(), 0);
    world.add_object(&ObjectDesc { shape: touched_exactly(stl), ..cube() }).unwrap();
}

/// The error of adding a changed table as static scenery.
fn static_error(change: impl FnOnce(&mut StaticDesc)) -> String {
    let mut world = world();
    let mut table = StaticDesc::ground(0.0, 0.5);
    table.name = "table".into();
    change(&mut table);
    let e = world.add_static(&table).unwrap_err();
    assert!(matches!(e, WorldError::Object(_)), "{e:?}");
    e.to_string()
}

#[test]
fn static_errors_name_the_scenery_and_the_field() {
    let e = static_error(|s| s.position.x = f32::INFINITY);
    names(e, &["object 'table': position: must be finite"]);
    let e = static_error(|s| s.rotation = Quat::from_xyzw(0.0, 0.0, 0.0, 0.0));
    names(e, &["object 'table': rotation: must be a unit quaternion"]);
    names(static_error(|s| s.friction = -0.5), &["object 'table': friction: ", "got -0.5"]);
    let e = static_error(|s| s.shape = ShapeDesc::Sphere { radius: 0.0 });
    names(e, &["object 'table': shape.radius: ", "got 0"]);
    let e = static_error(|s| s.shape = mesh(TriangleMesh::default(), 1.0, MeshBody::TriMesh));
    names(e, &["object 'table': shape.Mesh.file: 'tet.obj' is not loaded"]);
}

#[test]
fn calls_on_missing_hands_and_objects_name_the_id() {
    let mut world = world();
    let ghost = HandId(3);
    let e = world.set_hand_pose(ghost, &pose()).unwrap_err();
    assert_eq!(e, WorldError::NoSuchHand(ghost));
    names(e, &["hand 3 does not exist"]);
    names(world.clear_hand_pose(ghost).unwrap_err(), &["hand 3 does not exist"]);
    let missing = ObjectId(7);
    names(world.set_object_locked(missing, true).unwrap_err(), &["object 7 does not exist"]);
    names(world.reseat_contacts(missing).unwrap_err(), &["object 7 does not exist"]);
    let e = world.object_state(missing).unwrap_err();
    assert_eq!(e, WorldError::NoSuchObject(missing));
    names(e, &["object 7 does not exist"]);
    let mut driver = Driver::new(&mut world);
    let e = driver.drive(ghost, PoseFn::new(Side::Right, |_| Some(pose()))).unwrap_err();
    names(e, &["hand 3 does not exist"]);
}

#[test]
fn a_hosts_state_is_checked_whole_before_any_of_it_is_written() {
    use coulomb_hands::{HandWrench, HostBody, Method};
    let mut world = world();
    let id = world.add_object(&cube()).unwrap();
    let body = &world.physics().bodies[world.object_body(id).unwrap()];
    let good = HostBody::of_rapier(body);
    let before = world.object_state(id).unwrap();
    type Break = fn(&mut HostBody);
    let cases: [(&str, Break); 7] = [
        ("position: ", |s| s.position.x = f32::NAN),
        ("linvel: ", |s| s.linvel.y = f32::INFINITY),
        ("rotation: must be a unit quaternion", |s| {
            s.rotation = Quat::from_xyzw(0.0, 0.0, 0.0, 2.0)
        }),
        ("mass: ", |s| s.mass = -0.2),
        ("principal_inertia.y: ", |s| s.principal_inertia.y = 0.0),
        ("center_of_mass: ", |s| s.center_of_mass.z = f32::NAN),
        ("inertia_rotation: ", |s| s.inertia_rotation = Quat::from_xyzw(0.0, 0.0, 0.0, 0.0)),
    ];
    for (field, break_it) in cases {
        let mut bad = HostBody { position: Vec3::new(0.3, 0.4, 0.5), ..good };
        break_it(&mut bad);
        let e = world.set_host_body(id, &bad).unwrap_err();
        names(e, &["object 'crate': ", field]);
        assert_eq!(world.object_state(id).unwrap(), before, "{field}: nothing written");
    }
    let missing = ObjectId(4);
    names(world.set_host_body(missing, &good).unwrap_err(), &["object 4 does not exist"]);
    let wrench =
        |force| HandWrench { object: id, force, torque: Vec3::ZERO, touched: true, pushed: true };
    let e = world.integrate_wrenches(&[wrench(Vec3::new(0.0, f32::NAN, 0.0))]).unwrap_err();
    names(e, &["object 'crate': force: "]);
    assert_eq!(world.time(), 0.0, "no step was taken");
    // A force has no bound in metres: 25 N is a force like any other.
    world.integrate_wrenches(&[wrench(Vec3::new(0.0, 25.0, 0.0))]).unwrap();
    assert!(world.time() > 0.0, "the step was taken");
    // A grab baseline carries objects itself, which a host's cannot be.
    let mut grab =
        InteractionWorld::new(Method::Kinematic.config(InteractionConfig::default())).unwrap();
    let e = grab.host_step().unwrap_err();
    names(e, &["Kinematic grab baseline moves objects itself", "coulomb, thesis"]);
    assert_eq!(grab.time(), 0.0);
}

#[test]
fn a_scene_the_world_refuses_in_part_adds_none_of_it() {
    use coulomb_hands::scene::{Ground, Scene};
    // Without gravity, an automatic γ (Eq. 3.11, from the weight) is zero,
    // which the world refuses: the second object here, after a ground, a
    // table and a fixed-γ box that it would take.
    let config = InteractionConfig { gravity: Vec3::ZERO, ..InteractionConfig::default() };
    let mut world = InteractionWorld::new(config).unwrap();
    let fixed = ObjectDesc {
        gamma: Some(GammaMode::Fixed(350.0)),
        ..ObjectDesc::cuboid("crate", Vec3::splat(0.06), 0.2, Vec3::new(0.0, 0.03, 0.0))
    };
    let auto = ObjectDesc {
        gamma: Some(GammaMode::Auto),
        ..ObjectDesc::cuboid("tin", Vec3::splat(0.04), 0.1, Vec3::new(0.2, 0.02, 0.0))
    };
    let table = StaticDesc::ground(0.7, 0.4);
    let scene = Scene {
        ground: Some(Ground { height: 0.0, friction: 0.5 }),
        gravity: None,
        statics: vec![table],
        objects: vec![fixed, auto],
        towers: Vec::new(),
    };
    let err = world.add_scene(&scene).unwrap_err().to_string();
    assert!(err.contains("tin") && err.contains("gamma"), "{err}");
    assert_eq!(world.object_count(), 0, "no object was added");
    assert_eq!(world.physics().colliders.len(), 0, "no ground or table was added");
}
