// Headless Chromium loads the page and runs the demo and the grasp-lift scenario through its
// own frame loop; their traces (every 250 steps, the objects' states and the contacts, bit for
// bit) must equal the native library's (`examples/reference.rs` of crates/coulomb-hands-web,
// built with enhanced-determinism, as the page is), and the scenario's report too. Every
// shipped scenario, chosen in the page, reports as natively (and passes), and the bundled
// recording's closings get the native verdicts; the bundled capture draws its captured object as
// a ghost that rises as the captured hand lifts it. Then a malformed scene shows its error and
// the page keeps running.
//
//   scripts/web.sh
//   cargo run -p coulomb-hands-web --features enhanced-determinism --example reference > ref.json
//   node web/tests/page.mjs ref.json
import fs from 'node:fs/promises';
import { serve, browser as launch, open, check } from './browser.mjs';

const reference = JSON.parse(await fs.readFile(process.argv[2], 'utf8'));
const server = await serve();
const browser = await launch();
try {
  for (const run of ['demo', 'grasp-lift']) {
    const { page, console } = await open(browser, server.url, `?run=${run}&fast&trace`);
    await page.waitForFunction(() => window.app.done, { timeout: 300_000 });
    const got = await page.evaluate(() => ({
      steps: window.app.world.steps, trace: window.app.trace, report: window.app.world.report(),
      errors: window.app.errors,
    }));
    const expected = reference[run];
    check(got.errors.length === 0 && console.length === 0, `${run}: no errors (${got.errors} ${console})`);
    check(got.steps === expected.steps, `${run}: ${got.steps} steps, as natively`);
    check(got.trace.length === expected.rows.length, `${run}: ${got.trace.length} trace rows`);
    const first = got.trace.findIndex((row, k) => row !== expected.rows[k]);
    check(first === -1, `${run}: every row bit-equal to the native library's`
      + (first === -1 ? '' : ` (row ${first} differs:\n${got.trace[first]}\n${expected.rows[first]})`));
    if (expected.report) {
      check(got.report === expected.report, `${run}: the report equals the native one`);
      check(JSON.parse(got.report).passed, `${run}: its checks pass`);
    }
    await page.close();
  }
  // Every shipped scenario and the recording, one after another as a user picks them.
  {
    const { page, console } = await open(browser, server.url, '?run=desk&fast');
    for (const name of [...Object.keys(reference.reports), 'recording']) {
      await page.select('#mode', name);
      await page.waitForFunction((n) => window.app.mode === n && window.app.done, { timeout: 300_000 }, name);
      const got = await page.evaluate(() => ({ report: window.app.world.report(),
        verdicts: window.app.world.verdicts(), steps: window.app.world.steps, shown: document.getElementById('report').textContent }));
      if (name === 'recording') {
        check(got.steps === reference.recording.steps && got.verdicts === reference.recording.verdicts,
          `the recording: ${got.steps} steps, its ${JSON.parse(got.verdicts).length} closings' verdicts as natively`);
        check(got.shown.includes('closing-1'), 'the verdicts shown on the page');
      } else {
        check(got.report === reference.reports[name] && JSON.parse(got.report).passed,
          `${name}: the native report, passed`);
      }
    }
    check(console.length === 0, `no console errors (${console})`);
    await page.close();
  }
  // The bundled capture: its captured object drawn as a see-through ghost at the captured pose,
  // which rises as the captured hand lifts it, and TACO credited.
  {
    const { page, console } = await open(browser, server.url, '?run=capture&granted');
    const ghost = () => page.evaluate(() => ({ ghost: window.app.shownGhost(),
      steps: window.app.world.steps, credit: !document.getElementById('credit').hidden,
      objects: window.app.shownObjects() }));
    const start = await ghost();
    const shown = start.ghost && start.ghost.inScene && start.ghost.visible;
    check(shown && start.ghost.triangles === 2000 && Math.abs(start.ghost.opacity - 0.35) < 1e-6,
      `the capture's ghost is drawn: ${JSON.stringify(start.ghost)}`);
    check(start.credit && start.objects.length === 1 && start.objects[0], 'TACO credited, the object drawn');
    await page.evaluate(() => window.app.grant(1300));
    await page.waitForFunction(() => window.app.world.steps === 1300, { timeout: 120_000 });
    const lifted = await ghost();
    const rise = lifted.ghost.position[1] - start.ghost.position[1];
    check(rise > 0.05, `the ghost rose ${(rise * 1000).toFixed(1)} mm by 1.3 s`);
    check(console.length === 0, `no console errors (${console})`);
    await page.close();
  }
  // Bad input: the library's message on the page and in the console, and the page runs on.
  const { page, console } = await open(browser, server.url, '?run=desk');
  const shown = await page.evaluate(async () => {
    const file = new File(['{"objects": [{"name": 3}]}'], 'broken-scene.json');
    const loaded = await window.app.load('desk', file);
    const steps = window.app.world.steps;
    await new Promise((r) => setTimeout(r, 500));
    return { loaded, text: document.getElementById('error').textContent, mode: window.app.mode,
      moved: window.app.world.steps > steps };
  });
  check(!shown.loaded && shown.text.startsWith('broken-scene.json'), `a bad scene's error is shown: ${shown.text}`);
  check(console.some((m) => m.includes('broken-scene.json')), 'and in the console');
  check(shown.mode === 'desk' && shown.moved, 'the desk keeps running');
  // A broken mesh and a broken recording: the same.
  for (const [name, content] of [['broken.obj', 'v 1 2\nf 1 2 3\n'], ['broken.json.lz', 'not lz']]) {
    const got = await page.evaluate(async (name, content) => {
      const loaded = await window.app.load('desk', new File([content], name));
      return { loaded, text: document.getElementById('error').textContent, mode: window.app.mode };
    }, name, content);
    check(!got.loaded && got.text.startsWith(name) && got.mode === 'desk', `${name}: ${got.text}`);
  }
  await page.close();
} finally {
  await browser.close();
  server.close();
}
