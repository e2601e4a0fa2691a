// The page in an immersive session, on an emulated headset with hand tracking (iwer's Meta
// Quest 3, whose hands give standard WebXR joints): the page enters immersive-vr; a scripted
// right hand pinches the desk's cube, lifts it and opens. The cube must be held (lifted with
// the hand, pressed by it), then released (no contact presses it) and fall back to the desk.
// Screenshots of the desk page and of the immersive view are checked for the hand's skin and
// the cube's wood. An object removed from the desk page's world is hidden and the others keep
// their rows. Without WebXR, or with the session refused, Enter VR says so and the page
// stays on the desk; Enter AR enters immersive-ar. The immersive pages step only the steps
// the test grants (`granted`), with the hands as the test last set them, so every run is
// the same run, whatever the browser's frame times.
//
//   scripts/web.sh && node web/tests/xr.mjs [SCREENSHOT_DIR]
import path from 'node:path';
import fs from 'node:fs/promises';
import { serve, browser as launch, open, check } from './browser.mjs';
import { colours } from './pixels.mjs';
import { enterVr, object, simulate, aimPinch, pinch } from './emulated.mjs';

const shots = process.argv[2] ?? path.join(process.cwd(), 'target', 'web-screenshots');
await fs.mkdir(shots, { recursive: true });
const server = await serve();
const browser = await launch();

const cube = (page) => object(page, 0);

