//! Objects removed from a running world: a held object's contacts end, what
//! rested on a removed object falls, the other objects keep their ids, and
//! a session replays the removal.

use coulomb_hands::eval::grip::grip;
use coulomb_hands::output::session::Session;
use coulomb_hands::run::RunError;
use coulomb_hands::run::drive::{Driver, Observer, PoseFn, StepView};
use coulomb_hands::run::observe::Summary;
use coulomb_hands::run::report::ObjectSeriesRecorder;
use coulomb_hands::run::scenario::history::History;
use coulomb_hands::run::scenario::script::smoothstep;
use coulomb_hands::{
    ContactEventKind, InteractionConfig, InteractionWorld, Method, ObjectDesc, ObjectId, Side,
    StaticDesc, WorldError,
};
use glam::{Quat, Vec3};

/// Half the held cube's side (m); the ground is this far below its centre.
const H: f32 = 0.021;
/// Side of the stacked cubes (m).
const STACKED: f32 = 0.032;
/// When the held cube and the stack's lower cube are removed (s).
const REMOVED_AT: f64 = 1.7;

/// What the run saw around the removal.
#[derive(Default)]
struct Watch {
    /// The run's summary and its objects' series, as the CLI keeps them.
    summary: Option<Summary>,
    series: ObjectSeriesRecorder,
    history: History,
    /// The held cube's contacts in the step before the removal.
    held_contacts: usize,
    /// Whether a grab baseline held it then.
    grabbed: bool,
    /// Events of the step after the removal: (object, kind).
    events_after: Option<Vec<(ObjectId, ContactEventKind)>>,
    /// The most contacts of any step after the removal.
    later_contacts: usize,
}

/// Removes the held cube and the stack's lower cube at [`REMOVED_AT`].
struct Remover {
    ids: [ObjectId; 2],
    watch: Watch,
    removed: bool,
}

impl Observer for Remover {
    fn before_step(&mut self, world: &mut InteractionWorld, t: f64) -> Result<(), RunError> {
        if !self.removed && t >= REMOVED_AT {
            self.watch.held_contacts = world.contacts_on(self.ids[0]).len();
            self.watch.grabbed = world.held_by(self.ids[0]).is_some();
            for id in self.ids {
                world.remove_object(id)?;
            }
            self.removed = true;
        }
        Ok(())
    }

    fn after_step(&mut self, step: &StepView) -> Result<(), RunError> {
        if self.removed {
            let w = &mut self.watch;
            let events = || step.world.events().iter().map(|e| (e.object, e.kind)).collect();
            w.events_after.get_or_insert_with(events);
            w.later_contacts = w.later_contacts.max(step.world.contacts().len());
        }
        Ok(())
    }
}

/// A cube gripped and lifted by a right hand, a stack of two smaller cubes
/// beside it, recorded in a session, by `method`. Runs 3 s, removing the held cube and
/// the stack's lower cube at [`REMOVED_AT`].
fn run(method: Method) -> (InteractionWorld, [ObjectId; 4], Watch) {
    let config = method.config(InteractionConfig::default());
    let mut world = InteractionWorld::new(config).unwrap();
    Session::start(&mut world);
    world.add_static(&StaticDesc::ground(-H, 0.6)).unwrap();
    let held = ObjectDesc::cuboid("held", Vec3::splat(2.0 * H), 0.055, Vec3::ZERO);
    let stacked = |name: &str, level: f32| {
        let at = Vec3::new(0.35, -H + STACKED * (level + 0.5), 0.05);
        ObjectDesc::cuboid(name, Vec3::splat(STACKED), 0.03, at)
    };
    let held = world.add_object(&held).unwrap();
    let lower = world.add_object(&stacked("lower", 0.0)).unwrap();
    let upper = world.add_object(&stacked("upper", 1.0)).unwrap();
    let hand = world.add_hand(Side::Right);
    // Close, then lift 8 cm, and stay closed.
    let pose = |t: f64| {
        let t = t as f32;
        let lift = Vec3::new(0.0, 0.08 * smoothstep(0.8, 1.4, t), 0.0);
        Some(grip(H, smoothstep(0.2, 0.6, t), 0.004).transformed(Vec3::ZERO, Quat::IDENTITY, lift))
    };
    let mut remover = Remover { ids: [held, lower], watch: Watch::default(), removed: false };
    let mut summary = Summary::new(&world).unwrap();
    let mut series = ObjectSeriesRecorder::default();
    let mut history = History::new(&world);
    let mut driver = Driver::new(&mut world);
    driver.drive(hand, PoseFn::new(Side::Right, pose)).unwrap();
    driver.run(3000, &mut [&mut remover, &mut summary, &mut series, &mut history]).unwrap();
    let watch = &mut remover.watch;
    (watch.summary, watch.series, watch.history) = (Some(summary), series, history);
    let later = world.add_object(&stacked("later", 3.0)).unwrap();
    (world, [held, lower, upper, later], remover.watch)
}

