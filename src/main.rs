//! `coulomb-hands`: the headless command line. Each subcommand's options
//! are one struct in its own file of `cli/`, which clap fills and which
//! runs the subcommand; this file lists the subcommands and turns the
//! outcome into the exit code.

mod cli;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    version,
    about = "Hands that move virtual objects only through Coulomb friction contact forces"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    Demo(cli::demo::DemoArgs),
    Replay(cli::replay::ReplayArgs),
    #[cfg(feature = "live")]
    Live(cli::live::LiveArgs),
    Scenario(cli::scenario::ScenarioArgs),
    Eval(cli::eval::EvalArgs),
    Report(cli::report::ReportArgs),
    Mesh(cli::mesh::MeshArgs),
    Bench(cli::bench::BenchArgs),
}

impl Command {
    fn run(self) -> cli::Outcome {
        match self {
            Command::Demo(args) => args.run(),
            Command::Replay(args) => args.run(),
            #[cfg(feature = "live")]
            Command::Live(args) => args.run(),
            Command::Scenario(args) => args.run(),
            Command::Eval(args) => args.run(),
            Command::Report(args) => args.run(),
            Command::Mesh(args) => args.run(),
            Command::Bench(args) => args.run(),
        }
    }
}

/// Parses the command line and runs the subcommand it names. A clap error
/// (a usage error, or the help or version it is asked for) comes back as
/// a `clap::Error`, for `main` to print as clap does.
fn run() -> cli::Outcome {
    let command = match Cli::try_parse()?.command {
        Some(command) => command,
        None => Command::Demo(cli::demo::DemoArgs::defaults()?),
    };
    command.run()
}

/// A reader that stops reading early (`coulomb-hands replay … | head`)
/// ends the program quietly, as it does other Unix tools, instead of
/// making `println!` panic on the closed pipe: Rust's runtime ignores
/// SIGPIPE, and this gives it back its default.
#[cfg(unix)]
fn end_quietly_on_a_closed_pipe() {
    // SAFETY: first thing in `main`, before any other thread exists;
    // `signal` with `SIG_DFL` only resets a disposition.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}

/// Exit codes: 0 on success (and for `--help` and `--version`), 2 on a
/// usage error (clap's), 1 on any other error, printed as `error: …`.
fn main() -> ExitCode {
    #[cfg(unix)]
    end_quietly_on_a_closed_pipe();
    let Err(error) = run() else { return ExitCode::SUCCESS };
    match error.downcast::<clap::Error>() {
        Ok(usage) => {
            // Help and version go to stdout, usage errors to stderr.
            usage.print().ok();
            ExitCode::from(u8::try_from(usage.exit_code()).unwrap_or(2))
        }
        Err(error) => {
            eprintln!("error: {error}");
            ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    /// clap's own checks of every subcommand's arguments (ids, conflicts,
    /// defaults that their parsers accept), which parsing runs only for
    /// the subcommand parsed.
    #[test]
    fn the_command_line_is_well_formed() {
        use clap::CommandFactory;
        super::Cli::command().debug_assert();
    }
}
