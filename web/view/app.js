// The live view's page. It knows only the view protocol (docs/simulator.md, "The view protocol"):
// messages come from a transport — a WebSocket to `stepdance sim --live --view`, or a Web Worker
// running the simulator in the page — and the page never asks which.
"use strict";

const PROTOCOL_VERSION = 2;
const SVG_NS = "http://www.w3.org/2000/svg";
/// A page-held button shorter than this is held this long, as a scenario's click is (100 ms).
const SHORTEST_PRESS_MS = 100;
/// A knob's arrow key turns it a scroll notch (a 24th of a turn); PageUp/PageDown a quarter turn.
const NOTCHES_PER_TURN = 24;
const NOTCHES_PER_PAGE_KEY = 6;
/// Messages wait at most this long for an animation frame (a hidden page gets none).
const LONGEST_BATCH_MS = 100;
/// A black stroke's points that no update will change go into paths of this many segments.
const SETTLED_POINTS = 256;
/// The page draws at most about 30 times a second (the simulator sends up to 60 updates): on a
/// machine of two cores the browser's drawing takes its time from the simulation's.
const SHORTEST_FRAME_MS = 33;

// What tests read (and nothing else needs): the drawing and state as received.
// Updated as each batch of messages is drawn, so that what it says is on the page.
const view = (window.stepdanceView = { hello: null, strokes: [], shades: [], shadeScale: null, pen: null, t_s: 0, errors: [],
  updates: 0, drawings: [], run: null, travel: null, sent: [] });

// ---- transport -------------------------------------------------------------------------------

// The page reaches the simulator only through a transport: a function (onMessage, onState) that
// returns {send(text)}, calls onMessage(text) for each view-protocol message and onState("open"
// or "closed") when the link changes. A host page picks one by setting window.stepdanceTransport
// before this script runs (the replay page's recording, the WebAssembly build's Web Worker);
// otherwise it is a WebSocket to the server that served this page. connect() at the end of this
// file starts it, once everything below is ready for its first message.

/// A WebSocket to the server that served this page (the token comes from the page's address).
function webSocketTransport(onMessage, onState) {
  const token = new URLSearchParams(location.search).get("token") || "";
  const socket = new WebSocket(`ws://${location.host}/ws?token=${encodeURIComponent(token)}`);
  socket.onopen = () => onState("open");
  socket.onclose = () => onState("closed");
  socket.onmessage = (event) => onMessage(event.data);
  return { send: (text) => socket.readyState === WebSocket.OPEN && socket.send(text) };
}

let transport = null;
let immediate = false;
let linkState = "connecting";

/// The transport of a page that shows this one in a frame (the WebAssembly build's page runs the
/// simulator in its Web Worker), if it offers one; a frame of another origin cannot be asked.
function embeddingTransport() {
  try {
    return window.parent !== window ? window.parent.stepdanceTransport : undefined;
  } catch (error) {
    return undefined;
  }
}

function connect() {
  const open = window.stepdanceTransport || embeddingTransport() || webSocketTransport;
  transport = open(receive, showConnection);
  // A transport that feeds the page a recording (the replay page) reads the page right after
  // it delivers: it says `immediate`, and its messages are drawn as they come.
  immediate = Boolean(transport && transport.immediate);
}

function send(message) { if (transport) transport.send(JSON.stringify(message)); }

function showConnection(state) {
  linkState = state;
  showStatus();
}

// ---- messages in -----------------------------------------------------------------------------

// Messages are handled in batches, one per animation frame: a page that draws slowly takes
// several updates at once and draws once, and never holds up the simulator (which sends the
// next update only when the last has gone: the socket is read as fast as messages come).
const pending = [];
let batchDue = false;
let lastBatchAt = -Infinity;

function receive(text) {
  pending.push(text);
  if (immediate) return handleBatch();
  if (batchDue) return;
  batchDue = true;
  const wait = Math.max(0, lastBatchAt + SHORTEST_FRAME_MS - performance.now());
  setTimeout(() => requestAnimationFrame(handleBatch), wait);
  setTimeout(handleBatch, wait + LONGEST_BATCH_MS);
}

function handleBatch() {
  batchDue = false;
  if (pending.length === 0) return;
  lastBatchAt = performance.now();
  for (const text of pending.splice(0)) handle(text);
  render();
}

function handle(text) {
  let message;
  try { message = JSON.parse(text); } catch (error) { return showError("unreadable message from the simulator"); }
  switch (message.type) {
    case "hello": return onHello(message);
    case "update": return onUpdate(message);
    case "error": view.errors.push(message.message); return showError(message.message);
    case "drawing": view.drawings.push(message.svg); return download(message.svg);
    default: return showError(`unknown message "${message.type}"`);
  }
}

function showError(text) {
  const box = document.getElementById("error");
  box.textContent = text;
  box.hidden = false;
}

// ---- the machine from above ------------------------------------------------------------------

const drawing = { svg: document.getElementById("drawing"), layer: null, pen: null, lines: [], fixedPage: false,
  turntable: false, table: null, paper: null, arm: null, tableRadius: null, machineParts: new Map() };

