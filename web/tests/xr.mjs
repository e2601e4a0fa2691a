// The page in an immersive session, on an emulated headset with hand tracking (iwer's Meta
// Quest 3, whose hands give standard WebXR joints): the page enters immersive-vr; a scripted
// right hand pinches the desk's cube, lifts it and opens. The cube must be held (lifted with
// the hand, pressed by it), then released (no contact presses it) and fall back to the desk.
// Screenshots of the desk page and of the immersive view are checked for the hand's skin and
// the cube's wood. Without WebXR, Enter VR says so and the page stays on the desk.
//
//   node web/tests/xr.mjs [SCREENSHOT_DIR]
import path from 'node:path';
import fs from 'node:fs/promises';
import { serve, browser as launch, open, check } from './browser.mjs';
import { colours } from './pixels.mjs';
import * as THREE from 'three';

const shots = process.argv[2] ?? path.join(process.cwd(), 'target', 'web-screenshots');
await fs.mkdir(shots, { recursive: true });
const server = await serve();
const browser = await launch();

// The page's cube (id 0, the desk's first object) and whether a hand presses it.
const cube = (page) => page.evaluate(() => {
  const world = window.app.world;
  const s = world.objectStates();
  const c = world.contacts();
  let pressing = 0;
  for (let k = 0; k < c.length; k += 18) if (c[k] === 0 && c[k + 17] > 0) pressing++;
  return { y: s[1], x: s[0], z: s[2], pressing, time: world.time };
});

// Waits `seconds` of the page's simulated time.
async function simulate(page, seconds) {
  const start = await page.evaluate(() => window.app.world.time);
  await page.waitForFunction((t) => window.app.world.time >= t, { timeout: 120_000 }, start + seconds);
}

