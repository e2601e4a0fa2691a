//! Soak runs: a recording replayed over and over in one world, for a
//! wall-clock duration or a number of loops, watching memory, speed and
//! the objects (`replay --loop`).
//!
//! Every loop is the same experiment repeated in the same world: before
//! each loop after the first, the hands lose tracking (their contacts
//! end and their bone velocities restart from rest), every object is put
//! back where it was when the soak began, at rest
//! ([`InteractionWorld::place_object`]), and the fixtures of objects at a
//! grasp are locked again. The hands are added once and re-driven from
//! the recording's start each loop. So every loop grasps, lifts and drops
//! again, rather than waving over an object that fell in the first one,
//! while the world, its rapier sets and its buffers live through the
//! whole soak.

use super::RunError;
use super::drive::{self, Driver, HandSource, Observer, RecordedHand};
use super::observe::Summary;
use super::replay::{Fixture, Fixtures};
use crate::hand::{HandId, HandSample, Side};
use crate::input::playback::Playback;
use crate::pipeline::InteractionWorld;
use crate::scene::ObjectId;
use glam::{Quat, Vec3};
use std::time::{Duration, Instant};

/// Memory may grow this much (a fraction) from the end of the first loop
/// to the end of the soak before the report flags it.
pub const MEMORY_TOLERANCE: f64 = 0.05;

/// Steps run between looks at the clock and progress reports.
const CHUNK: usize = 250;

/// How long a soak runs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SoakLength {
    /// Until this much wall-clock time has passed, checked every few
    /// hundred steps; at least one whole loop is always run. The last loop
    /// may stop part-way.
    Wall(Duration),
    /// Exactly this many whole loops (at least one).
    Loops(usize),
}

/// Where a soak is, for a progress bar.
#[derive(Debug, Clone, Copy)]
pub struct SoakProgress {
    /// Wall-clock time since the first step.
    pub elapsed: Duration,
    /// Whole loops done.
    pub loops: usize,
    /// Steps run.
    pub steps: usize,
}

/// The process's resident memory, read at three moments of a soak (kB).
/// `None` where it cannot be read (anywhere but Linux).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct MemoryReport {
    /// Before the first step.
    pub start_kib: Option<u64>,
    /// After the first loop, once every buffer has grown to its working
    /// size: the baseline for `growth`.
    pub first_loop_kib: Option<u64>,
    /// After the last step.
    pub end_kib: Option<u64>,
    /// `(end − first loop) / first loop`.
    pub growth: Option<f64>,
    /// Whether `growth` exceeds [`MEMORY_TOLERANCE`].
    pub grew: bool,
}

/// What a soak did; `replay --loop --json` prints exactly this.
#[derive(Debug, Clone, serde::Serialize)]
pub struct SoakReport {
    /// The recording's name.
    pub source: String,
    /// Whole loops run.
    pub loops: usize,
    /// Steps run, a last partial loop included.
    pub steps: usize,
    /// Steps in one loop.
    pub steps_per_loop: usize,
    /// Simulated time (s).
    pub simulated: f64,
    /// Wall-clock time from the first step to the last (s).
    pub wall: f64,
    /// `steps / wall`.
    pub steps_per_second: f64,
    /// Resident memory.
    pub memory: MemoryReport,
    /// The largest speed of any object in any loop (m/s).
    pub peak_speed: f32,
    /// The object that reached it, if there are objects.
    pub peak_object: Option<String>,
    /// The loop it was reached in, from 1.
    pub peak_loop: usize,
    /// The smallest and largest of the whole loops' own peak speeds (m/s):
    /// close together when every loop does the same.
    pub loop_peak_range: [f32; 2],
    /// Contacts begun over the soak.
    pub contacts_begun: usize,
    /// True when every hand and object number stayed finite.
    pub all_finite: bool,
}

/// One hand of the recording, sampled on the loop's own clock.
struct LoopHand<'a> {
    hand: RecordedHand<'a>,
    /// The driver's time at the loop's first step (s).
    origin: f64,
}

