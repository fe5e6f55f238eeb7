// The simulation of the Stepdance page, in a Web Worker: the WebAssembly simulator
// (stepdance_web.js, stepdance_sim.js) runs one example's scenario, paced to the wall clock at the
// speed the view asks for, and speaks the view protocol (docs/simulator.md) to the page.
//
// The worker lives as long as the page: the module is loaded once and every run after the first
// reuses it (and the boards it fetched), so a second Run reaches its first frame without
// fetching or compiling anything.
//
// From the page: {kind: "start", run, example, files, path, text} ends the run before, loads the
// example's files and boards and opens the scenario `text` as the file `path`; {kind: "view",
// text} is a view-protocol message from the view; {kind: "stop"} ends the run. To the page, each
// message tagged with its `run`: {kind: "view", text} (hello, update, drawing, error messages of
// the view protocol), {kind: "failed", text} (the scenario reader's or the simulation's errors,
// `file:line: message` lines), {kind: "result", result} when the run ends (the document
// `stepdance sim --result-json` writes), {kind: "crashed", text} when the module failed.
"use strict";

importScripts("stepdance_web.js", "stepdance_sim.js", "named_files.js");

/// How long one slice of simulation may hold the worker at --speed max (wall ms): messages from
/// the page are answered between slices.
const MAX_SPEED_SLICE_MS = 15;
/// Simulated seconds run at once at max speed, between looks at the wall clock.
const MAX_SPEED_STEP_S = 0.01;
/// At a set speed, the run never catches up more than this much wall time at once (a tab that
/// was in the background resumes from where it is instead of racing).
const LONGEST_CATCH_UP_S = 0.25;
/// The shortest wall time between two updates handed to the view (s). The view draws at most
/// about 30 times a second (web/view/app.js, SHORTEST_FRAME_MS), so the protocol's 60 updates a
/// second would be made, copied to the page, parsed and merged twice for each drawing seen; on a
/// machine of two cores that work is taken from the simulation (docs/web.md, "Figures").
const SHORTEST_UPDATE_PERIOD_S = 1 / 30;

let sim = null;      // the module, loaded by the first run
let runId = null;    // the page's number of the run going (its messages carry it)
let anchor = null;   // {wall_s, sim_s, speed}: where wall clock and simulated time were tied
let finished = true;
let lastUpdateWallS = -Infinity; // when the view was last handed an update
const addedBoards = new Set(); // sketch folder names whose boards the module has

const wallSeconds = () => performance.now() / 1000;

// The next tick: after `ms`, or at once (a MessageChannel message: a task, so the page's messages
// are answered between slices, without setTimeout's clamp of 4 ms between nested calls).
const immediate = new MessageChannel();
immediate.port1.onmessage = (event) => tick(event.data);
function tickAfter(ms) {
  const run = runId;
  if (ms > 0) setTimeout(() => tick(run), ms);
  else immediate.port2.postMessage(run);
}
const tell = (message) => postMessage({ ...message, run: runId });
const post = (text) => tell({ kind: "view", text });

const fetched = new Map(); // url → bytes: the site's files do not change while the page is open

async function fetchBytes(url) {
  if (fetched.has(url)) return fetched.get(url);
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: ${response.status} ${response.statusText}`);
  const bytes = new Uint8Array(await response.arrayBuffer());
  fetched.set(url, bytes);
  return bytes;
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
    const bytes = await fetchBytes(`examples/${other.folder}/${other.file}`).catch(() => null);
    if (bytes) sim.writeFile(`${examples}/${other.folder}/${other.file}`, bytes);
  }
}

async function start(request) {
  finished = true; // the run before (if any) ticks no more
  anchor = null;
  lastUpdateWallS = -Infinity;
  runId = request.run;
  if (!sim) sim = await StepdanceSim.create(createStepdanceModule, { print: () => {}, printErr: () => {} });
  sim.close();
  await writeFiles(request);
  let sketches;
  try {
    sketches = sim.sketches(request.path, request.text);
  } catch (error) {
    tell({ kind: "failed", text: error.message });
    return;
  }
  for (const name of sketches.filter((name) => !addedBoards.has(name))) {
    sim.addBoard(name, await fetchBytes(`boards/${name}.wasm`));
    addedBoards.add(name);
  }
  if (runId !== request.run) return; // a newer start came while this one fetched
  const errors = sim.open(request.path, request.text);
  if (errors) {
    tell({ kind: "failed", text: errors });
    return;
  }
  finished = false;
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

function tick(run) {
  if (!sim || finished || run !== runId) return;
  try {
    paceOnce();
  } catch (error) {
    finished = true;
    tell({ kind: "crashed", text: String((error && error.stack) || error) });
    sim = null; // a trapped module is not trusted again: the next run loads a fresh one
    addedBoards.clear();
  }
}

// The view's update, if the protocol has one due and the view's last is SHORTEST_UPDATE_PERIOD_S old.
function postDueUpdate() {
  const now = wallSeconds();
  if (now - lastUpdateWallS < SHORTEST_UPDATE_PERIOD_S) return;
  const update = sim.update(now);
  if (!update) return;
  post(update);
  lastUpdateWallS = now;
}

// One step of the run: as far as the pace allows, an update if one is due, the result at the end.
function paceOnce() {
  const state = sim.state();
  if (state.paused) {
    anchor = null; // paced from where it resumes
  } else if (!state.done) {
    advance(state);
  }
  postDueUpdate();
  if (sim.state().done) {
    finished = true;
    post(sim.updateNow());
    tell({ kind: "result", result: sim.finish() });
    return;
  }
  tickAfter(state.speed > 0 || state.paused ? 4 : 0);
}

onmessage = (event) => {
  const message = event.data;
  if (message.kind === "start") {
    start(message).catch((error) => tell({ kind: "failed", text: String(error.message || error) }));
  } else if (message.kind === "stop") {
    finished = true;
  } else if (message.kind === "view" && sim) {
    for (const reply of sim.receive(message.text)) post(reply);
  }
};
