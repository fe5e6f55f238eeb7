#!/usr/bin/env python3
"""Runs one of the original Stepdance library's example sketches, unchanged, under a scenario of ours.

Usage:
  run_original_sketch.py --stepdance BUILD/stepdance --scenario SCENARIO.toml --out DIR [--original DIR]

The sketches are not in this repository: DIR (or, when --original is empty, the environment
variable STEPDANCE_ORIGINAL_DIR) names a checkout of the original (github.com/imoyer/stepdance;
its lib/examples folder, or that folder itself). Without one the run is skipped (exit 77, which
CTest reports as skipped).

A scenario names its sketches with placeholders, replaced here before the run:
  @ORIGINAL_EXAMPLES@  the original's lib/examples folder
  @SUITE_DIR@          this folder (our own files: receiving sketches, G-code, EBB, RPC lines)
Its first lines say what it runs, as comments the runner reads:
  # original-sketch: axidraw_examples/stepasketch
  # machine: AxiDraw
The resolved scenario is written to DIR/scenario.toml and run with `stepdance sim` into DIR/run.

A run passes when
  - every [[expect]] of the scenario holds (stepdance sim exits 0), and the scenario has a
    pen_mm (final pen position) and a strokes or bounds_mm check among them;
  - the pen never left the machine's travel area (summary.json: machine.travel_excursions = 0);
  - the pen drew at least one stroke (machine.strokes >= 1).
Exit status: 0 pass, 1 fail, 2 bad usage or a bad checkout, 77 skipped.
"""

import argparse
import json
import os
import subprocess
import sys
import tomllib
from pathlib import Path

SKIP = 77
SUITE_DIR = Path(__file__).resolve().parent


def examples_folder(checkout: str) -> Path | None:
    """The original's lib/examples folder inside `checkout` (or `checkout` itself), else None."""
    root = Path(checkout).expanduser().resolve()
    for candidate in (root / "lib" / "examples", root):
        if (candidate / "axidraw_examples").is_dir():
            return candidate
    return None


def header_fields(text: str) -> dict[str, str]:
    fields = {}
    for line in text.splitlines():
        if not line.startswith("#"):
            break
        key, sep, value = line[1:].strip().partition(":")
        if sep and key.strip() in ("original-sketch", "machine"):
            fields[key.strip()] = value.strip()
    return fields


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--stepdance", required=True, help="the stepdance command (build/stepdance)")
    parser.add_argument("--scenario", required=True, help="a scenario of tests/original_sketches/scenarios")
    parser.add_argument("--out", required=True, help="the run's output folder")
    parser.add_argument("--original", default="", help="a checkout of the original library")
    args = parser.parse_args()

    scenario = Path(args.scenario).resolve()
    text = scenario.read_text()
    fields = header_fields(text)
    sketch = fields.get("original-sketch", "?")
    machine = fields.get("machine", "?")
    if sketch == "?" or machine == "?":
        print(f"{scenario}: the first comment lines must name the 'original-sketch:' and the 'machine:'")
        return 2

    checkout = args.original or os.environ.get("STEPDANCE_ORIGINAL_DIR", "")
    if not checkout:
        print(f"SKIPPED original sketch {sketch}: no checkout of the original Stepdance library was given. "
              "Set STEPDANCE_ORIGINAL_DIR to one (a CMake cache variable, or an environment variable when "
              "ctest runs), e.g. STEPDANCE_ORIGINAL_DIR=/path/to/stepdance ctest --test-dir build -L original_sketches")
        return SKIP
    examples = examples_folder(checkout)
    if examples is None:
        print(f"STEPDANCE_ORIGINAL_DIR={checkout} holds no lib/examples/axidraw_examples: not a checkout of the original")
        return 2
    if not (examples / sketch).is_dir():
        print(f"{examples / sketch} is missing from the checkout")
        return 2

    resolved_text = text.replace("@ORIGINAL_EXAMPLES@", str(examples)).replace("@SUITE_DIR@", str(SUITE_DIR))
    expectations = tomllib.loads(resolved_text).get("expect", [])
    kinds = {key for entry in expectations for key in entry}
    if "pen_mm" not in kinds or not kinds & {"strokes", "bounds_mm"}:
        print(f"{scenario}: needs a pen_mm expectation (the hand-worked end point) and a strokes or bounds_mm one")
        return 2

    out = Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    resolved = out / "scenario.toml"
    resolved.write_text(resolved_text)
    run_dir = out / "run"
    print(f"original sketch {sketch} ({machine}) under {scenario.name}", flush=True)
    status = subprocess.run([args.stepdance, "sim", str(resolved), "--out", str(run_dir)]).returncode

    problems = []
    if status != 0:
        problems.append(f"stepdance sim exited with status {status}")
    summary_file = run_dir / "summary.json"
    pen = strokes = excursions = None
    if summary_file.exists():
        machine_summary = json.loads(summary_file.read_text()).get("machine", {})
        pen = machine_summary.get("pen_mm")
        strokes = machine_summary.get("strokes")
        excursions = machine_summary.get("travel_excursions")
        if excursions != 0:
            problems.append(f"the pen left the travel area {excursions} times")
        if not strokes:
            problems.append("no pen-down stroke")
    else:
        problems.append(f"no {summary_file}")

    pen_text = f"[{pen[0]:.3f}, {pen[1]:.3f}] mm" if pen else "?"
    result = "pass" if not problems else "FAIL: " + "; ".join(problems)
    line = (f"{sketch} | {scenario.name} | {machine} | {result} "
            f"(pen {pen_text}, {strokes} strokes, {excursions} travel excursions)")
    (out / "result.txt").write_text(line + "\n")
    print("original-sketch result: " + line)
    return 0 if not problems else 1


if __name__ == "__main__":
    sys.exit(main())
