// The live view's page. It knows only the view protocol (docs/simulator.md, "The view protocol"):
// messages come from a transport — a WebSocket to `stepdance sim --live --view`, or a Web Worker
// running the simulator in the page — and the page never asks which.
"use strict";

const PROTOCOL_VERSION = 1;
const SVG_NS = "http://www.w3.org/2000/svg";
/// A page-held button shorter than this is held this long, as a scenario's click is (100 ms).
const SHORTEST_PRESS_MS = 100;

// What tests read (and nothing else needs): the drawing and state as received.
const view = (window.stepdanceView = { hello: null, strokes: [], shades: [], shadeScale: null, pen: null, t_s: 0, errors: [], updates: 0, drawings: [] });

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
}

function send(message) { if (transport) transport.send(JSON.stringify(message)); }

function showConnection(state) {
  const label = document.getElementById("connection");
  label.textContent = state === "open" ? "connected" : "disconnected";
  label.className = "state " + state;
}

// ---- messages in -----------------------------------------------------------------------------

function receive(text) {
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
  turntable: false, table: null, paper: null, arm: null, tableRadius: null };

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
  drawing.tableRadius = null;
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
  // A turntable: the table seen from above, the paper on it turned by the table's angle (the
  // drawing in paper mm inside), the radial arm fixed along +x from the centre.
  let paper = drawing.layer;
  drawing.turntable = machine.kind === "polar";
  if (drawing.turntable) {
    drawing.table = svgElement("circle", { cx: 0, cy: 0, r: 10, fill: "#f4efe4", stroke: "#bbb", "stroke-width": 0.5, id: "turntable" }, drawing.layer);
    paper = drawing.paper = svgElement("g", { id: "paper", transform: "rotate(0)" }, drawing.layer);
    svgElement("line", { x1: -3, y1: 0, x2: 3, y2: 0, stroke: "#bbb", "stroke-width": 0.4 }, paper);  // the paper's own axes,
    svgElement("line", { x1: 0, y1: -3, x2: 0, y2: 3, stroke: "#bbb", "stroke-width": 0.4 }, paper);  // to see it turn
  }
  drawing.strokes = svgElement("g", { stroke: "black", "stroke-width": machine.pen_width_mm, id: "strokes" }, paper);
  if (drawing.turntable) drawing.arm = svgElement("line", { x1: 0, y1: 0, x2: 0, y2: 0, stroke: "#666", "stroke-width": 1.5, "stroke-linecap": "round", id: "arm" }, drawing.layer);
  drawing.pen = svgElement("circle", { r: 2, id: "pen", class: "up", "stroke-width": 0.4, stroke: "#c22", fill: "none" }, paper);
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
  const pieces = shades.length === 0 || !view.shadeScale ? [{ points, colour: null }]
    : shades.map(([from, shade], j) => ({
      points: points.slice(from, j + 1 < shades.length ? shades[j + 1][0] + 1 : points.length),
      colour: shadeColour(shade, view.shadeScale),
    }));
  while (group.children.length > pieces.length) group.lastChild.remove();
  while (group.children.length < pieces.length) svgElement("polyline", {}, group);
  pieces.forEach((piece, j) => {
    const line = group.children[j];
    line.setAttribute("points", pointsText(piece.points));
    if (piece.colour) line.setAttribute("stroke", piece.colour); else line.removeAttribute("stroke");
  });
}

function applyStrokes(parts, shadeScale) {
  const scaleChanged = JSON.stringify(shadeScale || null) !== JSON.stringify(view.shadeScale);
  view.shadeScale = shadeScale || null;
  const changed = new Set();
  for (const part of parts) {
    while (view.strokes.length <= part.i) {
      view.strokes.push([]);
      view.shades.push([]);
      drawing.lines.push(svgElement("g", { class: "stroke" }, drawing.strokes));
    }
    const stroke = view.strokes[part.i];
    stroke.length = part.from;
    for (const point of part.points) stroke.push(point);
    view.shades[part.i] = view.shades[part.i].filter(([from]) => from < part.from).concat(part.shades || []);
    changed.add(part.i);
  }
  if (scaleChanged) view.shades.forEach((shades, i) => { if (shades.length > 0) changed.add(i); });
  for (const i of changed) renderStroke(i);
  if (!drawing.fixedPage && parts.length > 0) fitToDrawing();
}

