/* Bad input gets its status and a message naming the argument, and leaves the world as it
 * was: null pointers, wrong lengths, numbers that are not finite, unknown names, too short
 * buffers, stale handles, another ABI version. */
#include <math.h>

#include "check.h"
#include "hand.h"

/* The status of a call and whether the last error names `what`. */
#define REFUSED(call, status, what)                                                   \
  do {                                                                                \
    ChStatus got = (call);                                                            \
    CHECK(got == (status), "%s gave %d, not %s", #call, (int)got, #status);           \
    CHECK(strstr(last_error(), (what)) != NULL, "%s's message names %s", #call, what); \
  } while (0)

/* A world's observable state: every object's state and the time, as bytes. */
typedef struct {
  ChObjectState objects[4];
  size_t count;
  double time;
} Snapshot;

static Snapshot snapshot(ChWorld world) {
  Snapshot s;
  memset(&s, 0, sizeof s);
  OK(ch_world_object_states(world, s.objects, 4, &s.count));
  OK(ch_world_time(world, &s.time));
  return s;
}

static int same(const Snapshot *a, const Snapshot *b) {
  return a->count == b->count && a->time == b->time &&
         memcmp(a->objects, b->objects, sizeof a->objects) == 0;
}

static ChHostBody resting(float y) {
  ChHostBody body = {
      .position = {0.0f, y, 0.0f},
      .rotation = {0, 0, 0, 1},
      .linvel = {0, 0, 0},
      .angvel = {0, 0, 0},
      .mass = 0.07f,
      .center_of_mass = {0, 0, 0},
      .principal_inertia = {2e-5f, 2e-5f, 2e-5f},
      .inertia_rotation = {0, 0, 0, 1},
  };
  return body;
}

int main(void) {
  REFUSED(ch_check_abi(CH_ABI_VERSION + 1), CH_STATUS_ABI_MISMATCH, "ABI version");
  CHECK(ch_abi_version() == CH_ABI_VERSION, "the library's version is the header's");

  /* Making a world. */
  ChWorld world = 0;
  REFUSED(ch_world_new(NULL, NULL, NULL), CH_STATUS_NULL_POINTER, "world");
  REFUSED(ch_world_new("grip", NULL, &world), CH_STATUS_INVALID_ARGUMENT, "method");
  REFUSED(ch_world_new(NULL, "{\"dt\": 0.001,", &world), CH_STATUS_INVALID_INPUT, "config_json");
  REFUSED(ch_world_new(NULL, "{\"dt\": -1}", &world), CH_STATUS_INVALID_INPUT, "dt");
  REFUSED(ch_world_new(NULL, "{\"stiffnes\": 3}", &world), CH_STATUS_INVALID_INPUT, "stiffnes");
  CHECK(world == 0, "no handle was written (%zu)", (size_t)world);
  OK(ch_world_new("coulomb", "{\"dt\": 0.0125}", &world));
  CHECK(world != 0, "a handle");

  /* Objects. */
  const ChVec3 size = {0.05f, 0.04f, 0.03f}, at = {0.0f, 0.3f, 0.0f};
  const ChVec3 bad_at = {0.0f, NAN, 0.0f}, flat = {0.05f, 0.0f, 0.03f};
  const ChQuat turn = {0, 0, 0, 1}, zero_turn = {0, 0, 0, 0};
  uint32_t box = 99;
  REFUSED(ch_world_add_box(world, NULL, size, 0.07f, at, turn, NULL, &box),
          CH_STATUS_NULL_POINTER, "name");
  REFUSED(ch_world_add_box(world, "box", size, 0.07f, bad_at, turn, NULL, &box),
          CH_STATUS_INVALID_ARGUMENT, "position[1]");
  REFUSED(ch_world_add_box(world, "box", size, INFINITY, at, turn, NULL, &box),
          CH_STATUS_INVALID_ARGUMENT, "mass");
  REFUSED(ch_world_add_box(world, "box", size, -0.07f, at, turn, NULL, &box), CH_STATUS_REFUSED,
          "mass");
  REFUSED(ch_world_add_box(world, "box", flat, 0.07f, at, turn, NULL, &box), CH_STATUS_REFUSED,
          "half_extents.y");
  REFUSED(ch_world_add_box(world, "box", size, 0.07f, at, zero_turn, NULL, &box),
          CH_STATUS_INVALID_ARGUMENT, "rotation");
  REFUSED(ch_world_add_box(world, "box", size, 0.07f, at, turn, "velvet", &box),
          CH_STATUS_INVALID_ARGUMENT, "velvet");
  REFUSED(ch_world_add_sphere(world, "ball", -0.02f, 0.07f, at, NULL, &box), CH_STATUS_REFUSED,
          "radius");
  uint32_t first = 0, count = 0;
  REFUSED(ch_world_add_scene(world, "{\"objects\": [}", NULL, &first, &count),
          CH_STATUS_INVALID_INPUT, "scene_json");
  CHECK(box == 99, "no id was written");
  size_t objects = 0;
  OK(ch_world_object_states(world, NULL, 0, &objects));
  CHECK(objects == 0, "no object was added (%zu)", objects);
  OK(ch_world_add_box(world, "box", size, 0.07f, at, turn, "glass", &box));

  /* Hands. */
  uint32_t hand = 99;
  REFUSED(ch_world_add_hand(world, "middle", &hand), CH_STATUS_INVALID_ARGUMENT, "side");
  CHECK(hand == 99, "no hand id was written");
  OK(ch_world_add_hand(world, "right", &hand));
  float joints[3 * JOINTS], radii[JOINTS];
  pinch_hand(1, 0.2f, 0.3f, 0.0f, joints, radii);
  REFUSED(ch_world_set_hand_joints(world, hand, "openxr", joints, 3 * 25, NULL, 0, NULL, 0),
          CH_STATUS_INVALID_ARGUMENT, "positions");
  REFUSED(ch_world_set_hand_joints(world, hand, "leap", joints, 3 * JOINTS, NULL, 0, NULL, 0),
          CH_STATUS_INVALID_ARGUMENT, "layout");
  REFUSED(ch_world_set_hand_joints(world, hand, "openxr", NULL, 3 * JOINTS, NULL, 0, NULL, 0),
          CH_STATUS_NULL_POINTER, "positions");
  REFUSED(ch_world_set_hand_joints(world, hand, "openxr", joints, 3 * JOINTS, radii, 3, NULL, 0),
          CH_STATUS_INVALID_ARGUMENT, "radii");
  REFUSED(ch_world_set_hand_joints(world, hand + 1, "openxr", joints, 3 * JOINTS, NULL, 0, NULL,
                                   0),
          CH_STATUS_REFUSED, "hand");
  joints[3 * 9 + 2] = NAN;
  REFUSED(ch_world_set_hand_joints(world, hand, "openxr", joints, 3 * JOINTS, NULL, 0, NULL, 0),
          CH_STATUS_INVALID_ARGUMENT, "positions[29]");
  pinch_hand(1, 0.2f, 0.3f, 0.0f, joints, radii);
  OK(ch_world_set_hand_joints(world, hand, "openxr", joints, 3 * JOINTS, radii, JOINTS, NULL, 0));
  OK(ch_world_step(world, 3));

  /* Host states: all checked before any is written. */
  const Snapshot before = snapshot(world);
  ChHostBody bodies[2] = {resting(0.25f), resting(0.25f)};
  uint32_t ids[2] = {box, box};
  bodies[1].linvel[2] = NAN;
  REFUSED(ch_world_set_host_bodies(world, ids, bodies, 2), CH_STATUS_INVALID_ARGUMENT,
          "bodies[1]");
  bodies[1] = resting(0.25f);
  bodies[1].mass = -1.0f;
  REFUSED(ch_world_set_host_bodies(world, ids, bodies, 2), CH_STATUS_REFUSED, "mass");
  bodies[1] = resting(0.25f);
  bodies[1].rotation[3] = 2.0f;
  REFUSED(ch_world_set_host_bodies(world, ids, bodies, 2), CH_STATUS_REFUSED, "rotation");
  ids[1] = 7;
  bodies[1] = resting(0.25f);
  REFUSED(ch_world_set_host_bodies(world, ids, bodies, 2), CH_STATUS_REFUSED, "7");
  REFUSED(ch_world_set_host_bodies(world, NULL, bodies, 2), CH_STATUS_NULL_POINTER, "ids");
  REFUSED(ch_world_set_host_bodies(world, ids, NULL, 2), CH_STATUS_NULL_POINTER, "bodies");
  ChWrench wrench;
  size_t written = 77;
  REFUSED(ch_world_host_step(world, &wrench, 0, &written), CH_STATUS_BUFFER_TOO_SMALL,
          "wrenches");
  REFUSED(ch_world_host_step(world, NULL, 1, &written), CH_STATUS_NULL_POINTER, "wrenches");
  REFUSED(ch_world_host_step(world, &wrench, 1, NULL), CH_STATUS_NULL_POINTER, "written");
  CHECK(written == 77, "nothing was written");
  const Snapshot after = snapshot(world);
  CHECK(same(&before, &after), "the refused calls left the world as it was");
  /* And the world still works. */
  ids[1] = box;
  OK(ch_world_set_host_bodies(world, ids, bodies, 2));
  OK(ch_world_host_step(world, &wrench, 1, &written));
  CHECK(written == 1, "one wrench");

  /* Outputs. */
  ChObjectState states[1];
  size_t needed = 0;
  OK(ch_world_add_sphere(world, "second", 0.02f, 0.07f, at, NULL, &box));
  REFUSED(ch_world_object_states(world, states, 1, &needed), CH_STATUS_BUFFER_TOO_SMALL,
          "states");
  CHECK(needed == 2, "a too-short buffer is told the size it needs (%zu)", needed);
  REFUSED(ch_world_object_states(world, states, 1, NULL), CH_STATUS_NULL_POINTER, "needed");
  OK(ch_world_object_states(world, NULL, 0, &needed));
  CHECK(needed == 2, "two objects (%zu)", needed);
  char tiny[4];
  size_t message = 0;
  OK(ch_last_error(NULL, 0, &message));
  CHECK(message > sizeof tiny, "the message's size (%zu)", message);
  CHECK(ch_last_error(tiny, sizeof tiny, &message) == CH_STATUS_BUFFER_TOO_SMALL,
        "too short a buffer for the message");

  /* A host with no bodies steps, with no room for wrenches. */
  ChWorld empty = 0;
  OK(ch_world_new(NULL, NULL, &empty));
  OK(ch_world_host_step(empty, NULL, 0, &written));
  CHECK(written == 0, "no wrenches (%zu)", written);
  OK(ch_world_free(empty));

  /* Stale and made-up handles. */
  OK(ch_world_free(world));
  REFUSED(ch_world_step(world, 1), CH_STATUS_STALE_HANDLE, "world");
  REFUSED(ch_world_free(world), CH_STATUS_STALE_HANDLE, "world");
  REFUSED(ch_world_add_ground(12345, 0.0f, 0.5f), CH_STATUS_STALE_HANDLE, "12345");
  REFUSED(ch_world_host_step(0, &wrench, 1, &written), CH_STATUS_STALE_HANDLE, "world");

  /* A recording that is not there, and one that is. */
  REFUSED(ch_replay("data/leap/missing.json.lz", NULL, 0, &needed), CH_STATUS_INVALID_INPUT,
          "missing.json.lz");
  OK(ch_replay("data/leap/pinch-57fps.json.lz", NULL, 0, &needed));
  char *json = malloc(needed);
  size_t again = 0;
  OK(ch_replay("data/leap/pinch-57fps.json.lz", json, needed, &again));
  CHECK(again == needed && strstr(json, "\"source\"") != NULL, "the replay's JSON (%zu bytes)",
        again);
  printf("replay --json: %zu bytes\n", needed);
  free(json);
  return failures == 0 ? 0 : 1;
}
