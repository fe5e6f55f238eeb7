#!/usr/bin/env node
// saxi (npm `saxi`) plots saxi_plot_test.js's drawing (a square, a triangle, a circle) on a
// pseudo-terminal a running simulator announced, then exits: for tests that watch something
// else meanwhile (saxi_view_test.py: the live view's page).
//
// Usage: node saxi_plot_pty.js PTY_PATH
'use strict';
const { EBB } = require('saxi/dist/server/ebb');
const { SerialPortSerialPort } = require('saxi/dist/server/serialport-serialport');
const planning = require('saxi/dist/server/planning');
const { drawing } = require('./saxi_plot_test');

async function main() {
  const port = new SerialPortSerialPort(process.argv[2]);
  await port.open({ baudRate: 9600 });
  const ebb = new EBB(port);
  await ebb.executePlan(planning.plan(drawing(), planning.AxidrawFast));  // EM,2,2 … QM until idle, EM,0,0
  console.log(`saxi plotted ${drawing().length} paths`);
}

main().then(() => process.exit(0), (error) => {
  console.error(error.stack || String(error));
  process.exit(1);
});
