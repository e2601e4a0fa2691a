//! Tells the C tests (`tests/c_programs.rs`) which target the library was
//! built for, so that `cc` picks the C compiler and flags for the same.

fn main() {
    let target = std::env::var("TARGET").unwrap_or_default();
    println!("cargo:rustc-env=COULOMB_HANDS_C_TARGET={target}");
    println!("cargo:rerun-if-changed=build.rs");
}
