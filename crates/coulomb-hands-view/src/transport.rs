//! Playback: pause, single step, speed, seeking on the timeline, the end of
//! a scenario or recording, screenshots at chosen simulated times, and
//! quitting after one.
//!
//! The plugin steps the physics once per tick of its clock; the transport
//! only decides whether a tick steps ([`may_step`], a run condition on the
//! plugin's step set), so the physics of a viewed run is the headless
//! run's, step for step. Speed scales Bevy's virtual clock. A seek back in
//! time rebuilds the world from t = 0 and steps it to the target in one
//! frame, which is exact because runs are deterministic. Live hands play in
//! real time: no speed but 1×, and no going back or on.
//!
//! The transport owns its state: other modules ask for a seek, a restart or
//! a pause with the messages [`Seek`], [`Restart`] and [`Pause`].

use crate::hud::{HudLines, HudSection};
use crate::keys::{self, Group};
use crate::ready::RendererReady;
use crate::sets::ViewerSystems;
use crate::source::Source;
use crate::timing::StepTimer;
use bevy::diagnostic::FrameCount;
use bevy::prelude::*;
use bevy::render::view::screenshot::{Screenshot, ScreenshotCaptured};
use bevy::window::PrimaryWindow;
use coulomb_hands::pipeline::Method;
use coulomb_hands_bevy::prelude::*;
use std::collections::VecDeque;
use std::path::PathBuf;
use std::time::Duration;

/// Playback speeds (× real time) the `[` and `]` keys move between.
pub const SPEEDS: [f32; 9] = [0.0625, 0.125, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0];

/// A screenshot to save when the simulated time reaches `at`.
#[derive(Debug, Clone, PartialEq)]
pub struct Shot {
    /// Simulated time (s).
    pub at: f64,
    /// A PNG file to write.
    pub path: PathBuf,
}

impl std::str::FromStr for Shot {
    type Err = String;
    /// `T=PATH`: a time in seconds and a `.png` file.
    fn from_str(s: &str) -> Result<Shot, String> {
        let (t, path) = s.split_once('=').ok_or(format!("expected T=PATH.png, got {s:?}"))?;
        let at = t.trim().parse::<f64>().ok().filter(|t| t.is_finite() && *t >= 0.0);
        let at = at.ok_or(format!("{t:?} is not a time in seconds ≥ 0"))?;
        if !path.ends_with(".png") {
            return Err(format!("screenshots are PNG files; {path:?} does not end in .png"));
        }
        Ok(Shot { at, path: PathBuf::from(path) })
    }
}

/// What is viewed, kept to rebuild the interaction on a seek back or a
/// restart.
#[derive(Resource, Debug, Clone)]
pub struct Viewed {
    /// The loaded input.
    pub source: Source,
    /// How hands move objects.
    pub method: Method,
}

/// The playback state.
#[derive(Resource, Debug, Clone)]
pub struct Transport {
    /// Whether stepping is paused.
    pub paused: bool,
    /// Index into [`SPEEDS`].
    pub speed: usize,
    /// One step is due although paused.
    step_once: bool,
    /// A seek was applied this frame, which then takes no steps: the
    /// frame shows the state sought.
    sought: bool,
    /// A time to go to (s), set by the keys or the timeline.
    pub seek: Option<f64>,
    /// The end of a scenario or recording (s); a scene has none.
    pub end: Option<f64>,
    /// Hands from a live tracker, which play at the tracker's own pace: the
    /// speed and the ← → keys are off (a live stream has no future to go
    /// to, and played faster it would only hold its newest frame).
    pub live: bool,
    /// Screenshots still to take, in time order.
    shots: VecDeque<Shot>,
    /// Frames the first shot has waited, held at its time.
    shot_frames: u32,
    /// Quit once this simulated time is reached and the shots are saved.
    pub exit_after: Option<f64>,
    /// A screenshot that could not be saved: the app exits with this error.
    pub failed: Option<String>,
}

impl Transport {
    /// Playing at 1×, to `end`, with `shots` to take.
    pub fn new(end: Option<f64>, mut shots: Vec<Shot>, exit_after: Option<f64>) -> Transport {
        shots.sort_by(|a, b| a.at.total_cmp(&b.at));
        let speed = SPEEDS.iter().position(|s| *s == 1.0).unwrap_or(0);
        Transport {
            paused: false,
            speed,
            step_once: false,
            sought: false,
            seek: None,
            end,
            live: false,
            shots: shots.into(),
            shot_frames: 0,
            exit_after,
            failed: None,
        }
    }