impl HandSource for LoopHand<'_> {
    fn side(&self) -> Side {
        self.hand.side()
    }

    fn tracker_id(&self) -> Option<i64> {
        self.hand.tracker_id()
    }

    fn sample(&mut self, t: f64) -> Result<Option<HandSample>, RunError> {
        self.hand.sample(t - self.origin)
    }
}

/// Where every object was when the soak began.
type Placement = Vec<(ObjectId, Vec3, Quat)>;

/// Replays `playback` (one hand per track) into `world` over and over for
/// `length`, as the module docs describe, with `fixtures` (from
/// [`super::replay::place_at_grasp`]) held until gripped in every loop.
/// Every step is shown to `observers`, and `progress` is called every few
/// hundred steps. The first loop is exactly [`super::replay::replay`].
pub fn soak(
    source: &str,
    playback: &Playback,
    world: &mut InteractionWorld,
    fixtures: &[Fixture],
    length: SoakLength,
    observers: &mut [&mut dyn Observer],
    progress: &mut dyn FnMut(&SoakProgress),
) -> Result<SoakReport, RunError> {
    let placement = world
        .object_ids()
        .map(|id| world.object_state(id).map(|s| (id, s.position, s.rotation)))
        .collect::<Result<Placement, _>>()?;
    let hands: Vec<HandId> = playback.tracks.iter().map(|t| world.add_hand(t.side)).collect();
    let per_loop = playback.steps(world.config().dt);
    let time_start = world.time();
    let mut tally = Tally::new(source, per_loop);
    let start_kib = resident_kib();
    let started = Instant::now();
    let time_up = |loops: usize| match length {
        SoakLength::Wall(d) => loops >= 1 && started.elapsed() >= d,
        SoakLength::Loops(n) => loops >= n.max(1),
    };
    while !time_up(tally.loops) {
        if tally.steps > 0 {
            put_back(world, &placement, &hands, fixtures)?;
        }
        let origin = world.time();
        let shifted = fixtures.iter().map(|f| Fixture { release_by: f.release_by + origin, ..*f });
        let mut fixtures = Fixtures(shifted.collect());
        let mut summary = Summary::new(world)?;
        let mut driver = Driver::new(&mut *world);
        for (track, &hand) in hands.iter().enumerate() {
            driver.drive(hand, LoopHand { hand: RecordedHand { playback, track }, origin })?;
        }
        let mut done = 0;
        while done < per_loop && !(done > 0 && time_up(tally.loops)) {
            let n = CHUNK.min(per_loop - done);
            let mut all = drive::observers(vec![&mut fixtures, &mut summary], observers);
            driver.run(n, &mut all)?;
            done += n;
            tally.steps += n;
            let loops = tally.loops + usize::from(done == per_loop);
            progress(&SoakProgress { elapsed: started.elapsed(), loops, steps: tally.steps });
        }
        tally.add_loop(&summary, driver.world(), done == per_loop)?;
        if tally.loops == 1 && done == per_loop {
            tally.first_loop_kib = resident_kib();
        }
    }
    let wall = started.elapsed().as_secs_f64();
    let memory = memory_report(start_kib, tally.first_loop_kib, resident_kib());
    Ok(tally.report(world.time() - time_start, wall, memory))
}

/// Before a loop: the hands lose tracking, the objects go back to where
/// they began, and the fixtures are locked again.
fn put_back(
    world: &mut InteractionWorld,
    placement: &Placement,
    hands: &[HandId],
    fixtures: &[Fixture],
) -> Result<(), RunError> {
    for &hand in hands {
        world.clear_hand_pose(hand)?;
    }
    for &(id, position, rotation) in placement {
        world.place_object(id, position, rotation)?;
    }
    for f in fixtures {
        world.set_object_locked(f.object, true)?;
    }
    Ok(())
}

