//! The page's API natively: what it runs is what the library runs, bit for
//! bit, and bad input is the library's error, leaving the world as it was.

use coulomb_hands::input::{capture, recording};
use coulomb_hands::run::demo::GraspLiftCarry;
use coulomb_hands::run::replay::{ReplayOptions, replay_recording};
use coulomb_hands::run::scenario::Scenario;
use coulomb_hands::scene::mesh::TriangleMesh;
use coulomb_hands::{InteractionConfig, ObjectId};
use coulomb_hands_web::arrays;
use coulomb_hands_web::sim::{self, Sim};

const GRAB: &[u8] = include_bytes!("../../../data/leap/grab.json.lz");
const TACO: &str = include_str!("../../../data/taco/taco_20231104_017.json");
const TACO_MESH: &[u8] = include_bytes!("../../../data/taco/taco_20231104_017.obj");

fn state(sim: &Sim, id: u32) -> coulomb_hands::ObjectState {
    sim.world().object_state(ObjectId(id)).expect("an object")
}

#[test]
fn the_demo_is_the_clis_demo_bit_for_bit() {
    let demo = GraspLiftCarry::new(InteractionConfig::default()).expect("the demo");
    let report = demo.run(0.25).expect("its run");
    let mut demo = Sim::demo().expect("the page's demo");
    for row in &report.timeline {
        demo.step(250).expect("steps");
        assert_eq!(
            state(&demo, 0).position.to_array().map(f32::to_bits),
            row.cube.map(f32::to_bits)
        );
    }
    assert!(demo.finished(), "5 s run");
    assert_eq!(demo.step(10), Ok(0), "a script stops at its end");
    assert_eq!(state(&demo, 0).position.y.to_bits(), report.final_height.to_bits());
}

#[test]
fn a_shipped_scenario_runs_as_the_cli_runs_it() {
    let scenario = Scenario::find("grasp-lift").expect("found");
    let expected = scenario.run(&mut []).expect("run");
    let mut page = Sim::shipped_scenario("grasp-lift").expect("shipped");
    let rows = sim::trace(&mut page, 250).expect("traced");
    assert!(rows.len() > 4);
    assert_eq!(page.report(), Some(expected.clone()));
    assert!(expected.passed, "{expected:?}");
}

#[test]
fn a_recording_is_replayed_with_its_closings_verdicts_as_replay_gives_them() {
    let object = sim::CLOSING_OBJECT.parse().expect("an object");
    let options = ReplayOptions { object_at_grasp: Some(object), ..ReplayOptions::default() };
    let recorded = recording::from_bytes("grab.json.lz", GRAB.to_vec()).expect("a recording");
    let (summary, _) = replay_recording(&recorded, &options, &mut []).expect("replayed");
    let mut page = Sim::recording("grab.json.lz", GRAB.to_vec(), Some(sim::CLOSING_OBJECT))
        .expect("the page's replay");
    while !page.finished() {
        page.step(1000).expect("steps");
    }
    assert_eq!(page.steps(), summary.steps);
    let expected = serde_json::to_string(&summary.closings).expect("json");
    assert_eq!(page.verdicts_json(), expected);
    assert!(!summary.closings.is_empty());
    let lines: Vec<String> = summary.closings.iter().map(ToString::to_string).collect();
    assert_eq!(page.verdict_lines(), lines, "the CLI's lines");
}

#[test]
fn a_capture_lifts_its_object_with_the_captured_one_as_a_ghost() {
    let mut page = Sim::capture("taco.json", TACO, TACO_MESH).expect("the page's capture");
    let captured = capture::parse("taco.json", TACO, &|file| {
        TriangleMesh::from_bytes(file, TACO_MESH).map_err(|e| e.to_string())
    })
    .expect("a capture");
    let ghost = page.ghost_pose();
    let (position, rotation) = captured.poses[0];
    assert_eq!(ghost[..3], position.to_array(), "the first captured position");
    let turn = glam::Quat::from_slice(&ghost[3..]);
    assert!(turn.dot(rotation).abs() > 1.0 - 1e-6, "the first captured rotation: {turn}");
    assert_eq!(page.ghost_mesh().len(), captured.mesh.triangles.len() * 9);
    assert_eq!(page.world().object_count(), 1, "the simulated object");
    let start = state(&page, 0).position;
    // 1.3 s: the captured object has risen about 60 mm by 1.2 s, 97 mm by 1.33 s.
    assert_eq!(page.step(1300), Ok(1300));
    let risen = page.ghost_pose()[1] - position.y;
    assert!(risen > 0.05, "the ghost rose {risen} m");
    let moved = state(&page, 0).position - start;
    assert!(moved.length() > 0.005, "the hand moved the object: {moved}");
}

