//! The placement task of §5.2 (Table 5.2), for people: a cube on a
//! chessboard is to be moved to the highlighted square, trial after trial,
//! with the mouse hand (or any hand the viewer drives). Enter ends a trial.
//!
//! Each trial's placement error and time are logged to the JSON that
//! `coulomb-hands eval accuracy --json` writes, as one more row, named for
//! the method and the person. So `coulomb-hands report --accuracy FILE`
//! shows a person's results beside the synthetic users'. The file is
//! rewritten after every trial, so quitting early loses nothing.

use crate::hud::{HudLines, HudSection};
use crate::keys;
use crate::sets::ViewerSystems;
use crate::source::Source;
use crate::transport::{Pause, Restart};
use bevy::prelude::*;
use coulomb_hands::eval::board::{self, Placement};
use coulomb_hands::eval::{AccuracyStudy, Trial, summarise, thesis_table};
use coulomb_hands::pipeline::{InteractionWorld, Method};
use coulomb_hands::scene::ObjectId;
use coulomb_hands_bevy::prelude::*;
use std::path::PathBuf;

/// A trial ended sooner than this after it began (s) is ignored: a key
/// still held from the last one.
const MIN_TRIAL: f64 = 0.5;
/// The task's cube: the only object on the board.
const CUBE: ObjectId = ObjectId(0);

/// The board's light and dark squares and the target's highlight.
const LIGHT: Color = Color::srgb(0.82, 0.80, 0.74);
const DARK: Color = Color::srgb(0.30, 0.29, 0.27);
const TARGET: Color = Color::srgb(0.96, 0.78, 0.10);

/// How a person's session runs.
#[derive(Debug, Clone, PartialEq)]
pub struct TaskOptions {
    /// Trials in the session (the thesis had 20 per person).
    pub trials: usize,
    /// The seed of the squares: the same seed, the same trials.
    pub seed: u64,
    /// The accuracy JSON to add this person's row to (made if missing).
    pub log: Option<PathBuf>,
    /// The person's name in the row: `METHOD (NAME)`.
    pub person: String,
}

/// The session: its trials, and the results so far.
#[derive(Resource, Debug, Clone)]
pub struct ChessboardTask {
    options: TaskOptions,
    method: Method,
    placements: Vec<Placement>,
    /// The finished trials, in order.
    pub results: Vec<Trial>,
    /// The last log write's failure, shown on the HUD.
    pub log_error: Option<String>,
    /// The trial's time before the world was last rebuilt (Home, ←), and
    /// the time of the world seen last (s).
    carried: f64,
    seen: Option<f64>,
    /// The next rebuild starts the next trial, rather than restarting this one.
    next_trial: bool,
}

impl ChessboardTask {
    /// A session of `placements` under `method`.
    pub fn new(options: TaskOptions, method: Method, placements: Vec<Placement>) -> Self {
        let (carried, seen, next_trial) = (0.0, None, false);
        let results = Vec::new();
        ChessboardTask {
            options,
            method,
            placements,
            results,
            log_error: None,
            carried,
            seen,
            next_trial,
        }
    }

    /// A session of `options.trials` trials drawn from `options.seed`.
    pub fn drawn(options: TaskOptions, method: Method) -> Self {
        let placements = board::placements(options.seed, options.trials);
        Self::new(options, method, placements)
    }

    /// The trial under way (its index and squares), or `None` when all are done.
    pub fn current(&self) -> Option<(usize, Placement)> {
        let i = self.results.len();
        self.placements.get(i).map(|p| (i, *p))
    }

    /// The source of the trial under way (the last one's, once all are
    /// done), or `None` for a session of no trials.
    pub fn source(&self) -> Option<Source> {
        let i = self.results.len().min(self.placements.len().saturating_sub(1));
        let placement = *self.placements.get(i)?;
        Some(Source::Task { trial: i + 1, placement })
    }

    /// The row's name: the method's, and the person's.
    pub fn row_name(&self) -> String {
        format!("{} ({})", self.method.name(), self.options.person)
    }

