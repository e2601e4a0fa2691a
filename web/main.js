// The page: the library in WebAssembly (pkg/, built by scripts/web.sh), drawn with three.js.
// Physics steps at its own 1 kHz clock, as many steps per frame as the frame's time holds,
// whatever the display's rate; hands come from the run's script, the mouse and keys (the
// desk), or WebXR hand tracking (Enter VR / Enter AR).
//
// URL parameters: `run=demo|desk|recording|capture|<scenario name>` picks the run; `fast` steps 250
// steps a frame whatever the clock (the tests'); `granted` steps only the steps granted by
// `app.grant(n)`, each grant run whole at the next frame, after the hands are posed (and
// the hands posed only then), so a test that moves a hand and then grants steps gets the
// same run in every browser and at any frame rate (the immersive test's); `trace` records
// the run's trace (trace.js), which the browser test compares with the native library's.
import * as THREE from 'three';
import { OrbitControls } from 'three/controls/OrbitControls.js';
import init, * as wasm from './pkg/coulomb_hands_web.js';
import { HandView, Arrows, FORCE_SCALE, MOTION_SCALE } from './hands.js';
import { MouseHand } from './mouse.js';
import { XrHands, xrSupported, startXr } from './xr.js';
import { traceRow, TRACE_EVERY } from './trace.js';

const params = new URLSearchParams(location.search);
// Stepping only what a test grants (`granted`).
const GRANTING = params.has('granted');
// At most this many steps in one frame (100 ms of physics): a stalled tab catches up slowly
// rather than freezing on a long backlog.
const MAX_STEPS_PER_FRAME = 100;
const FAST_STEPS_PER_FRAME = 250;
// Where the desk's origin sits in an immersive session's floor-level space (m): a table
// height ahead of the viewer.
const XR_DESK = new THREE.Vector3(0, 0.85, -0.4);
// The captured object of a capture, drawn beside the simulated one: light blue, see-through.
const GHOST_COLOR = 0x9ecbff;
const GHOST_OPACITY = 0.35;
// The bundled hand–object capture (TACO) and the mesh it names, copied into data/ by
// scripts/web.sh.
const CAPTURE = 'taco_20231104_017';
const MATERIAL_COLORS = { wood: 0xd9a441, rubber: 0x3a7bd5, aluminium: 0xb8bcc4, steel: 0x9aa0a8,
  glass: 0x9fd8e8, plastic: 0x52b788, ceramic: 0xf1f1e6 };

const status = document.getElementById('status');
const reportBox = document.getElementById('report');
const errorBox = document.getElementById('error');
const modeSelect = document.getElementById('mode');
const credit = document.getElementById('credit');

// Every error shows on the page and in the console, and the page keeps running.
function showError(error) {
  const message = error instanceof Error ? error.message : String(error);
  console.error(message);
  errorBox.textContent = message;
  errorBox.hidden = false;
  app.errors.push(message);
}

function clearError() {
  errorBox.hidden = true;
}

const pauseButton = document.getElementById('pause');
function setPaused(paused) {
  app.paused = paused;
  pauseButton.textContent = paused ? 'Resume' : 'Pause';
}

const app = {
  ready: false,
  world: null,
  mode: null,
  paused: false,
  done: false,
  trace: [],
  errors: [],
  xr: null,
  frames: 0,
  // The WebXR joints last given to the world, per side: positions, and all three arrays as
  // given (for the tests and the benchmark).
  joints: {},
  jointArrays: {},
  // Whether the page steps only what is granted (`granted`), and the steps granted and not
  // yet run.
  granting: GRANTING,
  granted: 0,
};
window.app = app;
// Which objects' meshes are shown, by id (for the tests).
app.shownObjects = () => drawn.objects.map((mesh) => mesh.visible);
// A capture's ghost as drawn, or null (for the tests).
app.shownGhost = () => drawn.ghost && { visible: drawn.ghost.visible,
  opacity: drawn.ghost.material.opacity, inScene: drawn.ghost.parent === root,
  triangles: drawn.ghost.geometry.attributes.position.count / 3,
  position: drawn.ghost.position.toArray() };
