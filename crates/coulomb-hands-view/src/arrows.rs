//! Arrows at the contacts (Fig. 1.1), and the raw tracked skeleton.
//!
//! - **Red:** each contact's force on the object, from its point C, at
//!   [`FORCE_SCALE`] (3 cm per newton), clipped at [`MAX_ARROW`].
//! - **Yellow:** the hand's motion at each contact: from the bone's point p,
//!   where p will be in [`MOTION_SCALE`] (0.1 s) at its current velocity.
//! - **Cyan** (Tab): the tracked skeleton, as the physics sees it, which
//!   may sink into objects where the drawn hand does not.
//!
//! Gizmos are drawn over the scene, so arrows inside an object stay visible.

use crate::keys;
use crate::sets::ViewerSystems;
use bevy::prelude::*;
use coulomb_hands::hand::{BoneShape, HandId, HandPose};
use coulomb_hands::scene::ObjectId;
use coulomb_hands_bevy::convert::to_bevy_vec3;
use coulomb_hands_bevy::prelude::*;
use std::collections::HashMap;

/// Arrow length per newton of contact force (m/N).
pub const FORCE_SCALE: f32 = 0.03;
/// Arrow length per m/s of hand motion (s).
pub const MOTION_SCALE: f32 = 0.1;
/// Longer arrows are clipped to this length (m).
pub const MAX_ARROW: f32 = 0.5;
/// The force arrows' colour.
pub const FORCE_RED: Color = Color::srgb(1.0, 0.0, 0.0);
/// The motion arrows' colour.
pub const MOTION_YELLOW: Color = Color::srgb(1.0, 0.9, 0.0);
/// The skeleton's colour.
const SKELETON_CYAN: Color = Color::srgb(0.0, 0.9, 1.0);
/// Slower contact points get no motion arrow (m/s).
const STILL: f32 = 0.002;

/// Whether the raw skeleton is shown.
#[derive(Resource, Debug, Default, Clone, Copy)]
pub struct ShowSkeleton(pub bool);

/// A contact: its hand, bone (index) and object.
type ContactKey = (HandId, usize, ObjectId);

/// The contacts' bone points when last drawn, for their velocities.
#[derive(Resource, Debug, Default)]
pub struct ContactMotion {
    /// The world time (s) the points are from.
    at: f64,
    /// Per contact: the point p then.
    points: HashMap<ContactKey, Vec3>,
    /// Per contact: p's velocity (m/s), kept while paused.
    velocities: HashMap<ContactKey, Vec3>,
}

/// Gizmos on top of the scene, in thicker lines.
pub fn setup_gizmos(mut store: ResMut<GizmoConfigStore>) {
    let (config, _) = store.config_mut::<DefaultGizmoConfigGroup>();
    config.depth_bias = -1.0;
    config.line.width = 3.0;
}

/// Tab shows or hides the skeleton.
pub fn toggle_skeleton(input: Res<ButtonInput<KeyCode>>, mut show: ResMut<ShowSkeleton>) {
    if keys::SKELETON.just_pressed(&input) {
        show.0 = !show.0;
    }
}

/// A vector drawn from `from`, `scale` long per unit, clipped.
fn arrow(gizmos: &mut Gizmos, from: Vec3, v: Vec3, scale: f32, color: Color) {
    let v = (v * scale).clamp_length_max(MAX_ARROW);
    if v.length() > 1e-4 {
        gizmos.arrow(from, from + v, color).with_tip_length(0.01_f32.min(v.length() / 2.0));
    }
}

/// Draws the force and motion arrows of every contact.
pub fn draw_arrows(
    physics: Option<Res<HandPhysics>>,
    mut replaced: MessageReader<HandPhysicsReplaced>,
    mut motion: ResMut<ContactMotion>,
    mut gizmos: Gizmos,
) {
    let Some(physics) = physics else { return };
    if replaced.read().last().is_some() {
        *motion = ContactMotion::default();
    }
    let world = physics.world();
    let t = world.time();
    let moved = t > motion.at;
    if moved || t < motion.at {
        let elapsed = (t - motion.at) as f32;
        let mut points = HashMap::new();
        for c in world.contacts() {
            let key = (c.hand, c.bone.index(), c.object);
            let p = to_bevy_vec3(c.bone_point);
            if let (true, Some(before)) = (moved, motion.points.get(&key).copied()) {
                motion.velocities.insert(key, (p - before) / elapsed);
            }
            points.insert(key, p);
        }
        motion.velocities.retain(|k, _| points.contains_key(k));
        (motion.points, motion.at) = (points, t);
    }
    for c in world.contacts() {
        arrow(&mut gizmos, to_bevy_vec3(c.point), to_bevy_vec3(c.force), FORCE_SCALE, FORCE_RED);
        let key = (c.hand, c.bone.index(), c.object);
        let v = motion.velocities.get(&key).copied().unwrap_or_default();
        if v.length() > STILL {
            arrow(&mut gizmos, to_bevy_vec3(c.bone_point), v, MOTION_SCALE, MOTION_YELLOW);
        }
    }
}

/// Draws each tracked hand's bones as lines: the palm's box and each
/// phalanx's axis, joint to joint.
pub fn draw_skeleton(
    physics: Option<Res<HandPhysics>>,
    show: Res<ShowSkeleton>,
    mut gizmos: Gizmos,
) {
    let Some(physics) = physics.filter(|_| show.0) else { return };
    let world = physics.world();
    let poses = (0..world.hand_count()).filter_map(|i| world.hand_pose(HandId(i as u32)));
    poses.for_each(|pose: &HandPose| {
        for bone in coulomb_hands::hand::Bone::all() {
            match pose.bone(bone) {
                BoneShape::Palm(p) => {
                    let place = coulomb_hands_bevy::convert::transform(p.center, p.rotation);
                    let size = to_bevy_vec3(p.half_extents) * 2.0;
                    gizmos.cube(place.with_scale(size), SKELETON_CYAN);
                }
                BoneShape::Capsule(c) => {
                    gizmos.line(to_bevy_vec3(c.a), to_bevy_vec3(c.b), SKELETON_CYAN);
                }
            }
        }
    });
}

/// The arrows' and skeleton's systems.
#[derive(Debug, Clone, Copy, Default)]
pub struct ArrowsPlugin;

impl Plugin for ArrowsPlugin {
    fn build(&self, app: &mut App) {
        crate::sets::configure(app);
        app.init_resource::<ShowSkeleton>()
            .init_resource::<ContactMotion>()
            .add_systems(Startup, setup_gizmos)
            .add_systems(PreUpdate, toggle_skeleton.in_set(ViewerSystems::Input))
            .add_systems(Update, (draw_arrows, draw_skeleton).in_set(ViewerSystems::Draw));
    }
}
