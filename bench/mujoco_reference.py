"""MuJoCo's side of `coulomb-hands bench --mujoco` (thesis §5.3, Fig. 5.6).

Builds the bench's reference scene in MJCF and times `mj_step`:
a ground plane, the 54-block wooden tower of `src/scene/tower.rs`
(18 levels x 3 blocks of 7.5 x 2.5 x 1.5 cm, 600 kg/m^3, alternate levels
turned 90 degrees, standing at x = -0.4 m) and `--boxes` (16) boxes of 3 cm
and 20 g held mid-air, box k squeezed 2 mm deep between bone k of a left
hand and bone k of a right hand, as `run::bench::held_boxes_scene` builds
it: bone 0 is a mocap palm box (half extents 1 x 4 x 4.5 cm), the others
mocap capsules of radius 8 mm and 3 cm long. Friction 0.5 between objects
and the ground (rapier's average of wood's 0.5 and the ground's 0.5), 0.46
for skin on wood. dt = 1 ms.

The bench's coordinates are y-up; MuJoCo's are z-up: (x, y, z) becomes
(x, -z, y), a rotation, so the scene is the same.

Prints one JSON object: {"step_us", "settings", "steps", "mujoco",
"boxes_held", "boxes"}. With `--serve` it times on request instead, so
that the bench can alternate blocks of its own steps with blocks of
MuJoCo's, both seeing the machine as it is at that moment: after the
warm-up it prints {"settings", "mujoco"}, then answers each line n on
standard input with {"step_us"}, µs per step over n steps, until the end
of its input. `--cone` and `--integrator` choose other settings
than the default, the fastest here (pyramidal cones, Euler); `--compare`
times every cone x integrator pair instead and prints a table. Run by `coulomb-hands bench --mujoco`; made
ready by `bench/mujoco.sh`. Exits 3, with a message on stderr, when the
mujoco module is missing.
"""

import argparse
import json
import statistics
import sys
import time

SETTINGS = "pyramidal cone, Euler integrator, dt 1 ms"
HALF = 0.015  # held box half side (m)
BOX_MASS = 0.02  # kg
SQUEEZE = 0.002  # m
RADIUS = 0.008  # finger bone radius (m)
BLOCK = 100  # steps per timed block; the median block is reported


def mj(v):
    """A y-up bench vector (x, y, z) in MuJoCo's z-up frame."""
    x, y, z = v
    return (x, -z, y)


def fmt(v):
    return " ".join(f"{c:.6g}" for c in v)


def tower_blocks(base=(-0.4, 0.0, 0.0)):
    """(pos, half sizes, mass) of the 54 blocks, bench frame (y-up)."""
    long, wide, tall = 0.075, 0.025, 0.015
    mass = 600.0 * long * wide * tall
    blocks = []
    for level in range(18):
        for slot in range(3):
            across = (slot - 1.0) * wide
            y = tall * (level + 0.5)
            if level % 2 == 0:
                offset, size = (across, y, 0.0), (wide, tall, long)
            else:
                offset, size = (0.0, y, across), (long, tall, wide)
            pos = tuple(b + o for b, o in zip(base, offset))
            blocks.append((pos, tuple(s / 2 for s in size), mass))
    return blocks


