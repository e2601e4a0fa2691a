//! The `bench` command's measurements, thesis §5.3 and Fig. 5.6: step time
//! against bones in contact, the reference scene awake and asleep, and
//! MuJoCo's step on the same scene.
//!
//! * the **sweep**: [`sweep_scene`] with 6, 16, 32, 64 and 128 bones
//!   pressing ([`SWEEP_BONES`]), [`SAMPLES`] samples per contact, each step
//!   split into the interaction layer
//!   ([`InteractionWorld::apply_hand_forces`]) and rapier's step
//!   ([`InteractionWorld::step_physics`]);
//! * the **reference scene** ([`held_boxes_scene`]: ground, 54-block tower,
//!   16 held boxes, 32 bones pressing) with rapier's sleeping as it is (the
//!   tower falls asleep in its first second, which is timed apart as the
//!   settling figure) and with sleeping off ([`keep_awake`]: the tower
//!   stays awake, as it does while a hand works on it);
//! * the **cluttered scenes** ([`cluttered_scene`]): the reference scene's
//!   hands and held boxes among 70 to thousands of resting boxes, to show
//!   that the interaction layer's cost follows what the hands are near,
//!   not the size of the scene;
//! * [`mujoco`]: `bench/mujoco_reference.py` times MuJoCo's `mj_step` on
//!   the same reference scene, in a Python subprocess.
//!
//! Every figure is the median, over blocks of [`BLOCK`] steps, of a
//! block's mean µs per step: a block that another process interrupted
//! moves it little. The time is read from the [`Clock`] the caller passes
//! ([`run_with`], [`time_split_with`]); [`run`] and [`time_split`] read
//! the system's.

pub mod mujoco;
mod objects;
mod scene;

pub use crate::output::report::{
    BenchReport, MujocoStep, ObjectsPoint, ReferenceScene, StepTimes, SweepPoint,
};
pub use objects::{DEFAULT_OBJECTS, HELD, MAX_OBJECTS, cluttered_scene};
pub use scene::{BOXES_PER_HAND, MAX_HANDS, held_boxes_scene, sweep_scene};

use super::RunError;
use super::clock::Clock;
#[cfg(not(target_arch = "wasm32"))]
use super::clock::SystemClock;
use super::drive::{Driver, Observer, StepView};
use crate::hand::BONES_PER_HAND;
use crate::pipeline::{InteractionConfig, InteractionWorld, WorldError};
use rapier3d::prelude::RigidBodyActivation;
use std::path::PathBuf;
use std::time::Duration;

/// Bones in contact in the sweep (thesis Fig. 5.6), up to 8 hands.
pub const SWEEP_BONES: [usize; 5] = [6, 16, 32, 64, 128];
/// Skin-patch samples per contact in every bench scene.
pub const SAMPLES: usize = 8;
/// Steps every timed world runs first, untimed, so that its contacts have
/// begun and pressed in.
pub const WARM_UP: usize = 200;
/// Steps per timed block.
pub const BLOCK: usize = 100;

/// The bench's settings: the defaults, with [`SAMPLES`] samples per contact.
pub fn bench_config() -> InteractionConfig {
    let mut config = InteractionConfig::default();
    config.patch.samples = SAMPLES;
    config
}

/// What a bench run does.
#[derive(Debug, Clone, PartialEq)]
pub struct BenchOptions {
    /// Timed steps per figure, after the warm-up.
    pub steps: usize,
    /// Held boxes in the reference scene (1 to [`Self::MAX_BOXES`], two bones each).
    pub boxes: usize,
    /// Whether the reference scene has its tower.
    pub tower: bool,
    /// The Python to run MuJoCo's side with, if it is wanted.
    pub mujoco: Option<PathBuf>,
    /// Objects in each cluttered scene timed ([`HELD`] to [`MAX_OBJECTS`]
    /// each); none for no cluttered scenes.
    pub objects: Vec<usize>,
}

impl BenchOptions {
    /// The default timed steps per figure.
    pub const STEPS: usize = 5000;
    /// The most held boxes the reference scene has (and the default): one
    /// per bone of a hand, each pressed by that bone of both hands.
    pub const MAX_BOXES: usize = BONES_PER_HAND;

