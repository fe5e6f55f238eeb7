// The simulation of the Stepdance page, in a Web Worker: the WebAssembly simulator
// (stepdance_web.js, stepdance_sim.js) runs one example's scenario, paced to the wall clock at the
// speed the view asks for, and speaks the view protocol (docs/simulator.md) to the page.
//
// From the page: {kind: "start", example, files, path, text} loads the example's files and boards
// and opens the scenario `text` as the file `path`; {kind: "view", text} is a view-protocol
// message from the view. To the page: {kind: "view", text} (hello, update, drawing, error
// messages of the view protocol), {kind: "failed", text} (the scenario reader's or the
// simulation's errors, `file:line: message` lines), {kind: "result", result} when the run ends
// (the document `stepdance sim --result-json` writes).
"use strict";

importScripts("stepdance_web.js", "stepdance_sim.js");

/// How long one slice of simulation may hold the worker at --speed max (wall ms): messages from
/// the page are answered between slices.
const MAX_SPEED_SLICE_MS = 15;
/// Simulated seconds run at once at max speed, between looks at the wall clock.
const MAX_SPEED_STEP_S = 0.01;
/// At a set speed, the run never catches up more than this much wall time at once (a tab that
/// was in the background resumes from where it is instead of racing).
const LONGEST_CATCH_UP_S = 0.25;

let sim = null;
let anchor = null; // {wall_s, sim_s, speed}: where wall clock and simulated time were tied
let finished = false;

const wallSeconds = () => performance.now() / 1000;

// The next tick: after `ms`, or at once (a MessageChannel message: a task, so the page's messages
// are answered between slices, without setTimeout's clamp of 4 ms between nested calls).
const immediate = new MessageChannel();
immediate.port1.onmessage = () => tick();
function tickAfter(ms) {
  if (ms > 0) setTimeout(tick, ms);
  else immediate.port2.postMessage(null);
}
const post = (text) => postMessage({ kind: "view", text });

async function fetchBytes(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: ${response.status} ${response.statusText}`);
  return new Uint8Array(await response.arrayBuffer());
}

/// The files in other examples' folders that scenario `text` names, as quoted relative paths
/// (`sketch = "../ChainedKnobsBasic/ChainedKnobsBasic.ino"`): [{folder, file}].
function otherExamplesFiles(text) {
  const named = new Map();
  for (const match of text.matchAll(/"\.\.\/([A-Za-z0-9_][\w.-]*)\/([A-Za-z0-9_][\w.-]*)"/g)) {
    named.set(`${match[1]}/${match[2]}`, { folder: match[1], file: match[2] });
  }
  return [...named.values()];
}

/// Writes the example's own files and every file its scenario names in other examples' folders
/// (the site carries every example's folder). A named file the site lacks is left out: the
/// scenario reader then says which one is missing, as natively.
async function writeFiles(request) {
  const folder = request.path.substring(0, request.path.lastIndexOf("/"));
  for (const file of request.files) {
    sim.writeFile(`${folder}/${file}`, await fetchBytes(`examples/${request.example}/${file}`));
  }
  const examples = folder.substring(0, folder.lastIndexOf("/"));
  for (const other of otherExamplesFiles(request.text)) {
    const response = await fetch(`examples/${other.folder}/${other.file}`);
    if (response.ok) sim.writeFile(`${examples}/${other.folder}/${other.file}`, new Uint8Array(await response.arrayBuffer()));
  }
}

async function start(request) {
  sim = await StepdanceSim.create(createStepdanceModule, { print: () => {}, printErr: () => {} });
  await writeFiles(request);
  let sketches;
  try {
    sketches = sim.sketches(request.path, request.text);
  } catch (error) {
    postMessage({ kind: "failed", text: error.message });
    return;
  }
  for (const name of sketches) sim.addBoard(name, await fetchBytes(`boards/${name}.wasm`));
  const errors = sim.open(request.path, request.text);
  if (errors) {
    postMessage({ kind: "failed", text: errors });
    return;
  }
  post(sim.hello());
  tickAfter(0);
}

// Runs the simulation as far as the wall clock and the asked speed say (0: as fast as it goes).
function advance(state) {
  const now = wallSeconds();
  if (!anchor || anchor.speed !== state.speed) anchor = { wall_s: now, sim_s: state.now_s, speed: state.speed };
  if (state.speed > 0) {
    const due_s = anchor.sim_s + (now - anchor.wall_s) * state.speed;
    const reachable_s = state.now_s + LONGEST_CATCH_UP_S * state.speed;
    if (due_s > reachable_s) anchor = { wall_s: now, sim_s: reachable_s, speed: state.speed };
    sim.runUntil(Math.min(due_s, reachable_s));
    return;
  }
  const until = now + MAX_SPEED_SLICE_MS / 1000;
  let reached = state.now_s;
  while (wallSeconds() < until && reached < state.duration_s) reached = sim.runUntil(reached + MAX_SPEED_STEP_S);
}

function tick() {
  if (!sim || finished) return;
  try {
    paceOnce();
  } catch (error) {
    finished = true;
    postMessage({ kind: "crashed", text: String((error && error.stack) || error) });
  }
}

// One step of the run: as far as the pace allows, an update if one is due, the result at the end.
function paceOnce() {
  const state = sim.state();
  if (state.paused) {
    anchor = null; // paced from where it resumes
  } else if (!state.done) {
    advance(state);
  }
  const update = sim.update(wallSeconds());
  if (update) post(update);
  if (sim.state().done) {
    finished = true;
    post(sim.updateNow());
    postMessage({ kind: "result", result: sim.finish() });
    return;
  }
  tickAfter(state.speed > 0 || state.paused ? 4 : 0);
}

onmessage = (event) => {
  const message = event.data;
  if (message.kind === "start") {
    start(message).catch((error) => postMessage({ kind: "failed", text: String(error.message || error) }));
  } else if (message.kind === "view" && sim) {
    for (const reply of sim.receive(message.text)) post(reply);
  }
};
