// The Stepdance page: pick an example, read its sketch, edit its scenario, run it and watch it in
// the live view (view/, the page `stepdance sim --live --view` serves, unchanged: this page hands
// it a transport), then read the run's summary. A run goes to one of two runners, which speak the
// same view protocol: the WebAssembly simulator in a Web Worker (worker.js), or, when a local
// `stepdance serve` answers, that server, which compiles an edited sketch with the host's
// toolchain and runs it (docs/web.md, "Editing a sketch").
"use strict";

/// Where the page looks for `stepdance serve` (its default port), unless ?serve=PORT says otherwise.
const DEFAULT_SERVE_PORT = 8001;
/// The edit protocol's version this page speaks (2: the run request is `sketch_run`, apart from
/// the view protocol's `run` control, which goes to the run as every other view message).
const EDIT_PROTOCOL_VERSION = 2;

const site = (window.stepdanceSite = { examples: [], scenarios: {}, result: null, problems: [], runner: null,
                                       server: null });

const $ = (id) => document.getElementById(id);
let viewInbox = [];      // view messages that came before the view attached
let viewReceiver = null; // the view's onMessage, once it attached

async function fetchText(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: ${response.status} ${response.statusText}`);
  return response.text();
}

function status(text) { $("status").textContent = text; }

// ---- the example and its sources --------------------------------------------------------------

function currentExample() { return site.examples.find((example) => example.name === $("example").value); }
function exampleFolder(example) { return `/examples/${example.name}/`; }
function sketchFile(example) {
  return example.files.find((file) => file === `${example.name}.ino`) || example.files.find((file) => file.endsWith(".ino"));
}

async function showExample() {
  const example = currentExample();
  location.hash = example.name;
  $("sketch-name").textContent = sketchFile(example);
  site.sketchText = await fetchText(`examples/${example.name}/${sketchFile(example)}`);
  showSketch();
  // The example's scenarios: its TOML files that declare a board (scenario.toml first; live.toml
  // has no timeline, for the knobs).
  const picker = $("scenario-file");
  picker.textContent = "";
  site.scenarios = {};
  for (const file of example.files.filter((name) => name.endsWith(".toml"))) {
    const text = await fetchText(`examples/${example.name}/${file}`);
    if (!/^\[\[board\]\]/m.test(text)) continue;
    site.scenarios[file] = text;
    picker.add(new Option(file, file), file === "scenario.toml" ? 0 : undefined);
  }
  picker.value = "scenario.toml";
  showScenario();
  site.shown = example.name;
}

// The sketch: highlighted and read-only, or, with a server to compile it, in an editor.
function showSketch() {
  const editable = !!site.server;
  $("sketch").hidden = editable;
  $("sketch-editor").hidden = !editable;
  $("sketch-mode").textContent = editable ? "(edit: stepdance serve compiles it)" : "(read-only)";
  if (editable) $("sketch-editor").value = site.sketchText;
  else highlightCpp($("sketch"), site.sketchText);
}

function showScenario() {
  $("scenario").value = site.scenarios[$("scenario-file").value];
  showProblems("");
  $("result").hidden = true;
  status("ready: Run starts the scenario");
}

// The scenario editor's line numbers, lines with a problem marked.
function numberLines(badLines = new Set()) {
  const gutter = $("scenario-lines");
  gutter.textContent = "";
  const count = $("scenario").value.split("\n").length;
  for (let line = 1; line <= count; ++line) {
    const number = document.createElement("span");
    number.textContent = line + "\n";
    if (badLines.has(line)) number.className = "bad";
    gutter.appendChild(number);
  }
  $("scenario").style.height = `${count * 1.4 + 1.2}em`;
}

// The reader's, the compiler's or the simulation's errors, each `file:line[:column]: message` one
// shown at its line (the run's folder left out of the file's name); text without such lines as it is.
function showProblems(text) {
  const list = $("problems");
  list.textContent = "";
  site.problems = [];
  const folder = exampleFolder(currentExample());
  const lines = text.split("\n").filter(Boolean).map((line) => (line.startsWith(folder) ? line.slice(folder.length) : line));
  const located = lines.map((line) => line.match(/^([\w.-]+):(\d+)(?::\d+)?: ?(.*)$/));
  const anyLocated = located.some(Boolean);
  lines.forEach((line, index) => {
    const match = located[index];
    if (anyLocated && !match) return; // the compiler's excerpts and carets
    const problem = match ? { file: match[1], line: Number(match[2]), message: match[3] } : { file: null, line: null, message: line };
    site.problems.push(problem);
    const item = document.createElement("li");
    item.textContent = problem.line ? `${problem.file} line ${problem.line}: ${problem.message}` : problem.message;
    if (problem.line) item.onclick = () => selectLine(problem.file, problem.line);
    list.appendChild(item);
  });
  const scenario = $("scenario-file").value;
  numberLines(new Set(site.problems.filter((problem) => problem.file === scenario).map((problem) => problem.line)));
}

function selectLine(file, line) {
  const box = file === $("scenario-file").value ? $("scenario") : site.server ? $("sketch-editor") : null;
  if (!box) return;
  const lines = box.value.split("\n");
  const start = lines.slice(0, line - 1).reduce((sum, text) => sum + text.length + 1, 0);
  box.focus();
  box.setSelectionRange(start, start + (lines[line - 1] || "").length);
}

// ---- the runners -----------------------------------------------------------------------------

// The view (in the frame) asks its parent for a transport: the current runner.
window.stepdanceTransport = (onMessage, onState) => {
  viewReceiver = onMessage;
  onState(site.runner ? "open" : "closed");
  for (const text of viewInbox) onMessage(text);
  viewInbox = [];
  return { send: (text) => site.runner && site.runner.send(text) };
};

function toView(text) {
  if (viewReceiver) viewReceiver(text);
  else viewInbox.push(text);
}

// What both runners report besides the view's messages.
const runEvents = {
  failed(text) { showProblems(text); status("the run did not start: see the problems under the scenario"); },
  result(result) { showResult(result); },
  crashed(text) { status(`the simulator failed: ${text}`); },
  // The sketch server's report of a run that ended early (a crash, exit(), a hang, a limit).
  ended(text) { showProblems(text); status("the run ended early: see the problems under the scenario"); },
};

/// The WebAssembly simulator in a Web Worker: {send(text), stop()}.
function workerRunner(example, scenarioFile, scenarioText) {
  const worker = new Worker("worker.js");
  worker.onmessage = (event) => {
    const message = event.data;
    if (message.kind === "view") toView(message.text);
    else if (runEvents[message.kind]) runEvents[message.kind](message.kind === "result" ? message.result : message.text);
  };
  worker.onerror = (event) => runEvents.crashed(event.message);
  worker.postMessage({ kind: "start", example: example.name, files: example.files,
                       path: exampleFolder(example) + scenarioFile, text: scenarioText });
  return { send: (text) => worker.postMessage({ kind: "view", text }), stop: () => worker.terminate() };
}

/// The run on the local `stepdance serve`, over its socket: {send(text), stop()}.
async function serverRunner(example, scenarioFile, scenarioText) {
  const files = {};
  for (const file of example.files) files[file] = await fetchText(`examples/${example.name}/${file}`);
  files[sketchFile(example)] = $("sketch-editor").value;
  files[scenarioFile] = scenarioText;
  const socket = site.server;
  socket.onmessage = (event) => {
    const message = JSON.parse(event.data);
    if (message.type === "building") status(`compiling ${sketchFile(example)} on stepdance serve…`);
    else if (message.type === "started") status(`running ${example.name} on stepdance serve`);
    else if (message.type === "failed") runEvents.failed(message.text);
    else if (message.type === "ended") runEvents.ended(message.text);
    else if (message.type === "result") runEvents.result(message.result);
    else toView(event.data); // the view protocol
  };
  socket.send(JSON.stringify({ type: "sketch_run", example: example.name, files, scenario: scenarioFile }));
  return { send: (text) => socket.send(text), stop: () => {} };
}

async function run() {
  if (site.runner) site.runner.stop();
  site.runner = null;
  viewInbox = [];
  viewReceiver = null;
  site.result = null;
  showProblems("");
  $("result").hidden = true;
  const example = currentExample();
  const scenarioFile = $("scenario-file").value;
  const text = $("scenario").value;
  site.runner = site.server ? await serverRunner(example, scenarioFile, text) : workerRunner(example, scenarioFile, text);
  $("view").src = `view/index.html?run=${Date.now()}`;
  $("reset").disabled = false;
  status(`running ${example.name}`);
}

// ---- a local stepdance serve -----------------------------------------------------------------

// Looks for `stepdance serve` on 127.0.0.1 (its edit protocol's serve_hello); says how to start
// one when nobody answers.
function findServer() {
  const port = Number(new URLSearchParams(location.search).get("serve")) || DEFAULT_SERVE_PORT;
  const origin = location.origin;
  const howTo = `To edit the sketch, run \`stepdance serve --allow-origin ${origin}\` on this computer and reload (docs/web.md).`;
  let socket;
  try {
    socket = new WebSocket(`ws://127.0.0.1:${port}/ws`);
  } catch (error) {
    $("serve-state").textContent = howTo;
    return;
  }
  socket.onmessage = (event) => {
    const message = JSON.parse(event.data);
    if (message.type !== "serve_hello" || message.version !== EDIT_PROTOCOL_VERSION) return;
    site.server = socket;
    $("serve-state").textContent = `Sketch edits compile on stepdance serve at 127.0.0.1:${port}.`;
    if (site.sketchText !== undefined) showSketch();
  };
  socket.onclose = () => {
    if (site.server === socket) {
      site.server = null;
      showSketch();
    }
    $("serve-state").textContent = howTo;
  };
}