    /// The playback speed (× real time).
    pub fn speed(&self) -> f32 {
        SPEEDS[self.speed.min(SPEEDS.len() - 1)]
    }

    /// Whether the physics may step from time `t` (s) with step `dt`: not
    /// paused (or one step asked for), not at the end or the time to quit,
    /// and not at a screenshot's time.
    pub fn allows_step(&self, t: f64, dt: f64) -> bool {
        let reached = |at: f64| reached(t, at, dt);
        let stop = self.end.is_some_and(reached) || self.exit_after.is_some_and(reached);
        if stop || self.sought || self.shots.front().is_some_and(|s| reached(s.at)) {
            return false;
        }
        !self.paused || self.step_once
    }
}

/// Go to this simulated time (s): back replays from t = 0.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct Seek(pub f64);

/// Start again from t = 0, with another source if one is given (the
/// chessboard task's next trial).
#[derive(Message, Debug, Clone)]
pub struct Restart(pub Option<Source>);

/// Pause (`true`) or play.
#[derive(Message, Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pause(pub bool);

/// Whether a left-drag began on the timeline (so it scrubs, not orbits),
/// and the time it last went to.
#[derive(Resource, Debug, Default)]
pub struct Scrubbing(pub bool, Option<f64>);

/// The timeline's height (logical pixels).
const TIMELINE_PX: f32 = 14.0;

/// The timeline's filled part.
#[derive(Component)]
pub struct TimelineFill;

/// The transport's systems: the run condition on the plugin's step set,
/// the keys, the timeline, the messages, screenshots and the exit (it
/// expects [`Transport`] and [`Viewed`] inserted, and the plugin added).
#[derive(Debug, Clone, Copy, Default)]
pub struct TransportPlugin;

impl Plugin for TransportPlugin {
    fn build(&self, app: &mut App) {
        crate::sets::configure(app);
        app.add_message::<Seek>()
            .add_message::<Restart>()
            .add_message::<Pause>()
            .init_resource::<Scrubbing>()
            .init_resource::<StepTimer>()
            .init_resource::<HudLines>()
            .configure_sets(HandPhysicsStep, WorldStep.run_if(may_step))
            .add_systems(HandPhysicsStep, spend_single_step.after(WorldStep))
            .add_systems(Startup, spawn_timeline)
            .add_systems(PreUpdate, (playback_keys, scrub_timeline).in_set(ViewerSystems::Input))
            .add_systems(PreUpdate, apply_requests.in_set(ViewerSystems::Transport))
            .add_systems(Update, (fill_timeline, hud_lines).in_set(ViewerSystems::HudLines))
            .add_systems(
                Update,
                (take_shots, exit_when_done, end_frame).chain().in_set(ViewerSystems::Output),
            );
    }
}

/// Whether `t` has reached `at`, within half a step `dt` (s).
pub fn reached(t: f64, at: f64, dt: f64) -> bool {
    t >= at - dt / 2.0
}

/// The run condition of the plugin's step set; with a renderer, the run
/// starts once it draws everything ([`RendererReady`]).
pub fn may_step(
    transport: Res<Transport>,
    physics: Option<Res<HandPhysics>>,
    renderer: Option<Res<RendererReady>>,
) -> bool {
    if renderer.is_some_and(|r| !r.started) {
        return false;
    }
    physics.is_some_and(|p| {
        let world = p.world();
        transport.allows_step(world.time(), f64::from(world.config().dt))
    })
}

/// After a tick: a single step is used up.
pub fn spend_single_step(mut transport: ResMut<Transport>) {
    transport.step_once = false;
}

/// After the frame's steps: the next frame steps again after a seek.
fn end_frame(mut transport: ResMut<Transport>) {
    transport.sought = false;
}

/// The playback keys ([`keys`]): pause, one step (pausing), half and
/// double speed, back and on by a second (these two not with live hands),
/// restart.
pub fn playback_keys(
    input: Res<ButtonInput<KeyCode>>,
    mut transport: ResMut<Transport>,
    mut time: ResMut<Time<Virtual>>,
    physics: Option<Res<HandPhysics>>,
) {
    let now = physics.map_or(0.0, |p| p.world().time());
    let t = &mut *transport;
    if keys::PAUSE.just_pressed(&input) {
        t.paused = !t.paused;
    }
    if keys::STEP.just_pressed(&input) {
        (t.paused, t.step_once) = (true, true);
    }
    let replayed = !t.live;
    let pressed = |k: KeyCode| input.just_pressed(k);
    if replayed && pressed(keys::SPEED.keys[0]) {
        t.speed = t.speed.saturating_sub(1);
    }
    if replayed && pressed(keys::SPEED.keys[1]) {
        t.speed = (t.speed + 1).min(SPEEDS.len() - 1);
    }
    if replayed && pressed(keys::SEEK.keys[0]) {
        t.seek = Some((now - 1.0).max(0.0));
    }
    if replayed && pressed(keys::SEEK.keys[1]) {
        t.seek = Some(now + 1.0);
    }
    if keys::RESTART.just_pressed(&input) {
        t.seek = Some(0.0);
    }
    if time.relative_speed() != t.speed() {
        time.set_relative_speed(t.speed());
        // At most a quarter second of simulation per frame at any speed, so
        // a fast replay of a heavy scene slows down rather than freezing.
        time.set_max_delta(Duration::from_secs_f32(0.25 / t.speed().max(1.0)));
    }
}

