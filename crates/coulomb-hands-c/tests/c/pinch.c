/* Two index fingertips pinch a 3 cm wooden box resting on a table, and lift it 10 cm, as a
 * person does, at an engine's 1/90 s step under gravity: a 40 g box comes up with the
 * fingers and a 450 g one slips out and stays on the table (the law's threshold for this
 * squeeze, 2·μ·γ·depth/g, is 0.30 kg). Once in the built-in world (the library steps
 * rapier), once in host mode, with the host's own integrator written here, and once more
 * with that host in Unreal's frame and centimetres. */
#include <math.h>

#include "check.h"
#include "hand.h"

#define DT (1.0f / 90.0f)
#define SIDE 0.03f    /* the box's edge (m) */
#define TABLE 0.485f  /* the table's top (m) */
#define SQUEEZE 0.008f /* how far each fingertip presses in (m) */
#define LIFT 0.1f     /* how far the fingers rise (m) */
#define STEPS 135     /* 1.5 s */

static const char *CONFIG = "{\"dt\": 0.011111111}";

/* How far each fingertip is in (m, negative outside) and raised (m) at time t (s): the
 * fingers close from 1 cm outside over 0.3 s, wait 0.1 s, lift in 0.5 s along a
 * minimum-jerk path (Flash & Hogan 1985) and hold. */
static void motion(float t, float *in, float *up) {
  *in = t < 0.3f ? -0.01f + (0.01f + SQUEEZE) * t / 0.3f : SQUEEZE;
  const float u = t < 0.4f ? 0.0f : t < 0.9f ? (t - 0.4f) / 0.5f : 1.0f;
  *up = LIFT * u * u * u * (10.0f - 15.0f * u + 6.0f * u * u);
}

/* Both hands' joints at step s; the fingertip joints are the fingers' ends. */
static void pose(ChWorld world, const uint32_t hands[2], int s) {
  float in, up, joints[3 * JOINTS], radii[JOINTS];
  motion((float)s * DT, &in, &up);
  for (int i = 0; i < 2; i++) {
    const int side = i == 0 ? -1 : 1;
    pinch_hand(side, (float)side * (SIDE / 2 - in), TABLE + SIDE / 2 + up, 0.0f, joints, radii);
    OK(ch_world_set_hand_joints(world, hands[i], "openxr", joints, 3 * JOINTS, radii, JOINTS,
                                NULL, 0));
  }
}

/* A world with the box on the table and two hands; the box's id. */
static ChWorld pinch_world(float mass, uint32_t hands[2], uint32_t *box) {
  ChWorld world = 0;
  OK(ch_world_new(NULL, CONFIG, &world));
  OK(ch_world_add_ground(world, TABLE, 0.5f));
  const ChVec3 size = {SIDE, SIDE, SIDE}, at = {0.0f, TABLE + SIDE / 2, 0.0f};
  const ChQuat unturned = {0.0f, 0.0f, 0.0f, 1.0f};
  OK(ch_world_add_box(world, "box", size, mass, at, unturned, "wood", box));
  OK(ch_world_add_hand(world, "left", &hands[0]));
  OK(ch_world_add_hand(world, "right", &hands[1]));
  return world;
}

/* How far the box rose (m) in the library's own world. */
static float built_in(float mass) {
  uint32_t hands[2], box;
  ChWorld world = pinch_world(mass, hands, &box);
  for (int s = 0; s < STEPS; s++) {
    pose(world, hands, s);
    OK(ch_world_step(world, 1));
  }
  ChObjectState state;
  size_t count = 0;
  OK(ch_world_object_states(world, &state, 1, &count));
  const float rise = state.position[1] - (TABLE + SIDE / 2);
  printf("built-in %.3f kg: rose %.4f m\n", mass, rise);
  OK(ch_world_free(world));
  return rise;
}

/* A body the host integrates: semi-implicit Euler, as PhysX and most engines step, with
 * the table as a floor that stops it and holds it still. */
typedef struct {
  float x[3], q[4], v[3], w[3], mass, inertia;
} Body;

