// The Stepdance page: pick an example, read its sketch, edit its scenario, run it and watch it in
// the live view (view/, the page `stepdance sim --live --view` serves, unchanged: this page hands
// it a transport), then read the run's summary. A run goes to one of two runners, which speak the
// same view protocol: the WebAssembly simulator in a Web Worker (worker.js), or, when a local
// `stepdance serve` answers, that server, which compiles an edited sketch with the host's
// toolchain and runs it (docs/web.md, "Editing a sketch"). Edits are kept per example
// (keep.js); the run's tables are summary.js's.
"use strict";

/// Where the page looks for `stepdance serve` (its default port), unless ?serve=PORT says otherwise.
const DEFAULT_SERVE_PORT = 8001;
/// The edit protocol's version this page speaks (2: the run request is `sketch_run`, apart from
/// the view protocol's `run` control, which goes to the run as every other view message).
const EDIT_PROTOCOL_VERSION = 2;
/// The example a first visit opens (the README's main job).
const FIRST_EXAMPLE = "StepASketch";
/// Set once a server answered: later visits look for it again without being asked.
const SERVER_SEEN_KEY = "stepdance.serve-seen";
const VISITED_KEY = "stepdance.visited";

const site = (window.stepdanceSite = { examples: [], scenarios: {}, original: null, result: null, problems: [],
                                       runner: null, server: null, shown: null, unsaved: false, worker: null });

const $ = (id) => document.getElementById(id);
let viewInbox = [];      // view messages that came before the view attached
let viewReceiver = null; // the view's onMessage, once it attached

async function fetchText(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: ${response.status} ${response.statusText}`);
  return response.text();
}

function status(text) { $("status").textContent = text; }

function remember(key, value) {
  try {
    localStorage.setItem(key, value);
  } catch (error) { /* no storage: nothing remembered */ }
}
function recalled(key) {
  try {
    return localStorage.getItem(key);
  } catch (error) {
    return null;
  }
}

// ---- the example and its sources --------------------------------------------------------------

function currentExample() { return site.examples.find((example) => example.name === $("example").value); }
function exampleFolder(example) { return `/examples/${example.name}/`; }
function sketchFile(example) {
  return example.files.find((file) => file === `${example.name}.ino`) || example.files.find((file) => file.endsWith(".ino"));
}

/// Shows the picked example: its own files, with the edits kept for it (or `shared` ones) on top.
async function showExample(shared = null) {
  const example = currentExample();
  history.replaceState(null, "", `#${encodeURIComponent(example.name)}`);
  $("sketch-name").textContent = sketchFile(example);
  const original = { sketch: await fetchText(`examples/${example.name}/${sketchFile(example)}`), scenarios: {} };
  // The example's scenarios: its TOML files that declare a board (scenario.toml first; live.toml
  // has no timeline, for the knobs).
  for (const file of example.files.filter((name) => name.endsWith(".toml"))) {
    const text = await fetchText(`examples/${example.name}/${file}`);
    if (/^\[\[board\]\]/m.test(text)) original.scenarios[file] = text;
  }
  site.original = original;
  const edits = shared || keep.load(example.name) || { scenarios: {} };
  site.scenarios = { ...original.scenarios };
  for (const [file, text] of Object.entries(edits.scenarios || {})) if (file in site.scenarios) site.scenarios[file] = text;
  site.sketchText = edits.sketch !== undefined ? edits.sketch : original.sketch;
  const picker = $("scenario-file");
  picker.textContent = "";
  for (const file of Object.keys(original.scenarios)) picker.add(new Option(file, file), file === "scenario.toml" ? 0 : undefined);
  picker.value = edits.scenario in original.scenarios ? edits.scenario : "scenario.toml";
  if (shared) keepEdits();
  showSketch();
  showScenario();
  site.shown = example.name;
}

// The sketch: highlighted and read-only, or, with a server to compile it, in an editor.
function showSketch() {
  const editable = !!site.server;
  const edited = site.original && site.sketchText !== site.original.sketch;
  $("sketch").hidden = editable;
  $("sketch-editor").hidden = !editable;
  $("sketch-mode").textContent = editable ? "(edit: stepdance serve compiles it)"
    : edited ? "(read-only: edited, and edits run only on stepdance serve)" : "(read-only)";
  if (editable) $("sketch-editor").value = site.sketchText;
  else highlightCpp($("sketch"), site.sketchText);
  markLines("sketch");
}