// With `granted`: `n` more steps, run at the next frame with the hands as posed then.
app.grant = (n) => {
  if (!GRANTING) throw new Error('app.grant needs the page opened with ?granted');
  if (!Number.isInteger(n) || n < 0) throw new Error(`app.grant: ${n} is not a step count`);
  app.granted += n;
};

try {
  await init();
} catch (e) {
  showError(`The physics could not be loaded (${e.message ?? e}): build the page with `
    + 'scripts/web.sh and serve it over http, e.g. scripts/web.sh --serve');
  throw e;
}
// The module itself, for the benchmark (web/bench/bench.mjs).
app.wasm = wasm;
const POSE = wasm.poseStride();
const STATE = wasm.stateStride();
const CONTACT = wasm.contactStride();

// The view.
const canvas = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, alpha: true,
  preserveDrawingBuffer: true });
renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
renderer.xr.enabled = true;
renderer.xr.setReferenceSpaceType('local-floor');
const scene = new THREE.Scene();
const background = new THREE.Color(0x2a2f38);
scene.background = background;
const camera = new THREE.PerspectiveCamera(45, 1, 0.01, 50);
const controls = new OrbitControls(camera, canvas);
controls.mouseButtons = { LEFT: THREE.MOUSE.ROTATE, MIDDLE: THREE.MOUSE.DOLLY, RIGHT: null };
scene.add(new THREE.HemisphereLight(0xffffff, 0x444450, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 1.8);
sun.position.set(0.5, 1.5, 0.8);
scene.add(sun);
// The physics' frame: at the origin on the page, at a table's height in an immersive session.
const root = new THREE.Group();
scene.add(root);
const forces = new Arrows(root, 0xff2020);
const motions = new Arrows(root, 0xffdd00);

function resize() {
  const width = window.innerWidth;
  const height = window.innerHeight;
  renderer.setSize(width, height, false);
  camera.aspect = width / Math.max(height, 1);
  camera.updateProjectionMatrix();
}
window.addEventListener('resize', resize);
resize();

// What is drawn of the world: its objects, its statics, its hands.
let drawn = { objects: [], statics: null, ghost: null, hands: new Map(), previous: new Map() };
let mouse = null;

function objectMaterial(name) {
  const color = MATERIAL_COLORS[name] ?? MATERIAL_COLORS.wood;
  return new THREE.MeshStandardMaterial({ color, roughness: 0.6 });
}

function geometry(triangles) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(triangles, 3));
  g.computeVertexNormals();
  return g;
}

function clearDrawn() {
  for (const mesh of drawn.objects) root.remove(mesh);
  if (drawn.statics) root.remove(drawn.statics);
  if (drawn.ghost) root.remove(drawn.ghost);
  for (const hand of drawn.hands.values()) root.remove(hand.group);
  drawn = { objects: [], statics: null, ghost: null, hands: new Map(), previous: new Map() };
}

// Meshes for the objects not drawn yet: all at first, then those a run adds (a recording's
// object at each closing). One removed before it was drawn gets an empty placeholder, so that
// meshes stay indexed by id.
function drawObjects(world) {
  const count = world.objectCount();
  if (drawn.objects.length === count) return;
  const names = world.objectNames();
  const states = world.objectStates();
  for (let id = drawn.objects.length; id < count; id++) {
    if (Number.isNaN(states[STATE * id])) {
      drawn.objects.push(new THREE.Group());
      continue;
    }
    const mesh = new THREE.Mesh(geometry(world.objectMesh(id)), objectMaterial(materialOf(names[id])));
    mesh.name = names[id];
    root.add(mesh);
    drawn.objects.push(mesh);
  }
}

function drawWorld(world) {
  clearDrawn();
  drawObjects(world);
  const statics = world.staticMesh();
  if (statics.length) {
    drawn.statics = new THREE.Mesh(geometry(statics),
      new THREE.MeshStandardMaterial({ color: 0x5d636e, roughness: 0.95, transparent: true,
        opacity: 1 }));
    // Over the room (AR) the desk's ground is left undrawn; it stays in the physics.
    drawn.statics.visible = !(app.xr && app.xr.mode === 'immersive-ar');
    root.add(drawn.statics);
  }
  // A capture's captured object: its own mesh, at the captured pose of the world's time.
  const ghost = world.ghostMesh();
  if (ghost.length) {
    drawn.ghost = new THREE.Mesh(geometry(ghost), new THREE.MeshStandardMaterial({
      color: GHOST_COLOR, roughness: 0.5, transparent: true, opacity: GHOST_OPACITY,
      depthWrite: false }));
    drawn.ghost.name = 'ghost';
    root.add(drawn.ghost);
  }
}

