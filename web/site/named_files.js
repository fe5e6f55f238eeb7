// The files in other examples' folders that a scenario names, for both runners (the worker and
// the sketch server): quoted relative paths such as
// `sketch = "../ChainedKnobsBasic/ChainedKnobsBasic.ino"`. Loaded by the page and by the worker.
"use strict";

/// [{folder, file}] for each distinct `"../<folder>/<file>"` in scenario `text`.
function otherExamplesFiles(text) {
  const named = new Map();
  for (const match of text.matchAll(/"\.\.\/([A-Za-z0-9_][\w.-]*)\/([A-Za-z0-9_][\w.-]*)"/g)) {
    named.set(`${match[1]}/${match[2]}`, { folder: match[1], file: match[2] });
  }
  return [...named.values()];
}
