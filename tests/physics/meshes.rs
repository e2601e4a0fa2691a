//! Concave objects from meshes (§3.7): the project's own U bracket and
//! pawn, voxelized or split into convex parts, touched by a finger.

use super::*;
use coulomb_hands::scene::mesh::{TriangleMesh, generate};
use coulomb_hands::{
    ContactEventKind, InteractionConfig, MeshBody, MeshShape, ObjectDesc, ShapeDesc, StaticDesc,
};

const INDEX_DISTAL: Bone =
    Bone::Finger(coulomb_hands::Finger::Index, coulomb_hands::Phalanx::Distal);

fn mesh_object(
    name: &str,
    mesh: TriangleMesh,
    body: MeshBody,
    mass: f32,
    position: Vec3,
) -> ObjectDesc {
    let shape = ShapeDesc::Mesh(MeshShape::new(format!("{name} (generated)"), 1.0, body, mesh));
    ObjectDesc { shape, ..ObjectDesc::cuboid(name, Vec3::splat(0.01), mass, position) }
}

/// The index fingertip, a capsule along z, centred at `(x, y, 0)`.
fn finger_at(x: f32, y: f32) -> HandPose {
    let mut pose = parked_hand(Side::Right);
    set_bone(
        &mut pose,
        INDEX_DISTAL,
        Capsule { a: Vec3::new(x, y, -0.008), b: Vec3::new(x, y, 0.008), radius: 0.008 },
    );
    pose
}

#[test]
fn a_slipping_contact_in_a_u_stays_on_its_arm_and_never_jumps_the_gap() {
    // The U's gap is 4 cm wide between inner faces at x = ±0.02, from the
    // base's top (y = 0.01) to the arms' tops (y = 0.04). A fingertip
    // presses 2 mm into the left inner face, slides 6 mm down it, then is
    // swept at 1.5 m/s right through the gap into the other arm, 12 mm above
    // the base (Fig. 3.8 R4/R5). C stays on the left face while the contact
    // lives; the right arm may only get a new contact.
    for body in [MeshBody::Voxels { size: 0.005 }, MeshBody::Voxels { size: 0.0025 }] {
        let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
        let u = world
            .add_object(&mesh_object(
                "u",
                generate::u_bracket(0.06, 0.04, 0.02, 0.01),
                body,
                0.05,
                Vec3::ZERO,
            ))
            .unwrap();
        world.set_object_locked(u, true).unwrap();
        let hand = world.add_hand(Side::Right);
        let x_press = -0.02 + 0.008 - 0.002;
        let path = |t: f32| {
            if t < 0.3 {
                finger_at(x_press, 0.034 - 0.006 * (t / 0.3))
            } else {
                let s = ((t - 0.3) / 0.03).min(1.0);
                finger_at(x_press + s * (0.025 - x_press), 0.028)
            }
        };
        let (mut on_left, mut alive, mut slid) = (0, true, false);
        let mut lowest = f32::INFINITY;
        run(&mut world, hand, 0.4, path, |w, _| {
            if w.events().iter().any(|e| e.kind == ContactEventKind::Ended) {
                alive = false;
            }
            if !alive {
                return;
            }
            if let Some(c) = w.contacts().iter().find(|c| c.bone == INDEX_DISTAL) {
                assert!(
                    (c.point.x + 0.02).abs() < 1e-3 && c.normal.x > 0.95,
                    "{body:?}: C jumped to {:?} n {:?}",
                    c.point,
                    c.normal
                );
                on_left += 1;
                lowest = lowest.min(c.point.y);
                slid |= c.state == coulomb_hands::FrictionState::Dynamic;
            }
        });
        assert!(on_left > 250, "{body:?}: the contact lived on the left face for {on_left} steps");
        assert!(slid, "{body:?}: the contact slipped along the face");
        assert!(lowest < 0.03, "{body:?}: C followed the finger down the face to {lowest}");
    }
}