    /// Ends the trial under way on `world`: the cube's horizontal distance
    /// from the target square's centre, and the time taken. Returns it, or
    /// `None` if no trial is under way or it has only just begun.
    pub fn finish(&mut self, world: &InteractionWorld) -> Option<Trial> {
        let (_, placement) = self.current()?;
        let time = self.carried + world.time();
        if time < MIN_TRIAL {
            return None;
        }
        let cube = world.object_state(CUBE).ok()?.position;
        let target = board::square_center(placement.target);
        let error = board::placement_error(cube, target);
        let failed = !board::on_board(cube);
        let trial = Trial { error, time, failed, drops: 0 };
        self.results.push(trial);
        (self.carried, self.next_trial) = (0.0, true);
        self.log_error = self.write_log().err();
        Some(trial)
    }

    /// Follows the world of the trial under way, at `time` (s): when it
    /// was `replaced` (rebuilt from t = 0 by a restart or a seek back) since
    /// the last call, the time spent so far is carried, so a trial's time
    /// is all the time it took.
    pub fn watch(&mut self, replaced: bool, time: f64) {
        if let (Some(last_time), true) = (self.seen, replaced) {
            match std::mem::take(&mut self.next_trial) {
                true => self.carried = 0.0,
                false => self.carried += last_time - time,
            }
        }
        self.seen = Some(time);
    }

    /// Whether the log can be written: an existing file must be an accuracy
    /// JSON, a new one's directory must exist. Checked before the first
    /// trial, so no trial is lost to a bad path.
    pub fn check_log(&self) -> Result<(), String> {
        let Some(path) = &self.options.log else { return Ok(()) };
        if path.exists() {
            let study = AccuracyStudy::load(path).map_err(|e| e.to_string())?;
            let row = self.row_name();
            if study.methods.iter().any(|m| m.method == row) {
                let why = "has a row of that name already; give another --person";
                return Err(format!("{}: {row:?} {why}", path.display()));
            }
            return Ok(());
        }
        match path.parent().filter(|d| !d.as_os_str().is_empty()) {
            Some(dir) if !dir.is_dir() => {
                Err(format!("{}: no such directory for the log", dir.display()))
            }
            _ => Ok(()),
        }
    }

    /// Writes the results so far into the log: this session's row replaced
    /// (it was refused at the start if another session had it) or added,
    /// every other row kept.
    pub fn write_log(&self) -> Result<(), String> {
        let Some(path) = &self.options.log else { return Ok(()) };
        let mut study = match path.exists() {
            true => AccuracyStudy::load(path).map_err(|e| e.to_string())?,
            false => AccuracyStudy {
                users: 0,
                trials: 0,
                seed: self.options.seed,
                noise: None,
                noise_rms_mm: None,
                noise_source: None,
                perception: None,
                methods: Vec::new(),
                thesis: thesis_table(),
            },
        };
        let row = summarise(&self.row_name(), &self.results);
        match study.methods.iter_mut().find(|m| m.method == row.method) {
            Some(old) => *old = row,
            None => study.methods.push(row),
        }
        let text = serde_json::to_string_pretty(&study).map_err(|e| e.to_string())?;
        // Written aside, then renamed over the log: a crash mid-write loses no row.
        let aside = path.with_extension("json.writing");
        let fail = |e: std::io::Error| format!("{}: {e}", path.display());
        std::fs::write(&aside, text + "\n").map_err(fail)?;
        std::fs::rename(&aside, path).map_err(fail)
    }

    /// The HUD's lines.
    pub fn lines(&self) -> Vec<String> {
        let total = self.placements.len();
        let mut lines = vec![match self.current() {
            Some((i, p)) => format!(
                "chessboard trial {}/{total}: move the cube from {} to the yellow square {}, \
                 then Enter",
                i + 1,
                square_name(p.start),
                square_name(p.target)
            ),
            None => format!("chessboard: all {total} trials done"),
        }];
        if let Some(last) = self.results.last() {
            let failed = if last.failed { " (off the board: failed)" } else { "" };
            let error = last.error * 1000.0;
            lines.push(format!("last trial: error {error:.1} mm in {:.1} s{failed}", last.time));
        }
        match (&self.log_error, &self.options.log) {
            (Some(e), _) => lines.push(format!("LOG NOT WRITTEN: {e}")),
            (None, Some(path)) => lines.push(format!("logging to {}", path.display())),
            (None, None) => {}
        }
        lines
    }
}

/// A square as on a chessboard: files a–h, ranks 1–8.
fn square_name((file, rank): (usize, usize)) -> String {
    format!("{}{}", (b'a' + file as u8) as char, rank + 1)
}

