//! An orbit camera: left-drag turns it about its focus, the wheel zooms,
//! middle-drag pans ([`crate::keys`]). It frames the whole run: the volume
//! the hands and objects take up from start to end ([`Framing`], worked out
//! before the first frame), and F frames it again. With no such volume (a
//! live scene with no objects) it frames the first tracked palm.
//!
//! In stereo (§3.8.2) there are two cameras, one per half of the window,
//! side by side, each moved half the virtual camera distance (VCD) to its
//! side along the view's right axis. With image pass-through the VCD must
//! equal the tracker's camera distance (ICD), or the virtual objects sit at
//! the wrong depth against the real image.

use crate::grasp_view::GraspSamples;
use crate::head::HeadMount;
use crate::keys;
use crate::sets::ViewerSystems;
use crate::source::{LoadError, Source};
use crate::transport::Scrubbing;
use bevy::camera::Viewport;
use bevy::core_pipeline::tonemapping::Tonemapping;
use bevy::input::mouse::{AccumulatedMouseMotion, AccumulatedMouseScroll, MouseScrollUnit};
use bevy::prelude::*;
use bevy::window::PrimaryWindow;
use coulomb_hands::hand::{BoneShape, HandId};
use coulomb_hands::pipeline::{InteractionWorld, Method};
use coulomb_hands_bevy::convert::{to_bevy_vec3, transform};
use coulomb_hands_bevy::prelude::*;

/// Radians of turn per pixel of drag.
const TURN_PER_PIXEL: f32 = 0.005;
/// Zoom factor per wheel line.
const ZOOM_PER_LINE: f32 = 0.1;
pub use crate::grasp_view::DEFAULT_PITCH;

/// Where the camera looks from.
#[derive(Component, Debug, Clone, Copy)]
pub struct Orbit {
    /// The point looked at (world, m).
    pub focus: Vec3,
    /// Turn about the vertical (rad); 0 looks along +z.
    pub yaw: f32,
    /// Elevation above the horizontal (rad).
    pub pitch: f32,
    /// Distance from the focus (m).
    pub distance: f32,
    /// Whether the focus has been put on what is viewed.
    framed: bool,
}

impl Orbit {
    /// The camera's transform.
    pub fn transform(&self) -> Transform {
        let back = Quat::from_euler(EulerRot::YXZ, self.yaw, self.pitch, 0.0) * Vec3::NEG_Z;
        Transform::from_translation(self.focus + back * self.distance)
            .looking_at(self.focus, Vec3::Y)
    }
}

impl Default for Orbit {
    fn default() -> Self {
        Orbit {
            focus: Vec3::new(0.0, 0.05, 0.0),
            yaw: 0.0,
            pitch: DEFAULT_PITCH,
            distance: 0.55,
            framed: false,
        }
    }
}

/// Where the camera starts: yaw and pitch (degrees), and a distance (m),
/// or the one that frames the run.
#[derive(Resource, Debug, Clone, Copy, PartialEq)]
pub struct StartView {
    /// Turn about the vertical (°); 0 looks along +z, 90 along +x (from −x).
    pub yaw_deg: f32,
    /// Elevation above the horizontal (°).
    pub pitch_deg: f32,
    /// Distance from what is looked at (m); `None` for the framing's.
    pub distance: Option<f32>,
}

impl std::str::FromStr for StartView {
    type Err = String;
    /// `YAW,PITCH[,DISTANCE]`, e.g. `90,20,0.5` or `90,20`.
    fn from_str(s: &str) -> Result<StartView, String> {
        let parts: Vec<f32> = s.split(',').map(|p| p.trim().parse().unwrap_or(f32::NAN)).collect();
        let fits = |pitch: f32, distance: Option<f32>| {
            parts.iter().all(|p| p.is_finite())
                && pitch.abs() <= 80.0
                && distance.is_none_or(|d| (0.1..=10.0).contains(&d))
        };
        match parts[..] {
            [yaw_deg, pitch_deg] if fits(pitch_deg, None) => {
                Ok(StartView { yaw_deg, pitch_deg, distance: None })
            }
            [yaw_deg, pitch_deg, d] if fits(pitch_deg, Some(d)) => {
                Ok(StartView { yaw_deg, pitch_deg, distance: Some(d) })
            }
            _ => Err(format!(
                "expected YAW_DEG,PITCH_DEG[,DISTANCE_M] with pitch within ±80° and distance \
                 0.1 to 10 m, got {s:?}"
            )),
        }
    }
}

