//! Keyboard input as a window sends it, for tests that drive the viewer's keys headless.

use bevy::input::ButtonState;
use bevy::input::keyboard::{Key, KeyboardInput, NativeKey};
use bevy::prelude::*;

/// Writes one key event; the next `app.update()` reads it.
pub fn key(app: &mut App, key_code: KeyCode, state: ButtonState) {
    let logical_key = Key::Unidentified(NativeKey::Unidentified);
    let window = Entity::PLACEHOLDER;
    let event = KeyboardInput { key_code, logical_key, state, text: None, repeat: false, window };
    app.world_mut().write_message(event);
}

/// Presses and releases `key_code`, one frame each.
pub fn press(app: &mut App, key_code: KeyCode) {
    for state in [ButtonState::Pressed, ButtonState::Released] {
        key(app, key_code, state);
        app.update();
    }
}
