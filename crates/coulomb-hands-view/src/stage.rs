//! The scene's look: lights, the static scenery, and a mesh for every
//! object the plugin spawns, each drawn from the object's own colliders.

use crate::sets::ViewerSystems;
use crate::shapes;
use bevy::prelude::*;
use coulomb_hands::pipeline::InteractionWorld;
use coulomb_hands_bevy::convert;
use coulomb_hands_bevy::prelude::*;
use rapier3d::geometry::Collider;

/// Object colours, in the order objects were added: cool hues, so the
/// skin-toned hand and the red force arrows stand out against them.
const PALETTE: [Color; 5] = [
    Color::srgb(0.16, 0.62, 0.68),
    Color::srgb(0.30, 0.42, 0.86),
    Color::srgb(0.33, 0.66, 0.30),
    Color::srgb(0.58, 0.38, 0.78),
    Color::srgb(0.20, 0.78, 0.74),
];
/// The scenery's colour: a blue-grey table.
const SCENERY: Color = Color::srgb(0.34, 0.37, 0.42);
/// The background.
pub const BACKGROUND: Color = Color::srgb(0.09, 0.10, 0.13);

/// A mesh of the static scenery (which AR mode turns into a mask).
#[derive(Component, Debug, Clone, Copy)]
pub struct SceneryMesh;

/// The static scenery drawn, for the world it belongs to, and the grids
/// on its boxes' top faces.
#[derive(Resource, Debug, Default)]
pub struct Scenery(Vec<Entity>, Vec<Grid>);

/// The lines drawn on a box's top face, so that a floor or a table reads
/// as a surface and not as the background: the shaded face alone is one
/// flat colour from edge to edge of the window.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Grid {
    /// Its centre and orientation: the face's plane is the grid's x–y.
    place: Isometry3d,
    /// Cells along its x and y.
    cells: UVec2,
}

/// A grid's cell (m): a hand's width, half a palm's length.
const CELL: f32 = 0.05;
/// The most a grid reaches from the run's centre (m): a desk, not a
/// 10 m ground to the horizon.
const GRID_REACH: f32 = 0.6;
/// The grid's lines: lighter than the scenery, faint.
const GRID: Color = Color::srgba(0.75, 0.80, 0.88, 0.35);

/// The light: a sun from above one shoulder, with shadows, and a soft fill.
pub fn setup_lights(mut commands: Commands) {
    commands.insert_resource(ClearColor(BACKGROUND));
    commands.insert_resource(GlobalAmbientLight { brightness: 400.0, ..default() });
    commands.spawn((
        DirectionalLight { illuminance: 6000.0, shadow_maps_enabled: true, ..default() },
        Transform::from_xyz(0.6, 1.5, -0.8).looking_at(Vec3::ZERO, Vec3::Y),
    ));
}

/// Gives each new object entity its meshes, as children.
pub fn dress_objects(
    physics: Option<Res<HandPhysics>>,
    objects: Query<(Entity, &InteractionObject), Added<InteractionObject>>,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
    mut commands: Commands,
) {
    let Some(physics) = physics else { return };
    let world = physics.world();
    for (entity, object) in &objects {
        let color = PALETTE[object.0.0 as usize % PALETTE.len()];
        let material = materials.add(StandardMaterial { base_color: color, ..default() });
        // The object's entity (the plugin's, with a transform only) joins
        // the visibility hierarchy its meshes hang from.
        commands.entity(entity).insert(Visibility::default());
        let Some(body) = world.object_body(object.0) else { continue };
        let colliders = world.physics().bodies.get(body).map(|b| b.colliders().to_vec());
        for handle in colliders.unwrap_or_default() {
            let Some(collider) = world.physics().colliders.get(handle) else { continue };
            let place = collider
                .position_wrt_parent()
                .map_or(Transform::IDENTITY, |p| convert::transform(p.translation, p.rotation));
            for (part, mesh) in shapes::meshes(collider.shape()) {
                let child = (Mesh3d(meshes.add(mesh)), MeshMaterial3d(material.clone()));
                commands.spawn((child, place * part, ChildOf(entity)));
            }
        }
    }
}

/// Draws the static scenery of a new world (the ground, a table).
pub fn dress_scenery(
    physics: Option<Res<HandPhysics>>,
    framing: Option<Res<crate::camera::Framing>>,
    mut replaced: MessageReader<HandPhysicsReplaced>,
    mut scenery: ResMut<Scenery>,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
    mut commands: Commands,
) {
    let (Some(physics), Some(_)) = (physics, replaced.read().last()) else { return };
    scenery.0.drain(..).for_each(|e| commands.entity(e).despawn());
    let material = materials.add(StandardMaterial {
        base_color: SCENERY,
        perceptual_roughness: 0.9,
        ..default()
    });
    for (place, mesh) in static_meshes(physics.world()) {
        let entity =
            (Mesh3d(meshes.add(mesh)), MeshMaterial3d(material.clone()), place, SceneryMesh);
        scenery.0.push(commands.spawn(entity).id());
    }
    let around = framing.map_or(Vec3::ZERO, |f| f.center);
    scenery.1 = top_faces(physics.world()).filter_map(|face| grid(face, around)).collect();
}

