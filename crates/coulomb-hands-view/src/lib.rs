//! coulomb-hands-view: a window onto an interaction, with the thesis's hand
//! visualization (§3.6), force and motion arrows (Fig. 1.1), a HUD,
//! playback controls and a hand driven by mouse and keyboard.
//!
//! The data path is the plugin's ([`coulomb_hands_bevy`]): the physics
//! steps once per tick of its own clock, whatever the frame rate. This crate
//! is layered, one plugin per module, in the order of [`ViewerSystems`]:
//!
//! - input and playback: [`keys`] (every binding, in one table),
//!   [`transport`] (pause, speed, seek, restart: it owns them, others ask
//!   by message), [`task`] (the chessboard task);
//! - the viewer's own hands: [`mouse_hand`], [`xr_hands`] (with the runtime
//!   itself in `openxr` under the `openxr` feature);
//! - the picture: [`camera`], [`stage`], [`ghost`] (a capture's object),
//!   [`hand_visual`], [`arrows`], [`sound`], [`ar`]; then [`hud`], whose
//!   lines each module writes, and [`timing`].
//!
//! A new world (a restart, a seek back) is the plugin's one message,
//! [`coulomb_hands_bevy::physics::HandPhysicsReplaced`].

pub mod ar;
pub mod arrows;
pub mod camera;
pub mod display;
pub mod ghost;
pub mod grasp_view;
pub mod hand_visual;
pub mod head;
pub mod hud;
pub mod keys;
pub mod mouse_hand;
#[cfg(feature = "openxr")]
pub mod openxr;
pub mod ready;
pub mod sets;
pub mod shapes;
pub mod sound;
pub mod source;
pub mod stage;
pub mod stereo;
pub mod task;
pub mod timing;
pub mod transport;
pub mod xr_hands;

use bevy::prelude::*;
use coulomb_hands::pipeline::Method;
use coulomb_hands_bevy::CoulombHandsPlugin;
use coulomb_hands_bevy::input::AppHand;
pub use sets::ViewerSystems;
use source::{LoadError, Source};
use transport::{Shot, Transport, Viewed};

/// What to show and how.
#[derive(Debug, Clone)]
pub struct Viewer {
    /// The input.
    pub source: Source,
    /// How hands move objects.
    pub method: Method,
    /// Screenshots to save at simulated times.
    pub shots: Vec<Shot>,
    /// Quit once this simulated time is reached (s).
    pub exit_after: Option<f64>,
    /// Start paused.
    pub paused: bool,
    /// Where the camera starts, if not the default.
    pub view: Option<camera::StartView>,
    /// Whether the raw skeleton is shown at first.
    pub skeleton: bool,
    /// Side-by-side stereo, if asked for.
    pub stereo: Option<camera::Stereo>,
    /// AR mode's background image: the hand becomes an occlusion mask over it.
    pub background: Option<ar::Background>,
    /// No contact sound, even with an audio device.
    pub mute: bool,
    /// The chessboard task's session, when the source is its trial.
    pub task: Option<task::ChessboardTask>,
    /// Where the scene sits in the room, for an XR runtime's hands.
    pub room: xr_hands::RoomPlacement,
}

impl Viewer {
    /// The app: a window, the plugin, and the viewer's systems, with the
    /// world built and ready at t = 0, and the camera framing its run.
    pub fn app(self) -> Result<App, LoadError> {
        let physics = self.source.build(self.method)?;
        let framing = camera::Framing::of_run(&self.source, self.method)?;
        let head = self.source.head().copied();
        let live_xr = self.source.app_hands().iter().any(|h| h.1 == source::HandDriver::Xr);
        let mut transport = Transport::new(self.source.duration(), self.shots, self.exit_after);
        transport.paused = self.paused;
        transport.live = self.source.is_live();
        let window = Window {
            title: format!("coulomb-hands-view: {}", self.source.name()),
            resolution: (1280u32, 720u32).into(),
            ..default()
        };
        // Audio is opened by the sound plugin, and only if there is a device.
        let plugins = DefaultPlugins
            .set(WindowPlugin { primary_window: Some(window), ..default() })
            .set(render_plugin())
            .disable::<bevy::audio::AudioPlugin>();
        let mut app = App::new();
        app.add_plugins((with_runtime(plugins, live_xr)?, CoulombHandsPlugin::default()));
        spawn_app_hands(&mut app, &self.source);
        app.add_plugins((ViewerPlugin { task: self.task.is_some() }, ready::RendererReadyPlugin))
            .insert_resource(physics)
            .insert_resource(transport)
            .insert_resource(self.room)
            .insert_resource(Viewed { source: self.source, method: self.method });
        app.insert_resource(arrows::ShowSkeleton(self.skeleton));
        let play = !self.mute && sound::audio_device_present();
        app.add_plugins(sound::SoundPlugin { play });
        if let Some(framing) = framing {
            app.insert_resource(framing);
        }
        if let Some(view) = self.view {
            app.insert_resource(view);
        }
        if let Some(stereo) = self.stereo {
            app.insert_resource(stereo);
        }
        if let Some(task) = self.task {
            app.insert_resource(task);
        }
        if let Some(background) = self.background {
            app.insert_resource(background).add_plugins(ar::ArPlugin);
        }
        #[cfg(feature = "openxr")]
        if live_xr {
            app.add_systems(Startup, openxr::exit_without_session);
        }
        if let Some(head) = head {
            app.insert_resource(camera::HeadView(head));
        }

        Ok(app)
    }
}