/// Applies the other modules' requests, then goes to the time asked for:
/// back by rebuilding from t = 0, then on by stepping, all in this frame
/// (never past the end, the time to quit or the next screenshot). These
/// steps write no contact messages. A scene's mouse hand is not replayed:
/// going back restarts it at its start pose, and going on steps with the
/// hand held still.
pub fn apply_requests(
    (mut seeks, mut restarts, mut pauses): (
        MessageReader<Seek>,
        MessageReader<Restart>,
        MessageReader<Pause>,
    ),
    mut transport: ResMut<Transport>,
    mut viewed: ResMut<Viewed>,
    physics: Option<ResMut<HandPhysics>>,
) {
    if let Some(Pause(paused)) = pauses.read().last() {
        transport.paused = *paused;
    }
    if let Some(Seek(to)) = seeks.read().last() {
        transport.seek = Some(*to);
    }
    let mut rebuild = false;
    for Restart(source) in restarts.read() {
        if let Some(source) = source {
            viewed.source = source.clone();
        }
        (transport.seek, rebuild) = (Some(0.0), true);
    }
    let (Some(target), Some(mut physics)) = (transport.seek.take(), physics) else { return };
    transport.sought = true;
    // Never past the end, the time to quit or the next screenshot's time.
    let next_shot = transport.shots.front().map(|s| s.at);
    let limits = [transport.end, transport.exit_after, next_shot];
    let target = limits.into_iter().flatten().fold(target, f64::min);
    let dt = f64::from(physics.world().config().dt);
    if rebuild || !reached(target, physics.world().time(), dt) {
        match viewed.source.build(viewed.method) {
            Ok(fresh) => *physics = fresh,
            Err(e) => {
                error!("could not restart: {e}");
                return;
            }
        }
    }
    while !reached(physics.world().time(), target, dt) && physics.step() {}
}

/// The timeline along the window's foot, for a run with an end.
fn spawn_timeline(mut commands: Commands, transport: Res<Transport>) {
    if transport.end.is_none() {
        return;
    }
    let bar = Node {
        position_type: PositionType::Absolute,
        bottom: Val::Px(0.0),
        left: Val::Px(0.0),
        width: Val::Percent(100.0),
        height: Val::Px(TIMELINE_PX),
        ..default()
    };
    let fill = Node { width: Val::Percent(0.0), height: Val::Percent(100.0), ..default() };
    commands.spawn((bar, BackgroundColor(Color::srgb(0.22, 0.23, 0.27)))).with_child((
        fill,
        BackgroundColor(Color::srgb(0.55, 0.62, 0.78)),
        TimelineFill,
    ));
}

/// Fills the timeline to the current time.
fn fill_timeline(
    transport: Res<Transport>,
    physics: Option<Res<HandPhysics>>,
    mut fill: Query<&mut Node, With<TimelineFill>>,
) {
    let (Some(end), Some(physics)) = (transport.end.filter(|e| *e > 0.0), physics) else {
        return;
    };
    let t = physics.world().time();
    for mut node in &mut fill {
        node.width = Val::Percent((t / end * 100.0).clamp(0.0, 100.0) as f32);
    }
}

/// A left press on the timeline seeks there, and dragging scrubs.
///
/// The bar spans the window, or in stereo the left eye's half, where the
/// UI is laid out. A held button seeks again only when the cursor moves.
pub fn scrub_timeline(
    buttons: Res<ButtonInput<MouseButton>>,
    windows: Query<&Window, With<PrimaryWindow>>,
    stereo: Option<Res<crate::stereo::Stereo>>,
    mut scrubbing: ResMut<Scrubbing>,
    mut transport: ResMut<Transport>,
) {
    let Some(end) = transport.end else { return };
    let Ok(window) = windows.single() else { return };
    let width = if stereo.is_some() { window.width() / 2.0 } else { window.width() };
    let cursor = window.cursor_position();
    if buttons.just_pressed(MouseButton::Left) {
        let on_bar = |c: Vec2| c.y >= window.height() - TIMELINE_PX && c.x <= width;
        *scrubbing = Scrubbing(cursor.is_some_and(on_bar), None);
    }
    if !buttons.pressed(MouseButton::Left) {
        scrubbing.0 = false;
    }
    if let (true, Some(c)) = (scrubbing.0, cursor) {
        let to = f64::from((c.x / width).clamp(0.0, 1.0)) * end;
        if scrubbing.1 != Some(to) {
            (scrubbing.1, transport.seek) = (Some(to), Some(to));
        }
    }
}