function svgElement(name, attributes, parent) {
  const element = document.createElementNS(SVG_NS, name);
  for (const [key, value] of Object.entries(attributes)) element.setAttribute(key, value);
  if (parent) parent.appendChild(element);
  return element;
}

/// The page as the run's SVG has it: the travel area plus a margin, white paper, the machine
/// origin at the travel area's top-left corner, y down, black pen lines 0.5 mm wide.
function setUpDrawing(machine) {
  const svg = drawing.svg;
  svg.replaceChildren();
  drawing.lines = [];
  drawing.box = [Infinity, Infinity, -Infinity, -Infinity];  // the points' x0, y0, x1, y1
  drawing.redrawFrom = [];  // per stroke: its first point changed since it was last drawn
  drawing.settled = [];     // per stroke: points drawn in its settled paths (renderBlackStroke)
  drawing.tableRadius = null;
  for (const node of drawing.machineParts.values()) if (node) node.remove();
  drawing.machineParts = new Map();  // part type → its text (a type this page does not draw), or null
  if (!machine) { svg.setAttribute("viewBox", "0 0 100 20"); return; }
  const margin = machine.margin_mm;
  const page = machine.page_mm || machine.travel_mm;
  drawing.fixedPage = Boolean(machine.page_mm);
  const [x0, x1, y0, y1] = page || [0, 10, 0, 10];
  svg.setAttribute("viewBox", `0 0 ${x1 - x0 + 2 * margin} ${y1 - y0 + 2 * margin}`);
  svgElement("rect", { x: 0, y: 0, width: x1 - x0 + 2 * margin, height: y1 - y0 + 2 * margin, fill: "white" }, svg);
  drawing.layer = svgElement("g", { transform: `translate(${margin - x0} ${margin - y0})`, fill: "none",
    "stroke-linecap": "round", "stroke-linejoin": "round" }, svg);
  if (machine.travel_mm) {
    const [tx0, tx1, ty0, ty1] = machine.travel_mm;
    svgElement("rect", { x: tx0, y: ty0, width: tx1 - tx0, height: ty1 - ty0, stroke: "#bbb",
      "stroke-width": 0.3, "stroke-dasharray": "2 2", id: "travel-area" }, drawing.layer);
  }
  drawing.turntable = false;
  drawing.strokes = svgElement("g", { stroke: "black", "stroke-width": machine.pen_width_mm, id: "strokes" }, drawing.layer);
  drawing.pen = svgElement("circle", { r: 2, id: "pen", class: "up", "stroke-width": 0.4, stroke: "#c22", fill: "none" }, drawing.layer);
  for (const part of machine.parts || []) setUpMachinePart(part);
}

/// A machine part type's drawing (hello's "parts", or the first update carrying it), once.
function setUpMachinePart(part) {
  if (!drawing.layer || drawing.machineParts.has(part)) return;
  const drawer = MACHINE_PARTS[part];
  drawing.machineParts.set(part, drawer ? drawer.setUp() || null : MACHINE_TEXT_PART.setUp(part));
}

/// A "table" part (a turntable): the table seen from above, the paper on it turned by the table's
/// angle (the drawing and the pen in paper mm inside it), the radial arm fixed along +x from the
/// centre.
function setUpTable() {
  const layer = drawing.layer;
  drawing.turntable = true;
  drawing.table = layer.insertBefore(svgElement("circle", { cx: 0, cy: 0, r: 10, fill: "#f4efe4", stroke: "#bbb", "stroke-width": 0.5, id: "turntable" }), drawing.strokes);
  const paper = drawing.paper = layer.insertBefore(svgElement("g", { id: "paper", transform: "rotate(0)" }), drawing.strokes);
  svgElement("line", { x1: -3, y1: 0, x2: 3, y2: 0, stroke: "#bbb", "stroke-width": 0.4 }, paper);  // the paper's own axes,
  svgElement("line", { x1: 0, y1: -3, x2: 0, y2: 3, stroke: "#bbb", "stroke-width": 0.4 }, paper);  // to see it turn
  paper.append(drawing.strokes, drawing.pen);
  drawing.arm = layer.insertBefore(svgElement("line", { x1: 0, y1: 0, x2: 0, y2: 0, stroke: "#666", "stroke-width": 1.5, "stroke-linecap": "round", id: "arm" }), paper.nextSibling);
}

/// The turntable's state: the paper turned by the table's angle (SVG's rotate() maps paper mm to
/// the table's as the machine does: r(cos −θ, sin −θ) on the paper lies at (r, 0)), the arm out to
/// the pen's radius, the table as large as the drawing and the arm need.
function showTable(table) {
  view.table = table;
  drawing.paper.setAttribute("transform", `rotate(${(table.angle_rad * 180) / Math.PI})`);
  drawing.arm.setAttribute("x2", table.radius_mm);
  fitToDrawing();
}

function pointsText(points) {
  const list = points.length === 1 ? [points[0], points[0]] : points;  // a dot, as the SVG draws one
  return list.map(([x, y]) => `${x},${y}`).join(" ");
}

