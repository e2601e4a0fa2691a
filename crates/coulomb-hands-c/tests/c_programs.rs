//! The C tests (`tests/c/*.c`): each compiled with the platform's C
//! compiler (through `cc`), linked against the static library this test
//! build made, and run; it prints what it measured and exits non-zero on a
//! failed check.

use std::path::{Path, PathBuf};
use std::process::Command;

/// Where cargo put the library for this test build (beside the test).
fn library_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("the test's own path");
    exe.parent().expect("the test's directory").to_path_buf()
}

/// Compiles `tests/c/{name}.c` against the static library and runs it in
/// `dir` (the repository's root, for data files); panics with its output
/// when it fails.
fn run_c_test(name: &str) {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let lib = library_dir().join("libcoulomb_hands_c.a");
    assert!(lib.exists(), "{} is missing: the test build makes it", lib.display());
    let out_dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("c-tests");
    std::fs::create_dir_all(&out_dir).unwrap();
    let exe = out_dir.join(name);
    let target = env!("COULOMB_HANDS_C_TARGET");
    let compiler = cc::Build::new()
        .target(target)
        .host(target)
        .opt_level(0)
        .cargo_metadata(false)
        .cargo_warnings(false)
        .warnings(true)
        .extra_warnings(true)
        .warnings_into_errors(true)
        .get_compiler();
    let mut cmd = compiler.to_command();
    cmd.arg(crate_dir.join(format!("tests/c/{name}.c")))
        .arg("-std=c11")
        .arg("-I")
        .arg(crate_dir.join("include"))
        .arg("-o")
        .arg(&exe)
        .arg(&lib)
        // What the Rust standard library needs of the system
        // (`rustc --print native-static-libs`).
        .args(["-lpthread", "-ldl", "-lm", "-lrt", "-lutil", "-lgcc_s"]);
    let built = cmd.output().expect("the C compiler runs");
    assert!(
        built.status.success(),
        "{name}.c did not compile:\n{}",
        String::from_utf8_lossy(&built.stderr)
    );
    let root = crate_dir.join("../..");
    let ran = Command::new(&exe).current_dir(root).output().expect("the C test runs");
    let stdout = String::from_utf8_lossy(&ran.stdout);
    println!("{stdout}");
    assert!(
        ran.status.success(),
        "{name} failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&ran.stderr)
    );
}

#[test]
fn a_pinch_holds_a_light_box_and_drops_a_heavy_one_built_in_and_hosted() {
    run_c_test("pinch");
}

#[test]
fn bad_input_gets_its_status_and_changes_nothing() {
    run_c_test("bad_input");
}