/// The HUD's lines of the run: what runs, the time and state, the keys.
fn hud_lines(
    physics: Option<Res<HandPhysics>>,
    (viewed, transport): (Res<Viewed>, Res<Transport>),
    mut hud: ResMut<HudLines>,
) {
    let Some(physics) = physics else { return };
    let world = physics.world();
    let (t, dt) = (world.time(), f64::from(world.config().dt));
    let end = transport.end.map_or(String::new(), |e| format!(" / {e:.3}"));
    let state = match physics.stopped() {
        Some(Stopped::Failed(e)) => format!("STOPPED: {e}"),
        Some(Stopped::Finished) => "finished".to_string(),
        None if transport.end.is_some_and(|e| reached(t, e, dt)) => "at the end".to_string(),
        None if transport.paused => "paused".to_string(),
        None => format!("playing {}x", transport.speed()),
    };
    hud.set(
        HudSection::Run,
        vec![
            format!("{} | method {}", viewed.source.name(), viewed.method.name()),
            format!("t {t:.3}{end} s | step {} | {state}", physics.steps()),
        ],
    );
    let live = if transport.live { "live hands at 1x | " } else { "" };
    let keys = format!("{live}{}", keys::hud_line(Group::Playback, transport.live));
    hud.set(HudSection::Keys, vec![keys]);
    if let Some(feed) = viewed.source.leap_feed() {
        hud.set(HudSection::LiveHands, vec![leap_line(&feed.stats())]);
    }
}

/// What the live Leap stream has sent, and whether it still runs.
pub fn leap_line(stats: &coulomb_hands::run::live::LiveStats) -> String {
    let state = match (&stats.error, stats.closed, stats.newest) {
        (Some(e), ..) => format!("FAILED: {e}"),
        (None, true, _) => "closed".to_string(),
        (None, false, None) => "waiting for the first frame".to_string(),
        (None, false, Some(t)) => format!("newest frame at {t:.2} s"),
    };
    format!(
        "Leap: {} frames, {} hands seen, {} skipped, {} dropped | {state}",
        stats.frames, stats.hands_seen, stats.skipped, stats.dropped
    )
}

/// Takes the next screenshot once the physics is held at its time and a
/// few frames have drawn that state with every pipeline ready.
pub fn take_shots(
    mut transport: ResMut<Transport>,
    physics: Option<Res<HandPhysics>>,
    renderer: Option<Res<RendererReady>>,
    mut commands: Commands,
) {
    /// Frames drawn at the held state, ready, before the capture.
    const SETTLE_FRAMES: u32 = 3;
    let Some(physics) = physics else { return };
    if renderer.is_some_and(|r| !r.ready()) && transport.shot_frames < SETTLE_FRAMES {
        transport.shot_frames = 0;
        return;
    }
    let world = physics.world();
    let (t, dt) = (world.time(), f64::from(world.config().dt));
    let Some(shot) = transport.shots.front().cloned() else { return };
    let at_end = transport.end.is_some_and(|end| reached(t, end, dt));
    if !reached(t, shot.at, dt) && !at_end && physics.stopped().is_none() {
        return;
    }
    transport.shot_frames += 1;
    if transport.shot_frames == SETTLE_FRAMES {
        commands.spawn(Screenshot::primary_window()).observe(
            move |captured: On<ScreenshotCaptured>, mut transport: ResMut<Transport>| {
                if let Err(e) = save_png(&captured.image, &shot.path) {
                    transport.failed = Some(format!("could not save {}: {e}", shot.path.display()));
                }
                transport.shots.pop_front();
                transport.shot_frames = 0;
            },
        );
    }
}

/// Writes a captured frame as an 8-bit RGB PNG (the alpha channel of a
/// window capture carries no transparency).
fn save_png(image: &Image, path: &std::path::Path) -> Result<(), String> {
    let rgb = image.clone().try_into_dynamic().map_err(|e| e.to_string())?.to_rgb8();
    rgb.save_with_format(path, image::ImageFormat::Png).map_err(|e| e.to_string())
}