/// Follows the world's rebuilds ([`ChessboardTask::watch`]).
pub fn watch_world(
    task: Option<ResMut<ChessboardTask>>,
    physics: Option<Res<HandPhysics>>,
    mut replaced: MessageReader<HandPhysicsReplaced>,
) {
    let (Some(mut task), Some(physics)) = (task, physics) else { return };
    task.watch(replaced.read().last().is_some(), physics.world().time());
}

/// Enter ends the trial under way, logs it and asks for the next one.
pub fn finish_on_enter(
    input: Res<ButtonInput<KeyCode>>,
    task: Option<ResMut<ChessboardTask>>,
    physics: Option<Res<HandPhysics>>,
    mut restart: MessageWriter<Restart>,
    mut pause: MessageWriter<Pause>,
) {
    let (Some(mut task), Some(physics)) = (task, physics) else { return };
    if !keys::FINISH.just_pressed(&input) {
        return;
    }
    let Some(trial) = task.finish(physics.world()) else { return };
    let n = task.results.len();
    info!("trial {n}: error {:.1} mm in {:.1} s", trial.error * 1000.0, trial.time);
    if let Some(e) = &task.log_error {
        error!("the task's log was not written: {e}");
    }
    match (task.current(), task.source()) {
        (Some(_), Some(next)) => {
            restart.write(Restart(Some(next)));
        }
        _ => {
            pause.write(Pause(true));
        }
    }
}

/// The board's squares, drawn for each trial's world.
#[derive(Resource, Debug, Default)]
pub struct BoardTiles(Vec<Entity>);

/// Draws the chessboard just above the ground for each new world, the
/// target square in yellow.
pub fn draw_board(
    task: Option<Res<ChessboardTask>>,
    mut replaced: MessageReader<HandPhysicsReplaced>,
    mut tiles: ResMut<BoardTiles>,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
    mut commands: Commands,
) {
    if replaced.read().last().is_none() {
        return;
    }
    let Some(task) = task else { return };
    tiles.0.drain(..).for_each(|e| commands.entity(e).despawn());
    let Some((_, placement)) = task.current() else { return };
    let tile = meshes.add(Plane3d::default().mesh().size(board::SQUARE, board::SQUARE));
    let mut colour = |c: Color| materials.add(StandardMaterial { base_color: c, ..default() });
    let (light, dark, target) = (colour(LIGHT), colour(DARK), colour(TARGET));
    for file in 0..board::SQUARES {
        for rank in 0..board::SQUARES {
            let material = match ((file, rank) == placement.target, (file + rank) % 2 == 0) {
                (true, _) => target.clone(),
                (false, true) => dark.clone(),
                (false, false) => light.clone(),
            };
            // 1 mm over the ground, so it is drawn over the ground's plane.
            let at = board::square_center((file, rank)) + glam::Vec3::Y * 0.001;
            let place = Transform::from_translation(Vec3::new(at.x, at.y, at.z));
            let entity = commands.spawn((Mesh3d(tile.clone()), MeshMaterial3d(material), place));
            tiles.0.push(entity.id());
        }
    }
}

/// The HUD's lines of the session.
fn hud_lines(task: Option<Res<ChessboardTask>>, mut hud: ResMut<HudLines>) {
    if let Some(task) = task {
        hud.set(HudSection::Task, task.lines());
    }
}

/// The task's systems (it expects [`ChessboardTask`] inserted, and the
/// transport's plugin added). Headless apps leave out [`draw_board`], which
/// needs a renderer's assets.
#[derive(Debug, Clone, Copy, Default)]
pub struct TaskPlugin {
    /// Whether the board is drawn.
    pub draw: bool,
}

impl Plugin for TaskPlugin {
    fn build(&self, app: &mut App) {
        crate::sets::configure(app);
        app.init_resource::<HudLines>()
            .add_systems(PreUpdate, finish_on_enter.in_set(ViewerSystems::Input))
            .add_systems(Update, watch_world.in_set(ViewerSystems::Drive))
            .add_systems(Update, hud_lines.in_set(ViewerSystems::HudLines));
        if self.draw {
            app.init_resource::<BoardTiles>()
                .add_systems(Update, draw_board.in_set(ViewerSystems::Draw));
        }
    }
}