/// The grids' gizmos: hidden behind what stands on the floor, where the
/// default group's (the arrows) are drawn over everything.
#[derive(Default, Reflect, GizmoConfigGroup)]
pub struct GridGizmos;

/// Draws the grids on the scenery's top faces (AR turns them off: there
/// the scenery is the real one's mask).
pub fn draw_grids(scenery: Res<Scenery>, mut gizmos: Gizmos<GridGizmos>) {
    for g in &scenery.1 {
        gizmos.grid(g.place, g.cells, Vec2::splat(CELL), GRID).outer_edges();
    }
}

/// A box's top face: its centre, its rotation (local y up), and its half
/// extents along its own x and z (world, m).
struct TopFace {
    center: Vec3,
    rotation: Quat,
    half: Vec2,
}

/// The faces of the static boxes that face up (within 10°).
fn top_faces(world: &InteractionWorld) -> impl Iterator<Item = TopFace> + '_ {
    static_colliders(world).filter_map(|c| {
        let cuboid = c.shape().as_cuboid()?;
        let h = convert::to_bevy_vec3(cuboid.half_extents);
        let rotation = convert::to_bevy_quat(c.position().rotation);
        // The box's axis nearest world up, and the face on its upper side.
        let axes = [Vec3::X, Vec3::Y, Vec3::Z].map(|a| rotation * a);
        let (i, up) =
            (0..3).map(|i| (i, axes[i])).max_by(|a, b| a.1.y.abs().total_cmp(&b.1.y.abs()))?;
        let up = up * up.y.signum();
        if up.y < 10f32.to_radians().cos() {
            return None;
        }
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let center = convert::to_bevy_vec3(c.position().translation) + up * h[i];
        let frame = Quat::from_mat3(&Mat3::from_cols(axes[j], up, up.cross(axes[j])));
        Some(TopFace { center, rotation: frame, half: Vec2::new(h[j], h[k]) })
    })
}

/// A face's grid: whole cells, within the face and within [`GRID_REACH`]
/// of `around` (projected on the face); `None` for a face too small for
/// one cell.
fn grid(face: TopFace, around: Vec3) -> Option<Grid> {
    let local = face.rotation.inverse() * (around - face.center);
    let (lo, hi) = (-face.half, face.half);
    let want = Vec2::new(local.x, local.z);
    let min = (want - GRID_REACH).max(lo);
    let max = (want + GRID_REACH).min(hi);
    let cells = ((max - min) / CELL).floor();
    if cells.min_element() < 1.0 {
        return None;
    }
    let mid = (min + max) / 2.0;
    // Just above the face, so the lines are not lost in its depth.
    let center = face.center + face.rotation * Vec3::new(mid.x, 0.0005, mid.y);
    // The grid lies in its x–y plane: turned so its y runs along the face's z.
    let rotation = face.rotation * Quat::from_rotation_x(std::f32::consts::FRAC_PI_2);
    Some(Grid { place: Isometry3d::new(center, rotation), cells: cells.as_uvec2() })
}

/// The stage's systems: lights, scenery and objects' meshes.
#[derive(Debug, Clone, Copy, Default)]
pub struct StagePlugin;

impl Plugin for StagePlugin {
    fn build(&self, app: &mut App) {
        crate::sets::configure(app);
        app.init_resource::<Scenery>()
            .init_gizmo_group::<GridGizmos>()
            .add_systems(Startup, setup_lights)
            .add_systems(Update, (dress_scenery, dress_objects).in_set(ViewerSystems::Draw))
            .add_systems(Update, draw_grids.after(dress_scenery).in_set(ViewerSystems::Draw));
    }
}

/// Every collider not on an object's body (the statics, each on a fixed
/// body of its own), as meshes in the world.
fn static_meshes(world: &InteractionWorld) -> Vec<(Transform, Mesh)> {
    static_colliders(world)
        .flat_map(|c| {
            let place = convert::transform(c.position().translation, c.position().rotation);
            shapes::meshes(c.shape()).into_iter().map(move |(t, mesh)| (place * t, mesh))
        })
        .collect()
}

/// Every collider not on an object's body: the statics, each on a fixed
/// body of its own.
fn static_colliders(world: &InteractionWorld) -> impl Iterator<Item = &Collider> + '_ {
    let objects: Vec<_> = world.object_ids().filter_map(|id| world.object_body(id)).collect();
    let colliders = world.physics().colliders.iter();
    colliders
        .map(|(_, c)| c)
        .filter(move |c| c.parent().is_none_or(|body| !objects.contains(&body)))
}
