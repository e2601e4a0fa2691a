//! Scene files (FileError): each error names the file, then the object or
//! the field, then what is wrong, before anything is simulated.

use crate::world::tetrahedron;
use crate::{Scratch, cli_error, names, repo};
use coulomb_hands::scene::Scene;

/// The error of parsing scene text as `s.json`.
fn scene_error(text: &str) -> String {
    let e = Scene::parse("s.json", text).unwrap_err();
    assert_eq!(e.file, "s.json");
    e.to_string()
}

/// A scene of one object whose JSON fields are `fields`.
fn object(fields: &str) -> String {
    format!(r#"{{"objects": [{{"name": "cube", {fields}}}]}}"#)
}

const CUBE: &str = r#""shape": {"Box": {"half_extents": [0.02, 0.02, 0.02]}}, "mass": 0.05,
    "material": "wood", "position": [0.0, 0.2, 0.0]"#;

#[test]
fn syntax_and_schema_errors_give_the_line_and_column_once() {
    let e = scene_error("{\"objects\": [\n");
    names(e.clone(), &["s.json: line 2 column 0: EOF while parsing"]);
    assert_eq!(e.matches("line").count(), 1, "the place is said once: {e}");
    names(scene_error(r#"{"objects": [], "lights": []}"#), &["s.json: line 1", "`lights`"]);
    let e = scene_error(&object(&CUBE.replace("0.05", "\"heavy\"")));
    names(e, &["s.json: line ", "invalid type: string \"heavy\""]);
    let e = scene_error(&object(&CUBE.replace("\"Box\"", "\"Cone\"")));
    names(e, &["s.json: line ", "unknown variant `Cone`"]);
    let e = scene_error(&object(&CUBE.replace("\"position\"", "\"place\"")));
    names(e, &["s.json: line ", "unknown field `place`"]);
}

#[test]
fn a_missing_scene_file_is_named() {
    let e = Scene::load(&repo("scenes/none.json")).unwrap_err();
    names(e, &["scenes/none.json: ", "No such file"]);
}

#[test]
fn unknown_material_names_list_the_known_ones() {
    let e = scene_error(&object(&CUBE.replace("\"wood\"", "\"cheese\"")));
    names(e, &["s.json: object 'cube': material: unknown name 'cheese'", "wood, nylon, glass"]);
}

#[test]
fn scene_level_fields_are_checked_by_name() {
    let e = scene_error(r#"{"ground": {"height": 1e39, "friction": 0.5}}"#);
    names(e, &["s.json: ground.height: must be finite", "got inf"]);
    let e = scene_error(r#"{"ground": {"height": 0.0, "friction": -0.5}}"#);
    names(e, &["s.json: ground.friction: must be finite and ≥ 0, got -0.5"]);
    let e = scene_error(r#"{"gravity": [0.0, -1e39, 0.0]}"#);
    names(e, &["s.json: gravity: must be finite, got Vec3(0.0, -inf, 0.0)"]);
    let e = scene_error(r#"{"towers": [{"base": [0, 0, 0]}, {"base": [0, 0, 2e4]}]}"#);
    names(e, &["s.json: towers[1].base: must be finite and within ±10000 m", "20000"]);
}

#[test]
fn objects_and_statics_are_checked_naming_them() {
    let e = scene_error(&object(&CUBE.replace("0.05,", "-1,")));
    names(e, &["s.json: object 'cube': mass: must be a positive finite number, got -1"]);
    let full = r#"{"name": "ice", "skin": {"static_mu": -0.2, "dynamic_mu": 0.1},
        "surface_friction": 0.1, "source": "test"}"#;
    let e = scene_error(&object(&CUBE.replace("\"wood\"", full)));
    names(e, &["s.json: object 'cube': material.skin.static_mu: ", "got -0.2"]);
    let e = scene_error(&object(&format!(r#"{CUBE}, "rotation": [0, 0, 0, 3]"#)));
    names(e, &["s.json: object 'cube': rotation: must be a unit quaternion"]);
    let e = scene_error(&object(&format!(r#"{CUBE}, "gamma": {{"Fixed": -400}}"#)));
    names(e, &["s.json: object 'cube': gamma: ", "got -400"]);
    let table = r#"{"statics": [{"name": "table", "shape": {"Sphere": {"radius": 0.3}},
        "position": [0, 0, 0], "rotation": [0, 0, 0, 1], "friction": -1}]}"#;
    names(scene_error(table), &["s.json: object 'table': friction: ", "got -1"]);
}

/// The error of a scene in `dir` whose object 'part' has this mesh shape.
fn mesh_scene_error(dir: &Scratch, file: &str, body: &str) -> String {
    let text = format!(
        r#"{{"objects": [{{"name": "part", "mass": 0.03, "material": "wood",
            "position": [0, 0.1, 0],
            "shape": {{"Mesh": {{"file": "{file}", "body": {body}}}}}}}]}}"#
    );
    let e = Scene::load(&dir.file("s.json", text)).unwrap_err();
    names(e.clone(), &[&dir.text("s.json")]);
    e.to_string()
}

#[test]
fn mesh_objects_name_the_object_the_file_and_the_problem() {
    let dir = Scratch::new("scene-mesh");
    dir.file("tet.obj", tetrahedron().to_obj("a unit tetrahedron"));
    dir.file("flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    let voxels = r#"{"Voxels": {"size": 0.1}}"#;
    let e = mesh_scene_error(&dir, "rook.obj", voxels);
    names(e, &["object 'part': shape.Mesh.file: ", &dir.text("rook.obj")]);
    let e = mesh_scene_error(&dir, "flat.obj", voxels);
    names(e, &["object 'part': shape.Mesh.file: ", "flat.obj: the mesh has no volume"]);
    let e = mesh_scene_error(&dir, "tet.obj", r#"{"Voxels": {"size": 1e-9}}"#);
    names(e, &["object 'part': shape.Mesh.body.Voxels.size: voxel size ", "too small"]);
    let e = mesh_scene_error(&dir, "tet.obj", r#"{"Voxels": {"size": 5}}"#);
    names(e, &["object 'part': shape.Mesh.body.Voxels.size: voxel size 5 m", "too large"]);
    let e = mesh_scene_error(&dir, "tet.obj", r#"{"ConvexParts": {"concavity": 0}}"#);
    names(e, &["object 'part': shape.Mesh.body.ConvexParts.concavity: ", "got 0"]);
    let e = mesh_scene_error(&dir, "tet.obj", r#""TriMesh""#);
    names(e, &["object 'part': shape.Mesh.body: ", "only be static scenery"]);
    let e = mesh_scene_error(&dir, "tet.obj", r#"{"Voxels": {"size": 0.1, "fill": 1}}"#);
    names(e, &["line ", "unknown field `fill`"]);
}

#[test]
fn the_cli_names_the_scene_file_before_reading_the_recording() {
    let dir = Scratch::new("scene-cli");
    let scene = dir.file("scene.json", object(&CUBE.replace("0.05,", "0,")));
    let e = cli_error(&["replay", "--scene", &scene.display().to_string(), "no-such.json"]);
    names(e, &[&dir.text("scene.json"), "object 'cube': mass: ", "got 0"]);
}

#[test]
fn an_object_the_automatic_gamma_cannot_stiffen_is_named_by_the_cli() {
    let dir = Scratch::new("scene-gamma");
    let ice = r#"{"name": "ice", "skin": {"static_mu": 0, "dynamic_mu": 0},
        "surface_friction": 0.1, "source": "test"}"#;
    let scene = dir.file("scene.json", object(&CUBE.replace("\"wood\"", ice)));
    let pinch = repo("data/leap/pinch.json.lz").display().to_string();
    let scene = scene.display().to_string();
    let e = cli_error(&["replay", "--gamma", "auto", "--scene", &scene, &pinch]);
    names(e, &["object 'cube': gamma: automatic γ is inf", "needs gravity, μ_st"]);
}
