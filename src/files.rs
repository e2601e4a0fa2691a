//! Where the files that other files name come from: a scene's meshes, a
//! scenario's meshes and recordings, a glTF's buffers. A file names another
//! by a path relative to its own folder; the loader joins the two and asks
//! a [`Files`] for that path, and errors name it so.
//!
//! The path loaders (`Scene::load`, `Scenario::load`, `TriangleMesh::load`)
//! read the file system ([`FileSystem`]). Where there is none, as in a web
//! page, the text or bytes go to the loaders' `parse_with` beside them with
//! the files they name as bytes: a map from paths to bytes, or any function
//! of the path. Joined to the folder `""`, a path is the one the file
//! writes (`../assets/meshes/pawn.obj`).

use std::collections::BTreeMap;
use std::io;
use std::path::{Path, PathBuf};

/// A source of files by path.
pub trait Files {
    /// The bytes of the file at `path`, or why there are none.
    fn read(&self, path: &Path) -> io::Result<Vec<u8>>;
}

/// The file system ([`std::fs::read`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct FileSystem;

impl Files for FileSystem {
    fn read(&self, path: &Path) -> io::Result<Vec<u8>> {
        std::fs::read(path)
    }
}

/// Files held in memory, by path; any other path is not found.
impl Files for BTreeMap<PathBuf, Vec<u8>> {
    fn read(&self, path: &Path) -> io::Result<Vec<u8>> {
        self.get(path).cloned().ok_or_else(not_given)
    }
}

/// Any `Fn(&Path) -> io::Result<Vec<u8>>` is a source of files.
impl<F: Fn(&Path) -> io::Result<Vec<u8>>> Files for F {
    fn read(&self, path: &Path) -> io::Result<Vec<u8>> {
        self(path)
    }
}

/// No files: every path is not found (only the bytes given are read).
#[derive(Debug, Clone, Copy, Default)]
pub struct NoFiles;

impl Files for NoFiles {
    fn read(&self, _: &Path) -> io::Result<Vec<u8>> {
        Err(not_given())
    }
}

/// The error for a path a source in memory does not hold.
pub fn not_given() -> io::Error {
    io::Error::new(io::ErrorKind::NotFound, "not among the files given")
}
