// The page's budgets (issue 44), measured, not tested:
// - the page's WebAssembly, gzipped (at most 1.5 MB);
// - a step of the demo in Chromium against the native library's, side by side on this machine
//   (within 2×): the demo's mean step, best of 5 whole runs, in the page and natively
//   (crates/coulomb-hands-web/examples/bench.rs, run here in release, with and without
//   enhanced-determinism; the page is built with it);
// - a 90 Hz frame keeping up with 1 kHz physics for two hands: on the emulated headset, the
//   right hand pinching the desk's cube and the left its ball, 900 frames each posing both
//   hands from their WebXR joints (carrying what they hold up and down) and stepping 11 or 12
//   steps (1000 a second), timed; the objects' pressing contacts before and after.
//
//   node web/bench/bench.mjs [OUT.json]   (after scripts/web.sh; prints one JSON object, and
//                                         writes it to OUT.json, target/web-bench.json by default)
import fs from 'node:fs/promises';
import zlib from 'node:zlib';
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { serve, browser as launch, open, WEB } from '../tests/browser.mjs';
import { enterVr, aimPinch, pinch, simulate, object } from '../tests/emulated.mjs';

const wasm = await fs.readFile(path.join(WEB, 'pkg', 'coulomb_hands_web_bg.wasm'));
const native = (features) => JSON.parse(execFileSync('cargo', ['run', '-q', '--release', '--locked',
  '-p', 'coulomb-hands-web', ...features, '--example', 'bench'], { cwd: path.join(WEB, '..') }));
const result = {
  wasm_bytes: wasm.length,
  wasm_gzip_bytes: zlib.gzipSync(wasm, { level: 9 }).length,
  native: native([]),
  native_enhanced_determinism: native(['--features', 'enhanced-determinism']),
};
const server = await serve();
const browser = await launch();
try {
  const { page } = await open(browser, server.url, '?run=desk');
  await page.evaluate(() => { window.app.paused = true; });
  result.page_demo_step_us = await page.evaluate(() => {
    let best = Infinity;
    for (let k = 0; k < 5; k++) {
      const demo = window.app.wasm.World.demo();
      const start = performance.now();
      while (!demo.finished) demo.step(1000);
      best = Math.min(best, (performance.now() - start) / demo.steps);
      demo.free();
    }
    return best * 1000;
  });
  result.page_over_native = result.page_demo_step_us / result.native_enhanced_determinism.demo_step_us;
  result.page_over_native_default = result.page_demo_step_us / result.native.demo_step_us;
  await page.evaluate(() => { window.app.paused = false; });

  await enterVr(page);
  const right = await aimPinch(page, 'right', 0, 0.04, [0.15, 1.0, -0.3]);
  await pinch(page, 'right', right);
  const left = await aimPinch(page, 'left', 1, 0.06, [0.0, 1.0, -0.3], 0.004);
  await pinch(page, 'left', left);
  await simulate(page, 0.3);
  const held = [await object(page, 0), await object(page, 1)].map((o) => o.pressing);
  result.frames = await page.evaluate(() => {
    const app = window.app;
    app.paused = true;
    const world = app.world;
    const hands = app.xr.hands;
    const frames = [];
    let steps = 0;
    // Both hands carry what they hold up and down, 4 cm either way once a second, as a frame's
    // joints would move them.
    const moved = { left: new Float32Array(75), right: new Float32Array(75) };
    for (let f = 0; f < 900; f++) {
      const n = Math.floor(((f + 1) * 1000) / 90) - Math.floor((f * 1000) / 90);
      const lift = 0.04 * (1 - Math.cos((2 * Math.PI * f) / 90));
      const start = performance.now();
      for (const side of ['left', 'right']) {
        const [positions, radii, orientations] = app.jointArrays[side];
        for (let k = 0; k < 75; k++) moved[side][k] = positions[k] + (k % 3 === 1 ? lift : 0);
        world.setHandWebxr(hands[side], moved[side], radii, orientations);
      }
      steps += world.step(n);
      frames.push(performance.now() - start);
    }
    frames.sort((a, b) => a - b);
    const mean = frames.reduce((a, b) => a + b, 0) / frames.length;
    return { frames: frames.length, steps, budget_ms: 1000 / 90, mean_ms: mean,
      p95_ms: frames[Math.floor(0.95 * frames.length)], max_ms: frames[frames.length - 1],
      over_budget: frames.filter((t) => t > 1000 / 90).length,
      contacts: world.contacts().length / 18 };
  });
  result.frames.pressing_before = held;
  const after = [await object(page, 0), await object(page, 1)];
  result.frames.pressing_after = after.map((o) => o.pressing);
  result.frames.heights_after = after.map((o) => o.y);
} finally {
  await browser.close();
  server.close();
}
const out = process.argv[2] ?? path.join(WEB, '..', 'target', 'web-bench.json');
await fs.writeFile(out, JSON.stringify(result, null, 2));
console.log(JSON.stringify(result, null, 2));
