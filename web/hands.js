// The thesis's visuals (§3.6): each hand as its 16 bones (a palm box and 15 capsules), drawn
// semi-transparent, and opaque while it touches an object; red arrows for the contacts' forces
// on the objects and yellow ones for the hand's motion (its palm and fingertips).
import * as THREE from 'three';

export const SKIN = 0xe0896b;
const SEE_THROUGH = 0.35;
// Arrow lengths: metres per newton of contact force, and seconds of hand motion.
const FORCE_SCALE = 0.08;
const MOTION_SCALE = 0.12;
const MIN_ARROW = 0.004;

const cylinder = new THREE.CylinderGeometry(1, 1, 1, 14, 1, true);
const sphere = new THREE.SphereGeometry(1, 14, 10);
const box = new THREE.BoxGeometry(2, 2, 2);
const up = new THREE.Vector3(0, 1, 0);

/** One hand: `update(pose)` with the world's `poseStride()` numbers, `hide()` while untracked. */
export class HandView {
  constructor(parent) {
    this.material = new THREE.MeshStandardMaterial({ color: SKIN, roughness: 0.7, transparent: true });
    this.group = new THREE.Group();
    this.palm = new THREE.Mesh(box, this.material);
    this.group.add(this.palm);
    this.bones = [];
    for (let k = 0; k < 15; k++) {
      const shaft = new THREE.Mesh(cylinder, this.material);
      const a = new THREE.Mesh(sphere, this.material);
      const b = new THREE.Mesh(sphere, this.material);
      this.group.add(shaft, a, b);
      this.bones.push({ shaft, a, b });
    }
    parent.add(this.group);
    this.previous = null;
    this.setOpaque(false);
  }

  setOpaque(opaque) {
    this.material.opacity = opaque ? 1 : SEE_THROUGH;
    this.material.depthWrite = opaque;
    this.opaque = opaque;
  }

  hide() {
    this.group.visible = false;
    this.previous = null;
  }

  update(pose) {
    this.group.visible = true;
    this.palm.position.set(pose[0], pose[1], pose[2]);
    this.palm.quaternion.set(pose[3], pose[4], pose[5], pose[6]);
    this.palm.scale.set(pose[7], pose[8], pose[9]);
    const a = new THREE.Vector3();
    const b = new THREE.Vector3();
    for (let k = 0; k < 15; k++) {
      const at = 10 + 7 * k;
      a.set(pose[at], pose[at + 1], pose[at + 2]);
      b.set(pose[at + 3], pose[at + 4], pose[at + 5]);
      const r = pose[at + 6];
      const bone = this.bones[k];
      const along = b.clone().sub(a);
      const length = along.length();
      bone.shaft.position.copy(a).add(b).multiplyScalar(0.5);
      bone.shaft.quaternion.setFromUnitVectors(up, length > 0 ? along.divideScalar(length) : up);
      bone.shaft.scale.set(r, Math.max(length, 1e-6), r);
      bone.a.position.copy(a);
      bone.b.position.copy(b);
      bone.a.scale.setScalar(r);
      bone.b.scale.setScalar(r);
    }
  }

  /** The palm's centre and the five fingertips, to show the hand's motion. */
  static points(pose) {
    const points = [[pose[0], pose[1], pose[2]]];
    for (let f = 0; f < 5; f++) {
      const at = 10 + 7 * (3 * f + 2) + 3;
      points.push([pose[at], pose[at + 1], pose[at + 2]]);
    }
    return points;
  }
}

const shaftGeometry = new THREE.CylinderGeometry(1, 1, 1, 8).translate(0, 0.5, 0);
const headGeometry = new THREE.ConeGeometry(1, 1, 12).translate(0, 0.5, 0);
// Arrow widths (m): a shaft's radius, and its head's radius and length at the most.
const SHAFT = 0.0012;
const HEAD = 0.0035;
const HEAD_LENGTH = 0.009;

/** A pool of solid arrows of one colour, unlit and drawn over everything, afresh each frame. */
export class Arrows {
  constructor(parent, color) {
    this.parent = parent;
    this.material = new THREE.MeshBasicMaterial({ color, depthTest: false });
    this.pool = [];
    this.used = 0;
  }

  begin() {
    this.used = 0;
  }

  add(from, vector, scale) {
    const length = Math.hypot(vector[0], vector[1], vector[2]) * scale;
    if (!(length > MIN_ARROW)) return;
    if (this.used === this.pool.length) {
      const arrow = new THREE.Group();
      arrow.add(new THREE.Mesh(shaftGeometry, this.material), new THREE.Mesh(headGeometry, this.material));
      arrow.children.forEach((m) => { m.renderOrder = 10; });
      this.parent.add(arrow);
      this.pool.push(arrow);
    }
    const arrow = this.pool[this.used++];
    const direction = new THREE.Vector3(vector[0], vector[1], vector[2]).normalize();
    arrow.position.set(from[0], from[1], from[2]);
    arrow.quaternion.setFromUnitVectors(up, direction);
    const head = Math.min(0.35 * length, HEAD_LENGTH);
    const [shaft, tip] = arrow.children;
    shaft.scale.set(SHAFT, length - head, SHAFT);
    tip.position.set(0, length - head, 0);
    tip.scale.set(HEAD * head / HEAD_LENGTH, head, HEAD * head / HEAD_LENGTH);
    arrow.visible = true;
  }

  end() {
    for (let k = this.used; k < this.pool.length; k++) this.pool[k].visible = false;
  }
}

export { FORCE_SCALE, MOTION_SCALE };
