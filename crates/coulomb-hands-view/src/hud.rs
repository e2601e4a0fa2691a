//! The heads-up display: what runs, the time, the physics step's cost and
//! the bones in contact, the keys; and the timeline, whose bar is clicked
//! or dragged to seek.

use crate::mouse_hand::MouseHand;
use crate::transport::{Transport, Viewed};
use bevy::prelude::*;
use bevy::window::PrimaryWindow;
use coulomb_hands_bevy::interaction::{Interaction, Stopped};
use std::collections::HashSet;
use std::time::Instant;

/// The timeline's height (logical pixels).
const TIMELINE_PX: f32 = 14.0;

/// The HUD's text.
#[derive(Component)]
pub struct HudText;

/// The timeline's filled part.
#[derive(Component)]
pub struct TimelineFill;

/// Whether a left-drag began on the timeline (so it scrubs, not orbits),
/// and the time it last went to.
#[derive(Resource, Debug, Default)]
pub struct Scrubbing(pub bool, Option<f64>);

/// The wall time of the physics steps: each fixed tick's step alone, and
/// the frame's whole fixed loop (the step plus Bevy's schedule per tick).
#[derive(Resource, Debug, Default)]
pub struct StepTimer {
    tick: Option<(Instant, usize)>,
    frame: Option<(Instant, usize)>,
    /// Mean wall time of one physics step (µs), smoothed over steps.
    pub mean_us: f64,
    /// Mean wall time of one fixed tick (µs), smoothed over frames.
    pub tick_us: f64,
}

/// A running mean that forgets slowly.
fn smooth(mean: f64, x: f64, weight: f64) -> f64 {
    if mean == 0.0 { x } else { (1.0 - weight) * mean + weight * x }
}

/// In a fixed tick, just before the step.
pub fn start_step(mut timer: ResMut<StepTimer>, interaction: Option<NonSend<Interaction>>) {
    timer.tick = interaction.map(|i| (Instant::now(), i.steps()));
}

/// In a fixed tick, just after the step: its time, if it stepped.
pub fn stop_step(mut timer: ResMut<StepTimer>, interaction: Option<NonSend<Interaction>>) {
    let (Some((t0, n0)), Some(i)) = (timer.tick.take(), interaction) else { return };
    if i.steps() > n0 {
        timer.mean_us = smooth(timer.mean_us, t0.elapsed().as_secs_f64() * 1e6, 0.01);
    }
}

/// Before the frame's fixed ticks.
pub fn start_fixed_loop(mut timer: ResMut<StepTimer>, interaction: Option<NonSend<Interaction>>) {
    timer.frame = interaction.map(|i| (Instant::now(), i.steps()));
}

/// After them: the mean per step this frame joins the running figure.
pub fn stop_fixed_loop(mut timer: ResMut<StepTimer>, interaction: Option<NonSend<Interaction>>) {
    let (Some((t0, n0)), Some(i)) = (timer.frame.take(), interaction) else { return };
    let steps = i.steps().saturating_sub(n0);
    if steps > 0 {
        let us = t0.elapsed().as_secs_f64() * 1e6 / steps as f64;
        timer.tick_us = smooth(timer.tick_us, us, 0.1);
    }
}

/// The HUD's text and the timeline.
pub fn spawn_hud(mut commands: Commands, transport: Res<Transport>) {
    let panel = Node {
        position_type: PositionType::Absolute,
        top: Val::Px(8.0),
        left: Val::Px(8.0),
        padding: UiRect::all(Val::Px(6.0)),
        ..default()
    };
    commands.spawn((panel, BackgroundColor(Color::srgba(0.0, 0.0, 0.0, 0.55)))).with_child((
        Text::new(""),
        TextFont { font_size: FontSize::Px(13.0), ..default() },
        TextColor(Color::srgb(0.92, 0.92, 0.92)),
        HudText,
    ));
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

/// Writes the HUD and fills the timeline to the current time.
pub fn update_hud(
    interaction: Option<NonSend<Interaction>>,
    (viewed, transport): (Res<Viewed>, Res<Transport>),
    timer: Res<StepTimer>,
    hand: Res<MouseHand>,
    (task, xr): (Option<Res<crate::task::ChessboardTask>>, Res<crate::xr_hands::XrHands>),
    mut text: Query<&mut Text, With<HudText>>,
    mut fill: Query<&mut Node, With<TimelineFill>>,
) {
    let Some(interaction) = interaction else { return };
    let world = interaction.world();
    let t = world.time();
    let bones: HashSet<_> = world.contacts().iter().map(|c| (c.hand, c.bone)).collect();
    let end = transport.end.map_or(String::new(), |e| format!(" / {e:.3}"));
    let state = match interaction.stopped() {
        Some(Stopped::Failed(e)) => format!("STOPPED: {e}"),
        Some(Stopped::Finished) => "finished".to_string(),
        None if transport.end.is_some_and(|e| t >= e - 1e-6) => "at the end".to_string(),
        None if transport.paused => "paused".to_string(),
        None => format!("playing {}x", transport.speed()),
    };
    let mut lines = vec![
        format!("{} | method {}", viewed.source.name(), viewed.method.name()),
        format!("t {t:.3}{end} s | step {} | {state}", interaction.steps()),
        format!(
            "physics step {:.1} us, fixed tick {:.1} us (dt {} ms) | bones in contact {}",
            timer.mean_us,
            timer.tick_us,
            world.config().dt * 1000.0,
            bones.len()
        ),
        if transport.live {
            "live hands at 1x | Space pause  . step  Home restart  Tab skeleton".to_string()
        } else {
            "Space pause  . step  [ ] speed  <- -> 1 s  Home restart  Tab skeleton".to_string()
        },
        "drag orbit  wheel zoom  middle-drag pan".to_string(),
    ];
    if hand.active() {
        lines.push("hand: WASD move  E/Q up/down  right-drag move  Shift fine".to_string());
        lines.push(
            "      JL IK UO turn  G/H curl/open  1-5 finger (Shift opens)  T thumb".to_string(),
        );
    }
    if let Some(line) = xr.hud_line() {
        lines.push(line);
    }
    if let Some(feed) = viewed.source.leap_feed() {
        lines.push(leap_line(&feed.stats()));
    }
    if let Some(task) = task {
        lines.extend(task.hud_lines());
    }
    for mut text in &mut text {
        text.0 = lines.join("\n");
    }
    if let Some(end) = transport.end.filter(|e| *e > 0.0) {
        for mut node in &mut fill {
            node.width = Val::Percent((t / end * 100.0).clamp(0.0, 100.0) as f32);
        }
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

/// A left press on the timeline seeks there, and dragging scrubs.
///
/// The bar spans the window, or in stereo the left eye's half, where the
/// UI is laid out. A held button seeks again only when the cursor moves.
pub fn scrub_timeline(
    buttons: Res<ButtonInput<MouseButton>>,
    windows: Query<&Window, With<PrimaryWindow>>,
    stereo: Option<Res<crate::camera::Stereo>>,
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
