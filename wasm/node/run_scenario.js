// Runs a scenario in the WebAssembly build under node and prints the run's result (the document
// `stepdance sim --result-json` writes), for the `web` tests and bench/web_speed.sh.
//
//   node --no-experimental-fetch wasm/node/run_scenario.js SITE SCENARIO [--out FILE] [--repeat N]
//
// SITE is the built site (build/web); SCENARIO a scenario file or an example folder. The folder
// holding the scenario's folder (examples/) is copied into the module's file system at the same
// absolute path, so paths in messages are the native run's. --repeat runs it N times and prints
// the simulated and wall seconds of each run (and of its loading) on stderr. (node 20 needs --no-experimental-fetch:
// with fetch present, the generated loader would fetch the .wasm by URL.)
'use strict';
const fs = require('fs');
const path = require('path');

function copyTree(sim, folder) {
  for (const entry of fs.readdirSync(folder, { withFileTypes: true })) {
    const full = path.join(folder, entry.name);
    if (entry.isDirectory()) copyTree(sim, full);
    else if (entry.isFile()) sim.writeFile(full, fs.readFileSync(full));
  }
}

async function main() {
  const args = process.argv.slice(2);
  const option = (name, fallback) => {
    const at = args.indexOf(name);
    if (at < 0) return fallback;
    const value = args[at + 1];
    args.splice(at, 2);
    return value;
  };
  const out = option('--out', null);
  const repeat = Number(option('--repeat', '1'));
  if (args.length !== 2) {
    process.stderr.write('usage: run_scenario.js SITE SCENARIO [--out FILE] [--repeat N]\n');
    process.exit(2);
  }
  const site = path.resolve(args[0]);
  let scenario = path.resolve(args[1]);
  if (fs.statSync(scenario).isDirectory()) scenario = path.join(scenario, 'scenario.toml');
  const createModule = require(path.join(site, 'stepdance_web.js'));
  const { StepdanceSim } = require(path.join(site, 'stepdance_sim.js'));
  const sim = await StepdanceSim.create(createModule, { print: () => {}, printErr: (t) => process.stderr.write(t + '\n') });
  copyTree(sim, path.dirname(path.dirname(scenario)));
  const text = fs.readFileSync(scenario, 'utf8');
  for (const name of sim.sketches(scenario, text)) {
    sim.addBoard(name, fs.readFileSync(path.join(site, 'boards', `${name}.wasm`)));
  }
  let result = '';
  for (let run = 0; run < repeat; ++run) {
    const started = process.hrtime.bigint();
    const errors = sim.open(scenario, text);
    if (errors) {
      process.stderr.write(errors + (errors.endsWith('\n') ? '' : '\n'));
      process.exit(1);
    }
    // The run alone is timed, as `stepdance sim` times it (its wall time leaves out loading and
    // the files written at the end).
    const opened = process.hrtime.bigint();
    sim.runUntil(sim.state().duration_s);
    const ran = process.hrtime.bigint();
    result = sim.finishText();
    const openS = Number(opened - started) / 1e9;
    const runS = Number(ran - opened) / 1e9;
    const simulatedS = JSON.parse(result).summary.simulated_time_s;
    if (repeat > 1) {
      process.stderr.write(`run ${run + 1}: simulated ${simulatedS} s in ${runS.toFixed(3)} s of wall time ` +
                           `(${(simulatedS / runS).toFixed(0)}x real time; loading took ${openS.toFixed(3)} s)\n`);
    }
    sim.close();
  }
  if (out) fs.writeFileSync(out, result);
  else process.stdout.write(result);
}

main().catch((error) => {
  process.stderr.write(`${error.stack || error}\n`);
  process.exit(1);
});
