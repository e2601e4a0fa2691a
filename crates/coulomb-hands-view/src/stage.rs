//! The scene's look: lights, the static scenery, and a mesh for every
//! object the plugin spawns, each drawn from the object's own colliders.

use crate::sets::ViewerSystems;
use crate::shapes;
use bevy::prelude::*;
use coulomb_hands::pipeline::InteractionWorld;
use coulomb_hands_bevy::convert;
use coulomb_hands_bevy::prelude::*;

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

/// The static scenery drawn, for the world it belongs to.
#[derive(Resource, Debug, Default)]
pub struct Scenery(Vec<Entity>);

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
}

/// The stage's systems: lights, scenery and objects' meshes.
#[derive(Debug, Clone, Copy, Default)]
pub struct StagePlugin;

impl Plugin for StagePlugin {
    fn build(&self, app: &mut App) {
        crate::sets::configure(app);
        app.init_resource::<Scenery>()
            .add_systems(Startup, setup_lights)
            .add_systems(Update, (dress_scenery, dress_objects).in_set(ViewerSystems::Draw));
    }
}

/// Every collider not on an object's body (the statics, each on a fixed
/// body of its own), as meshes in the world.
fn static_meshes(world: &InteractionWorld) -> Vec<(Transform, Mesh)> {
    let objects: Vec<_> = world.object_ids().filter_map(|id| world.object_body(id)).collect();
    let colliders = world.physics().colliders.iter();
    colliders
        .filter(|(_, c)| c.parent().is_none_or(|body| !objects.contains(&body)))
        .flat_map(|(_, c)| {
            let place = convert::transform(c.position().translation, c.position().rotation);
            shapes::meshes(c.shape()).into_iter().map(move |(t, mesh)| (place * t, mesh))
        })
        .collect()
}
