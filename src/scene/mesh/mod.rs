//! Arbitrary object shapes (§3.7): triangle meshes from OBJ, STL and
//! glTF/GLB files, and how a concave mesh becomes a rigid body.
//!
//! A physics engine collides dynamic bodies as convex pieces, so a concave
//! mesh is either voxelized into boxes at a chosen voxel size (the thesis's
//! approach) or split into convex parts (V-HACD). Static scenery may stay
//! an exact triangle mesh. A hand's contacts need no convex pieces, so a
//! closed mesh may also be touched exactly ([`TriangleMesh::solid`]) while
//! the engine moves its pieces. [`generate`] builds the project's own
//! concave test shapes.

pub mod generate;
mod solid;
mod voxels;

use crate::files::{FileSystem, Files, NoFiles};
use glam::Vec3;
use std::path::Path;

/// An indexed triangle mesh (metres, counter-clockwise outward faces).
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct TriangleMesh {
    /// Vertex positions (m).
    pub vertices: Vec<Vec3>,
    /// Vertex indices, three per triangle.
    pub triangles: Vec<[u32; 3]>,
}

/// Why a mesh file was rejected: the file, and its [`MeshProblem`].
pub type MeshError = crate::file_error::FileError;

/// What is wrong with a mesh, or with making a body of it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MeshProblem {
    /// The file's extension (lower case, or empty when it has none) is
    /// none of the formats read.
    #[error(
        "unknown mesh format {} (obj, stl, gltf or glb)",
        if .0.is_empty() { "(no file extension)".to_string() } else { format!("\".{}\"", .0) }
    )]
    UnknownFormat(String),
    /// The file could not be read or parsed; the reader's own message.
    #[error("{0}")]
    Unreadable(String),
    /// Nothing to collide with.
    #[error("the mesh has no triangles")]
    NoTriangles,
    /// A vertex is NaN or infinite.
    #[error("vertex {index} is not finite: {vertex:?}")]
    NonFiniteVertex {
        /// Its index.
        index: usize,
        /// Its position.
        vertex: Vec3,
    },
    /// A triangle names a vertex that does not exist.
    #[error("triangle {triangle} refers to a vertex beyond the {vertices} there are")]
    IndexOutOfRange {
        /// The triangle's index.
        triangle: usize,
        /// How many vertices there are.
        vertices: u32,
    },
    /// The mesh is flat along some axis (or all but vanishingly small), so
    /// it has no inside.
    #[error("the mesh has no volume: it is flat ({size:?} across)")]
    Flat {
        /// Its bounding box's size (m).
        size: Vec3,
    },
    /// The voxel size is not positive, would make too many cells, or is
    /// larger than the mesh.
    #[error(
        "voxel size {voxel} m is not positive, or too small or too large for a mesh {size:?} m \
         across"
    )]
    VoxelSize {
        /// The voxel size asked for (m).
        voxel: f32,
        /// The mesh's bounding box's size (m).
        size: Vec3,
    },
    /// No voxel centre is inside the mesh.
    #[error("voxel size {voxel} m leaves no voxel inside the mesh")]
    NoVoxels {
        /// The voxel size asked for (m).
        voxel: f32,
    },
    /// Some edges are not shared by a triangle running the other way along
    /// them, so the mesh has holes or flipped triangles and no inside a
    /// point can be told to be in.
    #[error(
        "the mesh is not closed: {edges} of its edges are not matched by a triangle running the \
         other way along them (a hole or a flipped triangle)"
    )]
    NotClosed {
        /// How many edges are unmatched.
        edges: usize,
    },
    /// Its triangles wind inwards: their enclosed volume is negative.
    #[error("the mesh's triangles wind inwards (enclosed volume {volume:e}): flip them")]
    InsideOut {
        /// The signed volume it encloses (the file's units³).
        volume: f32,
    },
    /// More boxes than allowed.
    #[error("voxel size {voxel} m gives {boxes} boxes, more than {max}: use larger voxels")]
    TooManyVoxels {
        /// The voxel size asked for (m).
        voxel: f32,
        /// The boxes it would give.
        boxes: usize,
        /// The most allowed.
        max: usize,
    },
}

impl From<String> for MeshProblem {
    fn from(reason: String) -> Self {
        MeshProblem::Unreadable(reason)
    }
}

impl From<&str> for MeshProblem {
    fn from(reason: &str) -> Self {
        MeshProblem::Unreadable(reason.to_string())
    }
}

impl TriangleMesh {
    /// Loads `.obj`, `.stl`, `.gltf` or `.glb` (all meshes of the file, in
    /// its units), then [`Self::check`]s it.
    pub fn load(path: &Path) -> Result<TriangleMesh, MeshError> {
        Self::load_from(path, &FileSystem)
    }