// ---- the summary -----------------------------------------------------------------------------

function row(table, cells, className) {
  const tr = table.insertRow();
  for (const cell of cells) {
    const td = tr.insertCell();
    td.textContent = cell;
    if (className) td.className = className;
  }
}

function showResult(result) {
  site.result = result;
  const summary = result.summary;
  const table = $("summary");
  table.textContent = "";
  row(table, ["simulated time", `${summary.simulated_time_s} s`]);
  for (const [motor, counts] of Object.entries(summary.motors || {})) row(table, [`motor ${motor}`, `${counts.steps} steps`]);
  if (summary.machine) {
    const machine = summary.machine;
    if (machine.pen_mm) row(table, ["pen", `${machine.pen_mm.map((mm) => mm.toFixed(2)).join(", ")} mm, ${machine.pen_down ? "down" : "up"}`]);
    if (machine.strokes !== undefined) row(table, ["strokes", String(machine.strokes)]);
  }
  if (result.stopped) row(table, ["stopped", result.stopped], "failed");
  const expectations = $("expectations");
  expectations.textContent = "";
  const folder = exampleFolder(currentExample());
  for (const expectation of result.expectations) {
    const verdict = !expectation.checked ? "not run" : expectation.met ? "ok" : "FAILED";
    const message = expectation.message.replace(/^.*?([\w.-]+\.toml):(\d+): /, "$1 line $2: ").replace(folder, "");
    row(expectations, [verdict, message], expectation.checked && expectation.met ? "ok" : "failed");
  }
  $("result").hidden = false;
  const failed = result.expectations.filter((expectation) => !(expectation.checked && expectation.met)).length;
  status(failed ? `ended: ${failed} expectation(s) not met` : "ended: every expectation met");
}

// ---- start -----------------------------------------------------------------------------------

async function startPage() {
  findServer();
  const listing = JSON.parse(await fetchText("examples.json"));
  site.examples = listing.examples;
  const picker = $("example");
  for (const example of site.examples) picker.add(new Option(example.name, example.name));
  const wanted = decodeURIComponent(location.hash.slice(1));
  if (site.examples.some((example) => example.name === wanted)) picker.value = wanted;
  picker.onchange = showExample;
  $("scenario-file").onchange = showScenario;
  $("scenario").oninput = () => numberLines();
  $("run").onclick = run;
  $("reset").onclick = run;
  await showExample();
}

startPage().catch((error) => status(`the page could not start: ${error.message}`));