/// "#rrggbb" of a shade on the SVG's scale [low, high]: blue (0, 0, 0.8) at low, dark green
/// (0, 0.6, 0) in the middle, red (0.8, 0, 0) at high, two straight ramps, clamped outside
/// (docs/simulator.md, "The view protocol"; the same arithmetic as the SVG writer's).
function shadeColour(shade, [low, high]) {
  const span = high - low;
  let t = span > 0 ? (shade - low) / span : 0.5;
  t = t < 0 ? 0 : (t > 1 ? 1 : t);
  const mix = (a, b, u) => a.map((value, k) => value + (b[k] - value) * u);
  const rgb = t < 0.5 ? mix([0, 0, 0.8], [0, 0.6, 0], 2 * t) : mix([0, 0.6, 0], [0.8, 0, 0], 2 * t - 1);
  return "#" + rgb.map((channel) => Math.floor(channel * 255 + 0.5).toString(16).padStart(2, "0")).join("");
}

/// Stroke i as the SVG draws it: one black polyline, or for a shaded stroke one polyline per
/// shade, each from its shade's first point to the next one's, in its colour.
function renderStroke(i) {
  const group = drawing.lines[i];
  const points = view.strokes[i];
  const shades = view.shades[i];
  const from = drawing.redrawFrom[i] ?? 0;
  drawing.redrawFrom[i] = undefined;
  if (shades.length === 0 || !view.shadeScale) return renderBlackStroke(i, group, points, from);
  for (const settled of group.querySelectorAll("path")) settled.remove();
  drawing.settled[i] = 0;
  const pieces = shades.map(([start, shade], j) => ({
    points: points.slice(start, j + 1 < shades.length ? shades[j + 1][0] + 1 : points.length),
    colour: shadeColour(shade, view.shadeScale),
  }));
  while (group.children.length > pieces.length) group.lastChild.remove();
  while (group.children.length < pieces.length) svgElement("polyline", {}, group);
  pieces.forEach((piece, j) => {
    const line = group.children[j];
    line.setAttribute("points", pointsText(piece.points));
    line.setAttribute("stroke", piece.colour);
  });
}

/// A black stroke: its settled points (those no update will change: before `from`) in paths of
/// SETTLED_POINTS segments, written once, then one polyline with the rest, rewritten as the
/// stroke grows. The browser then repaints only the rest's area, not the whole stroke's, at each
/// frame. A path and the next one (or the polyline) share their joining point.
function renderBlackStroke(i, group, points, from) {
  let settled = drawing.settled[i] || 0;
  let tail = group.lastElementChild;
  if (from < settled || !tail || tail.tagName !== "polyline" || group.children.length - 1 !== group.querySelectorAll("path").length) {
    group.replaceChildren();  // drawn afresh (a new stroke, or one that was shaded)
    tail = svgElement("polyline", {}, group);
    settled = 0;
  }
  tail.removeAttribute("stroke");
  while (Math.min(from, points.length - 2) - settled >= SETTLED_POINTS) {
    const end = settled + SETTLED_POINTS;
    const d = "M" + points.slice(settled, end + 1).map(([x, y]) => `${x},${y}`).join("L");
    group.insertBefore(svgElement("path", { d, class: "settled" }), tail);
    settled = end;
  }
  drawing.settled[i] = settled;
  tail.setAttribute("points", pointsText(points.slice(settled)));
}

/// What changed since the page last drew, drawn by render() once per batch of messages.
const dirty = { strokes: new Set(), boards: new Set(), console: new Map(), parts: new Map(), machineParts: new Set(),
  fit: false, pen: false, travel: false, run: false };

function applyStrokes(parts) {
  for (const part of parts) {
    while (view.strokes.length <= part.i) {
      view.strokes.push([]);
      view.shades.push([]);
      drawing.lines.push(svgElement("g", { class: "stroke" }, drawing.strokes));
    }
    const stroke = view.strokes[part.i];
    stroke.length = part.from;
    const box = drawing.box;  // every point received (a moved head's old place too: it was drawn)
    for (const point of part.points) {
      stroke.push(point);
      box[0] = Math.min(box[0], point[0]); box[1] = Math.min(box[1], point[1]);
      box[2] = Math.max(box[2], point[0]); box[3] = Math.max(box[3], point[1]);
    }
    drawing.redrawFrom[part.i] = Math.min(drawing.redrawFrom[part.i] ?? Infinity, part.from);
    view.shades[part.i] = view.shades[part.i].filter(([from]) => from < part.from).concat(part.shades || []);
    dirty.strokes.add(part.i);
    dirty.fit = true;
  }
}

/// A new colour scale: every shaded stroke is coloured again.
function applyShadeScale(scale) {
  view.shadeScale = scale;
  view.shades.forEach((shades, i) => { if (shades.length > 0) dirty.strokes.add(i); });
}

function renderStrokes() {
  for (const i of dirty.strokes) renderStroke(i);
  dirty.strokes.clear();
  if (dirty.fit && !drawing.fixedPage) fitToDrawing();
  dirty.fit = false;
}

/// A machine without a fixed page: the view follows the drawing's bounding box (a turntable's:
/// the circle around the centre holding the drawing and the arm).
function fitToDrawing() {
  if (drawing.turntable) return fitTable();
  const [x0, y0, x1, y1] = drawing.box;
  if (!(x0 <= x1)) return;
  const margin = view.hello.machine.margin_mm;
  const box = `${x0 - margin} ${y0 - margin} ${Math.max(x1 - x0, 10) + 2 * margin} ${Math.max(y1 - y0, 10) + 2 * margin}`;
  if (box === drawing.svg.getAttribute("viewBox")) return;  // a new viewBox repaints the whole drawing
  drawing.svg.setAttribute("viewBox", box);
  drawing.layer.setAttribute("transform", "");
}

