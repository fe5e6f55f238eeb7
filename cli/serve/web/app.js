// The Stepdance control page: controls built from the board's __index__ (and __describe__, when
// the board has it), calls over the bridge's WebSocket, a live view of a simulated drawing.
"use strict";

const socket = new WebSocket(`ws://${location.host}/ws`);
const pending = new Map();  // this tab's request id → resolve
let nextId = 1;
const $ = (id) => document.getElementById(id);

/** Sends one request; resolves with the board's (or the bridge's) reply object. */
function call(name, args) {
  const id = nextId++;
  const request = args === undefined ? { name, id } : { name, args, id };
  socket.send(JSON.stringify(request));
  return new Promise((resolve) => pending.set(id, resolve));
}
window.stepdance = { call };

function show(output, reply) {
  const ok = reply.result === "ok";
  output.classList.toggle("error", !ok);
  output.value = ok ? ("return" in reply ? JSON.stringify(reply.return) : "ok") : `error ${reply.code}: ${reply.error}`;
}

function log(text) {
  const item = document.createElement("li");
  item.textContent = text;
  const list = $("log");
  list.append(item);
  while (list.children.length > 200) list.firstChild.remove();
  list.scrollTop = list.scrollHeight;
}

// ---- controls ---------------------------------------------------------------------------------

const kArgTypes = { n: "number", i: "integer", b: "boolean", s: "string" };

function element(tag, props = {}, ...children) {
  const node = Object.assign(document.createElement(tag), props);
  node.append(...children);
  return node;
}

function argInput(name, letter, index) {
  const label = `${name} argument ${index + 1} (${kArgTypes[letter] || "value"})`;
  if (letter === "b") return element("input", { type: "checkbox", className: "arg", title: label, ariaLabel: label });
  if (letter === "s") return element("input", { type: "text", className: "arg", placeholder: "text", ariaLabel: label });
  return element("input", { type: "number", step: "any", className: "arg", placeholder: kArgTypes[letter] || "number",
                            ariaLabel: label });
}

function argValue(input) {
  if (input.type === "checkbox") return input.checked;
  if (input.type === "text") return input.value;
  if (input.value.trim() === "") throw new Error("fill in every argument");
  return Number(input.value);
}

function functionControl(name, signature) {
  const row = element("div", { className: "control" }, element("span", { className: "name" }, name));
  row.dataset.name = name;
  row.dataset.kind = "function";
  const inputs = [];
  if (signature) {
    [...signature.args].forEach((letter, i) => inputs.push(argInput(name, letter, i)));
  } else {
    inputs.push(element("input", { type: "text", className: "args-json", placeholder: "[arguments]", ariaLabel: `${name} arguments as JSON` }));
  }
  const button = element("button", { type: "button" }, "call");
  button.dataset.call = name;
  const output = element("output", { className: "result" });
  row.append(...inputs, button, output);
  button.addEventListener("click", async () => {
    let args;
    try {
      args = signature ? inputs.map(argValue) : (inputs[0].value.trim() ? JSON.parse(inputs[0].value) : undefined);
    } catch (error) {
      output.classList.add("error");
      output.value = error.message;
      return;
    }
    show(output, await call(name, signature && args.length === 0 ? undefined : args));
  });
  if (signature && signature.args === "" && "nib".includes(signature.returns) && isReader(name)) addWatch(row, name, output);
  return row;
}

/** Whether reading `name` looks free of side effects: a port's read, an is_… or get_… query. */
function isReader(name) {
  const last = name.slice(name.lastIndexOf(".") + 1);
  return /^(read|read_deep)$/.test(last) || /^(is|get)_/.test(last);
}

/** A "watch" box on a reader: while ticked, the value is read four times a second. */
const watched = new Map();  // name → output
function addWatch(row, name, output) {
  const box = element("input", { type: "checkbox", ariaLabel: `watch ${name}` });
  box.addEventListener("change", () => (box.checked ? watched.set(name, output) : watched.delete(name)));
  row.append(element("label", {}, box, " watch"));
  $("watch-note").hidden = false;
}
setInterval(() => {
  if (socket.readyState !== WebSocket.OPEN) return;
  for (const [name, output] of watched) if (!output.dataset.busy) {
    output.dataset.busy = "1";
    call(name).then((reply) => { delete output.dataset.busy; show(output, reply); updateReadout(name, reply); });
  }
}, 250);