/// A machine without a fixed page: the view follows the drawing's bounding box (a turntable's:
/// the circle around the centre holding the drawing and the arm).
function fitToDrawing() {
  if (drawing.turntable) return fitTable();
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const stroke of view.strokes) for (const [x, y] of stroke) {
    x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
  }
  if (!(x0 <= x1)) return;
  const margin = view.hello.machine.margin_mm;
  drawing.svg.setAttribute("viewBox", `${x0 - margin} ${y0 - margin} ${Math.max(x1 - x0, 10) + 2 * margin} ${Math.max(y1 - y0, 10) + 2 * margin}`);
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
  view.pen = pen;
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

const boards = new Map();  // name → {console, figures, faults}

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
  setUpDrawing(hello.machine);
  const container = document.getElementById("boards");
  container.replaceChildren();
  boards.clear();
  for (const board of hello.boards) boards.set(board.name, buildBoard(board, container));
  showRun(hello.run);
}

function buildBoard(board, container) {
  const box = element("section", { class: "board", id: `board-${board.name}` }, container);
  element("h2", {}, box, `${board.name} (${board.module})`);
  const devices = element("div", { class: "devices" }, box);
  const screens = new Map();
  for (const device of board.devices) {
    const holder = element("div", { class: "device" }, devices);
    const control = device.control;
    if (control.type === "knob" || control.type === "knob_with_button") addKnob(holder, device);
    if (control.type === "knob_with_button" || control.type === "button") addButton(holder, device);
    if (control.type === "slider") addSlider(holder, device);
    if (control.type === "screen") screens.set(device.name, element("canvas", { class: "screen", width: 128, height: 32, id: `screen-${device.name}` }, holder));
    if (device.kind === "five_bar_arm") addArm(holder, device);
    element("label", {}, holder, `${device.name} · ${device.connector}`);
  }
  const figures = element("table", { class: "figures" }, box);
  const faults = element("p", { class: "fault", hidden: "" }, box);
  const consoleText = element("pre", { class: "console", id: `console-${board.name}` }, box);
  const line = element("form", { class: "console-line" }, box);
  const input = element("input", { type: "text", placeholder: "a line for the sketch", id: `send-${board.name}` }, line);
  element("button", { type: "submit" }, line, "Send");
  line.addEventListener("submit", (event) => {
    event.preventDefault();
    send({ type: "console", board: board.name, text: input.value + "\n" });
    input.value = "";
  });
  return { figures, faults, console: consoleText, screens };
}

/// An endless knob: dragged around its centre (clockwise = positive counts, one turn of the hand
/// = the device's counts per turn) or scrolled (a 24th of a turn a notch).
function addKnob(holder, device) {
  const knob = element("div", { class: "knob", id: `control-${device.name}`, role: "slider", "aria-label": device.name }, holder);
  const mark = element("div", { class: "mark" }, knob);
  const perTurn = device.control.counts_per_turn || 24;
  let angle = 0, sent = 0, last = null;
  const show = () => { mark.style.transform = `rotate(${angle}rad)`; };
  const flush = () => {
    const target = Math.round(angle / (2 * Math.PI) * perTurn);
    if (target !== sent) send({ type: "input", device: device.name, action: "turn", counts: target - sent });
    sent = target;
  };
  const angleAt = (event) => {
    const box = knob.getBoundingClientRect();
    return Math.atan2(event.clientY - (box.top + box.height / 2), event.clientX - (box.left + box.width / 2));
  };
  knob.addEventListener("pointerdown", (event) => { knob.setPointerCapture(event.pointerId); last = angleAt(event); event.preventDefault(); });
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
  knob.addEventListener("wheel", (event) => {
    event.preventDefault();
    angle += (event.deltaY < 0 ? 1 : -1) * 2 * Math.PI / 24;
    show();
    flush();
  });
}

/// A momentary button: held while the pointer is down (at least SHORTEST_PRESS_MS).
function addButton(holder, device) {
  const button = element("button", { type: "button", class: "press", id: `control-${device.name}${device.control.type === "knob_with_button" ? "-button" : ""}`, "aria-label": device.name }, holder);
  let pressedAt = null;
  const release = () => {
    if (pressedAt === null) return;
    const held = performance.now() - pressedAt;
    pressedAt = null;
    setTimeout(() => { send({ type: "input", device: device.name, action: "release" }); button.classList.remove("down"); },
               Math.max(0, SHORTEST_PRESS_MS - held));
  };
  button.addEventListener("pointerdown", (event) => {
    button.setPointerCapture(event.pointerId);
    pressedAt = performance.now();
    button.classList.add("down");
    send({ type: "input", device: device.name, action: "press" });
  });
  button.addEventListener("pointerup", release);
  button.addEventListener("pointercancel", release);
}