#[test]
fn a_held_cube_removed_lets_go_of_the_hand_and_what_rested_on_a_removed_cube_falls() {
    let (mut world, [held, lower, upper, later], watch) = run(Method::Coulomb);
    assert!(watch.held_contacts >= 4, "held by {} contacts", watch.held_contacts);
    assert!(!watch.grabbed, "by friction alone");
    let events = watch.events_after.unwrap_or_default();
    let ended = events.iter().filter(|e| **e == (held, ContactEventKind::Ended)).count();
    assert_eq!(ended, watch.held_contacts, "each of its contacts ended");
    assert_eq!(events.len(), watch.held_contacts, "and nothing else happened");
    assert_eq!(watch.later_contacts, 0, "the closed hand touches nothing after");
    // The upper cube falls the lower one's height onto the ground.
    let y = world.object_state(upper).unwrap().position.y;
    let resting = -H + STACKED / 2.0;
    assert!((y - resting).abs() < 0.002, "upper cube at y {y}, resting at {resting}");
    // Ids: the removed ones name nothing, the others keep theirs.
    assert_eq!(world.object_ids().collect::<Vec<_>>(), [upper, later]);
    assert_eq!((later, world.object_count()), (ObjectId(3), 4));
    assert_eq!(world.object_name(upper), Some("upper"));
    assert_eq!(world.object_name(held), None);
    // What the run kept of each object stays with that object: the upper
    // cube fell one cube's height, and the removed ones' series end.
    let summary = watch.summary.expect("observed").objects(&world).unwrap();
    let names: Vec<&str> = summary.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["upper", "later"]);
    let fell = summary[0].start[1] - summary[0].end[1];
    assert!((fell - STACKED).abs() < 0.002, "the upper cube's summary fell {fell} m");
    let series = &watch.series.objects;
    let names: Vec<&str> = series.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["held", "lower", "upper"]);
    let last = |k: usize| *series[k].height_m.last().unwrap();
    assert!(last(0).is_nan() && last(1).is_nan(), "removed: {} {}", last(0), last(1));
    assert!((last(2) - resting).abs() < 0.002, "the upper cube's series ends at {}", last(2));
    // And a scenario's history, which its checks read by name.
    let history = &watch.history;
    let upper_row = history.names.iter().position(|n| n == "upper").unwrap();
    let (at, _) = history.poses.last().unwrap()[upper_row];
    assert!((at.y - resting).abs() < 0.002, "the history's upper cube ends at {}", at.y);
    assert!(history.poses.last().unwrap()[0].0.is_nan(), "the held cube's pose ends");
    for id in [held, lower] {
        let missing = Err(WorldError::NoSuchObject(id));
        assert_eq!(world.object_state(id).map(drop), missing);
        assert_eq!(world.remove_object(id), missing);
        assert_eq!(world.place_object(id, Vec3::ZERO, Quat::IDENTITY), missing);
        assert_eq!(world.set_object_locked(id, true), missing);
        assert_eq!(world.reseat_contacts(id), missing);
    }
}

#[test]
fn a_session_replays_a_removal_bit_for_bit() {
    let (mut world, [.., upper, _], _) = run(Method::Coulomb);
    let session = Session::take(&mut world).expect("recorded");
    let replayed = session.replay(|_| {}).unwrap();
    assert_eq!(replayed.object_ids().collect::<Vec<_>>(), world.object_ids().collect::<Vec<_>>());
    assert_eq!(replayed.object_state(upper), world.object_state(upper));
}

#[test]
fn a_cube_a_kinematic_grasp_carries_can_be_removed() {
    let (world, [held, ..], watch) = run(Method::Kinematic);
    assert!(watch.grabbed, "grabbed when removed");
    assert_eq!(world.held_by(held), None);
    assert_eq!(watch.later_contacts, 0, "the closed hand touches nothing after");
}