// The runs the page offers: the demo, every shipped scenario, the bundled recording, the desk.
const MODES = [['desk', 'Desk: your hand (mouse and keys, or WebXR)'],
  ['demo', 'Demo: grasp, lift, carry, turn, open'],
  ['recording', 'Recording: grab.json.lz, a box at each closing'],
  ['capture', 'Capture: TACO, the ghost in blue'],
  ...wasm.shippedScenarios().map((name) => [name, `Scenario: ${name}`])];
for (const [value, label] of MODES) {
  const option = document.createElement('option');
  option.value = value;
  option.textContent = label;
  modeSelect.append(option);
}

async function makeWorld(mode, file) {
  if (file) return worldOfFile(file);
  if (mode === 'demo') return wasm.World.demo();
  if (mode === 'desk') return wasm.World.desk();
  if (mode === 'recording') {
    const bytes = await fetchData('grab.json.lz');
    return wasm.World.recording('grab.json.lz', bytes, wasm.closingObject());
  }
  if (mode === 'capture') {
    const files = [`${CAPTURE}.json`, `${CAPTURE}.obj`];
    const [json, mesh] = await Promise.all(files.map(fetchData));
    return wasm.World.capture(`${CAPTURE}.json`, new TextDecoder().decode(json), mesh);
  }
  return wasm.World.scenario(mode);
}

// A bundled file's bytes, from data/.
async function fetchData(name) {
  const response = await fetch(`data/${name}`);
  if (!response.ok) throw new Error(`data/${name}: ${response.status} ${response.statusText}`);
  return new Uint8Array(await response.arrayBuffer());
}

// A file of the user's: a recording, a scenario or scene, or a mesh put on the desk.
async function worldOfFile(file) {
  const name = file.name;
  const bytes = new Uint8Array(await file.arrayBuffer());
  if (/\.(json\.lz|jsonl)$/.test(name)) return wasm.World.recording(name, bytes, wasm.closingObject());
  if (/\.(obj|stl|gltf|glb)$/i.test(name)) {
    const world = wasm.World.desk();
    try {
      world.addMesh(name, name, bytes, 1.0, undefined, 0.1, new Float32Array([0, 0.15, 0.1]),
        new Float32Array(), 'wood');
    } catch (e) {
      world.free();
      throw e;
    }
    return world;
  }
  const text = new TextDecoder().decode(bytes);
  let json;
  try {
    json = JSON.parse(text);
  } catch {
    // A Leap recording that is not JSON text, or a broken file: the library says which.
    return wasm.World.recording(name, bytes, wasm.closingObject());
  }
  if (json && json.hands && json.checks) return wasm.World.scenarioText(name, text);
  if (json && (json.objects || json.ground || json.statics)) return wasm.World.scene(name, text);
  return wasm.World.recording(name, bytes, wasm.closingObject());
}

// Colours by the material an object is made of, where its name says it (the desk's do).
function materialOf(name) {
  return { ball: 'rubber', can: 'aluminium' }[name] ?? 'wood';
}

function placeCamera(mode) {
  if (mode === 'recording') {
    camera.position.set(0.3, 0.36, 0.45);
    controls.target.set(0.04, 0.14, 0);
  } else if (mode === 'capture') {
    // The captured table top is at about 0.55 m; the object rises 0.2 m above it.
    camera.position.set(0.5, 0.95, 0.68);
    controls.target.set(0, 0.64, 0.08);
  } else if (mode === 'desk') {
    camera.position.set(0.05, 0.38, -0.62);
    controls.target.set(0, 0.04, 0.02);
  } else {
    camera.position.set(0.42, 0.3, 0.5);
    controls.target.set(0, 0.08, 0);
  }
  controls.update();
}