try {
  // The desk page with the mouse-driven hand closed over the cube, and its screenshot.
  {
    const { page } = await open(browser, server.url, '?run=desk');
    // The viewer's keys drive the hand: E lifts it.
    const palm = () => page.evaluate(() => Array.from(window.app.world.handPose(0).slice(0, 3)));
    const start = await palm();
    await page.keyboard.down('KeyE');
    await simulate(page, 0.5);
    await page.keyboard.up('KeyE');
    const lifted = await palm();
    check(lifted[1] - start[1] > 0.03, `E lifts the desk's hand (${(100 * (lifted[1] - start[1])).toFixed(1)} cm)`);
    const untouched = await colours(page);
    check(untouched.red === 0, 'before the hand touches anything, no force arrow is drawn');
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
    // A browser that refuses the session (or hand tracking): the same.
    await page.evaluate(() => Object.defineProperty(navigator, 'xr', { configurable: true, value: {
      isSessionSupported: async () => true,
      requestSession: async () => {
        throw new DOMException('hand-tracking was refused', 'NotSupportedError');
      },
    } }));
    await page.evaluate(() => window.app.enter('immersive-vr'));
    const denied = await page.evaluate(() => ({ text: document.getElementById('error').textContent,
      mode: window.app.mode, xr: Boolean(window.app.xr), steps: window.app.world.steps }));
    await simulate(page, 0.1);
    check(denied.text.includes('hand-tracking was refused') && denied.mode === 'desk' && !denied.xr,
      `refused, the page says so and stays on the desk: ${denied.text}`);
    await page.close();
  }

  const { page } = await open(browser, server.url, '?run=desk&granted');
  const entered = await enterVr(page);
  check(entered.mode === 'immersive-vr' && entered.presenting,
    `the page entered immersive-vr (${entered.errors})`);
  // The left hand out of the way; the right hand's pinch brought to the cube from the side,
  // its thumb and finger level, 1 cm below the cube's middle (`aimPinch`).
  await page.evaluate(() => window.device.hands.left.position.set(-0.5, 1.6, 0.2));
  const squeeze = await aimPinch(page, 'right', 0, 0.04, [0.15, 1.0, -0.3]);
  const before = await cube(page);
  check(before.pressing === 0 && Math.abs(before.y - 0.02) < 0.003,
    `open, the hand around the cube does not move it (y ${before.y.toFixed(4)})`);
  // Pinch over 0.4 s, hold, lift 12 cm over 1 s.
  await pinch(page, 'right', squeeze);
  await simulate(page, 0.2);
  const gripped = await cube(page);
  for (let k = 1; k <= 20; k++) {
    await page.evaluate(() => { window.device.hands.right.position.y += 0.006; });
    await simulate(page, 0.05);
  }
  await simulate(page, 0.3);
  const held = await cube(page);
  const file = path.join(shots, 'immersive.png');
  await page.screenshot({ path: file });
  const seen = await colours(page);
  check(gripped.pressing >= 2, `pinched: ${gripped.pressing} contacts press on the cube (${JSON.stringify(gripped)})`);
  check(held.pressing >= 2 && held.y > before.y + 0.08,
    `held: lifted ${(100 * (held.y - before.y)).toFixed(1)} cm with the hand, pressed by it`);
  check(seen.skin > 300 && seen.wood > 100 && seen.red > 20,
    `immersive screenshot: the hand (${seen.skin} skin pixels), the cube (${seen.wood} wood pixels) and the grip's force arrows (${seen.red} red pixels)`);
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
  // An object removed from the page's world: its numbers go NaN, its name empty and its mesh
  // hidden; the others keep their rows and stay where they were, and the page runs on.
  {
    const { page: desk } = await open(browser, server.url, '?run=desk');
    await simulate(desk, 0.3);
    const read = () => desk.evaluate(() => {
      const world = window.app.world;
      const s = world.objectStates();
      const rows = Array.from({ length: world.objectCount() }, (_, id) =>
        (Number.isNaN(s[17 * id]) ? null : Array.from(s.subarray(17 * id, 17 * id + 3))));
      return { rows, names: world.objectNames(), time: world.time,
        shown: window.app.shownObjects(), errors: window.app.errors };
    });
    const before = await read();
    await desk.evaluate(() => window.app.world.removeObject(1));
    await simulate(desk, 0.3);
    const after = await read();
    const again = await desk.evaluate(() => {
      try { window.app.world.removeObject(1); return ''; } catch (e) { return String(e.message ?? e); }
    });
    const kept = [0, 2, 3].every((id) => after.rows[id] && after.rows[id].every(
      (v, k) => Math.abs(v - before.rows[id][k]) < 0.001) && after.names[id] === before.names[id]);
    check(after.rows.length === before.rows.length && after.rows[1] === null && after.names[1] === ''
      && before.shown[1] && !after.shown[1] && after.shown[0],
      `removed: the ${before.names[1]}'s row is NaN, its name empty, its mesh hidden`);
    check(kept, `the other objects keep their rows and rest where they were (${JSON.stringify(after.rows)})`);
    check(/1/.test(again), `removing it again is an error naming it (${again})`);
    check(after.time > before.time && after.errors.length === 0, `the page runs on (${after.errors})`);
    await desk.close();
  }
  // Enter AR: the same desk and hands over the room, its backdrop and ground not drawn.
  {
    const { page: ar } = await open(browser, server.url, '?run=desk&granted');
    const inAr = await enterVr(ar, 'immersive-ar');
    await simulate(ar, 0.2);
    const state = await ar.evaluate(() => ({ hands: window.app.world.handCount(),
      mode: window.app.mode, errors: window.app.errors }));
    check(inAr.mode === 'immersive-ar' && inAr.presenting && state.mode === 'desk' && state.hands === 2,
      `the page entered immersive-ar on the desk with both hands (${state.errors})`);
    // Holding the cube, the hand stops being tracked (the headset's input goes to its
    // controllers): the world's hand is cleared, so it lets go, and the cube falls.
    await ar.evaluate(() => window.device.hands.left.position.set(-0.5, 1.6, 0.2));
    const squeezeAr = await aimPinch(ar, 'right', 0, 0.04, [0.15, 1.0, -0.3]);
    await pinch(ar, 'right', squeezeAr);
    await simulate(ar, 0.2);
    for (let k = 1; k <= 10; k++) {
      await ar.evaluate(() => { window.device.hands.right.position.y += 0.006; });
      await simulate(ar, 0.05);
    }
    const lifted = await object(ar, 0);
    await ar.evaluate(() => { window.device.primaryInputMode = 'controller'; });
    await simulate(ar, 1.0);
    const dropped = await object(ar, 0);
    const pose = await ar.evaluate(() => window.app.world.handPose(window.app.xr.hands.right).length);
    check(lifted.pressing >= 2 && lifted.y > 0.06 && dropped.pressing === 0 && pose === 0
      && Math.abs(dropped.y - 0.02) < 0.01,
      `untracked, the hand lets go: the cube held at ${(100 * lifted.y).toFixed(1)} cm fell to ${(100 * dropped.y).toFixed(1)} cm`);
    await ar.close();
  }
} finally {
  await browser.close();
  server.close();
}