#[test]
fn the_desk_and_a_rig_hand_push_its_cube() {
    let mut desk = Sim::desk().expect("the desk");
    assert_eq!(desk.world().object_count(), 4);
    let hand = desk.add_hand(sim::side("right").expect("a side"));
    let down = glam::Quat::from_rotation_z(std::f32::consts::PI);
    let start = state(&desk, 0).position;
    // The palm, fingers straight ahead (+z), sweeps through the cube's place.
    for k in 0..600 {
        let z = -0.12 + 0.0004 * k as f32;
        let palm = [0.0, 0.03, z];
        desk.set_hand_rig(hand, &palm, &down.to_array(), &[0.1; 5], 0.0).expect("posed");
        desk.step(1).expect("a step");
    }
    let moved = state(&desk, 0).position - start;
    assert!(moved.z > 0.02, "pushed along +z: {moved}");
    assert_eq!(desk.hand_pose(hand).expect("a hand").len(), arrays::POSE);
}

#[test]
fn webxr_joints_pose_a_hand_where_they_are() {
    // WebXR's layout is OpenXR's without its first joint, the palm.
    let text = std::fs::read_to_string("../../data/joints/pinch-57fps.jsonl").expect("joints");
    let frames = coulomb_hands::input::joints::parse("pinch-57fps.jsonl", &text).expect("parsed");
    let hand = frames.iter().find_map(|f| f.hands.first()).expect("a hand");
    let mut world = Sim::empty(InteractionConfig::default()).expect("a world");
    let id = world.add_hand(hand.side);
    let webxr = &coulomb_hands::input::layouts::to_openxr(hand)[1..];
    let positions: Vec<f32> = webxr.iter().flat_map(|j| j.position.to_array()).collect();
    let radii: Vec<f32> = webxr.iter().map(|j| j.radius).collect();
    let turns: Vec<f32> = webxr.iter().flat_map(|j| j.orientation.to_array()).collect();
    world.set_hand_webxr(id, &positions, &radii, Some(&turns)).expect("posed with orientations");
    world.set_hand_webxr(id, &positions, &radii, None).expect("posed");
    world.step(1).expect("a step");
    let pose = world.hand_pose(id).expect("a pose");
    let wrist = glam::Vec3::from_slice(&positions[..3]);
    let palm = glam::Vec3::from_slice(&pose[..3]);
    assert!(palm.distance(wrist) < 0.08, "the palm by the wrist: {palm} {wrist}");
}

#[test]
fn bad_input_is_the_librarys_message_and_changes_nothing() {
    let bad_scene = Sim::scene("mine.json", "{\"objects\": [{\"name\": 3}]}").err().expect("bad");
    assert!(bad_scene.starts_with("mine.json"), "{bad_scene}");
    let bad_recording = Sim::recording("x.json.lz", b"not lz".to_vec(), None).err().expect("bad");
    assert!(bad_recording.contains("x.json.lz"), "{bad_recording}");
    let unknown = Sim::shipped_scenario("nope").err().expect("unknown");
    assert!(unknown.contains("grasp-lift"), "names the shipped ones: {unknown}");
    let mut desk = Sim::desk().expect("the desk");
    let hand = desk.add_hand(coulomb_hands::Side::Left);
    let short = desk.set_hand_webxr(hand, &[0.0; 6], &[0.01; 25], None).unwrap_err();
    assert_eq!(short, "positions: expected 75 numbers, got 6");
    let nan = [f32::NAN; 75];
    let not_finite = desk.set_hand_webxr(hand, &nan, &[0.01; 25], None).unwrap_err();
    assert!(not_finite.contains("webxr joint 0"), "{not_finite}");
    let mesh = desk.add_mesh("m", "m.obj", b"v 1 2", 1.0, None, 0.1, &[0.0; 3], &[], "wood");
    assert!(mesh.unwrap_err().contains("m.obj"));
    let material = desk.add_box("b", &[0.1; 3], 0.1, &[0.0; 3], &[], "cheese").unwrap_err();
    assert!(material.contains("cheese") && material.contains("wood"), "{material}");
    let rate = TACO.replacen("\"frame_rate_hz\":30.0", "\"frame_rate_hz\":-1", 1);
    let bad_capture = Sim::capture("taco.json", &rate, TACO_MESH).err().expect("bad");
    assert!(
        bad_capture.contains("taco.json") && bad_capture.contains("frame_rate_hz"),
        "{bad_capture}"
    );
    let bad_mesh = Sim::capture("taco.json", TACO, b"v 1 2").err().expect("bad");
    assert!(bad_mesh.contains("object.mesh"), "{bad_mesh}");
    assert_eq!(desk.world().object_count(), 4, "nothing added");
    assert!(desk.world().hand_pose(coulomb_hands::HandId(hand)).is_none(), "nothing posed");
    assert!(desk.ghost_pose().is_empty() && desk.ghost_mesh().is_empty(), "no capture, no ghost");
    assert!(sim::config("{\"dt\": -1}").is_err());
    assert!(sim::config("{\"nope\": 1}").unwrap_err().starts_with("config:"));
}