function fitTable() {
  let radius = Math.max(10, view.table ? Math.abs(view.table.radius_mm) : 0);
  for (const stroke of view.strokes) for (const [x, y] of stroke) radius = Math.max(radius, Math.hypot(x, y));
  if (radius === drawing.tableRadius) return;
  drawing.tableRadius = radius;
  const half = radius + view.hello.machine.margin_mm;
  drawing.table.setAttribute("r", radius);
  drawing.svg.setAttribute("viewBox", `${-half} ${-half} ${2 * half} ${2 * half}`);
  drawing.layer.setAttribute("transform", "");
}

function showPen(pen) {
  document.getElementById("pen-x").textContent = pen.x_mm.toFixed(2);
  document.getElementById("pen-y").textContent = pen.y_mm.toFixed(2);
  document.getElementById("pen-state").textContent = pen.down ? "down" : "up";
  if (!drawing.pen) return;
  drawing.pen.setAttribute("cx", pen.x_mm);
  drawing.pen.setAttribute("cy", pen.y_mm);
  drawing.pen.setAttribute("class", pen.down ? "down" : "up");
  drawing.pen.setAttribute("fill", pen.down ? "#c22" : "none");
}

// ---- boards: devices as controls, figures, console -------------------------------------------

const boards = new Map();  // name → {figures, faults, console}
const devices = new Map();  // name → {holder, label, parts: part type → its drawing}
// The run's state as the updates built it (version 2: each update carries what changed); `parts`:
// each device part type's entries by device.
const state = { motors: new Map(), boards: new Map(), parts: new Map() };

function element(tag, attributes = {}, parent = null, text = "") {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
  if (text) node.textContent = text;
  if (parent) parent.appendChild(node);
  return node;
}

function onHello(hello) {
  if (hello.version !== PROTOCOL_VERSION) return showError(`the simulator speaks view protocol ${hello.version}, this page ${PROTOCOL_VERSION}`);
  view.hello = hello;
  view.strokes = [];
  view.shades = [];
  view.shadeScale = null;
  view.table = null;
  view.travel = null;
  view.run = hello.run;
  state.motors.clear();
  state.boards.clear();
  state.parts.clear();
  dirty.strokes.clear();
  dirty.boards.clear();
  dirty.console.clear();
  dirty.parts.clear();
  dirty.machineParts.clear();
  dirty.pen = dirty.travel = false;
  dirty.run = true;
  setUpDrawing(hello.machine);
  setUpTravel(hello.machine);
  const container = document.getElementById("boards");
  container.replaceChildren();
  boards.clear();
  devices.clear();
  for (const board of hello.boards) boards.set(board.name, buildBoard(board, container));
  shownReason = undefined;  // new controls: their state is written at the next render
}

function buildBoard(board, container) {
  const box = element("section", { class: "board", id: `board-${board.name}`, "aria-label": `Board ${board.name}` }, container);
  element("h2", {}, box, `${board.name} (${board.module})`);
  const list = element("div", { class: "devices" }, box);
  for (const device of board.devices) {
    const holder = element("div", { class: "device" }, list);
    const control = device.control;
    if (control.type === "knob" || control.type === "knob_with_button") addKnob(holder, device);
    if (control.type === "knob_with_button" || control.type === "button") addButton(holder, device);
    if (control.type === "slider") addSlider(holder, device);
    const label = element("span", { class: "device-name" }, holder, `${device.name} · ${device.connector}`);
    devices.set(device.name, { holder, label, parts: new Map() });
    for (const part of device.parts || []) devicePartDrawing(device.name, part);
  }
  const figures = element("table", { class: "figures", "aria-label": `${board.name} figures` }, box);
  const faults = element("p", { class: "fault", hidden: "" }, box);
  const consoleText = element("pre", { class: "console", id: `console-${board.name}`, tabindex: 0, role: "log", "aria-label": `${board.name} console` }, box);
  addConsoleLine(board, box, consoleText);
  return { figures, faults, console: consoleText, rows: new Map() };
}

/// The line to send to a board's console: what is sent is echoed in the console (marked "> "),
/// and "Clear" empties the console on the page.
function addConsoleLine(board, box, consoleText) {
  const line = element("form", { class: "console-line" }, box);
  const input = element("input", { type: "text", placeholder: "a line for the sketch", id: `send-${board.name}`, "aria-label": `A line for ${board.name}'s sketch` }, line);
  element("button", { type: "submit", class: "act" }, line, "Send");
  const clear = element("button", { type: "button", id: `clear-${board.name}` }, line, "Clear");
  line.addEventListener("submit", (event) => {
    event.preventDefault();
    if (blocked("The line was not sent")) return;
    send({ type: "console", board: board.name, text: input.value + "\n" });
    view.sent.push({ board: board.name, text: input.value });
    appendConsole(consoleText, `> ${input.value}\n`, "sent");
    input.value = "";
  });
  clear.addEventListener("click", () => { consoleText.replaceChildren(); });
}