/// The soak's running totals.
struct Tally {
    source: String,
    per_loop: usize,
    loops: usize,
    steps: usize,
    first_loop_kib: Option<u64>,
    peak: (f32, Option<String>, usize),
    loop_peaks: Option<[f32; 2]>,
    contacts_begun: usize,
    all_finite: bool,
}

impl Tally {
    fn new(source: &str, per_loop: usize) -> Tally {
        Tally {
            source: source.to_string(),
            per_loop,
            loops: 0,
            steps: 0,
            first_loop_kib: None,
            peak: (0.0, None, 0),
            loop_peaks: None,
            contacts_begun: 0,
            all_finite: true,
        }
    }

    /// Folds in one loop's summary; `whole` if the loop ran to its end.
    fn add_loop(
        &mut self,
        summary: &Summary,
        world: &InteractionWorld,
        whole: bool,
    ) -> Result<(), RunError> {
        let objects = summary.objects(world)?;
        let top = objects.iter().max_by(|a, b| a.max_speed.total_cmp(&b.max_speed));
        let loop_peak = top.map_or(0.0, |o| o.max_speed);
        if let Some(o) = top.filter(|o| o.max_speed > self.peak.0 || self.peak.1.is_none()) {
            self.peak = (o.max_speed, Some(o.name.clone()), self.loops + 1);
        }
        self.contacts_begun += summary.contacts_begun;
        self.all_finite &= summary.all_finite;
        if whole {
            self.loops += 1;
            let [lo, hi] = self.loop_peaks.unwrap_or([loop_peak; 2]);
            self.loop_peaks = Some([lo.min(loop_peak), hi.max(loop_peak)]);
        }
        Ok(())
    }

    fn report(self, simulated: f64, wall: f64, memory: MemoryReport) -> SoakReport {
        SoakReport {
            source: self.source,
            loops: self.loops,
            steps: self.steps,
            steps_per_loop: self.per_loop,
            simulated,
            wall,
            steps_per_second: if wall > 0.0 { self.steps as f64 / wall } else { 0.0 },
            memory,
            peak_speed: self.peak.0,
            peak_object: self.peak.1,
            peak_loop: self.peak.2,
            loop_peak_range: self.loop_peaks.unwrap_or([0.0; 2]),
            contacts_begun: self.contacts_begun,
            all_finite: self.all_finite,
        }
    }
}

fn memory_report(start: Option<u64>, first: Option<u64>, end: Option<u64>) -> MemoryReport {
    let growth = match (first, end) {
        (Some(f), Some(e)) if f > 0 => Some((e as f64 - f as f64) / f as f64),
        _ => None,
    };
    let grew = growth.is_some_and(|g| g > MEMORY_TOLERANCE);
    MemoryReport { start_kib: start, first_loop_kib: first, end_kib: end, growth, grew }
}

/// The process's resident set size (kB), from `/proc/self/status`
/// (`VmRSS`); `None` where there is no such file (anywhere but Linux) or
/// it cannot be read.
pub fn resident_kib() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find_map(|l| l.strip_prefix("VmRSS:"))?;
    line.trim().strip_suffix("kB")?.trim().parse().ok()
}

/// Why a text is not a [`parse_duration`] duration.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DurationError {
    /// Not numbers each followed by a unit.
    #[error("expected a duration such as 90s, 10m or 1h30m, got \"{0}\"")]
    Form(String),
    /// A unit other than ms, s, m or h.
    #[error("unknown unit \"{unit}\" in \"{text}\": use ms, s, m or h (e.g. 10m)")]
    Unit {
        /// The unit given.
        unit: String,
        /// The whole text.
        text: String,
    },
    /// A number without a unit.
    #[error("\"{0}\" needs a unit: ms, s, m or h (e.g. 10m)")]
    NoUnit(String),
    /// Zero, or too long to represent.
    #[error("the duration must be longer than zero and shorter than 10⁹ s, got \"{0}\"")]
    Range(String),
}

