#!/usr/bin/env node
// saxi (npm `saxi`, a plotter driver we did not write) plots through the live simulator.
//
// saxi's own modules do the work: its planner (constant acceleration, cornering) plans a drawing,
// its EBB driver sends it over the simulated board's pseudo-terminal with saxi's serial binding,
// choosing LM or XM from the firmware version the board reports. After SIGINT the simulator writes
// the drawing; every pen-down point must lie within one motor step (plus the pen trace's 0.01 mm)
// of saxi's planned path and every planned vertex as close to the drawing, with one stroke per
// path, and no command may be lost while saxi streams faster than the machine moves: the board's
// counters (summary.json) show every line answered and every queued command started, and motion
// commands that found the FIFO full and waited (saxi waits for every reply; a lost one would hang it).
//
// Usage: node saxi_plot_test.js STEPDANCE SCENARIO OUT_DIR {LM|XM} [IMAGE]
// With IMAGE (a Teensy 4.1 ELF), the board `driver` runs that firmware image on the emulated chip
// (`--image driver=IMAGE`) and saxi talks to the image's own USB serial.
'use strict';
const { spawn } = require('child_process');
const fs = require('fs');
const path = require('path');
const assert = require('assert');

const [stepdance, scenario, outDir, expectedPath, image] = process.argv.slice(2);
const { EBB } = require('saxi/dist/server/ebb');
const { SerialPortSerialPort } = require('saxi/dist/server/serialport-serialport');
const planning = require('saxi/dist/server/planning');

const STEPS_PER_MM = planning.Device.Axidraw.stepsPerMm;  // saxi plans in 1/5 mm steps

// The drawing, in saxi's units: a square, a triangle and a 48-gon circle (mm × 5).
function drawing() {
  const mm = (x, y) => ({ x: x * STEPS_PER_MM, y: y * STEPS_PER_MM });
  const circle = [];
  for (let i = 0; i <= 48; i++) {
    const a = (2 * Math.PI * i) / 48;
    circle.push(mm(120 + 25 * Math.cos(a), 60 + 25 * Math.sin(a)));
  }
  return [
    [mm(20, 20), mm(70, 20), mm(70, 70), mm(20, 70), mm(20, 20)],
    [mm(90, 100), mm(140, 100), mm(115, 140), mm(90, 100)],
    circle,
  ];
}

function startSimulator() {
  fs.rmSync(outDir, { recursive: true, force: true });
  const imageArgs = image ? ['--image', `driver=${image}`] : [];
  const sim = spawn(stepdance, ['sim', scenario, '--live', '--speed', '4', '--out', outDir, ...imageArgs],
                    { stdio: ['ignore', 'pipe', 'pipe'] });
  let stdout = '';
  let stderr = '';
  sim.stderr.on('data', (d) => { stderr += d; });
  const announced = new Promise((resolve, reject) => {
    sim.stdout.on('data', (d) => {
      stdout += d;
      const m = /^serial driver: (\/dev\/pts\/\d+)\n/.exec(stdout);
      if (m) resolve(m[1]);
    });
    sim.on('exit', (code) => reject(new Error(`simulator exited (${code}) before announcing: ${stderr}`)));
  });
  const finished = new Promise((resolve) => sim.on('exit', (code) => resolve({ code, stdout: () => stdout, stderr: () => stderr })));
  return { sim, announced, finished };
}

/** Polylines from our SVG writer: `<polyline points="x,y …"/>`, in machine mm. */
function strokesFromSvg(file) {
  const svg = fs.readFileSync(file, 'utf8');
  const strokes = [];
  for (const m of svg.matchAll(/<polyline points="([^"]*)"/g)) {
    strokes.push(m[1].trim().split(/\s+/).map((pair) => {
      const [x, y] = pair.split(',').map(Number);
      return { x, y };
    }));
  }
  return strokes;
}