    /// Checks the options a run needs: at least one step, 1 to
    /// [`Self::MAX_BOXES`] boxes, and each cluttered scene's objects in
    /// [`HELD`]`..=`[`MAX_OBJECTS`]. [`run`] checks them first.
    pub fn validate(&self) -> Result<(), BenchError> {
        let fail = |field, reason| Err(BenchError::Options { field, reason });
        if self.steps == 0 {
            return fail("steps", "must be at least 1, got 0".into());
        }
        if !(1..=Self::MAX_BOXES).contains(&self.boxes) {
            return fail(
                "boxes",
                format!("must be in 1..={}, got {}", Self::MAX_BOXES, self.boxes),
            );
        }
        match self.objects.iter().find(|n| !(HELD..=MAX_OBJECTS).contains(n)) {
            Some(bad) => fail("objects", format!("each in {HELD}..={MAX_OBJECTS}, got {bad}")),
            None => Ok(()),
        }
    }

    /// The steps a run takes, for a progress bar: the sweep's worlds and
    /// the reference scene's two (MuJoCo's steps not counted).
    pub fn total_steps(&self) -> u64 {
        let sweep = SWEEP_BONES.len() * (WARM_UP + self.steps);
        let reference = ONE_SECOND + self.steps + WARM_UP + self.steps;
        let objects = self.objects.len() * (ONE_SECOND + self.steps);
        (sweep + reference + objects) as u64
    }
}

/// The steps of one simulated second at the default 1 ms step.
const ONE_SECOND: usize = 1000;

