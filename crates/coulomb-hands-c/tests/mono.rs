//! The Unity package's C# (`bindings/unity/Runtime`, but for the one file
//! that needs UnityEngine), compiled with Mono's `mcs` with its tests
//! (`bindings/unity/Tests/Mono`) and run under `mono` against the shared
//! library this test build made, placed in the package's Linux plugin
//! folder. Mono is Debian's `mono-devel`, in
//! README's install line.

use coulomb_hands_c::{ChContact, ChHostBody, ChObjectState, ChWrench};
use std::path::{Path, PathBuf};
use std::process::Command;

fn sources(dir: &Path) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "cs"))
        .collect();
    files.sort();
    files
}

#[test]
fn the_unity_package_pinches_and_refuses_bad_input_under_mono() {
    let unity = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../bindings/unity");
    let library = std::env::current_exe().unwrap().parent().unwrap().to_path_buf();
    assert!(
        library.join("libcoulomb_hands_c.so").exists(),
        "the shared library is missing beside the test"
    );
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("mono");
    std::fs::create_dir_all(&out).unwrap();
    // Loaded from the package's own Linux plugin folder, as its README
    // says to place it (a copy of the folder, so the checkout stays clean).
    let platform = Path::new("Runtime/Plugins/Linux/x86_64");
    assert!(unity.join(platform).is_dir(), "the package has no {}", platform.display());
    let plugins = out.join(platform);
    std::fs::create_dir_all(&plugins).unwrap();
    let name = "libcoulomb_hands_c.so";
    std::fs::copy(library.join(name), plugins.join(name)).unwrap();
    let exe = out.join("CoulombHandsTests.exe");
    let mut files = sources(&unity.join("Runtime"));
    files.extend(sources(&unity.join("Tests/Mono")));
    let compiled = Command::new("mcs")
        .arg("-warnaserror")
        .arg(format!("-out:{}", exe.display()))
        .args(&files)
        .output()
        .expect("mcs runs: install mono-devel (README's apt line)");
    assert!(
        compiled.status.success(),
        "mcs:\n{}{}",
        String::from_utf8_lossy(&compiled.stdout),
        String::from_utf8_lossy(&compiled.stderr)
    );
    let sizes = [
        size_of::<ChHostBody>(),
        size_of::<ChWrench>(),
        size_of::<ChObjectState>(),
        size_of::<ChContact>(),
    ];
    let ran = Command::new("mono")
        .arg(&exe)
        .args(sizes.map(|s| s.to_string()))
        .arg(unity.join("Samples~/HandCubeTable"))
        .env("LD_LIBRARY_PATH", &plugins)
        .current_dir(unity.join("../.."))
        .output()
        .expect("mono runs: install mono-devel (README's apt line)");
    let stdout = String::from_utf8_lossy(&ran.stdout);
    println!("{stdout}");
    assert!(
        ran.status.success(),
        "the C# tests failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&ran.stderr)
    );
}