function showScenario() {
  $("scenario").value = site.scenarios[$("scenario-file").value];
  showProblems("");
  site.failedExpectations = [];
  $("result").hidden = true;
  status("ready: Run starts the scenario");
  showEdited();
}

// ---- the editors' margins ----------------------------------------------------------------------

const EDITORS = {
  scenario: { gutter: "scenario-lines", file: () => $("scenario-file").value, text: () => $("scenario").value },
  sketch: { gutter: "sketch-lines", file: () => sketchFile(currentExample()), text: () => site.sketchText },
};

/// Numbers editor `which`'s lines in its margin, marking the lines with a problem (class bad),
/// a warning (warn) or a failed expectation (failed).
function markLines(which) {
  const editor = EDITORS[which];
  const file = editor.file();
  const marks = new Map();
  for (const problem of site.problems) if (problem.file === file && problem.line) marks.set(problem.line, problem.kind === "warning" ? "warn" : "bad");
  for (const place of site.failedExpectations || []) if (place.file === file) marks.set(place.line, "failed");
  const gutter = $(editor.gutter);
  gutter.textContent = "";
  const count = editor.text().split("\n").length;
  for (let line = 1; line <= count; ++line) {
    const number = document.createElement("span");
    number.textContent = line + "\n";
    if (marks.has(line)) number.className = marks.get(line);
    gutter.appendChild(number);
  }
  if (which === "scenario") $("scenario").style.height = `${count * 1.4 + 1.2}em`;
  if (which === "sketch") $("sketch-editor").style.height = `${count * 1.4 + 1.2}em`;
}

function markAllLines() {
  markLines("scenario");
  markLines("sketch");
}

/// Selects `line` of `file` in its editor and scrolls it into view.
function selectLine(file, line) {
  const isScenario = file === $("scenario-file").value;
  const box = isScenario ? $("scenario") : site.server ? $("sketch-editor") : null;
  const gutter = $(isScenario ? "scenario-lines" : "sketch-lines");
  const number = gutter.children[line - 1];
  if (number) number.scrollIntoView({ block: "center" });
  if (!box) return;
  const lines = box.value.split("\n");
  const start = lines.slice(0, line - 1).reduce((sum, text) => sum + text.length + 1, 0);
  box.focus({ preventScroll: true });
  box.setSelectionRange(start, start + (lines[line - 1] || "").length);
}

// ---- edits: kept, shared, downloaded -----------------------------------------------------------

/// The current example's edits: the files that differ from its own.
function currentEdits() {
  const edits = { scenarios: {}, scenario: $("scenario-file").value };
  for (const [file, text] of Object.entries(site.scenarios)) if (text !== site.original.scenarios[file]) edits.scenarios[file] = text;
  if (site.sketchText !== site.original.sketch) edits.sketch = site.sketchText;
  return edits;
}

function keepEdits() {
  site.unsaved = !keep.store(currentExample().name, currentEdits());
  showEdited();
}

function showEdited() {
  const edited = site.original && !keep.empty(currentEdits());
  $("revert").disabled = !edited;
  $("edit-state").textContent = site.unsaved ? "edits not kept: this browser refused to store them"
    : edited ? "edited (kept in this browser)" : "";
}

function onScenarioInput() {
  site.scenarios[$("scenario-file").value] = $("scenario").value;
  markLines("scenario");
  keepEdits();
}

function onSketchInput() {
  site.sketchText = $("sketch-editor").value;
  markLines("sketch");
  keepEdits();
}

function revert() {
  if (!confirm(`Drop your edits to ${currentExample().name}?`)) return;
  site.scenarios = { ...site.original.scenarios };
  site.sketchText = site.original.sketch;
  keepEdits();
  showSketch();
  showScenario();
}

async function share() {
  const link = await keep.shareLink(currentExample().name, currentEdits());
  $("share-link").value = link;
  $("share-link").hidden = false;
  $("share-link").select();
  try {
    await navigator.clipboard.writeText(link);
    $("edit-state").textContent = "share link copied";
  } catch (error) {
    $("edit-state").textContent = "share link: copy it from the box";
  }
}

// ---- problems ----------------------------------------------------------------------------------