/// Why a bench run failed.
#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    /// An option out of its range ([`BenchOptions::validate`]).
    #[error("{field}: {reason}")]
    Options {
        /// The option: `steps`, `boxes` or `objects`.
        field: &'static str,
        /// What is wrong with it.
        reason: String,
    },
    /// A scene was rejected (never for the shipped scenes).
    #[error(transparent)]
    World(#[from] WorldError),
    /// A sweep scene did not press with the bones it is named after, so its
    /// figure would not measure what it says.
    #[error("the {bones}-bone sweep scene has {pressing} bones pressing after its warm-up")]
    NotPressing {
        /// Bones that should press.
        bones: usize,
        /// Bones that did.
        pressing: usize,
    },
    /// The driver loop failed (it does not, with no hand sources).
    #[error(transparent)]
    Run(#[from] RunError),
    /// MuJoCo's side could not run.
    #[error(transparent)]
    Mujoco(#[from] mujoco::MujocoError),
}

/// Runs the whole bench: the sweep, the reference scene asleep and awake
/// (with MuJoCo's side beside it if asked for, checked before anything is
/// timed, so a missing MuJoCo fails at once), then the cluttered scenes.
/// `progress` is told of every block of our steps done
/// ([`BenchOptions::total_steps`] in all). Timed by the system's clock.
#[cfg(not(target_arch = "wasm32"))]
pub fn run(
    options: &BenchOptions,
    progress: &mut dyn FnMut(u64),
) -> Result<BenchReport, BenchError> {
    run_with(options, &SystemClock::new(), progress)
}

/// [`run`], timed by `clock`.
pub fn run_with(
    options: &BenchOptions,
    clock: &dyn Clock,
    progress: &mut dyn FnMut(u64),
) -> Result<BenchReport, BenchError> {
    options.validate()?;
    if let Some(python) = &options.mujoco {
        mujoco::check(python)?;
    }
    let mut sweep = Vec::with_capacity(SWEEP_BONES.len());
    for bones in SWEEP_BONES {
        let (mut world, hands) = sweep_scene(bench_config(), bones / 2)?;
        steps(&mut world, WARM_UP, progress)?;
        let pressing = bones_pressing(&world);
        if pressing != bones {
            return Err(BenchError::NotPressing { bones, pressing });
        }
        let times = time_split_with(&mut world, options.steps, clock, progress)?;
        sweep.push(SweepPoint { bones, hands: hands.len(), samples_per_contact: SAMPLES, times });
    }
    let (reference, mujoco) = reference(options, clock, progress)?;
    let objects = cluttered(&options.objects, options.steps, clock, progress)?;
    Ok(BenchReport { sweep, reference, mujoco, objects })
}

/// The cluttered scenes, one per object count of `counts`. Each first
/// runs its first second untimed (the clutter settles and falls asleep);
/// then they are timed a block each in turn, round after round, for
/// `steps` steps each. So every scene is timed across the same stretch of
/// the machine's time, and how the layer grows with the scene does not
/// hang on when each scene ran.
fn cluttered(
    counts: &[usize],
    steps: usize,
    clock: &dyn Clock,
    progress: &mut dyn FnMut(u64),
) -> Result<Vec<ObjectsPoint>, BenchError> {
    let mut worlds = Vec::with_capacity(counts.len());
    for &objects in counts {
        let mut world = cluttered_scene(bench_config(), objects)?;
        self::steps(&mut world, ONE_SECOND, progress)?;
        worlds.push(world);
    }
    let mut blocks = vec![Vec::new(); worlds.len()];
    for n in block_lengths(steps) {
        for (world, blocks) in worlds.iter_mut().zip(&mut blocks) {
            blocks.push(time_block(world, n, clock)?);
            progress(n as u64);
        }
    }
    let point = |(world, blocks): (&InteractionWorld, &Vec<[f64; 3]>)| {
        let awake = (0..world.object_count())
            .filter_map(|o| world.object_state(crate::scene::ObjectId(o as u32)).ok())
            .filter(|state| !state.sleeping)
            .count();
        let (objects, bones_pressing) = (world.object_count(), bones_pressing(world));
        ObjectsPoint { objects, bones_pressing, awake, times: medians(blocks) }
    };
    Ok(worlds.iter().zip(&blocks).map(point).collect())
}

/// How much the interaction layer grows from the fewest objects timed to
/// the most: their ratio, and the object counts; `None` for fewer than two.
pub fn objects_growth(points: &[ObjectsPoint]) -> Option<(f64, usize, usize)> {
    let fewest = points.iter().min_by_key(|p| p.objects)?;
    let most = points.iter().max_by_key(|p| p.objects)?;
    (most.objects > fewest.objects).then(|| {
        (most.times.interaction_us / fewest.times.interaction_us, fewest.objects, most.objects)
    })
}

/// The reference scene asleep (after its timed first second) and awake;
/// with `--mujoco`, MuJoCo's step on the same scene, a block of its steps
/// after each block of ours ([`mujoco::Rival`]).
fn reference(
    options: &BenchOptions,
    clock: &dyn Clock,
    progress: &mut dyn FnMut(u64),
) -> Result<(ReferenceScene, Option<MujocoStep>), BenchError> {
    let mut rival = match &options.mujoco {
        Some(python) => Some(mujoco::Rival::start(python, options.boxes, options.tower)?),
        None => None,
    };
    let (mut asleep_pairs, mut awake_pairs) = (Vec::new(), Vec::new());
    let (mut world, _) = held_boxes_scene(bench_config(), options.boxes, options.tower)?;
    let start = clock.now();
    steps(&mut world, ONE_SECOND, progress)?;
    let settling_us = elapsed(clock, start).as_secs_f64() * 1e6 / ONE_SECOND as f64;
    let (n, pairs) = (options.steps, &mut asleep_pairs);
    let asleep = time_against(&mut world, n, clock, progress, &mut rival, pairs)?;
    let (bones_pressing, objects) = (bones_pressing(&world), world.object_count());
    drop(world);
    let (mut world, _) = held_boxes_scene(bench_config(), options.boxes, options.tower)?;
    keep_awake(&mut world);
    steps(&mut world, WARM_UP, progress)?;
    let (n, pairs) = (options.steps, &mut awake_pairs);
    let awake = time_against(&mut world, n, clock, progress, &mut rival, pairs)?;
    let scene = ReferenceScene { bones_pressing, objects, asleep, awake, settling_us };
    let mujoco = rival.map(|rival| {
        let theirs = asleep_pairs.iter().chain(&awake_pairs).map(|p| p[1]).collect();
        let ratio = |pairs: &[[f64; 2]]| median(pairs.iter().map(|p| p[0] / p[1]).collect());
        MujocoStep {
            step_us: median(theirs),
            settings: rival.settings.clone(),
            ratio_awake: ratio(&awake_pairs),
            ratio_asleep: ratio(&asleep_pairs),
        }
    });
    Ok((scene, mujoco))
}

/// [`time_split`], and after each of its blocks, when there is a `rival`,
/// as many of MuJoCo's steps: per pair of blocks, our full step and
/// MuJoCo's (µs), pushed to `pairs`.
fn time_against(
    world: &mut InteractionWorld,
    steps: usize,
    clock: &dyn Clock,
    progress: &mut dyn FnMut(u64),
    rival: &mut Option<mujoco::Rival>,
    pairs: &mut Vec<[f64; 2]>,
) -> Result<StepTimes, BenchError> {
    time_blocks(world, steps, clock, progress, &mut |n, ours| {
        if let Some(rival) = rival.as_mut() {
            pairs.push([ours[2], rival.time(n)?]);
        }
        Ok(())
    })
}

/// Steps `world` `n` times through the driver loop, untimed.
fn steps(
    world: &mut InteractionWorld,
    n: usize,
    progress: &mut dyn FnMut(u64),
) -> Result<(), BenchError> {
    Driver::new(world).run(n, &mut [])?;
    progress(n as u64);
    Ok(())
}

/// Bones pressing on an object (a contact with a normal force).
pub fn bones_pressing(world: &InteractionWorld) -> usize {
    world.contacts().iter().filter(|c| c.normal_force > 0.0).count()
}

/// Turns rapier's sleeping off for every dynamic body of `world`, and
/// wakes them: they stay awake however still they are.
pub fn keep_awake(world: &mut InteractionWorld) {
    for (_, body) in world.physics_mut().bodies.iter_mut() {
        if body.is_dynamic() {
            *body.activation_mut() = RigidBodyActivation::cannot_sleep();
        }
    }
}

/// Times `steps` steps of `world` through the driver loop, the
/// interaction layer apart from rapier's step: per quantity, the median
/// over blocks of [`BLOCK`] steps of the block's mean. Timed by the
/// system's clock.
#[cfg(not(target_arch = "wasm32"))]
pub fn time_split(
    world: &mut InteractionWorld,
    steps: usize,
    progress: &mut dyn FnMut(u64),
) -> Result<StepTimes, BenchError> {
    time_split_with(world, steps, &SystemClock::new(), progress)
}

/// [`time_split`], timed by `clock`.
pub fn time_split_with(
    world: &mut InteractionWorld,
    steps: usize,
    clock: &dyn Clock,
    progress: &mut dyn FnMut(u64),
) -> Result<StepTimes, BenchError> {
    time_blocks(world, steps, clock, progress, &mut |_, _| Ok(()))
}

/// What [`time_blocks`] calls after each block: with its length and its
/// µs per step, `[interaction layer, rapier, full]`.
type AfterBlock<'a> = &'a mut dyn FnMut(usize, &[f64; 3]) -> Result<(), BenchError>;

/// [`time_split`], calling `after_block` after each block.
fn time_blocks(
    world: &mut InteractionWorld,
    steps: usize,
    clock: &dyn Clock,
    progress: &mut dyn FnMut(u64),
    after_block: AfterBlock,
) -> Result<StepTimes, BenchError> {
    let mut blocks = Vec::with_capacity(steps.div_ceil(BLOCK));
    for n in block_lengths(steps) {
        let block = time_block(world, n, clock)?;
        after_block(n, &block)?;
        blocks.push(block);
        progress(n as u64);
    }
    Ok(medians(&blocks))
}

/// The blocks `steps` steps (at least 1) are timed in: [`BLOCK`] steps
/// each, the last what is left.
fn block_lengths(steps: usize) -> impl Iterator<Item = usize> {
    let steps = steps.max(1);
    (0..steps).step_by(BLOCK).map(move |done| BLOCK.min(steps - done))
}

/// Times `n` steps of `world` through the driver loop: µs per step,
/// `[interaction layer, rapier, full]`.
fn time_block(
    world: &mut InteractionWorld,
    n: usize,
    clock: &dyn Clock,
) -> Result<[f64; 3], BenchError> {
    let mut watch = Stopwatch { clock, start: None, between: None, hands_ns: 0, rapier_ns: 0 };
    Driver::new(world).run(n, &mut [&mut watch])?;
    let per_step = |ns: u128| ns as f64 / n as f64 / 1e3;
    let (hands, rapier) = (watch.hands_ns, watch.rapier_ns);
    Ok([per_step(hands), per_step(rapier), per_step(hands + rapier)])
}

/// Per quantity, the median over `blocks` of their µs per step.
fn medians(blocks: &[[f64; 3]]) -> StepTimes {
    let median = |i: usize| median(blocks.iter().map(|b| b[i]).collect());
    StepTimes { interaction_us: median(0), rapier_us: median(1), full_us: median(2) }
}

/// The time from `start` (a reading of `clock`) to now; zero if the clock
/// went back.
fn elapsed(clock: &dyn Clock, start: Duration) -> Duration {
    clock.now().saturating_sub(start)
}

/// Times each step's halves: the hand forces, from before the step to
/// between its halves, and rapier's step, from there to after it.
struct Stopwatch<'a> {
    clock: &'a dyn Clock,
    start: Option<Duration>,
    between: Option<Duration>,
    hands_ns: u128,
    rapier_ns: u128,
}

impl Observer for Stopwatch<'_> {
    fn before_step(&mut self, _: &mut InteractionWorld, _: f64) -> Result<(), RunError> {
        self.start = Some(self.clock.now());
        Ok(())
    }

    fn after_hand_forces(&mut self, _: &mut InteractionWorld) -> Result<(), RunError> {
        self.between = Some(self.clock.now());
        Ok(())
    }

    fn after_step(&mut self, _: &StepView) -> Result<(), RunError> {
        let end = self.clock.now();
        if let (Some(start), Some(between)) = (self.start, self.between) {
            self.hands_ns += between.saturating_sub(start).as_nanos();
            self.rapier_ns += end.saturating_sub(between).as_nanos();
        }
        Ok(())
    }
}