pub use crate::stereo::{HUMAN_IPD, LEAP_ICD, Stereo};

/// The camera is the eyes of this head (§3.8.1): a head-mounted
/// recording is seen from where it was made, and the mouse does not move it.
#[derive(Resource, Debug, Clone, Copy)]
pub struct HeadView(pub HeadMount);

impl HeadView {
    /// The camera's transform: at the eyes, looking along the head's −z.
    pub fn transform(&self) -> Transform {
        let (position, rotation) = self.0.eyes();
        transform(position, rotation)
    }
}

/// One camera of a stereo pair: how far it sits right of the view's centre
/// (m, negative for the left eye).
#[derive(Component, Debug, Clone, Copy)]
pub struct Eye(pub f32);

/// The camera, or with [`Stereo`] the two eyes' cameras (the left one draws
/// the HUD), with a tone mapping that needs no lookup tables.
/// A head-mounted view has no orbit: its eyes stay at the head.
pub fn spawn_camera(
    mut commands: Commands,
    start: Option<Res<StartView>>,
    framing: Option<Res<Framing>>,
    stereo: Option<Res<Stereo>>,
    head: Option<Res<HeadView>>,
) {
    let orbit = start_orbit(framing.as_deref(), start.as_deref());
    let view = head.as_deref().map_or_else(|| orbit.transform(), HeadView::transform);
    let eyes = match stereo.as_deref() {
        None => vec![None],
        Some(s) => vec![Some(Eye(-s.vcd / 2.0)), Some(Eye(s.vcd / 2.0))],
    };
    for (order, eye) in eyes.into_iter().enumerate() {
        let mut transform = view;
        let camera = Camera { order: order as isize, ..default() };
        let mut entity = commands.spawn((Camera3d::default(), camera, Tonemapping::AcesFitted));
        if let Some(eye) = eye {
            transform.translation += transform.right() * eye.0;
            entity.insert(eye);
        }
        entity.insert(transform);
        if head.is_none() {
            entity.insert(orbit);
        }
        if order == 0 && stereo.is_some() {
            entity.insert(IsDefaultUiCamera);
        }
    }
}

/// The orbit the camera starts from: the start view's angles (or those
/// that show the run's grasps, or the default's), looking at the run's
/// volume from where it fits the view (or from the start view's distance,
/// if given).
fn start_orbit(framing: Option<&Framing>, start: Option<&StartView>) -> Orbit {
    let mut orbit = Orbit::default();
    if let Some(f) = framing {
        (orbit.focus, orbit.distance, orbit.framed) = (f.center, f.distance(), true);
        if let Some((yaw, pitch)) = f.view {
            (orbit.yaw, orbit.pitch) = (yaw, pitch);
        }
    }
    if let Some(v) = start {
        (orbit.yaw, orbit.pitch) = (v.yaw_deg.to_radians(), v.pitch_deg.to_radians());
        orbit.distance = v.distance.unwrap_or(orbit.distance);
    }
    orbit
}

/// Each eye draws into its half of the window.
pub fn fit_eyes(
    windows: Query<&Window, With<PrimaryWindow>>,
    mut eyes: Query<(&Eye, &mut Camera)>,
) {
    let Ok(window) = windows.single() else { return };
    let size = window.physical_size();
    let half = UVec2::new(size.x / 2, size.y);
    if half.x == 0 || half.y == 0 {
        return;
    }
    for (eye, mut camera) in &mut eyes {
        let x = if eye.0 < 0.0 { 0 } else { half.x };
        let position = UVec2::new(x, 0);
        let fits = camera
            .viewport
            .as_ref()
            .is_some_and(|v| (v.physical_position, v.physical_size) == (position, half));
        if !fits {
            camera.viewport =
                Some(Viewport { physical_position: position, physical_size: half, ..default() });
        }
    }
}

/// The volume a run's hands and objects take up from start to end: a
/// sphere about their bounding box, which the camera keeps in view; and
/// the direction that shows its grasps ([`crate::grasp_view`]).
#[derive(Resource, Debug, Clone, Copy, PartialEq)]
pub struct Framing {
    /// The box's centre (world, m).
    pub center: Vec3,
    /// Half the box's diagonal (m).
    pub radius: f32,
    /// Yaw and pitch (rad) from which the most of the hands' pressing
    /// contacts are in sight; `None` for a run with none.
    pub view: Option<(f32, f32)>,
}