static void integrate(Body *b, const ChWrench *wrench) {
  const float gravity[3] = {0.0f, -9.81f, 0.0f};
  for (int k = 0; k < 3; k++) {
    b->v[k] += (wrench->force[k] / b->mass + gravity[k]) * DT;
    b->w[k] += wrench->torque[k] / b->inertia * DT; /* a cube: the same about every axis */
  }
  if (b->x[1] - SIDE / 2 <= TABLE + 1e-6f && b->v[1] <= 0.0f) { /* resting on the table */
    for (int k = 0; k < 3; k++) b->v[k] = b->w[k] = 0.0f;
  }
  for (int k = 0; k < 3; k++) b->x[k] += b->v[k] * DT;
  if (b->x[1] - SIDE / 2 < TABLE) b->x[1] = TABLE + SIDE / 2;
  /* q += dt/2 (0, w) q, then normalised */
  const float *w = b->w, *q = b->q;
  const float dq[4] = {
      0.5f * DT * (w[0] * q[3] + w[1] * q[2] - w[2] * q[1]),
      0.5f * DT * (-w[0] * q[2] + w[1] * q[3] + w[2] * q[0]),
      0.5f * DT * (w[0] * q[1] - w[1] * q[0] + w[2] * q[3]),
      0.5f * DT * (-w[0] * q[0] - w[1] * q[1] - w[2] * q[2]),
  };
  float norm = 0.0f;
  for (int k = 0; k < 4; k++) {
    b->q[k] += dq[k];
    norm += b->q[k] * b->q[k];
  }
  for (int k = 0; k < 4; k++) b->q[k] /= sqrtf(norm);
}

/* How far the box rose (m) with the host integrating it. */
static float hosted(float mass) {
  uint32_t hands[2], box;
  ChWorld world = pinch_world(mass, hands, &box);
  Body b = {{0.0f, TABLE + SIDE / 2, 0.0f}, {0, 0, 0, 1}, {0}, {0}, mass, mass * SIDE * SIDE / 6};
  for (int s = 0; s < STEPS; s++) {
    ChHostBody state = {
        .position = {b.x[0], b.x[1], b.x[2]},
        .rotation = {b.q[0], b.q[1], b.q[2], b.q[3]},
        .linvel = {b.v[0], b.v[1], b.v[2]},
        .angvel = {b.w[0], b.w[1], b.w[2]},
        .mass = b.mass,
        .center_of_mass = {0, 0, 0},
        .principal_inertia = {b.inertia, b.inertia, b.inertia},
        .inertia_rotation = {0, 0, 0, 1},
    };
    OK(ch_world_set_host_bodies(world, &box, &state, 1));
    pose(world, hands, s);
    ChWrench wrench;
    size_t written = 0;
    OK(ch_world_host_step(world, &wrench, 1, &written));
    CHECK(written == 1 && wrench.object == box, "one wrench, the box's (%zu)", written);
    integrate(&b, &wrench);
  }
  const float rise = b.x[1] - (TABLE + SIDE / 2);
  printf("hosted   %.3f kg: rose %.4f m\n", mass, rise);
  OK(ch_world_free(world));
  return rise;
}

/* The same hosted lift in Unreal's frame and units (ch_world_set_frame "unreal": z up, x
 * forward, y right, centimetres, forces in kg·cm/s²): every value the host gives and takes is
 * Unreal's, and its integrator knows nothing of metres. Returns the rise in cm. */
