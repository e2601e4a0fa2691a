//! The book's figures of the bundled hand–object capture (TACO, Liu et
//! al., CVPR 2024, CC BY 4.0): the capture replayed with each method at the
//! default mass and material, as the report's "Real hands moving real
//! objects" shows it, drawn by the report's own plot functions into
//! `docs/book/src/images/captures-height.svg` and `captures-error.svg`.
//!
//! `cargo run --release --example capture_plots`

use coulomb_hands::output::report::{capture_errors, capture_heights};
use coulomb_hands::run::report::{BUNDLED_CAPTURE, CaptureInput};
use std::path::Path;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let input = CaptureInput::bundled()?.ok_or(format!("{BUNDLED_CAPTURE} is not here"))?;
    let runs = input.run_every_method();
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/book/src/images");
    for (file, svg) in [
        ("captures-height.svg", capture_heights(&runs)),
        ("captures-error.svg", capture_errors(&runs)),
    ] {
        let path = dir.join(file);
        std::fs::write(&path, svg + "\n").map_err(|e| format!("{}: {e}", path.display()))?;
        println!("wrote {}", path.display());
    }
    for m in &runs.methods {
        let (lift, of) = (m.simulated_lift_mm, m.captured_lift_mm);
        let error = m.error.as_ref().map_or(String::new(), |e| format!("; stopped: {e}"));
        println!("{}: lifted {lift:.0} of {of:.0} mm{error}", m.method);
    }
    Ok(())
}
