//! The checked-in header is what cbindgen makes of the crate now: a change
//! to the ABI that forgot the header fails here.

use std::path::Path;

#[test]
fn the_checked_in_header_is_the_one_cbindgen_generates() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(dir.join("cbindgen.toml")).expect("cbindgen.toml");
    let mut generated = Vec::new();
    cbindgen::Builder::new()
        .with_crate(dir)
        .with_config(config)
        .generate()
        .expect("cbindgen reads the crate")
        .write(&mut generated);
    let path = dir.join("include/coulomb_hands.h");
    if std::env::var_os("COULOMB_HANDS_BLESS").is_some() {
        std::fs::write(&path, &generated).expect("the header is writable");
    }
    let checked_in = std::fs::read(&path).unwrap_or_default();
    assert!(
        checked_in == generated,
        "{} is stale: regenerate it with COULOMB_HANDS_BLESS=1 cargo test -p coulomb-hands-c \
         --test header, and review the change",
        path.display()
    );
}

#[test]
fn the_unity_package_declares_every_function_of_the_header() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let header = std::fs::read_to_string(dir.join("include/coulomb_hands.h")).unwrap();
    let native =
        std::fs::read_to_string(dir.join("../../bindings/unity/Runtime/Native.cs")).unwrap();
    let functions: Vec<&str> = header
        .split(|c: char| !(c.is_alphanumeric() || c == '_'))
        .filter(|w| w.starts_with("ch_"))
        .collect();
    assert!(functions.len() > 15, "{functions:?}");
    for f in functions {
        assert!(native.contains(&format!(" {f}(")), "Native.cs does not declare {f}");
    }
    let (_, version) = header.split_once("#define CH_ABI_VERSION ").expect("the ABI version");
    let version = version.split_whitespace().next().unwrap_or_default();
    assert!(native.contains(&format!("AbiVersion = {version};")), "Native.cs's ABI version");
}
