//! Whether the renderer is drawing everything: Bevy compiles a render
//! pipeline in the background the first time a kind of mesh, material or
//! gizmo is shown, and draws nothing with it until it is ready (a second or
//! more on a software renderer). The run starts, and a screenshot is taken,
//! only once no pipeline is waiting, so neither shows a half-drawn scene.

use bevy::prelude::*;
use bevy::render::render_resource::PipelineCache;
use bevy::render::{ExtractSchedule, MainWorld, RenderApp};

/// The renderer's state, as the last frames saw it.
#[derive(Resource, Debug, Default, Clone, Copy)]
pub struct RendererReady {
    /// Frames in a row with no pipeline waiting.
    pub frames: u32,
    /// Whether it has been ready once (the run may start).
    pub started: bool,
}

/// Frames in a row with no pipeline waiting before the renderer counts as
/// ready: a pipeline asked for in one frame is queued only in the next.
pub const READY_FRAMES: u32 = 3;

impl RendererReady {
    /// Whether everything shown is being drawn.
    pub fn ready(&self) -> bool {
        self.frames >= READY_FRAMES
    }
}

/// Reports the render world's pipeline queue to the main world each frame.
#[derive(Debug, Clone, Copy, Default)]
pub struct RendererReadyPlugin;

impl Plugin for RendererReadyPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<RendererReady>();
        if let Some(render) = app.get_sub_app_mut(RenderApp) {
            render.add_systems(ExtractSchedule, report_pipelines);
        }
    }
}

/// In the render world's extract step: counts the frames with an empty
/// queue into the main world's [`RendererReady`].
fn report_pipelines(mut main: ResMut<MainWorld>, cache: Res<PipelineCache>) {
    let idle = cache.waiting_pipelines().next().is_none() && cache.pipelines().next().is_some();
    if let Some(mut ready) = main.get_resource_mut::<RendererReady>() {
        ready.frames = if idle { ready.frames + 1 } else { 0 };
        ready.started |= ready.ready();
    }
}
