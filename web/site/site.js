// The Stepdance page: pick an example, read its sketch, edit its scenario, run it in a Web Worker
// (worker.js) and watch it in the live view (view/, the page `stepdance sim --live --view`
// serves, unchanged: it gets this page's Worker as its transport), then read the run's summary.
"use strict";

const site = (window.stepdanceSite = { examples: [], result: null, problems: [], worker: null });

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
function scenarioPath(example) { return `/examples/${example.name}/${$("scenario-file").value}`; }

async function showExample() {
  const example = currentExample();
  location.hash = example.name;
  const sketchFile = example.files.find((file) => file === `${example.name}.ino`) ||
    example.files.find((file) => file.endsWith(".ino"));
  $("sketch-name").textContent = sketchFile;
  highlightCpp($("sketch"), await fetchText(`examples/${example.name}/${sketchFile}`));
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

// The reader's or the simulation's errors (`file:line: message` lines), each at its line.
function showProblems(text) {
  const list = $("problems");
  list.textContent = "";
  site.problems = [];
  const path = scenarioPath(currentExample());
  for (const line of text.split("\n").filter(Boolean)) {
    const match = line.startsWith(path + ":") && line.slice(path.length).match(/^:(\d+)(?::\d+)?: ?(.*)$/);
    const problem = match ? { line: Number(match[1]), message: match[2] } : { line: null, message: line };
    site.problems.push(problem);
    const item = document.createElement("li");
    item.textContent = problem.line ? `line ${problem.line}: ${problem.message}` : problem.message;
    if (problem.line) item.onclick = () => selectLine(problem.line);
    list.appendChild(item);
  }
  numberLines(new Set(site.problems.map((problem) => problem.line).filter(Boolean)));
}

function selectLine(line) {
  const lines = $("scenario").value.split("\n");
  const start = lines.slice(0, line - 1).reduce((sum, text) => sum + text.length + 1, 0);
  $("scenario").focus();
  $("scenario").setSelectionRange(start, start + lines[line - 1].length);
}

// ---- the run ---------------------------------------------------------------------------------

// The view (in the frame) asks its parent for a transport: this page's Worker.
window.stepdanceTransport = (onMessage, onState) => {
  viewReceiver = onMessage;
  onState(site.worker ? "open" : "closed");
  for (const text of viewInbox) onMessage(text);
  viewInbox = [];
  return { send: (text) => site.worker && site.worker.postMessage({ kind: "view", text }) };
};

function toView(text) {
  if (viewReceiver) viewReceiver(text);
  else viewInbox.push(text);
}

function run() {
  if (site.worker) site.worker.terminate();
  viewInbox = [];
  viewReceiver = null;
  site.result = null;
  showProblems("");
  $("result").hidden = true;
  const example = currentExample();
  const worker = (site.worker = new Worker("worker.js"));
  worker.onmessage = (event) => {
    const message = event.data;
    if (message.kind === "view") toView(message.text);
    else if (message.kind === "failed") { showProblems(message.text); status("the scenario did not load"); }
    else if (message.kind === "result") showResult(message.result);
    else if (message.kind === "crashed") status(`the simulator failed: ${message.text}`);
  };
  worker.onerror = (event) => status(`the simulator failed: ${event.message}`);
  worker.postMessage({ kind: "start", example: example.name, files: example.files,
                       path: scenarioPath(example), text: $("scenario").value });
  $("view").src = `view/index.html?run=${Date.now()}`;
  $("reset").disabled = false;
  status(`running ${example.name}`);
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
  const path = scenarioPath(currentExample());
  for (const expectation of result.expectations) {
    const verdict = !expectation.checked ? "not run" : expectation.met ? "ok" : "FAILED";
    const message = expectation.message.startsWith(path + ":")
      ? expectation.message.slice(path.length + 1).replace(/^(\d+): /, "line $1: ") : expectation.message;
    row(expectations, [verdict, message], expectation.checked && expectation.met ? "ok" : "failed");
  }
  $("result").hidden = false;
  const failed = result.expectations.filter((expectation) => !(expectation.checked && expectation.met)).length;
  status(failed ? `ended: ${failed} expectation(s) not met` : "ended: every expectation met");
}

// ---- start -----------------------------------------------------------------------------------

async function startPage() {
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
