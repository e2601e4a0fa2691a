// The desk's hand, driven by mouse and keys as the viewer's is (crates/coulomb-hands-view's
// mouse_hand.rs, with its keys.rs bindings and rates): the rig's adult right hand, palm down,
// fingers away from the camera.
import * as THREE from 'three';

const SPEED = 0.12; // m/s
const FINE_SPEED = 0.03; // m/s, with Shift held
const DRAG = 0.0006; // m per pixel of right-drag
const TURN = Math.PI / 3; // rad/s
const CURL_RATE = 0.6; // of a full curl per s
const OPPOSE_RATE = 3.0; // per s
const START_PALM = [0, 0.15, -0.2];

export class MouseHand {
  constructor(world, hand, camera, canvas) {
    this.world = world;
    this.hand = hand;
    this.camera = camera;
    this.palm = new THREE.Vector3(...START_PALM);
    this.turn = new THREE.Vector3();
    this.curl = [0.1, 0.1, 0.1, 0.1, 0.1];
    this.opposition = 0;
    this.opposing = false;
    this.held = new Set();
    this.drag = null;
    this.abort = new AbortController();
    const signal = this.abort.signal;
    window.addEventListener('keydown', (e) => {
      if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
      this.held.add(e.code);
      if (e.code === 'KeyT' && !e.repeat) this.opposing = !this.opposing;
    }, { signal });
    window.addEventListener('keyup', (e) => this.held.delete(e.code), { signal });
    window.addEventListener('blur', () => this.held.clear(), { signal });
    canvas.addEventListener('contextmenu', (e) => e.preventDefault(), { signal });
    canvas.addEventListener('pointerdown', (e) => {
      if (e.button === 2) this.drag = [e.clientX, e.clientY];
    }, { signal });
    window.addEventListener('pointerup', () => { this.drag = null; }, { signal });
    window.addEventListener('pointermove', (e) => {
      if (!this.drag) return;
      const [dx, dy] = [e.clientX - this.drag[0], e.clientY - this.drag[1]];
      this.drag = [e.clientX, e.clientY];
      const { right } = this.heading();
      this.palm.addScaledVector(right, dx * DRAG);
      this.palm.y -= dy * DRAG;
    }, { signal });
  }

  /** The camera's heading on the ground: forward and right. */
  heading() {
    const forward = new THREE.Vector3();
    this.camera.getWorldDirection(forward);
    forward.y = 0;
    if (forward.lengthSq() < 1e-8) forward.set(0, 0, 1);
    forward.normalize();
    const right = new THREE.Vector3().crossVectors(forward, new THREE.Vector3(0, 1, 0));
    return { forward, right };
  }

  rotation() {
    const down = new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(0, 0, 1), Math.PI);
    const turn = new THREE.Quaternion().setFromEuler(
      new THREE.Euler(this.turn.y, this.turn.x, this.turn.z, 'YXZ'));
    return turn.multiply(down);
  }

  axis(minus, plus) {
    return (this.held.has(plus) ? 1 : 0) - (this.held.has(minus) ? 1 : 0);
  }

  /** Moves the hand by the keys held over `dt` seconds and poses the world's hand: W S away
   * and back, D A right and left, E Q up and down, J L I K O U turn it (yaw, pitch, roll),
   * G H curl and open all fingers, 1 to 5 curl one (with Shift, open it), T swings the thumb
   * across or back; Shift moves finely. */
  update(dt) {
    const fine = this.held.has('ShiftLeft') || this.held.has('ShiftRight');
    const { forward, right } = this.heading();
    const along = new THREE.Vector3()
      .addScaledVector(forward, this.axis('KeyS', 'KeyW'))
      .addScaledVector(right, this.axis('KeyA', 'KeyD'))
      .addScaledVector(new THREE.Vector3(0, 1, 0), this.axis('KeyQ', 'KeyE'));
    this.palm.addScaledVector(along, (fine ? FINE_SPEED : SPEED) * dt);
    const turn = new THREE.Vector3(this.axis('KeyL', 'KeyJ'), this.axis('KeyK', 'KeyI'),
      this.axis('KeyU', 'KeyO'));
    this.turn.addScaledVector(turn, TURN * dt);
    const all = this.axis('KeyH', 'KeyG');
    this.curl = this.curl.map((c, f) => {
      const own = this.held.has(`Digit${f + 1}`) ? (fine ? -1 : 1) : 0;
      return Math.min(1, Math.max(0, c + (all + own) * CURL_RATE * dt));
    });
    const target = this.opposing ? 1 : 0;
    const step = OPPOSE_RATE * dt;
    this.opposition += Math.max(-step, Math.min(step, target - this.opposition));
    this.pose();
  }

  pose() {
    const q = this.rotation();
    this.world.setHandRig(this.hand, new Float32Array(this.palm.toArray()),
      new Float32Array([q.x, q.y, q.z, q.w]), new Float32Array(this.curl), this.opposition);
  }

  /** Sets the hand's state at once (the tests'). */
  set({ palm, curl, opposition }) {
    if (palm) this.palm.set(...palm);
    if (curl !== undefined) this.curl = Array.isArray(curl) ? curl : [curl, curl, curl, curl, curl];
    if (opposition !== undefined) {
      this.opposition = opposition;
      this.opposing = opposition > 0.5;
    }
  }

  dispose() {
    this.abort.abort();
  }
}