/// A headless app of `source` under `method`, for tests and tools that run
/// the viewer's logic with no display: Bevy's minimal plugins and input,
/// the coulomb-hands plugin, the transport (playing, to the source's end)
/// and the mouse hand, with the world built and the source's app hands
/// spawned. Nothing is drawn.
pub fn headless_app(source: Source, method: Method) -> Result<App, LoadError> {
    let physics = source.build(method)?;
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, bevy::input::InputPlugin, CoulombHandsPlugin::default()))
        .add_plugins((transport::TransportPlugin, mouse_hand::MouseHandPlugin));
    spawn_app_hands(&mut app, &source);
    app.insert_resource(physics)
        .insert_resource(Transport::new(source.duration(), Vec::new(), None))
        .insert_resource(Viewed { source, method });
    Ok(app)
}

/// Spawns the hands `source` has the viewer pose itself (the mouse hand, an
/// XR runtime's two), as app hands that outlive every rebuilt world.
pub fn spawn_app_hands(app: &mut App, source: &Source) {
    for (side, driver) in source.app_hands() {
        app.world_mut().spawn((AppHand::new(*side), *driver));
    }
}

/// The renderer on wgpu's native backends (Vulkan, Metal, DX12), unless
/// `WGPU_BACKEND` names others. wgpu is built with its GL backend too (the
/// `openxr` feature needs it, and both builds share one wgpu), and probing
/// GL where it has no driver only logs an EGL error.
fn render_plugin() -> bevy::render::RenderPlugin {
    use bevy::render::settings::{Backends, WgpuSettings};
    let backends = Backends::from_env().unwrap_or(Backends::PRIMARY);
    let settings = WgpuSettings { backends: Some(backends), ..default() };
    bevy::render::RenderPlugin { render_creation: settings.into(), ..default() }
}

/// `plugins`, with an XR runtime's session and hand tracking when the
/// hands are live.
fn with_runtime(
    plugins: bevy::app::PluginGroupBuilder,
    live_xr: bool,
) -> Result<bevy::app::PluginGroupBuilder, LoadError> {
    match live_xr {
        false => Ok(plugins),
        #[cfg(feature = "openxr")]
        true => Ok(openxr::with_openxr(plugins)),
        #[cfg(not(feature = "openxr"))]
        true => Err(NO_OPENXR.into()),
    }
}

/// Why `--openxr` cannot work in a build without the `openxr` feature.
pub const NO_OPENXR: &str = "--openxr: this viewer was built without OpenXR; build it with \
     `cargo run -p coulomb-hands-view --release --features openxr -- --openxr`";

/// The viewer's plugins, one per module (it expects [`Transport`] and
/// [`Viewed`] inserted, and the coulomb-hands plugin added).
#[derive(Debug, Clone, Copy, Default)]
pub struct ViewerPlugin {
    /// Whether the chessboard task runs.
    pub task: bool,
}

impl Plugin for ViewerPlugin {
    fn build(&self, app: &mut App) {
        app.add_plugins((
            transport::TransportPlugin,
            timing::TimingPlugin,
            hud::HudPlugin,
            camera::CameraPlugin,
            stage::StagePlugin,
            ghost::GhostPlugin { draw: true },
            hand_visual::HandVisualPlugin,
            arrows::ArrowsPlugin,
            mouse_hand::MouseHandPlugin,
            xr_hands::XrHandsPlugin,
        ));
        if self.task {
            app.add_plugins(task::TaskPlugin { draw: true });
        }
    }
}
