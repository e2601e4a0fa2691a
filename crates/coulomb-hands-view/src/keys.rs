//! Every key and mouse binding of the viewer, in one table: the systems
//! read their keys from it, the HUD writes its key lines from it, and the
//! book's key list is generated from it ([`markdown`], checked by a test).

use bevy::prelude::{ButtonInput, KeyCode};

/// What a binding belongs to: one HUD line each.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Group {
    /// Pause, step, speed, seek, restart, and what is drawn.
    Playback,
    /// The orbit camera.
    Camera,
    /// The mouse hand's palm.
    Hand,
    /// The mouse hand's fingers and turn.
    Fingers,
    /// The chessboard task.
    Task,
}

/// One binding: its keys (a pair is +/−, as W/S), how the HUD and the book
/// name it, and what it does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Binding {
    /// The keys, if keys (none for the mouse's).
    pub keys: &'static [KeyCode],
    /// The HUD's words for it.
    pub hud: &'static str,
    /// The book's name for the input.
    pub input: &'static str,
    /// What it does, for the book.
    pub does: &'static str,
    /// Its HUD line.
    pub group: Group,
    /// Off with live hands, which have no future and play at 1×.
    pub replayed_only: bool,
}

impl Binding {
    /// Whether one of its keys went down this frame.
    pub fn just_pressed(&self, keys: &ButtonInput<KeyCode>) -> bool {
        keys.any_just_pressed(self.keys.iter().copied())
    }

    /// Whether one of its keys is held now.
    pub fn held(&self, keys: &ButtonInput<KeyCode>) -> bool {
        keys.any_pressed(self.keys.iter().copied())
    }

    /// A pair's direction held now: +1 for the first key, −1 for the
    /// second, 0 for both or neither.
    pub fn axis(&self, keys: &ButtonInput<KeyCode>) -> f32 {
        let held = |i: usize| self.keys.get(i).is_some_and(|k| keys.pressed(*k));
        f32::from(u8::from(held(0))) - f32::from(u8::from(held(1)))
    }
}

use Group::{Camera, Fingers, Hand, Playback, Task};
use KeyCode as K;

const fn binding(
    keys: &'static [KeyCode],
    hud: &'static str,
    does: &'static str,
    group: Group,
) -> Binding {
    Binding { keys, hud, input: hud, does, group, replayed_only: false }
}

/// Space: pause or play.
pub const PAUSE: Binding =
    Binding { input: "Space", ..binding(&[K::Space], "Space pause", "pause or play", Playback) };
/// `.`: one physics step, paused.
pub const STEP: Binding = Binding {
    input: ".",
    ..binding(&[K::Period], ". step", "one physics step, then paused", Playback)
};
/// `[` and `]`: half and double speed.
pub const SPEED: Binding = Binding {
    input: "[ / ]",
    replayed_only: true,
    ..binding(
        &[K::BracketLeft, K::BracketRight],
        "[ ] speed",
        "half / double speed (1/16× to 16×)",
        Playback,
    )
};
/// ← and →: back and on by a second.
pub const SEEK: Binding = Binding {
    input: "← / →",
    replayed_only: true,
    ..binding(
        &[K::ArrowLeft, K::ArrowRight],
        "<- -> 1 s",
        "back / on by a second (back replays from t = 0)",
        Playback,
    )
};
/// Home: from t = 0 again.
pub const RESTART: Binding = Binding {
    input: "Home",
    ..binding(&[K::Home], "Home restart", "restart from t = 0", Playback)
};
/// A click or drag on the timeline: go to that time.
pub const TIMELINE: Binding = Binding {
    input: "click or drag the timeline",
    replayed_only: true,
    ..binding(&[], "", "go to that time (a run with an end)", Playback)
};
/// Tab: the raw tracked skeleton.
pub const SKELETON: Binding = Binding {
    input: "Tab",
    ..binding(&[K::Tab], "Tab skeleton", "show or hide the raw tracked skeleton", Playback)
};
/// Left-drag: turn the camera.
pub const ORBIT: Binding = Binding {
    input: "left-drag",
    ..binding(&[], "drag orbit", "turn the camera about what it looks at", Camera)
};
/// The wheel: zoom.
pub const ZOOM: Binding = Binding { input: "wheel", ..binding(&[], "wheel zoom", "zoom", Camera) };
/// Middle-drag: pan.
pub const PAN: Binding =
    Binding { input: "middle-drag", ..binding(&[], "middle-drag pan", "pan", Camera) };
/// F: frame the run again.
pub const FRAME: Binding =
    Binding { input: "F", ..binding(&[K::KeyF], "F frame", "frame the whole run again", Camera) };
/// W/S: palm away from / towards the camera.
pub const AWAY: Binding = Binding {
    input: "W / S",
    ..binding(&[K::KeyW, K::KeyS], "WASD move", "palm away from / towards the camera", Hand)
};
/// D/A: palm right / left.
pub const SIDEWAYS: Binding =
    Binding { input: "D / A", ..binding(&[K::KeyD, K::KeyA], "", "palm right / left", Hand) };