/// Steps between two looks at the run (10 ms at the default 1 ms step).
const FRAMING_EVERY: usize = 10;
/// The camera's vertical field of view (Bevy's default perspective).
const FOV: f32 = std::f32::consts::FRAC_PI_4;
/// Room around the framed sphere, for the HUD and the timeline.
const MARGIN: f32 = 1.15;

impl Framing {
    /// The volume of `source`'s run under `method`, played headlessly to its
    /// end on a world of its own (runs are deterministic, so it is the run
    /// the viewer will show). A run with no end (a scene, live hands) is
    /// framed as it starts. `None` when there is nothing in it yet.
    pub fn of_run(source: &Source, method: Method) -> Result<Option<Framing>, LoadError> {
        Ok(Framing::survey(source, method)?.0)
    }

    /// [`Framing::of_run`], with the contacts its view was chosen by.
    pub fn survey(
        source: &Source,
        method: Method,
    ) -> Result<(Option<Framing>, GraspSamples), LoadError> {
        let mut physics = source.build(method)?;
        let dt = f64::from(physics.world().config().dt);
        let steps = source.duration().map_or(0, |d| (d / dt).round() as usize);
        let mut bounds = Bounds::default();
        let mut grasps = GraspSamples::default();
        bounds.add_world(physics.world());
        if let Some(capture) = source.captured() {
            // The ghost goes where the captured object went, which the
            // simulated one may not follow.
            let reach = capture.mesh.vertices.iter().map(|v| v.length()).fold(0.0, f32::max);
            capture.poses.iter().for_each(|(p, _)| bounds.add(to_bevy_vec3(*p), reach));
        }
        for i in 0..steps {
            if !physics.step() {
                break;
            }
            if i % FRAMING_EVERY == 0 {
                bounds.add_world(physics.world());
                grasps.add(physics.world());
            }
        }
        bounds.add_world(physics.world());
        let framing = bounds.framing().map(|f| {
            let center = coulomb_hands_bevy::convert::to_core_vec3(f.center);
            Framing { view: grasps.view(center, f.distance()), ..f }
        });
        Ok((framing, grasps))
    }

    /// How far from its centre the camera sees the whole sphere (m).
    pub fn distance(&self) -> f32 {
        (self.radius * MARGIN / (FOV / 2.0).sin()).clamp(0.1, 10.0)
    }
}

/// A bounding box that grows.
#[derive(Debug, Clone, Copy)]
struct Bounds {
    min: Vec3,
    max: Vec3,
}

impl Default for Bounds {
    fn default() -> Self {
        Bounds { min: Vec3::INFINITY, max: Vec3::NEG_INFINITY }
    }
}

impl Bounds {
    fn add(&mut self, p: Vec3, r: f32) {
        if p.is_finite() {
            (self.min, self.max) = (self.min.min(p - r), self.max.max(p + r));
        }
    }

    /// The objects' colliders and the tracked hands' bones.
    fn add_world(&mut self, world: &InteractionWorld) {
        for id in world.object_ids() {
            let Some(body) = world.object_body(id) else { continue };
            let Some(body) = world.physics().bodies.get(body) else { continue };
            for handle in body.colliders() {
                let Some(collider) = world.physics().colliders.get(*handle) else { continue };
                let aabb = collider.compute_aabb();
                self.add(to_bevy_vec3(aabb.mins), 0.0);
                self.add(to_bevy_vec3(aabb.maxs), 0.0);
            }
        }
        for i in 0..world.hand_count() {
            let Some(pose) = world.hand_pose(HandId(i as u32)) else { continue };
            for bone in coulomb_hands::hand::Bone::all() {
                match pose.bone(bone) {
                    BoneShape::Palm(p) => {
                        self.add(to_bevy_vec3(p.center), p.half_extents.length());
                    }
                    BoneShape::Capsule(c) => {
                        self.add(to_bevy_vec3(c.a), c.radius);
                        self.add(to_bevy_vec3(c.b), c.radius);
                    }
                }
            }
        }
    }

    fn framing(&self) -> Option<Framing> {
        (self.min.cmple(self.max).all()).then(|| Framing {
            center: (self.min + self.max) / 2.0,
            radius: ((self.max - self.min).length() / 2.0).max(0.05),
            view: None,
        })
    }
}

