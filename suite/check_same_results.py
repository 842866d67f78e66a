#!/usr/bin/env python3
"""Checks that two lightcts runs say the same thing, apart from timings:
`lightcts run --jobs 1` against `--jobs 2`, or a merge of shards
against the unsharded run. Compares results.json test for test (every field
but the timings), the mutant records, the backends' statuses and counts,
junit.xml's testcases, failures.csv and results.csv, and the evidence files
byte for byte. Exit 0 when they agree, 1 with the differences listed.

With --every-key, results.json must be equal key for key at every level,
apart from what says when, how long and from which shards (TIMES_AND_PROVENANCE):
what `merge` of a run's single shard must give against the unsharded run.

Usage: check_same_results.py [--every-key] RUN_A RUN_B"""
import csv
import filecmp
import json
import os
import sys
import xml.etree.ElementTree as ET

import results_json

# What may differ between two runs of the same tests: when and how long.
TIMING_KEYS = {"timings_ms", "wall_s", "duration_s", "started_utc", "command", "jobs", "shard", "merged_from",
               "slowest", "time", "timestamp"}


def without_timings(value):
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if k not in TIMING_KEYS}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


# What may differ between an unsharded run and the merge of its one shard:
# when and how long (the summed task times included), the command line, and
# the merge's own record of its shards.
TIMES_AND_PROVENANCE = {"timings_ms", "wall_s", "duration_s", "started_utc", "command", "slowest"}
TIMED = {"task_ms": ("reference", "total")}  # keys whose times differ while their counts must not


def key_differences(a, b, path=""):
    """Every path where two JSON values differ, outside TIMES_AND_PROVENANCE."""
    if isinstance(a, dict) and isinstance(b, dict):
        if list(a) != list(b):
            return [f"{path or '/'}: keys {list(a)} against {list(b)}"]
        times = TIMED.get(path.rsplit("/", 1)[-1], ())
        return [d for k in a if k not in TIMES_AND_PROVENANCE and k not in times
                for d in key_differences(a[k], b[k], f"{path}/{k}")]
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return [f"{path}: {len(a)} items against {len(b)}"]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in key_differences(x, y, f"{path}/{i}")]
    return [] if a == b else [f"{path}: {json.dumps(a)[:80]} against {json.dumps(b)[:80]}"]


def every_key(a, b):
    ra = results_json.load(os.path.join(a, "results.json"))
    rb = results_json.load(os.path.join(b, "results.json"))
    # The merge names its shards; the run it stands for has none.
    rb = {k: v for k, v in rb.items() if k != "merged_from"}
    problems = key_differences(ra, rb)
    for p in problems[:40]:
        print(p)
    print(f"results.json key for key: " + ("the same" if not problems else f"{len(problems)} difference(s)"))
    return 1 if problems else 0


def junit_cases(path):
    cases = []
    for case in ET.parse(path).getroot().iter("testcase"):
        outcome = sorted(child.tag for child in case if child.tag in ("failure", "error", "skipped"))
        cases.append((case.get("classname"), case.get("name"), tuple(outcome)))
    return cases


def csv_rows(path):
    """deqp-runner's test,status,duration rows without the duration and the
    '#' lines, which say when the run started."""
    with open(path, newline="") as f:
        return [row[:2] for row in csv.reader(f) if row and not row[0].startswith("#")]


def evidence_files(run):
    files = []
    for folder in ("evidence", "mutants"):
        root = os.path.join(run, folder)
        for dirpath, _, names in os.walk(root):
            files += [os.path.relpath(os.path.join(dirpath, n), run) for n in names]
    return sorted(files)


def main(a, b):
    problems = []
    ra = results_json.load(os.path.join(a, "results.json"))
    rb = results_json.load(os.path.join(b, "results.json"))
    ta, tb = ra["tests"], rb["tests"]
    if [t["name"] for t in ta] != [t["name"] for t in tb]:
        problems.append(f"the tests differ or are in another order: {len(ta)} against {len(tb)}")
    for x, y in zip(ta, tb):
        if without_timings(x) != without_timings(y):
            keys = [k for k in x if without_timings(x.get(k)) != without_timings(y.get(k))]
            problems.append(f"test {x['name']} differs in {keys}")
    if without_timings(ra["mutants"]) != without_timings(rb["mutants"]):
        ma = {(m["mutant"], m["backend"]): m for m in ra["mutants"]}
        mb = {(m["mutant"], m["backend"]): m for m in rb["mutants"]}
        for key in sorted(set(ma) | set(mb)):
            if without_timings(ma.get(key)) != without_timings(mb.get(key)):
                problems.append(f"mutant {key} differs: {ma.get(key)} against {mb.get(key)}")
    backend_keys = ("backend", "status", "message", "device", "counts", "mutant_counts")
    ba = [{k: x.get(k) for k in backend_keys} for x in ra["backends"]]
    bb = [{k: x.get(k) for k in backend_keys} for x in rb["backends"]]
    if ba != bb:
        problems.append(f"backends differ: {ba} against {bb}")
    for key in ("lightcts_revision", "scenes_digest", "mutants_run"):
        if ra.get(key) != rb.get(key):
            problems.append(f"{key} differs: {ra.get(key)} against {rb.get(key)}")
    if junit_cases(os.path.join(a, "junit.xml")) != junit_cases(os.path.join(b, "junit.xml")):
        problems.append("junit.xml's testcases differ")
    for name in ("failures.csv", "results.csv"):
        if csv_rows(os.path.join(a, name)) != csv_rows(os.path.join(b, name)):
            problems.append(f"{name} differs")
    fa, fb = evidence_files(a), evidence_files(b)
    if fa != fb:
        problems.append(f"evidence files differ: only in A {sorted(set(fa) - set(fb))[:5]}, "
                        f"only in B {sorted(set(fb) - set(fa))[:5]}")
    for f in set(fa) & set(fb):
        if f.endswith(".png") and not filecmp.cmp(os.path.join(a, f), os.path.join(b, f), shallow=False):
            problems.append(f"{f} differs")
    for p in problems[:40]:
        print(p)
    print(f"{len(ta)} tests, {len(ra['mutants'])} mutant records, {len(fa)} evidence files: "
          + ("the same" if not problems else f"{len(problems)} difference(s)"))
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--every-key":
        sys.exit(every_key(sys.argv[2], sys.argv[3]))
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