/** Loads a run; on an error the page says so and keeps the run it had. */
async function load(mode, file = null) {
  let world;
  try {
    world = await makeWorld(mode, file);
  } catch (e) {
    showError(e);
    return false;
  }
  if (app.world) app.world.free();
  app.world = world;
  app.mode = file ? file.name : mode;
  app.source = { mode, file };
  app.done = false;
  setPaused(false);
  app.trace = [];
  app.accumulated = 0;
  if (mouse) mouse.dispose();
  mouse = null;
  if (!app.xr && (mode === 'desk' || (file && !world.duration))) {
    mouse = new MouseHand(world, world.addHand('right'), camera, canvas);
  }
  if (app.xr) app.xr.attach(world);
  drawWorld(world);
  if (!app.xr) placeCamera(mode);
  reportBox.textContent = '';
  // The capture's data is TACO's (CC BY 4.0): credited while it plays.
  credit.hidden = !(mode === 'capture' && !file);
  document.title = `coulomb-hands: ${app.mode}`;
  return true;
}
app.load = load;
app.mouseHand = () => mouse;

// One frame: the hands posed, the steps that fit its time, then the drawing.
let last = null;
function frame(time, xrFrame) {
  app.frames++;
  const world = app.world;
  const elapsed = last === null ? 0 : Math.min(time - last, 100);
  last = time;
  if (!world) return;
  try {
    // Granted, the hands are posed only at the frames that step, so a run depends on the
    // poses a test set before its grants, not on how many frames the browser drew between.
    const posing = !GRANTING || app.granted > 0;
    if (app.xr && xrFrame) {
      if (posing) app.xr.update(xrFrame, world);
    } else if (mouse) mouse.update(elapsed / 1000);
    let steps = 0;
    if (!app.paused && !app.done) {
      if (GRANTING) {
        steps = app.granted;
        app.granted = 0;
      } else if (params.has('fast')) {
        steps = FAST_STEPS_PER_FRAME;
      } else {
        app.accumulated += elapsed;
        const dtMs = world.dt * 1000;
        steps = Math.min(Math.floor(app.accumulated / dtMs), MAX_STEPS_PER_FRAME);
        app.accumulated = Math.min(app.accumulated - steps * dtMs, dtMs);
      }
      stepWorld(world, steps);
    }
  } catch (e) {
    showError(e);
    setPaused(true);
  }
  draw(world, elapsed / 1000);
  renderer.render(scene, camera);
}

// Steps in chunks that end on the trace's rows, recording a row there.
function stepWorld(world, steps) {
  const tracing = params.has('trace');
  let left = steps;
  while (left > 0) {
    const chunk = tracing ? Math.min(left, TRACE_EVERY - (world.steps % TRACE_EVERY)) : left;
    const run = world.step(chunk);
    left -= chunk;
    if (tracing && (world.steps % TRACE_EVERY === 0 || world.finished)) app.trace.push(traceRow(world));
    if (world.finished || run < chunk) break;
  }
  if (world.finished && !app.done) finish(world);
}

function finish(world) {
  app.done = true;
  const report = JSON.parse(world.report());
  const verdicts = JSON.parse(world.verdicts());
  app.report = report;
  app.verdicts = verdicts;
  const lines = [];
  if (report) {
    lines.push(`${report.name}: ${report.passed ? 'PASSED' : 'FAILED'}`);
    for (const c of report.checks) {
      lines.push(`  ${c.passed ? '✓' : '✗'} ${c.name}: ${Number(c.value).toPrecision(4)}`);
    }
  }
  if (verdicts) {
    lines.push(`${verdicts.length} closings:`, ...world.verdictLines());
  }
  reportBox.textContent = lines.join('\n');
  document.title = `coulomb-hands: ${app.mode} done`;
}

