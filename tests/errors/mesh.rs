//! Mesh files (MeshProblem in a FileError): every way TriangleMesh::load
//! rejects a file names the file and the problem.

use crate::world::tetrahedron;
use crate::{Scratch, names};
use base64::Engine;
use coulomb_hands::scene::mesh::TriangleMesh;
use serde_json::json;

/// The error of loading `name` with these contents; it names the file.
fn load_error(dir: &Scratch, name: &str, contents: impl AsRef<[u8]>) -> String {
    let path = dir.file(name, contents);
    let e = TriangleMesh::load(&path).unwrap_err();
    assert_eq!(e.file, path.display().to_string());
    e.to_string()
}

const TETRAHEDRON_OBJ: &str =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

#[test]
fn unknown_formats_and_unreadable_files() {
    let dir = Scratch::new("mesh-formats");
    let e = load_error(&dir, "tet.ply", "ply\n");
    names(e, &["tet.ply: unknown mesh format \".ply\" (obj, stl, gltf or glb)"]);
    let e = load_error(&dir, "tet", TETRAHEDRON_OBJ);
    names(e, &["tet: unknown mesh format (no file extension)"]);
    let missing = dir.path("gone.obj");
    let e = TriangleMesh::load(&missing).unwrap_err();
    names(e, &[&dir.text("gone.obj")]);
    let e =
        load_error(&dir, "short.stl", "solid x\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\n");
    names(e, &["short.stl: not a readable STL file: "]);
    let e = load_error(&dir, "noise.glb", [7u8; 64]);
    names(e, &["noise.glb: not a readable glTF file: "]);
    let e = load_error(&dir, "bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 9\n");
    names(e, &["bad.obj: line 3: position index 9 is not one of the 2 defined before it"]);
}

