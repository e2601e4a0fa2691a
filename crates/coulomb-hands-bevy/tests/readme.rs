//! The crate's README shows the example `tracked_hand`, which `cargo
//! test` builds: this keeps the two the same, and runs it as a user would.

use std::process::Command;

const EXAMPLE: &str = include_str!("../examples/tracked_hand/main.rs");

/// The example's code from its first `use`: what the README shows.
fn shown() -> &'static str {
    &EXAMPLE[EXAMPLE.find("use bevy::prelude::*;").expect("the example's uses")..]
}

#[test]
fn readme_shows_the_example_as_it_is_in_at_most_27_lines() {
    let readme = include_str!("../README.md");
    assert!(
        readme.contains(&format!("```rust\n{}```\n", shown())),
        "update README from the example"
    );
    assert!(shown().lines().count() <= 27, "{} lines", shown().lines().count());
}

#[test]
fn the_example_pushes_a_tracked_hand_that_touches_the_cube() {
    // `cargo test` builds the examples beside the test binaries' directory.
    let deps = std::env::current_exe().expect("the test binary");
    let exe =
        deps.parent().and_then(|d| d.parent()).expect("target dir").join("examples/tracked_hand");
    let out = Command::new(&exe).output().unwrap_or_else(|e| panic!("{}: {e}", exe.display()));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{}\n{}", stdout, String::from_utf8_lossy(&out.stderr));
    // The sweeping hand's lower fingers meet the cube's side, after it has
    // travelled the 9 cm from its start to the cube (0.45 s at 0.2 m/s).
    let touch = stdout.lines().next().unwrap_or_else(|| panic!("no touch:\n{stdout}"));
    assert!(touch.ends_with("touched the cube"), "{touch}");
    let t: f64 = touch.split(" s:").next().and_then(|t| t.parse().ok()).expect("a time");
    assert!((0.2..0.9).contains(&t), "touched at {t} s");
}
