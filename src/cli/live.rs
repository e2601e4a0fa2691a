//! `live`: the physics on a live Leap Motion stream, with a scene and an
//! object to touch, optionally recorded.

use coulomb_hands::run::replay::GraspObject;
use coulomb_hands::{InteractionConfig, RunError};
use std::path::Path;

pub struct LiveArgs<'a> {
    pub url: &'a str,
    pub seconds: f64,
    pub device: glam::Vec3,
    pub grace: f64,
    pub scene: Option<&'a Path>,
    /// An object, and where its centre starts (m).
    pub object: Option<(GraspObject, glam::Vec3)>,
    pub record: Option<&'a Path>,
    pub json: bool,
}

pub fn live(args: LiveArgs) -> Result<(), RunError> {
    use coulomb_hands::input::convert::Conversion;
    use coulomb_hands::output::Session;
    use coulomb_hands::run::{live::run_live, replay::replay_world};
    let LiveArgs { url, seconds, device, grace, scene, object, record, json } = args;
    let scene = scene.map(coulomb_hands::scene::Scene::load).transpose()?;
    let mut config = InteractionConfig::default();
    if let Some(scene) = &scene {
        config = config.with_scene(scene);
    }
    let mut world = replay_world(config, record.is_some())?;
    if let Some(scene) = &scene {
        world.add_scene(scene)?;
    }
    if let Some((object, at)) = object {
        world.add_object(&object.desc("object", at))?;
    }
    let conversion = Conversion::leap_desktop(device);
    let s = run_live(url, &mut world, conversion, grace, seconds, &mut [])?;
    if let (Some(path), Some(session)) = (record, Session::take(&mut world)) {
        session.save(path)?;
    }
    if json {
        println!("{}", serde_json::to_string_pretty(&s).map_err(std::io::Error::other)?);
        return Ok(());
    }
    println!(
        "live {url}: {} frames, {} skipped, {} hands seen, {:.2} s simulated, {} contacts begun",
        s.frames, s.skipped, s.hands_seen, s.simulated, s.contacts_begun
    );
    for o in &s.objects {
        println!(
            "object {}: moved {:.3} m, max speed {:.3} m/s",
            o.name, o.displacement, o.max_speed
        );
    }
    Ok(())
}