    /// [`Self::load`], the file and a glTF's buffer files beside it read
    /// from `files`.
    pub fn load_from(path: &Path, files: &dyn Files) -> Result<TriangleMesh, MeshError> {
        let file = path.display().to_string();
        let bytes = files.read(path).map_err(|e| MeshError::new(&file, e.to_string()))?;
        Self::parse_with(&file, &bytes, path.parent().unwrap_or(Path::new(".")), files)
    }

    /// Parses the bytes of a mesh file in the format its name's extension
    /// says (`.obj`, `.stl`, `.gltf` or `.glb`), then [`Self::check`]s it.
    /// A glTF's external buffer files are read relative to `dir`; an OBJ's
    /// material libraries are not read.
    pub fn parse(file: &str, bytes: &[u8], dir: &Path) -> Result<TriangleMesh, MeshError> {
        Self::parse_with(file, bytes, dir, &FileSystem)
    }

    /// [`Self::parse`] of the file's bytes alone: a glTF's external buffer
    /// files are errors (its data URIs and a GLB's own buffer are read).
    pub fn from_bytes(file: &str, bytes: &[u8]) -> Result<TriangleMesh, MeshError> {
        Self::parse_with(file, bytes, Path::new(""), &NoFiles)
    }

    /// [`Self::parse`], a glTF's external buffer files read from `files`
    /// at their paths joined to `dir`.
    pub fn parse_with(
        file: &str,
        bytes: &[u8],
        dir: &Path,
        files: &dyn Files,
    ) -> Result<TriangleMesh, MeshError> {
        let fail = |problem: MeshProblem| MeshError::new(file, problem.to_string());
        let ext = Path::new(file)
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .unwrap_or_default();
        let mesh = match ext.as_str() {
            "obj" => parse_obj(bytes),
            "stl" => parse_stl(bytes),
            "gltf" | "glb" => parse_gltf(bytes, dir, files),
            other => return Err(fail(MeshProblem::UnknownFormat(other.to_string()))),
        }
        .map_err(fail)?;
        mesh.check().map_err(fail)?;
        Ok(mesh)
    }

    /// A usable solid: at least one triangle, finite vertices, indices in
    /// range, and a volume: no axis shorter than 1e-6 of the longest, nor
    /// than 1e-9 (in the file's units).
    pub fn check(&self) -> Result<(), MeshProblem> {
        if self.triangles.is_empty() {
            return Err(MeshProblem::NoTriangles);
        }
        if let Some(index) = self.vertices.iter().position(|v| !v.is_finite()) {
            return Err(MeshProblem::NonFiniteVertex { index, vertex: self.vertices[index] });
        }
        let vertices = self.vertices.len() as u32;
        if let Some(triangle) = self.triangles.iter().position(|t| t.iter().any(|&k| k >= vertices))
        {
            return Err(MeshProblem::IndexOutOfRange { triangle, vertices });
        }
        let (lo, hi) = self.bounds();
        let size = hi - lo;
        // Absolutely too: parry's voxelization asserts on a 1e-39 mesh.
        if size.min_element() <= (1e-6 * size.max_element()).max(1e-9) {
            return Err(MeshProblem::Flat { size });
        }
        Ok(())
    }

    /// Axis-aligned bounds (min, max).
    pub fn bounds(&self) -> (Vec3, Vec3) {
        let lo = self.vertices.iter().copied().fold(Vec3::splat(f32::INFINITY), Vec3::min);
        let hi = self.vertices.iter().copied().fold(Vec3::splat(f32::NEG_INFINITY), Vec3::max);
        (lo, hi)
    }

    /// The same mesh scaled about the origin.
    pub fn scaled(&self, k: f32) -> TriangleMesh {
        TriangleMesh {
            vertices: self.vertices.iter().map(|v| *v * k).collect(),
            triangles: self.triangles.clone(),
        }
    }