/// A wall-clock duration such as `90s`, `10m`, `1h`, `1h30m` or `1.5s`:
/// one or more numbers, each followed by a unit (`ms`, `s`, `m`, `h`).
pub fn parse_duration(text: &str) -> Result<Duration, DurationError> {
    let form = || DurationError::Form(text.to_string());
    let mut rest = text;
    let mut seconds = 0.0_f64;
    if rest.is_empty() {
        return Err(form());
    }
    while !rest.is_empty() {
        let digits = rest.find(|c: char| !(c.is_ascii_digit() || c == '.')).unwrap_or(rest.len());
        let number: f64 = rest[..digits].parse().map_err(|_| form())?;
        rest = &rest[digits..];
        let letters = rest.find(|c: char| !c.is_alphabetic()).unwrap_or(rest.len());
        let scale = match &rest[..letters] {
            "" => return Err(DurationError::NoUnit(text.to_string())),
            "ms" => 1e-3,
            "s" => 1.0,
            "m" => 60.0,
            "h" => 3600.0,
            unit => {
                let unit = unit.to_string();
                return Err(DurationError::Unit { unit, text: text.to_string() });
            }
        };
        rest = &rest[letters..];
        seconds += number * scale;
    }
    let range = || DurationError::Range(text.to_string());
    if !(seconds > 0.0 && seconds < 1e9) {
        return Err(range());
    }
    Duration::try_from_secs_f64(seconds).map_err(|_| range())
}