/// Appends `text` to a console, its oldest text dropped past 20,000 characters; `kind` "sent"
/// marks the page's own lines.
function appendConsole(consoleText, text, kind) {
  const last = consoleText.lastChild;
  if (!kind && last && last.nodeType === Node.TEXT_NODE) last.appendData(text);
  else if (kind) element("span", { class: kind }, consoleText, text);
  else consoleText.appendChild(document.createTextNode(text));
  while (consoleText.textContent.length > 20000 && consoleText.firstChild) {
    const first = consoleText.firstChild;
    const excess = consoleText.textContent.length - 20000;
    if (first.nodeType === Node.TEXT_NODE && first.length > excess) first.deleteData(0, excess);
    else first.remove();
  }
  consoleText.scrollTop = consoleText.scrollHeight;
}

/// An endless knob, a slider for the keyboard and screen readers (its value: the counts the page
/// turned it by): dragged around its centre (clockwise = positive counts, one turn of the hand =
/// the device's counts per turn), scrolled (a 24th of a turn a notch), or turned with the arrow
/// keys (a notch) and PageUp/PageDown (a quarter turn); up and right are clockwise.
function addKnob(holder, device) {
  const knob = element("div", { class: "knob", id: `control-${device.name}`, role: "slider", tabindex: 0,
    "aria-label": `${device.name} knob`, "aria-valuenow": 0, "aria-valuetext": "0 counts" }, holder);
  const mark = element("div", { class: "mark" }, knob);
  const perTurn = device.control.counts_per_turn || 24;
  let angle = 0, sent = 0, last = null;
  const show = () => { mark.style.transform = `rotate(${angle}rad)`; };
  const flush = () => {
    const target = Math.round(angle / (2 * Math.PI) * perTurn);
    if (target === sent) return;
    if (blocked("The knob's turn was not sent")) {
      angle = sent / perTurn * 2 * Math.PI;  // the knob goes back: nothing turned
      return show();
    }
    send({ type: "input", device: device.name, action: "turn", counts: target - sent });
    sent = target;
    knob.setAttribute("aria-valuenow", sent);
    knob.setAttribute("aria-valuetext", `${sent} counts`);
  };
  const turnBy = (notches) => { angle += notches * 2 * Math.PI / NOTCHES_PER_TURN; show(); flush(); };
  const angleAt = (event) => {
    const box = knob.getBoundingClientRect();
    return Math.atan2(event.clientY - (box.top + box.height / 2), event.clientX - (box.left + box.width / 2));
  };
  knob.addEventListener("pointerdown", (event) => { knob.setPointerCapture(event.pointerId); last = angleAt(event); event.preventDefault(); knob.focus(); });
  knob.addEventListener("pointermove", (event) => {
    if (last === null) return;
    const now = angleAt(event);
    let delta = now - last;
    if (delta > Math.PI) delta -= 2 * Math.PI;
    if (delta < -Math.PI) delta += 2 * Math.PI;
    angle += delta;
    last = now;
    show();
    flush();
  });
  const end = () => { last = null; };
  knob.addEventListener("pointerup", end);
  knob.addEventListener("pointercancel", end);
  knob.addEventListener("wheel", (event) => { event.preventDefault(); turnBy(event.deltaY < 0 ? 1 : -1); });
  const keys = { ArrowUp: 1, ArrowRight: 1, ArrowDown: -1, ArrowLeft: -1, PageUp: NOTCHES_PER_PAGE_KEY, PageDown: -NOTCHES_PER_PAGE_KEY };
  knob.addEventListener("keydown", (event) => {
    if (!(event.key in keys)) return;
    event.preventDefault();
    turnBy(keys[event.key]);
  });
}

/// A momentary button: held while the pointer is down, or while Space or Enter is (at least
/// SHORTEST_PRESS_MS either way).
function addButton(holder, device) {
  const button = element("button", { type: "button", class: "press", id: `control-${device.name}${device.control.type === "knob_with_button" ? "-button" : ""}`, "aria-label": `${device.name} button`, "aria-pressed": "false" }, holder);
  let pressedAt = null;
  const press = () => {
    if (pressedAt !== null || blocked("The press was not sent")) return false;
    pressedAt = performance.now();
    button.classList.add("down");
    button.setAttribute("aria-pressed", "true");
    send({ type: "input", device: device.name, action: "press" });
    return true;
  };
  const release = () => {
    if (pressedAt === null) return;
    const held = performance.now() - pressedAt;
    pressedAt = null;
    setTimeout(() => {
      send({ type: "input", device: device.name, action: "release" });
      button.classList.remove("down");
      button.setAttribute("aria-pressed", "false");
    }, Math.max(0, SHORTEST_PRESS_MS - held));
  };
  button.addEventListener("pointerdown", (event) => { if (press()) button.setPointerCapture(event.pointerId); });
  button.addEventListener("pointerup", release);
  button.addEventListener("pointercancel", release);
  button.addEventListener("keydown", (event) => {
    if (event.key !== " " && event.key !== "Enter") return;
    event.preventDefault();  // no click: the key holds the button as a finger would
    if (!event.repeat) press();
  });
  button.addEventListener("keyup", (event) => {
    if (event.key !== " " && event.key !== "Enter") return;
    event.preventDefault();
    release();
  });
  button.addEventListener("blur", release);
}