function distanceToSegment(p, a, b) {
  const dx = b.x - a.x, dy = b.y - a.y;
  const lengthSq = dx * dx + dy * dy;
  const t = lengthSq > 0 ? Math.max(0, Math.min(1, ((p.x - a.x) * dx + (p.y - a.y) * dy) / lengthSq)) : 0;
  return Math.hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

function farthest(points, polyline) {
  let worst = 0;
  for (const p of points) {
    let best = Infinity;
    if (polyline.length === 1) best = Math.hypot(p.x - polyline[0].x, p.y - polyline[0].y);
    for (let i = 0; i + 1 < polyline.length; i++) best = Math.min(best, distanceToSegment(p, polyline[i], polyline[i + 1]));
    worst = Math.max(worst, best);
  }
  return worst;
}

let plotDone = false;
function exitOnUncaught() {
  process.on('uncaughtException', (error) => {
    if (plotDone && error.code === 'ERR_STREAM_PREMATURE_CLOSE') return;
    console.error(error.stack || String(error));
    process.exit(1);
  });
}

async function main() {
  const { sim, announced, finished } = startSimulator();
  const ptyPath = await announced;
  const port = new SerialPortSerialPort(ptyPath);
  await port.open({ baudRate: 9600 });
  const ebb = new EBB(port);
  // Every command line saxi writes, in order (saxi waits for each reply before the next).
  const sent = [];
  const write = ebb.write.bind(ebb);
  ebb.write = (text) => {
    sent.push(text.replace(/\r$/, ''));
    return write(text);
  };
  const version = await ebb.firmwareVersionNumber();
  const usesLM = await ebb.supportsLM();
  assert.strictEqual(usesLM ? 'LM' : 'XM', expectedPath, `firmware ${version.join('.')} selects the wrong path`);
  assert.ok(await ebb.areSteppersPowered(), 'QC must report a healthy supply');

  const paths = drawing();
  const plan = planning.plan(paths, planning.AxidrawFast);
  await ebb.executePlan(plan);  // EM,2,2 … motions … QM until idle, EM,0,0
  // EM,0,0 is answered when queued: polled until the FIFO has taken it too, so the interrupt
  // below cannot come before its frame (it did on a loaded machine).
  await ebb.waitUntilMotorsIdle();
  plotDone = true;  // from here, the serial stream closing under saxi is expected
  // saxi sends each command as soon as the last one is answered; QM polls after its last motion
  // command (reported, not checked: how many depends on the host's speed) mean moves still ran.
  const lastMotion = sent.map((line) => /^(LM|XM|SM)\b/i.test(line)).lastIndexOf(true);
  const pollsAfter = sent.slice(lastMotion + 1).filter((line) => /^QM$/i.test(line)).length;

  sim.kill('SIGINT');
  const result = await finished;
  assert.strictEqual(result.code, 0, `simulator exit ${result.code}: ${result.stderr()}`);

  // Compare the drawing with saxi's paths, in machine mm (the SVG's margin is a group transform).
  const strokes = strokesFromSvg(path.join(outDir, 'drawing.svg'));
  const planned = paths.map((p) => p.map((q) => ({ x: q.x / STEPS_PER_MM, y: q.y / STEPS_PER_MM })));
  assert.strictEqual(strokes.length, planned.length, `${strokes.length} pen-down strokes for ${planned.length} paths`);
  // saxi rounds every block to whole steps in x and y (1/8 microstepping: 1/40 mm), carrying the
  // remainder, so its commanded vertices sit within one step of the plan on each coordinate; the
  // EBB algorithm then runs each belt on its own rate, which may lead or lag by one more step
  // inside a move. Two steps on each coordinate, plus the pen trace's 0.01 mm:
  const bound = Math.SQRT2 * 2 / 40 + 0.01;
  for (let i = 0; i < planned.length; i++) {
    const away = farthest(strokes[i], planned[i]);
    const missed = farthest(planned[i], strokes[i]);
    assert.ok(away <= bound, `stroke ${i}: a pen point ${away.toFixed(4)} mm off saxi's path`);
    assert.ok(missed <= bound, `stroke ${i}: a planned vertex ${missed.toFixed(4)} mm from the drawing`);
  }

  // No command lost while saxi streamed faster than the machine moved: the board answered every
  // line saxi sent and started every queued one, and at times a motion command found the FIFO
  // full and waited unread (flow control).
  const board = JSON.parse(fs.readFileSync(path.join(outDir, 'summary.json'), 'utf8')).counters.driver;
  const name = Object.keys(board).find((key) => key.startsWith('Eibotboard'));
  assert.ok(name, 'the summary has the Eibotboard counters');
  const counters = board[name];
  const queued = sent.filter((line) => /^(LM|XM|SM|HM|EM|S2|SP|TP)\b/i.test(line)).length;
  assert.strictEqual(counters.commands, sent.length, `${sent.length} commands sent, ${counters.commands} answered`);
  assert.strictEqual(counters.moves_started, queued, `${queued} FIFO commands sent, ${counters.moves_started} started`);
  assert.strictEqual(counters.errors_replied, 0, 'no command refused');
  assert.strictEqual(counters.replies_dropped, 0, 'no reply dropped');
  assert.ok(counters.fifo_full_waits > 0, 'saxi never outran the machine: the FIFO was never full');
  console.log(`saxi ${expectedPath} path: ${planned.length} strokes drawn within ${bound.toFixed(4)} mm of the plan; ` +
              `${sent.length} commands, ${queued} queued, ${counters.fifo_full_waits} waited for FIFO room, ` +
              `${pollsAfter} QM polls after the last move`);
}

module.exports = { drawing };

if (require.main === module) {
  exitOnUncaught();
  main().then(() => process.exit(0), (error) => {
    console.error(error.stack || String(error));
    process.exit(1);
  });
}
