// The boards' frames call their own functions without going through JavaScript
// (wasm/bind_own_imports.js). Seen from outside: emscripten's stubs call the function they
// found with Function.prototype.apply, so this counts apply calls on WebAssembly functions
// while Step-A-Sketch runs its first simulated second under node. Without the binding its
// vtables reach OutputPort::run 3 times and Encoder::run twice a frame through a stub: 125,000
// calls a simulated second at 25,000 frames a second. With it, the calls left are the few
// direct ones made outside the frame (a handful a run).
//
//   node --no-experimental-fetch tests/web/own_imports_test.js SITE SOURCE_DIR
'use strict';
const assert = require('assert');
const fs = require('fs');
const path = require('path');

const MOST_STUB_CALLS_PER_SIMULATED_S = 1000;

async function main() {
  const [site, source] = process.argv.slice(2).map((arg) => path.resolve(arg));
  const createModule = require(path.join(site, 'stepdance_web.js'));
  const { StepdanceSim } = require(path.join(site, 'stepdance_sim.js'));
  const sim = await StepdanceSim.create(createModule, { print: () => {}, printErr: () => {} });
  const folder = path.join(source, 'examples', 'StepASketch');
  for (const file of fs.readdirSync(folder)) sim.writeFile(path.join(folder, file), fs.readFileSync(path.join(folder, file)));
  const scenario = path.join(folder, 'scenario.toml');
  const text = fs.readFileSync(scenario, 'utf8');
  for (const name of sim.sketches(scenario, text)) sim.addBoard(name, fs.readFileSync(path.join(site, 'boards', `${name}.wasm`)));
  assert.strictEqual(sim.open(scenario, text), '');

  const apply = Function.prototype.apply;
  let wasmCalls = 0;
  Function.prototype.apply = function (...args) { // eslint-disable-line no-extend-native
    if (/\[native code\]/.test(Function.prototype.toString.call(this)) && /^\d+$/.test(this.name)) ++wasmCalls;
    return Reflect.apply(this, args[0], args[1] || []);
  };
  const reached_s = sim.runUntil(1.0);
  Function.prototype.apply = apply;

  assert.strictEqual(reached_s, 1.0);
  console.log(`WebAssembly functions called through apply in ${reached_s} simulated s: ${wasmCalls}`);
  assert.ok(wasmCalls <= MOST_STUB_CALLS_PER_SIMULATED_S * reached_s,
            `${wasmCalls} calls through JavaScript stubs (at most ${MOST_STUB_CALLS_PER_SIMULATED_S} expected)`);
  sim.close();
}

main().catch((error) => {
  process.stderr.write(`${error.stack || error}\n`);
  process.exit(1);
});