/// An "arms" part: a five-bar linkage from above (pivots, arms, elbow, stylus).
function addArm(name) {
  const svg = svgElement("svg", { class: "arm", id: `arm-${name}`, width: 160, height: 160, viewBox: "-100 -20 200 260", role: "img", "aria-label": `${name} linkage` });
  const style = { fill: "none", stroke: "#555", "stroke-width": 3, "stroke-linejoin": "round", "stroke-linecap": "round" };
  svgElement("polyline", { ...style, class: "right-side" }, svg);  // right pivot, C, E, stylus T
  svgElement("polyline", { ...style, class: "left-side" }, svg);   // left pivot, D, E
  svgElement("circle", { r: 4, fill: "#c22", class: "stylus" }, svg);
  return svg;
}

function showArm(svg, arm) {
  const text = (points) => points.map(([x, y]) => `${x},${y}`).join(" ");
  svg.querySelector(".right-side").setAttribute("points", text([arm.right_pivot, arm.c, arm.e, arm.t]));
  svg.querySelector(".left-side").setAttribute("points", text([arm.left_pivot, arm.d, arm.e]));
  const stylus = svg.querySelector(".stylus");
  stylus.setAttribute("cx", arm.t[0]);
  stylus.setAttribute("cy", arm.t[1]);
  const all = [arm.right_pivot, arm.left_pivot, arm.c, arm.d, arm.e, arm.t];
  const xs = all.map((p) => p[0]), ys = all.map((p) => p[1]);
  const x0 = Math.min(...xs) - 10, y0 = Math.min(...ys) - 10;
  const size = Math.max(Math.max(...xs) - x0, Math.max(...ys) - y0) + 10;
  svg.setAttribute("viewBox", `${x0} ${y0} ${size} ${size}`);
}

function addSlider(holder, device) {
  const c = device.control;
  const slider = element("input", { type: "range", min: c.low, max: c.high, step: c.step, id: `control-${device.name}`, "aria-label": `${device.name} (${c.unit})` }, holder);
  let position = Number(slider.value);
  slider.addEventListener("input", () => {
    if (blocked("The slider's move was not sent")) { slider.value = position; return; }
    position = Number(slider.value);
    send({ type: "input", device: device.name, action: "set", position });
  });
}

/// A board's figures: frames, load, each motor's steps and rate, warnings; its fault.
function renderBoard(name) {
  const board = boards.get(name);
  const figures = state.boards.get(name);
  if (!board || !figures) return;
  const rows = [["frames", figures.frames]];
  if (figures.load_average_percent !== null) rows.push(["frame load", `${figures.load_average_percent.toFixed(1)} % (peak ${figures.load_peak_percent.toFixed(1)} %)`]);
  for (const motor of state.motors.values()) {
    if (motor.board === name) rows.push([`motor ${motor.port}`, `${motor.steps} steps, ${Math.round(motor.rate_steps_per_s)} steps/s`]);
  }
  for (const warning of figures.warnings || []) rows.push([`warning ${warning.name}`, `×${warning.count} ${warning.detail}`]);
  const names = rows.map(([label]) => label).join("\n");
  if (board.rowNames !== names) {  // the rows change seldom: their cells are written in place
    board.rowNames = names;
    board.rows.clear();
    board.figures.replaceChildren(...rows.map(([label]) => {
      const row = document.createElement("tr");
      element("th", {}, row, label);
      board.rows.set(label, element("td", { "data-figure": label }, row));
      return row;
    }));
  }
  for (const [label, value] of rows) setText(board.rows.get(label), String(value));
  board.faults.hidden = !figures.fault;
  if (figures.fault) board.faults.textContent = `fault: ${figures.fault.reason} ×${figures.fault.count} ${figures.fault.detail}`;
}

/// A "screens" part: a display's picture, 128 × 32 pixels.
function addScreen(name) {
  return element("canvas", { class: "screen", width: 128, height: 32, id: `screen-${name}`, role: "img", "aria-label": `${name} screen` });
}

function drawScreen(canvas, screen) {
  const context = canvas.getContext("2d");
  const image = context.createImageData(128, 32);
  screen.rows.forEach((row, y) => {
    for (let x = 0; x < 128; ++x) {
      const lit = screen.on && (parseInt(row[x >> 2], 16) >> (3 - (x & 3))) & 1;
      const at = (y * 128 + x) * 4;
      image.data[at] = image.data[at + 1] = image.data[at + 2] = lit ? 230 : 0;
      image.data[at + 3] = 255;
    }
  });
  context.putImageData(image, 0, 0);
}

// ---- the kinds' own parts ------------------------------------------------------------------------

