//! An orbit camera: left-drag turns it about its focus, the wheel zooms,
//! middle-drag pans. It first frames the objects, or else the tracked hands.
//!
//! In stereo (§3.8.2) there are two cameras, one per half of the window,
//! side by side, each moved half the virtual camera distance (VCD) to its
//! side along the view's right axis. With image pass-through the VCD must
//! equal the tracker's camera distance (ICD), or the virtual objects sit at
//! the wrong depth against the real image.

use crate::head::HeadMount;
use bevy::camera::Viewport;
use bevy::core_pipeline::tonemapping::Tonemapping;
use bevy::input::mouse::{AccumulatedMouseMotion, AccumulatedMouseScroll, MouseScrollUnit};
use bevy::prelude::*;
use bevy::window::PrimaryWindow;
use coulomb_hands::hand::HandId;
use coulomb_hands_bevy::convert::{to_bevy_vec3, transform};
use coulomb_hands_bevy::interaction::Interaction;

/// Radians of turn per pixel of drag.
const TURN_PER_PIXEL: f32 = 0.005;
/// Zoom factor per wheel line.
const ZOOM_PER_LINE: f32 = 0.1;

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
            pitch: 0.55,
            distance: 0.55,
            framed: false,
        }
    }
}

/// Where the camera starts: yaw and pitch (degrees), distance (m).
#[derive(Resource, Debug, Clone, Copy, PartialEq)]
pub struct StartView {
    /// Turn about the vertical (°); 0 looks along +z, 90 along +x (from −x).
    pub yaw_deg: f32,
    /// Elevation above the horizontal (°).
    pub pitch_deg: f32,
    /// Distance from what is looked at (m).
    pub distance: f32,
}

impl std::str::FromStr for StartView {
    type Err = String;
    /// `YAW,PITCH,DISTANCE`, e.g. `90,20,0.5`.
    fn from_str(s: &str) -> Result<StartView, String> {
        let parts: Vec<f32> = s.split(',').map(|p| p.trim().parse().unwrap_or(f32::NAN)).collect();
        match parts[..] {
            [yaw_deg, pitch_deg, distance]
                if parts.iter().all(|p| p.is_finite())
                    && pitch_deg.abs() <= 80.0
                    && (0.1..=10.0).contains(&distance) =>
            {
                Ok(StartView { yaw_deg, pitch_deg, distance })
            }
            _ => Err(format!(
                "expected YAW_DEG,PITCH_DEG,DISTANCE_M with pitch within ±80° and distance \
                 0.1 to 10 m, got {s:?}"
            )),
        }
    }
}

/// Side-by-side stereo, with this virtual camera distance.
#[derive(Resource, Debug, Clone, Copy, PartialEq)]
pub struct Stereo {
    /// Between the two cameras (m).
    pub vcd: f32,
}

/// The average adult interpupillary distance (m).
pub const HUMAN_IPD: f32 = 0.063;
/// The distance between a Leap Motion controller's two cameras (m), the
/// VCD its image pass-through needs.
pub const LEAP_ICD: f32 = 0.040;

impl std::str::FromStr for Stereo {
    type Err = String;
    /// `ipd` (63 mm), `leap` (40 mm) or a distance in millimetres.
    fn from_str(s: &str) -> Result<Stereo, String> {
        let vcd = match s {
            "ipd" => HUMAN_IPD,
            "leap" => LEAP_ICD,
            mm => match mm.parse::<f32>() {
                Ok(mm) if mm.is_finite() && mm > 0.0 && mm <= 1000.0 => mm / 1000.0,
                _ => {
                    let why = "expected ipd (63 mm), leap (40 mm) or millimetres in (0, 1000]";
                    return Err(format!("{why}, got {s:?}"));
                }
            },
        };
        Ok(Stereo { vcd })
    }
}

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
    stereo: Option<Res<Stereo>>,
    head: Option<Res<HeadView>>,
) {
    let mut orbit = Orbit::default();
    if let Some(v) = start {
        (orbit.yaw, orbit.pitch) = (v.yaw_deg.to_radians(), v.pitch_deg.to_radians());
        orbit.distance = v.distance;
    }
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

/// Puts the focus on the objects' centre, or on the first tracked palm,
/// once there is one.
pub fn frame_view(interaction: Option<NonSend<Interaction>>, mut orbits: Query<&mut Orbit>) {
    let Some(interaction) = interaction else { return };
    let world = interaction.world();
    for mut orbit in orbits.iter_mut().filter(|o| !o.framed) {
        let objects: Vec<Vec3> = world
            .object_ids()
            .filter_map(|id| world.object_state(id).ok())
            .map(|s| to_bevy_vec3(s.position))
            .collect();
        let palm = (0..world.hand_count())
            .find_map(|i| world.hand_pose(HandId(i as u32)))
            .map(|p| to_bevy_vec3(p.palm.center));
        if !objects.is_empty() {
            orbit.focus = objects.iter().sum::<Vec3>() / objects.len() as f32;
        } else if let Some(palm) = palm {
            orbit.focus = palm;
        } else {
            continue;
        }
        orbit.framed = true;
    }
}

/// Turns, zooms and pans from the mouse.
pub fn orbit_camera(
    buttons: Res<ButtonInput<MouseButton>>,
    motion: Res<AccumulatedMouseMotion>,
    scroll: Res<AccumulatedMouseScroll>,
    scrubbing: Res<crate::hud::Scrubbing>,
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stereo_takes_the_presets_or_millimetres_and_refuses_others() {
        assert_eq!("ipd".parse::<Stereo>(), Ok(Stereo { vcd: 0.063 }));
        assert_eq!("leap".parse::<Stereo>(), Ok(Stereo { vcd: 0.040 }));
        assert_eq!("55".parse::<Stereo>(), Ok(Stereo { vcd: 0.055 }));
        for bad in ["0", "-5", "NaN", "inf", "eyes", "2000"] {
            assert!(bad.parse::<Stereo>().unwrap_err().contains("ipd"), "{bad}");
        }
    }

    #[test]
    fn a_start_view_is_yaw_pitch_distance_within_limits() {
        let v: StartView = "90,20,0.5".parse().expect("a view");
        assert_eq!(v, StartView { yaw_deg: 90.0, pitch_deg: 20.0, distance: 0.5 });
        for bad in ["90,20", "0,85,1", "0,0,0.01", "a,b,c", "0,0,NaN", "1,x,2,3", "1,2,0.5,"] {
            assert!(bad.parse::<StartView>().is_err(), "{bad}");
        }
    }
}