function draw(world, seconds) {
  drawObjects(world);
  const states = world.objectStates();
  for (let id = 0; id < drawn.objects.length; id++) {
    const s = states.subarray(STATE * id, STATE * (id + 1));
    // A removed object's numbers are NaN: its mesh is hidden.
    drawn.objects[id].visible = !Number.isNaN(s[0]);
    if (!drawn.objects[id].visible) continue;
    drawn.objects[id].position.set(s[0], s[1], s[2]);
    drawn.objects[id].quaternion.set(s[3], s[4], s[5], s[6]);
  }
  if (drawn.ghost) {
    const g = world.ghostPose();
    drawn.ghost.position.set(g[0], g[1], g[2]);
    drawn.ghost.quaternion.set(g[3], g[4], g[5], g[6]);
  }
  const contacts = world.contacts();
  // Each hand is drawn opaque exactly while it has contacts, as the viewer draws it (§3.6).
  const touching = new Set();
  forces.begin();
  for (let k = 0; k < contacts.length; k += CONTACT) {
    const c = contacts.subarray(k, k + CONTACT);
    touching.add(c[1]);
    forces.add([c[4], c[5], c[6]], [c[13], c[14], c[15]], FORCE_SCALE);
  }
  forces.end();
  motions.begin();
  for (let hand = 0; hand < world.handCount(); hand++) {
    let view = drawn.hands.get(hand);
    if (!view) {
      view = new HandView(root);
      drawn.hands.set(hand, view);
    }
    const pose = world.handPose(hand);
    if (pose.length !== POSE) {
      view.hide();
      drawn.previous.delete(hand);
      continue;
    }
    view.update(pose);
    view.setOpaque(touching.has(hand));
    const points = HandView.points(pose);
    const before = drawn.previous.get(hand);
    if (before && seconds > 0) {
      for (let p = 0; p < points.length; p++) {
        const v = points[p].map((x, i) => (x - before[p][i]) / seconds);
        motions.add(points[p], v, MOTION_SCALE);
      }
    }
    drawn.previous.set(hand, points);
  }
  motions.end();
  const duration = world.duration;
  status.textContent = `${app.mode}${app.xr ? ` (${app.xr.mode})` : ''}\n`
    + `t = ${world.time.toFixed(3)} s${duration ? ` of ${duration.toFixed(2)}` : ''}, `
    + `${world.steps} steps of ${(world.dt * 1000).toFixed(1)} ms\n`
    + `contacts ${contacts.length / CONTACT}, hands touching ${touching.size}`
    + (app.paused ? '\npaused' : '');
}

// The controls.
modeSelect.addEventListener('change', () => {
  clearError();
  load(modeSelect.value);
});
document.getElementById('restart').addEventListener('click', () => {
  clearError();
  load(app.source.mode, app.source.file);
});
document.getElementById('pause').addEventListener('click', () => setPaused(!app.paused));
document.getElementById('file').addEventListener('change', (event) => {
  const file = event.target.files[0];
  clearError();
  if (file) load('desk', file);
});

// Immersive sessions, with hands from WebXR hand tracking. Unavailable or refused: the page
// says so and stays on the desk.
async function enter(mode) {
  try {
    const session = await startXr(renderer, mode);
    // The desk afresh, with both hands from the session (and none from the mouse).
    app.xr = new XrHands(session, mode, renderer, XR_DESK);
    modeSelect.value = 'desk';
    await load('desk');
    root.position.copy(XR_DESK);
    // Over the room (AR): no backdrop.
    if (mode === 'immersive-ar') scene.background = null;
    session.addEventListener('end', () => {
      app.xr = null;
      root.position.set(0, 0, 0);
      scene.background = background;
      load('desk');
    });
  } catch (e) {
    showError(`${mode === 'immersive-ar' ? 'Enter AR' : 'Enter VR'}: ${e.message ?? e}; staying on the desk`);
  }
}
app.enter = enter;
for (const [id, mode] of [['enter-vr', 'immersive-vr'], ['enter-ar', 'immersive-ar']]) {
  const button = document.getElementById(id);
  button.addEventListener('click', () => enter(mode));
  xrSupported(mode).then((ok) => {
    button.disabled = !ok;
    if (!ok) button.title = `${mode} with hand tracking is not available in this browser`;
  });
}

const first = params.get('run') ?? 'desk';
modeSelect.value = first;
if (!(await load(first))) await load('desk');
renderer.setAnimationLoop(frame);
app.ready = true;