#[test]
fn meshes_that_are_not_solids() {
    let dir = Scratch::new("mesh-solids");
    let e = load_error(&dir, "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    names(e, &["points.obj: the mesh has no triangles"]);
    let e = load_error(&dir, "flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    names(e, &["flat.obj: the mesh has no volume: it is flat", "Vec3(1.0, 1.0, 0.0)"]);
    // A binary STL whose second triangle has an infinite corner.
    let mut stl = vec![0u8; 80];
    stl.extend(2u32.to_le_bytes());
    for corner in [[0.0, 0.0, 1.0f32], [f32::INFINITY, 0.0, 1.0]] {
        let floats = [[0.0f32; 3], [0.0; 3], [1.0, 0.0, 0.0], corner];
        stl.extend(floats.iter().flatten().flat_map(|f| f.to_le_bytes()));
        stl.extend([0u8; 2]);
    }
    let e = load_error(&dir, "inf.stl", stl);
    names(e, &["inf.stl: vertex ", " is not finite: Vec3(", "inf"]);
}

/// A glTF file of one mesh whose primitives are `(positions, indices)`,
/// its buffer a base64 data URI of `data` (all primitives' bytes, unless
/// given).
fn gltf(primitives: &[(Vec<[f32; 3]>, Vec<u32>)], data: Option<Vec<u8>>) -> serde_json::Value {
    let mut bytes = Vec::new();
    let (mut views, mut accessors, mut prims) = (vec![], vec![], vec![]);
    for (positions, indices) in primitives {
        let mut view = |b: Vec<u8>| {
            views.push(json!({"buffer": 0, "byteOffset": bytes.len(), "byteLength": b.len()}));
            bytes.extend(b);
            views.len() - 1
        };
        let p = view(positions.iter().flatten().flat_map(|f| f.to_le_bytes()).collect());
        let i = view(indices.iter().flat_map(|k| k.to_le_bytes()).collect());
        let (lo, hi) = ([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]);
        accessors.push(json!({"bufferView": p, "componentType": 5126, "count": positions.len(),
                              "type": "VEC3", "min": lo, "max": hi}));
        accessors.push(json!({"bufferView": i, "componentType": 5125, "count": indices.len(),
                              "type": "SCALAR"}));
        let n = accessors.len();
        prims.push(json!({"attributes": {"POSITION": n - 2}, "indices": n - 1}));
    }
    let length = bytes.len();
    let data = base64::engine::general_purpose::STANDARD.encode(data.unwrap_or(bytes));
    let uri = format!("data:application/octet-stream;base64,{data}");
    json!({
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": length, "uri": uri}],
        "bufferViews": views, "accessors": accessors,
        "meshes": [{"primitives": prims}], "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]
    })
}

fn tet() -> (Vec<[f32; 3]>, Vec<u32>) {
    let t = tetrahedron();
    (t.vertices.iter().map(|v| v.to_array()).collect(), t.triangles.concat())
}

#[test]
fn gltf_files_whose_buffers_do_not_hold_the_mesh() {
    let dir = Scratch::new("mesh-gltf");
    let ok = gltf(&[tet()], None);
    TriangleMesh::load(&dir.file("ok.gltf", ok.to_string())).expect("a valid glTF");
    // Only the positions' 48 bytes are there: the indices are missing.
    let short = gltf(&[tet()], Some(vec![0; 48])).to_string();
    let e = load_error(&dir, "short.gltf", short);
    names(e, &["short.gltf: accessor 1: ", "do not fit buffer view 1"]);
    let none = gltf(&[tet()], Some(vec![0; 8])).to_string();
    let e = load_error(&dir, "none.gltf", none);
    names(e, &["none.gltf: accessor 0: ", "do not fit buffer view 0"]);
    let with_uri = |uri: Option<&str>| {
        let mut file = ok.clone();
        match uri {
            Some(uri) => file["buffers"][0]["uri"] = uri.into(),
            None => drop(file["buffers"][0].as_object_mut().unwrap().remove("uri")),
        }
        file.to_string()
    };
    let e = load_error(&dir, "external.gltf", with_uri(Some("tet.bin")));
    names(e, &["external.gltf: buffer 0 (tet.bin): "]);
    let e = load_error(&dir, "odd.gltf", with_uri(Some("data:text/plain,tet")));
    names(e, &["odd.gltf: buffer 0: unsupported data URI"]);
    let e = load_error(&dir, "garbled.gltf", with_uri(Some("data:x;base64,!!")));
    names(e, &["garbled.gltf: buffer 0: "]);
    let e = load_error(&dir, "no-uri.gltf", with_uri(None));
    names(e, &["no-uri.gltf: buffer 0 has no uri, and the file no GLB binary chunk"]);
}

#[test]
fn gltf_indices_beyond_the_vertices_are_an_error_not_an_overflow() {
    let dir = Scratch::new("mesh-indices");
    let (positions, mut indices) = tet();
    indices[4] = 9;
    let beyond = gltf(&[(positions.clone(), indices)], None).to_string();
    let e = load_error(&dir, "beyond.gltf", beyond);
    names(e, &["beyond.gltf: triangle 1 refers to a vertex beyond the 4 there are"]);
    // A second primitive's index so large that adding the first's vertex
    // count would overflow.
    let (_, mut huge) = tet();
    huge[11] = u32::MAX;
    let e = load_error(&dir, "huge.gltf", gltf(&[tet(), (positions, huge)], None).to_string());
    names(e, &["huge.gltf: triangle 7 refers to a vertex beyond the 8 there are"]);
}

#[test]
fn meshes_from_bytes_and_their_buffers_from_the_files_given() {
    let dir = Scratch::new("mesh-bytes");
    let obj = TriangleMesh::load(&dir.file("tet.obj", TETRAHEDRON_OBJ)).unwrap();
    assert_eq!(TriangleMesh::from_bytes("tet.obj", TETRAHEDRON_OBJ.as_bytes()).unwrap(), obj);
    let e = TriangleMesh::from_bytes("tet.ply", b"ply\n").unwrap_err().to_string();
    names(e, &["tet.ply: unknown mesh format \".ply\""]);
    // The same glTF with its buffer in a file of its own, beside it.
    let mut external = gltf(&[tet()], None);
    let uri = external["buffers"][0]["uri"].as_str().unwrap().to_string();
    let (_, data) = uri.split_once(";base64,").unwrap();
    let bin = base64::engine::general_purpose::STANDARD.decode(data).unwrap();
    external["buffers"][0]["uri"] = "tet.bin".into();
    let text = external.to_string();
    dir.file("tet.bin", &bin);
    let from_disk = TriangleMesh::load(&dir.file("tet.gltf", &text)).unwrap();
    let files = std::collections::BTreeMap::from([("meshes/tet.bin".into(), bin)]);
    let dir_in_memory = std::path::Path::new("meshes");
    let given = TriangleMesh::parse_with("tet.gltf", text.as_bytes(), dir_in_memory, &files);
    assert_eq!(given.unwrap(), from_disk);
    let e = TriangleMesh::from_bytes("tet.gltf", text.as_bytes()).unwrap_err().to_string();
    names(e, &["tet.gltf: buffer 0 (tet.bin): not among the files given"]);
}
