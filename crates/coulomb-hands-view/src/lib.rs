//! coulomb-hands-view: a window onto an interaction, with the thesis's hand
//! visualization (§3.6), force and motion arrows (Fig. 1.1), a HUD,
//! playback controls and a hand driven by mouse and keyboard.
//!
//! The data path is the plugin's ([`coulomb_hands_bevy`]): the interaction
//! steps once per fixed tick, whatever the frame rate; this crate only
//! draws it ([`stage`], [`hand_visual`], [`arrows`], [`hud`]), decides
//! whether a tick steps ([`transport`]), and poses the mouse hand
//! ([`mouse_hand`]) or takes an XR runtime's hands ([`xr_hands`], with
//! the runtime itself in `openxr` under the `openxr` feature).

pub mod ar;
pub mod arrows;
pub mod camera;
pub mod display;
pub mod hand_visual;
pub mod head;
pub mod hud;
pub mod mouse_hand;
#[cfg(feature = "openxr")]
pub mod openxr;
pub mod ready;
pub mod shapes;
pub mod sound;
pub mod source;
pub mod stage;
pub mod task;
pub mod transport;
pub mod xr_hands;

use bevy::app::{RunFixedMainLoop, RunFixedMainLoopSystems};
use bevy::prelude::*;
use coulomb_hands::pipeline::Method;
use coulomb_hands_bevy::{CoulombHandsPlugin, InteractionSystems};
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
    /// interaction built and ready at t = 0.
    pub fn app(self) -> Result<App, LoadError> {
        let (interaction, inlets) = self.source.build(self.method)?;
        let head = self.source.head().copied();
        let live_xr = inlets.xr.is_some();
        let mut transport = Transport::new(self.source.duration(), self.shots, self.exit_after);
        transport.paused = self.paused;
        transport.live = self.source.is_live();
        let mut hand = mouse_hand::MouseHand::default();
        hand.attach(inlets.mouse);
        let mut xr = xr_hands::XrHands::default();
        xr.attach(inlets.xr);
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
        app.add_plugins((
            with_runtime(plugins, live_xr)?,
            CoulombHandsPlugin,
            ViewerPlugin,
            ready::RendererReadyPlugin,
        ))
        .insert_non_send(interaction)
        .insert_resource(transport)
        .insert_resource(hand)
        .insert_resource(xr)
        .insert_resource(self.room)
        .insert_resource(Viewed { source: self.source, method: self.method });
        app.insert_resource(arrows::ShowSkeleton(self.skeleton));
        let play = !self.mute && sound::audio_device_present();
        app.add_plugins(sound::SoundPlugin { play });
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

/// The viewer's systems (it expects [`Transport`], [`Viewed`] and
/// [`mouse_hand::MouseHand`] inserted, and the plugin added).
#[derive(Debug, Clone, Copy, Default)]
pub struct ViewerPlugin;

impl Plugin for ViewerPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<hand_visual::DrawnHands>()
            .init_resource::<hand_visual::Grips>()
            .init_resource::<arrows::ShowSkeleton>()
            .init_resource::<arrows::ContactMotion>()
            .init_resource::<stage::Scenery>()
            .init_resource::<hud::StepTimer>()
            .init_resource::<hud::Scrubbing>()
            .init_resource::<task::BoardTiles>()
            .add_plugins((transport::TransportPlugin, xr_hands::XrHandsPlugin))
            .add_systems(
                FixedUpdate,
                (
                    hud::start_step.before(InteractionSystems::Step),
                    (hud::stop_step, hand_visual::track_grips).after(InteractionSystems::Step),
                ),
            )
            .add_systems(
                RunFixedMainLoop,
                (
                    hud::start_fixed_loop.in_set(RunFixedMainLoopSystems::BeforeFixedMainLoop),
                    hud::stop_fixed_loop.in_set(RunFixedMainLoopSystems::AfterFixedMainLoop),
                ),
            )
            .add_systems(
                Startup,
                (camera::spawn_camera, stage::setup_lights, arrows::setup_gizmos, hud::spawn_hud),
            )
            .add_systems(
                Update,
                (
                    hud::scrub_timeline.after(transport::playback_keys).before(transport::seek),
                    task::finish_on_enter.after(transport::playback_keys).before(transport::seek),
                    arrows::toggle_skeleton,
                    mouse_hand::drive_mouse_hand.after(transport::seek),
                    (camera::frame_view, camera::orbit_camera, camera::fit_eyes).chain(),
                ),
            )
            .add_systems(
                Update,
                (
                    stage::dress_scenery,
                    stage::dress_objects,
                    task::draw_board,
                    hand_visual::draw_hands,
                    arrows::draw_arrows,
                    arrows::draw_skeleton,
                    hud::update_hud,
                    transport::take_shots,
                    transport::exit_when_done,
                )
                    .after(transport::seek),
            );
    }
}
