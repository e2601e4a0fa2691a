"""MediaPipe hand landmarks to physics: a hand closes on a cube, and the contact forces
are plotted.

    python examples/python/mediapipe_to_physics.py [LANDMARKS.npy] [--out forces.png]

The hand is MediaPipe's world landmarks (21, 3), in metres: by default the bundled frame
data/mediapipe/fist_landmarks.pbtxt (MediaPipe's own test frame of a fist), or any (21, 3)
array saved with numpy.save (MediaPipe's axes, y down, as `results.hand_world_landmarks`
gives them). The hand opens its fingers straight from the frame's knuckles, then closes
over 0.6 s back to the tracked pose around a 4 cm wooden cube on a table, and holds it;
each finger bone's contact force on the cube is plotted against time and saved as a PNG
(no window opens).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only, no GUI
import matplotlib.pyplot as plt
import numpy as np
import coulomb_hands as ch

REPO = Path(__file__).resolve().parents[2]
FIST = REPO / "data" / "mediapipe" / "fist_landmarks.pbtxt"
WRIST = 0
FINGERS = [[1, 2, 3, 4], [5, 6, 7, 8], [9, 10, 11, 12], [13, 14, 15, 16], [17, 18, 19, 20]]


def opened(landmarks: np.ndarray) -> np.ndarray:
    """The same hand with each finger straight: its joints on the line from the wrist
    through its first joint, each segment as long as tracked."""
    out = landmarks.copy()
    for finger in FINGERS:
        base = landmarks[finger[0]]
        direction = base - landmarks[WRIST]
        direction /= np.linalg.norm(direction)
        for a, b in zip(finger, finger[1:]):
            out[b] = out[a] + direction * np.linalg.norm(landmarks[b] - landmarks[a])
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("landmarks", nargs="?", help="a (21, 3) .npy of world landmarks")
    parser.add_argument("--out", default="contact_forces.png", help="the plot's file")
    args = parser.parse_args()
    if args.landmarks:
        fist = ch.mediapipe_to_y_up(np.load(args.landmarks))
        side = "right"
    else:
        frame = ch.load_mediapipe(FIST, label="mirrored")  # MediaPipe's test data mirrors
        fist, side = frame["joints"], frame["side"]

    world = ch.World(ch.Config(gamma="Auto"))
    world.add_ground(0.0, 0.6)
    side_m, mass = 0.04, 0.05
    # The cube where the closed fingers' middle joints meet, resting on the table.
    grip = fist[[6, 10, 14, 18]].mean(axis=0)
    centre = np.array([grip[0], side_m / 2, grip[2]])
    cube = world.add_box("cube", [side_m] * 3, mass, centre)
    shift = centre - grip + [0.0, 0.004, 0.0]
    fist = fist + shift
    open_hand = opened(fist)
    hand = world.add_hand(side)

    dt = world.config.dt
    steps = 1500
    names = ch.BONES
    forces = np.zeros((steps, len(names)))
    for i in range(steps):
        t = min(1.0, i * dt / 0.6)  # closes over 0.6 s, then holds
        world.set_hand_joints(hand, (1 - t) * open_hand + t * fist, "mediapipe")
        world.step()
        contacts = world.contacts()
        on_cube = contacts["object"] == cube
        np.add.at(forces[i], contacts["bone"][on_cube], contacts["normal_force"][on_cube])

    time = np.arange(steps) * dt
    figure, axes = plt.subplots(figsize=(8, 4.5))
    for bone in np.flatnonzero(forces.max(axis=0) > 0):
        axes.plot(time, forces[:, bone], label=names[bone])
    axes.set_xlabel("time (s)")
    axes.set_ylabel("normal force on the cube (N)")
    axes.set_title("a MediaPipe hand closing on a 4 cm, 50 g cube")
    axes.legend(fontsize="small", ncol=2)
    figure.tight_layout()
    figure.savefig(args.out, dpi=120)
    moved = np.linalg.norm(world.object_states()["position"][cube] - centre)
    touching = int((forces[-1] > 0).sum())
    print(f"{touching} bones press the cube at the end; it moved {moved * 1000:.1f} mm")
    print(f"saved {args.out}")


if __name__ == "__main__":
    main()
