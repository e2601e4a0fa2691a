//! AR mode (§3.6): the virtual objects over a background image (a frame of
//! the headset's pass-through video, or any photo). The hand is not drawn.
//! It is an occlusion mask that hides the virtual objects behind the real
//! hand in the image and leaves the ones in front of it visible. The static
//! scenery (ground, table) stands for real surfaces, so it masks in the same
//! way.
//!
//! A mask writes depth and shows the background's own pixel where it
//! covers ([`PassThroughMaterial`]). That draws the same picture as a
//! depth-only mesh drawn before the rest, in whatever order the renderer
//! draws. A far sphere around the scene, in the same material, shows the
//! background everywhere else.

use crate::hand_visual::DrawnBone;
use crate::stage::SceneryMesh;
use bevy::asset::{RenderAssetUsages, embedded_asset};
use bevy::light::{NotShadowCaster, NotShadowReceiver};
use bevy::mesh::MeshVertexBufferLayoutRef;
use bevy::pbr::{MaterialPipeline, MaterialPipelineKey};
use bevy::prelude::*;
use bevy::render::render_resource::{
    AsBindGroup, Extent3d, RenderPipelineDescriptor, SpecializedMeshPipelineError,
    TextureDimension, TextureFormat,
};
use bevy::shader::ShaderRef;
use std::path::Path;

/// The backdrop sphere's radius (m): far beyond any scene, inside the
/// camera's view distance.
const BACKDROP_RADIUS: f32 = 400.0;

/// The largest background side (pixels): wgpu's default texture limit.
const MAX_SIDE: u32 = 8192;

/// The background image, decoded (8-bit sRGB RGBA).
#[derive(Resource, Debug, Clone)]
pub struct Background {
    /// Width and height (pixels).
    pub size: UVec2,
    /// The pixels, row by row from the top.
    pub rgba: Vec<u8>,
}

impl Background {
    /// Reads an image file (PNG or JPEG); an error names the file.
    pub fn load(path: &Path) -> Result<Background, String> {
        let fail = |e: &dyn std::fmt::Display| {
            format!("{}: cannot read the background image: {e}", path.display())
        };
        let image = image::ImageReader::open(path)
            .map_err(|e| fail(&e))?
            .with_guessed_format()
            .map_err(|e| fail(&e))?
            .decode()
            .map_err(|e| fail(&e))?
            .to_rgba8();
        let size = UVec2::new(image.width(), image.height());
        if size.max_element() > MAX_SIDE {
            let why = format!("{} × {} pixels; at most {MAX_SIDE} a side", size.x, size.y);
            return Err(fail(&why));
        }
        Ok(Background { size, rgba: image.into_raw() })
    }

    fn image(&self) -> Image {
        let size = Extent3d { width: self.size.x, height: self.size.y, depth_or_array_layers: 1 };
        Image::new(
            size,
            TextureDimension::D2,
            self.rgba.clone(),
            TextureFormat::Rgba8UnormSrgb,
            RenderAssetUsages::RENDER_WORLD,
        )
    }
}

/// Shows the background image where it covers, and hides what is behind.
#[derive(Asset, TypePath, AsBindGroup, Debug, Clone)]
pub struct PassThroughMaterial {
    /// The background image.
    #[texture(0)]
    #[sampler(1)]
    pub background: Handle<Image>,
}

impl Material for PassThroughMaterial {
    fn fragment_shader() -> ShaderRef {
        "embedded://coulomb_hands_view/shaders/pass_through.wgsl".into()
    }

    /// Both faces: the backdrop is seen from inside.
    fn specialize(
        _pipeline: &MaterialPipeline,
        descriptor: &mut RenderPipelineDescriptor,
        _layout: &MeshVertexBufferLayoutRef,
        _key: MaterialPipelineKey<Self>,
    ) -> Result<(), SpecializedMeshPipelineError> {
        descriptor.primitive.cull_mode = None;
        Ok(())
    }
}

/// AR mode's material, backdrop and masks; the app inserts [`Background`].
#[derive(Debug, Clone, Copy, Default)]
pub struct ArPlugin;

impl Plugin for ArPlugin {
    fn build(&self, app: &mut App) {
        embedded_asset!(app, "shaders/pass_through.wgsl");
        app.add_plugins(MaterialPlugin::<PassThroughMaterial>::default())
            .add_systems(Startup, (spawn_backdrop, hide_grids))
            .add_systems(PostUpdate, mask_real_things);
    }
}

/// No grid on the scenery: it is the real one's mask, and the real floor
/// shows through it.
fn hide_grids(store: Option<ResMut<GizmoConfigStore>>) {
    let grids = store.and_then(|s| s.into_inner().get_config_mut::<crate::stage::GridGizmos>());
    if let Some((config, _)) = grids {
        config.enabled = false;
    }
}

/// The material every mask shares.
#[derive(Resource, Debug, Clone)]
struct Mask(Handle<PassThroughMaterial>);

fn spawn_backdrop(
    background: Res<Background>,
    mut images: ResMut<Assets<Image>>,
    mut materials: ResMut<Assets<PassThroughMaterial>>,
    mut meshes: ResMut<Assets<Mesh>>,
    mut commands: Commands,
) {
    let material =
        materials.add(PassThroughMaterial { background: images.add(background.image()) });
    commands.spawn((
        Mesh3d(meshes.add(Sphere::new(BACKDROP_RADIUS).mesh().uv(32, 16))),
        MeshMaterial3d(material.clone()),
        NotShadowCaster,
        NotShadowReceiver,
    ));
    commands.insert_resource(Mask(material));
}

/// The drawn hands' bones and the scenery, not yet masks.
type NotYetMasks =
    (Or<(With<DrawnBone>, With<SceneryMesh>)>, With<MeshMaterial3d<StandardMaterial>>);

/// Turns the drawn hands' bones and the scenery into masks, as they appear.
fn mask_real_things(
    mask: Option<Res<Mask>>,
    real: Query<Entity, NotYetMasks>,
    mut commands: Commands,
) {
    let Some(mask) = mask else { return };
    for entity in &real {
        commands.entity(entity).remove::<MeshMaterial3d<StandardMaterial>>().insert((
            MeshMaterial3d(mask.0.clone()),
            NotShadowCaster,
            NotShadowReceiver,
        ));
    }
}
