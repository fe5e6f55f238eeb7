// The replay page's transport (`stepdance sim --html`): the view page fed from a recording of a
// run, instant by instant, under a time slider, with the devices' inputs and a logic-analyser
// strip of the output ports. The page itself (app.js) draws as it does live; nothing here draws
// the machine. The recording's format is in docs/simulator.md, "The replay page".
"use strict";

(() => {
  const recording = JSON.parse(document.getElementById("stepdance-replay").textContent);
  const samples = recording.samples;
  const replay = (window.stepdanceReplay = { recording, count: samples.length, index: -1, seek: null });
  const SVG_NS = "http://www.w3.org/2000/svg";
  const SIGNALS = "XYRTZE";  // a STEP pulse of 2 µs is X, 3 µs Y, … 7 µs E

  let deliver = null;  // the page's onMessage
  let shown = -1;      // the last sample the page has been given

  window.stepdanceTransport = (onMessage, onState) => {
    deliver = (message) => onMessage(JSON.stringify(message));
    // The page is ready for messages once app.js asks for its transport.
    setTimeout(() => {
      onState("open");
      buildControls();
      seek(samples.length - 1);
    }, 0);
    // A replay takes no inputs (the knobs show what the run had); the page draws each message as
    // it is delivered (immediate), since seek() reads the page right after.
    return { send: () => {}, immediate: true, label: "replay" };
  };

  if (recording.format !== "stepdance-replay" || recording.version !== 2) {
    throw new Error(`not a replay this page reads (format ${recording.format}, version ${recording.version})`);
  }

  function element(tag, attributes = {}, parent = null, text = "") {
    const node = document.createElement(tag);
    for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
    if (text) node.textContent = text;
    if (parent) parent.appendChild(node);
    return node;
  }

  function svgElement(name, attributes, parent) {
    const node = document.createElementNS(SVG_NS, name);
    for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
    if (parent) parent.appendChild(node);
    return node;
  }

  // ---- the slider ------------------------------------------------------------------------------

  let slider, timeLabel, inputsTable, strip, playButton, timer = null;

  function buildControls() {
    document.title = "Stepdance replay";
    document.querySelector("header h1").textContent = "Stepdance replay";
    document.getElementById("connection").textContent = "replay";
    document.getElementById("run-controls").hidden = true;
    document.body.classList.add("replay");  // style.css: no console line to send
    const bar = element("section", { id: "replay", "aria-label": "Replay" });
    document.querySelector("header").after(bar);
    playButton = element("button", { type: "button", id: "replay-play" }, bar, "Play");
    slider = element("input", { type: "range", id: "replay-slider", min: 0, max: samples.length - 1, step: 1,
                                value: samples.length - 1, "aria-label": "Time" }, bar);
    timeLabel = element("output", { id: "replay-time" }, bar);
    const note = element("p", { id: "replay-note" }, bar);
    note.textContent = `${recording.scenario.split("/").slice(-2).join("/")}: ${samples.length} instants, one every ${(recording.interval_s * 1000).toFixed(1)} ms ` +
      `of the run's ${recording.duration_s.toFixed(3)} s.` + (recording.complete ? "" : ` ${recording.note}.`) +
      (recording.wire.frames_not_kept > 0 ? ` The wire strip keeps ${recording.wire.max_frames_per_window} frames a port ` +
        `per instant: ${recording.wire.frames_not_kept} more were not kept.` : "");
    if (!recording.complete) note.classList.add("fault");
    slider.addEventListener("input", () => { stop(); seek(Number(slider.value)); });
    playButton.addEventListener("click", () => (timer ? stop() : play()));

    const machine = document.getElementById("machine");
    const wire = element("section", { id: "wire", "aria-label": "The wire" }, machine);
    element("h2", {}, wire, `The wire around the instant (±${recording.wire.window_ns / 2000} µs); STEP pulse width → signal: ` +
      Object.entries(recording.wire.pulse_widths_us).sort((a, b) => a[1] - b[1]).map(([name, us]) => `${name} ${us} µs`).join(", "));
    strip = svgElement("svg", { id: "wire-strip", xmlns: SVG_NS }, wire);
    inputsTable = element("table", { id: "replay-inputs", class: "figures" }, bar);
  }

  function play() {
    if (shown >= samples.length - 1) seek(0);
    playButton.textContent = "Pause";
    timer = setInterval(() => {
      if (shown >= samples.length - 1) return stop();
      seek(shown + 1);
    }, Math.max(16, recording.interval_s * 1000));
  }

  function stop() {
    if (timer) clearInterval(timer);
    timer = null;
    playButton.textContent = "Play";
  }

  /// Shows instant `index`: the page gets the messages up to it (from hello again when going back).
  function seek(index) {
    index = Math.max(0, Math.min(samples.length - 1, index));
    if (index < shown || shown < 0) {
      deliver(recording.hello);
      shown = -1;
    }
    for (let i = shown + 1; i <= index; ++i) deliver(samples[i].update);
    shown = index;
    replay.index = index;
    slider.value = index;
    const sample = samples[index];
    timeLabel.textContent = `t = ${sample.update.t_s.toFixed(3)} s`;
    showInputs(sample.inputs || {});
    drawWire(sample);
  }
  replay.seek = seek;

  // ---- the devices' inputs ---------------------------------------------------------------------

  function devices() {
    return recording.hello.boards.flatMap((board) => board.devices);
  }

  function showInputs(inputs) {
    inputsTable.replaceChildren();
    for (const device of devices()) {
      const state = inputs[device.name];
      if (!state) continue;
      for (const [key, value] of Object.entries(state)) {
        const row = element("tr", {}, inputsTable);
        element("th", {}, row, `${device.name} ${key}`);
        const text = typeof value === "boolean" ? (value ? "yes" : "no") : String(Math.round(value * 1000) / 1000);
        element("td", { "data-device": device.name, "data-input": key }, row, text);
      }
      const control = device.control;
      if ("counts" in state && (control.type === "knob" || control.type === "knob_with_button")) {
        const mark = document.querySelector(`#control-${device.name} .mark`);
        const turns = state.counts / (control.counts_per_turn || 24);
        if (mark) mark.style.transform = `rotate(${turns * 2 * Math.PI}rad)`;
      }
      if ("pressed" in state) {
        const id = control.type === "knob_with_button" ? `control-${device.name}-button` : `control-${device.name}`;
        const button = document.getElementById(id);
        if (button) button.classList.toggle("down", state.pressed);
      }
    }
  }

  // ---- the logic-analyser strip ----------------------------------------------------------------

  const STRIP = { left: 110, width: 800, row: 20, high: 10 };

  /// Each port's STEP and DIR around the instant; each STEP pulse labelled with its signal.
  function drawWire(sample) {
    const ports = recording.wire.ports;
    const span = recording.wire.window_ns;
    const height = ports.length * 2 * STRIP.row + 18;
    strip.setAttribute("viewBox", `0 0 ${STRIP.left + STRIP.width + 10} ${height}`);
    strip.replaceChildren();
    const x = (ns) => STRIP.left + ((ns + span / 2) / span) * STRIP.width;
    const byPort = ports.map(() => []);
    for (const [port, offset, step, dir] of sample.wire || []) byPort[port].push({ offset, step, dir });
    ports.forEach((name, p) => {
      const frames = byPort[p].sort((a, b) => a.offset - b.offset);
      drawLine(`${name} STEP`, 2 * p, frames.map((f) => [f.offset, f.step]), x, true);
      drawLine(`${name} DIR`, 2 * p + 1, frames.map((f) => [f.offset, f.dir]), x, false);
    });
    const axis = ports.length * 2 * STRIP.row + 12;
    for (const [ns, text] of [[-span / 2, `−${span / 2000} µs`], [0, "instant"], [span / 2, `+${span / 2000} µs`]]) {
      svgElement("text", { x: x(ns), y: axis, "font-size": 9, "text-anchor": ns < 0 ? "start" : ns > 0 ? "end" : "middle" }, strip)
        .textContent = text;
    }
    svgElement("line", { x1: x(0), x2: x(0), y1: 0, y2: axis - 9, stroke: "#c22", "stroke-width": 0.8 }, strip);
  }

  /// One line: `words` are [offset ns, 32 bits a µs each from the offset] in time order.
  function drawLine(label, rowIndex, words, x, labelPulses) {
    const low = rowIndex * STRIP.row + STRIP.row - 3;
    const high = low - STRIP.high;
    svgElement("text", { x: 2, y: low, "font-size": 9 }, strip).textContent = label;
    let path = `M ${STRIP.left} ${low}`;
    for (const [offset, bits] of words) {
      for (let bit = 0; bit < 32; ) {
        if (!((bits >>> bit) & 1)) { ++bit; continue; }
        let end = bit;
        while (end < 32 && (bits >>> end) & 1) ++end;
        const rise = offset + bit * 1000, fall = offset + end * 1000;
        path += ` H ${x(rise)} V ${high} H ${x(fall)} V ${low}`;
        if (labelPulses) {
          const width = end - bit;
          const name = SIGNALS[width - 2] || "?";
          const text = svgElement("text", { x: x(rise), y: high - 1, "font-size": 8, "text-anchor": "start",
                                            class: "pulse", "data-width-us": width, "data-signal": name }, strip);
          text.textContent = `${name} ${width} µs`;
          svgElement("title", {}, text).textContent = `${width} µs: ${name}`;
        }
        bit = end;
      }
    }
    path += ` H ${STRIP.left + STRIP.width}`;
    svgElement("path", { d: path, fill: "none", stroke: "#222", "stroke-width": 0.8, class: "wire-line" }, strip);
  }
})();
