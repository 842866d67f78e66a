#!/usr/bin/env python3
"""A real `lightcts run` of a selection (SPEC 8): a caselist, an --exclude and
an expected-failures file on Vulkan. Checks that results.json holds exactly
the tests the selection names, derived here from the scene files (every
attenuation/point-d-*.json but point-d-range, on vulkan), that it records the
selection as given, and each caselist and baseline file with the SHA-256 of
its bytes, computed here with hashlib.

Usage: check_test_choice.py LIGHTCTS OUT_DIR SCENES_DIR CASELIST BASELINE
Exit 0 pass, 1 fail, 77 when Vulkan is not present (a skip)."""
import fnmatch
import hashlib
import os
import subprocess
import sys

import results_json


def sha256(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def main():
    lightcts, out, scenes, caselist, baseline = sys.argv[1:6]
    exclude = "*point-d-range.*"
    run = subprocess.run([lightcts, "run", "--backend", "vulkan", "--scenes", scenes, "--caselist", caselist,
                          "--exclude", exclude, "--expected-failures", baseline, "--no-mutants", "--out", out],
                         capture_output=True, text=True)
    print(run.stdout + run.stderr)
    if run.returncode == 3:
        print("NotSupported: vulkan is not present")
        return 77
    if run.returncode != 0:
        print(f"FAIL: lightcts run exited {run.returncode}")
        return 1
    results = results_json.load(os.path.join(out, "results.json"))
    group = os.path.basename(os.path.normpath(scenes))
    expected = sorted(f"{group}.{name[:-5]}.vulkan" for name in os.listdir(scenes)
                      if fnmatch.fnmatchcase(name, "point-d-*.json") and name != "point-d-range.json")
    names = sorted(t["name"] for t in results["tests"])
    failures = []
    if not expected:
        failures.append("no point-d-* scene to select")
    if names != expected:
        failures.append(f"tests {names}, expected exactly {expected}")
    wanted_selection = {"include": [], "exclude": [exclude], "caselists": [caselist]}
    if results.get("selection") != wanted_selection:
        failures.append(f"selection {results.get('selection')}, expected {wanted_selection}")
    wanted_files = [{"kind": "expected-failures", "path": baseline, "sha256": sha256(baseline)},
                    {"kind": "caselist", "path": caselist, "sha256": sha256(caselist)}]
    if results.get("baseline_files") != wanted_files:
        failures.append(f"baseline_files {results.get('baseline_files')}, expected {wanted_files}")
    for failure in failures:
        print("FAIL:", failure)
    if not failures:
        print(f"PASS: exactly the {len(expected)} selected tests, the selection and both files' SHA-256 recorded")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