/// A five-bar arm (the pantograph): its linkage from above, as the updates' "arms" give it.
function addArm(holder, device) {
  const svg = svgElement("svg", { class: "arm", id: `arm-${device.name}`, width: 160, height: 160, viewBox: "-100 -20 200 260" }, holder);
  const style = { fill: "none", stroke: "#555", "stroke-width": 3, "stroke-linejoin": "round", "stroke-linecap": "round" };
  svgElement("polyline", { ...style, class: "right-side" }, svg);  // right pivot, C, E, stylus T
  svgElement("polyline", { ...style, class: "left-side" }, svg);   // left pivot, D, E
  svgElement("circle", { r: 4, fill: "#c22", class: "stylus" }, svg);
}

function showArms(arms) {
  for (const arm of arms) {
    const svg = document.getElementById(`arm-${arm.device}`);
    if (!svg) continue;
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
  view.arms = arms;
}

function addSlider(holder, device) {
  const c = device.control;
  const slider = element("input", { type: "range", min: c.low, max: c.high, step: c.step, id: `control-${device.name}` }, holder);
  slider.addEventListener("input", () => send({ type: "input", device: device.name, action: "set", position: Number(slider.value) }));
}

function showBoards(update) {
  for (const state of update.boards || []) {
    const board = boards.get(state.name);
    if (!board) continue;
    const rows = [["frames", state.frames]];
    if (state.load_average_percent !== null) rows.push(["frame load", `${state.load_average_percent.toFixed(1)} % (peak ${state.load_peak_percent.toFixed(1)} %)`]);
    for (const motor of update.motors.filter((m) => m.board === state.name)) {
      rows.push([`motor ${motor.port}`, `${motor.steps} steps, ${Math.round(motor.rate_steps_per_s)} steps/s`]);
    }
    for (const warning of state.warnings || []) rows.push([`warning ${warning.name}`, `×${warning.count} ${warning.detail}`]);
    board.figures.replaceChildren(...rows.map(([name, value]) => {
      const row = document.createElement("tr");
      element("th", {}, row, name);
      element("td", { "data-figure": name }, row, String(value));
      return row;
    }));
    board.faults.hidden = !state.fault;
    if (state.fault) board.faults.textContent = `fault: ${state.fault.reason} ×${state.fault.count} ${state.fault.detail}`;
  }
  for (const output of update.console || []) {
    const board = boards.get(output.board);
    if (!board) continue;
    board.console.textContent = (board.console.textContent + output.text).slice(-20000);
    board.console.scrollTop = board.console.scrollHeight;
  }
  for (const screen of update.screens || []) {
    for (const board of boards.values()) {
      const canvas = board.screens.get(screen.device);
      if (canvas) drawScreen(canvas, screen);
    }
  }
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

// ---- run control -----------------------------------------------------------------------------

function showRun(run) {
  document.getElementById("pause").hidden = run.paused;
  document.getElementById("resume").hidden = !run.paused;
  for (const button of document.querySelectorAll(".speed")) {
    const speed = button.dataset.speed === "max" ? 0 : Number(button.dataset.speed);
    button.classList.toggle("active", speed === run.speed);
  }
}

document.getElementById("pause").addEventListener("click", () => send({ type: "run", action: "pause" }));
document.getElementById("resume").addEventListener("click", () => send({ type: "run", action: "resume" }));
for (const button of document.querySelectorAll(".speed")) {
  button.addEventListener("click", () => send({ type: "run", action: "speed", speed: button.dataset.speed === "max" ? "max" : Number(button.dataset.speed) }));
}
document.getElementById("save").addEventListener("click", () => send({ type: "save" }));

function download(svg) {
  const link = document.createElement("a");
  link.href = URL.createObjectURL(new Blob([svg], { type: "image/svg+xml" }));
  link.download = "drawing.svg";
  link.click();
  setTimeout(() => URL.revokeObjectURL(link.href), 1000);
}

function onUpdate(update) {
  view.updates += 1;
  view.t_s = update.t_s;
  document.getElementById("sim-time").textContent = `t = ${update.t_s.toFixed(3)} s`;
  if (update.strokes) applyStrokes(update.strokes, update.shade_scale);
  if (update.pen) showPen(update.pen);
  if (update.table && drawing.turntable) showTable(update.table);
  if (update.arms) showArms(update.arms);
  view.motors = update.motors;
  showBoards(update);
  showRun(update.run);
}

connect();
