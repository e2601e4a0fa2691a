//! The whole grip: pads of one or two hands that press a box from opposite
//! sides, each pad a single bone placed by hand, so a test controls
//! exactly how deep each one sinks and when it backs out. Shared by
//! `balance.rs` and `release.rs`.

use super::*;
use coulomb_hands::{
    Finger, GammaMode, InteractionConfig, ObjectDesc, Palm, Phalanx, RunError, StaticDesc,
};

/// One pad: a bone of a hand pressing the box's face at `at` (the face
/// point it first touches, world) along `inward` (unit, into the box).
#[derive(Debug, Clone, Copy)]
pub struct Pad {
    /// Which of the grip's hands (0 or 1).
    pub hand: usize,
    pub bone: Bone,
    pub at: Vec3,
    pub inward: Vec3,
    /// When it starts to back out (s), if it does.
    pub opens_at: Option<f32>,
}

/// A distal pad of `finger` of hand `hand`.
pub fn tip(hand: usize, finger: Finger, at: Vec3, inward: Vec3) -> Pad {
    Pad { hand, bone: Bone::Finger(finger, Phalanx::Distal), at, inward, opens_at: None }
}

/// The palm of hand `hand`.
pub fn palm(hand: usize, at: Vec3, inward: Vec3) -> Pad {
    Pad { hand, bone: Bone::Palm, at, inward, opens_at: None }
}

/// Capsule radius of the test pads (m).
const RADIUS: f32 = 0.0085;
/// Half the palm's thickness (m).
const PALM_HALF: f32 = 0.01;

/// A box held by pads, each sunk `depth` into it, opening at `speed`.
pub struct Grip {
    pub world: InteractionWorld,
    pub cube: ObjectId,
    hands: Vec<HandId>,
    pub layout: Layout,
}

/// Where the pads are and how they move.
#[derive(Debug, Clone)]
pub struct Layout {
    pub pads: Vec<Pad>,
    /// How deep each pad sinks into the box while it grips (m).
    pub depth: f32,
    /// How fast an opening pad backs out along its normal (m/s).
    pub speed: f32,
}

/// The box: `size` across (m), `mass` (kg), at `centre`, with γ fixed.
pub struct BoxSpec {
    pub size: Vec3,
    pub mass: f32,
    pub centre: Vec3,
    pub gamma: f32,
}

fn side(h: usize) -> Side {
    if h == 0 { Side::Right } else { Side::Left }
}

impl Grip {
    /// A world with the box, the hands of `layout` (right, then left), and
    /// a table under the box when `table` is given (its top's height, m).
    pub fn new(
        config: InteractionConfig,
        spec: &BoxSpec,
        layout: Layout,
        table: Option<f32>,
    ) -> Grip {
        let mut world = InteractionWorld::new(config).unwrap();
        if let Some(top) = table {
            world.add_static(&StaticDesc::ground(top, 0.5)).unwrap();
        }
        let desc = ObjectDesc::cuboid("box", spec.size, spec.mass, spec.centre)
            .with_material(test_material(0.5))
            .with_gamma(GammaMode::Fixed(spec.gamma));
        let cube = world.add_object(&desc).unwrap();
        let count = layout.pads.iter().map(|p| p.hand + 1).max().unwrap_or(1);
        let hands = (0..count).map(|h| world.add_hand(side(h))).collect();
        Grip { world, cube, hands, layout }
    }

    /// Steps `seconds`, with the weight loaded over `load` seconds at the
    /// start, calling `each(world, t)` after every step.
    pub fn run(&mut self, seconds: f32, load: f32, mut each: impl FnMut(&InteractionWorld, f32)) {
        let dt = self.world.config().dt;
        let gravity = self.world.config().gravity;
        let mut driver = Driver::new(&mut self.world);
        for (h, &id) in self.hands.iter().enumerate() {
            let layout = self.layout.clone();
            let source = PoseFn::new(side(h), move |t| Some(layout.pose(h, t as f32)));
            driver.drive(id, source).unwrap();
        }
        let start = driver.steps();
        for i in 0..(seconds / dt).round() as usize {
            let t = (start + i) as f32 * dt;
            let share = if load > 0.0 { (t / load).min(1.0) } else { 1.0 };
            driver.world_mut().physics_mut().gravity = gravity * share;
            let mut observe = |step: &StepView| -> Result<(), RunError> {
                each(step.world, step.t as f32);
                Ok(())
            };
            driver.step(&mut [&mut observe]).unwrap();
        }
    }
}

impl Layout {
    /// Every pad opens at `t` (s), those for which `first` holds `lead`
    /// seconds earlier.
    pub fn open_at(mut self, t: f32, lead: f32, first: impl Fn(&Pad) -> bool) -> Layout {
        for pad in self.pads.iter_mut() {
            pad.opens_at = Some(if first(pad) { t - lead } else { t });
        }
        self
    }

    /// Hand `h`'s pose at `t` (s): its pads placed, every other bone parked.
    pub fn pose(&self, h: usize, t: f32) -> HandPose {
        let mut pose = parked_hand(side(h));
        for pad in self.pads.iter().filter(|p| p.hand == h) {
            let out = pad.opens_at.map_or(0.0, |t0| self.speed * (t - t0).max(0.0));
            let sunk = self.depth - out;
            match pad.bone {
                Bone::Palm => {
                    let centre = pad.at + pad.inward * (sunk - PALM_HALF);
                    let along = pad.inward.any_orthonormal_vector();
                    let extents = Vec3::new(0.04, PALM_HALF, 0.045);
                    pose.palm = Palm::from_normal_direction(centre, pad.inward, along, extents)
                        .expect("a unit normal");
                }
                bone => {
                    // The pad's axis runs across the face, upright unless
                    // the pad presses from above or below.
                    let up = if pad.inward.y.abs() > 0.9 { Vec3::Z } else { Vec3::Y };
                    let axis = pad.at + pad.inward * (sunk - RADIUS);
                    let half = up * 0.012;
                    let capsule = Capsule { a: axis + half, b: axis - half, radius: RADIUS };
                    set_bone(&mut pose, bone, capsule);
                }
            }
        }
        pose
    }
}