static float hosted_in_unreal(float mass) {
  ChWorld world = 0;
  uint32_t hands[2], box;
  const float cm = 100.0f, table = TABLE * cm, side = SIDE * cm;
  OK(ch_world_new(NULL, CONFIG, &world));
  OK(ch_world_set_frame(world, "unreal"));
  OK(ch_world_add_ground(world, table, 0.5f));
  const ChVec3 size = {side, side, side}, at = {0.0f, 0.0f, table + side / 2};
  const ChQuat unturned = {0.0f, 0.0f, 0.0f, 1.0f};
  OK(ch_world_add_box(world, "box", size, mass, at, unturned, "wood", &box));
  OK(ch_world_add_hand(world, "left", &hands[0]));
  OK(ch_world_add_hand(world, "right", &hands[1]));
  float z = table + side / 2, vz = 0.0f, v[2] = {0.0f, 0.0f}, xy[2] = {0.0f, 0.0f};
  const float inertia = mass * side * side / 6; /* kg·cm² */
  for (int s = 0; s < STEPS; s++) {
    ChHostBody state = {
        .position = {xy[0], xy[1], z},
        .rotation = {0, 0, 0, 1},
        .linvel = {v[0], v[1], vz},
        .angvel = {0, 0, 0},
        .mass = mass,
        .center_of_mass = {0, 0, 0},
        .principal_inertia = {inertia, inertia, inertia},
        .inertia_rotation = {0, 0, 0, 1},
    };
    OK(ch_world_set_host_bodies(world, &box, &state, 1));
    /* The hands as the library's frame has them, each joint moved to Unreal's: its x is the
     * library's -z, its y the library's x, its z the library's y. */
    float in, up, joints[3 * JOINTS], radii[JOINTS];
    motion((float)s * DT, &in, &up);
    for (int i = 0; i < 2; i++) {
      const int hand_side = i == 0 ? -1 : 1;
      pinch_hand(hand_side, (float)hand_side * (SIDE / 2 - in), TABLE + SIDE / 2 + up, 0.0f,
                 joints, radii);
      for (int j = 0; j < JOINTS; j++) {
        const float x = joints[3 * j], y = joints[3 * j + 1], zl = joints[3 * j + 2];
        joints[3 * j] = -zl * cm;
        joints[3 * j + 1] = x * cm;
        joints[3 * j + 2] = y * cm;
        radii[j] *= cm;
      }
      OK(ch_world_set_hand_joints(world, hands[i], "openxr", joints, 3 * JOINTS, radii, JOINTS,
                                  NULL, 0));
    }
    ChWrench wrench;
    size_t written = 0;
    OK(ch_world_host_step(world, &wrench, 1, &written));
    /* Semi-implicit Euler in cm and s; gravity 981 cm/s² down z; the table a floor. */
    vz += (wrench.force[2] / mass - 981.0f) * DT;
    for (int k = 0; k < 2; k++) v[k] += wrench.force[k] / mass * DT;
    if (z - side / 2 <= table + 1e-4f && vz <= 0.0f) vz = v[0] = v[1] = 0.0f;
    z = fmaxf(z + vz * DT, table + side / 2);
    for (int k = 0; k < 2; k++) xy[k] += v[k] * DT;
  }
  const float rise = z - (table + side / 2);
  printf("hosted in Unreal's frame %.3f kg: rose %.2f cm\n", mass, rise);
  OK(ch_world_free(world));
  return rise;
}

int main(void) {
  OK(ch_check_abi(CH_ABI_VERSION));
  const float light = 0.04f, heavy = 0.45f;
  /* lifted: within 1 cm of the fingers' 10 cm; slipped: left within 1 cm of the table */
  float rise = built_in(light);
  CHECK(rise > LIFT - 0.01f, "the built-in world lifts %.3f kg (rose %.4f m)", light, rise);
  rise = built_in(heavy);
  CHECK(rise < 0.01f, "the built-in world lets %.3f kg slip (rose %.4f m)", heavy, rise);
  rise = hosted(light);
  CHECK(rise > LIFT - 0.01f, "the host lifts %.3f kg (rose %.4f m)", light, rise);
  rise = hosted(heavy);
  CHECK(rise < 0.01f, "the host lets %.3f kg slip (rose %.4f m)", heavy, rise);
  /* The same in Unreal's centimetres: the law's threshold does not move with the units. */
  rise = hosted_in_unreal(light);
  CHECK(rise > (LIFT - 0.01f) * 100.0f, "Unreal's host lifts %.3f kg (rose %.2f cm)", light, rise);
  rise = hosted_in_unreal(heavy);
  CHECK(rise < 1.0f, "Unreal's host lets %.3f kg slip (rose %.2f cm)", heavy, rise);
  return failures == 0 ? 0 : 1;
}