/// The median of `values` (the mean of the middle two for an even count);
/// 0 for none.
fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    match n {
        0 => 0.0,
        _ if n % 2 == 1 => values[n / 2],
        _ => 0.5 * (values[n / 2 - 1] + values[n / 2]),
    }
}

/// A least-squares line `y = slope·x + intercept` and its R².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearFit {
    /// dy/dx.
    pub slope: f64,
    /// y at x = 0.
    pub intercept: f64,
    /// The share of y's variance the line explains (1 for a perfect fit).
    pub r_squared: f64,
}

/// The least-squares line through `points`, if they have two distinct x
/// and every coordinate is finite.
pub fn linear_fit(points: &[(f64, f64)]) -> Option<LinearFit> {
    let finite = points.iter().all(|(x, y)| x.is_finite() && y.is_finite());
    if points.len() < 2 || !finite {
        return None;
    }
    let n = points.len() as f64;
    let mean_x = points.iter().map(|p| p.0).sum::<f64>() / n;
    let mean_y = points.iter().map(|p| p.1).sum::<f64>() / n;
    let sxx: f64 = points.iter().map(|p| (p.0 - mean_x).powi(2)).sum();
    let sxy: f64 = points.iter().map(|p| (p.0 - mean_x) * (p.1 - mean_y)).sum();
    let syy: f64 = points.iter().map(|p| (p.1 - mean_y).powi(2)).sum();
    if sxx <= 0.0 {
        return None;
    }
    let slope = sxy / sxx;
    let intercept = mean_y - slope * mean_x;
    let residual: f64 = points.iter().map(|p| (p.1 - slope * p.0 - intercept).powi(2)).sum();
    let r_squared = if syy > 0.0 { 1.0 - residual / syy } else { 1.0 };
    Some(LinearFit { slope, intercept, r_squared })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_fits_exactly_and_noise_lowers_r_squared() {
        let line: Vec<_> = [6.0, 16.0, 32.0, 64.0, 128.0].map(|x| (x, 0.5 * x + 2.0)).into();
        let fit = linear_fit(&line).unwrap();
        assert!((fit.slope - 0.5).abs() < 1e-12 && (fit.intercept - 2.0).abs() < 1e-12);
        assert!((fit.r_squared - 1.0).abs() < 1e-12);
        let noisy = [(0.0, 0.0), (1.0, 2.0), (2.0, 1.0), (3.0, 3.0)];
        let fit = linear_fit(&noisy).unwrap();
        assert!(fit.r_squared > 0.0 && fit.r_squared < 1.0);
        assert_eq!(linear_fit(&[(1.0, 1.0)]), None);
        assert_eq!(linear_fit(&[(1.0, 1.0), (1.0, 2.0)]), None);
        assert_eq!(linear_fit(&[(1.0, f64::NAN), (2.0, 2.0)]), None);
    }

    #[test]
    fn options_out_of_range_are_named() {
        let ok = BenchOptions { steps: 10, boxes: 3, tower: false, mujoco: None, objects: vec![] };
        assert!(ok.validate().is_ok());
        let error = |o: BenchOptions| o.validate().unwrap_err().to_string();
        assert_eq!(
            error(BenchOptions { steps: 0, ..ok.clone() }),
            "steps: must be at least 1, got 0"
        );
        let many = BenchOptions::MAX_BOXES + 1;
        assert!(
            error(BenchOptions { boxes: many, ..ok.clone() }).starts_with("boxes: must be in 1..=")
        );
        assert!(error(BenchOptions { boxes: 0, ..ok.clone() }).starts_with("boxes"));
        let few = BenchOptions { objects: vec![HELD, HELD - 1], ..ok.clone() };
        assert_eq!(
            error(few),
            format!("objects: each in {HELD}..={MAX_OBJECTS}, got {}", HELD - 1)
        );
        let more = BenchOptions { objects: vec![MAX_OBJECTS + 1], ..ok };
        assert!(error(more).starts_with("objects"));
    }

    #[test]
    fn the_median_is_the_middle() {
        assert_eq!(median(vec![3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(vec![4.0, 1.0, 2.0, 3.0]), 2.5);
        assert_eq!(median(Vec::new()), 0.0);
    }

    #[test]
    fn the_json_has_the_reports_shape() {
        let times = StepTimes { interaction_us: 1.0, rapier_us: 2.0, full_us: 3.0 };
        let row = SweepPoint { bones: 6, hands: 1, samples_per_contact: 8, times };
        let reference = ReferenceScene {
            bones_pressing: 32,
            objects: 70,
            asleep: times,
            awake: times,
            settling_us: 4.0,
        };
        let settings = mujoco::SETTINGS.to_string();
        let step = MujocoStep { step_us: 700.0, settings, ratio_awake: 0.5, ratio_asleep: 0.25 };
        let clutter = ObjectsPoint { objects: 2000, bones_pressing: 32, awake: 16, times };
        let report =
            BenchReport { sweep: vec![row], reference, mujoco: Some(step), objects: vec![clutter] };
        let json = serde_json::to_value(&report).unwrap();
        let expected = serde_json::json!({
            "sweep": [{"bones": 6, "hands": 1, "samples_per_contact": 8,
                       "interaction_us": 1.0, "rapier_us": 2.0, "full_us": 3.0}],
            "reference": {"bones_pressing": 32, "objects": 70,
                          "asleep": {"interaction_us": 1.0, "rapier_us": 2.0, "full_us": 3.0},
                          "awake": {"interaction_us": 1.0, "rapier_us": 2.0, "full_us": 3.0},
                          "settling_us": 4.0},
            "mujoco": {"step_us": 700.0, "settings": mujoco::SETTINGS,
                       "ratio_awake": 0.5, "ratio_asleep": 0.25},
            "objects": [{"objects": 2000, "bones_pressing": 32, "awake": 16,
                         "interaction_us": 1.0, "rapier_us": 2.0, "full_us": 3.0}]
        });
        assert_eq!(json, expected);
        assert_eq!(serde_json::from_value::<BenchReport>(json).unwrap(), report);
    }
}
