//! Replays the committed fuzz corpora and crash reproducers
//! (`fuzz/corpus/<target>/`, `fuzz/regressions/<target>/`) through the same
//! entry points as the cargo-fuzz targets, on the stable toolchain: no
//! input may panic, and whatever parses must be finite. The fuzzing itself
//! is run by hand (the book, "Fuzzing").

#[path = "../fuzz/entry.rs"]
mod entry;

use coulomb_hands::hand::rig::HandRig;
use coulomb_hands::input::convert::Conversion;
use coulomb_hands::input::playback::Playback;
use coulomb_hands::input::{TrackingFrame, leap};
use coulomb_hands::scene::Scene;
use coulomb_hands::scene::mesh::TriangleMesh;
use coulomb_hands::{PoseError, Side};
use glam::{Quat, Vec3};
use std::path::{Path, PathBuf};

fn files(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else { return Vec::new() };
    let mut out: Vec<PathBuf> =
        entries.flatten().map(|e| e.path()).filter(|p| p.is_file()).collect();
    out.sort();
    out
}

fn replay(kind: &str) -> usize {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz").join(kind);
    let mut failures = Vec::new();
    let mut count = 0;
    for target in entry::TARGETS {
        for file in files(&root.join(target)) {
            let data = std::fs::read(&file).unwrap();
            count += 1;
            if let Err(e) = std::panic::catch_unwind(|| entry::run(target, &data)) {
                let why = e
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default();
                failures.push(format!("{target}: {}: {why}", file.display()));
            }
        }
    }
    assert!(failures.is_empty(), "inputs that panic:\n{}", failures.join("\n"));
    count
}

#[test]
fn every_corpus_input_parses_or_is_rejected_without_a_panic() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/corpus");
    for target in entry::TARGETS {
        assert!(!files(&root.join(target)).is_empty(), "fuzz/corpus/{target} has no inputs");
    }
    assert!(replay("corpus") >= entry::TARGETS.len());
}

#[test]
fn every_fixed_crash_stays_fixed() {
    assert!(replay("regressions") > 0);
}

// The bugs fuzzing found, each fixed in the library; their reproducers are
// in `fuzz/regressions/`.

#[test]
fn timestamps_before_zero_or_too_far_apart_are_errors_not_overflows() {
    let e = leap::parse(
        "r.json",
        r#"{"metadata": {"formatVersion": 1}, "frames": [{"timestamp": -5}]}"#,
    )
    .unwrap_err();
    assert_eq!((e.frame, e.field.as_str()), (Some(0), "timestamp"));
    assert!(e.reason.contains("≥ 0"), "{e}");
    // Frames from elsewhere (not a Leap file) are not checked for sign.
    let frames = [i64::MIN, i64::MAX].map(|t| TrackingFrame { timestamp_us: t, hands: vec![] });
    let e = Playback::new("f", &frames, &Conversion::identity(), 0.1).unwrap_err();
    assert_eq!((e.frame, e.field.as_str()), (Some(1), "timestamp"));
    assert!(e.reason.contains("more than 3600 s"), "{e}");
}

#[test]
fn hand_bones_larger_than_the_world_are_rejected() {
    let pose = HandRig::adult(Side::Right).pose(Vec3::ZERO, Quat::IDENTITY, [0.3; 5]);
    pose.validate(0).unwrap();
    let mut palm = pose.clone();
    palm.palm.half_extents.x = 1.0e20;
    let e = palm.validate(0).unwrap_err();
    assert!(matches!(e, PoseError::BadPalmExtents { .. }) && e.to_string().contains("at most"));
    let mut finger = pose.clone();
    finger.fingers[2][1].radius = 1.0e20;
    let e = finger.validate(0).unwrap_err();
    assert!(matches!(e, PoseError::BadRadius { .. }) && e.to_string().contains("at most"));
}

fn scene_with(shape: &str) -> Result<Scene, String> {
    let text = format!(
        r#"{{"objects": [{{"name": "o", "shape": {shape}, "mass": 0.05, "material": "wood",
            "position": [0, 0.1, 0]}}]}}"#
    );
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    Scene::parse_in("s.json", &text, &dir).map_err(|e| e.to_string())
}