/// E/Q: palm up / down.
pub const UP: Binding = Binding {
    input: "E / Q",
    ..binding(&[K::KeyE, K::KeyQ], "E/Q up/down", "palm up / down", Hand)
};
/// Right-drag: palm across the view.
pub const DRAG: Binding = Binding {
    input: "right-drag",
    ..binding(&[], "right-drag move", "palm across the view", Hand)
};
/// Shift: slow, fine motion (and opens a finger with 1–5).
pub const FINE: Binding = Binding {
    input: "Shift",
    ..binding(&[K::ShiftLeft, K::ShiftRight], "Shift fine", "slow, fine motion", Hand)
};
/// J/L: turn the palm left / right (yaw).
pub const YAW: Binding = Binding {
    input: "J / L",
    ..binding(&[K::KeyJ, K::KeyL], "JL IK UO turn", "turn the palm: yaw", Fingers)
};
/// I/K: pitch.
pub const PITCH: Binding =
    Binding { input: "I / K", ..binding(&[K::KeyI, K::KeyK], "", "turn the palm: pitch", Fingers) };
/// O/U: roll.
pub const ROLL: Binding =
    Binding { input: "O / U", ..binding(&[K::KeyO, K::KeyU], "", "turn the palm: roll", Fingers) };
/// G/H: curl / open all fingers.
pub const CURL: Binding = Binding {
    input: "G / H",
    ..binding(&[K::KeyG, K::KeyH], "G/H curl/open", "curl / open all fingers", Fingers)
};
/// 1–5: curl one finger, thumb first (Shift opens it).
pub const FINGER: Binding = Binding {
    input: "1 … 5",
    ..binding(
        &[K::Digit1, K::Digit2, K::Digit3, K::Digit4, K::Digit5],
        "1-5 finger (Shift opens)",
        "curl one finger, thumb first (with Shift, open it)",
        Fingers,
    )
};
/// T: oppose the thumb, or bring it back.
pub const THUMB: Binding = Binding {
    input: "T",
    ..binding(&[K::KeyT], "T thumb", "oppose the thumb, or bring it back", Fingers)
};
/// Enter: end the chessboard trial.
pub const FINISH: Binding = Binding {
    input: "Enter",
    ..binding(&[K::Enter, K::NumpadEnter], "", "end the chessboard trial and start the next", Task)
};

/// The table, in the HUD's and the book's order.
pub const ALL: [Binding; 23] = [
    PAUSE, STEP, SPEED, SEEK, RESTART, TIMELINE, SKELETON, ORBIT, ZOOM, PAN, FRAME, AWAY, SIDEWAYS,
    UP, DRAG, FINE, YAW, PITCH, ROLL, CURL, FINGER, THUMB, FINISH,
];

/// The HUD's line of `group`'s bindings (with live hands, without those
/// that are off).
pub fn hud_line(group: Group, live: bool) -> String {
    let shown = ALL.iter().filter(|b| b.group == group && !b.hud.is_empty());
    let words: Vec<&str> = shown.filter(|b| !(live && b.replayed_only)).map(|b| b.hud).collect();
    words.join("  ")
}

/// The book's key list: a Markdown table of every binding.
pub fn markdown() -> String {
    let mut out = String::from("| input | does |\n|---|---|\n");
    for b in ALL {
        let live = if b.replayed_only { " (not with live hands)" } else { "" };
        out += &format!("| {} | {}{live} |\n", b.input, b.does);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::{Path, PathBuf};

    #[test]
    fn the_hud_lines_come_from_the_table_and_leave_out_what_live_hands_cannot_do() {
        let replayed = hud_line(Playback, false);
        let all = "Space pause  . step  [ ] speed  <- -> 1 s  Home restart  Tab skeleton";
        assert_eq!(replayed, all);
        assert_eq!(hud_line(Playback, true), "Space pause  . step  Home restart  Tab skeleton");
        assert_eq!(hud_line(Camera, false), "drag orbit  wheel zoom  middle-drag pan  F frame");
        // No key is bound twice.
        let mut all: Vec<KeyCode> = ALL.iter().flat_map(|b| b.keys.iter().copied()).collect();
        let count = all.len();
        all.sort_by_key(|k| format!("{k:?}"));
        all.dedup();
        assert_eq!(all.len(), count, "a key bound twice");
    }

    /// README.md and the book's pages.
    fn docs() -> Vec<PathBuf> {
        fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
            for entry in std::fs::read_dir(dir).into_iter().flatten().flatten() {
                let path = entry.path();
                if path.is_dir() {
                    walk(&path, out);
                } else if path.extension().is_some_and(|e| e == "md") {
                    out.push(path);
                }
            }
        }
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let mut out = vec![root.join("README.md")];
        walk(&root.join("docs/book/src"), &mut out);
        out
    }

    /// The book's key list is this table's; `UPDATE_KEYS=1` rewrites it.
    #[test]
    fn the_docs_key_list_is_generated_from_the_table() {
        const BEGIN: &str = "<!-- keys:begin -->\n";
        const END: &str = "<!-- keys:end -->";
        let mut found = 0;
        for path in docs() {
            let text = std::fs::read_to_string(&path).expect("readable");
            let Some(start) = text.find(BEGIN).map(|i| i + BEGIN.len()) else { continue };
            let end = start + text[start..].find(END).expect("a keys:end marker");
            found += 1;
            if text[start..end] == markdown() {
                continue;
            }
            if std::env::var_os("UPDATE_KEYS").is_some() {
                let fresh = format!("{}{}{}", &text[..start], markdown(), &text[end..]);
                std::fs::write(&path, fresh).expect("written");
            } else {
                panic!("{}: the key list is stale; run with UPDATE_KEYS=1", path.display());
            }
        }
        assert!(found > 0, "no page lists the keys between {BEGIN:?} and {END:?}");
    }
}
