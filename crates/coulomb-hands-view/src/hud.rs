//! The heads-up display: a panel of text lines, each written by the module
//! that owns what it says ([`HudLines`]), in the order of [`HudSection`].

use bevy::prelude::*;
use std::collections::BTreeMap;

/// Where a module's lines go on the HUD, top to bottom.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum HudSection {
    /// What runs, its time and state ([`crate::transport`]).
    Run,
    /// A capture's ghost and credit ([`crate::ghost`]).
    Capture,
    /// The physics step's cost ([`crate::timing`]).
    Timing,
    /// The playback's keys ([`crate::transport`]).
    Keys,
    /// The camera's keys ([`crate::camera`]).
    CameraKeys,
    /// The mouse hand's keys ([`crate::mouse_hand`]).
    MouseHand,
    /// Live hands' state ([`crate::xr_hands`], the Leap stream).
    LiveHands,
    /// The chessboard task ([`crate::task`]).
    Task,
}

/// The HUD's lines by section; each owner replaces its own every frame,
/// before [`crate::sets::ViewerSystems::Hud`] draws them.
#[derive(Resource, Debug, Default)]
pub struct HudLines(BTreeMap<HudSection, Vec<String>>);

impl HudLines {
    /// Sets `section`'s lines (none to clear it).
    pub fn set(&mut self, section: HudSection, lines: Vec<String>) {
        self.0.insert(section, lines);
    }

    /// The whole text, top to bottom.
    pub fn text(&self) -> String {
        self.0.values().flatten().cloned().collect::<Vec<_>>().join("\n")
    }
}

/// The HUD's text.
#[derive(Component)]
pub struct HudText;

/// The HUD's panel, top left.
pub fn spawn_hud(mut commands: Commands) {
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
}

/// Writes the lines into the panel.
pub fn draw_hud(lines: Res<HudLines>, mut text: Query<&mut Text, With<HudText>>) {
    let joined = lines.text();
    for mut text in &mut text {
        if text.0 != joined {
            text.0.clone_from(&joined);
        }
    }
}

/// The HUD's systems.
#[derive(Debug, Clone, Copy, Default)]
pub struct HudPlugin;

impl Plugin for HudPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<HudLines>()
            .add_systems(Startup, spawn_hud)
            .add_systems(Update, draw_hud.in_set(crate::sets::ViewerSystems::Hud));
    }
}