// The reader's, the compiler's or the simulation's errors, each `file:line[:column]: message` one
// shown at its line (the run's folder left out of the file's name); text without such lines as it
// is. The compiler's warnings and notes are told apart from its errors.
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
    problem.kind = /^(warning|note):/.test(problem.message) ? problem.message.split(":")[0] : "error";
    if (problem.kind === "note") return; // an error's or warning's context, on the line before
    site.problems.push(problem);
    const item = document.createElement("li");
    item.className = problem.kind;
    item.textContent = problem.line ? `${problem.file} line ${problem.line}: ${problem.message}` : problem.message;
    if (problem.line) item.onclick = () => selectLine(problem.file, problem.line);
    list.appendChild(item);
  });
  markAllLines();
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

/// Empties the view's frame, saying `why` (a run that did not start leaves no stale drawing).
function clearView(why) {
  viewReceiver = null;
  viewInbox = [];
  $("view").removeAttribute("src");
  $("view").srcdoc = `<!doctype html><meta charset="utf-8"><style>body{font:14px system-ui,sans-serif;color:#777;` +
    `padding:2em}@media (prefers-color-scheme: dark){body{color:#aaa;background:#1b1d1f}}</style><p>${why}</p>`;
}

// What both runners report besides the view's messages.
const runEvents = {
  failed(text) {
    showProblems(text);
    clearView("Nothing runs: see the problems under the scenario.");
    const errors = site.problems.filter((problem) => problem.kind === "error").length;
    status(errors ? "the run did not start: see the problems under the scenario" : "the run did not start");
  },
  result(result) { showResult(result); },
  crashed(text) { status(`the simulator failed: ${text}`); },
  // The sketch server's report of a run that ended early (a crash, exit(), a hang, a limit).
  ended(text) { showProblems(text); status("the run ended early: see the problems under the scenario"); },
};

/// The Web Worker that runs the WebAssembly simulator (worker.js), made once: it keeps the loaded
/// module and boards between runs. Its messages are handed to the run they belong to.
function simulationWorker() {
  if (site.worker) return site.worker;
  const worker = new Worker("worker.js");
  worker.onmessage = (event) => {
    const message = event.data;
    if (message.run !== site.runId) return; // a run that has been replaced
    if (message.kind === "view") toView(message.text);
    else if (runEvents[message.kind]) runEvents[message.kind](message.kind === "result" ? message.result : message.text);
  };
  worker.onerror = (event) => runEvents.crashed(event.message);
  site.worker = worker;
  return worker;
}

/// A run of the WebAssembly simulator in the page's worker: {send(text), stop()}.
function workerRunner(example, scenarioFile, scenarioText) {
  const worker = simulationWorker();
  const run = (site.runId = (site.runId || 0) + 1);
  worker.postMessage({ kind: "start", run, example: example.name, files: example.files,
                       path: exampleFolder(example) + scenarioFile, text: scenarioText });
  return { send: (text) => worker.postMessage({ kind: "view", text }), stop: () => worker.postMessage({ kind: "stop" }) };
}

/// The run on the local `stepdance serve`, over its socket: {send(text), stop()}.
async function serverRunner(example, scenarioFile, scenarioText) {
  const files = {};
  for (const file of example.files) files[file] = await fetchText(`examples/${example.name}/${file}`);
  files[sketchFile(example)] = site.sketchText;
  files[scenarioFile] = scenarioText;
  const others = {};
  for (const other of otherExamplesFiles(scenarioText)) {
    const text = await fetchText(`examples/${other.folder}/${other.file}`).catch(() => null);
    if (text !== null && other.folder !== example.name) (others[other.folder] ||= {})[other.file] = text;
  }
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
  socket.send(JSON.stringify({ type: "sketch_run", example: example.name, files, others, scenario: scenarioFile }));
  return { send: (text) => socket.send(text), stop: () => {} };
}

async function run() {
  if (site.runner) site.runner.stop();
  site.runner = null;
  viewInbox = [];
  viewReceiver = null;
  site.result = null;
  site.failedExpectations = [];
  showProblems("");
  $("result").hidden = true;
  $("hint").hidden = true;
  remember(VISITED_KEY, "1");
  const example = currentExample();
  const scenarioFile = $("scenario-file").value;
  const text = $("scenario").value;
  if (site.server) site.sketchText = $("sketch-editor").value;
  site.runner = site.server ? await serverRunner(example, scenarioFile, text) : workerRunner(example, scenarioFile, text);
  $("view").removeAttribute("srcdoc");
  $("view").src = `view/index.html?run=${Date.now()}`;
  $("reset").disabled = false;
  status(`running ${example.name}`);
}