try {
  // The desk page with the mouse-driven hand closed over the cube, and its screenshot.
  {
    const { page } = await open(browser, server.url, '?run=desk');
    await page.evaluate(() => window.app.mouseHand().set({ palm: [0, 0.07, -0.06], curl: 0.3 }));
    await simulate(page, 0.3);
    const file = path.join(shots, 'desk.png');
    await page.screenshot({ path: file });
    const seen = await colours(page);
    check(seen.skin > 500, `desk screenshot: the hand drawn (${seen.skin} skin pixels)`);
    check(seen.wood > 300, `desk screenshot: the cube drawn (${seen.wood} wood pixels)`);
    // No WebXR here: Enter VR says so and the page stays on the desk.
    await page.evaluate(() => window.app.enter('immersive-vr'));
    const refused = await page.evaluate(() => ({ text: document.getElementById('error').textContent,
      mode: window.app.mode, xr: Boolean(window.app.xr) }));
    check(/Enter VR: .*staying on the desk/.test(refused.text) && refused.mode === 'desk' && !refused.xr,
      `without WebXR, the page says so: ${refused.text}`);
    await page.close();
  }

  const { page } = await open(browser, server.url, '?run=desk');
  await page.addScriptTag({ type: 'module', content: `
    import { XRDevice, metaQuest3 } from '/node_modules/iwer/build/iwer.module.js';
    const device = new XRDevice(metaQuest3);
    device.primaryInputMode = 'hand';
    device.installRuntime({ forceInstall: true });
    // The head 40 cm behind and above the desk, looking down at it.
    device.position.set(0, 1.3, 0.05);
    window.device = device;` });
  await page.waitForFunction(() => window.device);
  await page.evaluate((q) => window.device.quaternion.set(...q),
    new THREE.Quaternion().setFromEuler(new THREE.Euler(-0.75, 0, 0)).toArray());
  await page.evaluate(() => window.app.enter('immersive-vr'));
  const entered = await page.evaluate(() => ({ xr: window.app.xr && window.app.xr.mode,
    presenting: window.app.xr && window.app.xr.renderer.xr.isPresenting, errors: window.app.errors }));
  check(entered.xr === 'immersive-vr' && entered.presenting, `the page entered immersive-vr (${entered.errors})`);

  // The left hand out of the way; the right hand's pinch (between its thumb and index tips)
  // brought to the cube's middle, from the side, its thumb and finger level.
  await page.evaluate(() => {
    const { left, right } = window.device.hands;
    left.position.set(-0.5, 1.6, 0.2);
    right.position.set(0.15, 1.0, -0.3);
    right.quaternion.set(0, 0, 0, 1);
  });
  await simulate(page, 0.2);
  const tips = () => page.evaluate(() => {
    const j = window.app.joints.right;
    return j && { thumb: j.slice(12, 15), index: j.slice(27, 30) };
  });
  // How far apart iwer's pinch value puts the thumb and index tips.
  const pinchTo = async (value) => {
    await page.evaluate((v) => window.device.hands.right.updatePinchValue(v), value);
    await simulate(page, 0.2);
    const t = await tips();
    const gap = Math.hypot(...t.index.map((v, k) => v - t.thumb[k]));
    return { ...t, gap, middle: t.thumb.map((v, k) => (v + t.index[k]) / 2) };
  };
  check((await tips()) !== null, 'the emulated right hand is tracked');
  const apart = (await pinchTo(0)).gap;
  const closed = (await pinchTo(1)).gap;
  // The pinch that brings the tips 4 mm into each side of the 4 cm cube, as the demo's pads
  // squeeze (the gap closes about linearly with the pinch value).
  const squeeze = (apart - (0.04 - 0.008)) / (apart - closed);
  // Turn the hand so that its tips close on each other level at that pinch, then put the
  // point between them at the cube's middle, and open.
  let t = await pinchTo(squeeze);
  const across = new THREE.Vector3(...t.index).sub(new THREE.Vector3(...t.thumb)).normalize();
  const level = new THREE.Vector3(across.x, 0, across.z).normalize();
  const turn = new THREE.Quaternion().setFromUnitVectors(across, level);
  await page.evaluate((q) => window.device.hands.right.quaternion.set(...q), turn.toArray());
  t = await pinchTo(squeeze);
  check(Math.abs(t.index[1] - t.thumb[1]) < 0.005,
    `at the pinch, the tips level and ${(1000 * t.gap).toFixed(1)} mm apart`);
  const meet = t.middle;
  await pinchTo(0);
  const state0 = await cube(page);
  const target = [state0.x, state0.y + 0.004, state0.z];
  await page.evaluate((d) => {
    const p = window.device.hands.right.position;
    p.set(p.x + d[0], p.y + d[1], p.z + d[2]);
  }, target.map((v, k) => v - meet[k]));
  await simulate(page, 0.2);
  const before = await cube(page);
  check(before.pressing === 0 && Math.abs(before.y - state0.y) < 0.003,
    `open, the hand around the cube does not move it (y ${before.y.toFixed(4)})`);
  // Pinch over 0.4 s, hold, lift 12 cm over 1 s.
  for (let k = 1; k <= 8; k++) {
    await page.evaluate((v) => window.device.hands.right.updatePinchValue(v), squeeze * k / 8);
    await simulate(page, 0.05);
  }
  await simulate(page, 0.3);
  const gripped = await cube(page);
  for (let k = 1; k <= 20; k++) {
    await page.evaluate(() => { window.device.hands.right.position.y += 0.006; });
    await simulate(page, 0.05);
  }
  await simulate(page, 0.3);
  const held = await cube(page);
  if (process.env.DEBUG) {
    console.log(JSON.stringify({ before, gripped, held, tips: await tips(),
      contacts: await page.evaluate(() => Array.from(window.app.world.contacts())) }));
  }
  const file = path.join(shots, 'immersive.png');
  await page.screenshot({ path: file });
  const seen = await colours(page);
  check(gripped.pressing >= 2, `pinched: ${gripped.pressing} contacts press on the cube`);
  check(held.pressing >= 2 && held.y > before.y + 0.08,
    `held: lifted ${(100 * (held.y - before.y)).toFixed(1)} cm with the hand, pressed by it`);
  check(seen.skin > 300 && seen.wood > 100,
    `immersive screenshot: the hand (${seen.skin} skin pixels) and the cube (${seen.wood} wood pixels)`);
  // Open: released, it falls back to the desk.
  await page.evaluate(() => window.device.hands.right.updatePinchValue(0));
  await simulate(page, 0.15);
  const released = await cube(page);
  await simulate(page, 0.8);
  const fell = await cube(page);
  check(released.pressing === 0, 'released: no contact presses the cube once the hand opens');
  check(Math.abs(fell.y - before.y) < 0.01, `fell back to the desk (y ${fell.y.toFixed(4)}, was ${held.y.toFixed(4)})`);
  const errors = await page.evaluate(() => window.app.errors);
  check(errors.length === 0, `no errors on the page (${errors})`);
  await page.close();
} finally {
  await browser.close();
  server.close();
}
