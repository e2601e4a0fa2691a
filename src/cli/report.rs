//! `report`: the self-contained HTML report (`output::report`), with the
//! scenarios and replays run here and the accuracy study and benchmark
//! read from their JSON.

use super::progress_bar;
use coulomb_hands::output::report::{
    AccuracyStudy, BenchReport, Header, ReportData, Sourced, html, utc_date,
};
use coulomb_hands::run::report::{ReplayInput, bundled_recordings, scenario_run};
use coulomb_hands::run::scenario::{Scenario, shipped};
use std::path::{Path, PathBuf};

pub struct ReportArgs<'a> {
    pub out: &'a Path,
    pub accuracy: Option<&'a Path>,
    pub bench: Option<&'a Path>,
    pub scenarios: Option<&'a [String]>,
    pub replays: Option<&'a [PathBuf]>,
}

/// Checks that `dir` can be written (making it), before any work: a probe
/// file is written and removed.
fn writable(dir: &Path) -> Result<(), String> {
    let fail = |e: std::io::Error| format!("--out {}: cannot write there: {e}", dir.display());
    std::fs::create_dir_all(dir).map_err(fail)?;
    let probe = dir.join(format!(".coulomb-hands-probe-{}", std::process::id()));
    std::fs::write(&probe, b"").map_err(fail)?;
    std::fs::remove_file(&probe).map_err(fail)
}

/// `file`'s data with its source, if a file was given.
fn read<T>(
    file: Option<&Path>,
    load: fn(&Path) -> Result<T, coulomb_hands::FileError>,
    command: &str,
) -> Result<Option<Sourced<T>>, coulomb_hands::FileError> {
    let Some(file) = file else { return Ok(None) };
    let source = format!("{}, written by {command}", file.display());
    Ok(Some(Sourced { source, data: load(file)? }))
}

/// The command line as typed, the program by its file name.
fn command_line() -> String {
    let mut args = std::env::args();
    let program = args.next().map(PathBuf::from);
    let program = program.as_ref().and_then(|p| p.file_name()).map(|p| p.to_string_lossy());
    let quote = |a: String| if a.contains([' ', '"', '\'']) { format!("{a:?}") } else { a };
    let mut line = program.map_or("coulomb-hands".into(), |p| p.into_owned());
    for a in args.map(quote) {
        line.push(' ');
        line.push_str(&a);
    }
    line
}

fn header() -> Header {
    let secs = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH);
    let cores = std::thread::available_parallelism().map_or(0, |n| n.get());
    let profile = if cfg!(debug_assertions) { "debug" } else { "release" };
    let features =
        if cfg!(feature = "enhanced-determinism") { ", enhanced-determinism" } else { "" };
    Header {
        version: env!("CARGO_PKG_VERSION").to_string(),
        date: secs.map_or("unknown".into(), |d| utc_date(d.as_secs())),
        machine: format!("{cores} cores, {} {}", std::env::consts::OS, std::env::consts::ARCH),
        build: format!("{profile}{features}"),
        command: command_line(),
    }
}

/// Writes `out/index.html`: checks `out` and reads every input first, then
/// runs the scenarios and replays with a progress bar on a terminal.
pub fn report(args: ReportArgs) -> Result<(), Box<dyn std::error::Error>> {
    writable(args.out)?;
    let accuracy = read(args.accuracy, AccuracyStudy::load, "coulomb-hands eval accuracy --json")?;
    let bench = read(args.bench, BenchReport::load, "coulomb-hands bench --json")?;
    let names: Vec<String> = match args.scenarios {
        Some(names) => names.to_vec(),
        None => shipped().iter().map(|s| s.0.to_string()).collect(),
    };
    let scenarios = names.iter().map(|n| Scenario::find(n)).collect::<Result<Vec<_>, _>>()?;
    let files = args.replays.map_or_else(bundled_recordings, <[PathBuf]>::to_vec);
    let inputs = files.iter().map(|f| ReplayInput::load(f)).collect::<Result<Vec<_>, _>>()?;

    use std::io::IsTerminal;
    let runs = (scenarios.len() + inputs.len()) as u64;
    let template = "{bar:30} {pos}/{len} {msg} ({elapsed})";
    let bar = progress_bar(std::io::stderr().is_terminal(), runs, template);
    let mut scenario_runs = Vec::new();
    for s in &scenarios {
        bar.set_message(format!("scenario {}", s.name));
        scenario_runs.push(scenario_run(s));
        bar.inc(1);
    }
    let mut replay_runs = Vec::new();
    for input in &inputs {
        bar.set_message(format!("replay {}", input.name));
        replay_runs.push(input.run());
        bar.inc(1);
    }
    bar.finish_and_clear();

    let header = header();
    let passed = scenario_runs.iter().filter(|r| r.passed).count();
    let summary = format!(
        "{} scenarios ({passed} passed), {} replays; accuracy: {}, bench: {}",
        scenario_runs.len(),
        replay_runs.len(),
        if accuracy.is_some() { "given" } else { "not given" },
        if bench.is_some() { "given" } else { "not given" },
    );
    let (n, build) = (scenario_runs.len(), &header.build);
    let which = match args.scenarios {
        None => format!("every shipped scenario ({n})"),
        Some(_) => format!("the {n} scenario(s) named by --scenarios"),
    };
    let scenarios = Sourced {
        source: format!("run by this command ({build} build): {which}"),
        data: scenario_runs,
    };
    let n = replay_runs.len();
    let which = match args.replays {
        None => format!("every Leap Motion recording in data/leap/ ({n})"),
        Some(_) => format!("the {n} recording(s) named by --replays"),
    };
    let replays = Sourced {
        source: format!(
            "replayed by this command: {which}, at the 1 kHz physics rate with automatic γ \
             (Eq. 3.11) and a box at each one's first grasp (4.5 cm, 50 g in a fist; 2 cm, \
             10 g otherwise)"
        ),
        data: replay_runs,
    };
    let data =
        ReportData { header, accuracy, bench, scenarios: Some(scenarios), replays: Some(replays) };
    let path = args.out.join("index.html");
    std::fs::write(&path, html(&data)).map_err(|e| format!("{}: {e}", path.display()))?;
    println!("wrote {}: {summary}", path.display());
    Ok(())
}