// ---- a local stepdance serve -----------------------------------------------------------------

function servePort() { return Number(new URLSearchParams(location.search).get("serve")) || DEFAULT_SERVE_PORT; }
function serveHowTo() {
  return `To edit the sketch, run \`stepdance serve --allow-origin ${location.origin}\` on this computer, ` +
    "then press Connect (docs/web.md).";
}

// Looks for `stepdance serve` on 127.0.0.1 (its edit protocol's serve_hello). A page opened
// without ?serve= and that never met a server does not look by itself (a refused connection is
// logged by the browser): it says how to start one, and Connect looks.
function findServer() {
  const port = servePort();
  $("serve-state").textContent = `Looking for stepdance serve on 127.0.0.1:${port}…`;
  let socket;
  try {
    socket = new WebSocket(`ws://127.0.0.1:${port}/ws`);
  } catch (error) {
    $("serve-state").textContent = serveHowTo();
    return;
  }
  socket.onmessage = (event) => {
    const message = JSON.parse(event.data);
    if (message.type !== "serve_hello" || message.version !== EDIT_PROTOCOL_VERSION) return;
    site.server = socket;
    remember(SERVER_SEEN_KEY, "1");
    $("serve-state").textContent = `Sketch edits compile on stepdance serve at 127.0.0.1:${port}.`;
    $("connect").hidden = true;
    if (site.sketchText !== undefined) showSketch();
  };
  socket.onclose = () => {
    if (site.server === socket) {
      site.server = null;
      showSketch();
    }
    $("serve-state").textContent = serveHowTo();
    $("connect").hidden = false;
  };
}

// ---- the summary -----------------------------------------------------------------------------

function showResult(result) {
  site.result = result;
  site.failedExpectations = showRunResult(result, exampleFolder(currentExample()), selectLine);
  markAllLines();
  $("result").hidden = false;
  $("result").scrollIntoView({ block: "start" });
  const failed = result.expectations.filter((expectation) => !(expectation.checked && expectation.met)).length;
  status(failed ? `ended: ${failed} expectation(s) not met` : "ended: every expectation met");
}

// ---- start -----------------------------------------------------------------------------------

function wireControls() {
  $("example").onchange = () => showExample();
  $("scenario-file").onchange = showScenario;
  $("scenario").oninput = onScenarioInput;
  $("sketch-editor").oninput = onSketchInput;
  $("run").onclick = run;
  $("reset").onclick = run;
  $("revert").onclick = revert;
  $("share").onclick = share;
  $("connect").onclick = findServer;
  $("download-scenario").onclick = () => keep.download($("scenario-file").value, $("scenario").value);
  $("download-sketch").onclick = () => keep.download(sketchFile(currentExample()), site.sketchText);
  window.addEventListener("beforeunload", (event) => {
    if (!site.unsaved) return;
    event.preventDefault();
    event.returnValue = ""; // the browser asks whether to leave
  });
}

async function startPage() {
  if (location.protocol === "file:") {
    status("This page must come from a web server: run `python3 -m http.server -d build/web 8000` and open " +
           "http://127.0.0.1:8000/ (a browser runs no Web Worker and fetches no file from file://; docs/web.md).");
    return;
  }
  wireControls();
  const asked = new URLSearchParams(location.search).has("serve");
  if (asked || recalled(SERVER_SEEN_KEY)) findServer();
  else $("serve-state").textContent = serveHowTo();
  const listing = JSON.parse(await fetchText("examples.json"));
  site.examples = listing.examples;
  const picker = $("example");
  for (const example of site.examples) picker.add(new Option(example.name, example.name));
  const fragment = keep.fragment();
  const wanted = site.examples.some((example) => example.name === fragment.name) ? fragment.name : FIRST_EXAMPLE;
  if (site.examples.some((example) => example.name === wanted)) picker.value = wanted;
  let shared = null;
  if (fragment.shared) shared = await keep.decode(fragment.shared).catch(() => null);
  await showExample(shared);
  if (fragment.shared) status(shared ? "ready: the shared edits are in the editors; Run starts them" : "ready: the share link is damaged, so nothing of it was taken; Run starts the scenario shown");
  if (!recalled(VISITED_KEY)) $("hint").hidden = false;
}

startPage().catch((error) => status(`the page could not start: ${error.message}`));