/// Quits once the time to quit after is reached (or the run cannot go on)
/// and every screenshot is saved; a failed step exits with an error.
pub fn exit_when_done(
    transport: Res<Transport>,
    physics: Option<Res<HandPhysics>>,
    frames: Res<FrameCount>,
    time: Res<Time<Real>>,
    timer: Res<StepTimer>,
    mut exit: MessageWriter<AppExit>,
) {
    if let Some(e) = &transport.failed {
        eprintln!("error: {e}");
        exit.write(AppExit::error());
        return;
    }
    let (Some(after), Some(physics)) = (transport.exit_after, physics) else { return };
    if let Some(Stopped::Failed(e)) = physics.stopped() {
        eprintln!("error: the run failed: {e}");
        exit.write(AppExit::error());
        return;
    }
    let world = physics.world();
    let (t, dt) = (world.time(), f64::from(world.config().dt));
    let last = transport.end.map_or(after, |end| after.min(end));
    let stuck = physics.stopped().is_some();
    if (reached(t, last, dt) || stuck) && transport.shots.is_empty() {
        let wall = time.elapsed_secs_f64();
        eprintln!(
            "coulomb-hands-view: {} frames in {wall:.1} s ({:.1} per s), {} physics steps of \
             {:.1} µs ({:.1} µs per tick)",
            frames.0,
            f64::from(frames.0) / wall,
            physics.steps(),
            timer.mean_us,
            timer.tick_us,
        );
        exit.write(AppExit::Success);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_shot_reads_its_time_and_png_path_and_refuses_others() {
        let shot: Shot = "1.25=out/grasp.png".parse().expect("a shot");
        assert_eq!(shot, Shot { at: 1.25, path: PathBuf::from("out/grasp.png") });
        assert!("1.25".parse::<Shot>().unwrap_err().contains("T=PATH"));
        assert!("-1=a.png".parse::<Shot>().unwrap_err().contains("≥ 0"));
        assert!("NaN=a.png".parse::<Shot>().is_err());
        assert!("2=a.jpg".parse::<Shot>().unwrap_err().contains("PNG"));
    }

    #[test]
    fn stepping_holds_at_the_end_at_a_shot_and_while_paused() {
        let dt = 0.001;
        let shot = Shot { at: 0.5, path: PathBuf::from("a.png") };
        let mut t = Transport::new(Some(2.0), vec![shot], None);
        assert!(t.allows_step(0.3, dt));
        assert!(!t.allows_step(0.4996, dt), "held at the shot's time");
        t.shots.clear();
        assert!(t.allows_step(0.4996, dt));
        assert!(!t.allows_step(1.9995, dt), "held at the end");
        t.paused = true;
        assert!(!t.allows_step(1.0, dt));
        t.step_once = true;
        assert!(t.allows_step(1.0, dt), "one step while paused");
    }

    /// The transport after `keys` are pressed in one frame.
    fn after_keys(live: bool, keys: &[KeyCode]) -> Transport {
        use bevy::ecs::system::RunSystemOnce;
        let mut world = World::new();
        let mut input = ButtonInput::<KeyCode>::default();
        keys.iter().for_each(|&key| input.press(key));
        let mut transport = Transport::new(None, vec![], None);
        transport.live = live;
        world.insert_resource(input);
        world.insert_resource(transport);
        world.insert_resource(Time::<Virtual>::default());
        world.run_system_once(playback_keys).unwrap();
        world.remove_resource::<Transport>().unwrap()
    }

    #[test]
    fn live_hands_play_at_one_speed_with_no_seeking_but_pause_and_restart() {
        use KeyCode::{ArrowLeft, ArrowRight, BracketLeft, BracketRight, Home, Space};
        let one = Transport::new(None, vec![], None).speed;
        for live in [false, true] {
            let faster = after_keys(live, &[BracketRight, BracketRight]);
            let slower = after_keys(live, &[BracketLeft]);
            let on = after_keys(live, &[ArrowRight]);
            let back = after_keys(live, &[ArrowLeft, Space]);
            assert_eq!(faster.speed == one, live, "live {live}: faster");
            assert_eq!(slower.speed == one, live, "live {live}: slower");
            assert_eq!(on.seek.is_none(), live, "live {live}: on by a second");
            assert_eq!(back.seek.is_none(), live, "live {live}: back");
            assert!(back.paused, "live {live}: Space pauses");
            assert_eq!(after_keys(live, &[Home]).seek, Some(0.0), "live {live}: Home");
        }
    }
}
