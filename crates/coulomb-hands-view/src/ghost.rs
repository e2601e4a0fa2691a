//! The captured object as a ghost beside the simulated one, while a
//! hand–object capture plays: the capture's own mesh, light blue and
//! see-through, at the pose the capture gives for the physics time. Where
//! the two part is what the replay gets wrong (the book's
//! `science/captures.md`), so the HUD gives their distance too.
//!
//! The ghost is no body: nothing touches it, and it follows the capture
//! alone, so a seek or restart (which rebuilds the world from t = 0) only
//! moves it to the time's pose.

use crate::hud::{HudLines, HudSection};
use crate::sets::ViewerSystems;
use crate::source::Source;
use crate::transport::Viewed;
use bevy::light::NotShadowCaster;
use bevy::prelude::*;
use coulomb_hands_bevy::convert;
use coulomb_hands_bevy::prelude::*;

/// The ghost's colour: a light blue, unlike the objects' saturated hues and
/// the skin-toned hand, and 35 % opaque, so the simulated object and the
/// hand's fingers show through it.
pub const GHOST: Color = Color::srgba(0.62, 0.80, 1.0, 0.35);

/// The captured object's drawn ghost (the one entity there is while a
/// capture plays).
#[derive(Component, Debug, Clone, Copy)]
pub struct Ghost;

/// Spawns the ghost when a capture plays, and puts it at the captured pose
/// of the physics time each frame; removes it when the source is not a
/// capture.
pub fn place_ghost(
    viewed: Res<Viewed>,
    physics: Option<Res<HandPhysics>>,
    mut ghosts: Query<(Entity, &mut Transform), With<Ghost>>,
    mut commands: Commands,
) {
    let (Some(capture), Some(physics)) = (viewed.source.captured(), physics) else {
        ghosts.iter().for_each(|(e, _)| commands.entity(e).despawn());
        return;
    };
    let (position, rotation) = capture.pose_at(physics.world().time());
    let place = convert::transform(position, rotation);
    match ghosts.iter_mut().next() {
        Some((_, mut transform)) => *transform = place,
        None => {
            commands.spawn((Ghost, place, Visibility::default()));
        }
    }
}

/// Gives a new ghost the capture's mesh, see-through: it casts no shadow,
/// which would darken the table under an object that is not there.
pub fn dress_ghost(
    viewed: Res<Viewed>,
    ghosts: Query<Entity, Added<Ghost>>,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
    mut commands: Commands,
) {
    let Some(capture) = viewed.source.captured() else { return };
    for entity in &ghosts {
        let mesh = crate::shapes::faceted(&capture.mesh.vertices, &capture.mesh.triangles);
        let material = StandardMaterial {
            base_color: GHOST,
            alpha_mode: AlphaMode::Blend,
            perceptual_roughness: 0.8,
            ..default()
        };
        let look = (Mesh3d(meshes.add(mesh)), MeshMaterial3d(materials.add(material)));
        commands.entity(entity).insert((look, NotShadowCaster));
    }
}

/// The HUD's capture lines: what the ghost is, how far the simulated
/// object is from it (between their origins, as `replay` measures a
/// frame's translation error), and the capture's credit.
pub fn hud_lines(
    viewed: Res<Viewed>,
    physics: Option<Res<HandPhysics>>,
    mut hud: ResMut<HudLines>,
) {
    let (Some(capture), Some(physics)) = (viewed.source.captured(), physics) else { return };
    let world = physics.world();
    let (captured, _) = capture.pose_at(world.time());
    // A capture's world has one object: the captured one's simulated twin.
    let state = world.object_ids().next().and_then(|id| world.object_state(id).ok());
    let error = state.map_or(String::new(), |s| {
        format!(" | translation error {:.1} mm", (s.position - captured).length() * 1e3)
    });
    let mut lines = vec![format!("ghost (light blue): the captured object{error}")];
    if let Some(credit) = credit(&viewed.source) {
        lines.extend(wrap(&format!("capture: {credit}"), CREDIT_WIDTH));
    }
    hud.set(HudSection::Capture, lines);
}

/// The credit's line length (characters): TACO's note, 150 characters,
/// would run out of a 1280-pixel window on one line.
const CREDIT_WIDTH: usize = 90;

/// `text` in lines of at most `width` characters, broken between words
/// (a longer word has a line of its own); the lines after the first are
/// indented.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split_whitespace() {
        let fits = |line: &&mut String| line.chars().count() + 1 + word.chars().count() <= width;
        if let Some(line) = lines.last_mut().filter(fits) {
            line.push(' ');
            line.push_str(word);
        } else if lines.is_empty() {
            lines.push(word.to_string());
        } else {
            lines.push(format!("  {word}"));
        }
    }
    lines
}

/// The capture's credit, if its file gives one.
fn credit(source: &Source) -> Option<&str> {
    match source {
        Source::Capture { credit, .. } => credit.as_deref(),
        _ => None,
    }
}

/// The ghost's systems (they expect [`Viewed`] inserted). Headless apps
/// leave out [`dress_ghost`], which needs a renderer's assets: the ghost
/// is then placed, not drawn.
#[derive(Debug, Clone, Copy, Default)]
pub struct GhostPlugin {
    /// Whether the ghost is drawn.
    pub draw: bool,
}

impl Plugin for GhostPlugin {
    fn build(&self, app: &mut App) {
        crate::sets::configure(app);
        app.init_resource::<HudLines>()
            .add_systems(Update, place_ghost.in_set(ViewerSystems::Draw))
            .add_systems(Update, hud_lines.in_set(ViewerSystems::HudLines));
        if self.draw {
            app.add_systems(Update, dress_ghost.after(place_ghost).in_set(ViewerSystems::Draw));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_credit_is_wrapped_between_words_and_keeps_every_word() {
        let credit = "capture: TACO (Liu et al., CVPR 2024, 'TACO: Benchmarking Generalizable \
                      Bimanual Tool-ACtion-Object Understanding'), sequence taco_20231104_017, \
                      licensed CC BY 4.0";
        let lines = wrap(credit, 40);
        assert!(lines.len() > 1 && lines.iter().all(|l| l.chars().count() <= 40), "{lines:?}");
        assert!(lines[1..].iter().all(|l| l.starts_with("  ")), "{lines:?}");
        let words = |t: &str| t.split_whitespace().map(str::to_string).collect::<Vec<_>>();
        assert_eq!(words(&lines.join(" ")), words(credit));
        assert_eq!(wrap("short", 40), ["short"]);
    }
}