    /// Wavefront OBJ text of the mesh (1-based indices).
    pub fn to_obj(&self, comment: &str) -> String {
        let mut out = String::new();
        for line in comment.lines() {
            out.push_str(&format!("# {line}\n"));
        }
        for v in &self.vertices {
            out.push_str(&format!("v {} {} {}\n", v.x, v.y, v.z));
        }
        for t in &self.triangles {
            out.push_str(&format!("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1));
        }
        out
    }
}

/// Every face, line and point index of OBJ text must name a position,
/// texture coordinate or normal defined before it (1-based, or negative
/// counting back). tobj does its index arithmetic unchecked, so an index of
/// 0 or far out of range overflows it (a panic in debug builds).
fn check_obj_indices(text: &str) -> Result<(), MeshProblem> {
    let mut counts = [0usize; 3];
    for (n, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => counts[0] += 1,
            Some("vt") => counts[1] += 1,
            Some("vn") => counts[2] += 1,
            Some("f" | "l" | "p") => {
                for word in words {
                    for (k, part) in word.split('/').enumerate().take(3) {
                        let Ok(i) = part.parse::<isize>() else { continue };
                        if i == 0 || i.unsigned_abs() > counts[k] {
                            let kind = ["position", "texture coordinate", "normal"][k];
                            let why = format!(
                                "line {}: {kind} index {i} is not one of the {} defined before it",
                                n + 1,
                                counts[k]
                            );
                            return Err(MeshProblem::Unreadable(why));
                        }
                    }
                }
            }
            _ => {}
        }
    }
    Ok(())
}

fn parse_obj(bytes: &[u8]) -> Result<TriangleMesh, MeshProblem> {
    check_obj_indices(std::str::from_utf8(bytes).map_err(|_| "an OBJ file must be UTF-8 text")?)?;
    let options = tobj::LoadOptions { triangulate: true, single_index: true, ..Default::default() };
    // Materials are not used, so material libraries are not read.
    let (models, _) =
        tobj::load_obj_buf(&mut std::io::Cursor::new(bytes), &options, |_| Ok(Default::default()))
            .map_err(|e| e.to_string())?;
    let mut mesh = TriangleMesh::default();
    for model in models {
        let m = model.mesh;
        let base = mesh.vertices.len() as u32;
        mesh.vertices.extend(m.positions.chunks_exact(3).map(|p| Vec3::new(p[0], p[1], p[2])));
        mesh.triangles
            .extend(m.indices.chunks_exact(3).map(|t| [base + t[0], base + t[1], base + t[2]]));
    }
    Ok(mesh)
}

fn parse_stl(bytes: &[u8]) -> Result<TriangleMesh, MeshProblem> {
    let stl = stl_io::read_stl(&mut std::io::Cursor::new(bytes))
        .map_err(|e| format!("not a readable STL file: {e}"))?;
    Ok(TriangleMesh {
        vertices: stl.vertices.iter().map(|v| Vec3::new(v[0], v[1], v[2])).collect(),
        triangles: stl.faces.iter().map(|f| f.vertices.map(|k| k as u32)).collect(),
    })
}

/// Every mesh primitive of the default scene (or of all root nodes), with
/// the node transforms applied. Buffers may be the GLB's binary chunk,
/// files in `dir` (next to the `.gltf`) read from `files`, or base64 data
/// URIs.
fn parse_gltf(bytes: &[u8], dir: &Path, files: &dyn Files) -> Result<TriangleMesh, MeshProblem> {
    use base64::Engine;
    // The gltf crate computes `length - 12` unchecked (a panic in debug builds).
    if let Some(length) = bytes.strip_prefix(b"glTF").and_then(|b| b.get(4..8)) {
        let length = u32::from_le_bytes(length.try_into().expect("4 bytes"));
        if length < 12 {
            return Err(format!("GLB length {length} is shorter than its 12-byte header").into());
        }
    }
    let unreadable = |e: gltf::Error| format!("not a readable glTF file: {e}");
    let gltf::Gltf { document, blob } =
        gltf::Gltf::from_slice_without_validation(bytes).map_err(unreadable)?;
    // gltf-json's validation indexes a primitive's POSITION accessor unchecked.
    let json = document.into_json();
    for (m, mesh) in json.meshes.iter().enumerate() {
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            if let Some(a) =
                primitive.attributes.values().find(|a| a.value() >= json.accessors.len())
            {
                let n = json.accessors.len();
                return Err(
                    format!("mesh {m} primitive {p}: accessor {a} is not one of {n}").into()
                );
            }
        }
    }
    let gltf = gltf::Document::from_json(json).map_err(unreadable)?;
    let mut buffers = Vec::new();
    for buffer in gltf.buffers() {
        let data = match buffer.source() {
            gltf::buffer::Source::Bin => blob.clone().ok_or_else(|| {
                format!("buffer {} has no uri, and the file no GLB binary chunk", buffer.index())
            })?,
            gltf::buffer::Source::Uri(uri) => match uri.strip_prefix("data:") {
                Some(rest) => {
                    let (_, b64) = rest
                        .split_once(";base64,")
                        .ok_or(format!("buffer {}: unsupported data URI", buffer.index()))?;
                    base64::engine::general_purpose::STANDARD
                        .decode(b64)
                        .map_err(|e| format!("buffer {}: {e}", buffer.index()))?
                }
                None => files
                    .read(&dir.join(uri))
                    .map_err(|e| format!("buffer {} ({uri}): {e}", buffer.index()))?,
            },
        };
        buffers.push(data);
    }
    let mut mesh = TriangleMesh::default();
    let roots: Vec<gltf::Node> = match gltf.default_scene().or_else(|| gltf.scenes().next()) {
        Some(scene) => scene.nodes().collect(),
        None => gltf.nodes().collect(),
    };
    let mut stack: Vec<(gltf::Node, glam::Mat4)> =
        roots.into_iter().map(|n| (n, glam::Mat4::IDENTITY)).collect();
    let mut visits = 0;
    while let Some((node, parent)) = stack.pop() {
        visits += 1;
        if visits > gltf.nodes().len() {
            return Err("the node hierarchy is not a tree (a node is its own ancestor)".into());
        }
        let transform = parent * glam::Mat4::from_cols_array_2d(&node.transform().matrix());
        if let Some(m) = node.mesh() {
            for primitive in m.primitives() {
                if primitive.mode() != gltf::mesh::Mode::Triangles {
                    continue;
                }
                use gltf::accessor::{DataType, Dimensions};
                let Some(positions) = primitive.get(&gltf::Semantic::Positions) else { continue };
                check_accessor(&positions, &buffers, &[DataType::F32], Dimensions::Vec3)?;
                if let Some(indices) = primitive.indices() {
                    let types = [DataType::U8, DataType::U16, DataType::U32];
                    check_accessor(&indices, &buffers, &types, Dimensions::Scalar)?;
                }
                let reader = primitive.reader(|b| buffers.get(b.index()).map(Vec::as_slice));
                let Some(positions) = reader.read_positions() else {
                    let (mesh, primitive) = (m.index(), primitive.index());
                    let why = "POSITION is missing or runs past the end of its buffer";
                    return Err(format!("mesh {mesh} primitive {primitive}: {why}").into());
                };
                let base = mesh.vertices.len() as u32;
                mesh.vertices.extend(positions.map(|p| transform.transform_point3(Vec3::from(p))));
                let count = mesh.vertices.len() as u32 - base;
                let indices: Vec<u32> = match (reader.read_indices(), primitive.indices()) {
                    (Some(i), _) => i.into_u32().collect(),
                    (None, None) => (0..count).collect(),
                    (None, Some(_)) => {
                        let (mesh, primitive) = (m.index(), primitive.index());
                        let why = "its indices run past the end of their buffer";
                        return Err(format!("mesh {mesh} primitive {primitive}: {why}").into());
                    }
                };
                // An index past the vertices saturates and fails `check`.
                mesh.triangles.extend(
                    indices
                        .chunks_exact(3)
                        .map(|t| [t[0], t[1], t[2]].map(|i| base.saturating_add(i))),
                );
            }
        }
        stack.extend(node.children().map(|c| (c, transform)));
    }
    Ok(mesh)
}