// A device or machine kind gives its own parts of the state (docs/simulator.md, "The view
// protocol"): hello declares their types ("parts"), the updates carry them under that type. The
// page draws each by its type, never by the kind: set up once (at hello, or at the first update
// carrying a type hello did not declare), then shown at each change. A device part of a type not
// listed here is shown as its text beside the device.
const MACHINE_PARTS = { table: { setUp: setUpTable, show: showTable } };
const MACHINE_TEXT_PART = {
  setUp: (part) => {
    const node = element("pre", { class: "part", id: `part-machine-${part}`, "aria-label": `machine ${part}` });
    drawing.svg.after(node);
    return node;
  },
  show: (node, value) => { node.textContent = JSON.stringify(value); },
};
const DEVICE_PARTS = { screens: { setUp: addScreen, show: drawScreen }, arms: { setUp: addArm, show: showArm } };
const TEXT_PART = {
  setUp: (name, part) => element("pre", { class: "part", id: `part-${name}-${part}`, "aria-label": `${name} ${part}` }),
  show: (node, entry) => { node.textContent = JSON.stringify(entry, (key, value) => (key === "device" ? undefined : value)); },
};

/// Device `name`'s drawing of part type `part`, made (before the device's name) if it has none.
function devicePartDrawing(name, part) {
  const device = devices.get(name);
  if (!device) return null;
  if (!device.parts.has(part)) {
    const drawer = DEVICE_PARTS[part] || TEXT_PART;
    device.parts.set(part, device.holder.insertBefore(drawer.setUp(name, part), device.label));
  }
  return device.parts.get(part);
}

/// The update's device parts (arrays of entries naming their `device`): kept in `state.parts`, as
/// `view[part]` for tests, and marked to be drawn.
function applyDeviceParts(update) {
  for (const [part, entries] of Object.entries(update)) {
    if (!Array.isArray(entries) || !entries.every((entry) => entry && typeof entry.device === "string")) continue;
    if (!state.parts.has(part)) state.parts.set(part, new Map());
    for (const entry of entries) {
      state.parts.get(part).set(entry.device, entry);
      dirty.parts.set(`${part} ${entry.device}`, [part, entry]);
    }
    if (entries.length > 0) view[part] = [...state.parts.get(part).values()];
  }
}

/// The update's machine parts: the fields hello declared, and those this page draws (a replay
/// recorded before hello declared them), each kept as `view[part]`.
function applyMachineParts(update) {
  const declared = (view.hello.machine && view.hello.machine.parts) || [];
  for (const part of new Set([...declared, ...Object.keys(MACHINE_PARTS)])) {
    if (update[part] === undefined) continue;
    view[part] = update[part];
    dirty.machineParts.add(part);
  }
}

function renderMachineParts() {
  for (const part of dirty.machineParts) {
    setUpMachinePart(part);
    if (!drawing.machineParts.has(part)) continue;  // no machine drawn
    const node = drawing.machineParts.get(part);
    if (MACHINE_PARTS[part]) MACHINE_PARTS[part].show(view[part]);
    else if (node) MACHINE_TEXT_PART.show(node, view[part]);
  }
  dirty.machineParts.clear();
}

function renderDeviceParts() {
  for (const [part, entry] of dirty.parts.values()) {
    const node = devicePartDrawing(entry.device, part);
    if (node) (DEVICE_PARTS[part] || TEXT_PART).show(node, entry);
  }
  dirty.parts.clear();
}

// ---- off the paper: the travel area --------------------------------------------------------------

/// The travel area is drawn (setUpDrawing's dashed rectangle); each excursion past it gets a
/// marker where the pen left, and a line above the drawing says how often, as the summary's
/// travel_excursions counts it.
function setUpTravel(machine) {
  const note = document.getElementById("travel-note");
  note.hidden = true;
  note.textContent = "";
  drawing.excursions = drawing.layer ? svgElement("g", { id: "excursions" }, drawing.layer) : null;
}

function showTravel(travel) {
  const note = document.getElementById("travel-note");
  note.hidden = travel.excursions === 0;
  const marked = travel.first_points.length;
  const last = travel.first_points[marked - 1];
  note.textContent = travel.excursions === 0 ? "" : `Off the travel area: the pen left it ${travel.excursions === 1 ? "once" : `${travel.excursions} times`} (the summary's travel_excursions)` +
    (last ? `; ${marked < travel.excursions ? `the first ${marked} are marked, the last of them` : "marked ×, the last"} at t = ${last.t_s.toFixed(3)} s, (${last.x_mm.toFixed(2)}, ${last.y_mm.toFixed(2)}) mm` : "") +
    (travel.outside ? "; it is outside now." : "; it is back inside.");
  document.getElementById("drawing").classList.toggle("outside", travel.outside);
  if (!drawing.excursions) return;
  while (drawing.excursions.children.length > travel.first_points.length) drawing.excursions.lastChild.remove();
  travel.first_points.forEach((point, k) => {
    const marker = drawing.excursions.children[k] || svgElement("g", { class: "excursion" }, drawing.excursions);
    marker.replaceChildren();
    svgElement("circle", { cx: point.x_mm, cy: point.y_mm, r: 3, fill: "none", stroke: "#d00", "stroke-width": 0.8 }, marker);
    svgElement("path", { d: `M ${point.x_mm - 2} ${point.y_mm - 2} L ${point.x_mm + 2} ${point.y_mm + 2} M ${point.x_mm - 2} ${point.y_mm + 2} L ${point.x_mm + 2} ${point.y_mm - 2}`, stroke: "#d00", "stroke-width": 0.8 }, marker);
    svgElement("title", {}, marker).textContent = `left the travel area at t = ${point.t_s.toFixed(3)} s`;
  });
}

