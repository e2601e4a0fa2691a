//! What a C call costs over the Rust call it makes, side by side in one
//! run: the cheapest call (a count, where the wrapper is all there is) and
//! a host step of one held box (status, handle lookup, lock, panic guard,
//! argument checks and frame conversion around the library's work).
//! `cargo bench -p coulomb-hands-c --bench round_trip`

use coulomb_hands::{HostBody, InteractionConfig, InteractionWorld, ObjectDesc, ObjectId};
use coulomb_hands_c::{ChHostBody, ChWorld, ChWrench};
use criterion::{Criterion, criterion_group, criterion_main};
use glam::{Quat, Vec3};
use std::hint::black_box;

const STATE: HostBody = HostBody {
    position: Vec3::new(0.0, 0.5, 0.0),
    rotation: Quat::IDENTITY,
    linvel: Vec3::ZERO,
    angvel: Vec3::ZERO,
    mass: 0.05,
    center_of_mass: Vec3::ZERO,
    principal_inertia: Vec3::splat(1.3e-5),
    inertia_rotation: Quat::IDENTITY,
};

fn rust_world() -> InteractionWorld {
    let config = InteractionConfig { dt: 1.0 / 90.0, ..InteractionConfig::default() };
    let mut world = InteractionWorld::new(config).unwrap();
    let desc = ObjectDesc::cuboid("box", Vec3::splat(0.04), 0.05, STATE.position);
    world.add_object(&desc).unwrap();
    world
}

fn c_world() -> ChWorld {
    let mut world: ChWorld = 0;
    let config = c"{\"dt\": 0.011111111}";
    // SAFETY: valid texts and out pointers.
    unsafe {
        assert_eq!(
            coulomb_hands_c::ch_world_new(std::ptr::null(), config.as_ptr(), &mut world),
            coulomb_hands_c::ChStatus::Ok
        );
        let size = coulomb_hands_c::ChVec3 { x: 0.04, y: 0.04, z: 0.04 };
        let at = coulomb_hands_c::ChVec3 { x: 0.0, y: 0.5, z: 0.0 };
        let turn = coulomb_hands_c::ChQuat { x: 0.0, y: 0.0, z: 0.0, w: 1.0 };
        let mut id = 0;
        let name = c"box";
        coulomb_hands_c::ch_world_add_box(
            world,
            name.as_ptr(),
            size,
            0.05,
            at,
            turn,
            std::ptr::null(),
            &mut id,
        );
    }
    world
}

fn round_trip(c: &mut Criterion) {
    let mut group = c.benchmark_group("round trip");
    let mut rust = rust_world();
    let world = c_world();
    group.bench_function("object count, Rust", |b| b.iter(|| black_box(rust.object_count())));
    group.bench_function("object count, C", |b| {
        b.iter(|| {
            let mut n = 0u32;
            // SAFETY: a live world and a writable count.
            unsafe { coulomb_hands_c::ch_world_object_count(world, &mut n) };
            black_box(n)
        })
    });
    group.bench_function("host step of a box, Rust", |b| {
        b.iter(|| {
            rust.set_host_bodies(&[(ObjectId(0), STATE)]).unwrap();
            black_box(rust.host_step().unwrap())
        })
    });
    let p = STATE.position.to_array();
    let body = ChHostBody {
        position: p,
        rotation: [0.0, 0.0, 0.0, 1.0],
        linvel: [0.0; 3],
        angvel: [0.0; 3],
        mass: STATE.mass,
        center_of_mass: [0.0; 3],
        principal_inertia: STATE.principal_inertia.to_array(),
        inertia_rotation: [0.0, 0.0, 0.0, 1.0],
    };
    group.bench_function("host step of a box, C", |b| {
        b.iter(|| {
            let mut wrench = std::mem::MaybeUninit::<ChWrench>::uninit();
            let mut written = 0usize;
            // SAFETY: a live world, one id and body, room for one wrench.
            unsafe {
                coulomb_hands_c::ch_world_set_host_bodies(world, &0, &body, 1);
                coulomb_hands_c::ch_world_host_step(world, wrench.as_mut_ptr(), 1, &mut written);
            }
            black_box(written)
        })
    });
    group.finish();
}

criterion_group!(benches, round_trip);
criterion_main!(benches);