function niceRange(value) {
  const magnitude = Math.max(1, Math.abs(value) * 2);
  const step = Math.pow(10, Math.floor(Math.log10(magnitude)));
  return Math.ceil(magnitude / step) * step;
}

function parameterControl(name, type) {
  const row = element("div", { className: "control" }, element("span", { className: "name" }, name));
  row.dataset.name = name;
  row.dataset.kind = "parameter";
  const slider = element("input", { type: "range", ariaLabel: `${name} slider` });
  const field = element("input", { type: "number", step: "any", ariaLabel: `${name} value` });
  const set = element("button", { type: "button" }, "set");
  set.dataset.set = name;
  const read = element("button", { type: "button" }, "read");
  const output = element("output", { className: "result" });
  row.append(slider, field, set, read, output);
  let sending = false;
  let latest = null;  // the slider's value waiting for the previous write's reply
  const write = async (value) => {
    if (sending) { latest = value; return; }
    sending = true;
    show(output, await call(name, [type === "b" ? value !== 0 : value]));
    sending = false;
    if (latest !== null) { const next = latest; latest = null; write(next); }
  };
  const refresh = async () => {
    const reply = await call(name);
    show(output, reply);
    if (reply.result !== "ok" || typeof reply.return !== "number") return;
    field.value = reply.return;
    const range = niceRange(reply.return);
    Object.assign(slider, { min: reply.return < 0 || type === "i" ? -range : 0, max: range, step: type === "i" ? 1 : range / 200 });
    slider.value = reply.return;
  };
  slider.addEventListener("input", () => { field.value = slider.value; write(Number(slider.value)); });
  set.addEventListener("click", () => field.value.trim() !== "" && write(Number(field.value)));
  read.addEventListener("click", refresh);
  refresh();
  return row;
}

function parseSignature(text) {
  // "function nnn i" / "function - v" / "parameter n" (see RPC's __describe__)
  if (typeof text !== "string") return null;
  const [kind, args, returns] = text.split(" ");
  return kind === "function" ? { args: args === "-" ? "" : args, returns } : { type: args };
}

function buildControls(index, described) {
  const controls = $("controls");
  controls.replaceChildren();
  const groups = new Map();
  for (const [name, kind] of Object.entries(index)) {
    const signature = described ? parseSignature(described[name]) : null;
    const row = kind === "parameter" ? parameterControl(name, signature && signature.type) : functionControl(name, signature);
    const dot = name.indexOf(".");
    if (dot < 0) { controls.append(row); continue; }
    const prefix = name.slice(0, dot);
    if (!groups.has(prefix)) {
      const group = element("details", {}, element("summary", {}, prefix));
      groups.set(prefix, group);
      controls.append(group);
    }
    groups.get(prefix).append(row);
  }
  $("empty").hidden = Object.keys(index).length > 0;
  if (!$("empty").hidden) $("empty").textContent = "The sketch enrolls no names.";
  // A real board: follow the first planner-like x/y outputs as the position readout.
  for (const axis of ["x", "y"]) {
    const reader = Object.keys(index).find((n) => n.endsWith(`output_${axis}.read`));
    const row = reader && document.querySelector(`.control[data-name="${reader}"] input[type=checkbox]`);
    if (row && !simulated) { row.checked = true; row.dispatchEvent(new Event("change")); }
  }
}

function updateReadout(name, reply) {
  if (simulated || reply.result !== "ok") return;
  if (name.endsWith("output_x.read")) $("pen-x").value = Number(reply.return).toFixed(2);
  if (name.endsWith("output_y.read")) $("pen-y").value = Number(reply.return).toFixed(2);
}

// ---- the simulated drawing --------------------------------------------------------------------

