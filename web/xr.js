// Immersive sessions with WebXR hand tracking: each tracked hand's 25 joints (wrist first, the
// library's `webxr` layout) with their radii and orientations pose a hand of the world every
// frame; a hand whose joints are not all tracked is untracked, and lets go.
const JOINTS = 25;

/** Whether `mode` (immersive-vr, immersive-ar) can start here. */
export async function xrSupported(mode) {
  if (!navigator.xr) return false;
  try {
    return await navigator.xr.isSessionSupported(mode);
  } catch {
    return false;
  }
}

/** Starts an immersive session with hand tracking, and gives it to three.js's renderer. */
export async function startXr(renderer, mode) {
  if (!navigator.xr) throw new Error('WebXR is not available in this browser');
  if (!(await xrSupported(mode))) throw new Error(`${mode} is not supported here`);
  const session = await navigator.xr.requestSession(mode, {
    requiredFeatures: ['hand-tracking'], optionalFeatures: ['local-floor'],
  });
  await renderer.xr.setSession(session);
  return session;
}

export class XrHands {
  /** `desk`: where the physics' origin sits in the session's reference space. */
  constructor(session, mode, renderer, desk) {
    this.session = session;
    this.mode = mode;
    this.renderer = renderer;
    this.desk = desk;
    this.hands = {};
    this.positions = new Float32Array(3 * JOINTS);
    this.radii = new Float32Array(JOINTS);
    this.orientations = new Float32Array(4 * JOINTS);
    this.tracked = { left: false, right: false };
  }

  /** A new world gets both hands, untracked until seen. */
  attach(world) {
    this.hands = { left: world.addHand('left'), right: world.addHand('right') };
  }

  /** Poses the world's hands from this frame's joints. */
  update(frame, world) {
    const space = this.renderer.xr.getReferenceSpace();
    const seen = { left: false, right: false };
    for (const source of this.session.inputSources) {
      const side = source.handedness;
      if (!source.hand || !(side in this.hands)) continue;
      let k = 0;
      let all = true;
      for (const joint of source.hand.values()) {
        if (k === JOINTS) break;
        const pose = frame.getJointPose(joint, space);
        if (!pose) {
          all = false;
          break;
        }
        const p = pose.transform.position;
        const q = pose.transform.orientation;
        this.positions.set([p.x - this.desk.x, p.y - this.desk.y, p.z - this.desk.z], 3 * k);
        this.orientations.set([q.x, q.y, q.z, q.w], 4 * k);
        this.radii[k] = pose.radius ?? 0.008;
        k++;
      }
      if (!all || k !== JOINTS) continue;
      world.setHandWebxr(this.hands[side], this.positions, this.radii, this.orientations);
      seen[side] = true;
      window.app.joints[side] = Array.from(this.positions);
      window.app.jointArrays[side] = [this.positions, this.radii, this.orientations].map(
        (a) => a.slice());
    }
    for (const side of ['left', 'right']) {
      if (!seen[side] && this.tracked[side]) world.clearHand(this.hands[side]);
      this.tracked[side] = seen[side];
    }
  }
}