/// The gltf crate's reader trusts an accessor's type and extent (it
/// panics on float indices, and on a count or stride that overflows): so
/// its element type, and that its elements lie within its buffer view and
/// the view within its buffer, are checked first. Sparse accessors are not
/// read.
fn check_accessor(
    accessor: &gltf::Accessor,
    buffers: &[Vec<u8>],
    types: &[gltf::accessor::DataType],
    dimensions: gltf::accessor::Dimensions,
) -> Result<(), MeshProblem> {
    let fail =
        |why: String| MeshProblem::Unreadable(format!("accessor {}: {why}", accessor.index()));
    let (ty, dims) = (accessor.data_type(), accessor.dimensions());
    if !types.contains(&ty) || dims != dimensions {
        return Err(fail(format!("{dims:?} of {ty:?}, expected {dimensions:?} of {types:?}")));
    }
    if accessor.sparse().is_some() {
        return Err(fail("sparse accessors are not supported".into()));
    }
    let Some(view) = accessor.view() else { return Ok(()) };
    let size = accessor.size();
    let stride = view.stride().unwrap_or(size);
    let end = accessor
        .count()
        .checked_sub(1)
        .and_then(|n| n.checked_mul(stride))
        .and_then(|n| n.checked_add(size))
        .and_then(|n| n.checked_add(accessor.offset()));
    let buffer = buffers.get(view.buffer().index()).map_or(0, Vec::len);
    let view_end = view.offset().checked_add(view.length());
    match (end, view_end) {
        (Some(end), Some(view_end))
            if stride >= size && end <= view.length() && view_end <= buffer =>
        {
            Ok(())
        }
        _ => Err(fail(format!(
            "{} elements of {size} bytes every {stride} from byte {} do not fit buffer view {} \
             ({} bytes from byte {} of a {buffer}-byte buffer)",
            accessor.count(),
            accessor.offset(),
            view.index(),
            view.length(),
            view.offset()
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp(name: &str, contents: &[u8]) -> std::path::PathBuf {
        let path =
            std::env::temp_dir().join(format!("coulomb-hands-{}-{name}", std::process::id()));
        std::fs::write(&path, contents).unwrap();
        path
    }

    #[test]
    fn obj_stl_and_gltf_load_the_same_solid() {
        let cube = generate::u_bracket(0.04, 0.03, 0.02, 0.01);
        let obj = temp("u.obj", cube.to_obj("test").as_bytes());
        let from_obj = TriangleMesh::load(&obj).unwrap();
        assert_eq!(from_obj.triangles.len(), cube.triangles.len());

        // Binary STL via stl_io's writer.
        let triangles: Vec<stl_io::Triangle> = cube
            .triangles
            .iter()
            .map(|t| stl_io::Triangle {
                normal: stl_io::Normal::new([0.0; 3]),
                vertices: t.map(|k| stl_io::Vertex::new(cube.vertices[k as usize].to_array())),
            })
            .collect();
        let mut bytes = Vec::new();
        stl_io::write_stl(&mut bytes, triangles.iter()).unwrap();
        let from_stl = TriangleMesh::load(&temp("u.stl", &bytes)).unwrap();
        assert_eq!(from_stl.triangles.len(), cube.triangles.len());

        // glTF with an embedded base64 buffer and a node translation.
        let gltf = generate::to_gltf(&cube, Vec3::new(0.0, 1.0, 0.0));
        let from_gltf = TriangleMesh::load(&temp("u.gltf", gltf.as_bytes())).unwrap();
        assert_eq!(from_gltf.triangles.len(), cube.triangles.len());
        let ((a, b), (c, d)) = (from_obj.bounds(), from_gltf.bounds());
        assert!(
            (a + Vec3::Y - c).length() < 1e-6 && (b + Vec3::Y - d).length() < 1e-6,
            "node transform applied"
        );
        let from_glb =
            TriangleMesh::load(&temp("u.glb", &generate::to_glb(&cube, Vec3::new(0.0, 1.0, 0.0))))
                .unwrap();
        assert_eq!(
            (from_glb.vertices, from_glb.triangles),
            (from_gltf.vertices, from_gltf.triangles),
            "GLB = glTF"
        );
        std::fs::remove_file(obj).ok();
    }

    #[test]
    fn bad_meshes_are_errors_naming_the_file() {
        let missing = TriangleMesh::load(Path::new("no-such.obj")).unwrap_err();
        assert_eq!(missing.file, "no-such.obj");
        let flat = temp("flat.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        assert!(TriangleMesh::load(&flat).unwrap_err().reason.contains("no volume"));
        let nan = temp("nan.obj", b"v 0 0 0\nv 1 0 0\nv 0 nan 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n");
        let e = TriangleMesh::load(&nan).unwrap_err().to_string();
        assert!(e.contains("nan.obj") && (e.contains("not finite") || e.contains("parse")), "{e}");
        let bad = temp("x.ply", b"ply");
        assert!(TriangleMesh::load(&bad).unwrap_err().reason.contains("unknown mesh format"));
    }

    #[test]
    fn voxel_boxes_fill_the_u_but_not_its_gap() {
        let u = generate::u_bracket(0.06, 0.04, 0.02, 0.01);
        let boxes = u.voxel_boxes(0.005, 4096).unwrap();
        let inside =
            |p: Vec3| boxes.iter().any(|(c, h)| ((p - *c).abs() - *h).max_element() <= 1e-6);
        assert!(inside(Vec3::new(-0.025, 0.02, 0.0)), "an arm is solid");
        assert!(inside(Vec3::new(0.0, 0.005, 0.0)), "the base is solid");
        assert!(!inside(Vec3::new(0.0, 0.03, 0.0)), "the gap is empty");
        let volume: f32 = boxes.iter().map(|(_, h)| 8.0 * h.x * h.y * h.z).sum();
        let exact = 0.06 * 0.01 * 0.02 + 2.0 * 0.01 * 0.03 * 0.02;
        assert!((volume / exact - 1.0).abs() < 0.15, "voxel volume {volume} vs {exact}");
        assert!(u.voxel_boxes(0.0001, 100).is_err(), "too many boxes is an error");
    }
}
