// StepdanceSim: the JavaScript API of the WebAssembly simulator, for a Web Worker or node.
//
//   const sim = await StepdanceSim.create(createStepdanceModule);   // stepdance_web.js
//   sim.writeFile('/examples/StepASketch/scenario.toml', text);      // and the files it reads
//   for (const name of sim.sketches(path, text)) sim.addBoard(name, boardBytes[name]);
//   const errors = sim.open(path, text);                              // '' when it loaded
//   sim.hello(); sim.runUntil(1.0); sim.update(performance.now() / 1000); sim.receive(message);
//   const result = sim.finish();   // the run's result, as `stepdance sim --result-json` writes it
//
// The view protocol's messages (hello, update, receive) are the live command line's, made by the
// same C++ class (sim/view/ViewSession), so a page cannot tell a Worker from a WebSocket.
(function (root) {
  'use strict';

  class StepdanceSim {
    /// Instantiates the module (`createModule` is stepdance_web.js's factory).
    static async create(createModule, moduleOptions = {}) {
      return new StepdanceSim(await createModule(moduleOptions));
    }

    constructor(module) {
      this.module = module;
      const text = (name, args) => module.cwrap(name, 'string', args);
      this.c = {
        addBoard: module.cwrap('stepdance_web_add_board', null, ['string', 'string']),
        sketches: text('stepdance_web_sketches', ['string', 'string']),
        open: text('stepdance_web_open', ['string', 'string']),
        runUntil: module.cwrap('stepdance_web_run_until', 'number', ['number']),
        state: text('stepdance_web_state', []),
        finish: text('stepdance_web_finish', []),
        hello: text('stepdance_web_hello', []),
        update: text('stepdance_web_update', ['number']),
        updateNow: text('stepdance_web_update_now', []),
        receive: text('stepdance_web_receive', ['string']),
        close: module.cwrap('stepdance_web_close', null, []),
      };
    }

    /// Writes a file (string or Uint8Array) into the module's file system, making its folders.
    writeFile(path, data) {
      const folder = path.substring(0, path.lastIndexOf('/'));
      if (folder) this.module.FS.mkdirTree(folder);
      this.module.FS.writeFile(path, data);
    }

    /// Registers a precompiled board (the bytes of boards/<folderName>.wasm) for sketches in
    /// folders named `folderName`.
    addBoard(folderName, wasmBytes) {
      const path = `/boards/${folderName}.wasm`;
      this.writeFile(path, wasmBytes);
      this.c.addBoard(folderName, path);
    }

    /// The sketch folder names the scenario runs (fetch their boards before open()); throws
    /// with the reader's errors when it does not read.
    sketches(path, text) {
      const answer = JSON.parse(this.c.sketches(path, text));
      if (!Array.isArray(answer)) throw new Error(answer.error);
      return answer;
    }

    /// Loads scenario `text` as the file `path` and builds the run; '' on success, else the
    /// reader's or the simulation's errors (`file:line: message` lines).
    open(path, text) { return this.c.open(path, text); }
    /// Runs to `seconds` of simulated time; returns the time reached.
    runUntil(seconds) { return this.c.runUntil(seconds); }
    /// {now_s, duration_s, done, paused, speed} of the run (paused and speed: what the page asked).
    state() { return JSON.parse(this.c.state()); }
    /// Runs to the end; the run's result {summary, expectations, stopped}.
    finish() { return JSON.parse(this.c.finish()); }
    /// The result as text, byte for byte what `stepdance sim --result-json` writes.
    finishText() { return this.c.finish(); }
    /// The view protocol's hello message (text).
    hello() { return this.c.hello(); }
    /// The update due at wall time `wallSeconds`, or null if none is due yet.
    update(wallSeconds) { return this.c.update(wallSeconds) || null; }
    updateNow() { return this.c.updateNow(); }
    /// A page's message; the replies (texts).
    receive(message) { return JSON.parse(this.c.receive(message)); }
    close() { this.c.close(); }
  }

  if (typeof module === 'object' && module.exports) module.exports = { StepdanceSim };
  else root.StepdanceSim = StepdanceSim;
})(typeof self !== 'undefined' ? self : globalThis);
