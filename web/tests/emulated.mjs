// The page on an emulated headset: iwer's Meta Quest 3 with hand tracking, installed over the
// page's navigator.xr, and a hand of it aimed to pinch an object of the desk. Shared by the
// immersive test (xr.mjs) and the frame budget's benchmark (web/bench/bench.mjs).
import * as THREE from 'three';
import { check } from './browser.mjs';


/** Installs the emulated headset, its head above and behind the desk, looking down at it, and
 * enters an immersive session (`mode`) through the page's own Enter VR (or AR). */
export async function enterVr(page, mode = 'immersive-vr') {
  await page.addScriptTag({ type: 'module', content: `
    import { XRDevice, metaQuest3 } from '/node_modules/iwer/build/iwer.module.js';
    const device = new XRDevice(metaQuest3);
    device.primaryInputMode = 'hand';
    device.installRuntime({ forceInstall: true });
    device.position.set(0, 1.18, -0.12);
    window.device = device;` });
  await page.waitForFunction(() => window.device);
  await page.evaluate((q) => window.device.quaternion.set(...q),
    new THREE.Quaternion().setFromEuler(new THREE.Euler(-0.8, 0, 0)).toArray());
  await page.evaluate((mode) => window.app.enter(mode), mode);
  return page.evaluate(() => ({ mode: window.app.xr && window.app.xr.mode,
    presenting: Boolean(window.app.xr && window.app.xr.renderer.xr.isPresenting),
    errors: window.app.errors }));
}

/** An object's position (id, by the desk's order: cube, ball, block, can), how many contacts
 * press on it, and the world's time. */
export const object = (page, id = 0) => page.evaluate((id) => {
  const world = window.app.world;
  const s = world.objectStates().subarray(17 * id, 17 * id + 3);
  const c = world.contacts();
  let pressing = 0;
  for (let k = 0; k < c.length; k += 18) if (c[k] === id && c[k + 17] > 0) pressing++;
  return { x: s[0], y: s[1], z: s[2], pressing, time: world.time };
}, id);

/** Waits `seconds` of the page's simulated time: on a page opened with `granted`, exactly
 * that many steps, run with the hands as posed now; otherwise as many as the browser's frames
 * run in that time. */
export async function simulate(page, seconds) {
  const target = await page.evaluate((seconds) => {
    const app = window.app;
    const world = app.world;
    if (!app.granting) return { time: world.time + seconds };
    const steps = Math.round(seconds / world.dt);
    app.grant(steps);
    return { steps: world.steps + steps };
  }, seconds);
  await page.waitForFunction((target) => {
    const world = window.app.world;
    return target.steps === undefined ? world.time >= target.time : world.steps >= target.steps;
  }, { timeout: 120_000 }, target);
}

/** Aims the `side` hand to pinch object `id` of width `width` (m) across it: turned so that
 * its thumb and index tips close on each other level, the point between them `height` (m)
 * above the object's middle, open. Returns the pinch value that sinks each tip 4 mm into the
 * object, as the demo's pads squeeze (the tips' gap closes about linearly with iwer's pinch).
 *
 * iwer's pinch brings the index down onto the thumb from above, its bones sloping to the tip.
 * Pinched at the middle of the desk's 4 cm cube, they lie over its top edge, and the thumb and
 * index press adjacent faces, a grip that cannot lift; hence the default, 1 cm below the
 * middle. Measured on the immersive test's lift, in 1–2 mm steps of `height`: from 14 to 7 mm
 * below the middle every pinch lifts the cube; from 6 mm below to 6 mm above, 6 of 10 land on
 * the top edge and drop it. */
export async function aimPinch(page, side, id, width, start, height = -0.01) {
  await page.evaluate((side, start) => {
    const hand = window.device.hands[side];
    hand.position.set(...start);
    hand.quaternion.set(0, 0, 0, 1);
  }, side, start);
  await simulate(page, 0.2);
  const pinchTo = async (value) => {
    await page.evaluate((side, v) => window.device.hands[side].updatePinchValue(v), side, value);
    await simulate(page, 0.2);
    const j = await page.evaluate((side) => window.app.joints[side], side);
    if (!j) throw new Error(`the emulated ${side} hand is not tracked`);
    const [thumb, index] = [j.slice(12, 15), j.slice(27, 30)];
    const gap = Math.hypot(...index.map((v, k) => v - thumb[k]));
    return { thumb, index, gap, middle: thumb.map((v, k) => (v + index[k]) / 2) };
  };
  const apart = (await pinchTo(0)).gap;
  const closed = (await pinchTo(1)).gap;
  const squeeze = (apart - (width - 0.008)) / (apart - closed);
  let t = await pinchTo(squeeze);
  const across = new THREE.Vector3(...t.index).sub(new THREE.Vector3(...t.thumb)).normalize();
  const level = new THREE.Vector3(across.x, 0, across.z).normalize();
  const turn = new THREE.Quaternion().setFromUnitVectors(across, level);
  await page.evaluate((side, q) => window.device.hands[side].quaternion.set(...q), side, turn.toArray());
  t = await pinchTo(squeeze);
  check(Math.abs(t.index[1] - t.thumb[1]) < 0.005,
    `${side}: at the pinch, the tips level and ${(1000 * t.gap).toFixed(1)} mm apart`);
  await pinchTo(0);
  const at = await object(page, id);
  const move = [at.x, at.y + height, at.z].map((v, k) => v - t.middle[k]);
  await page.evaluate((side, d) => {
    const p = window.device.hands[side].position;
    p.set(p.x + d[0], p.y + d[1], p.z + d[2]);
  }, side, move);
  await simulate(page, 0.2);
  return squeeze;
}

/** Closes the `side` hand to `squeeze` over 0.4 s of simulated time. */
export async function pinch(page, side, squeeze) {
  for (let k = 1; k <= 8; k++) {
    await page.evaluate((side, v) => window.device.hands[side].updatePinchValue(v), side, squeeze * k / 8);
    await simulate(page, 0.05);
  }
}