impl std::fmt::Display for SoakReport {
    /// The report as `replay --loop` prints it, one figure a line.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let r = self;
        let mib = |k: Option<u64>| {
            k.map_or("unavailable".into(), |k| format!("{:.1} MiB", k as f64 / 1024.0))
        };
        writeln!(f, "soaked {} for {:.1} s of wall-clock time", r.source, r.wall)?;
        writeln!(
            f,
            "loops: {}, steps: {} ({} a loop), simulated: {:.1} s",
            r.loops, r.steps, r.steps_per_loop, r.simulated
        )?;
        writeln!(f, "steps per second: {:.0}", r.steps_per_second)?;
        writeln!(
            f,
            "peak object speed: {:.3} m/s ({} in loop {}); loop peaks {:.3}-{:.3} m/s",
            r.peak_speed,
            r.peak_object.as_deref().unwrap_or("no object"),
            r.peak_loop,
            r.loop_peak_range[0],
            r.loop_peak_range[1]
        )?;
        writeln!(f, "contacts begun: {}, all values finite: {}", r.contacts_begun, r.all_finite)?;
        let m = &r.memory;
        writeln!(
            f,
            "memory (RSS): start {}, after the first loop {}, end {}",
            mib(m.start_kib),
            mib(m.first_loop_kib),
            mib(m.end_kib)
        )?;
        match m.growth {
            Some(g) if m.grew => {
                writeln!(f, "memory GREW {:+.1} % since the first loop", g * 100.0)
            }
            Some(g) => writeln!(f, "memory flat: {:+.1} % since the first loop", g * 100.0),
            None => writeln!(f, "memory growth: unavailable"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn durations_parse_with_units_and_reject_the_rest() {
        let ok = |t: &str| parse_duration(t).unwrap();
        assert_eq!(ok("10m"), Duration::from_secs(600));
        assert_eq!(ok("90s"), Duration::from_secs(90));
        assert_eq!(ok("1h"), Duration::from_secs(3600));
        assert_eq!(ok("1h30m"), Duration::from_secs(5400));
        assert_eq!(ok("1.5s"), Duration::from_millis(1500));
        assert_eq!(ok("250ms"), Duration::from_millis(250));
        let err = |t: &str| parse_duration(t).unwrap_err();
        assert!(matches!(err("10x"), DurationError::Unit { .. }), "{}", err("10x"));
        assert!(matches!(err("10"), DurationError::NoUnit(_)));
        for zero in ["0s", "0m", "0h0m"] {
            assert!(matches!(err(zero), DurationError::Range(_)), "{zero}");
        }
        for bad in ["", "m", "-1s", "1..5s", " 1s", "1 s", "1e3s", "NaNs"] {
            assert!(parse_duration(bad).is_err(), "{bad:?} parsed");
        }
        assert!(matches!(err("99999999999h"), DurationError::Range(_)));
    }

    /// A pinch with a 2 cm, 10 g box at its grasp, soaked for `length`.
    fn pinch_soak(length: SoakLength) -> (SoakReport, usize, usize) {
        use crate::input::{convert::Conversion, leap, playback::DEFAULT_GRACE};
        use crate::run::replay::{GraspObject, place_at_grasp, replay_world};
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data/leap/pinch.json.lz");
        let rec = leap::load(&path).unwrap();
        let conversion = Conversion::leap_desktop(Vec3::ZERO);
        let playback = Playback::new("pinch", &rec.frames, &conversion, DEFAULT_GRACE).unwrap();
        let config = crate::pipeline::InteractionConfig {
            gamma: crate::scene::GammaMode::Auto,
            ..Default::default()
        };
        let mut world = replay_world(config, false).unwrap();
        let object = GraspObject { sphere: false, size: 0.02, mass: 0.01 };
        let (fixture, _) = place_at_grasp(&mut world, &playback, object, 0).unwrap();
        let mut calls = 0;
        let mut progress = |_: &SoakProgress| calls += 1;
        let r = soak("pinch", &playback, &mut world, &[fixture], length, &mut [], &mut progress);
        (r.unwrap(), calls, world.hand_count())
    }

    #[test]
    fn a_short_soak_reports_sane_figures_and_every_loop_drops_the_box() {
        let (r, calls, hands) = pinch_soak(SoakLength::Loops(3));
        assert_eq!((r.loops, r.steps), (3, 3 * r.steps_per_loop), "{r:?}");
        assert_eq!(r.steps_per_loop, 2689);
        assert_eq!(hands, 1, "the hands are added once");
        assert!(calls >= r.steps / CHUNK, "progress was called {calls} times");
        assert!((r.simulated - r.steps as f64 * 1e-3).abs() < 1e-6, "{}", r.simulated);
        assert!(r.wall > 0.0 && r.steps_per_second.is_finite() && r.steps_per_second > 0.0);
        assert!(r.all_finite && r.contacts_begun >= 3 * 2, "{r:?}");
        // The box falls from the pinch in every loop: the objects really
        // are put back, and each loop does about the same.
        assert_eq!(r.peak_object.as_deref(), Some("grasped"));
        let [lo, hi] = r.loop_peak_range;
        assert!(r.peak_speed.is_finite() && r.peak_speed == hi, "{r:?}");
        assert!(lo > 0.5 && hi < 1.1 * lo, "loop peaks {lo}-{hi} m/s");
        assert!((1..=3).contains(&r.peak_loop));
        let m = r.memory;
        if cfg!(target_os = "linux") {
            for kib in [m.start_kib, m.first_loop_kib, m.end_kib] {
                assert!(kib.is_some_and(|k| k > 0), "{m:?}");
            }
            assert!(m.growth.is_some_and(f64::is_finite), "{m:?}");
        }
    }

    #[test]
    fn a_soak_runs_at_least_one_whole_loop_however_short() {
        let (r, _, _) = pinch_soak(SoakLength::Wall(Duration::from_nanos(1)));
        assert_eq!((r.loops, r.steps), (1, r.steps_per_loop), "{r:?}");
        let (r, _, _) = pinch_soak(SoakLength::Loops(0));
        assert_eq!(r.loops, 1);
    }

    #[test]
    fn resident_memory_is_read_on_linux() {
        let kib = resident_kib();
        if cfg!(target_os = "linux") {
            assert!(kib.is_some_and(|k| k > 0), "{kib:?}");
        }
    }
}
