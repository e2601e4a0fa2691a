//! The subcommands of the `coulomb-hands` binary, one file each, and what they share.

pub mod args;
pub mod bench;
pub mod demo;
pub mod eval;
pub mod live;
pub mod options;
pub mod replay;
pub mod report;
pub mod scenario;

use coulomb_hands::RunError;
use coulomb_hands::output::trace::TraceFile;

/// A progress bar of `len` steps drawn with `template`, or a hidden one.
pub fn progress_bar(show: bool, len: u64, template: &str) -> indicatif::ProgressBar {
    if !show {
        return indicatif::ProgressBar::hidden();
    }
    let style = indicatif::ProgressStyle::with_template(template).expect("a valid template");
    indicatif::ProgressBar::new(len).with_style(style)
}

/// A buffered output file; its errors name it.
pub fn create(path: &std::path::Path) -> Result<TraceFile, RunError> {
    Ok(TraceFile::create(path)?)
}

/// Writes `mesh::generate::shipped()` as OBJ files into `out`.
pub fn write_meshes(out: &std::path::Path) -> std::io::Result<()> {
    use coulomb_hands::scene::mesh::generate::{header, shipped};
    let named = |path: &std::path::Path, e: std::io::Error| {
        std::io::Error::new(e.kind(), format!("{}: {e}", path.display()))
    };
    std::fs::create_dir_all(out).map_err(|e| named(out, e))?;
    for (name, mesh) in shipped() {
        let path = out.join(format!("{name}.obj"));
        std::fs::write(&path, mesh.to_obj(&header(name))).map_err(|e| named(&path, e))?;
        println!("wrote {} ({} triangles)", path.display(), mesh.triangles.len());
    }
    Ok(())
}
