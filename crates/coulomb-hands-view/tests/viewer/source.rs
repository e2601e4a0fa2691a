//! A recording's object, spelled as `replay` spells it: `--object-at grasp`
//! puts it at every closing, `--object-at x,y,z` once, in the scene.

use coulomb_hands::pipeline::Method;
use coulomb_hands::run::replay::{GraspObject, ObjectPlace};
use coulomb_hands_view::source::{LoadOptions, Source};

const GRAB: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/leap/grab.json.lz");

fn load(place: ObjectPlace) -> Source {
    let ball: GraspObject = "sphere:0.03:0.02".parse().expect("an object");
    let options = LoadOptions { object: Some((ball, place)), ..LoadOptions::default() };
    Source::load(Some(GRAB), &options).expect("the bundled recording")
}

#[test]
fn a_recording_s_object_goes_at_its_closings_or_once_where_it_is_told() {
    let Source::Recording { object, scene, .. } = load(ObjectPlace::Grasp) else { panic!() };
    assert!(object.is_some_and(|o| o.sphere) && scene.is_none(), "at every closing");
    let at = glam::Vec3::new(0.4, 0.015, 0.0);
    let once = load(ObjectPlace::At(at));
    let Source::Recording { object, scene, .. } = &once else { panic!() };
    assert!(object.is_none(), "no closings' objects");
    assert_eq!(scene.as_ref().map(|s| s.objects.len()), Some(1));
    let physics = once.build(Method::Coulomb).expect("a world");
    let world = physics.world();
    let id = world.object_ids().next().expect("the object");
    assert_eq!(world.object_name(id), Some("object"));
    assert_eq!(world.object_state(id).unwrap().position, at);
}