let simulated = false;
let area = null;  // [x_min, x_max, y_min, y_max] mm, from the machine, else from the drawing
const strokes = [];
let pen = null;
let penDown = false;
let redrawQueued = false;

function applyDrawing(update) {
  for (const chunk of update.strokes) {
    const stroke = strokes[chunk.index] || (strokes[chunk.index] = []);
    stroke.length = Math.min(stroke.length, chunk.from);
    stroke.push(...chunk.points);
  }
  pen = update.pen;
  penDown = update.down;
  $("pen-x").value = pen[0].toFixed(2);
  $("pen-y").value = pen[1].toFixed(2);
  $("pen-state").value = penDown ? "pen down" : "pen up";
  $("sim-time").value = `t = ${update.t.toFixed(1)} s`;
  if (!redrawQueued) { redrawQueued = true; requestAnimationFrame(redraw); }
}

function bounds() {
  if (area) return area;
  const b = [0, 100, 0, 100];
  for (const stroke of strokes) for (const [x, y] of stroke || []) {
    b[0] = Math.min(b[0], x); b[1] = Math.max(b[1], x); b[2] = Math.min(b[2], y); b[3] = Math.max(b[3], y);
  }
  return b;
}

function redraw() {
  redrawQueued = false;
  const canvas = $("drawing");
  const context = canvas.getContext("2d");
  const [x0, x1, y0, y1] = bounds();
  const margin = 10;
  const scale = Math.min((canvas.width - 2 * margin) / (x1 - x0), (canvas.height - 2 * margin) / (y1 - y0));
  const at = ([x, y]) => [margin + (x - x0) * scale, margin + (y - y0) * scale];
  context.clearRect(0, 0, canvas.width, canvas.height);
  context.strokeStyle = "#eee";
  context.strokeRect(...at([x0, y0]), (x1 - x0) * scale, (y1 - y0) * scale);
  context.strokeStyle = "#123";
  context.lineWidth = 1.5;
  for (const stroke of strokes) {
    if (!stroke || stroke.length === 0) continue;
    context.beginPath();
    context.moveTo(...at(stroke[0]));
    for (const point of stroke) context.lineTo(...at(point));
    context.stroke();
  }
  if (pen) {
    context.beginPath();
    context.arc(...at(pen), 4, 0, 2 * Math.PI);
    context.fillStyle = penDown ? "#d32" : "#fff";
    context.fill();
    context.strokeStyle = "#d32";
    context.stroke();
  }
}

// ---- the connection ---------------------------------------------------------------------------

socket.addEventListener("open", async () => {
  $("connection").textContent = "connected";
  $("connection").className = "state open";
  const index = await call("__index__");
  if (index.result !== "ok") { $("empty").textContent = `The board did not list its names: ${index.error}`; return; }
  const described = await call("__describe__");  // older boards answer "unknown name": plain fields then
  buildControls(index.return, described.result === "ok" ? described.return : null);
});

socket.addEventListener("close", () => {
  $("connection").textContent = "disconnected";
  $("connection").className = "state closed";
});

socket.addEventListener("message", (event) => {
  const message = JSON.parse(event.data);
  if ("result" in message && pending.has(message.id)) {
    pending.get(message.id)(message);
    pending.delete(message.id);
  } else if (message.drawing) {
    applyDrawing(message.drawing);
  } else if (message.hello) {
    $("board").textContent = `— ${message.hello.board}`;
    simulated = message.hello.simulated;
    $("drawing").hidden = !simulated;
    if (message.hello.machine && message.hello.machine.area_mm) area = message.hello.machine.area_mm;
  } else if (message.bridge) {
    const b = message.bridge;
    $("bridge").textContent = `${b.forwarded} requests, ${b.dropped + b.messages_dropped} dropped, ${b.timed_out} unanswered`;
  } else if (message.ended) {
    log(`the simulated board's run ended:\n${message.ended.text}`);  // a crash, exit(), a hang
  } else if ("console" in message) {
    log(message.console);
  } else {
    log(event.data);  // an event, or a reply this tab did not ask for
  }
});