#[test]
fn a_convex_decomposition_of_the_u_keeps_its_gap_open() {
    // V-HACD's parts only approximate the faces (they may bevel the inner
    // corners), but the gap between the arms must stay empty: a fingertip
    // in its middle touches nothing, and one pressed into an arm does.
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    let body = MeshBody::ConvexParts { concavity: 0.01 };
    let u = world
        .add_object(&mesh_object(
            "u",
            generate::u_bracket(0.06, 0.04, 0.02, 0.01),
            body,
            0.05,
            Vec3::ZERO,
        ))
        .unwrap();
    world.set_object_locked(u, true).unwrap();
    let hand = world.add_hand(Side::Right);
    let mut touched = false;
    run(
        &mut world,
        hand,
        0.05,
        |_| finger_at(0.0, 0.03),
        |w, _| touched |= !w.contacts().is_empty(),
    );
    assert!(!touched, "the middle of the gap is empty");
    run(
        &mut world,
        hand,
        0.05,
        |_| finger_at(0.025, 0.03),
        |w, _| touched |= !w.contacts().is_empty(),
    );
    assert!(touched, "the right arm is solid");
}

#[test]
fn a_voxelized_pawn_rests_upright_on_a_palm_and_its_waist_is_hollow_to_a_finger() {
    // The pawn's waist (5 mm radius at y = 1.2–2.5 cm) is narrower than its
    // base (14 mm) and head: a fingertip at the waist's height, 10 mm from
    // the axis, touches nothing, though it is inside the convex hull.
    let config = InteractionConfig::default();
    let mut world = InteractionWorld::new(config).unwrap();
    world.add_static(&StaticDesc::ground(0.0, 0.5)).unwrap();
    let pawn = world
        .add_object(&mesh_object(
            "pawn",
            generate::pawn(),
            MeshBody::Voxels { size: 0.002 },
            0.03,
            Vec3::ZERO,
        ))
        .unwrap();
    let hand = world.add_hand(Side::Right);
    let mut touched = false;
    run(
        &mut world,
        hand,
        0.5,
        |_| finger_at(0.0105 + 0.008, 0.019),
        |w, _| touched |= !w.contacts().is_empty(),
    );
    assert!(!touched, "a finger beside the waist touched the pawn");
    let s = world.object_state(pawn).unwrap();
    assert!(
        s.position.y.abs() < 0.002 && (s.rotation * Vec3::Y).y > 0.999,
        "the pawn stands: {s:?}"
    );
    // The same finger 4 mm closer presses the waist.
    run(
        &mut world,
        hand,
        0.1,
        |_| finger_at(0.0105 + 0.008 - 0.0075, 0.019),
        |w, _| touched |= !w.contacts().is_empty(),
    );
    assert!(touched, "the waist itself is solid");
}

#[test]
fn static_scenery_may_be_an_exact_triangle_mesh_but_a_dynamic_object_may_not() {
    // A box dropped into a static U (exact triangles) lands on the base,
    // between the arms.
    let mut world = InteractionWorld::new(InteractionConfig::default()).unwrap();
    let mesh = generate::u_bracket(0.1, 0.06, 0.06, 0.01);
    let shape =
        ShapeDesc::Mesh(MeshShape::new("u (generated)", 1.0, MeshBody::TriMesh, mesh.clone()));
    world
        .add_static(&StaticDesc {
            name: "u".into(),
            shape,
            position: Vec3::ZERO,
            rotation: glam::Quat::IDENTITY,
            friction: 0.5,
        })
        .unwrap();
    let b = world
        .add_object(&ObjectDesc::cuboid("box", Vec3::splat(0.03), 0.05, Vec3::new(0.0, 0.1, 0.0)))
        .unwrap();
    for _ in 0..1000 {
        world.step();
    }
    let y = position(&world, b).y;
    assert!((y - (0.01 + 0.015)).abs() < 0.002, "rests on the base's top: {y}");

    let e = world
        .add_object(&mesh_object("bad", mesh, MeshBody::TriMesh, 0.05, Vec3::ZERO))
        .unwrap_err()
        .to_string();
    assert!(e.contains("'bad'") && e.contains("shape.Mesh.body") && e.contains("static"), "{e}");
}
