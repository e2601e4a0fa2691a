//! `mesh`: the project's generated meshes, written as OBJ files.

use super::Outcome;
use std::path::{Path, PathBuf};

/// Write the project's generated meshes (U bracket, chess pawn) as OBJ files.
#[derive(clap::Args)]
pub struct MeshArgs {
    /// The directory to write them to.
    #[arg(long, default_value = "assets/meshes")]
    out: PathBuf,
}

impl MeshArgs {
    /// Writes `mesh::generate::shipped()` into `--out`; an error names
    /// the directory or file.
    pub fn run(self) -> Outcome {
        use coulomb_hands::scene::mesh::generate::{header, shipped};
        let named = |path: &Path, e: std::io::Error| format!("{}: {e}", path.display());
        std::fs::create_dir_all(&self.out).map_err(|e| named(&self.out, e))?;
        for (name, mesh) in shipped() {
            let path = self.out.join(format!("{name}.obj"));
            std::fs::write(&path, mesh.to_obj(&header(name))).map_err(|e| named(&path, e))?;
            println!("wrote {} ({} triangles)", path.display(), mesh.triangles.len());
        }
        Ok(())
    }
}
