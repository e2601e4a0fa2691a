//! The order of the viewer's systems in a frame, one set per layer.

use bevy::prelude::*;

/// The viewer's layers, in the order they run. `Input` and `Transport` run
/// in `PreUpdate` (after Bevy's input), so a seek or restart is applied
/// before the plugin prepares the frame's physics steps; the rest in
/// `Update`, after the steps.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ViewerSystems {
    /// Keys, the timeline and Enter become transport messages.
    Input,
    /// The transport applies them: pause, speed, seek, restart.
    Transport,
    /// The viewer's own hands are posed (the mouse hand).
    Drive,
    /// The camera is framed and moved.
    Camera,
    /// The scene, hands, arrows and board are drawn, and sounds played.
    Draw,
    /// Each module writes its HUD lines.
    HudLines,
    /// The HUD draws them.
    Hud,
    /// Screenshots, and quitting when done.
    Output,
}

/// Orders the sets (the plugin of each module puts its systems in one).
pub fn configure(app: &mut App) {
    app.configure_sets(
        PreUpdate,
        (ViewerSystems::Input, ViewerSystems::Transport).chain().after(bevy::input::InputSystems),
    )
    .configure_sets(
        Update,
        (
            ViewerSystems::Drive,
            ViewerSystems::Camera,
            ViewerSystems::Draw,
            ViewerSystems::HudLines,
            ViewerSystems::Hud,
            ViewerSystems::Output,
        )
            .chain(),
    );
}
