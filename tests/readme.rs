//! README.md's sample outputs are the binary's real output: every
//! `console` block of the README is run and compared (trycmd).

#[test]
fn readme_examples_match_the_binary() {
    trycmd::TestCases::new().case("README.md");
}
