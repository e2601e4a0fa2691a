//! Option groups that several subcommands share, each one struct that
//! they flatten: `--json` (every subcommand that prints a result),
//! `--trace` and `--method` (`replay`, `scenario`), and a tracked
//! session's options (`replay`, `live`). The studies' own groups are in
//! `eval::options`.

use super::args::{at_least_zero, parse_vec3};
use coulomb_hands::input::playback::DEFAULT_GRACE;
use coulomb_hands::output::Session;
use coulomb_hands::output::trace::TraceFile;
use coulomb_hands::run::observe::TraceWriter;
use coulomb_hands::run::replay::{GraspObject, ObjectPlace};
use coulomb_hands::scene::Scene;
use coulomb_hands::{InteractionWorld, Method, RunError};
use std::path::PathBuf;

/// `--json`: the result as one JSON object on stdout, for programs.
#[derive(clap::Args)]
pub struct JsonOutput {
    /// Print one JSON object instead of the text.
    #[arg(long)]
    pub json: bool,
}

impl JsonOutput {
    /// Prints `value` as pretty JSON with `--json`, else as `text` prints it.
    pub fn print<T: serde::Serialize>(
        &self,
        value: &T,
        text: impl FnOnce(&T),
    ) -> std::io::Result<()> {
        if self.json {
            println!("{}", serde_json::to_string_pretty(value).map_err(std::io::Error::other)?);
        } else {
            text(value);
        }
        Ok(())
    }
}

/// `--trace`: every physics step of a run, as JSON lines in a file.
#[derive(clap::Args)]
pub struct TraceOutput {
    /// Write one JSON line per physics step to this file.
    #[arg(long)]
    pub trace: Option<PathBuf>,
}

impl TraceOutput {
    /// The trace's writer, its folder checked, if `--trace` asks for one.
    pub fn writer(&self) -> Result<Option<TraceWriter<TraceFile>>, RunError> {
        let file = self.trace.as_deref().map(TraceFile::at).transpose()?;
        Ok(file.map(TraceWriter::new))
    }
}

/// `--method`: how the hands of one run move objects.
#[derive(clap::Args)]
pub struct MethodChoice {
    /// How hands move objects: coulomb, thesis, kinematic or heuristic.
    #[arg(long, default_value_t = Method::default())]
    pub method: Method,
}

/// What a run on tracked hands shares, recorded (`replay`) or live
/// (`live`): where the tracker sits, how its gaps are bridged, the scene
/// the hands work in and the object put in it, and where the session is
/// recorded.
#[derive(clap::Args)]
pub struct SessionArgs {
    /// Where the desktop device sits in the world, "x,y,z" in metres.
    #[arg(long, default_value = "0,0,0", value_parser = parse_vec3)]
    pub device: glam::Vec3,
    /// Tracking gaps up to this long (s) are bridged; longer ones release the hand.
    #[arg(long, default_value_t = DEFAULT_GRACE, value_parser = at_least_zero)]
    pub grace: f64,
    /// Add the static scenery and objects of this scene file (JSON; see the
    /// `scene` module docs).
    #[arg(long)]
    pub scene: Option<PathBuf>,
    /// Record the whole session (scene, poses, steps) to this file; replaying
    /// that file reproduces the run bit for bit.
    #[arg(long)]
    pub record: Option<PathBuf>,
    /// Put an object (see --object) at each closing of a hand ("grasp", held until the hand
    /// grips it; not on a live stream), or once with its centre at "x,y,z" in metres.
    #[arg(long, value_name = "grasp|X,Y,Z")]
    pub object_at: Option<ObjectPlace>,
    /// The --object-at object: SHAPE:SIZE_M:MASS_KG, SHAPE box (SIZE its side) or sphere
    /// (SIZE its diameter), of wood.
    #[arg(
        long,
        value_name = "SHAPE:SIZE_M:MASS_KG",
        default_value = coulomb_hands::run::held::GraspObject::DEFAULT,
        requires = "object_at"
    )]
    pub object: GraspObject,
    /// The old spelling of `--object SHAPE:SIZE_M:MASS_KG --object-at grasp`, still read.
    #[arg(long, value_name = "SHAPE:SIZE_M:MASS_KG", hide = true, conflicts_with = "object_at")]
    pub object_at_grasp: Option<GraspObject>,
}

impl SessionArgs {
    /// The `--scene` file, read before anything else, so that a bad one
    /// is the first error; with the `--object-at x,y,z` object added.
    pub fn load_scene(&self) -> Result<Option<Scene>, RunError> {
        let mut scene = self.scene.as_deref().map(Scene::load).transpose()?;
        if let Some(ObjectPlace::At(at)) = self.object_at {
            scene.get_or_insert_with(Scene::default).objects.push(self.object.desc("object", at));
        }
        Ok(scene)
    }

    /// The object to put at every closing of a hand (`--object-at grasp`).
    pub fn grasp_object(&self) -> Option<GraspObject> {
        match self.object_at {
            Some(ObjectPlace::Grasp) => Some(self.object),
            _ => self.object_at_grasp,
        }
    }

    /// A world for `config` with `scene` in it, recording its session if
    /// `--record` asks for it.
    #[cfg(feature = "live")]
    pub fn world(
        &self,
        config: coulomb_hands::InteractionConfig,
        scene: Option<&Scene>,
    ) -> Result<InteractionWorld, RunError> {
        let record = self.record.is_some();
        Ok(coulomb_hands::run::replay::scene_world(config, scene, record)?)
    }

    /// Writes the session `world` recorded to `--record`'s file, if asked.
    pub fn save(&self, world: &mut InteractionWorld) -> Result<(), RunError> {
        if let (Some(path), Some(session)) = (&self.record, Session::take(world)) {
            session.save(path)?;
        }
        Ok(())
    }
}
