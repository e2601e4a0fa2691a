//! Head-attached hands (§3.8.1): a Leap recording made on a headset, viewed
//! from the head. A synthetic worn-device frame settles the signs: a hand
//! straight out of the device is ahead of the eyes and below them, as the
//! wearer saw it, and the viewer's camera is at those eyes.

use bevy::prelude::*;
use coulomb_hands::hand::HandId;
use coulomb_hands::input::convert::MountPreset;
use coulomb_hands::pipeline::Method;
use coulomb_hands_bevy::convert::to_bevy_vec3;
use coulomb_hands_view::camera::{HeadView, Orbit, spawn_camera};
use coulomb_hands_view::head::{HeadMount, HeadPose};
use coulomb_hands_view::source::{LoadOptions, Source};
use std::path::{Path, PathBuf};

/// A worn Leap's recording (format 1, mm, 0.3 s at 100 Hz) of a right hand
/// `out` mm straight out of the device and `below` mm towards the device's
/// +z (the wearer's down), palm down, fingers pointing out.
fn worn_recording(name: &str, out: f32, below: f32) -> PathBuf {
    let pointable = |f: i32| {
        let x = 38.0 - 19.0 * f as f32; // the thumb on the wearer's left: the device's +x
        let at = |along: f32| [x, out + 35.0 + along, below];
        serde_json::json!({"handId": 7, "id": 70 + f, "type": f, "width": 17.0,
            "mcpPosition": at(0.0), "pipPosition": at(42.0),
            "dipPosition": at(66.0), "tipPosition": at(88.0)})
    };
    let frames: Vec<_> = (0..30)
        .map(|i| {
            let hand = serde_json::json!({"id": 7, "type": "right",
                "palmPosition": [0.0, out, below], "palmNormal": [0.0, 0.0, 1.0],
                "direction": [0.0, 1.0, 0.0]});
            serde_json::json!({"timestamp": 10_000 * i, "hands": [hand],
                "pointables": (0..5).map(pointable).collect::<Vec<_>>()})
        })
        .collect();
    let text = serde_json::json!({"metadata": {"formatVersion": 1}, "frames": frames});
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::write(&path, text.to_string()).expect("a temporary file");
    path
}

fn load(path: &Path, head: HeadMount) -> Result<Source, String> {
    let options = LoadOptions { head: Some(head), ..LoadOptions::default() };
    Source::load(Some(path.to_str().expect("UTF-8")), &options).map_err(|e| e.to_string())
}

/// The camera's transform as the viewer spawns it for `head`, and whether it
/// can orbit.
fn spawned_camera(head: HeadMount) -> (Transform, bool) {
    let mut app = App::new();
    app.insert_resource(HeadView(head)).add_systems(Startup, spawn_camera);
    app.update();
    let world = app.world_mut();
    let mut cameras = world.query_filtered::<(&Transform, Has<Orbit>), With<Camera3d>>();
    let (transform, orbits) = cameras.single(world).expect("one camera");
    (*transform, orbits)
}

#[test]
fn a_head_mounted_recording_is_seen_from_the_eyes() {
    let path = worn_recording("worn-dk2.json", 270.0, 120.0);
    let head =
        HeadPose { position: glam::Vec3::new(-0.3, 1.4, 0.6), yaw_deg: 35.0, pitch_deg: -25.0 };
    let mount = HeadMount { mount: MountPreset::OculusDk2, head };
    let source = load(&path, mount).expect("a Leap recording");
    let mut interaction = source.build(Method::Coulomb).expect("a world");
    for _ in 0..50 {
        assert!(interaction.step());
    }
    let pose = interaction.world().hand_pose(HandId(0)).expect("tracked").clone();

    let (camera, orbits) = spawned_camera(mount);
    assert!(!orbits, "the head's view does not orbit");
    let eyes = to_bevy_vec3(head.position);
    assert!((camera.translation - eyes).length() < 1e-6, "the camera is at the eyes");
    // The palm in the eyes' frame: 270 mm out of a device 80 mm ahead of the eyes,
    // 120 mm below them, and the palm box's centre half its 17 mm thickness up.
    let palm = camera.compute_affine().inverse().transform_point3(to_bevy_vec3(pose.palm.center));
    assert!((palm - Vec3::new(0.0, -0.1115, -0.35)).length() < 1e-3, "{palm}");
    // So it is in view: inside the default 45° vertical field, near the middle.
    assert!((palm.y / -palm.z).atan().abs() < 22.5f32.to_radians());
    assert!(palm.x.abs() < 1e-3);
    // The thumb is on the wearer's left, the fingertips point away, the palm faces down.
    let local = |p: glam::Vec3| camera.compute_affine().inverse().transform_point3(to_bevy_vec3(p));
    assert!(local(pose.fingers[0][2].b).x < -0.02, "the thumb is on the left");
    assert!(local(pose.fingers[2][2].b).z < palm.z - 0.08, "the fingers point ahead");
    let normal = camera.rotation.inverse() * to_bevy_vec3(pose.palm.normal());
    assert!(normal.y < -0.99, "the palm faces down: {normal}");

    // The other mount: 7 cm up and 5 cm ahead, so the same hand sits 3 cm nearer and 7 cm
    // higher in the eyes' frame.
    let hololens = HeadMount { mount: MountPreset::HoloLens, head };
    let mut interaction = load(&path, hololens).expect("ok").build(Method::Coulomb).expect("ok");
    assert!(interaction.step());
    let pose = interaction.world().hand_pose(HandId(0)).expect("tracked").clone();
    let moved = local(pose.palm.center) - palm;
    assert!((moved - Vec3::new(0.0, 0.07, 0.03)).length() < 1e-3, "{moved}");
}

#[test]
fn only_a_leap_recording_can_be_head_mounted() {
    let head = HeadMount { mount: MountPreset::OculusDk2, head: HeadPose::default() };
    let joints = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/joints/pinch-57fps.jsonl");
    let e = load(&joints, head).expect_err("a joint recording is in the world already");
    assert!(e.contains("pinch-57fps.jsonl: format: a joint recording"), "{e}");
    let e =
        Source::load(Some("grasp-lift"), &LoadOptions { head: Some(head), ..Default::default() })
            .expect_err("a scenario has no worn tracker");
    assert_eq!(
        e.to_string(),
        "grasp-lift: --scene, --object-at and --head-mounted go with a recording"
    );
}
