//! `report`: the self-contained HTML report (`output::report`), with the
//! scenarios and replays run here, and the accuracy study and benchmark
//! run here too unless their JSON is given or they are left out.

use super::bench::BenchRunArgs;
use super::eval::accuracy::StudyArgs;
use super::{Outcome, progress_bar};
use coulomb_hands::GammaMode;
use coulomb_hands::Method;
use coulomb_hands::eval::AccuracyOptions;
use coulomb_hands::output::report::{
    Ablation, AccuracyStudy, BenchReport, CaptureRuns, Header, ReplayRun, ReportData, ScenarioRun,
    Sourced, SweepStudy, html, utc_date,
};
use coulomb_hands::run::bench::{BenchError, BenchOptions, mujoco};
use coulomb_hands::run::capture::CaptureOptions;
use coulomb_hands::run::report::{CaptureInput, ReplayInput, bundled_recordings, scenario_run};
use coulomb_hands::run::scenario::{Scenario, shipped};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};

/// Write a self-contained HTML report (index.html): placement accuracy, step
/// times, every shipped scenario and the bundled replays, with plots. Without
/// --accuracy or --bench, it runs the accuracy study and the bench itself.
#[derive(clap::Args)]
pub struct ReportArgs {
    /// The directory to write index.html to; checked before any work.
    #[arg(long, default_value = "report")]
    out: PathBuf,
    /// The placement-accuracy study's JSON (`eval accuracy --json`), instead of
    /// running the study.
    #[arg(long, value_name = "FILE")]
    accuracy: Option<PathBuf>,
    /// The benchmark's JSON (`bench --json`), instead of running the bench.
    #[arg(long, value_name = "FILE")]
    bench: Option<PathBuf>,
    /// The placement study over tracking noise (`eval sweep --json`); the report
    /// does not run it (it takes minutes).
    #[arg(long, value_name = "FILE")]
    sweep: Option<PathBuf>,
    /// The ablation of the thesis's law (`eval ablation --json`).
    #[arg(long, value_name = "FILE")]
    ablation: Option<PathBuf>,
    /// Leave the accuracy study out.
    #[arg(long, conflicts_with = "accuracy")]
    no_accuracy: bool,
    /// Leave the benchmark out.
    #[arg(long, conflicts_with = "bench")]
    no_bench: bool,
    /// Only these scenarios (shipped names or files), comma-separated.
    #[arg(long, value_name = "NAME,...", value_delimiter = ',')]
    scenarios: Option<Vec<String>>,
    /// Only these recordings (Leap or joint recordings), comma-separated (default: every one in
    /// data/leap/).
    #[arg(long, value_name = "FILE,...", value_delimiter = ',')]
    replays: Option<Vec<PathBuf>>,
    #[command(flatten, next_help_heading = "Accuracy study (without --accuracy)")]
    study: StudyArgs,
    #[command(flatten, next_help_heading = "Bench (without --bench)")]
    timing: BenchRunArgs,
}

/// Where the accuracy study or the benchmark comes from.
pub enum Source<'a, O> {
    /// Its JSON, written before.
    File(&'a Path),
    /// Run by the report, with these options.
    Run(O),
    /// Left out.
    Skip,
}

impl<'a, O> Source<'a, O> {
    /// A given file wins; else it is left out if `skip`, else run.
    pub fn new(file: Option<&'a Path>, skip: bool, run: impl FnOnce() -> O) -> Self {
        match file {
            Some(file) => Source::File(file),
            None if skip => Source::Skip,
            None => Source::Run(run()),
        }
    }

    /// For the summary line.
    fn word(&self) -> &'static str {
        match self {
            Source::File(_) => "given",
            Source::Run(_) => "run",
            Source::Skip => "skipped",
        }
    }
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

/// A section given as a file, or left out: the report does not run it.
fn given(file: Option<&Path>) -> Source<'_, ()> {
    file.map_or(Source::Skip, Source::File)
}

