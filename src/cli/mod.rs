//! The subcommands of the `coulomb-hands` binary, one file each: its
//! options, as the one struct clap fills, and how it runs and prints.
//! `options` holds the option groups several subcommands share, `args`
//! the value parsers.

pub mod args;
pub mod bench;
pub mod demo;
pub mod eval;
#[cfg(feature = "live")]
pub mod live;
pub mod mesh;
pub mod options;
pub mod replay;
pub mod report;
pub mod scenario;

use coulomb_hands::run::observe::ObjectSummary;

/// What a subcommand returns: its error, printed as `error: …` with exit
/// code 1 (or clap's own error, which `main` prints as clap does).
pub type Outcome = Result<(), Box<dyn std::error::Error>>;

/// A progress bar of `len` steps drawn with `template`, or a hidden one.
pub fn progress_bar(show: bool, len: u64, template: &str) -> indicatif::ProgressBar {
    if !show {
        return indicatif::ProgressBar::hidden();
    }
    let style = indicatif::ProgressStyle::with_template(template).expect("a valid template");
    indicatif::ProgressBar::new(len).with_style(style)
}

/// One line per object: how far it moved and how fast it went.
pub fn print_objects(objects: &[ObjectSummary]) {
    for o in objects {
        println!(
            "object {}: moved {:.3} m, max speed {:.3} m/s",
            o.name, o.displacement, o.max_speed
        );
    }
}