def box_centre(k):
    return (0.2 + 0.08 * (k % 4), 0.3 + 0.08 * (k // 4), 0.0)


def half_sizes(h):
    """Half sizes along the bench's x, y, z as MuJoCo box sizes."""
    return (h[0], h[2], h[1])


def mjcf(boxes, tower, cone, integrator):
    body = []
    if tower:
        for i, (pos, half, mass) in enumerate(tower_blocks()):
            body.append(
                f'<body name="block{i}" pos="{fmt(mj(pos))}"><freejoint/>'
                f'<geom type="box" size="{fmt(half_sizes(half))}" mass="{mass:.6g}"/></body>'
            )
    for k in range(boxes):
        c = box_centre(k)
        body.append(
            f'<body name="box{k}" pos="{fmt(mj(c))}"><freejoint/>'
            f'<geom type="box" size="{HALF} {HALF} {HALF}" mass="{BOX_MASS}"/></body>'
        )
        for s in (-1.0, 1.0):
            side = "l" if s < 0 else "r"
            if k == 0:
                # The palm, flat against the box: 1 cm thick along x.
                x = c[0] + s * (HALF + 0.01 - SQUEEZE)
                geom = '<geom class="bone" type="box" size="0.01 0.04 0.045"/>'
            else:
                x = c[0] + s * (HALF + RADIUS - SQUEEZE)
                geom = f'<geom class="bone" type="capsule" size="{RADIUS} 0.015"/>'
            pos = mj((x, c[1], c[2]))
            body.append(f'<body name="bone{side}{k}" mocap="true" pos="{fmt(pos)}">{geom}</body>')
    return f"""<mujoco model="coulomb-hands bench reference">
  <option timestep="0.001" cone="{cone}" integrator="{integrator}"/>
  <default>
    <geom friction="0.5 0.005 0.0001"/>
    <default class="bone"><geom friction="0.46 0.005 0.0001" priority="1"/></default>
  </default>
  <worldbody>
    <geom name="ground" type="plane" size="0 0 1"/>
    {chr(10).join("    " + b for b in body).lstrip()}
  </worldbody>
</mujoco>"""


def time_steps(mujoco, model, data, warmup, steps):
    """µs per mj_step: the median over blocks of BLOCK steps."""
    for _ in range(warmup):
        mujoco.mj_step(model, data)
    per_block = []
    done = 0
    while done < max(steps, 1):
        n = min(BLOCK, max(steps, 1) - done)
        t0 = time.perf_counter()
        for _ in range(n):
            mujoco.mj_step(model, data)
        per_block.append((time.perf_counter() - t0) / n * 1e6)
        done += n
    return statistics.median(per_block)


def serve(mujoco, model, data, warmup, settings):
    """Times blocks of steps on request (`--serve`)."""
    for _ in range(warmup):
        mujoco.mj_step(model, data)
    print(json.dumps({"settings": settings, "mujoco": mujoco.__version__}), flush=True)
    for line in sys.stdin:
        n = max(int(line), 1)
        t0 = time.perf_counter()
        for _ in range(n):
            mujoco.mj_step(model, data)
        step_us = (time.perf_counter() - t0) / n * 1e6
        print(json.dumps({"step_us": step_us}), flush=True)


def held(model, data, boxes):
    """Boxes within 1 cm of where they started."""
    count = 0
    for k in range(boxes):
        z0 = mj(box_centre(k))[2]
        if abs(data.body(f"box{k}").xpos[2] - z0) < 0.01:
            count += 1
    return count


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=5000)
    parser.add_argument("--warmup", type=int, default=200)
    parser.add_argument("--boxes", type=int, default=16, choices=range(1, 17))
    parser.add_argument("--no-tower", action="store_true")
    parser.add_argument("--check", action="store_true", help="print the version and exit")
    parser.add_argument("--compare", action="store_true", help="time every cone x integrator")
    parser.add_argument("--serve", action="store_true", help="time blocks asked for on stdin")
    parser.add_argument("--xml", action="store_true", help="print the MJCF and exit")
    parser.add_argument("--cone", default="pyramidal", choices=("pyramidal", "elliptic"))
    parser.add_argument("--integrator", default="Euler", choices=("Euler", "implicitfast"))
    args = parser.parse_args()
    if args.xml:
        print(mjcf(args.boxes, not args.no_tower, args.cone, args.integrator))
        return
    try:
        import mujoco
    except ImportError as e:
        print(
            f"error: {sys.executable} cannot import mujoco ({e}): run bench/mujoco.sh, "
            "or `pip install mujoco` and pass that Python with --python",
            file=sys.stderr,
        )
        sys.exit(3)
    if args.check:
        print(json.dumps({"mujoco": mujoco.__version__}))
        return
    settings = SETTINGS
    if (args.cone, args.integrator) != ("pyramidal", "Euler"):
        settings = f"{args.cone} cone, {args.integrator} integrator, dt 1 ms"
    if args.serve:
        xml = mjcf(args.boxes, not args.no_tower, args.cone, args.integrator)
        model = mujoco.MjModel.from_xml_string(xml)
        serve(mujoco, model, mujoco.MjData(model), args.warmup, settings)
        return
    pairs = [(args.cone, args.integrator)]
    if args.compare:
        pairs = [(c, i) for c in ("pyramidal", "elliptic") for i in ("Euler", "implicitfast")]
    results = []
    for cone, integrator in pairs:
        model = mujoco.MjModel.from_xml_string(mjcf(args.boxes, not args.no_tower, cone, integrator))
        data = mujoco.MjData(model)
        step_us = time_steps(mujoco, model, data, args.warmup, args.steps)
        results.append((cone, integrator, step_us, held(model, data, args.boxes)))
    if args.compare:
        for cone, integrator, step_us, kept in results:
            print(f"{cone:9} {integrator:12} {step_us:8.1f} µs/step, {kept}/{args.boxes} boxes held")
        return
    _, _, step_us, kept = results[0]
    print(
        json.dumps(
            {
                "step_us": step_us,
                "settings": settings,
                "steps": args.steps,
                "mujoco": mujoco.__version__,
                "boxes_held": kept,
                "boxes": args.boxes,
            }
        )
    )


if __name__ == "__main__":
    main()