/// `source`'s data read from its file, if it is one.
fn read<T, O>(
    source: &Source<'_, O>,
    load: fn(&Path) -> Result<T, coulomb_hands::FileError>,
    command: &str,
) -> Result<Option<Sourced<T>>, coulomb_hands::FileError> {
    let Source::File(file) = source else { return Ok(None) };
    let source = format!("{}, written by {command}", file.display());
    Ok(Some(Sourced { source, data: load(file)? }))
}

/// The accuracy study run here, if it is to be, with a progress bar.
fn study(
    source: &Source<AccuracyOptions>,
    build: &str,
) -> Result<Option<Sourced<AccuracyStudy>>, coulomb_hands::RunError> {
    let Source::Run(o) = source else { return Ok(None) };
    let methods: Vec<&str> = o.methods.iter().map(|m| m.name()).collect();
    let source = format!(
        "run by this command ({build} build): {} synthetic users × {} trials, seed {}, \
         methods {}",
        o.users,
        o.trials,
        o.seed,
        methods.join(", ")
    );
    let data = super::eval::accuracy::study(o, std::io::stderr().is_terminal())?;
    Ok(Some(Sourced { source, data }))
}

/// The benchmark run here, if it is to be, with a progress bar.
fn run_bench(
    source: &Source<BenchOptions>,
    build: &str,
) -> Result<Option<Sourced<BenchReport>>, BenchError> {
    let Source::Run(o) = source else { return Ok(None) };
    let source = format!(
        "measured by this command ({build} build): {} timed steps per figure; the reference \
         scene with {} held boxes{}{}{}",
        o.steps,
        o.boxes,
        if o.tower { " and its tower" } else { ", without its tower" },
        if o.mujoco.is_some() { "; MuJoCo in the same run" } else { "" },
        cluttered_scenes(&o.objects),
    );
    let data = super::bench::measure(o, std::io::stderr().is_terminal())?;
    Ok(Some(Sourced { source, data }))
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

impl ReportArgs {
    /// Writes `out/index.html`: checks `out`, reads every input and checks
    /// MuJoCo's Python first, then runs the accuracy study, the bench, the
    /// scenarios and the replays, with progress bars on a terminal.
    pub fn run(self) -> Outcome {
        let accuracy =
            Source::new(self.accuracy.as_deref(), self.no_accuracy, || self.study.options());
        let bench = Source::new(self.bench.as_deref(), self.no_bench, || self.timing.options());
        writable(&self.out)?;
        let accuracy_file =
            read(&accuracy, AccuracyStudy::load, "coulomb-hands eval accuracy --json")?;
        let bench_file = read(&bench, BenchReport::load, "coulomb-hands bench --json")?;
        let sweep = given(self.sweep.as_deref());
        let sweep = read(&sweep, SweepStudy::load, "coulomb-hands eval sweep --json")?;
        let ablation = given(self.ablation.as_deref());
        let ablation = read(&ablation, Ablation::load, "coulomb-hands eval ablation --json")?;
        let names: Vec<String> = match &self.scenarios {
            Some(names) => names.clone(),
            None => shipped().iter().map(|s| s.0.to_string()).collect(),
        };
        let scenarios = names.iter().map(|n| Scenario::find(n)).collect::<Result<Vec<_>, _>>()?;
        let files = self.replays.as_deref().map_or_else(bundled_recordings, <[PathBuf]>::to_vec);
        let inputs = files.iter().map(|f| ReplayInput::load(f)).collect::<Result<Vec<_>, _>>()?;
        let capture = CaptureInput::bundled()?;
        if let Source::Run(BenchOptions { mujoco: Some(python), .. }) = &bench {
            mujoco::check(python)?;
        }

        let (named_scenarios, named_replays) = (self.scenarios.is_some(), self.replays.is_some());
        let header = header();
        let accuracy_data = accuracy_file.or(study(&accuracy, &header.build)?);
        let bench_data = bench_file.or(run_bench(&bench, &header.build)?);
        let (scenario_runs, replay_runs, capture_runs) =
            run_catalogue(&scenarios, &inputs, capture.as_ref());
        let passed = scenario_runs.iter().filter(|r| r.passed).count();
        let summary = format!(
            "{} scenarios ({passed} passed), {} replays, {} capture replays; accuracy: {}, \
             bench: {}",
            scenario_runs.len(),
            replay_runs.len(),
            capture_runs.as_ref().map_or(0, |c| c.methods.len()),
            accuracy.word(),
            bench.word(),
        );
        let data = ReportData {
            accuracy: accuracy_data,
            sweep,
            ablation,
            bench: bench_data,
            scenarios: Some(scenarios_section(scenario_runs, named_scenarios, &header.build)),
            replays: Some(replays_section(replay_runs, named_replays)),
            captures: capture_runs.map(captures_section),
            header,
        };
        let path = self.out.join("index.html");
        std::fs::write(&path, html(&data)).map_err(|e| format!("{}: {e}", path.display()))?;
        println!("wrote {}: {summary}", path.display());
        Ok(())
    }
}

/// Every scenario, replay and method's replay of the capture, with a
/// progress bar on a terminal.
fn run_catalogue(
    scenarios: &[Scenario],
    inputs: &[ReplayInput],
    capture: Option<&CaptureInput>,
) -> (Vec<ScenarioRun>, Vec<ReplayRun>, Option<CaptureRuns>) {
    let methods = if capture.is_some() { Method::ALL.len() } else { 0 };
    let runs = (scenarios.len() + inputs.len() + methods) as u64;
    let template = "{bar:30} {pos}/{len} {msg} ({elapsed})";
    let bar = progress_bar(std::io::stderr().is_terminal(), runs, template);
    let mut scenario_runs = Vec::new();
    for s in scenarios {
        bar.set_message(format!("scenario {}", s.name));
        scenario_runs.push(scenario_run(s));
        bar.inc(1);
    }
    let mut replay_runs = Vec::new();
    for input in inputs {
        bar.set_message(format!("replay {}", input.name));
        replay_runs.push(input.run());
        bar.inc(1);
    }
    let capture_runs = capture.map(|c| {
        let mut runs = Vec::new();
        for method in Method::ALL {
            bar.set_message(format!("capture {} ({method})", c.name));
            runs.push(c.run(method));
            bar.inc(1);
        }
        c.runs(runs)
    });
    bar.finish_and_clear();
    (scenario_runs, replay_runs, capture_runs)
}

/// The scenarios' section, saying which ran: every shipped one, or those
/// `--scenarios` `named`.
fn scenarios_section(
    runs: Vec<ScenarioRun>,
    named: bool,
    build: &str,
) -> Sourced<Vec<ScenarioRun>> {
    let n = runs.len();
    let which = if named {
        format!("the {n} scenario(s) named by --scenarios")
    } else {
        format!("every shipped scenario ({n})")
    };
    Sourced { source: format!("run by this command ({build} build): {which}"), data: runs }
}

/// The replays' section, saying which ran (the bundled recordings, or
/// those `--replays` `named`) and how.
fn replays_section(runs: Vec<ReplayRun>, named: bool) -> Sourced<Vec<ReplayRun>> {
    let n = runs.len();
    let which = if named {
        format!("the {n} recording(s) named by --replays")
    } else {
        format!("every Leap Motion recording in data/leap/ ({n})")
    };
    let source = format!(
        "replayed by this command: {which}, at the 1 kHz physics rate with the replay's \
         defaults (γ = {} N/m) and a box at every closing of a hand (4 cm, 50 g if the \
         first closing is a fist; 2 cm, 10 g otherwise)",
        GammaMode::default()
    );
    Sourced { source, data: runs }
}

/// The capture's section, saying how it was replayed.
fn captures_section(runs: CaptureRuns) -> Sourced<CaptureRuns> {
    let source = format!(
        "replayed by this command: {} with each method, with the capture replay's defaults \
         (γ = {} N/m, a {} kg object, {}: the capture gives no mass or material)",
        runs.capture,
        CaptureOptions::default().gamma,
        runs.mass_kg,
        runs.material
    );
    Sourced { source, data: runs }
}

/// The cluttered scenes a bench run times, for its source sentence.
fn cluttered_scenes(objects: &[usize]) -> String {
    if objects.is_empty() {
        return String::new();
    }
    let counts: Vec<String> = objects.iter().map(usize::to_string).collect();
    format!("; cluttered scenes of {} objects", counts.join(", "))
}
