// The run's Summary and Expectations tables, as `stepdance sim` prints them. Each expectation
// row names its scenario line and jumps to it; the failed ones' lines are handed back to be
// marked in the editor's margin.
"use strict";

function summaryRow(table, cells, className) {
  const tr = table.insertRow();
  for (const cell of cells) {
    const td = tr.insertCell();
    td.textContent = cell;
    if (className) td.className = className;
  }
  return tr;
}

/// Where an expectation's message says it is: {file, line, text} (text: the message with the
/// file written `scenario.toml line N`), file and line null when it names none.
function expectationPlace(message, folder) {
  const match = message.match(/^.*?([\w.-]+\.toml):(\d+): /);
  const text = message.replace(/^.*?([\w.-]+\.toml):(\d+): /, "$1 line $2: ").replace(folder, "");
  return match ? { file: match[1], line: Number(match[2]), text } : { file: null, line: null, text };
}

function fillSummary(table, summary, stopped) {
  table.textContent = "";
  summaryRow(table, ["simulated time", `${summary.simulated_time_s} s`]);
  for (const [motor, counts] of Object.entries(summary.motors || {})) summaryRow(table, [`motor ${motor}`, `${counts.steps} steps`]);
  const machine = summary.machine;
  if (machine && machine.pen_mm) {
    summaryRow(table, ["pen", `${machine.pen_mm.map((mm) => mm.toFixed(2)).join(", ")} mm, ${machine.pen_down ? "down" : "up"}`]);
  }
  if (machine && machine.strokes !== undefined) summaryRow(table, ["strokes", String(machine.strokes)]);
  if (stopped) summaryRow(table, ["stopped", stopped], "failed");
}

/// Fills the tables with `result` (the run's result document); an expectation row's line
/// button calls `jump(file, line)`. Returns the failed expectations' places [{file, line}].
function showRunResult(result, folder, jump) {
  fillSummary(document.getElementById("summary"), result.summary, result.stopped);
  const table = document.getElementById("expectations");
  table.textContent = "";
  const failed = [];
  for (const expectation of result.expectations) {
    const met = expectation.checked && expectation.met;
    const verdict = !expectation.checked ? "not run" : expectation.met ? "ok" : "FAILED";
    const place = expectationPlace(expectation.message, folder);
    const tr = summaryRow(table, [verdict, ""], met ? "ok" : "failed");
    if (!met && place.line) failed.push(place);
    if (!place.line) {
      tr.cells[1].textContent = place.text;
      continue;
    }
    const button = document.createElement("button");
    button.type = "button";
    button.className = "line-link";
    button.textContent = place.text;
    button.title = `show ${place.file} line ${place.line}`;
    button.onclick = () => jump(place.file, place.line);
    tr.cells[1].appendChild(button);
  }
  return failed;
}