#[test]
fn object_shapes_larger_than_the_world_are_rejected() {
    let e = scene_with(r#"{"Capsule": {"half_height": 1e30, "radius": 0.01}}"#).unwrap_err();
    assert!(e.contains("'o'") && e.contains("shape.half_height") && e.contains("at most"), "{e}");
    let e = scene_with(r#"{"Sphere": {"radius": 1e20}}"#).unwrap_err();
    assert!(e.contains("shape.radius") && e.contains("at most"), "{e}");
    scene_with(r#"{"Capsule": {"half_height": 1.0, "radius": 0.01}}"#).unwrap();
}

#[test]
fn mesh_scales_that_overflow_or_leave_no_convex_part_are_errors() {
    let mesh = |scale: &str, body: &str| {
        scene_with(&format!(
            r#"{{"Mesh": {{"file": "../assets/meshes/u-bracket.obj", "scale": {scale},
                "body": {body}}}}}"#
        ))
    };
    let e = mesh("1e36", r#"{"Voxels": {"size": 1e34}}"#).unwrap_err();
    assert!(e.contains("'o'") && e.contains("shape.Mesh.scale") && e.contains("within"), "{e}");
    let e = mesh("1e-30", r#"{"ConvexParts": {"concavity": 0.5}}"#).unwrap_err();
    assert!(e.contains("'o'") && e.contains("shape.Mesh.scale") && e.contains("volume"), "{e}");
    mesh("1.0", r#"{"ConvexParts": {"concavity": 0.5}}"#).unwrap();
}

#[test]
fn obj_indices_outside_the_defined_vertices_are_errors() {
    let dir = Path::new(".");
    let obj = |faces: &str| {
        let text = format!("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\n{faces}\nf 1 2 4\n");
        TriangleMesh::parse("m.obj", text.as_bytes(), dir).map_err(|e| e.to_string())
    };
    obj("f 1/1 2/1 3/1").unwrap();
    obj("f -4 -3 -2").unwrap();
    let e = obj("f 1/9223372036854775807 2 3").unwrap_err();
    assert!(e.starts_with("m.obj: line 6: texture coordinate index"), "{e}");
    let e = obj("f 0 1 2").unwrap_err();
    assert!(e.contains("line 6: position index 0 is not one of the 4"), "{e}");
    let e = obj("f 1 2 -9223372036854775808").unwrap_err();
    assert!(e.contains("position index -9223372036854775808"), "{e}");
}

#[test]
fn gltf_accessors_the_reader_would_trip_on_are_errors() {
    use coulomb_hands::scene::mesh::generate;
    let u = generate::u_bracket(0.04, 0.03, 0.02, 0.01);
    let good: serde_json::Value = serde_json::from_str(&generate::to_gltf(&u, Vec3::ZERO)).unwrap();
    let parse = |edit: &dyn Fn(&mut serde_json::Value)| {
        let mut v = good.clone();
        edit(&mut v);
        TriangleMesh::parse("m.gltf", v.to_string().as_bytes(), Path::new("."))
            .map_err(|e| e.to_string())
    };
    assert_eq!(parse(&|_| {}).unwrap().triangles.len(), u.triangles.len());
    let e = parse(&|v| v["meshes"][0]["primitives"][0]["indices"] = 0.into()).unwrap_err();
    assert!(e.contains("accessor 0: Vec3 of F32, expected Scalar of [U8, U16, U32]"), "{e}");
    let e = parse(&|v| v["accessors"][0]["count"] = 4_000_000_000_u64.into()).unwrap_err();
    assert!(e.contains("accessor 0: 4000000000 elements") && e.contains("do not fit"), "{e}");
    let e = parse(&|v| v["nodes"][0]["children"] = serde_json::json!([0])).unwrap_err();
    assert!(e.contains("not a tree"), "{e}");
    let mut glb = generate::to_glb(&u, Vec3::ZERO);
    glb[8..12].copy_from_slice(&3u32.to_le_bytes());
    let e = TriangleMesh::parse("m.glb", &glb, Path::new(".")).unwrap_err().to_string();
    assert!(e.contains("GLB length 3 is shorter than its 12-byte header"), "{e}");
}

#[test]
fn voxels_larger_than_the_mesh_are_an_error() {
    use coulomb_hands::scene::mesh::{MeshProblem, generate};
    let u = generate::u_bracket(0.06, 0.04, 0.02, 0.01);
    assert!(!u.voxel_boxes(0.01, 4096).unwrap().is_empty());
    for voxel in [0.1, 1.0e19] {
        let e = u.voxel_boxes(voxel, 4096).unwrap_err();
        assert!(matches!(e, MeshProblem::VoxelSize { .. }), "{voxel}: {e}");
        assert!(e.to_string().contains("too large"), "{e}");
    }
}

#[test]
fn gltf_position_accessors_that_do_not_exist_and_vanishing_meshes_are_errors() {
    use coulomb_hands::scene::mesh::generate;
    let u = generate::u_bracket(0.04, 0.03, 0.02, 0.01);
    let mut v: serde_json::Value =
        serde_json::from_str(&generate::to_gltf(&u, Vec3::ZERO)).unwrap();
    v["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 65.into();
    let e = TriangleMesh::parse("m.gltf", v.to_string().as_bytes(), Path::new("."));
    let e = e.unwrap_err().to_string();
    assert!(e.contains("mesh 0 primitive 0: accessor 65 is not one of 2"), "{e}");
    // A solid 1e-39 across (subnormal floats) has no usable volume.
    let tiny = u.scaled(1.0e-37);
    assert!(tiny.vertices.iter().all(|v| v.is_finite()));
    let e = tiny.check().unwrap_err().to_string();
    assert!(e.contains("no volume"), "{e}");
    u.scaled(1.0e-3).check().unwrap();
}