// ---- run control, and what the controls can do ------------------------------------------------

/// Why the page's controls no longer reach the run, or null when they do.
function blockedReason() {
  if (view.run && (view.run.ended || view.run.stopped)) return "The run has ended: the controls no longer act on it.";
  if (linkState === "closed") return "Not connected to the simulator: the controls do nothing.";
  if (linkState !== "open") return "Connecting to the simulator…";
  return null;
}

/// Whether the controls cannot act now; if so, says so in the controls' note, with `what`.
function blocked(what) {
  const reason = blockedReason();
  if (reason === null) return false;
  const note = document.getElementById("controls-note");
  note.textContent = `${reason} ${what}.`;
  note.hidden = false;
  return true;
}

let shownReason;  // what showStatus() last wrote (undefined: nothing yet)

/// The connection's label ("connected", "ended", "disconnected"), and the controls' state.
/// Sets an element's text only when it changes (a write, even of the same text, costs a layout).
function setText(node, text) {
  if (node.textContent !== text) node.textContent = text;
}

function showStatus() {
  const label = document.getElementById("connection");
  const ended = view.run && (view.run.ended || view.run.stopped);
  const text = transport && transport.label ? transport.label
    : ended ? "ended" : linkState === "open" ? "connected" : linkState === "closed" ? "disconnected" : "connecting…";
  setText(label, text);
  const className = "state " + (ended ? "ended" : linkState);
  if (label.className !== className) label.className = className;
  const reason = blockedReason();
  if (reason === shownReason) return;  // the controls' state is written when it changes only
  shownReason = reason;
  const note = document.getElementById("controls-note");
  note.hidden = reason === null;
  if (reason !== null) note.textContent = reason;
  document.body.classList.toggle("inert-controls", reason !== null);
  for (const control of document.querySelectorAll("#boards .knob, #boards button, #boards input, #run-controls button")) {
    if (reason === null) control.removeAttribute("aria-disabled"); else control.setAttribute("aria-disabled", "true");
  }
  for (const control of document.querySelectorAll("#run-controls button")) control.title = reason || "";
}

function showRun(run) {
  document.getElementById("pause").hidden = run.paused;
  document.getElementById("resume").hidden = !run.paused;
  for (const button of document.querySelectorAll(".speed")) {
    const speed = button.dataset.speed === "max" ? 0 : Number(button.dataset.speed);
    button.classList.toggle("active", speed === run.speed);
    button.setAttribute("aria-pressed", String(speed === run.speed));
  }
  showStatus();
}

function sendRun(message) {
  if (blocked("The run was not changed")) return;
  send(message);
}

document.getElementById("pause").addEventListener("click", () => sendRun({ type: "run", action: "pause" }));
document.getElementById("resume").addEventListener("click", () => sendRun({ type: "run", action: "resume" }));
for (const button of document.querySelectorAll(".speed")) {
  button.addEventListener("click", () => sendRun({ type: "run", action: "speed", speed: button.dataset.speed === "max" ? "max" : Number(button.dataset.speed) }));
}
document.getElementById("save").addEventListener("click", () => send({ type: "save" }));

function download(svg) {
  const link = document.createElement("a");
  link.href = URL.createObjectURL(new Blob([svg], { type: "image/svg+xml" }));
  link.download = "drawing.svg";
  link.click();
  setTimeout(() => URL.revokeObjectURL(link.href), 1000);
}

// ---- an update: merged into the state, drawn by render() -----------------------------------------

function onUpdate(update) {
  view.updates += 1;
  view.t_s = update.t_s;
  if (update.run) view.run = update.run, dirty.run = true;
  if (update.pen) view.pen = update.pen, dirty.pen = true;
  if (update.shade_scale) applyShadeScale(update.shade_scale);
  if (update.strokes) applyStrokes(update.strokes);
  applyMachineParts(update);
  if (update.travel) view.travel = update.travel, dirty.travel = true;
  for (const motor of update.motors || []) {
    state.motors.set(`${motor.board} ${motor.port}`, motor);
    dirty.boards.add(motor.board);
  }
  for (const figures of update.boards || []) {
    state.boards.set(figures.name, figures);
    dirty.boards.add(figures.name);
  }
  applyDeviceParts(update);
  for (const output of update.console || []) dirty.console.set(output.board, (dirty.console.get(output.board) || "") + output.text);
  view.motors = [...state.motors.values()];
}

/// Draws what the batch of messages changed.
function render() {
  if (!view.hello) return;
  setText(document.getElementById("sim-time"), `t = ${view.t_s.toFixed(3)} s`);
  renderStrokes();
  if (dirty.pen) showPen(view.pen);
  renderMachineParts();
  dirty.pen = false;
  for (const name of dirty.boards) renderBoard(name);
  dirty.boards.clear();
  for (const [name, text] of dirty.console) {
    const board = boards.get(name);
    if (board) appendConsole(board.console, text);
  }
  dirty.console.clear();
  renderDeviceParts();
  if (dirty.travel) showTravel(view.travel);
  dirty.travel = false;
  if (dirty.run && view.run) showRun(view.run);
  dirty.run = false;
}

connect();
