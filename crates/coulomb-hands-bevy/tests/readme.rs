//! README's "In a Bevy app" shows the example `scenario.rs`, which `cargo
//! test` builds; this keeps the two the same.

#[test]
fn readme_shows_the_scenario_example_as_it_is() {
    let readme = include_str!("../../../README.md");
    let example = include_str!("../examples/scenario.rs");
    let code = &example[example.find("use bevy::prelude::*;").unwrap()..];
    assert!(readme.contains(&format!("```rust\n{code}```\n")), "update README from the example");
}