/// With no [`Framing`], puts the focus on the first tracked palm once
/// there is one (live hands in a scene with no objects).
pub fn frame_palm(
    physics: Option<Res<HandPhysics>>,
    framing: Option<Res<Framing>>,
    mut orbits: Query<&mut Orbit>,
) {
    let (Some(physics), None) = (physics, framing) else { return };
    let world = physics.world();
    let palm = (0..world.hand_count())
        .find_map(|i| world.hand_pose(HandId(i as u32)))
        .map(|p| to_bevy_vec3(p.palm.center));
    let Some(palm) = palm else { return };
    for mut orbit in orbits.iter_mut().filter(|o| !o.framed) {
        (orbit.focus, orbit.framed) = (palm, true);
    }
}

/// F frames the run again, from the start view.
pub fn reframe(
    input: Res<ButtonInput<KeyCode>>,
    framing: Option<Res<Framing>>,
    start: Option<Res<StartView>>,
    mut orbits: Query<&mut Orbit>,
) {
    if !keys::FRAME.just_pressed(&input) {
        return;
    }
    let start = start_orbit(framing.as_deref(), start.as_deref());
    for mut orbit in &mut orbits {
        *orbit = start;
    }
}

/// Turns, zooms and pans from the mouse.
pub fn orbit_camera(
    buttons: Res<ButtonInput<MouseButton>>,
    motion: Res<AccumulatedMouseMotion>,
    scroll: Res<AccumulatedMouseScroll>,
    scrubbing: Res<Scrubbing>,
    mut cameras: Query<(&mut Orbit, &mut Transform, Option<&Eye>)>,
) {
    for (mut orbit, mut transform, eye) in &mut cameras {
        let d = motion.delta;
        if buttons.pressed(MouseButton::Left) && !scrubbing.0 {
            orbit.yaw -= d.x * TURN_PER_PIXEL;
            orbit.pitch = (orbit.pitch + d.y * TURN_PER_PIXEL).clamp(-1.4, 1.4);
        }
        if buttons.pressed(MouseButton::Middle) {
            let pan = (transform.right() * -d.x + transform.up() * d.y) * orbit.distance * 0.002;
            orbit.focus += pan;
        }
        // A touchpad scrolls in pixels, a wheel in lines (about 20 pixels).
        let lines = match scroll.unit {
            MouseScrollUnit::Line => scroll.delta.y,
            MouseScrollUnit::Pixel => scroll.delta.y / 20.0,
        };
        orbit.distance = (orbit.distance * (-lines * ZOOM_PER_LINE).exp()).clamp(0.1, 10.0);
        *transform = orbit.transform();
        if let Some(eye) = eye {
            let right = transform.right();
            transform.translation += right * eye.0;
        }
    }
}

/// The HUD's line of the camera's keys.
fn hud_line(mut hud: ResMut<crate::hud::HudLines>) {
    let line = keys::hud_line(keys::Group::Camera, false);
    hud.set(crate::hud::HudSection::CameraKeys, vec![line]);
}

/// The camera's systems (it expects the transport's plugin added).
#[derive(Debug, Clone, Copy, Default)]
pub struct CameraPlugin;

impl Plugin for CameraPlugin {
    fn build(&self, app: &mut App) {
        crate::sets::configure(app);
        app.add_systems(Startup, spawn_camera)
            .add_systems(
                Update,
                (frame_palm, reframe, orbit_camera, fit_eyes).chain().in_set(ViewerSystems::Camera),
            )
            .add_systems(Update, hud_line.in_set(ViewerSystems::HudLines));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_start_view_is_yaw_pitch_distance_within_limits() {
        let v: StartView = "90,20,0.5".parse().expect("a view");
        assert_eq!(v, StartView { yaw_deg: 90.0, pitch_deg: 20.0, distance: Some(0.5) });
        let framed: StartView = "-30, 10".parse().expect("a view at the framing's distance");
        assert_eq!(framed, StartView { yaw_deg: -30.0, pitch_deg: 10.0, distance: None });
        for bad in ["90", "0,85,1", "0,85", "0,0,0.01", "a,b,c", "0,0,NaN", "1,x,2,3", "1,2,0.5,"] {
            assert!(bad.parse::<StartView>().is_err(), "{bad}");
        }
    }
}
